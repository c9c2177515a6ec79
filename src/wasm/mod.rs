//! The JavaScript bindings: the only module that uses wasm-bindgen.
//!
//! Every export takes and returns flat typed arrays, validates its arguments (types
//! included: a JS caller can pass anything), and turns the core's [`crate::Error`] into a
//! JS `Error` with the same message. Nothing here panics on any input, so no trap crosses
//! the boundary and the module stays usable after an error.

mod args;
mod buffers;
mod congruence;
mod congruence_focal;
mod error;
mod focal;
mod formula;
mod io;
mod live;
mod subdivide;
mod surface;
mod toolpath;

pub use congruence::{AnalyticCongruence, LineCongruence};
pub use focal::linear_complex_of;
pub use io::import_segments;
pub use live::live_objects;
pub use subdivide::subdivide_polygon;
pub use surface::{AnalyticSurface, RuledSurface};
pub use toolpath::ToolPath;

use wasm_bindgen::prelude::*;

/// The crate version, e.g. "0.1.0".
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}
