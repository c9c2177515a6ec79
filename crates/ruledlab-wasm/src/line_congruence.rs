//! `LineCongruence` for JavaScript: a discrete line congruence, a grid of lines (Section 5),
//! its subdivision, its rows and columns as ruled surfaces, its focal geometry (beyond the
//! paper), the buffers the page draws of it, its best-fitting linear complex and its export as
//! data.

use super::congruence_focal::CongruenceFocal;
use super::export::export;
use super::focal::{focal_js, sheet_figure, strokes};
use super::linear_complex::complex_js;
use super::ruled_surface::RuledSurface;
use js_sys::{Float32Array, Float64Array};
use ruledlab::tolerance::{MAX_CONGRUENCE_STEPS, MAX_PARTS, MAX_RULINGS, MAX_STRIDE};
use ruledlab::CongruenceScheme;
use ruledlab::Segment;
use ruledlab_js::args::{self, fail, finite_option, integer, integer_option, numbers, only_for};
use ruledlab_js::buffers::{self, points_f32, Lines};
use ruledlab_js::line_buffers;
use ruledlab_js::live::Live;
use ruledlab_js::subdivide_options::SubdivisionSpace;
use ruledlab_js::timing::Measure;
use serde::Deserialize;
use std::borrow::Cow;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// Options of `LineCongruence.subdivide` (Section 5).
#[derive(Deserialize, Default, Tsify)]
#[serde(rename_all = "camelCase")]
struct CongruenceSubdivideOptions {
    /// "butterfly" (16) on all edges, or "variational" (Section 5.2).
    scheme: Option<CongruenceSchemeName>,
    /// Butterfly tension w ∈ [−1/4, 1/4] (default 1/16, which reproduces cubics).
    #[serde(default)]
    w: Option<f64>,
    /// Butterfly only: return just the lines (16) on the diagonals, (rows − 1) × (cols − 1)
    /// of them (Fig. 13).
    #[serde(default)]
    diagonal_only: Option<bool>,
    /// Variational: parts per line K, 3 … 1000 (default 6); only "two-stage" depends on it
    /// ("paper" and "coupled" give the same lines for every K).
    #[serde(default, rename = "K")]
    k: Option<f64>,
    /// Variational (default "coupled"): "paper" is the paper's scheme read literally (edge
    /// lines by the strip energy (13)–(15), which is the midpoint rule; face lines the average
    /// of their 8 neighbours); "two-stage" the same with the coupled strip energy for the edge
    /// lines; "coupled" minimises the umbrella energy of every layer over all new lines at once
    /// (one sparse SPD solve).
    #[serde(default)]
    variant: Option<CongruenceVariant>,
    /// Steps, 0 … 12 (default 1); the result may hold at most 4 194 304 lines.
    #[serde(default)]
    steps: Option<f64>,
    /// Butterfly only. "points" (default): on the points p, q. "lines": on the lines
    /// themselves (dual unit vectors): independent of where p and q sit on their lines; each
    /// new line is cut to `length` centred on the mean of its footpoints with its grid
    /// neighbours.
    #[serde(default)]
    space: Option<SubdivisionSpace>,
    /// With space "lines": length of the output segments (default: mean input length).
    #[serde(default)]
    length: Option<f64>,
}

/// The schemes of `LineCongruence.subdivide`.
#[derive(Deserialize, Clone, Copy, Tsify)]
#[serde(rename_all = "kebab-case", expecting = "\"butterfly\" or \"variational\"")]
enum CongruenceSchemeName {
    /// The butterfly scheme (16).
    Butterfly,
    /// The variational scheme of Section 5.2.
    Variational,
}

/// The variants of the variational congruence scheme.
#[derive(Deserialize, Clone, Copy, Tsify)]
#[serde(rename_all = "kebab-case", expecting = "one of \"paper\", \"two-stage\", \"coupled\"")]
enum CongruenceVariant {
    /// The paper's scheme read literally.
    Paper,
    /// The coupled strip energy for the edge lines.
    TwoStage,
    /// The umbrella energy of every layer at once.
    Coupled,
}

/// A discrete line congruence: a rows × cols grid of lines p_{i,j} → q_{i,j}, row-major.
#[wasm_bindgen]
pub struct LineCongruence {
    inner: ruledlab::LineCongruence,
    _live: Live,
}

impl LineCongruence {
    /// Wraps a core congruence.
    pub(super) fn from_core(inner: ruledlab::LineCongruence) -> Self {
        LineCongruence { inner, _live: Live::new() }
    }

    /// The core congruence.
    pub fn core(&self) -> &ruledlab::LineCongruence {
        &self.inner
    }
}

#[wasm_bindgen]
impl LineCongruence {
    // --- making one, and its lines

