//! Polygons refined by the curve schemes of Section 4: `subdivide_polygon` and
//! `turning_angles` (how much the refined polygons turn, step by step), as the JavaScript
//! functions of the same names (`crates/ruledlab-wasm/src/polygon.rs`).

use crate::arrays;
use crate::error::{fail, fail_input};
use crate::layout::Layout;
use crate::scheme_options::{read, SchemeArgs, Space};
use glam::DVec3;
use pyo3::prelude::*;

/// `f` of the points of an (N, 3) array, checked (finite, at most 1e150, 2 … 4 194 304 points)
/// and read where they lie, the GIL released.
fn with_polygon<'py, T: Send>(
    py: Python<'py>,
    func: &str,
    points: &Bound<'py, PyAny>,
    f: impl FnOnce(&[DVec3]) -> ruledlab::Result<T> + Send,
) -> PyResult<T> {
    let p = arrays::numbers(func, "points", points)?;
    let n = arrays::rows(func, "points", &p, 3, "point")?;
    let flat = p.slice();
    let points = ruledlab::checked_points(flat)
        .map_err(|e| fail_input(func, e, &Layout::One { name: "points", shape: vec![n, 3], lead: 1 }))?;
    py.detach(|| f(points)).map_err(|e| fail(func, e))
}

/// The curve scheme, closedness and steps of a polygon function's keyword arguments (the
/// options of `subdivide_polygon`: no variational scheme's `n` or `variant`, no `space`).
fn curve_scheme(
    func: &str,
    scheme: &Bound<'_, PyAny>,
    steps: Option<&Bound<'_, PyAny>>,
    w: Option<&Bound<'_, PyAny>>,
    degree: Option<&Bound<'_, PyAny>>,
    closed: Option<&Bound<'_, PyAny>>,
) -> PyResult<(ruledlab::Scheme, bool, usize)> {
    let a = SchemeArgs {
        scheme: Some(scheme),
        steps,
        w,
        n: None,
        variant: None,
        degree,
        closed,
        space: None,
        length: None,
    };
    let (scheme, closed, steps, space) = read(func, &a, None)?;
    debug_assert!(matches!(space, Space::Points));
    Ok((scheme, closed, steps))
}

/// A polygon ((N, 3)) refined by a curve scheme of Section 4: ``scheme`` "chaikin", "bspline"
/// (``degree`` 1 … 7, default 3), "bezier" (de Casteljau) or "four-point" (Dyn–Levin–Gregory
/// (8), tension ``w``, default 1/16); ``steps`` 0 … 24 (default 1); ``closed``. Releases the GIL.
#[pyfunction]
#[pyo3(signature = (points, *, scheme, steps=None, w=None, degree=None, closed=None))]
#[allow(clippy::too_many_arguments)]
pub fn subdivide_polygon<'py>(
    py: Python<'py>,
    points: &Bound<'py, PyAny>,
    scheme: &Bound<'py, PyAny>,
    steps: Option<&Bound<'py, PyAny>>,
    w: Option<&Bound<'py, PyAny>>,
    degree: Option<&Bound<'py, PyAny>>,
    closed: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    const F: &str = "subdivide_polygon";
    let (scheme, closed, steps) = curve_scheme(F, scheme, steps, w, degree, closed)?;
    let out = with_polygon(py, F, points, |p| ruledlab::subdivide_polygon(p, scheme, closed, steps))?;
    arrays::points(py, out)
}

// subdivide_polygon's keywords again: the two functions take the same options, and PyO3 binds
// each function's own signature (what reads them is one: curve_scheme, with_polygon)
/// The largest turning angle (radians, 0 … π: the largest angle between an edge and the next)
/// of a polygon ((N, 3)) and of each of its refinements by a curve scheme (the options of
/// ``subdivide_polygon``): (steps + 1,), the first for the polygon itself. Where the limit is a
/// regular C¹ curve the polygons turn less and less from step to step.
#[pyfunction]
#[pyo3(signature = (points, *, scheme, steps=None, w=None, degree=None, closed=None))]
#[allow(clippy::too_many_arguments)]
pub fn turning_angles<'py>(
    py: Python<'py>,
    points: &Bound<'py, PyAny>,
    scheme: &Bound<'py, PyAny>,
    steps: Option<&Bound<'py, PyAny>>,
    w: Option<&Bound<'py, PyAny>>,
    degree: Option<&Bound<'py, PyAny>>,
    closed: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    const F: &str = "turning_angles";
    let (scheme, closed, steps) = curve_scheme(F, scheme, steps, w, degree, closed)?;
    let out = with_polygon(py, F, points, |p| ruledlab::turning_angles(p, scheme, closed, steps))?;
    let n = out.len();
    arrays::array(py, out, &[n])
}
