//! Segments as text (CSV, JSON, OBJ; a surface's invariants as CSV or JSON): what
//! `RuledSurface.export` and `LineCongruence.export` write, as the JavaScript API's `export`.
//! No class.

use crate::args;
use crate::error::{fail, fail_option};
use pyo3::prelude::*;
use ruledlab::tolerance::MAX_OBJECT_NAME;

/// Segments (`flat`: 6 numbers each) as text in `format`; `grid`: their shape, for JSON;
/// `surface`: the invariants too, and OBJ faces between consecutive rulings.
pub fn export(
    func: &str,
    format: &Bound<'_, PyAny>,
    name: Option<&Bound<'_, PyAny>>,
    flat: &[f64],
    grid: Option<(usize, usize)>,
    surface: Option<&ruledlab::RuledSurface>,
) -> PyResult<String> {
    let known: &[&str] = if surface.is_some() {
        &["csv", "json", "obj", "invariants-csv", "invariants-json"]
    } else {
        &["csv", "json", "obj"]
    };
    let format = args::choice(func, "format", Some(format), known)?.map(|k| known[k]);
    let name = args::optional_text(func, "name", name)?.unwrap_or_else(|| "ruledlab".into());
    if name.chars().count() > MAX_OBJECT_NAME {
        return Err(fail_option(func, "name", format!("name must be at most {MAX_OBJECT_NAME} characters")));
    }
    Ok(match (format, surface) {
        (Some("csv"), _) => ruledlab::write_csv(flat),
        (Some("json"), _) => ruledlab::write_json(flat, grid),
        (Some("obj"), _) => ruledlab::write_obj(flat, surface.is_some(), &name),
        (Some("invariants-csv"), Some(s)) => ruledlab::invariants_csv(&s.invariants()),
        (Some("invariants-json"), Some(s)) => ruledlab::invariants_json(&s.invariants()),
        _ => return Err(fail(func, "format is required")),
    })
}
