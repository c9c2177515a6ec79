//! Focal geometry of congruences and linear complexes for JavaScript (beyond the paper):
//! `LineCongruence.focal()`, `AnalyticCongruence.focal()`, the focal sheets and torsal strokes
//! the page draws, and `linearComplex` of segments, surfaces and congruences.

use super::args::{self, fail, finite_option, to_js};
use super::buffers::{points_f32, segments_f32};
use super::congruence::{AnalyticCongruence, LineCongruence};
use super::surface::RuledSurface;
use crate::congruence::focal::{self, Focal};
use crate::line::Segment;
use crate::linear_complex::{self, LinearComplex};
use crate::ruled::RuledSurface as CoreSurface;
use crate::tolerance::MAX_RULINGS;
use js_sys::{Float32Array, Float64Array, Uint32Array, Uint8Array};
use serde::{Deserialize, Serialize};
use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &str = r#"
/**
 * The focal geometry of every line of a congruence (README, "Focal geometry"): a line runs
 * p → q, e = (q − p)/|q − p|, a point on it is p + t·e. Per line, row-major.
 */
export interface FocalGeometry {
  rows: number; cols: number;
  /** 6 per line: the focal points F1 then F2 (NaN when not real or at infinity). */
  points: Float64Array;
  /** 2 per line: t1 ≤ t2 (±Infinity for a focal point at infinity, NaN when not real). */
  parameters: Float64Array;
  /** 1 per line: 0 elliptic (no real focal point), 1 hyperbolic (two), 2 parabolic (one double). */
  kind: Uint8Array;
  /** 4 per line: the unit torsal directions (du, dv) of F1 and of F2, in grid steps, du > 0 (NaN when not real). */
  torsal: Float64Array;
  /** 3 per line: the midpoint of the focal points (real for every kind; NaN if the quadratic degenerates). */
  middle: Float64Array;
  /** 1 per line: |cos| of the angle between the focal planes, 0 for a normal congruence (NaN when not real). */
  normality: Float64Array;
}

/** Options of `linearComplex`. */
export interface LinearComplexOptions {
  /** Root-mean-square residual in the fit's frame (centred, lengths divided by the lines' spread) under which a complex holds the lines; default 1e-9. */
  tolerance?: number;
}

/**
 * The linear complex c·m + c̄·d = 0 that fits the lines best (Plücker coordinates (d, m), d unit,
 * m = x × d), with how many independent complexes hold them.
 */
export interface LinearComplexFit {
  /** (c, c̄), |c| = 1 (|c̄| = 1 when c = 0: the lines orthogonal to c̄). */
  plucker: Float64Array;
  /** (c·c̄)/(c·c); Infinity when c = 0. */
  pitch: number;
  /** (c × c̄)/(c·c): the axis point nearest the origin (NaN when c = 0). */
  axisPoint: Float64Array;
  /** c (c̄ when c = 0), unit. */
  axisDirection: Float64Array;
  /** 6 numbers: a piece of the axis to draw, centred at the foot of the lines' centroid, 4 spreads long (NaN when c = 0). */
  axisSegment: Float64Array;
  /** Root mean square of c·m + c̄·d over the lines. */
  residual: number;
  /** The residual (in the fit's frame) of each of six orthogonal complexes, ascending. */
  spectrum: Float64Array;
  /** How many independent complexes hold the lines within the tolerance. */
  nullity: number;
  /** 0: "general", 1: "complex", 2: "congruence", 3: "regulus" (or "special": a bundle or field of lines), more: "special". */
  kind: "general" | "complex" | "congruence" | "regulus" | "special";
}

/** A focal sheet for WebGL: positions, triangle indices and smooth vertex normals. */
export interface FocalSheetBuffers { positions: Float32Array; indices: Uint32Array; normals: Float32Array }
"#;

/// `FocalGeometry`.
#[derive(Serialize)]
struct FocalJs {
    rows: usize,
    cols: usize,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    points: Float64Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    parameters: Float64Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    kind: Uint8Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    torsal: Float64Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    middle: Float64Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    normality: Float64Array,
}

