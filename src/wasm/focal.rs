//! Focal geometry of congruences and linear complexes for JavaScript (beyond the paper):
//! `LineCongruence.focal()`, `AnalyticCongruence.focal()`, the focal sheets and torsal strokes
//! the page draws, and `linearComplex` of segments, surfaces and congruences.

use super::args::{self, fail, to_js};
use super::buffers::{points_f32, segments_f32};
use super::catalogue::AnalyticCongruence;
use super::congruence::LineCongruence;
use super::live::Live;
use super::timing::Measure;
use crate::congruence::focal::{self, Focal, FocalKind};
use crate::congruence::LineCongruence as CoreCongruence;
use crate::tolerance::{MAX_RULINGS, MAX_STROKE_SCALE};
use glam::DVec3;
use js_sys::{Float32Array, Float64Array, Uint32Array, Uint8Array};
use serde::Serialize;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// The focal geometry of every line of a congruence (README, "Focal geometry"): a line runs
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

#[wasm_bindgen]
impl LineCongruence {
    /// The focal geometry of every line: focal points and parameters, kind, torsal
    /// directions, middle points and normality (`FocalGeometry`), from the lines' Plücker
    /// coordinates differenced over the grid (second order, at the boundary too).
    #[wasm_bindgen(unchecked_return_type = "FocalGeometry")]
    pub fn focal(&self) -> Result<JsValue, JsValue> {
        let _measure = Measure::start("LineCongruence.focal");
        let c = self.core();
        focal_js("LineCongruence.focal", c.rows(), c.cols(), &focal::focal_grid(c.rows(), c.cols(), &c.p(), &c.q()))
    }

    /// Focal sheet 1 (of t1) or 2 (of t2) as a mesh with vertex normals and the box of its drawn
    /// vertices (`FocalSheetFigure`, as `focalGeometry().sheetF32(sheet)`): the grid's quads
    /// whose four focal points are real and within three bounding-box diagonals of the lines'
    /// centre.
    #[wasm_bindgen(js_name = focalSheetF32, unchecked_return_type = "FocalSheetFigure")]
    pub fn focal_sheet_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "1 | 2")] sheet: JsValue,
    ) -> Result<JsValue, JsValue> {
        let c = self.core();
        sheet_figure("LineCongruence.focalSheetF32", c, &focal::focal_grid(c.rows(), c.cols(), &c.p(), &c.q()), &sheet)
    }

    /// Strokes on the director surface d₁ along the real torsal directions, p ± scale·(du·p_i
    /// + dv·p_j) (`scale` default 0.35 of a grid step), as f32 segments.
    #[wasm_bindgen(js_name = torsalStrokesF32)]
    pub fn torsal_strokes_f32(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] scale: JsValue,
    ) -> Result<Float32Array, JsValue> {
        let c = self.core();
        strokes("LineCongruence.torsalStrokesF32", c, &focal::focal_grid(c.rows(), c.cols(), &c.p(), &c.q()), &scale)
    }
}

#[wasm_bindgen]
impl AnalyticCongruence {
    /// The exact focal geometry at the lines of its rows × cols grid (default: the paper's
    /// grid size), from the exact derivatives, torsal directions in grid steps: comparable
    /// line by line with `grid(rows, cols).focal()`.
    #[wasm_bindgen(unchecked_return_type = "FocalGeometry")]
    pub fn focal(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] rows: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] cols: JsValue,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "AnalyticCongruence.focal";
        let _measure = Measure::start(F);
        let (_, _, r0, c0) = self.core().domain();
        let rows = args::optional_integer(F, "rows", &rows, 2, MAX_RULINGS, r0)?;
        let cols = args::optional_integer(F, "cols", &cols, 2, MAX_RULINGS, c0)?;
        if rows.saturating_mul(cols) > MAX_RULINGS {
            let got = rows.saturating_mul(cols);
            return Err(fail(F, crate::Error::TooMany { what: "lines", got, max: MAX_RULINGS }));
        }
        focal_js(F, rows, cols, &focal::focal_analytic(self.core(), rows, cols))
    }
}

/// The focal geometry of a congruence's lines, computed once (free it when done).
#[wasm_bindgen]
pub struct CongruenceFocal {
    grid: CoreCongruence,
    focal: Vec<Focal>,
    _live: Live,
}

/// A focal sheet for WebGL (positions, triangle indices, smooth vertex normals) with the box of
/// its drawn vertices.
#[derive(Serialize, Tsify)]
struct FocalSheetFigure {
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float32Array")]
    positions: Float32Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Uint32Array")]
    indices: Uint32Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float32Array")]
    normals: Float32Array,
    /// The least x, y, z of the drawn vertices (NaN when nothing is drawn).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    min: Float64Array,
    /// The greatest x, y, z of the drawn vertices (NaN when nothing is drawn).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    max: Float64Array,
}

