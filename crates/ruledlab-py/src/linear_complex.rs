//! Linear complexes (beyond the paper): `linear_complex(a, b)` and the fit that
//! `RuledSurface.linear_complex()` and `LineCongruence.linear_complex()` return — the complex
//! c·m + c̄·d = 0 that fits the lines best (Plücker coordinates (d, m), d unit, m = x × d).

use crate::args;
use crate::arrays::{self, interleave};
use crate::error::{fail_input, fail_option};
use crate::layout::Layout;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use ruledlab::{LinearComplex, Segment};

/// The tolerance argument: (0, 1], None for the default (1e-9).
fn tolerance(func: &str, value: Option<&Bound<'_, PyAny>>) -> PyResult<Option<f64>> {
    let t = args::optional_number(func, "tolerance", value)?;
    if let Some(t) = t.filter(|t| !(*t > 0.0 && *t <= 1.0)) {
        return Err(fail_option(func, "tolerance", format!("tolerance must be a number in (0, 1], got {t}")));
    }
    Ok(t)
}

/// The best-fitting complex of `segments` as a dict: `plucker` (6,) (c, c̄), `pitch`,
/// `axis_point` (3,), `axis_direction` (3,), `axis_segment` (6,), `residual`, `spectrum` (6,),
/// `nullity`, `kind` ("general", "complex", "congruence", "regulus", "special").
pub fn complex_dict<'py>(
    py: Python<'py>,
    func: &str,
    segments: &[Segment],
    tol: Option<&Bound<'_, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let tol = tolerance(func, tol)?;
    let f: LinearComplex = py.detach(|| ruledlab::fit_linear_complex(segments, tol));
    let d = PyDict::new(py);
    d.set_item("plucker", arrays::array(py, f.plucker.to_vec(), &[6])?)?;
    d.set_item("pitch", f.pitch)?;
    d.set_item("axis_point", arrays::array(py, f.axis_point.to_array().to_vec(), &[3])?)?;
    d.set_item("axis_direction", arrays::array(py, f.axis_direction.to_array().to_vec(), &[3])?)?;
    let [p, q] = f.axis_segment;
    d.set_item("axis_segment", arrays::array(py, [p.to_array(), q.to_array()].concat(), &[6])?)?;
    d.set_item("residual", f.residual)?;
    d.set_item("spectrum", arrays::array(py, f.spectrum.to_vec(), &[6])?)?;
    d.set_item("nullity", f.nullity)?;
    d.set_item("kind", f.kind.name())?;
    Ok(d)
}

/// The linear complex c·m + c̄·d = 0 that fits the lines through `a[i]` and `b[i]` best (N × 3
/// each, N ≥ 2), with how many independent complexes hold them (`nullity`: 1 a complex, 2 a
/// congruence, 3 a regulus). `tolerance`: the root-mean-square residual in the fit's frame under
/// which a complex holds the lines (default 1e-9).
#[pyfunction]
#[pyo3(signature = (a, b, *, tolerance=None))]
pub fn linear_complex<'py>(
    py: Python<'py>,
    a: &Bound<'py, PyAny>,
    b: &Bound<'py, PyAny>,
    tolerance: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    const F: &str = "linear_complex";
    let (na, nb) = (arrays::numbers(F, "a", a)?, arrays::numbers(F, "b", b)?);
    let n = arrays::rows(F, "a", &na, 3, "point")?;
    arrays::rows(F, "b", &nb, 3, "point")?;
    arrays::same_shape(F, ["a", "b"], &na, &nb)?;
    let surface = ruledlab::RuledSurface::from_points(interleave(na.slice(), nb.slice()))
        .map_err(|e| fail_input(F, e, &Layout::Pair { names: ["a", "b"], lead: vec![n] }))?;
    complex_dict(py, F, &surface.segments().collect::<Vec<_>>(), tolerance)
}