    /// A congruence from a Float64Array of 6 · rows · cols numbers (p then q per line, row by
    /// row). Throws for a length mismatch, fewer than 2 × 2 lines, more than 4 194 304,
    /// non-finite numbers or zero-length lines.
    #[wasm_bindgen(js_name = fromGrid)]
    pub fn from_grid(
        #[wasm_bindgen(unchecked_param_type = "number")] rows: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] cols: JsValue,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] coords: JsValue,
    ) -> Result<LineCongruence, JsValue> {
        const F: &str = "LineCongruence.fromGrid";
        let rows = integer(F, "rows", &rows, 2, MAX_RULINGS)?;
        let cols = integer(F, "cols", &cols, 2, MAX_RULINGS)?;
        ruledlab::check_grid_shape(rows, cols).map_err(|e| fail(F, e))?;
        let coords = numbers(F, "coords", &coords)?;
        ruledlab::LineCongruence::from_flat(rows, cols, &coords).map(LineCongruence::from_core).map_err(|e| fail(F, e))
    }

    /// Number of rows.
    #[wasm_bindgen(getter)]
    pub fn rows(&self) -> usize {
        self.inner.rows()
    }

    /// Number of columns.
    #[wasm_bindgen(getter)]
    pub fn cols(&self) -> usize {
        self.inner.cols()
    }

    /// The lines, 6 numbers each (p then q), row-major (a copy).
    pub fn segments(&self) -> Float64Array {
        Float64Array::from(self.inner.flat())
    }

    /// Row i as a discrete ruled surface (Section 2's invariants apply).
    pub fn row(&self, #[wasm_bindgen(unchecked_param_type = "number")] i: JsValue) -> Result<RuledSurface, JsValue> {
        let i = integer("LineCongruence.row", "i", &i, 0, self.inner.rows() - 1)?;
        self.inner.row(i).map(RuledSurface::from_core).map_err(|e| fail("LineCongruence.row", e))
    }

    /// Column j as a discrete ruled surface.
    pub fn column(&self, #[wasm_bindgen(unchecked_param_type = "number")] j: JsValue) -> Result<RuledSurface, JsValue> {
        let j = integer("LineCongruence.column", "j", &j, 0, self.inner.cols() - 1)?;
        self.inner.column(j).map(RuledSurface::from_core).map_err(|e| fail("LineCongruence.column", e))
    }

    // --- subdivision (Section 5)

    /// The refined congruence (see `CongruenceSubdivideOptions`): each step maps rows × cols
    /// to (2 rows − 1) × (2 cols − 1) with the old lines at even indices, unchanged.
    pub fn subdivide(
        &self,
        #[wasm_bindgen(unchecked_param_type = "CongruenceSubdivideOptions")] options: JsValue,
    ) -> Result<LineCongruence, JsValue> {
        const F: &str = "LineCongruence.subdivide";
        let _measure = Measure::start(F);
        let o: CongruenceSubdivideOptions = args::options(F, options)?;
        let chosen = o.scheme.map(|s| match s {
            CongruenceSchemeName::Butterfly => "butterfly",
            CongruenceSchemeName::Variational => "variational",
        });
        for (key, present, s) in [
            ("w", o.w.is_some(), "butterfly"),
            ("diagonalOnly", o.diagonal_only.is_some(), "butterfly"),
            ("K", o.k.is_some(), "variational"),
            ("variant", o.variant.is_some(), "variational"),
            ("space", o.space.is_some(), "butterfly"),
            ("length", o.length.is_some(), "butterfly"),
        ] {
            only_for(F, key, present, s, chosen)?;
        }
        let steps = integer_option(F, "steps", o.steps, 0, MAX_CONGRUENCE_STEPS)?.unwrap_or(1);
        let scheme = match o.scheme {
            Some(CongruenceSchemeName::Butterfly) => {
                let w = finite_option(F, "w", o.w)?.unwrap_or(1.0 / 16.0);
                let length = finite_option(F, "length", o.length)?;
                match o.space {
                    None | Some(SubdivisionSpace::Points) => {
                        if length.is_some() {
                            return Err(args::fail_option(
                                F,
                                "length",
                                "options.length applies to space \"lines\" only",
                            ));
                        }
                    }
                    Some(SubdivisionSpace::Lines) => {
                        return ruledlab::butterfly_lines(&self.inner, w, steps, length)
                            .map(LineCongruence::from_core)
                            .map_err(|e| fail(F, e));
                    }
                }
                if o.diagonal_only.unwrap_or(false) {
                    if steps != 1 {
                        return Err(args::fail_option(
                            F,
                            "diagonalOnly",
                            "options.diagonalOnly gives the lines of one step: leave steps at 1",
                        ));
                    }
                    return ruledlab::butterfly_diagonal(&self.inner, w)
                        .map(LineCongruence::from_core)
                        .map_err(|e| fail(F, e));
                }
                CongruenceScheme::Butterfly { w }
            }
            Some(CongruenceSchemeName::Variational) => {
                let k = integer_option(F, "K", o.k, 3, MAX_PARTS)?.unwrap_or(6);
                match o.variant.unwrap_or(CongruenceVariant::Coupled) {
                    CongruenceVariant::Coupled => CongruenceScheme::Coupled { k },
                    CongruenceVariant::TwoStage => CongruenceScheme::TwoStage { k },
                    CongruenceVariant::Paper => CongruenceScheme::Paper { k },
                }
            }
            None => {
                return Err(args::fail_option(
                    F,
                    "scheme",
                    "options.scheme is required: \"butterfly\" or \"variational\"",
                ))
            }
        };
        ruledlab::subdivide_congruence(&self.inner, scheme, steps)
            .map(LineCongruence::from_core)
            .map_err(|e| fail(F, e))
    }

