//! `AnalyticSurface` for Python: the ruled surfaces of the catalogue, known in closed form, and
//! those typed as formulas; listed, sampled and evaluated exactly, with the measured convergence
//! and sampling orders of their discrete invariants (Section 2, Propositions 1 and 2) — the
//! JavaScript class of the same name (`crates/ruledlab-wasm/src/analytic_surface.rs`).

use crate::args;
use crate::arrays;
use crate::catalogue_entry::entry_dict;
use crate::convert::to_python;
use crate::error::{fail, fail_option};
use crate::formula::{surface_presets, surface_spec};
use crate::ruled_surface::RuledSurface;
use glam::DVec3;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use ruledlab::tolerance::{MAX_SAMPLES, MAX_STRIDE, MAX_STUDY_LEVELS};
use ruledlab::SmoothRuled;

/// An analytic ruled surface x(u, v) = a(u) + v·d(u) with exact striction curve and
/// distribution parameter: one of the catalogue (``AnalyticSurface.by_name("hyperboloid")``,
/// ``AnalyticSurface.list()``) or one typed as formulas (``AnalyticSurface.from_formulas``).
#[pyclass(module = "ruledlab._core", frozen)]
pub struct AnalyticSurface {
    inner: ruledlab::AnalyticSurface,
}

/// The keyword arguments of the sampling ranges (the surface's own where left out).
const RANGES: [&str; 5] = ["u_min", "u_max", "v_min", "v_max", "closed"];

impl AnalyticSurface {
    /// The core surface.
    pub fn core(&self) -> &ruledlab::AnalyticSurface {
        &self.inner
    }

    fn ranges(&self, func: &str, kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<ruledlab::Ranges> {
        let d = self.inner.ranges();
        let r = args::keywords(func, kwargs, &RANGES)?;
        let bound = |k: usize, default: f64| {
            args::optional_number(func, RANGES[k], r[k].as_ref()).map(|x| x.unwrap_or(default))
        };
        Ok(ruledlab::Ranges {
            u: (bound(0, d.u.0)?, bound(1, d.u.1)?),
            v: (bound(2, d.v.0)?, bound(3, d.v.1)?),
            closed: args::flag(func, "closed", r[4].as_ref(), d.closed)?,
        })
    }

    /// The parameters u passed: a 1-D array of finite numbers, at most `MAX_SAMPLES`.
    fn u_values<'py>(func: &str, u: &Bound<'py, PyAny>) -> PyResult<arrays::Numbers<'py>> {
        let values = arrays::numbers(func, "u", u)?;
        let n = arrays::vector(func, "u", &values)?;
        if n > MAX_SAMPLES {
            return Err(fail(func, ruledlab::Error::TooMany { what: "parameters", got: n, max: MAX_SAMPLES }));
        }
        if let Some(k) = values.slice().iter().position(|x| !x.is_finite()) {
            return Err(fail_option(func, "u", format!("every u must be finite, got u[{k}] = {}", values.slice()[k])));
        }
        Ok(values)
    }

    /// `at(u)` for each u, (M, 3) (NaN where it is None).
    fn points_at<'py>(
        &self,
        py: Python<'py>,
        func: &str,
        u: &Bound<'py, PyAny>,
        at: impl Fn(&ruledlab::AnalyticSurface, f64) -> Option<DVec3> + Send + Sync,
    ) -> PyResult<Bound<'py, PyAny>> {
        let values = Self::u_values(func, u)?;
        let u = values.slice();
        let inner = &self.inner;
        let out: Vec<DVec3> = py.detach(|| u.iter().map(|&u| at(inner, u).unwrap_or(DVec3::NAN)).collect());
        arrays::points(py, out)
    }
}

#[pymethods]
impl AnalyticSurface {
    // --- the catalogue, and surfaces typed as formulas
    // (list, by_name, formula_presets, name and title have AnalyticCongruence's signatures: PyO3 binds
    // methods class by class; what they do is shared: catalogue_entry, args, formula)

    /// Every analytic surface of the catalogue: dicts with ``name``, ``title`` and the default
    /// ranges ``u_min``, ``u_max``, ``v_min``, ``v_max``, ``closed``.
    #[staticmethod]
    fn list(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
        let list = PyList::empty(py);
        for s in ruledlab::AnalyticSurface::ALL.iter() {
            let r = s.ranges();
            let d = entry_dict(py, s.name(), s.title(), r.u, r.v)?;
            d.set_item("closed", r.closed)?;
            list.append(d)?;
        }
        Ok(list)
    }

    /// The surface of the catalogue named ``name`` (see ``list()``).
    #[staticmethod]
    fn by_name(name: &Bound<'_, PyAny>) -> PyResult<Self> {
        const F: &str = "AnalyticSurface.by_name";
        let name = args::text(F, "name", name)?;
        ruledlab::AnalyticSurface::by_name(&name).map(|inner| AnalyticSurface { inner }).map_err(|e| fail(F, e))
    }

