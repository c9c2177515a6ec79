//! Hidden lines for JavaScript: `hiddenLines(figure, options)`, the visible and hidden runs of a
//! figure's lines behind its meshes for the camera of the view, for the vector exports (SVG,
//! TikZ) of `www/export/`.

//!
//! The figure is read field by field (its typed arrays as they are) rather than by serde: the
//! option types below are declared for TypeScript only, and the checks name the same fields.

use glam::{DMat4, DVec3};
use js_sys::{Array, Float64Array, Object, Reflect, Uint32Array, Uint8Array};
use ruledlab::tolerance::MAX_HIDDEN_LINE_ITEMS;
use ruledlab::{HiddenLineOptions as CoreOptions, LineKind, View};
use ruledlab_js::args::{self, describe, fail, fail_option, to_js};
use ruledlab_js::timing::Measure;
use serde::Serialize;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

const F: &str = "hiddenLines";

/// What `hiddenLines` looks at: the camera, the meshes that hide, the lines that may be hidden.
#[derive(Tsify)]
#[serde(rename_all = "camelCase")]
#[allow(dead_code)]
struct HiddenLineFigure {
    /// The view-projection matrix, column-major (16 numbers, as WebGL takes it).
    #[tsify(type = "Float32Array | Float64Array | number[]")]
    view_proj: JsValue,
    /// The viewport's width in pixels.
    width: f64,
    /// The viewport's height in pixels.
    height: f64,
    /// The triangle meshes that hide lines.
    meshes: Vec<HiddenLineMesh>,
    /// The lines, in the order their runs come back.
    lines: Vec<HiddenLineSet>,
}

/// A mesh that hides lines: 3 numbers per vertex, 3 indices per triangle.
#[derive(Tsify)]
#[serde(rename_all = "camelCase")]
#[allow(dead_code)]
struct HiddenLineMesh {
    #[tsify(type = "Float32Array | Float64Array | number[]")]
    positions: JsValue,
    #[tsify(type = "Uint32Array | number[]")]
    indices: JsValue,
    /// A 4 × 4 model matrix, column-major, applied to the positions.
    #[tsify(optional, type = "Float32Array | Float64Array | number[]")]
    transform: JsValue,
}

/// Lines of one kind: segments (6 numbers each), a polyline (3 per point; a NaN point breaks it)
/// or dots (3 per point).
#[derive(Tsify)]
#[serde(rename_all = "camelCase")]
#[allow(dead_code)]
struct HiddenLineSet {
    #[tsify(type = "\"segments\" | \"polyline\" | \"points\"")]
    kind: String,
    #[tsify(type = "Float32Array | Float64Array | number[]")]
    positions: JsValue,
    /// A polyline: join the last point to the first.
    #[tsify(optional)]
    closed: bool,
    /// A 4 × 4 model matrix, column-major, applied to the positions.
    #[tsify(optional, type = "Float32Array | Float64Array | number[]")]
    transform: JsValue,
}

/// Options of `hiddenLines`.
#[derive(Tsify)]
#[serde(rename_all = "camelCase")]
#[allow(dead_code)]
struct HiddenLineOptions {
    /// Lines within this distance of a triangle's plane are not hidden by it, as a fraction of
    /// the diagonal of the meshes' bounding box (default 1e-3); a triangle's own tolerance is
    /// at least half of how far its neighbours bend away from its plane.
    #[tsify(optional)]
    tolerance: Option<f64>,
    /// Runs shorter than this many pixels between runs of the other kind are given to their
    /// neighbours (default 1).
    #[tsify(optional)]
    min_piece: Option<f64>,
}

/// The runs of one set of lines: run k has the points `runs[2k] … runs[2k] + runs[2k + 1] − 1`
/// (x, y pairs in pixels, y down) and is seen when `visible[k]` is 1.
#[derive(Serialize, Tsify)]
struct HiddenLineRuns {
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    points: Float64Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Uint32Array")]
    runs: Uint32Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Uint8Array")]
    visible: Uint8Array,
}

/// The result of `hiddenLines`: the runs of each set of lines, in the order given.
#[derive(Serialize, Tsify)]
struct HiddenLines {
    lines: Vec<HiddenLineRuns>,
}

/// The fields of a plain object (`what` in messages), refusing keys that are not in `known`.
fn object(what: &str, value: &JsValue, known: &[&str]) -> Result<(), JsValue> {
    let plain = value.is_object() && !Array::is_array(value) && !value.is_function();
    if !plain {
        return Err(fail(F, format!("{what} must be an object {{ {} }}, got {}", known.join(", "), describe(value))));
    }
    for key in Object::keys(value.unchecked_ref::<Object>()).iter() {
        let key = key.as_string().unwrap_or_default();
        if !known.contains(&key.as_str()) {
            return Err(fail_option(
                F,
                &key,
                format!("unknown field \"{key}\" of {what}; known fields: {}", known.join(", ")),
            ));
        }
    }
    Ok(())
}

fn field(value: &JsValue, name: &str) -> JsValue {
    Reflect::get(value, &JsValue::from_str(name)).unwrap_or(JsValue::UNDEFINED)
}

/// The elements of an array field.
fn array(what: &str, value: &JsValue) -> Result<Vec<JsValue>, JsValue> {
    match value.dyn_ref::<Array>() {
        Some(a) => Ok(a.iter().collect()),
        None => Err(fail_option(F, what, format!("{what} must be an array, got {}", describe(value)))),
    }
}

/// An optional finite number option.
fn finite(options: &JsValue, name: &str) -> Result<Option<f64>, JsValue> {
    let v = field(options, name);
    if v.is_undefined() {
        return Ok(None);
    }
    match v.as_f64() {
        Some(x) if x.is_finite() => Ok(Some(x)),
        _ => Err(fail_option(F, name, format!("options.{name} must be a finite number, got {}", describe(&v)))),
    }
}

