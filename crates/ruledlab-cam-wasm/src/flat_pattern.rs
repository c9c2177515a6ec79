//! `FlatPattern` for JavaScript (the CAM module: the strip comes as its segments, 6 numbers per
//! ruling): a strip unfolded onto the plane — exactly for a developable strip
//! (an isometry, checked), or by Section 3's approximate development with the gaps it leaves — its
//! overlaps and pieces, and its sheet for cutting as SVG (1:1 in millimetres, or tiled on A4/Letter
//! pages) and DXF R12 (the core's `developable` and `io::sheet_svg`, `io::sheet_dxf`).

use super::developable::strip;
use glam::DVec2;
use js_sys::{Array, Float32Array, Float64Array, Uint32Array};
use ruledlab::tolerance::{PAGE_MARGIN_MM, PAGE_OVERLAP_MM};
use ruledlab::{ApproximatePattern, Paper, Sheet, SheetOptions, Unfolding};
use ruledlab_js::args::{self, fail, fail_option};
use ruledlab_js::live::Live;
use ruledlab_js::timing::Measure;
use serde::Deserialize;
use std::ops::Range;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// How a flat pattern is laid out for cutting (every field optional).
#[derive(Deserialize, Tsify)]
#[serde(default, rename_all = "camelCase")]
pub struct PatternOptions {
    /// Millimetres per unit of the model (default 50).
    scale: f64,
    /// Glue tabs where the pattern was split and where a closed strip meets itself (default true).
    tabs: bool,
    /// A tab's width, millimetres (default 8).
    tab: f64,
    /// The kerf, millimetres: the cut line runs half of it outside the outline (default 0).
    kerf: f64,
    /// Rulings bent through more than this angle (radians) are score lines (default 10°).
    fold_angle: f64,
    /// The free border round the sheet and between pieces, millimetres (default 10).
    margin: f64,
    /// The paper of a tiled print (`pages()`): "a4" (default) or "letter".
    #[tsify(type = "\"a4\" | \"letter\"")]
    paper: String,
}

impl Default for PatternOptions {
    /// The core's sheet defaults, on A4.
    fn default() -> Self {
        let SheetOptions { scale, tabs, tab, kerf, fold_angle, margin } = SheetOptions::default();
        PatternOptions { scale, tabs, tab, kerf, fold_angle, margin, paper: "a4".into() }
    }
}

impl PatternOptions {
    /// The core's options of the sheet (all but the paper).
    fn sheet(&self) -> SheetOptions {
        let PatternOptions { scale, tabs, tab, kerf, fold_angle, margin, paper: _ } = *self;
        SheetOptions { scale, tabs, tab, kerf, fold_angle, margin }
    }
}

/// A strip unfolded onto the plane: the images A_i, B_i of its rulings' ends.
#[wasm_bindgen]
pub struct FlatPattern {
    surface: ruledlab::RuledSurface,
    points: Vec<DVec2>,
    approximate: Option<ApproximatePattern>,
    isometry: ruledlab::IsometryError,
    overlaps: Vec<(usize, usize)>,
    pieces: Vec<Range<usize>>,
    _live: Live,
}

impl FlatPattern {
    fn new(surface: &ruledlab::RuledSurface, points: Vec<DVec2>, approximate: Option<ApproximatePattern>) -> Self {
        let isometry = ruledlab::isometry_error(surface, &points);
        let overlaps = ruledlab::overlapping_faces(&points);
        let pieces = ruledlab::pieces(&points, &overlaps);
        FlatPattern { surface: surface.clone(), points, approximate, isometry, overlaps, pieces, _live: Live::new() }
    }

    fn sheet(&self, f: &str, options: JsValue) -> Result<(Sheet, Paper), JsValue> {
        let o: PatternOptions = args::options(f, options)?;
        let paper = match o.paper.as_str() {
            "a4" => Paper::A4,
            "letter" => Paper::LETTER,
            other => {
                return Err(fail_option(
                    f,
                    "paper",
                    format!("options.paper must be \"a4\" or \"letter\", got \"{other}\""),
                ))
            }
        };
        let sheet = Sheet::lay_out(&self.surface, &self.points, &self.pieces, &o.sheet()).map_err(|e| fail(f, e))?;
        Ok((sheet, paper))
    }
}

