//! The JavaScript bindings: the only module that uses wasm-bindgen.
//!
//! Every export takes and returns flat typed arrays, validates its arguments (types
//! included: a JS caller can pass anything), and turns the core's [`crate::Error`] into a
//! JS `Error` with the same message. Nothing here panics on any input, so no trap crosses
//! the boundary and the module stays usable after an error.

mod args;
mod buffers;
mod catalogue;
mod congruence;
mod error;
mod focal;
mod formula;
mod io;
mod line_fit;
mod linear_complex;
mod live;
mod milling;
mod subdivision;
mod surface;
mod timing;
mod visibility;

pub use catalogue::{AnalyticCongruence, AnalyticSurface};
pub use congruence::LineCongruence;
pub use io::import_segments;
pub use linear_complex::linear_complex_of;
pub use live::live_objects;
pub use milling::ToolPath;
pub use subdivision::subdivide_polygon;
pub use surface::RuledSurface;
pub use visibility::hidden_lines;

use wasm_bindgen::prelude::*;

/// The crate version, e.g. "0.1.0".
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}
