//! Reading data files JavaScript hands in as text: `importSegments` (segments as CSV or JSON),
//! `importToolPoses` (tool poses), `importTarget` (a target curve) and `detectImport` (which of
//! them a text holds).

use super::args::{describe, fail, to_js};
use super::buffers::points_f64;
use super::timing::Measure;
use crate::io;
use crate::milling;
use glam::DVec3;
use js_sys::{Float64Array, Uint32Array};
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

/// The text an import reads and whether it is JSON: `format` "json" or "csv", or, left out, JSON
/// when the text starts with `[` or `{`. Throws (as `f`) for a text that is not a string or
/// another format.
fn text_and_format(f: &str, text: JsValue, format: &JsValue) -> Result<(String, bool), JsValue> {
    let Some(text) = text.as_string() else {
        return Err(fail(f, format!("text must be a string, got {}", describe(&text))));
    };
    let json = match format.as_string().as_deref() {
        None if format.is_undefined() || format.is_null() => text.trim_start().starts_with(['[', '{']),
        Some("json") => true,
        Some("csv") => false,
        Some(other) => return Err(fail(f, format!("format must be \"csv\" or \"json\", got \"{other}\""))),
        None => return Err(fail(f, format!("format must be \"csv\" or \"json\", got {}", describe(format)))),
    };
    Ok((text, json))
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
        if json { io::json::read_json_with(&text, &js_number) } else { io::csv::read_csv_with(&text, &js_number) }
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
    /// The 1-based line of each pose in the text.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Uint32Array")]
    lines: Uint32Array,
    /// "mm" or "inch" where the file says so (`# units: inch`, JSON `"units"`).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional, type = "\"mm\" | \"inch\"")]
    units: Option<String>,
    /// The machine whose rotary angles the file gives (`x,y,z,a,b,c` columns), where it gives
    /// angles.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    machine: Option<String>,
}

/// Options of `importToolPoses`.
#[derive(serde::Deserialize, Default, Tsify)]
#[serde(default)]
struct PoseImportOptions {
    /// The machine whose rotary angles a CSV's a, b, c columns are (a preset's name), where the
    /// file names none (`# machine: …`).
    #[tsify(optional, type = "\"table-table-ac\" | \"table-table-bc\" | \"head-table-bc\" | \"head-head-ac\"")]
    machine: Option<String>,
}

/// A target curve read by `importTarget`.
#[derive(Serialize, Tsify)]
struct ImportedTarget {
    /// The points, 3 numbers each.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    points: Float64Array,
    /// "mm" or "inch" where the file says so.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional, type = "\"mm\" | \"inch\"")]
    units: Option<String>,
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

/// Reads tool poses from CSV (tip x, y, z, axis i, j, k per row; a header naming the columns
/// as CAM systems do, `x,y,z,i,j,k` in any order; or `x,y,z,a,b,c`, rotary angles in degrees of
/// the machine the file names in `# machine: …` or `options.machine`) or JSON (`{ poses: [{ tip,
/// axis }], tool?, units? }`), ruledlab's own tool-path files included (with their tool).
/// `format` defaults to JSON when the text starts with `[` or `{`, else CSV.
#[wasm_bindgen(js_name = importToolPoses, unchecked_return_type = "ImportedPoses")]
pub fn import_tool_poses(
    #[wasm_bindgen(unchecked_param_type = "string")] text: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "\"csv\" | \"json\"")] format: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "PoseImportOptions")] options: JsValue,
) -> Result<JsValue, JsValue> {
    const F: &str = "importToolPoses";
    let _measure = Measure::start(F);
    let (text, json) = text_and_format(F, text, &format)?;
    let o: PoseImportOptions = super::args::options(F, options)?;
    let machine = match o.machine.as_deref() {
        None => None,
        Some(name) => Some(super::gcode_options::preset(F, name)?),
    };
    let p = io::toolpath::read_tool_poses_for(&text, json, &js_number, machine.as_ref()).map_err(|e| fail(F, e))?;
    let tool = p.tool.map(|t| ToolOut {
        radius: t.radius,
        length: t.length,
        end: match t.end {
            milling::ToolEnd::Ball => "ball",
            milling::ToolEnd::Flat => "flat",
        },
    });
    let poses: Vec<DVec3> = p.tips.iter().zip(&p.axes).flat_map(|(&t, &a)| [t, a]).collect();
    let lines: Vec<u32> = p.lines.iter().map(|&l| l.min(u32::MAX as usize) as u32).collect();
    to_js(
        F,
        &ImportedPoses {
            tips: points_f64(&p.tips),
            axes: points_f64(&p.axes),
            poses: points_f64(&poses),
            tool,
            lines: Uint32Array::from(&lines[..]),
            units: p.units,
            machine: p.machine,
        },
    )
}

/// Reads a target curve — the edge or contact curve the tool should machine — from CSV (x, y, z
/// per row, an optional header, `# units: inch`) or JSON (`[[x, y, z], …]` or `{ points, units?
/// }`). `format` defaults to JSON when the text starts with `[` or `{`, else CSV.
#[wasm_bindgen(js_name = importTarget, unchecked_return_type = "ImportedTarget")]
pub fn import_target(
    #[wasm_bindgen(unchecked_param_type = "string")] text: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "\"csv\" | \"json\"")] format: JsValue,
) -> Result<JsValue, JsValue> {
    const F: &str = "importTarget";
    let (text, json) = text_and_format(F, text, &format)?;
    let t = io::target::read_target(&text, json, &js_number).map_err(|e| fail(F, e))?;
    to_js(F, &ImportedTarget { points: points_f64(&t.points), units: t.units })
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
    Ok(if io::toolpath::looks_like_poses(&text) {
        "poses"
    } else if io::target::looks_like_target(&text) {
        "target"
    } else {
        "segments"
    }
    .to_string())
}
