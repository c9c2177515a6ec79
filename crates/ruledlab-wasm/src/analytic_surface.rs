//! `AnalyticSurface` for JavaScript: the ruled surfaces of the catalogue, known in closed form,
//! and those typed as formulas; listed, sampled and evaluated exactly, with the measured
//! convergence and sampling orders of their discrete invariants (Section 2).

use super::catalogue_entry::CatalogueEntry;
use super::formula::{surface_presets, surface_spec};
use super::ruled_surface::RuledSurface;
use js_sys::Float64Array;
use ruledlab::tolerance::{MAX_SAMPLES, MAX_STRIDE, MAX_STUDY_LEVELS};
use ruledlab::SmoothRuled;
use ruledlab_js::args::{
    self, fail, finite_option, integer, integer_option, interval, numbers, options, to_js, to_js_with,
};
use ruledlab_js::live::Live;
use ruledlab_js::timing::Measure;
use serde::Deserialize;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// Sampling options; omitted fields take the surface's defaults (`AnalyticSurface.list()`).
#[derive(Deserialize, Default, Tsify)]
#[serde(rename_all = "camelCase", default)]
struct SampleOptions {
    u_min: Option<f64>,
    u_max: Option<f64>,
    v_min: Option<f64>,
    v_max: Option<f64>,
    /// Read the surface as closed (R_{N−1} followed by R_0).
    closed: Option<bool>,
}

/// One analytic surface as listed by `AnalyticSurface.list()`: its name, title and default
/// ranges.
#[derive(Tsify)]
#[allow(dead_code)] // the type is for TypeScript: `list` sets `closed` on the entry
struct AnalyticSurfaceInfo {
    /// Name, title and default ranges.
    #[serde(flatten)]
    entry: CatalogueEntry,
    /// The surface closes (R_{N−1} followed by R_0).
    closed: bool,
}

/// Options of `AnalyticSurface.convergence` (Propositions 1 and 2).
#[derive(Deserialize, Default, Tsify)]
#[serde(default)]
struct ConvergenceOptions {
    /// Parameter u to study (default 0.7).
    u: Option<f64>,
    /// Largest step H₀ ∈ (0, 1] (default 0.2).
    h0: Option<f64>,
    /// Number of steps H₀, H₀/2, … (2 … 20, default 8).
    levels: Option<f64>,
}

/// An analytic ruled surface x(u, v) = a(u) + v d(u) with exact striction curve and
/// distribution parameter.
#[wasm_bindgen]
pub struct AnalyticSurface {
    inner: ruledlab::AnalyticSurface,
    _live: Live,
}

impl AnalyticSurface {
    /// Wraps a core surface.
    pub(crate) fn from_core(inner: ruledlab::AnalyticSurface) -> Self {
        AnalyticSurface { inner, _live: Live::new() }
    }

    /// The core surface.
    pub(super) fn core(&self) -> &ruledlab::AnalyticSurface {
        &self.inner
    }

