//! What JavaScript can ask of the CAM module itself: `version()` and `liveObjects()` (declared by
//! `ruledlab_js::module_info!`, as the teaching module declares its own).

ruledlab_js::module_info!("the CAM module (ToolPath, FlatPattern; the teaching module counts its own)");
