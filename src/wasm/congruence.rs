//! Line congruences for JavaScript (Section 5): `LineCongruence` and `AnalyticCongruence`.

use super::args::{describe, fail, integer, numbers, ObjectBuilder, Options};
use super::live::Live;
use super::surface::RuledSurface;
use crate::congruence::{self, CongruenceScheme};
use crate::examples;
use crate::tolerance::MAX_RULINGS;
use js_sys::{Float32Array, Float64Array};
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

/** Errors of a refined congruence against the exact one, over its new lines. */
export interface CongruenceErrors { distance: number; angle: number }
"#;

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
        rows: f64,
        cols: f64,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] coords: JsValue,
    ) -> Result<LineCongruence, JsValue> {
        const F: &str = "LineCongruence.fromGrid";
        let rows = integer(F, "rows", rows, 2, MAX_RULINGS)?;
        let cols = integer(F, "cols", cols, 2, MAX_RULINGS)?;
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
    pub fn row(&self, i: f64) -> Result<RuledSurface, JsValue> {
        let i = integer("LineCongruence.row", "i", i, 0, self.inner.rows() - 1)?;
        self.inner.row(i).map(RuledSurface::from_core).map_err(|e| fail("LineCongruence.row", e))
    }

    /// Column j as a discrete ruled surface.
    pub fn column(&self, j: f64) -> Result<RuledSurface, JsValue> {
        let j = integer("LineCongruence.column", "j", j, 0, self.inner.cols() - 1)?;
        self.inner.column(j).map(RuledSurface::from_core).map_err(|e| fail("LineCongruence.column", e))
    }

    /// The refined congruence (see `CongruenceSubdivideOptions`): each step maps rows × cols
    /// to (2 rows − 1) × (2 cols − 1) with the old lines at even indices, unchanged.
    pub fn subdivide(
        &self,
        #[wasm_bindgen(unchecked_param_type = "CongruenceSubdivideOptions")] options: JsValue,
    ) -> Result<LineCongruence, JsValue> {
        const F: &str = "LineCongruence.subdivide";
        let o = Options::new(F, options, &["scheme", "w", "diagonalOnly", "K", "variant", "steps", "space", "length"])?;
        let scheme = o.string("scheme")?;
        for (key, s) in [
            ("w", "butterfly"),
            ("diagonalOnly", "butterfly"),
            ("K", "variational"),
            ("variant", "variational"),
            ("space", "butterfly"),
            ("length", "butterfly"),
        ] {
            o.only_for(key, s, scheme.as_deref())?;
        }
        let steps = o.integer("steps", 0, 12)?.unwrap_or(1);
        let scheme = match scheme.as_deref() {
            Some("butterfly") => {
                let w = o.number("w")?.unwrap_or(1.0 / 16.0);
                match o.string("space")?.as_deref() {
                    None | Some("points") => {
                        if o.has("length") {
                            return Err(fail(F, "options.length applies to space \"lines\" only"));
                        }
                    }
                    Some("lines") => {
                        return crate::subdivision::line_space::butterfly_lines(
                            &self.inner,
                            w,
                            steps,
                            o.number("length")?,
                        )
                        .map(|inner| LineCongruence { inner, _live: Live::new() })
                        .map_err(|e| fail(F, e));
                    }
                    Some(other) => {
                        return Err(fail(F, format!("options.space must be \"points\" or \"lines\", got \"{other}\"")))
                    }
                }
                if o.boolean("diagonalOnly")?.unwrap_or(false) {
                    if steps != 1 {
                        return Err(fail(F, "options.diagonalOnly gives the lines of one step: leave steps at 1"));
                    }
                    return congruence::butterfly_diagonal(&self.inner, w)
                        .map(|inner| LineCongruence { inner, _live: Live::new() })
                        .map_err(|e| fail(F, e));
                }
                CongruenceScheme::Butterfly { w }
            }
            Some("variational") => {
                let k = o.integer("K", 3, 1000)?.unwrap_or(6);
                match o.string("variant")?.as_deref() {
                    None | Some("coupled") => CongruenceScheme::Coupled { k },
                    Some("two-stage") => CongruenceScheme::TwoStage { k },
                    Some("paper") => CongruenceScheme::Paper { k },
                    Some(v) => {
                        return Err(fail(
                            F,
                            format!("options.variant must be \"paper\", \"two-stage\" or \"coupled\", got {v:?}"),
                        ))
                    }
                }
            }
            None => return Err(fail(F, "options.scheme is required: \"butterfly\" or \"variational\"")),
            Some(other) => {
                return Err(fail(F, format!("unknown scheme \"{other}\"; use \"butterfly\" or \"variational\"")))
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
}

#[wasm_bindgen]
impl AnalyticCongruence {
    /// Every congruence: name, title, domain and the grid size of the paper's figure.
    #[wasm_bindgen(
        unchecked_return_type = "Array<{name: string, title: string, uMin: number, uMax: number, vMin: number, vMax: number, rows: number, cols: number}>"
    )]
    pub fn list() -> js_sys::Array {
        examples::AnalyticCongruence::ALL
            .iter()
            .map(|c| {
                let ((u0, u1), (v0, v1), rows, cols) = c.domain();
                ObjectBuilder::new()
                    .set("name", c.name())
                    .set("title", c.title())
                    .set("uMin", u0)
                    .set("uMax", u1)
                    .set("vMin", v0)
                    .set("vMax", v1)
                    .set("rows", rows as u32)
                    .set("cols", cols as u32)
                    .build()
            })
            .collect()
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
    pub fn grid(&self, rows: Option<f64>, cols: Option<f64>, reach: Option<f64>) -> Result<LineCongruence, JsValue> {
        const F: &str = "AnalyticCongruence.grid";
        let (_, _, r0, c0) = self.inner.domain();
        let rows = integer(F, "rows", rows.unwrap_or(r0 as f64), 2, MAX_RULINGS)?;
        let cols = integer(F, "cols", cols.unwrap_or(c0 as f64), 2, MAX_RULINGS)?;
        let reach = reach.unwrap_or(1.0);
        if !(reach.is_finite() && reach > 0.0 && reach <= 1e6) {
            return Err(fail(F, format!("reach must be a positive number, got {reach}")));
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
    pub fn errors(&self, refined: &LineCongruence) -> JsValue {
        let (distance, angle) = self.inner.errors(&refined.inner);
        ObjectBuilder::new().set("distance", distance).set("angle", angle).build()
    }
}
