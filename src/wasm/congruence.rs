//! Line congruences for JavaScript (Section 5): `LineCongruence` and `AnalyticCongruence`.

use super::args::{self, describe, fail, finite_option, integer, integer_option, numbers, only_for, to_js};
use super::live::Live;
use super::surface::RuledSurface;
use crate::catalogue as examples;
use crate::congruence::SmoothCongruence;
use crate::congruence::{self, CongruenceScheme};
use crate::tolerance::MAX_RULINGS;
use js_sys::{Float32Array, Float64Array};
use serde::{Deserialize, Serialize};
use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &str = r#"
/** Options of `LineCongruence.subdivide` (Section 5). */
export interface CongruenceSubdivideOptions {
  /** "butterfly" (16) on all edges, or "variational" (Section 5.2). */
  scheme: "butterfly" | "variational";
  /** Butterfly tension w ∈ [−1/4, 1/4] (default 1/16, which reproduces cubics). */
  w?: number;
  /** Butterfly only: return just the lines (16) on the diagonals, (rows − 1) × (cols − 1) of them (Fig. 13). */
  diagonalOnly?: boolean;
  /** Variational: parts per line K, 3 … 1000 (default 6). */
  K?: number;
  /**
   * Variational (default "coupled"): "paper" is the paper's scheme read literally (edge lines by
   * the strip energy (13)–(15), which is the midpoint rule; face lines the average of their 8
   * neighbours); "two-stage" the same with the coupled strip energy for the edge lines;
   * "coupled" minimises the umbrella energy of every layer over all new lines at once (one
   * sparse SPD solve).
   */
  variant?: "paper" | "two-stage" | "coupled";
  /** Steps, 0 … 12 (default 1); the result may hold at most 4 194 304 lines. */
  steps?: number;
  /**
   * Butterfly only. "points" (default): on the points p, q. "lines": on the lines themselves
   * (dual unit vectors): independent of where p and q sit on their lines; each new line is cut
   * to `length` centred on the mean of its footpoints with its grid neighbours.
   */
  space?: "points" | "lines";
  /** With space "lines": length of the output segments (default: mean input length). */
  length?: number;
}

/** One congruence as listed by `AnalyticCongruence.list()`: its domain and the grid size of the paper's figure. */
export interface AnalyticCongruenceInfo {
  name: string; title: string;
  uMin: number; uMax: number; vMin: number; vMax: number; rows: number; cols: number;
}

/** Errors of a refined congruence against the exact one, over its new lines. */
export interface CongruenceErrors { distance: number; angle: number }
"#;

/// `CongruenceSubdivideOptions`, read by serde.
#[derive(Deserialize, Default)]
#[serde(rename_all = "camelCase")]
struct SubdivideOptions {
    scheme: Option<SchemeName>,
    w: Option<f64>,
    diagonal_only: Option<bool>,
    #[serde(rename = "K")]
    k: Option<f64>,
    variant: Option<VariantName>,
    steps: Option<f64>,
    space: Option<super::subdivide::SpaceName>,
    length: Option<f64>,
}

#[derive(Deserialize, Clone, Copy)]
#[serde(rename_all = "kebab-case", expecting = "\"butterfly\" or \"variational\"")]
enum SchemeName {
    Butterfly,
    Variational,
}

#[derive(Deserialize, Clone, Copy)]
#[serde(rename_all = "kebab-case", expecting = "one of \"paper\", \"two-stage\", \"coupled\"")]
enum VariantName {
    Paper,
    TwoStage,
    Coupled,
}

/// One entry of `AnalyticCongruence.list()`.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct CongruenceInfo {
    name: &'static str,
    title: &'static str,
    u_min: f64,
    u_max: f64,
    v_min: f64,
    v_max: f64,
    rows: usize,
    cols: usize,
}

/// `CongruenceErrors`.
#[derive(Serialize)]
struct ErrorsJs {
    distance: f64,
    angle: f64,
}

/// A discrete line congruence: a rows × cols grid of lines p_{i,j} → q_{i,j}, row-major.
#[wasm_bindgen]
pub struct LineCongruence {
    inner: congruence::LineCongruence,
    _live: Live,
}

