//! What JavaScript can ask of the module itself: `version()` and `liveObjects()` (declared by
//! `ruledlab_js::module_info!`, as the CAM module declares its own).

ruledlab_js::module_info!(
    "the teaching module (RuledSurface, AnalyticSurface, LineCongruence, AnalyticCongruence, \
     CongruenceFocal, InvariantsBuffer; the CAM module counts its own)"
);
