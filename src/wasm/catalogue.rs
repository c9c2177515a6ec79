//! The catalogue for JavaScript: `AnalyticSurface` and `AnalyticCongruence`, the surfaces and
//! congruences known in closed form (Sections 2 and 5, Examples 1–5), listed, sampled and
//! evaluated exactly.

use super::args::{self, describe, fail, finite_option, integer, interval, numbers, options, to_js};
use super::congruence::LineCongruence;
use super::live::Live;
use super::surface::RuledSurface;
use super::timing::Measure;
use crate::catalogue as examples;
use crate::congruence::SmoothCongruence;
use crate::ruled::SmoothRuled;
use crate::tolerance::{MAX_REACH, MAX_RULINGS, MAX_SAMPLES};
use js_sys::Float64Array;
use serde::{Deserialize, Serialize};
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// Sampling options; omitted fields take the surface's defaults (`AnalyticSurface.list()`).
#[derive(Deserialize, Default, Tsify)]
#[serde(rename_all = "camelCase", default)]
pub(super) struct SampleOptions {
    u_min: Option<f64>,
    u_max: Option<f64>,
    v_min: Option<f64>,
    v_max: Option<f64>,
    /// Read the surface as closed (R_{N−1} followed by R_0).
    closed: Option<bool>,
}

/// One analytic surface as listed by `AnalyticSurface.list()`: its name, title and default
/// ranges.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
struct AnalyticSurfaceInfo {
    name: &'static str,
    title: &'static str,
    u_min: f64,
    u_max: f64,
    v_min: f64,
    v_max: f64,
    closed: bool,
}

/// One congruence as listed by `AnalyticCongruence.list()`: its domain and the grid size of
/// the paper's figure.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
struct AnalyticCongruenceInfo {
    name: &'static str,
    title: &'static str,
    u_min: f64,
    u_max: f64,
    v_min: f64,
    v_max: f64,
    rows: usize,
    cols: usize,
}

/// Errors of a refined congruence against the exact one, over its new lines.
#[derive(Serialize, Tsify)]
struct CongruenceErrors {
    /// The largest distance of the d₁ points.
    distance: f64,
    /// The largest angle of the directions (radians).
    angle: f64,
}

/// An analytic ruled surface x(u, v) = a(u) + v d(u) with exact striction curve and
/// distribution parameter.
#[wasm_bindgen]
pub struct AnalyticSurface {
    inner: examples::AnalyticSurface,
    _live: Live,
}

impl AnalyticSurface {
    /// Wraps a core surface.
    pub(crate) fn from_core(inner: examples::AnalyticSurface) -> Self {
        AnalyticSurface { inner, _live: Live::new() }
    }

    /// The core surface.
    pub(super) fn core(&self) -> &examples::AnalyticSurface {
        &self.inner
    }
}

#[wasm_bindgen]
impl AnalyticSurface {
    /// Every analytic surface: name, title and default ranges.
    #[wasm_bindgen(unchecked_return_type = "AnalyticSurfaceInfo[]")]
    pub fn list() -> Result<JsValue, JsValue> {
        let list: Vec<AnalyticSurfaceInfo> = examples::AnalyticSurface::ALL
            .iter()
            .map(|s| {
                let r = s.ranges();
                AnalyticSurfaceInfo {
                    name: s.name(),
                    title: s.title(),
                    u_min: r.u.0,
                    u_max: r.u.1,
                    v_min: r.v.0,
                    v_max: r.v.1,
                    closed: r.closed,
                }
            })
            .collect();
        to_js("AnalyticSurface.list", &list)
    }

    /// The surface named `name` (see `list()`); throws for an unknown name.
    #[wasm_bindgen(js_name = byName)]
    pub fn by_name(#[wasm_bindgen(unchecked_param_type = "string")] name: JsValue) -> Result<AnalyticSurface, JsValue> {
        let Some(name) = name.as_string() else {
            return Err(fail("AnalyticSurface.byName", format!("name must be a string, got {}", describe(&name))));
        };
        examples::AnalyticSurface::by_name(&name)
            .map(|inner| AnalyticSurface { inner, _live: Live::new() })
            .map_err(|e| fail("AnalyticSurface.byName", e))
    }