/// World points from flat coordinates and an optional model matrix.
fn points(what: &str, positions: &JsValue, transform: &JsValue) -> Result<Vec<DVec3>, JsValue> {
    let coords = args::numbers(F, what, positions)?;
    if coords.len() % 3 != 0 {
        return Err(fail_option(F, what, format!("{what} must hold 3 numbers per point, got {}", coords.len())));
    }
    let model = if transform.is_undefined() || transform.is_null() {
        None
    } else {
        let m = args::numbers(F, "transform", transform)?;
        if m.len() != 16 || m.iter().any(|x| !x.is_finite()) {
            return Err(fail_option(
                F,
                "transform",
                "transform must be 16 finite numbers (a column-major 4 × 4 matrix)",
            ));
        }
        Some(DMat4::from_cols_slice(&m))
    };
    let world: Vec<DVec3> = coords.chunks_exact(3).map(DVec3::from_slice).collect();
    Ok(ruledlab::transformed(&world, model.as_ref()))
}

/// The visible and hidden runs of a figure's lines behind its meshes, for the camera given by
/// `figure.viewProj` on a `figure.width` × `figure.height` viewport: each set of lines comes
/// back as runs of pixel positions, each seen or hidden (docs/src/teaching/figures.md).
#[wasm_bindgen(js_name = hiddenLines, unchecked_return_type = "HiddenLines")]
pub fn hidden_lines(
    #[wasm_bindgen(unchecked_param_type = "HiddenLineFigure")] figure: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "HiddenLineOptions")] options: JsValue,
) -> Result<JsValue, JsValue> {
    let _measure = Measure::start(F);
    object("figure", &figure, &["viewProj", "width", "height", "meshes", "lines"])?;
    let matrix = args::numbers(F, "viewProj", &field(&figure, "viewProj"))?;
    let width = args::number(F, "width", &field(&figure, "width"))?;
    let height = args::number(F, "height", &field(&figure, "height"))?;
    let view = View::new(&matrix, width, height).map_err(|e| fail(F, e))?;
    let mut total = 0usize;
    let mut meshes = Vec::new();
    for mesh in array("meshes", &field(&figure, "meshes"))? {
        object("a mesh", &mesh, &["positions", "indices", "transform"])?;
        let p = points("positions", &field(&mesh, "positions"), &field(&mesh, "transform"))?;
        let idx = args::indices(F, "indices", &field(&mesh, "indices"))?;
        total += p.len() + idx.len();
        if total > 2 * MAX_HIDDEN_LINE_ITEMS {
            return Err(fail(
                F,
                ruledlab::Error::TooMany { what: "points", got: total, max: 2 * MAX_HIDDEN_LINE_ITEMS },
            ));
        }
        meshes.push((p, idx));
    }
    let mut lines = Vec::new();
    for set in array("lines", &field(&figure, "lines"))? {
        object("a set of lines", &set, &["kind", "positions", "closed", "transform"])?;
        let closed = args::optional_bool(F, "closed", &field(&set, "closed"), false)?;
        let kind = match field(&set, "kind").as_string().as_deref() {
            Some("segments") => LineKind::Segments,
            Some("polyline") => LineKind::Polyline { closed },
            Some("points") => LineKind::Points,
            _ => {
                return Err(fail_option(
                    F,
                    "kind",
                    format!(
                        "kind must be \"segments\", \"polyline\" or \"points\", got {}",
                        describe(&field(&set, "kind"))
                    ),
                ))
            }
        };
        let p = points("positions", &field(&set, "positions"), &field(&set, "transform"))?;
        if kind == LineKind::Segments && p.len() % 2 != 0 {
            return Err(fail_option(F, "positions", "segments need 6 numbers each"));
        }
        total += p.len();
        if total > 2 * MAX_HIDDEN_LINE_ITEMS {
            return Err(fail(
                F,
                ruledlab::Error::TooMany { what: "points", got: total, max: 2 * MAX_HIDDEN_LINE_ITEMS },
            ));
        }
        lines.push((kind, p));
    }
    let defaults = CoreOptions::default();
    let core = if options.is_undefined() || options.is_null() {
        defaults
    } else {
        object("options", &options, &["tolerance", "minPiece"])?;
        CoreOptions {
            tolerance: finite(&options, "tolerance")?.unwrap_or(defaults.tolerance),
            min_piece: finite(&options, "minPiece")?.unwrap_or(defaults.min_piece),
        }
    };
    let mesh_refs: Vec<(&[DVec3], &[u32])> = meshes.iter().map(|(p, i)| (&p[..], &i[..])).collect();
    let line_refs: Vec<(LineKind, &[DVec3])> = lines.iter().map(|(k, p)| (*k, &p[..])).collect();
    let result = ruledlab::hidden_lines(&view, &mesh_refs, &line_refs, core).map_err(|e| fail(F, e))?;
    let out = result
        .into_iter()
        .map(|runs| {
            let mut points = Vec::new();
            let mut starts = Vec::with_capacity(2 * runs.len());
            let mut visible = Vec::with_capacity(runs.len());
            for run in runs {
                starts.extend([(points.len() / 2) as u32, run.points.len() as u32]);
                points.extend(run.points.iter().flat_map(|p| [p.x, p.y]));
                visible.push(run.visible as u8);
            }
            HiddenLineRuns {
                points: Float64Array::from(&points[..]),
                runs: Uint32Array::from(&starts[..]),
                visible: Uint8Array::from(&visible[..]),
            }
        })
        .collect();
    to_js(F, &HiddenLines { lines: out })
}
