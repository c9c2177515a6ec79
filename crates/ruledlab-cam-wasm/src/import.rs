//! Reading the CAM module's data files: `importToolPoses` (tool poses, from the files CAM systems
//! and ruledlab write) and `importTarget` (a target curve). Which of them a text holds the
//! teaching module says (`detectImport`), so that the page loads this module only for these.

use crate::gcode_options;
use glam::DVec3;
use js_sys::{Float64Array, Uint32Array};
use ruledlab_cam::{read_target, read_tool_poses_for, ToolEnd};
use ruledlab_js::args::{fail, to_js};
use ruledlab_js::buffers::points_f64;
use ruledlab_js::text::{js_number, text_and_format};
use ruledlab_js::timing::Measure;
use serde::Serialize;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

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
    let o: PoseImportOptions = ruledlab_js::args::options(F, options)?;
    let machine = match o.machine.as_deref() {
        None => None,
        Some(name) => Some(gcode_options::preset(F, name)?),
    };
    let p = read_tool_poses_for(&text, json, &js_number, machine.as_ref()).map_err(|e| fail(F, e))?;
    let tool = p.tool.map(|t| ToolOut {
        radius: t.radius,
        length: t.length,
        end: match t.end {
            ToolEnd::Ball => "ball",
            ToolEnd::Flat => "flat",
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
    let t = read_target(&text, json, &js_number).map_err(|e| fail(F, e))?;
    to_js(F, &ImportedTarget { points: points_f64(&t.points), units: t.units })
}
