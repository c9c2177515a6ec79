//! Import and export of segments as text (CSV, JSON) for JavaScript.

use super::args::{describe, fail, to_js};
use super::congruence::LineCongruence;
use super::surface::RuledSurface;
use crate::io;
use crate::tolerance::MAX_OBJECT_NAME;
use js_sys::Float64Array;
use serde::Serialize;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// Segments read by `importSegments`: 6 numbers per line, and a grid shape when the file
/// gives one.
#[derive(Serialize, Tsify)]
struct ImportedSegments {
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    segments: Float64Array,
    #[serde(skip_serializing_if = "Option::is_none")]
    rows: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    cols: Option<usize>,
}

/// The host's `parseFloat` (correctly rounded), for tokens the core has checked to be decimal
/// numbers: keeps Rust's float-parsing tables out of the wasm file.
fn js_number(token: &str) -> f64 {
    js_sys::parse_float(token)
}

/// Reads segments from CSV (six numbers per line, optional header, `#` comments) or JSON
/// (`[[ax, ay, az, bx, by, bz], …]`, a flat array, or `{ segments, rows?, cols? }`).
/// `format` defaults to JSON when the text starts with `[` or `{`, else CSV. Throws with the
/// line and column of anything malformed; texts over 64 MiB are refused before parsing.
#[wasm_bindgen(js_name = importSegments, unchecked_return_type = "ImportedSegments")]
pub fn import_segments(
    #[wasm_bindgen(unchecked_param_type = "string")] text: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "\"csv\" | \"json\"")] format: JsValue,
) -> Result<JsValue, JsValue> {
    const F: &str = "importSegments";
    let Some(text) = text.as_string() else {
        return Err(fail(F, format!("text must be a string, got {}", describe(&text))));
    };
    let format = if format.is_undefined() || format.is_null() {
        if text.trim_start().starts_with(['[', '{']) {
            "json".to_string()
        } else {
            "csv".to_string()
        }
    } else {
        format.as_string().unwrap_or_default()
    };
    let imported = match format.as_str() {
        "csv" => io::csv::parse_with(&text, &js_number),
        "json" => io::json::parse_with(&text, &js_number),
        other => return Err(fail(F, format!("format must be \"csv\" or \"json\", got \"{other}\""))),
    }
    .map_err(|e| fail(F, e))?;
    let (rows, cols) = imported.grid.map_or((None, None), |(r, c)| (Some(r), Some(c)));
    to_js(F, &ImportedSegments { segments: Float64Array::from(&imported.coords[..]), rows, cols })
}

/// Options of `RuledSurface.export` and `LineCongruence.export`.
#[derive(serde::Deserialize, Default, Tsify)]
#[serde(default)]
struct ExportOptions {
    /// The object's name in an OBJ file (default "ruledlab").
    name: Option<String>,
}

/// Segments as text in `format`; `surface`: the invariants of Section 2 too (not for a
/// congruence's lines) and OBJ faces between consecutive rulings.
fn export(
    func: &str,
    format: &JsValue,
    options: JsValue,
    flat: &[f64],
    grid: Option<(usize, usize)>,
    surface: Option<&crate::ruled::RuledSurface>,
) -> Result<String, JsValue> {
    let o: ExportOptions = super::args::options(func, options)?;
    let name = o.name.as_deref().unwrap_or("ruledlab");
    if name.chars().count() > MAX_OBJECT_NAME {
        return Err(super::args::fail_option(
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
        (Some("csv"), _) => Ok(io::csv::write(flat)),
        (Some("json"), _) => Ok(io::json::write(flat, grid)),
        (Some("obj"), _) => Ok(io::obj::write_obj(flat, surface.is_some(), name)),
        (Some("invariants-csv"), Some(s)) => Ok(io::invariants::write_csv(&s.invariants())),
        (Some("invariants-json"), Some(s)) => Ok(io::invariants::write_json(&s.invariants())),
        (got, _) => {
            let got = got.map_or_else(|| describe(format), |g| format!("\"{g}\""));
            Err(fail(func, format!("format must be {known}, got {got}")))
        }
    }
}

#[wasm_bindgen]
impl RuledSurface {
    /// The surface as data: "csv" (header `ax,ay,az,bx,by,bz`), "json" (`{ "segments": [[…],
    /// …] }`), "obj" (vertices, ruling lines and the quads between them; `options.name`), or its
    /// invariants (Section 2) as "invariants-csv" (a row per pair of rulings) or
    /// "invariants-json" (the arrays of `invariants()`, NaN as null); full precision.
    pub fn export(
        &self,
        #[wasm_bindgen(
            unchecked_param_type = "\"csv\" | \"json\" | \"obj\" | \"invariants-csv\" | \"invariants-json\""
        )]
        format: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "ExportOptions")] options: JsValue,
    ) -> Result<String, JsValue> {
        export("RuledSurface.export", &format, options, self.core().flat(), None, Some(self.core()))
    }
}

#[wasm_bindgen]
impl LineCongruence {
    /// The lines as data: "json" (`{ "rows", "cols", "segments": [[…], …] }`), "csv" (row-major,
    /// the grid shape is not kept) or "obj" (vertices and line elements).
    pub fn export(
        &self,
        #[wasm_bindgen(unchecked_param_type = "\"csv\" | \"json\" | \"obj\"")] format: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "ExportOptions")] options: JsValue,
    ) -> Result<String, JsValue> {
        export(
            "LineCongruence.export",
            &format,
            options,
            self.core().flat(),
            Some((self.core().rows(), self.core().cols())),
            None,
        )
    }
}