    // --- focal geometry (beyond the paper)

    /// The focal geometry of every line: focal points and parameters, kind, torsal
    /// directions, middle points and normality (`FocalGeometry`), from the lines' Plücker
    /// coordinates differenced over the grid (second order, at the boundary too).
    #[wasm_bindgen(unchecked_return_type = "FocalGeometry")]
    pub fn focal(&self) -> Result<JsValue, JsValue> {
        let _measure = Measure::start("LineCongruence.focal");
        let c = self.core();
        focal_js("LineCongruence.focal", c.rows(), c.cols(), &ruledlab::focal_grid(c.rows(), c.cols(), &c.p(), &c.q()))
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
        sheet_figure(
            "LineCongruence.focalSheetF32",
            c,
            &ruledlab::focal_grid(c.rows(), c.cols(), &c.p(), &c.q()),
            &sheet,
        )
    }

    /// Strokes on the director surface d₁ along the real torsal directions, p ± scale·(du·p_i
    /// + dv·p_j) (`scale` default 0.35 of a grid step), as f32 segments.
    #[wasm_bindgen(js_name = torsalStrokesF32)]
    pub fn torsal_strokes_f32(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] scale: JsValue,
    ) -> Result<Float32Array, JsValue> {
        let c = self.core();
        strokes("LineCongruence.torsalStrokesF32", c, &ruledlab::focal_grid(c.rows(), c.cols(), &c.p(), &c.q()), &scale)
    }

    /// The focal geometry of every line, computed once, with the figures drawn from it
    /// (`CongruenceFocal`): what `focal()`, `focalSheetF32` and `torsalStrokesF32` each compute
    /// anew.
    #[wasm_bindgen(js_name = focalGeometry)]
    pub fn focal_geometry(&self) -> CongruenceFocal {
        let _measure = Measure::start("LineCongruence.focalGeometry");
        let c = self.core();
        CongruenceFocal::new(c.clone(), ruledlab::focal_grid(c.rows(), c.cols(), &c.p(), &c.q()))
    }

    // --- buffers for WebGL (and `segmentsF32()`, `insertedF32(stride)`: `line_buffers!` below)

    /// The points of the director surface d₁ (`which` = 1, the p) or d₂ (2, the q), f32,
    /// 3 per line, row-major: draw them as a rows × cols grid.
    #[wasm_bindgen(js_name = directorF32)]
    pub fn director_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] which: JsValue,
    ) -> Result<Float32Array, JsValue> {
        let which = integer("LineCongruence.directorF32", "which", &which, 1, 2)?;
        Ok(points_f32(&if which == 1 { self.core().p() } else { self.core().q() }))
    }

    /// The points of d₁ (`which` = 1) or d₂ of the lines that `insertedF32(stride)` returns.
    #[wasm_bindgen(js_name = insertedDirectorF32)]
    pub fn inserted_director_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] stride: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] which: JsValue,
    ) -> Result<Float32Array, JsValue> {
        const F: &str = "LineCongruence.insertedDirectorF32";
        let stride = integer(F, "stride", &stride, 1, MAX_STRIDE)?;
        let which = integer(F, "which", &which, 1, 2)?;
        Ok(buffers::ends_f32(&self.core().inserted(stride), which))
    }

    // --- the linear complex, and the lines as data

    /// The linear complex that fits the lines best.
    #[wasm_bindgen(js_name = linearComplex, unchecked_return_type = "LinearComplexFit")]
    pub fn linear_complex(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "LinearComplexOptions")] options: JsValue,
    ) -> Result<JsValue, JsValue> {
        let c = self.core();
        let segments: Vec<Segment> = (0..c.rows() * c.cols()).map(|k| c.line(k / c.cols(), k % c.cols())).collect();
        complex_js("LineCongruence.linearComplex", &segments, options)
    }

    /// The lines as data: "json" (`{ "rows", "cols", "segments": [[…], …] }`), "csv" (row-major,
    /// the grid shape is not kept) or "obj" (vertices and line elements).
    pub fn export(
        &self,
        #[wasm_bindgen(unchecked_param_type = "\"csv\" | \"json\" | \"obj\"")] format: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "ExportOptions")] options: JsValue,
    ) -> Result<String, JsValue> {
        export(
            "LineCongruence.export",
            &format,
            options,
            self.core().flat(),
            Some((self.core().rows(), self.core().cols())),
            None,
        )
    }
}

line_buffers!(LineCongruence);

// the same shape as RuledSurface's: both cores keep their lines as one flat array and insert by stride
impl Lines for LineCongruence {
    const CLASS: &'static str = "LineCongruence";
    fn coordinates(&self) -> Cow<'_, [f64]> {
        Cow::Borrowed(self.inner.flat())
    }
    fn inserted(&self, stride: usize) -> ruledlab::Result<Vec<Segment>> {
        Ok(self.core().inserted(stride))
    }
}
