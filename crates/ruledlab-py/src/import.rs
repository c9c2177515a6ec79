//! Reading data files given as text: `import_segments` (segments as CSV or JSON) and
//! `detect_import` (what a text holds: segments, tool poses or a target curve), as the
//! JavaScript functions of the same names (`crates/ruledlab-wasm/src/import.rs`).

use crate::args;
use crate::arrays;
use crate::error::fail;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The text and whether it is JSON: ``format`` "json" or "csv", or, left out, JSON when the
/// text starts with ``[`` or ``{``.
pub fn text_and_format(
    func: &str,
    text: &Bound<'_, PyAny>,
    format: Option<&Bound<'_, PyAny>>,
) -> PyResult<(String, bool)> {
    let text = args::text(func, "text", text)?;
    let json = match args::choice(func, "format", format, &["json", "csv"])? {
        Some(k) => k == 0,
        None => text.trim_start().starts_with(['[', '{']),
    };
    Ok((text, json))
}

/// Segments read from CSV (six numbers per line, optional header, ``#`` comments) or JSON
/// (``[[ax, ay, az, bx, by, bz], …]``, a flat array, or ``{"segments", "rows", "cols"}``):
/// ``segments`` (N, 6) and, when the file gives a grid, ``rows`` and ``cols``. Anything malformed
/// is a ``RuledlabError`` (``parse-error``) with its line and column; texts over 64 MiB are
/// refused before parsing.
#[pyfunction]
#[pyo3(signature = (text, format=None))]
pub fn import_segments<'py>(
    py: Python<'py>,
    text: &Bound<'py, PyAny>,
    format: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    const F: &str = "import_segments";
    let (text, json) = text_and_format(F, text, format)?;
    let imported = py
        .detach(|| if json { ruledlab::read_json(&text) } else { ruledlab::read_csv(&text) })
        .map_err(|e| fail(F, e))?;
    let d = PyDict::new(py);
    let n = imported.coords.len() / 6;
    d.set_item("segments", arrays::array(py, imported.coords, &[n, 6])?)?;
    if let Some((rows, cols)) = imported.grid {
        d.set_item("rows", rows)?;
        d.set_item("cols", cols)?;
    }
    Ok(d)
}

/// What a text holds: "poses" (tool poses), "target" (a target curve) or "segments".
#[pyfunction]
pub fn detect_import(text: &Bound<'_, PyAny>) -> PyResult<&'static str> {
    let text = args::text("detect_import", "text", text)?;
    Ok(ruledlab::detect_import(&text))
}
