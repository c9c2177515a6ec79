//! `AnalyticCongruence` for Python: the line congruences of the catalogue, known in closed form
//! (Section 5, Examples 4 and 5), and those typed as formulas; listed, sampled as grids, compared
//! with refined grids, and their exact focal geometry — the JavaScript class of the same name
//! (`crates/ruledlab-wasm/src/analytic_congruence.rs`).

use crate::args;
use crate::catalogue_entry::entry_dict;
use crate::error::fail;
use crate::focal::focal_dict;
use crate::formula::{congruence_presets, congruence_spec};
use crate::line_congruence::LineCongruence;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use ruledlab::tolerance::{MAX_REACH, MAX_RULINGS};
use ruledlab::SmoothCongruence;

/// An analytic line congruence p(u, v) + t·d(u, v): one of the catalogue ("sphere",
/// "hyperbolic-paraboloid", "example5") or one typed as formulas.
#[pyclass(module = "ruledlab._core", frozen)]
pub struct AnalyticCongruence {
    inner: ruledlab::AnalyticCongruence,
}

/// `{"distance": …, "angle": …}`.
fn errors_dict(py: Python<'_>, (distance, angle): (f64, f64)) -> PyResult<Bound<'_, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("distance", distance)?;
    d.set_item("angle", angle)?;
    Ok(d)
}

#[pymethods]
impl AnalyticCongruence {
    // --- the catalogue, and congruences typed as formulas
    // (list, by_name, formula_presets, name and title have AnalyticSurface's signatures: PyO3 binds
    // methods class by class; what they do is shared: catalogue_entry, args, formula)

    /// Every congruence of the catalogue: dicts with ``name``, ``title``, the domain ``u_min``,
    /// ``u_max``, ``v_min``, ``v_max`` and the grid size of the paper's figure ``rows``, ``cols``.
    #[staticmethod]
    fn list(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
        let list = PyList::empty(py);
        for c in ruledlab::AnalyticCongruence::ALL.iter() {
            let (u, v, rows, cols) = c.domain();
            let d = entry_dict(py, c.name(), c.title(), u, v)?;
            d.set_item("rows", rows)?;
            d.set_item("cols", cols)?;
            list.append(d)?;
        }
        Ok(list)
    }

    /// The congruence of the catalogue named ``name``.
    #[staticmethod]
    fn by_name(name: &Bound<'_, PyAny>) -> PyResult<Self> {
        const F: &str = "AnalyticCongruence.by_name";
        let name = args::text(F, "name", name)?;
        ruledlab::AnalyticCongruence::by_name(&name).map(|inner| AnalyticCongruence { inner }).map_err(|e| fail(F, e))
    }

    /// Every congruence of the catalogue as formulas, in menu order (``name``, ``p``, ``e``,
    /// ``u``, ``v``, ``rows``, ``cols``, ``parameters``, ``reach``).
    #[staticmethod]
    fn formula_presets(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
        congruence_presets(py)
    }

    /// A congruence typed as formulas in u, v (and a, b, c): the line through p(u, v) along
    /// e(u, v), ``p`` and ``e`` three formulas each, over ``u`` × ``v`` (two bounds each, numbers
    /// or formulas); ``rows``, ``cols``: the default grid of ``grid()`` (2 … 1000, default 8);
    /// exact derivatives.
    #[staticmethod]
    #[pyo3(signature = (p, e, u, v, *, parameters=None, rows=None, cols=None, decimal_comma=None))]
    #[allow(clippy::too_many_arguments)]
    fn from_formulas(
        py: Python<'_>,
        p: &Bound<'_, PyAny>,
        e: &Bound<'_, PyAny>,
        u: &Bound<'_, PyAny>,
        v: &Bound<'_, PyAny>,
        parameters: Option<&Bound<'_, PyAny>>,
        rows: Option<&Bound<'_, PyAny>>,
        cols: Option<&Bound<'_, PyAny>>,
        decimal_comma: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        const F: &str = "AnalyticCongruence.from_formulas";
        let spec = congruence_spec(F, p, e, u, v, parameters, rows, cols, decimal_comma)?;
        py.detach(|| ruledlab::AnalyticCongruence::from_formulas(&spec))
            .map(|inner| AnalyticCongruence { inner })
            .map_err(|e| fail(F, e))
    }