#[wasm_bindgen]
impl FlatPattern {
    /// The exact unfolding of a developable strip (its segments): every face laid into the plane beside the one
    /// before, every length and angle kept (`isometryLength`, `isometryAngle` say how well).
    /// Throws `degenerate` with reason `not-developable` for a strip with a pair of rulings that
    /// is not coplanar (use `approximate`), and `rulings-collinear` for a face without width.
    pub fn unfold(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] segments: JsValue,
    ) -> Result<FlatPattern, JsValue> {
        const F: &str = "FlatPattern.unfold";
        let _measure = Measure::start(F);
        let surface = strip(F, &segments)?;
        let flat = Unfolding::of(&surface).map_err(|e| fail(F, e))?;
        Ok(FlatPattern::new(&surface, flat.points, None))
    }

    /// Section 3's approximate development of any strip (its conoidal model projected): the
    /// rulings keep their lengths and angles, the distances h between them are dropped — the
    /// `gaps` a paper model of it cannot close.
    pub fn approximate(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] segments: JsValue,
    ) -> Result<FlatPattern, JsValue> {
        const F: &str = "FlatPattern.approximate";
        let _measure = Measure::start(F);
        let surface = strip(F, &segments)?;
        let a = ApproximatePattern::of(&surface);
        Ok(FlatPattern::new(&surface, a.points.clone(), Some(a)))
    }

    /// Whether the pattern is the exact unfolding (not the approximate development).
    #[wasm_bindgen(getter)]
    pub fn exact(&self) -> bool {
        self.approximate.is_none()
    }

    /// The images A_0, B_0, A_1, B_1, …: 4 numbers (x, y of A_i, then of B_i) per ruling.
    pub fn points(&self) -> Float64Array {
        Float64Array::from(bytemuck::cast_slice::<_, f64>(&self.points))
    }

    /// The largest relative change of a distance between corners of a face, pattern against strip.
    #[wasm_bindgen(getter, js_name = isometryLength)]
    pub fn isometry_length(&self) -> f64 {
        self.isometry.length
    }

    /// The largest change of a corner angle of a face, radians.
    #[wasm_bindgen(getter, js_name = isometryAngle)]
    pub fn isometry_angle(&self) -> f64 {
        self.isometry.angle
    }

    /// The gap of each pair of consecutive rulings (N − 1 numbers; all 0 for the exact unfolding).
    pub fn gaps(&self) -> Float64Array {
        match &self.approximate {
            Some(a) => Float64Array::from(&a.gaps[..]),
            None => Float64Array::from(&vec![0.0; self.points.len() / 2 - 1][..]),
        }
    }

    /// The sum of the gaps: how far the paper's last ruling stays from where the strip puts it.
    #[wasm_bindgen(getter)]
    pub fn climb(&self) -> f64 {
        self.approximate.as_ref().map_or(0.0, |a| a.climb)
    }

    /// Pairs of faces (i, j) whose interiors overlap in the plane, 2 numbers each.
    pub fn overlaps(&self) -> Uint32Array {
        let flat: Vec<u32> = self.overlaps.iter().flat_map(|&(i, j)| [i as u32, j as u32]).collect();
        Uint32Array::from(&flat[..])
    }

    /// The pieces the pattern is cut into so that none overlaps itself: first and last ruling of
    /// each, 2 numbers each (one piece when nothing overlaps).
    pub fn pieces(&self) -> Uint32Array {
        let flat: Vec<u32> = self.pieces.iter().flat_map(|r| [r.start as u32, r.end as u32]).collect();
        Uint32Array::from(&flat[..])
    }

    /// Line segments for WebGL, 6 floats per segment (x, y, 0 at both ends): every ruling and the
    /// edges A_i A_{i+1}, B_i B_{i+1}; with `overlapping` only the edges of faces that overlap
    /// another.
    pub fn segments(&self, overlapping: Option<bool>) -> Float32Array {
        let n = self.points.len() / 2;
        let p = &self.points;
        let mut out: Vec<f32> = Vec::with_capacity(18 * n);
        let mut push = |a: DVec2, b: DVec2| out.extend([a.x as f32, a.y as f32, 0.0, b.x as f32, b.y as f32, 0.0]);
        if overlapping == Some(true) {
            let mut faces: Vec<usize> = self.overlaps.iter().flat_map(|&(i, j)| [i, j]).collect();
            faces.sort_unstable();
            faces.dedup();
            for i in faces {
                push(p[2 * i], p[2 * i + 2]);
                push(p[2 * i + 1], p[2 * i + 3]);
                push(p[2 * i], p[2 * i + 1]);
                push(p[2 * i + 2], p[2 * i + 3]);
            }
        } else {
            for i in 0..n {
                push(p[2 * i], p[2 * i + 1]);
                if i + 1 < n {
                    push(p[2 * i], p[2 * i + 2]);
                    push(p[2 * i + 1], p[2 * i + 3]);
                }
            }
        }
        Float32Array::from(&out[..])
    }

    /// The pattern laid out on one sheet as SVG at 1:1 in millimetres: cut (red), score (blue,
    /// dashed) and ruling (grey) strokes, piece numbers and glue letters, a 100 mm check square.
    pub fn svg(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "PatternOptions")] options: JsValue,
    ) -> Result<String, JsValue> {
        let (sheet, _) = self.sheet("FlatPattern.svg", options)?;
        Ok(ruledlab::sheet_svg(&sheet))
    }

    /// The sheet as DXF R12 in millimetres, layers CUT, SCORE, RULING, TEXT and CHECK.
    pub fn dxf(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "PatternOptions")] options: JsValue,
    ) -> Result<String, JsValue> {
        let (sheet, _) = self.sheet("FlatPattern.dxf", options)?;
        Ok(ruledlab::sheet_dxf(&sheet))
    }

    /// The sheet tiled on pages of `options.paper` (10 mm margins, overlapping by 10 mm, with
    /// registration marks): one SVG per page, row by row from the top.
    #[wasm_bindgen(unchecked_return_type = "string[]")]
    pub fn pages(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "PatternOptions")] options: JsValue,
    ) -> Result<Array, JsValue> {
        const F: &str = "FlatPattern.pages";
        let (sheet, paper) = self.sheet(F, options)?;
        let tiling = ruledlab::tile(sheet.size, paper, PAGE_MARGIN_MM, PAGE_OVERLAP_MM).map_err(|e| fail(F, e))?;
        Ok((0..tiling.tiles.len()).map(|k| JsValue::from(ruledlab::page_svg(&sheet, &tiling, k))).collect())
    }
}