#[wasm_bindgen]
impl LineCongruence {
    /// The focal geometry of every line, computed once, with the figures drawn from it
    /// (`CongruenceFocal`): what `focal()`, `focalSheetF32` and `torsalStrokesF32` each compute
    /// anew.
    #[wasm_bindgen(js_name = focalGeometry)]
    pub fn focal_geometry(&self) -> CongruenceFocal {
        let _measure = Measure::start("LineCongruence.focalGeometry");
        let c = self.core();
        CongruenceFocal {
            grid: c.clone(),
            focal: focal::focal_grid(c.rows(), c.cols(), &c.p(), &c.q()),
            _live: Live::new(),
        }
    }
}

#[wasm_bindgen]
impl CongruenceFocal {
    /// Per line, row-major: focal points and parameters, kind, torsal directions, middle
    /// points and normality (`FocalGeometry`, as `LineCongruence.focal()`).
    #[wasm_bindgen(unchecked_return_type = "FocalGeometry")]
    pub fn result(&self) -> Result<JsValue, JsValue> {
        focal_js("CongruenceFocal.result", self.grid.rows(), self.grid.cols(), &self.focal)
    }

    /// How many lines are elliptic, hyperbolic and parabolic (in that order).
    pub fn counts(&self) -> Vec<u32> {
        let count = |k: FocalKind| self.focal.iter().filter(|f| f.kind == k).count() as u32;
        vec![count(FocalKind::Elliptic), count(FocalKind::Hyperbolic), count(FocalKind::Parabolic)]
    }

    /// The lines of one kind (0 elliptic, 1 hyperbolic, 2 parabolic) as f32 segments p → q.
    #[wasm_bindgen(js_name = linesOfKindF32)]
    pub fn lines_of_kind_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "0 | 1 | 2")] kind: JsValue,
    ) -> Result<Float32Array, JsValue> {
        let kind = args::integer("CongruenceFocal.linesOfKindF32", "kind", &kind, 0, 2)?;
        let cols = self.grid.cols();
        let lines: Vec<_> = (0..self.focal.len())
            .filter(|&k| self.focal[k].kind as usize == kind)
            .map(|k| self.grid.line(k / cols, k % cols))
            .collect();
        Ok(segments_f32(&lines))
    }

    /// Focal sheet 1 (of t1) or 2 (of t2) as a mesh with vertex normals and the box of the
    /// vertices its triangles use (what a view frames): the grid's quads whose four focal
    /// points are real and near the lines.
    #[wasm_bindgen(js_name = sheetF32, unchecked_return_type = "FocalSheetFigure")]
    pub fn sheet_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "1 | 2")] sheet: JsValue,
    ) -> Result<JsValue, JsValue> {
        sheet_figure("CongruenceFocal.sheetF32", &self.grid, &self.focal, &sheet)
    }

    /// Strokes on the director surface d₁ along the real torsal directions, p ± scale·(du·p_i
    /// + dv·p_j) (`scale` default 0.35 of a grid step), as f32 segments.
    #[wasm_bindgen(js_name = strokesF32)]
    pub fn strokes_f32(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] scale: JsValue,
    ) -> Result<Float32Array, JsValue> {
        strokes("CongruenceFocal.strokesF32", &self.grid, &self.focal, &scale)
    }
}

/// Focal sheet `sheet` (1 or 2) of `grid` from its focal geometry `all`, with its box.
fn sheet_figure(func: &str, grid: &CoreCongruence, all: &[Focal], sheet: &JsValue) -> Result<JsValue, JsValue> {
    let sheet = args::integer(func, "sheet", sheet, 1, 2)?;
    let mesh = focal::focal_sheet(grid, all, sheet - 1);
    let normals = mesh.vertex_normals();
    let used = mesh.indices.iter().map(|&i| mesh.positions[i as usize]);
    let (min, max) =
        used.fold((DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)), |(a, b), p| (a.min(p), b.max(p)));
    let finite = |v: DVec3| if v.is_finite() { v } else { DVec3::NAN };
    to_js(
        func,
        &FocalSheetFigure {
            positions: points_f32(&mesh.positions),
            indices: Uint32Array::from(&mesh.indices[..]),
            normals: points_f32(&normals),
            min: Float64Array::from(&finite(min).to_array()[..]),
            max: Float64Array::from(&finite(max).to_array()[..]),
        },
    )
}

/// Torsal strokes of `grid` from its focal geometry `all`, `scale` (default 0.35) of a grid step.
fn strokes(func: &str, grid: &CoreCongruence, all: &[Focal], scale: &JsValue) -> Result<Float32Array, JsValue> {
    let scale = if scale.is_undefined() { 0.35 } else { args::number(func, "scale", scale)? };
    if !(scale > 0.0 && scale <= MAX_STROKE_SCALE) {
        return Err(fail(func, format!("scale must be a number in (0, {MAX_STROKE_SCALE}], got {scale}")));
    }
    Ok(segments_f32(&focal::torsal_strokes(grid.rows(), grid.cols(), &grid.p(), all, scale)))
}
