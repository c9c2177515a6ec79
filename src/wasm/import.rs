//! Reading data files JavaScript hands in as text: `importSegments` (segments as CSV or JSON),
//! `importToolPoses` (tool poses) and `detectImport` (which of the two a text holds).

use super::args::{describe, fail, to_js};
use super::buffers::points_f64;
use super::timing::Measure;
use crate::io;
use crate::milling;
use glam::DVec3;
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
        "csv" => io::csv::read_csv_with(&text, &js_number),
        "json" => io::json::read_json_with(&text, &js_number),
        other => return Err(fail(F, format!("format must be \"csv\" or \"json\", got \"{other}\""))),
    }
    .map_err(|e| fail(F, e))?;
    let (rows, cols) = imported.grid.map_or((None, None), |(r, c)| (Some(r), Some(c)));
    to_js(F, &ImportedSegments { segments: Float64Array::from(&imported.coords[..]), rows, cols })
}

/// Tool poses read by `importToolPoses`.
#[derive(Serialize, Tsify)]
struct ImportedPoses {
    /// Tips, 3 numbers per pose.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    tips: Float64Array,
    /// Unit axes, 3 numbers per pose.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    axes: Float64Array,
    /// Tip and unit axis, 6 numbers per pose (what `ToolPath.fromPoses` reads).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    poses: Float64Array,
    /// The tool, where the file names one (ruledlab's own files).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    tool: Option<ToolOut>,
}

/// A tool as a file names it.
#[derive(Serialize, Tsify)]
struct ToolOut {
    radius: f64,
    length: f64,
    /// "ball" or "flat".
    #[tsify(type = "\"ball\" | \"flat\"")]
    end: &'static str,
}

/// Reads tool poses from CSV (tip x, y, z, axis i, j, k per row) or JSON (`{ poses: [{ tip,
/// axis }], tool? }`), ruledlab's own tool-path files included (with their tool). `format`
/// defaults to JSON when the text starts with `[` or `{`, else CSV.
#[wasm_bindgen(js_name = importToolPoses, unchecked_return_type = "ImportedPoses")]
pub fn import_tool_poses(
    #[wasm_bindgen(unchecked_param_type = "string")] text: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "\"csv\" | \"json\"")] format: JsValue,
) -> Result<JsValue, JsValue> {
    const F: &str = "importToolPoses";
    let _measure = Measure::start(F);
    let Some(text) = text.as_string() else {
        return Err(fail(F, format!("text must be a string, got {}", describe(&text))));
    };
    let json = match format.as_string().as_deref() {
        None if format.is_undefined() || format.is_null() => text.trim_start().starts_with(['[', '{']),
        Some("json") => true,
        Some("csv") => false,
        _ => return Err(fail(F, format!("format must be \"csv\" or \"json\", got {}", describe(&format)))),
    };
    let p = io::toolpath::read_tool_poses(&text, json, &js_number).map_err(|e| fail(F, e))?;
    let tool = p.tool.map(|t| ToolOut {
        radius: t.radius,
        length: t.length,
        end: match t.end {
            milling::ToolEnd::Ball => "ball",
            milling::ToolEnd::Flat => "flat",
        },
    });
    let poses: Vec<DVec3> = p.tips.iter().zip(&p.axes).flat_map(|(&t, &a)| [t, a]).collect();
    to_js(F, &ImportedPoses { tips: points_f64(&p.tips), axes: points_f64(&p.axes), poses: points_f64(&poses), tool })
}

/// What an imported text holds: "poses" (tool poses: JSON with poses or tips, CSV from
/// ruledlab's tool-path export or with a tip/axis header) or "segments".
#[wasm_bindgen(js_name = detectImport, unchecked_return_type = "\"poses\" | \"segments\"")]
pub fn detect_import(#[wasm_bindgen(unchecked_param_type = "string")] text: JsValue) -> Result<String, JsValue> {
    let Some(text) = text.as_string() else {
        return Err(fail("detectImport", format!("text must be a string, got {}", describe(&text))));
    };
    Ok(if io::toolpath::looks_like_poses(&text) { "poses" } else { "segments" }.to_string())
}
