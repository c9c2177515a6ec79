//! Line congruences for JavaScript (Section 5): `LineCongruence` and `AnalyticCongruence`.

use super::args::{self, fail, finite_option, integer, integer_option, numbers, only_for};
use super::live::Live;
use super::subdivision::SubdivisionSpace;
use super::surface::RuledSurface;
use super::timing::Measure;
use crate::congruence::{self, CongruenceScheme};
use crate::tolerance::{MAX_CONGRUENCE_STEPS, MAX_PARTS, MAX_RULINGS};
use js_sys::{Float32Array, Float64Array};
use serde::Deserialize;
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
    inner: congruence::LineCongruence,
    _live: Live,
}

impl LineCongruence {
    /// Wraps a core congruence.
    pub(super) fn from_core(inner: congruence::LineCongruence) -> Self {
        LineCongruence { inner, _live: Live::new() }
    }

    /// The core congruence.
    pub fn core(&self) -> &congruence::LineCongruence {
        &self.inner
    }
}

#[wasm_bindgen]
impl LineCongruence {
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
        congruence::grid::check_shape(rows, cols).map_err(|e| fail(F, e))?;
        let coords = numbers(F, "coords", &coords)?;
        congruence::LineCongruence::from_flat(rows, cols, &coords)
            .map(LineCongruence::from_core)
            .map_err(|e| fail(F, e))
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

    /// The lines as 32-bit floats for a WebGL buffer.
    #[wasm_bindgen(js_name = segmentsF32)]
    pub fn segments_f32(&self) -> Float32Array {
        let v: Vec<f32> = self.inner.flat().iter().map(|&x| x as f32).collect();
        Float32Array::from(&v[..])
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
                        return crate::congruence::line_space::butterfly_lines(&self.inner, w, steps, length)
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
                    return congruence::butterfly_diagonal(&self.inner, w)
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
        congruence::subdivide(&self.inner, scheme, steps).map(LineCongruence::from_core).map_err(|e| fail(F, e))
    }
}
