//! What Python can ask of the module itself: `version()`.

use pyo3::prelude::*;

/// The crate version, e.g. "0.1.0" (the npm package's and the Python package's).
#[pyfunction]
pub fn version() -> &'static str {
    env!("CARGO_PKG_VERSION")
}