pub(super) fn focal_js(func: &str, rows: usize, cols: usize, all: &[Focal]) -> Result<JsValue, JsValue> {
    let f64s = |values: Vec<f64>| Float64Array::from(&values[..]);
    let kind: Vec<u8> = all.iter().map(|f| f.kind as u8).collect();
    to_js(
        func,
        &FocalJs {
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

/// `LinearComplexOptions`.
#[derive(Deserialize, Default)]
#[serde(rename_all = "camelCase")]
struct ComplexOptions {
    tolerance: Option<f64>,
}

/// `LinearComplexFit`.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct ComplexJs {
    #[serde(with = "serde_wasm_bindgen::preserve")]
    plucker: Float64Array,
    pitch: f64,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    axis_point: Float64Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    axis_direction: Float64Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    axis_segment: Float64Array,
    residual: f64,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    spectrum: Float64Array,
    nullity: usize,
    kind: &'static str,
}

fn complex_js(func: &str, segments: &[Segment], options: JsValue) -> Result<JsValue, JsValue> {
    let options: ComplexOptions = args::options(func, options)?;
    let tolerance = finite_option(func, "tolerance", options.tolerance)?;
    if let Some(t) = tolerance.filter(|t| !(*t > 0.0 && *t <= 1.0)) {
        return Err(args::fail_option(
            func,
            "tolerance",
            format!("options.tolerance must be a number in (0, 1], got {t}"),
        ));
    }
    let f: LinearComplex = linear_complex::fit(segments, tolerance);
    to_js(
        func,
        &ComplexJs {
            plucker: Float64Array::from(&f.plucker[..]),
            pitch: f.pitch,
            axis_point: Float64Array::from(&f.axis_point.to_array()[..]),
            axis_direction: Float64Array::from(&f.axis_direction.to_array()[..]),
            axis_segment: Float64Array::from(
                &[f.axis_segment[0].to_array(), f.axis_segment[1].to_array()].concat()[..],
            ),
            residual: f.residual,
            spectrum: Float64Array::from(&f.spectrum[..]),
            nullity: f.nullity,
            kind: f.kind.name(),
        },
    )
}

/// The best-fitting linear complex of segments (6 numbers each: a then b; at least 2).
#[wasm_bindgen(js_name = linearComplex, unchecked_return_type = "LinearComplexFit")]
pub fn linear_complex_of(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] segments: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "LinearComplexOptions")] options: JsValue,
) -> Result<JsValue, JsValue> {
    const F: &str = "linearComplex";
    let coords = args::numbers(F, "segments", &segments)?;
    let surface = CoreSurface::from_flat(&coords).map_err(|e| fail(F, e))?;
    complex_js(F, &surface.segments().collect::<Vec<_>>(), options)
}

#[wasm_bindgen]
impl RuledSurface {
    /// The linear complex that fits the rulings best (a helical surface: its screw axis; a
    /// regulus: nullity 3).
    #[wasm_bindgen(js_name = linearComplex, unchecked_return_type = "LinearComplexFit")]
    pub fn linear_complex(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "LinearComplexOptions")] options: JsValue,
    ) -> Result<JsValue, JsValue> {
        complex_js("RuledSurface.linearComplex", &self.core().segments().collect::<Vec<_>>(), options)
    }
}

/// `FocalSheetBuffers`.
#[derive(Serialize)]
struct SheetJs {
    #[serde(with = "serde_wasm_bindgen::preserve")]
    positions: Float32Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    indices: Uint32Array,
    #[serde(with = "serde_wasm_bindgen::preserve")]
    normals: Float32Array,
}

#[wasm_bindgen]
impl LineCongruence {
    /// The focal geometry of every line: focal points and parameters, kind, torsal
    /// directions, middle points and normality (`FocalGeometry`), from the lines' Plücker
    /// coordinates differenced over the grid (second order, at the boundary too).
    #[wasm_bindgen(unchecked_return_type = "FocalGeometry")]
    pub fn focal(&self) -> Result<JsValue, JsValue> {
        let c = self.core();
        focal_js("LineCongruence.focal", c.rows(), c.cols(), &focal::focal_grid(c.rows(), c.cols(), &c.p(), &c.q()))
    }

    /// Focal sheet 1 (of t1) or 2 (of t2) as a mesh with vertex normals: the grid's quads whose
    /// four focal points are real and within three bounding-box diagonals of the lines' centre.
    #[wasm_bindgen(js_name = focalSheetF32, unchecked_return_type = "FocalSheetBuffers")]
    pub fn focal_sheet_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "1 | 2")] sheet: JsValue,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "LineCongruence.focalSheetF32";
        let sheet = args::integer(F, "sheet", &sheet, 1, 2)?;
        let c = self.core();
        let all = focal::focal_grid(c.rows(), c.cols(), &c.p(), &c.q());
        let mesh = focal::focal_sheet(c, &all, sheet - 1);
        let normals = mesh.vertex_normals();
        to_js(
            F,
            &SheetJs {
                positions: points_f32(&mesh.positions),
                indices: Uint32Array::from(&mesh.indices[..]),
                normals: points_f32(&normals),
            },
        )
    }

    /// Strokes on the director surface d₁ along the real torsal directions, p ± scale·(du·p_i
    /// + dv·p_j) (`scale` default 0.35 of a grid step), as f32 segments.
    #[wasm_bindgen(js_name = torsalStrokesF32)]
    pub fn torsal_strokes_f32(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] scale: JsValue,
    ) -> Result<Float32Array, JsValue> {
        const F: &str = "LineCongruence.torsalStrokesF32";
        let scale = if scale.is_undefined() { 0.35 } else { args::number(F, "scale", &scale)? };
        if !(scale > 0.0 && scale <= 10.0) {
            return Err(fail(F, format!("scale must be a number in (0, 10], got {scale}")));
        }
        let c = self.core();
        let p = c.p();
        let all = focal::focal_grid(c.rows(), c.cols(), &p, &c.q());
        Ok(segments_f32(&focal::torsal_strokes(c.rows(), c.cols(), &p, &all, scale)))
    }

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
