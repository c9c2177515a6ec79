//! Reading data files JavaScript hands in as text: `importSegments` (segments as CSV or JSON) and
//! `detectImport` (what a text holds: segments, or tool poses or a target curve, which the CAM
//! module reads: `importToolPoses`, `importTarget`).

use ruledlab_js::args::{describe, fail, to_js};
use ruledlab_js::text::{js_number, text_and_format};

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
    let (text, json) = text_and_format(F, text, &format)?;
    let imported =
        if json { ruledlab::read_json_with(&text, &js_number) } else { ruledlab::read_csv_with(&text, &js_number) }
            .map_err(|e| fail(F, e))?;
    let (rows, cols) = imported.grid.map_or((None, None), |(r, c)| (Some(r), Some(c)));
    to_js(F, &ImportedSegments { segments: Float64Array::from(&imported.coords[..]), rows, cols })
}

/// What an imported text holds: "poses" (tool poses: JSON with poses or tips, CSV from
/// ruledlab's tool-path export or whose header names a tip and an axis, `x,y,z,i,j,k` or
/// `x,y,z,a,b,c`), "target" (a target curve: JSON with "points", CSV of 3 numbers a line) or
/// "segments".
#[wasm_bindgen(js_name = detectImport, unchecked_return_type = "\"poses\" | \"segments\" | \"target\"")]
pub fn detect_import(#[wasm_bindgen(unchecked_param_type = "string")] text: JsValue) -> Result<String, JsValue> {
    let Some(text) = text.as_string() else {
        return Err(fail("detectImport", format!("text must be a string, got {}", describe(&text))));
    };
    Ok(ruledlab::detect_import(&text).to_string())
}
