//! The least-squares line of points (beyond the paper): `fit_line(points)`, as the JavaScript
//! `fitLine`.

use crate::arrays;
use crate::error::{fail, fail_input};
use crate::layout::Layout;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The line that fits ``points`` ((N, 3), N ≥ 2, not all equal) best in the least-squares
/// sense: ``point`` (3,) the centroid, ``direction`` (3,) unit, ``deviation`` the largest
/// distance of a point from the line (0 exactly when they are collinear), ``extent`` the length
/// of their shadow on the line.
#[pyfunction]
pub fn fit_line<'py>(py: Python<'py>, points: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyDict>> {
    const F: &str = "fit_line";
    let p = arrays::numbers(F, "points", points)?;
    let n = arrays::rows(F, "points", &p, 3, "point")?;
    let points = ruledlab::points_from_flat(p.slice())
        .map_err(|e| fail_input(F, e, &Layout::One { name: "points", shape: vec![n, 3], lead: 1 }))?;
    let fit = ruledlab::fit_line(&points).map_err(|e| fail(F, e))?;
    let d = PyDict::new(py);
    d.set_item("point", arrays::array(py, fit.point.to_array().to_vec(), &[3])?)?;
    d.set_item("direction", arrays::array(py, fit.direction.to_array().to_vec(), &[3])?)?;
    d.set_item("deviation", fit.deviation)?;
    d.set_item("extent", fit.extent)?;
    Ok(d)
}
