//! Linear complexes for JavaScript (beyond the paper): `linearComplex(segments)`, and the fit
//! that `RuledSurface.linearComplex()` and `LineCongruence.linearComplex()` return: the complex
//! c·m + c̄·d = 0 that fits lines best.

use js_sys::Float64Array;
use ruledlab::LinearComplex;
use ruledlab::RuledSurface as CoreSurface;
use ruledlab::Segment;
use ruledlab_js::args::{self, fail, finite_option, to_js};
use serde::{Deserialize, Serialize};
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// Options of `linearComplex`.
#[derive(Deserialize, Default, Tsify)]
#[serde(rename_all = "camelCase", default)]
struct LinearComplexOptions {
    /// Root-mean-square residual in the fit's frame (centred, lengths divided by the lines'
    /// spread) under which a complex holds the lines; default 1e-9.
    tolerance: Option<f64>,
}

/// The linear complex c·m + c̄·d = 0 that fits the lines best (Plücker coordinates (d, m), d
/// unit, m = x × d), with how many independent complexes hold them.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
struct LinearComplexFit {
    /// (c, c̄), |c| = 1 (|c̄| = 1 when c = 0: the lines orthogonal to c̄).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    plucker: Float64Array,
    /// (c·c̄)/(c·c); Infinity when c = 0.
    pitch: f64,
    /// (c × c̄)/(c·c): the axis point nearest the origin (NaN when c = 0).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    axis_point: Float64Array,
    /// c (c̄ when c = 0), unit.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    axis_direction: Float64Array,
    /// 6 numbers: a piece of the axis to draw, centred at the foot of the lines' centroid, 4
    /// spreads long (NaN when c = 0).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    axis_segment: Float64Array,
    /// Root mean square of c·m + c̄·d over the lines.
    residual: f64,
    /// The residual (in the fit's frame) of each of six orthogonal complexes, ascending.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    spectrum: Float64Array,
    /// How many independent complexes hold the lines within the tolerance.
    nullity: usize,
    /// 0: "general", 1: "complex", 2: "congruence", 3: "regulus" (or "special": a bundle or
    /// field of lines), more: "special".
    #[tsify(type = "\"general\" | \"complex\" | \"congruence\" | \"regulus\" | \"special\"")]
    kind: &'static str,
}

/// The best-fitting complex of `segments` as a `LinearComplexFit` object (`options`: its
/// `LinearComplexOptions`).
pub(super) fn complex_js(func: &str, segments: &[Segment], options: JsValue) -> Result<JsValue, JsValue> {
    let options: LinearComplexOptions = args::options(func, options)?;
    let tolerance = finite_option(func, "tolerance", options.tolerance)?;
    if let Some(t) = tolerance.filter(|t| !(*t > 0.0 && *t <= 1.0)) {
        return Err(args::fail_option(
            func,
            "tolerance",
            format!("options.tolerance must be a number in (0, 1], got {t}"),
        ));
    }
    let f: LinearComplex = ruledlab::fit_linear_complex(segments, tolerance);
    to_js(
        func,
        &LinearComplexFit {
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
/// In Rust `ruledlab::wasm::linear_complex_of`.
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