    /// Machine name, e.g. "hyperboloid".
    #[wasm_bindgen(getter)]
    pub fn name(&self) -> String {
        self.inner.name().into()
    }

    /// Human title.
    #[wasm_bindgen(getter)]
    pub fn title(&self) -> String {
        self.inner.title().into()
    }

    /// `count` rulings at equally spaced u (see `SampleOptions`; defaults from `list()`).
    pub fn sample(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] count: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "SampleOptions")] opts: JsValue,
    ) -> Result<RuledSurface, JsValue> {
        const F: &str = "AnalyticSurface.sample";
        let _measure = Measure::start(F);
        let count = integer(F, "count", &count, 2, MAX_SAMPLES)?;
        let r = self.ranges(F, opts)?;
        self.inner.sample(count, r).map(RuledSurface::from_core).map_err(|e| fail(F, e))
    }

    /// The parameters u_i at which `sample(count, options)` takes its rulings.
    pub fn parameters(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] count: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "SampleOptions")] opts: JsValue,
    ) -> Result<Float64Array, JsValue> {
        const F: &str = "AnalyticSurface.parameters";
        let count = integer(F, "count", &count, 2, MAX_SAMPLES)?;
        let r = self.ranges(F, opts)?;
        Ok(Float64Array::from(&crate::base::parameters(count, r)[..]))
    }

    /// Exact striction points s(u) for each u: 3 numbers per u (NaN on a cylindrical ruling).
    pub fn striction(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] u: JsValue,
    ) -> Result<Float64Array, JsValue> {
        self.points_at("AnalyticSurface.striction", &u, |u| self.inner.striction(u))
    }

    /// Exact distribution parameters δ(u).
    pub fn distribution(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] u: JsValue,
    ) -> Result<Float64Array, JsValue> {
        let u = self.u_values("AnalyticSurface.distribution", &u)?;
        let out: Vec<f64> = u.iter().map(|&u| self.inner.distribution(u)).collect();
        Ok(Float64Array::from(&out[..]))
    }

    /// Exact central tangent directions e₃(u) (4): 3 numbers per u (NaN on a cylindrical ruling).
    #[wasm_bindgen(js_name = centralTangent)]
    pub fn central_tangent(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] u: JsValue,
    ) -> Result<Float64Array, JsValue> {
        self.points_at("AnalyticSurface.centralTangent", &u, |u| self.inner.central_tangent(u))
    }

    /// Distance of each point (3 numbers per point) from the surface, its rulings extended to
    /// whole lines, searching the rulings with u in [uMin, uMax].
    pub fn distances(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] points: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] u_min: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] u_max: JsValue,
    ) -> Result<Float64Array, JsValue> {
        const F: &str = "AnalyticSurface.distances";
        let flat = numbers(F, "points", &points)?;
        let (u_min, u_max) = interval(F, &u_min, &u_max)?;
        if flat.len() % 3 != 0 || flat.len() / 3 > MAX_SAMPLES {
            return Err(fail(
                F,
                format!("points: length {} must be a multiple of 3 and at most {}", flat.len(), 3 * MAX_SAMPLES),
            ));
        }
        crate::base::check_coordinates(&flat, 3).map_err(|e| fail(F, e))?;
        let out: Vec<f64> =
            flat.chunks_exact(3).map(|p| self.inner.distance_to(glam::DVec3::from_slice(p), u_min, u_max)).collect();
        Ok(Float64Array::from(&out[..]))
    }
}