    /// Every surface of the catalogue as formulas, in menu order (``name``, ``a``, ``e``, ``u``,
    /// ``v``, ``closed``, ``parameters``): ``from_formulas`` of a preset is the surface of its name.
    #[staticmethod]
    fn formula_presets(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
        surface_presets(py)
    }

    /// A surface typed as formulas in u (and the parameters a, b, c): ``a`` and ``e`` three
    /// formulas each, x(u, v) = a(u) + v·e(u) for u in ``u`` (two bounds, numbers or formulas
    /// such as "2*pi") and v in ``v`` (default (−1, 1)); a′ and e′ are differentiated exactly.
    /// Functions: + − * / ^, sin cos tan asin acos atan atan2 sinh cosh tanh exp ln log sqrt abs;
    /// constants pi, e. ``decimal_comma``: True, False or "unambiguous".
    #[staticmethod]
    #[pyo3(signature = (a, e, u, *, v=None, closed=None, parameters=None, decimal_comma=None))]
    #[allow(clippy::too_many_arguments)]
    fn from_formulas(
        py: Python<'_>,
        a: &Bound<'_, PyAny>,
        e: &Bound<'_, PyAny>,
        u: &Bound<'_, PyAny>,
        v: Option<&Bound<'_, PyAny>>,
        closed: Option<&Bound<'_, PyAny>>,
        parameters: Option<&Bound<'_, PyAny>>,
        decimal_comma: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        const F: &str = "AnalyticSurface.from_formulas";
        let spec = surface_spec(F, a, e, u, v, closed, parameters, decimal_comma)?;
        py.detach(|| ruledlab::AnalyticSurface::from_formulas(&spec))
            .map(|inner| AnalyticSurface { inner })
            .map_err(|e| fail(F, e))
    }

    /// Machine name, e.g. "hyperboloid".
    #[getter]
    fn name(&self) -> String {
        self.inner.name().into()
    }

    /// Human title.
    #[getter]
    fn title(&self) -> String {
        self.inner.title().into()
    }

    fn __repr__(&self) -> String {
        format!("<ruledlab.AnalyticSurface {:?}>", self.inner.name())
    }

    // --- sampling

    /// ``count`` rulings at equally spaced u over the surface's ranges (or those given).
    #[pyo3(signature = (count, **ranges))]
    fn sample(
        &self,
        py: Python<'_>,
        count: &Bound<'_, PyAny>,
        ranges: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<RuledSurface> {
        const F: &str = "AnalyticSurface.sample";
        let count = args::integer(F, "count", count, 2, MAX_SAMPLES)?;
        let r = self.ranges(F, ranges)?;
        py.detach(|| self.inner.sample(count, r)).map(RuledSurface::from_core).map_err(|e| fail(F, e))
    }

    /// The parameters u_i at which ``sample(count, …)`` takes its rulings, (count,).
    #[pyo3(signature = (count, **ranges))]
    fn parameters<'py>(
        &self,
        py: Python<'py>,
        count: &Bound<'py, PyAny>,
        ranges: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        const F: &str = "AnalyticSurface.parameters";
        let count = args::integer(F, "count", count, 2, MAX_SAMPLES)?;
        let r = self.ranges(F, ranges)?;
        arrays::array(py, ruledlab::sample_parameters(count, r), &[count])
    }

    // --- exact values