    /// Machine name, e.g. "sphere".
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
        format!("<ruledlab.AnalyticCongruence {:?}>", self.inner.name())
    }

    // --- grids of its lines, and how far refined grids are from it

    /// A rows × cols grid of its lines (default: the paper's grid size), each the segment from
    /// p to p + reach·d (``reach`` default 1).
    #[pyo3(signature = (rows=None, cols=None, *, reach=None))]
    fn grid(
        &self,
        py: Python<'_>,
        rows: Option<&Bound<'_, PyAny>>,
        cols: Option<&Bound<'_, PyAny>>,
        reach: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<LineCongruence> {
        const F: &str = "AnalyticCongruence.grid";
        let (_, _, r0, c0) = self.inner.domain();
        let rows = args::optional_integer(F, "rows", rows, 2, MAX_RULINGS, r0)?;
        let cols = args::optional_integer(F, "cols", cols, 2, MAX_RULINGS, c0)?;
        let reach = args::optional_number(F, "reach", reach)?.unwrap_or(1.0);
        if !(reach > 0.0 && reach <= MAX_REACH) {
            return Err(fail(F, format!("reach must be a number in (0, {MAX_REACH:e}], got {reach}")));
        }
        py.detach(|| self.inner.grid_reaching(rows, cols, reach)).map(LineCongruence::from_core).map_err(|e| fail(F, e))
    }

    /// The errors of ``refined`` (refined from one of its grids) against the exact lines at the
    /// same parameters, over the new lines: ``distance`` (of the d₁ points) and ``angle``
    /// (radians, of the directions).
    fn errors<'py>(&self, py: Python<'py>, refined: &LineCongruence) -> PyResult<Bound<'py, PyDict>> {
        errors_dict(py, py.detach(|| self.inner.errors(refined.core())))
    }

    /// The errors of the paper's diagonal insertion (``subdivide(scheme="butterfly",
    /// diagonal_only=True)`` of one of its grids, Fig. 13) against the exact lines at the
    /// cells' centres: ``distance`` and ``angle``.
    fn diagonal_errors<'py>(&self, py: Python<'py>, diagonal: &LineCongruence) -> PyResult<Bound<'py, PyDict>> {
        errors_dict(py, py.detach(|| self.inner.diagonal_errors(diagonal.core())))
    }

    // --- focal geometry (beyond the paper)

    /// The exact focal geometry at the lines of its rows × cols grid (default: the paper's grid
    /// size), from the exact derivatives, torsal directions in grid steps: comparable line by
    /// line with ``grid(rows, cols).focal()``.
    #[pyo3(signature = (rows=None, cols=None))]
    fn focal<'py>(
        &self,
        py: Python<'py>,
        rows: Option<&Bound<'py, PyAny>>,
        cols: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        const F: &str = "AnalyticCongruence.focal";
        let (_, _, r0, c0) = self.inner.domain();
        let rows = args::optional_integer(F, "rows", rows, 2, MAX_RULINGS, r0)?;
        let cols = args::optional_integer(F, "cols", cols, 2, MAX_RULINGS, c0)?;
        if rows.saturating_mul(cols) > MAX_RULINGS {
            let got = rows.saturating_mul(cols);
            return Err(fail(F, ruledlab::Error::TooMany { what: "lines", got, max: MAX_RULINGS }));
        }
        let all = py.detach(|| ruledlab::focal_analytic(&self.inner, rows, cols));
        focal_dict(py, rows, cols, &all)
    }
}