impl AnalyticSurface {
    /// Sampling ranges from `SampleOptions`, defaults from the surface.
    pub(super) fn ranges(&self, func: &'static str, opts: JsValue) -> Result<crate::base::Ranges, JsValue> {
        let o: SampleOptions = options(func, opts)?;
        let d = self.inner.ranges();
        let bound =
            |name: &str, x: Option<f64>, default: f64| finite_option(func, name, x).map(|x| x.unwrap_or(default));
        Ok(crate::base::Ranges {
            u: (bound("uMin", o.u_min, d.u.0)?, bound("uMax", o.u_max, d.u.1)?),
            v: (bound("vMin", o.v_min, d.v.0)?, bound("vMax", o.v_max, d.v.1)?),
            closed: o.closed.unwrap_or(d.closed),
        })
    }

    /// `at(u)` for each u, 3 numbers each (NaN where it is `None`).
    fn points_at(
        &self,
        func: &str,
        u: &JsValue,
        at: impl Fn(f64) -> Option<glam::DVec3>,
    ) -> Result<Float64Array, JsValue> {
        let out: Vec<f64> =
            self.u_values(func, u)?.into_iter().flat_map(|u| at(u).unwrap_or(glam::DVec3::NAN).to_array()).collect();
        Ok(Float64Array::from(&out[..]))
    }

    pub(super) fn u_values(&self, func: &str, u: &JsValue) -> Result<Vec<f64>, JsValue> {
        let u = numbers(func, "u", u)?;
        if u.len() > MAX_SAMPLES {
            return Err(fail(func, crate::Error::TooMany { what: "parameters", got: u.len(), max: MAX_SAMPLES }));
        }
        if let Some(x) = u.iter().find(|x| !x.is_finite()) {
            return Err(fail(func, format!("every u must be finite, got {x}")));
        }
        Ok(u)
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
        let list: Vec<AnalyticCongruenceInfo> = examples::AnalyticCongruence::ALL
            .iter()
            .map(|c| {
                let ((u_min, u_max), (v_min, v_max), rows, cols) = c.domain();
                AnalyticCongruenceInfo { name: c.name(), title: c.title(), u_min, u_max, v_min, v_max, rows, cols }
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
        let _measure = Measure::start(F);
        let (_, _, r0, c0) = self.inner.domain();
        let rows = args::optional_integer(F, "rows", &rows, 2, MAX_RULINGS, r0)?;
        let cols = args::optional_integer(F, "cols", &cols, 2, MAX_RULINGS, c0)?;
        let reach = if reach.is_undefined() { 1.0 } else { args::number(F, "reach", &reach)? };
        if !(reach > 0.0 && reach <= MAX_REACH) {
            return Err(fail(F, format!("reach must be a number in (0, {MAX_REACH:e}], got {reach}")));
        }
        self.inner.grid_reaching(rows, cols, reach).map(LineCongruence::from_core).map_err(|e| fail(F, e))
    }

    /// Errors of `refined` (refined from one of its grids) against the exact lines at the
    /// same parameters, over the new lines: the largest distance of the d₁ points and the
    /// largest angle of the directions (radians).
    #[wasm_bindgen(unchecked_return_type = "CongruenceErrors")]
    pub fn errors(&self, refined: &LineCongruence) -> Result<JsValue, JsValue> {
        let _measure = Measure::start("AnalyticCongruence.errors");
        let (distance, angle) = self.inner.errors(refined.core());
        to_js("AnalyticCongruence.errors", &CongruenceErrors { distance, angle })
    }

    /// Errors of the paper's diagonal insertion (`subdivide({ scheme: 'butterfly', diagonalOnly:
    /// true })` of one of its grids: the (rows − 1) × (cols − 1) lines on the diagonals, Fig. 13)
    /// against the exact lines at the grid cells' centres: the largest distance of the d₁
    /// points and the largest angle of the directions (radians).
    #[wasm_bindgen(js_name = diagonalErrors, unchecked_return_type = "CongruenceErrors")]
    pub fn diagonal_errors(&self, diagonal: &LineCongruence) -> Result<JsValue, JsValue> {
        let _measure = Measure::start("AnalyticCongruence.diagonalErrors");
        let (distance, angle) = self.inner.diagonal_errors(diagonal.core());
        to_js("AnalyticCongruence.diagonalErrors", &CongruenceErrors { distance, angle })
    }
}
