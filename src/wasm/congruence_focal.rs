//! `CongruenceFocal`: the focal geometry of a congruence's lines computed once
//! (`LineCongruence.focalGeometry()`), and everything a figure draws of it — the lines of each
//! kind, each focal sheet with its bounds, the torsal strokes — from that one computation.

use super::args::{self, fail, to_js};
use super::buffers::{points_f32, segments_f32};
use super::congruence::LineCongruence;
use super::focal::focal_js;
use super::live::Live;
use crate::congruence::focal::{self, Focal, FocalKind};
use crate::congruence::LineCongruence as CoreCongruence;
use js_sys::{Float32Array, Float64Array, Uint32Array};
use serde::Serialize;
use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &str = r#"
/** A focal sheet for WebGL with the box of its drawn vertices (`min`, `max`; NaN when nothing is drawn). */
export interface FocalSheetFigure { positions: Float32Array; indices: Uint32Array; normals: Float32Array; min: Float64Array; max: Float64Array }
"#;

/// The focal geometry of a congruence's lines, computed once (free it when done).
#[wasm_bindgen]
pub struct CongruenceFocal {
    grid: CoreCongruence,
    focal: Vec<Focal>,
    _live: Live,
}

/// `FocalSheetFigure`.
#[derive(Serialize)]
struct SheetJs {
    #[serde(with = "serde_wasm_bindgen::preserve")]
    positions: Float32Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    indices: Uint32Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    normals: Float32Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    min: Float64Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    max: Float64Array,
}

#[wasm_bindgen]
impl LineCongruence {
    /// The focal geometry of every line, computed once, with the figures drawn from it
    /// (`CongruenceFocal`): what `focal()`, `focalSheetF32` and `torsalStrokesF32` each compute
    /// anew.
    #[wasm_bindgen(js_name = focalGeometry)]
    pub fn focal_geometry(&self) -> CongruenceFocal {
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
        const F: &str = "CongruenceFocal.sheetF32";
        let sheet = args::integer(F, "sheet", &sheet, 1, 2)?;
        let mesh = focal::focal_sheet(&self.grid, &self.focal, sheet - 1);
        let normals = mesh.vertex_normals();
        let used = mesh.indices.iter().map(|&i| mesh.positions[i as usize]);
        let (min, max) = used
            .fold((glam::DVec3::splat(f64::INFINITY), glam::DVec3::splat(f64::NEG_INFINITY)), |(a, b), p| {
                (a.min(p), b.max(p))
            });
        let finite = |v: glam::DVec3| if v.is_finite() { v } else { glam::DVec3::NAN };
        to_js(
            F,
            &SheetJs {
                positions: points_f32(&mesh.positions),
                indices: Uint32Array::from(&mesh.indices[..]),
                normals: points_f32(&normals),
                min: Float64Array::from(&finite(min).to_array()[..]),
                max: Float64Array::from(&finite(max).to_array()[..]),
            },
        )
    }

    /// Strokes on the director surface d₁ along the real torsal directions, p ± scale·(du·p_i
    /// + dv·p_j) (`scale` default 0.35 of a grid step), as f32 segments.
    #[wasm_bindgen(js_name = strokesF32)]
    pub fn strokes_f32(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] scale: JsValue,
    ) -> Result<Float32Array, JsValue> {
        const F: &str = "CongruenceFocal.strokesF32";
        let scale = if scale.is_undefined() { 0.35 } else { args::number(F, "scale", &scale)? };
        if !(scale > 0.0 && scale <= 10.0) {
            return Err(fail(F, format!("scale must be a number in (0, 10], got {scale}")));
        }
        Ok(segments_f32(&focal::torsal_strokes(self.grid.rows(), self.grid.cols(), &self.grid.p(), &self.focal, scale)))
    }
}
