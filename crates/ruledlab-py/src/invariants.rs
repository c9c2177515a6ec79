//! The discrete invariants of Section 2 as NumPy arrays: the dict that
//! `RuledSurface.invariants()` returns, each array owning the core's memory (no copy). No class.

use crate::arrays::{array, flags, points};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The core's invariants of N rulings (N − 1 pairs and N − 2 interior rulings; N and N closed)
/// as a dict of arrays:
///
/// | key | shape | |
/// |---|---|---|
/// | `angle` | (P,) | φ_{i,i+1} ∈ [0, π] |
/// | `distance` | (P,) | h_{i,i+1} = det(a_{i+1} − a_i, e_i, e_{i+1}) / ‖e_i × e_{i+1}‖, signed |
/// | `distribution` | (P,) | δ_{i,i+1} = h/φ (1) |
/// | `footpoints` | (P, 6) | f_{i,i+1} then f_{i+1,i} |
/// | `central_normal` | (P, 3) | n_{i,i+1} = e_i × e_{i+1} / ‖e_i × e_{i+1}‖ |
/// | `striction` | (M, 3) | m_i = (f_{i,i−1} + f_{i,i+1})/2 (7) |
/// | `distribution_mean` | (M,) | (δ_{i−1,i} + δ_{i,i+1})/2 (7) |
/// | `perpendicular_midpoints` | (P, 3) | (f_{i,i+1} + f_{i+1,i})/2 (Example 1) |
/// | `parallel` | (P,) bool | ‖sin φ‖ < 1e-9: there `distance` is unsigned and the rest NaN |
pub fn invariants_dict(py: Python<'_>, inv: ruledlab::Invariants) -> PyResult<Bound<'_, PyDict>> {
    let pairs = inv.angle.len();
    let d = PyDict::new(py);
    d.set_item("angle", array(py, inv.angle, &[pairs])?)?;
    d.set_item("distance", array(py, inv.distance, &[pairs])?)?;
    d.set_item("distribution", array(py, inv.distribution, &[pairs])?)?;
    d.set_item("footpoints", array(py, bytemuck::allocation::cast_vec(inv.footpoints), &[pairs, 6])?)?;
    d.set_item("central_normal", points(py, inv.central_normal)?)?;
    d.set_item("striction", points(py, inv.striction)?)?;
    let interior = inv.distribution_mean.len();
    d.set_item("distribution_mean", array(py, inv.distribution_mean, &[interior])?)?;
    d.set_item("perpendicular_midpoints", points(py, inv.perpendicular_midpoints)?)?;
    d.set_item("parallel", flags(py, inv.parallel))?;
    Ok(d)
}
