//! What JavaScript can ask of the CAM module itself: `version()` and `liveObjects()` (its own
//! objects: the teaching module counts its own).

use ruledlab_js::live;
use wasm_bindgen::prelude::*;

// the teaching module's two functions again (ruledlab-wasm): each wasm module exports its own

/// The crate version, e.g. "0.1.0" (the teaching module's too: they are built together).
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}

/// How many objects of the CAM module (ToolPath) exist, i.e. have been made and not yet freed.
#[wasm_bindgen(js_name = liveObjects)]
pub fn live_objects() -> usize {
    live::count()
}
