//! Segments as text (CSV, JSON, OBJ; a surface's invariants as CSV or JSON): what
//! `RuledSurface.export` and `LineCongruence.export` write. No JS class.

use ruledlab_js::args::{self, describe, fail};

use ruledlab::tolerance::MAX_OBJECT_NAME;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// Options of `RuledSurface.export` and `LineCongruence.export`.
#[derive(serde::Deserialize, Default, Tsify)]
#[serde(default)]
struct ExportOptions {
    /// The object's name in an OBJ file (default "ruledlab").
    name: Option<String>,
}

/// Segments as text in `format`; `surface`: the invariants of Section 2 too (not for a
/// congruence's lines) and OBJ faces between consecutive rulings.
pub(super) fn export(
    func: &str,
    format: &JsValue,
    options: JsValue,
    flat: &[f64],
    grid: Option<(usize, usize)>,
    surface: Option<&ruledlab::RuledSurface>,
) -> Result<String, JsValue> {
    let o: ExportOptions = args::options(func, options)?;
    let name = o.name.as_deref().unwrap_or("ruledlab");
    if name.chars().count() > MAX_OBJECT_NAME {
        return Err(args::fail_option(
            func,
            "name",
            format!("options.name must be at most {MAX_OBJECT_NAME} characters"),
        ));
    }
    let known = if surface.is_some() {
        "\"csv\", \"json\", \"obj\", \"invariants-csv\" or \"invariants-json\""
    } else {
        "\"csv\", \"json\" or \"obj\""
    };
    match (format.as_string().as_deref(), surface) {
        (Some("csv"), _) => Ok(ruledlab::write_csv(flat)),
        (Some("json"), _) => Ok(ruledlab::write_json(flat, grid)),
        (Some("obj"), _) => Ok(ruledlab::write_obj(flat, surface.is_some(), name)),
        (Some("invariants-csv"), Some(s)) => Ok(ruledlab::invariants_csv(&s.invariants())),
        (Some("invariants-json"), Some(s)) => Ok(ruledlab::invariants_json(&s.invariants())),
        (got, _) => {
            let got = got.map_or_else(|| describe(format), |g| format!("\"{g}\""));
            Err(fail(func, format!("format must be {known}, got {got}")))
        }
    }
}