impl LineCongruence {
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
            .map(|inner| LineCongruence { inner, _live: Live::new() })
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
        let o: SubdivideOptions = args::options(F, options)?;
        let chosen = o.scheme.map(|s| match s {
            SchemeName::Butterfly => "butterfly",
            SchemeName::Variational => "variational",
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
        let steps = integer_option(F, "steps", o.steps, 0, 12)?.unwrap_or(1);
        let scheme = match o.scheme {
            Some(SchemeName::Butterfly) => {
                let w = finite_option(F, "w", o.w)?.unwrap_or(1.0 / 16.0);
                let length = finite_option(F, "length", o.length)?;
                match o.space {
                    None | Some(super::subdivide::SpaceName::Points) => {
                        if length.is_some() {
                            return Err(args::fail_option(
                                F,
                                "length",
                                "options.length applies to space \"lines\" only",
                            ));
                        }
                    }
                    Some(super::subdivide::SpaceName::Lines) => {
                        return crate::congruence::line_space::butterfly_lines(&self.inner, w, steps, length)
                            .map(|inner| LineCongruence { inner, _live: Live::new() })
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
                        .map(|inner| LineCongruence { inner, _live: Live::new() })
                        .map_err(|e| fail(F, e));
                }
                CongruenceScheme::Butterfly { w }
            }
            Some(SchemeName::Variational) => {
                let k = integer_option(F, "K", o.k, 3, 1000)?.unwrap_or(6);
                match o.variant.unwrap_or(VariantName::Coupled) {
                    VariantName::Coupled => CongruenceScheme::Coupled { k },
                    VariantName::TwoStage => CongruenceScheme::TwoStage { k },
                    VariantName::Paper => CongruenceScheme::Paper { k },
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
        congruence::subdivide(&self.inner, scheme, steps)
            .map(|inner| LineCongruence { inner, _live: Live::new() })
            .map_err(|e| fail(F, e))
    }
}

/// The congruences of Examples 4 and 5 in closed form.
#[wasm_bindgen]
pub struct AnalyticCongruence {
    inner: examples::AnalyticCongruence,
    _live: Live,
}

impl AnalyticCongruence {
    /// Wraps a core congruence.
    pub(crate) fn from_core(inner: examples::AnalyticCongruence) -> Self {
        AnalyticCongruence { inner, _live: Live::new() }
    }

    /// The core congruence.
    pub fn core(&self) -> &examples::AnalyticCongruence {
        &self.inner
    }
}

#[wasm_bindgen]
impl AnalyticCongruence {
    /// Every congruence: name, title, domain and the grid size of the paper's figure.
    #[wasm_bindgen(unchecked_return_type = "AnalyticCongruenceInfo[]")]
    pub fn list() -> Result<JsValue, JsValue> {
        let list: Vec<CongruenceInfo> = examples::AnalyticCongruence::ALL
            .iter()
            .map(|c| {
                let ((u_min, u_max), (v_min, v_max), rows, cols) = c.domain();
                CongruenceInfo { name: c.name(), title: c.title(), u_min, u_max, v_min, v_max, rows, cols }
            })
            .collect();
        to_js("AnalyticCongruence.list", &list)
    }

    /// The congruence named `name` ("sphere", "hyperbolic-paraboloid", "example5").
    #[wasm_bindgen(js_name = byName)]
    pub fn by_name(
        #[wasm_bindgen(unchecked_param_type = "string")] name: JsValue,
    ) -> Result<AnalyticCongruence, JsValue> {
        let Some(name) = name.as_string() else {
            return Err(fail("AnalyticCongruence.byName", format!("name must be a string, got {}", describe(&name))));
        };
        examples::AnalyticCongruence::by_name(&name)
            .map(|inner| AnalyticCongruence { inner, _live: Live::new() })
            .map_err(|e| fail("AnalyticCongruence.byName", e))
    }

    /// A rows × cols grid of its lines (default: the paper's grid size), each the segment
    /// from p to p + reach·d (`reach` default 1: the paper gives no length, ERRATA.md 9;
    /// shorter segments are the same lines, and every scheme refines them to the same lines).
    pub fn grid(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] rows: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] cols: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] reach: JsValue,
    ) -> Result<LineCongruence, JsValue> {
        const F: &str = "AnalyticCongruence.grid";
        let (_, _, r0, c0) = self.inner.domain();
        let rows = args::optional_integer(F, "rows", &rows, 2, MAX_RULINGS, r0)?;
        let cols = args::optional_integer(F, "cols", &cols, 2, MAX_RULINGS, c0)?;
        let reach = if reach.is_undefined() { 1.0 } else { args::number(F, "reach", &reach)? };
        if !(reach > 0.0 && reach <= 1e6) {
            return Err(fail(F, format!("reach must be a number in (0, 1e6], got {reach}")));
        }
        self.inner
            .grid_reaching(rows, cols, reach)
            .map(|inner| LineCongruence { inner, _live: Live::new() })
            .map_err(|e| fail(F, e))
    }

    /// Errors of `refined` (refined from one of its grids) against the exact lines at the
    /// same parameters, over the new lines: the largest distance of the d₁ points and the
    /// largest angle of the directions (radians).
    #[wasm_bindgen(unchecked_return_type = "CongruenceErrors")]
    pub fn errors(&self, refined: &LineCongruence) -> Result<JsValue, JsValue> {
        let (distance, angle) = self.inner.errors(&refined.inner);
        to_js("AnalyticCongruence.errors", &ErrorsJs { distance, angle })
    }
}
