//! What JavaScript can ask of the module itself: `version()` and `liveObjects()`.

use super::live;
use wasm_bindgen::prelude::*;

/// The crate version, e.g. "0.1.0".
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}

/// How many ruledlab objects (RuledSurface, AnalyticSurface, LineCongruence,
/// AnalyticCongruence, ToolPath) exist, i.e. have been made and not yet freed.
#[wasm_bindgen(js_name = liveObjects)]
pub fn live_objects() -> usize {
    live::count()
}
