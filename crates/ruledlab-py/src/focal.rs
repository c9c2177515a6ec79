//! Focal geometry of congruences as NumPy arrays (beyond the paper; the book's "Focal geometry
//! and linear complexes"): the focal points, kinds and torsal directions of every line, a focal
//! sheet as a mesh, the torsal strokes — for `LineCongruence` and `AnalyticCongruence`. No class.

use crate::args;
use crate::arrays;
use crate::error::fail;
use glam::DVec3;
use numpy::PyArrayMethods;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use ruledlab::tolerance::MAX_STROKE_SCALE;
use ruledlab::{Focal, Mesh};

/// The focal geometry `all` of a rows × cols grid as a dict of arrays (a line runs p → q, e =
/// (q − p)/‖q − p‖, a point on it is p + t·e): ``points`` (rows, cols, 6) F1 then F2 (NaN when
/// not real or at infinity); ``parameters`` (rows, cols, 2) t1 ≤ t2 (±inf at infinity, NaN when
/// not real); ``kind`` (rows, cols) uint8, 0 elliptic, 1 hyperbolic, 2 parabolic; ``torsal``
/// (rows, cols, 4) the unit torsal directions (du, dv) of F1 then F2 in grid steps; ``middle``
/// (rows, cols, 3) the midpoint of the focal points; ``normality`` (rows, cols) |cos| of the
/// angle between the focal planes (0 for a normal congruence).
pub fn focal_dict<'py>(py: Python<'py>, rows: usize, cols: usize, all: &[Focal]) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("rows", rows)?;
    d.set_item("cols", cols)?;
    let points: Vec<f64> = all.iter().flat_map(|f| f.points).flat_map(|p| p.to_array()).collect();
    d.set_item("points", arrays::array(py, points, &[rows, cols, 6])?)?;
    let parameters: Vec<f64> = all.iter().flat_map(|f| f.parameters).collect();
    d.set_item("parameters", arrays::array(py, parameters, &[rows, cols, 2])?)?;
    let kind: Vec<u8> = all.iter().map(|f| f.kind as u8).collect();
    d.set_item("kind", numpy::PyArray1::from_vec(py, kind).reshape(vec![rows, cols])?)?;
    let torsal: Vec<f64> = all.iter().flat_map(|f| f.torsal).flat_map(|w| w.to_array()).collect();
    d.set_item("torsal", arrays::array(py, torsal, &[rows, cols, 4])?)?;
    let middle: Vec<f64> = all.iter().flat_map(|f| f.middle.to_array()).collect();
    d.set_item("middle", arrays::array(py, middle, &[rows, cols, 3])?)?;
    let normality: Vec<f64> = all.iter().map(|f| f.normality).collect();
    d.set_item("normality", arrays::array(py, normality, &[rows, cols])?)?;
    Ok(d)
}

/// A triangle mesh as a dict: ``positions`` (V, 3), ``indices`` (T, 3) uint32.
pub fn mesh_dict(py: Python<'_>, mesh: Mesh) -> PyResult<Bound<'_, PyDict>> {
    let d = PyDict::new(py);
    let triangles = mesh.indices.len() / 3;
    d.set_item("positions", arrays::points(py, mesh.positions)?)?;
    d.set_item("indices", arrays::indices(py, mesh.indices, &[triangles, 3])?)?;
    Ok(d)
}

/// Focal sheet `sheet` (1 or 2) of `grid` from its focal geometry `all`, as a mesh dict with
/// ``normals`` (V, 3) (smooth vertex normals) and the box of its drawn vertices ``min``, ``max``
/// (3,) (NaN when nothing is drawn).
pub fn sheet_dict<'py>(
    py: Python<'py>,
    func: &str,
    grid: &ruledlab::LineCongruence,
    all: &[Focal],
    sheet: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let sheet = args::integer(func, "sheet", sheet, 1, 2)?;
    let mesh = py.detach(|| ruledlab::focal_sheet(grid, all, sheet - 1));
    let normals = mesh.vertex_normals();
    let used = mesh.indices.iter().map(|&i| mesh.positions[i as usize]);
    let (min, max) =
        used.fold((DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)), |(a, b), p| (a.min(p), b.max(p)));
    let finite = |v: DVec3| if v.is_finite() { v } else { DVec3::NAN };
    let d = mesh_dict(py, mesh)?;
    d.set_item("normals", arrays::points(py, normals)?)?;
    d.set_item("min", arrays::array(py, finite(min).to_array().to_vec(), &[3])?)?;
    d.set_item("max", arrays::array(py, finite(max).to_array().to_vec(), &[3])?)?;
    Ok(d)
}

/// Strokes on the director surface d₁ along the real torsal directions, p ± scale·(du·p_i +
/// dv·p_j) (`scale` default 0.35 of a grid step), as an (S, 6) array of segments.
pub fn strokes<'py>(
    py: Python<'py>,
    func: &str,
    grid: &ruledlab::LineCongruence,
    all: &[Focal],
    scale: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let scale = args::optional_number(func, "scale", scale)?.unwrap_or(0.35);
    if !(scale > 0.0 && scale <= MAX_STROKE_SCALE) {
        return Err(fail(func, format!("scale must be a number in (0, {MAX_STROKE_SCALE}], got {scale}")));
    }
    let p = grid.p();
    let segments = ruledlab::torsal_strokes(grid.rows(), grid.cols(), &p, all, scale);
    let flat: Vec<f64> = segments.iter().flat_map(|s| [s.a, s.b]).flat_map(|q| q.to_array()).collect();
    let n = segments.len();
    arrays::array(py, flat, &[n, 6])
}
