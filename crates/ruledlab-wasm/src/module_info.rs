//! What JavaScript can ask of the module itself: `version()` and `liveObjects()`.

use ruledlab_js::live;
use wasm_bindgen::prelude::*;

// the CAM module's two functions again (ruledlab-cam-wasm): each wasm module exports its own

/// The crate version, e.g. "0.1.0".
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}

/// How many objects of the teaching module (RuledSurface, AnalyticSurface, LineCongruence,
/// AnalyticCongruence, CongruenceFocal, InvariantsBuffer) exist, i.e. have been made and not yet
/// freed (the CAM module counts its own).
#[wasm_bindgen(js_name = liveObjects)]
pub fn live_objects() -> usize {
    live::count()
}
