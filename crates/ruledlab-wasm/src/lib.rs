//! The teaching module's JavaScript bindings (`pkg/ruledlab.js`): the geometry of the paper and
//! beyond it, for the page, `<ruled-view>` and the npm package. The CAM module
//! (`ruledlab-cam-wasm`, `pkg/cam/`) is loaded only where tool paths are asked for; what both
//! share is `ruledlab-js`. Only the binding crates use wasm-bindgen.
//!
//! Every export takes and returns flat typed arrays, validates its arguments (types
//! included: a JS caller can pass anything), and turns the core's [`ruledlab::Error`] into a
//! JS `Error` with the same message. Nothing here panics on any input, so no trap crosses
//! the boundary and the module stays usable after an error.
//!
//! One file per JavaScript class, named after it (`ruled_surface.rs` for `RuledSurface`), with
//! every method of the class; the free functions in files named for what they do; the helpers
//! (argument checks, errors, option types and conversions) in files that declare no class. No
//! file uses another in a cycle (`tests/architecture.rs`).

// the classes
mod analytic_congruence;
mod analytic_surface;
mod congruence_focal;
mod invariants_buffer;
mod line_congruence;
mod ruled_surface;

// the free functions
mod hidden_lines;
mod import;
mod klein_departure;
mod klein_view;
mod line_fit;
mod mesh;
mod module_info;
mod polygon;
mod snap;

// what they share
mod catalogue_entry;
mod export;
mod focal;
mod formula;
mod invariants;
mod linear_complex;

pub use analytic_congruence::AnalyticCongruence;
pub use analytic_surface::AnalyticSurface;
pub use hidden_lines::hidden_lines;
pub use import::import_segments;
pub use klein_departure::klein_departure;
pub use klein_view::klein_view;
pub use line_congruence::LineCongruence;
pub use linear_complex::linear_complex_of;
pub use module_info::{live_objects, version};
pub use polygon::subdivide_polygon;
pub use ruled_surface::RuledSurface;
pub use snap::snap_point;
