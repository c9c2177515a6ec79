//! What `AnalyticSurface.list()` and `AnalyticCongruence.list()` say of each entry of the
//! catalogue (Sections 3 and 5's examples): its name, title and default domain — the
//! JavaScript `CatalogueEntry` (`crates/ruledlab-wasm/src/catalogue_entry.rs`).

use pyo3::prelude::*;
use pyo3::types::PyDict;

/// `{"name", "title", "u_min", "u_max", "v_min", "v_max"}` of an entry with domain
/// [u.0, u.1] × [v.0, v.1]; each class's `list()` adds its own keys.
pub fn entry_dict<'py>(
    py: Python<'py>,
    name: &str,
    title: &str,
    u: (f64, f64),
    v: (f64, f64),
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("name", name)?;
    d.set_item("title", title)?;
    d.set_item("u_min", u.0)?;
    d.set_item("u_max", u.1)?;
    d.set_item("v_min", v.0)?;
    d.set_item("v_max", v.1)?;
    Ok(d)
}
