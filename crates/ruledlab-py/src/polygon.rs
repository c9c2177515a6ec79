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

/// A function of a polygon ((N, 3)) and a curve scheme's keywords: `run` gives the core's
/// answer for the points, the scheme, closedness and steps, and `out` makes it an array. Both
/// functions take the same keywords and PyO3 reads a function's keywords from its own
/// signature: it is written once, here.
macro_rules! polygon_function {
    ($(#[$doc:meta])* $name:ident, run: $run:path, out: $out:path) => {
        $(#[$doc])*
        #[pyfunction]
        #[pyo3(signature = (points, *, scheme, steps=None, w=None, degree=None, closed=None))]
        #[allow(clippy::too_many_arguments)]
        pub fn $name<'py>(
            py: Python<'py>,
            points: &Bound<'py, PyAny>,
            scheme: &Bound<'py, PyAny>,
            steps: Option<&Bound<'py, PyAny>>,
            w: Option<&Bound<'py, PyAny>>,
            degree: Option<&Bound<'py, PyAny>>,
            closed: Option<&Bound<'py, PyAny>>,
        ) -> PyResult<Bound<'py, PyAny>> {
            const F: &str = stringify!($name);
            let (scheme, closed, steps) = curve_scheme(F, scheme, steps, w, degree, closed)?;
            let out = with_polygon(py, F, points, |p| $run(p, scheme, closed, steps))?;
            $out(py, out)
        }
    };
}

polygon_function!(
    /// A polygon ((N, 3)) refined by a curve scheme of Section 4: ``scheme`` "chaikin", "bspline"
    /// (``degree`` 1 … 7, default 3), "bezier" (de Casteljau) or "four-point" (Dyn–Levin–Gregory
    /// (8), tension ``w``, default 1/16); ``steps`` 0 … 24 (default 1); ``closed``. Releases the GIL.
    subdivide_polygon,
    run: ruledlab::subdivide_polygon,
    out: arrays::points
);

polygon_function!(
    /// The largest turning angle (radians, 0 … π: the largest angle between an edge and the next)
    /// of a polygon ((N, 3)) and of each of its refinements by a curve scheme (the options of
    /// ``subdivide_polygon``): (steps + 1,), the first for the polygon itself. Where the limit is a
    /// regular C¹ curve the polygons turn less and less from step to step.
    turning_angles,
    run: ruledlab::turning_angles,
    out: angles
);

/// The turning angles as a 1-D array.
fn angles(py: Python<'_>, angles: Vec<f64>) -> PyResult<Bound<'_, PyAny>> {
    let n = angles.len();
    arrays::array(py, angles, &[n])
}