    /// The exact striction points s(u) at each u (a 1-D array), (M, 3) (NaN on a cylindrical
    /// ruling).
    fn striction<'py>(&self, py: Python<'py>, u: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        self.points_at(py, "AnalyticSurface.striction", u, |s, u| s.striction(u))
    }

    /// The exact distribution parameters δ(u) at each u, (M,).
    fn distribution<'py>(&self, py: Python<'py>, u: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let values = Self::u_values("AnalyticSurface.distribution", u)?;
        let u = values.slice();
        let out: Vec<f64> = py.detach(|| u.iter().map(|&u| self.inner.distribution(u)).collect());
        let n = out.len();
        arrays::array(py, out, &[n])
    }

    /// The exact central tangent directions e₃(u) (4) at each u, (M, 3) (NaN on a cylindrical
    /// ruling).
    fn central_tangent<'py>(&self, py: Python<'py>, u: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        self.points_at(py, "AnalyticSurface.central_tangent", u, |s, u| s.central_tangent(u))
    }

    // --- how far discrete surfaces are from it

    /// The distance of each point ((M, 3)) from the surface, its rulings extended to whole
    /// lines, searching the rulings with u in [u_min, u_max], (M,).
    fn distances<'py>(
        &self,
        py: Python<'py>,
        points: &Bound<'py, PyAny>,
        u_min: &Bound<'py, PyAny>,
        u_max: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        const F: &str = "AnalyticSurface.distances";
        let p = arrays::numbers(F, "points", points)?;
        let n = arrays::rows(F, "points", &p, 3, "point")?;
        let (lo, hi) = (args::number(F, "u_min", u_min)?, args::number(F, "u_max", u_max)?);
        if lo >= hi {
            return Err(fail(F, format!("need u_min < u_max, got {lo} and {hi}")));
        }
        if n > MAX_SAMPLES {
            return Err(fail(F, ruledlab::Error::TooMany { what: "points", got: n, max: MAX_SAMPLES }));
        }
        let flat = p.slice();
        ruledlab::check_coordinates(flat, 3).map_err(|e| {
            crate::error::fail_input(F, e, &crate::layout::Layout::One { name: "points", shape: vec![n, 3], lead: 1 })
        })?;
        let out: Vec<f64> =
            py.detach(|| flat.chunks_exact(3).map(|q| self.inner.distance_to(DVec3::from_slice(q), lo, hi)).collect());
        arrays::array(py, out, &[n])
    }

    /// The largest distance from this surface of the rulings of ``refined`` whose index is not
    /// a multiple of ``stride`` (the inserted ones), sampled at 9 points each; ``refined`` was
    /// refined from a sampling of [u_min, u_max].
    fn inserted_distance(
        &self,
        py: Python<'_>,
        refined: &RuledSurface,
        stride: &Bound<'_, PyAny>,
        u_min: &Bound<'_, PyAny>,
        u_max: &Bound<'_, PyAny>,
    ) -> PyResult<f64> {
        const F: &str = "AnalyticSurface.inserted_distance";
        let stride = args::integer(F, "stride", stride, 2, MAX_STRIDE)?;
        let (lo, hi) = (args::number(F, "u_min", u_min)?, args::number(F, "u_max", u_max)?);
        if lo >= hi {
            return Err(fail(F, format!("need u_min < u_max, got {lo} and {hi}")));
        }
        let which = (0..refined.core().len()).filter(move |i| i % stride != 0);
        Ok(py.detach(|| ruledlab::max_distance(&self.inner, refined.core(), lo, hi, which)))
    }

    // --- convergence of the discrete invariants (Propositions 1 and 2)

    /// How far the discrete invariants of ``count`` sampled rulings are from the exact ones at
    /// those rulings: ``rulings``, ``parallel_pairs``, ``footpoint``, ``midpoint``,
    /// ``perpendicular_midpoint``, ``distribution_mean`` (closed surfaces read as closed).
    #[pyo3(signature = (count, **ranges))]
    fn sampling_errors<'py>(
        &self,
        py: Python<'py>,
        count: &Bound<'py, PyAny>,
        ranges: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        const F: &str = "AnalyticSurface.sampling_errors";
        let count = args::integer(F, "count", count, 3, MAX_SAMPLES)?;
        let r = self.ranges(F, ranges)?;
        let e = py.detach(|| ruledlab::sampling_errors(&self.inner, count, r)).map_err(|e| fail(F, e))?;
        to_python(py, &e)
    }

    /// The orders measured from ``count`` rulings and the spacing halved: log₂ of the ratio of
    /// the two samplings' errors (Propositions 1 and 2: 1, 2, 2, 2), with ``finer``.
    #[pyo3(signature = (count, **ranges))]
    fn sampling_orders<'py>(
        &self,
        py: Python<'py>,
        count: &Bound<'py, PyAny>,
        ranges: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        const F: &str = "AnalyticSurface.sampling_orders";
        let count = args::integer(F, "count", count, 3, MAX_SAMPLES / 2)?;
        let r = self.ranges(F, ranges)?;
        let o = py.detach(|| ruledlab::sampling_orders(&self.inner, count, r)).map_err(|e| fail(F, e))?;
        to_python(py, &o)
    }

    /// The measured convergence orders of the discrete invariants at ``u`` (default 0.7) for
    /// steps H₀ = ``h0`` (default 0.2), H₀/2, … (``levels`` 2 … 20, default 8): ``surface``,
    /// ``u``, ``steps``, ``series`` (per quantity: ``name``, ``expected_order``, ``errors``,
    /// ``orders``, ``fitted_order``).
    #[pyo3(signature = (*, u=None, h0=None, levels=None))]
    fn convergence<'py>(
        &self,
        py: Python<'py>,
        u: Option<&Bound<'py, PyAny>>,
        h0: Option<&Bound<'py, PyAny>>,
        levels: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        const F: &str = "AnalyticSurface.convergence";
        let levels = args::optional_integer(F, "levels", levels, 2, MAX_STUDY_LEVELS, 8)?;
        let u = args::optional_number(F, "u", u)?.unwrap_or(0.7);
        let h0 = args::optional_number(F, "h0", h0)?.unwrap_or(0.2);
        let study = py.detach(|| ruledlab::convergence_study(&self.inner, u, h0, levels)).map_err(|e| fail(F, e))?;
        to_python(py, &study)
    }
}
