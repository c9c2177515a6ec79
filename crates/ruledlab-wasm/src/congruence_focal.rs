//! `CongruenceFocal` for JavaScript (beyond the paper): the focal geometry of a congruence's
//! lines computed once (`LineCongruence.focalGeometry()`), with the figures the page draws
//! from it.

use super::focal::{focal_js, sheet_figure, strokes};
use js_sys::Float32Array;
use ruledlab::{Focal, FocalKind};
use ruledlab_js::args;
use ruledlab_js::buffers::segments_f32;
use ruledlab_js::live::Live;
use wasm_bindgen::prelude::*;

/// The focal geometry of a congruence's lines, computed once (free it when done).
#[wasm_bindgen]
pub struct CongruenceFocal {
    grid: ruledlab::LineCongruence,
    focal: Vec<Focal>,
    _live: Live,
}

impl CongruenceFocal {
    /// The focal geometry `focal` of the lines of `grid`.
    pub(super) fn new(grid: ruledlab::LineCongruence, focal: Vec<Focal>) -> Self {
        CongruenceFocal { grid, focal, _live: Live::new() }
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
