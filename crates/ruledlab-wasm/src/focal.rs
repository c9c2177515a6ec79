//! Focal geometry of congruences as JavaScript objects (beyond the paper): the focal points,
//! kinds and torsal directions of every line (`FocalGeometry`), a focal sheet as a mesh
//! (`FocalSheetFigure`) and the torsal strokes, for `LineCongruence`, `AnalyticCongruence` and
//! `CongruenceFocal`. No JS class.

use glam::DVec3;
use js_sys::{Float32Array, Float64Array, Uint8Array};
use ruledlab::tolerance::MAX_STROKE_SCALE;
use ruledlab::Focal;
use ruledlab_js::args::{self, fail, to_js, to_js_with};
use ruledlab_js::buffers::{points_f32, segments_f32, MeshBuffers};
use serde::Serialize;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// The focal geometry of every line of a congruence (docs/src/guide/focal.md): a line runs
/// p → q, e = (q − p)/|q − p|, a point on it is p + t·e. Per line, row-major.
#[derive(Serialize, Tsify)]
struct FocalGeometry {
    rows: usize,
    cols: usize,
    /// 6 per line: the focal points F1 then F2 (NaN when not real or at infinity).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    points: Float64Array,
    /// 2 per line: t1 ≤ t2 (±Infinity for a focal point at infinity, NaN when not real).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    parameters: Float64Array,
    /// 1 per line: 0 elliptic (no real focal point), 1 hyperbolic (two), 2 parabolic (one
    /// double).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Uint8Array")]
    kind: Uint8Array,
    /// 4 per line: the unit torsal directions (du, dv) of F1 and of F2, in grid steps, du > 0
    /// (NaN when not real).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    torsal: Float64Array,
    /// 3 per line: the midpoint of the focal points (real for every kind; NaN if the quadratic
    /// degenerates).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    middle: Float64Array,
    /// 1 per line: |cos| of the angle between the focal planes, 0 for a normal congruence (NaN
    /// when not real).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    normality: Float64Array,
}

/// The focal geometry `all` of a rows × cols grid as a `FocalGeometry` object.
pub(super) fn focal_js(func: &str, rows: usize, cols: usize, all: &[Focal]) -> Result<JsValue, JsValue> {
    let f64s = |values: Vec<f64>| Float64Array::from(&values[..]);
    let kind: Vec<u8> = all.iter().map(|f| f.kind as u8).collect();
    to_js(
        func,
        &FocalGeometry {
            rows,
            cols,
            points: f64s(all.iter().flat_map(|f| f.points).flat_map(|p| p.to_array()).collect()),
            parameters: f64s(all.iter().flat_map(|f| f.parameters).collect()),
            kind: Uint8Array::from(&kind[..]),
            torsal: f64s(all.iter().flat_map(|f| f.torsal).flat_map(|w| w.to_array()).collect()),
            middle: f64s(all.iter().flat_map(|f| f.middle.to_array()).collect()),
            normality: f64s(all.iter().map(|f| f.normality).collect()),
        },
    )
}

/// A focal sheet for WebGL (positions, triangle indices, smooth vertex normals) with the box of
/// its drawn vertices.
#[derive(Tsify)]
#[allow(dead_code)] // the type is for TypeScript: `sheet_figure` sets the fields on the mesh's buffers
struct FocalSheetFigure {
    /// Positions and triangle indices.
    #[serde(flatten)]
    mesh: MeshBuffers,
    /// A unit normal per vertex, 3 floats each.
    #[tsify(type = "Float32Array")]
    normals: Float32Array,
    /// The least x, y, z of the drawn vertices (NaN when nothing is drawn).
    #[tsify(type = "Float64Array")]
    min: Float64Array,
    /// The greatest x, y, z of the drawn vertices (NaN when nothing is drawn).
    #[tsify(type = "Float64Array")]
    max: Float64Array,
}

/// Focal sheet `sheet` (1 or 2) of `grid` from its focal geometry `all`, with its box.
pub(super) fn sheet_figure(
    func: &str,
    grid: &ruledlab::LineCongruence,
    all: &[Focal],
    sheet: &JsValue,
) -> Result<JsValue, JsValue> {
    let sheet = args::integer(func, "sheet", sheet, 1, 2)?;
    let mesh = ruledlab::focal_sheet(grid, all, sheet - 1);
    let normals = mesh.vertex_normals();
    let used = mesh.indices.iter().map(|&i| mesh.positions[i as usize]);
    let (min, max) =
        used.fold((DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)), |(a, b), p| (a.min(p), b.max(p)));
    let finite = |v: DVec3| if v.is_finite() { v } else { DVec3::NAN };
    let more = [
        ("normals", points_f32(&normals).into()),
        ("min", Float64Array::from(&finite(min).to_array()[..]).into()),
        ("max", Float64Array::from(&finite(max).to_array()[..]).into()),
    ];
    to_js_with(func, &MeshBuffers::of(&mesh), &more)
}

/// Torsal strokes of `grid` from its focal geometry `all`, `scale` (default 0.35) of a grid step.
pub(super) fn strokes(
    func: &str,
    grid: &ruledlab::LineCongruence,
    all: &[Focal],
    scale: &JsValue,
) -> Result<Float32Array, JsValue> {
    let scale = if scale.is_undefined() { 0.35 } else { args::number(func, "scale", scale)? };
    if !(scale > 0.0 && scale <= MAX_STROKE_SCALE) {
        return Err(fail(func, format!("scale must be a number in (0, {MAX_STROKE_SCALE}], got {scale}")));
    }
    Ok(segments_f32(&ruledlab::torsal_strokes(grid.rows(), grid.cols(), &grid.p(), all, scale)))
}