    /// Sampling ranges from `SampleOptions`, defaults from the surface.
    fn ranges(&self, func: &'static str, opts: JsValue) -> Result<ruledlab::Ranges, JsValue> {
        let o: SampleOptions = options(func, opts)?;
        let d = self.inner.ranges();
        let bound =
            |name: &str, x: Option<f64>, default: f64| finite_option(func, name, x).map(|x| x.unwrap_or(default));
        Ok(ruledlab::Ranges {
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

    /// The parameters u passed as `u`: finite, at most `MAX_SAMPLES` of them.
    fn u_values(&self, func: &str, u: &JsValue) -> Result<Vec<f64>, JsValue> {
        let u = numbers(func, "u", u)?;
        if u.len() > MAX_SAMPLES {
            return Err(fail(func, ruledlab::Error::TooMany { what: "parameters", got: u.len(), max: MAX_SAMPLES }));
        }
        if let Some(x) = u.iter().find(|x| !x.is_finite()) {
            return Err(fail(func, format!("every u must be finite, got {x}")));
        }
        Ok(u)
    }
}

#[wasm_bindgen]
impl AnalyticSurface {
    // --- the catalogue, and surfaces typed as formulas

    /// Every analytic surface: name, title and default ranges.
    #[wasm_bindgen(unchecked_return_type = "AnalyticSurfaceInfo[]")]
    pub fn list() -> Result<JsValue, JsValue> {
        let list: js_sys::Array = ruledlab::AnalyticSurface::ALL
            .iter()
            .map(|s| {
                let r = s.ranges();
                let entry = CatalogueEntry {
                    name: s.name(),
                    title: s.title(),
                    u_min: r.u.0,
                    u_max: r.u.1,
                    v_min: r.v.0,
                    v_max: r.v.1,
                };
                to_js_with("AnalyticSurface.list", &entry, &[("closed", r.closed.into())])
            })
            .collect::<Result<_, _>>()?;
        Ok(list.into())
    }

    /// The surface named `name` (see `list()`); throws for an unknown name.
    #[wasm_bindgen(js_name = byName)]
    pub fn by_name(#[wasm_bindgen(unchecked_param_type = "string")] name: JsValue) -> Result<AnalyticSurface, JsValue> {
        let inner = args::by_name("AnalyticSurface.byName", &name, ruledlab::AnalyticSurface::by_name)?;
        Ok(AnalyticSurface { inner, _live: Live::new() })
    }

    /// Every surface of the catalogue as formulas, in menu order: the presets of "Your
    /// surface". `fromFormulas` of a preset is the surface of its name (tested to 1e-12).
    #[wasm_bindgen(js_name = formulaPresets, unchecked_return_type = "SurfacePreset[]")]
    pub fn formula_presets() -> Result<JsValue, JsValue> {
        to_js("AnalyticSurface.formulaPresets", &surface_presets())
    }

    /// A surface typed as formulas (`SurfaceFormulas`): everything the built-in surfaces do,
    /// with a′ and e′ differentiated exactly. Throws with the formula and column of a syntax
    /// error, or the parameter where a value is not finite or e(u) vanishes.
    #[wasm_bindgen(js_name = fromFormulas)]
    pub fn from_formulas(
        #[wasm_bindgen(unchecked_param_type = "SurfaceFormulas")] spec: JsValue,
    ) -> Result<AnalyticSurface, JsValue> {
        const F: &str = "AnalyticSurface.fromFormulas";
        let _measure = Measure::start(F);
        let spec = surface_spec(F, spec)?;
        ruledlab::AnalyticSurface::from_formulas(&spec).map(AnalyticSurface::from_core).map_err(|e| fail(F, e))
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

    // --- sampling

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
        Ok(Float64Array::from(&ruledlab::sample_parameters(count, r)[..]))
    }

    // --- exact values

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

    // --- how far discrete surfaces are from it

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
        ruledlab::check_coordinates(&flat, 3).map_err(|e| fail(F, e))?;
        let out: Vec<f64> =
            flat.chunks_exact(3).map(|p| self.inner.distance_to(glam::DVec3::from_slice(p), u_min, u_max)).collect();
        Ok(Float64Array::from(&out[..]))
    }

    /// Largest distance from this surface of the rulings of `refined` whose index is not a
    /// multiple of `stride` (the inserted ones), sampled at 9 points each; `refined` was
    /// refined from a sampling of the parameter interval [uMin, uMax].
    #[wasm_bindgen(js_name = insertedDistance)]
    pub fn inserted_distance(
        &self,
        refined: &RuledSurface,
        #[wasm_bindgen(unchecked_param_type = "number")] stride: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] u_min: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] u_max: JsValue,
    ) -> Result<f64, JsValue> {
        const F: &str = "AnalyticSurface.insertedDistance";
        let stride = integer(F, "stride", &stride, 2, MAX_STRIDE)?;
        let (u_min, u_max) = interval(F, &u_min, &u_max)?;
        let which = (0..refined.length()).filter(|i| i % stride != 0);
        Ok(ruledlab::max_distance(self.core(), refined.core(), u_min, u_max, which))
    }

    // --- convergence of the discrete invariants (Propositions 1 and 2)

    /// How far the discrete invariants of `count` sampled rulings are from the exact ones at
    /// those rulings (closed surfaces read as closed).
    #[wasm_bindgen(js_name = samplingErrors, unchecked_return_type = "SamplingErrors")]
    pub fn sampling_errors(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] count: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "SampleOptions")] opts: JsValue,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "AnalyticSurface.samplingErrors";
        let _measure = Measure::start(F);
        let count = integer(F, "count", &count, 3, MAX_SAMPLES)?;
        let r = self.ranges(F, opts)?;
        let e = ruledlab::sampling_errors(self.core(), count, r).map_err(|e| fail(F, e))?;
        to_js(F, &e)
    }

    /// Orders measured from `count` rulings and the spacing halved (`SamplingOrders`): log₂ of
    /// the ratio of the two samplings' errors (Propositions 1 and 2: 1, 2, 2, 2).
    #[wasm_bindgen(js_name = samplingOrders, unchecked_return_type = "SamplingOrders")]
    pub fn sampling_orders(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] count: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "SampleOptions")] opts: JsValue,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "AnalyticSurface.samplingOrders";
        let _measure = Measure::start(F);
        let count = integer(F, "count", &count, 3, MAX_SAMPLES / 2)?;
        let r = self.ranges(F, opts)?;
        let o = ruledlab::sampling_orders(self.core(), count, r).map_err(|e| fail(F, e))?;
        to_js(F, &o)
    }

    /// Measured convergence orders of the discrete invariants (Propositions 1 and 2).
    #[wasm_bindgen(unchecked_return_type = "ConvergenceStudy")]
    pub fn convergence(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "ConvergenceOptions")] opts: JsValue,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "AnalyticSurface.convergence";
        let _measure = Measure::start(F);
        let o: ConvergenceOptions = options(F, opts)?;
        let levels = integer_option(F, "levels", o.levels, 2, MAX_STUDY_LEVELS)?.unwrap_or(8);
        let u = finite_option(F, "u", o.u)?.unwrap_or(0.7);
        let h0 = finite_option(F, "h0", o.h0)?.unwrap_or(0.2);
        let study = ruledlab::convergence_study(self.core(), u, h0, levels).map_err(|e| fail(F, e))?;
        to_js(F, &study)
    }
}
