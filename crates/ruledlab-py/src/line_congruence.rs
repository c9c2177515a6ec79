//! `LineCongruence` for Python: a discrete line congruence, a grid of lines (Section 5), its
//! subdivision (the butterfly scheme (16), the variational scheme of Section 5.2, and in the
//! space of lines), its rows and columns as ruled surfaces, its focal geometry (beyond the paper),
//! its best-fitting linear complex and its export as data — the JavaScript class of the same
//! name (`crates/ruledlab-wasm/src/line_congruence.rs`) without its WebGL buffers.

use crate::args::{self, given, only_for};
use crate::arrays::{self, interleave};
use crate::error::{fail, fail_input, fail_option};
use crate::export::export;
use crate::focal::{focal_dict, sheet_dict, strokes};
use crate::layout::Layout;
use crate::linear_complex::complex_dict;
use crate::ruled_surface::RuledSurface;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use ruledlab::tolerance::{MAX_CONGRUENCE_STEPS, MAX_PARTS, MAX_STRIDE};
use ruledlab::{CongruenceScheme, Segment};

/// A discrete line congruence: a rows × cols grid of lines, the line (i, j) through p_{i,j}
/// and q_{i,j} (Section 5), at least 2 × 2 and at most 4 194 304 lines.
///
/// ``LineCongruence(lines)`` takes a (rows, cols, 6) array (p then q per grid node) or a
/// (rows, cols, 2, 3) one; ``LineCongruence.from_grid(p, q)`` two (rows, cols, 3) arrays, as
/// ``View.from_grid(p, q)`` shows them.
#[pyclass(module = "ruledlab._core", frozen)]
pub struct LineCongruence {
    inner: ruledlab::LineCongruence,
}

impl LineCongruence {
    /// Wraps a core congruence.
    pub fn from_core(inner: ruledlab::LineCongruence) -> Self {
        LineCongruence { inner }
    }

    /// The core congruence.
    pub fn core(&self) -> &ruledlab::LineCongruence {
        &self.inner
    }

    /// A congruence from two (rows, cols, 3) arrays.
    pub fn from_pair(
        py: Python<'_>,
        func: &str,
        p: &Bound<'_, PyAny>,
        q: &Bound<'_, PyAny>,
    ) -> PyResult<ruledlab::LineCongruence> {
        let (np, nq) = (arrays::numbers(func, "p", p)?, arrays::numbers(func, "q", q)?);
        let (rows, cols) = arrays::grid_shape(func, "p", &np)?;
        arrays::grid_shape(func, "q", &nq)?;
        arrays::same_shape(func, ["p", "q"], &np, &nq)?;
        let (sp, sq) = (np.slice(), nq.slice());
        py.detach(|| ruledlab::LineCongruence::from_interleaved(rows, cols, interleave(sp, sq)))
            .map_err(|e| fail_input(func, e, &Layout::Pair { names: ["p", "q"], lead: vec![rows, cols] }))
    }

    fn segments_flat(segments: &[Segment]) -> Vec<f64> {
        segments.iter().flat_map(|s| [s.a, s.b]).flat_map(|p| p.to_array()).collect()
    }

    fn focal_all(&self, py: Python<'_>) -> Vec<ruledlab::Focal> {
        let c = &self.inner;
        py.detach(|| ruledlab::focal_grid(c.rows(), c.cols(), &c.p(), &c.q()))
    }
}

#[pymethods]
impl LineCongruence {
    // --- making one, and its lines

    #[new]
    fn new(py: Python<'_>, lines: &Bound<'_, PyAny>) -> PyResult<Self> {
        const F: &str = "LineCongruence";
        let s = arrays::numbers(F, "lines", lines)?;
        let (rows, cols) = arrays::grid_lines_shape(F, "lines", &s)?;
        let flat = s.slice();
        py.detach(|| ruledlab::LineCongruence::from_flat(rows, cols, flat))
            .map(Self::from_core)
            .map_err(|e| fail_input(F, e, &Layout::One { name: "lines", shape: s.shape().to_vec(), lead: 2 }))
    }

    /// The lines through ``p[i, j]`` and ``q[i, j]`` (two (rows, cols, 3) arrays).
    #[staticmethod]
    fn from_grid(py: Python<'_>, p: &Bound<'_, PyAny>, q: &Bound<'_, PyAny>) -> PyResult<Self> {
        Self::from_pair(py, "LineCongruence.from_grid", p, q).map(Self::from_core)
    }

    /// Number of rows.
    #[getter]
    fn rows(&self) -> usize {
        self.inner.rows()
    }

    /// Number of columns.
    #[getter]
    fn cols(&self) -> usize {
        self.inner.cols()
    }

    fn __repr__(&self) -> String {
        format!("<ruledlab.LineCongruence of {} × {} lines>", self.inner.rows(), self.inner.cols())
    }

    /// The lines, (rows, cols, 6): p then q per grid node (a copy).
    fn segments<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        arrays::array(py, self.inner.flat().to_vec(), &[self.inner.rows(), self.inner.cols(), 6])
    }

    /// Row ``i`` as a discrete ruled surface (Section 2's invariants apply).
    fn row(&self, i: &Bound<'_, PyAny>) -> PyResult<RuledSurface> {
        const F: &str = "LineCongruence.row";
        let i = args::integer(F, "i", i, 0, self.inner.rows() - 1)?;
        self.inner.row(i).map(RuledSurface::from_core).map_err(|e| fail(F, e))
    }

    /// Column ``j`` as a discrete ruled surface.
    fn column(&self, j: &Bound<'_, PyAny>) -> PyResult<RuledSurface> {
        const F: &str = "LineCongruence.column";
        let j = args::integer(F, "j", j, 0, self.inner.cols() - 1)?;
        self.inner.column(j).map(RuledSurface::from_core).map_err(|e| fail(F, e))
    }

    // --- subdivision (Section 5)

    /// The refined congruence: ``scheme`` "butterfly" ((16) on all edges, tension ``w`` ∈
    /// [−1/4, 1/4], default 1/16; ``diagonal_only``: just the (rows − 1) × (cols − 1) lines on
    /// the diagonals, Fig. 13; ``space`` "lines": on the lines as dual unit vectors, cut to
    /// ``length``) or "variational" (Section 5.2: ``K`` parts per line 3 … 1000, default 6;
    /// ``variant`` "coupled" (default), "two-stage" or "paper"); ``steps`` 0 … 12 (default 1).
    /// Each step maps rows × cols to (2 rows − 1) × (2 cols − 1) with the old lines at even
    /// indices, unchanged. Releases the GIL.
    #[pyo3(signature = (*, scheme, steps=None, w=None, diagonal_only=None, K=None, variant=None, space=None, length=None))]
    #[allow(clippy::too_many_arguments, non_snake_case)]
    fn subdivide(
        &self,
        py: Python<'_>,
        scheme: &Bound<'_, PyAny>,
        steps: Option<&Bound<'_, PyAny>>,
        w: Option<&Bound<'_, PyAny>>,
        diagonal_only: Option<&Bound<'_, PyAny>>,
        K: Option<&Bound<'_, PyAny>>,
        variant: Option<&Bound<'_, PyAny>>,
        space: Option<&Bound<'_, PyAny>>,
        length: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        const F: &str = "LineCongruence.subdivide";
        let names = ["butterfly", "variational"];
        let chosen = args::choice(F, "scheme", Some(scheme), &names)?.map(|k| names[k]);
        for (key, present, s) in [
            ("w", given(w), "butterfly"),
            ("diagonal_only", given(diagonal_only), "butterfly"),
            ("K", given(K), "variational"),
            ("variant", given(variant), "variational"),
            ("space", given(space), "butterfly"),
            ("length", given(length), "butterfly"),
        ] {
            only_for(F, key, present, s, chosen)?;
        }
        let steps = args::optional_integer(F, "steps", steps, 0, MAX_CONGRUENCE_STEPS, 1)?;
        let c = &self.inner;
        let scheme = if chosen == Some("butterfly") {
            let w = args::optional_number(F, "w", w)?.unwrap_or(1.0 / 16.0);
            let length = args::optional_number(F, "length", length)?;
            match args::choice(F, "space", space, &["points", "lines"])? {
                Some(1) => {
                    return py
                        .detach(|| ruledlab::butterfly_lines(c, w, steps, length))
                        .map(Self::from_core)
                        .map_err(|e| fail(F, e));
                }
                _ if length.is_some() => {
                    return Err(fail_option(F, "length", "length applies to space=\"lines\" only"));
                }
                _ => {}
            }
            if args::flag(F, "diagonal_only", diagonal_only, false)? {
                if steps != 1 {
                    return Err(fail_option(
                        F,
                        "diagonal_only",
                        "diagonal_only gives the lines of one step: leave steps at 1",
                    ));
                }
                return py.detach(|| ruledlab::butterfly_diagonal(c, w)).map(Self::from_core).map_err(|e| fail(F, e));
            }
            CongruenceScheme::Butterfly { w }
        } else {
            let k = args::optional_integer(F, "K", K, 3, MAX_PARTS, 6)?;
            match args::choice(F, "variant", variant, &["coupled", "two-stage", "paper"])? {
                None | Some(0) => CongruenceScheme::Coupled { k },
                Some(1) => CongruenceScheme::TwoStage { k },
                _ => CongruenceScheme::Paper { k },
            }
        };
        py.detach(|| ruledlab::subdivide_congruence(c, scheme, steps)).map(Self::from_core).map_err(|e| fail(F, e))
    }

    // --- focal geometry (beyond the paper)

    /// The focal geometry of every line, from the lines' Plücker coordinates differenced over
    /// the grid (second order, at the boundary too): a dict of (rows, cols, …) arrays
    /// (``points``, ``parameters``, ``kind``, ``torsal``, ``middle``, ``normality``; see the
    /// book's "Focal geometry and linear complexes"). Releases the GIL.
    fn focal<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let all = self.focal_all(py);
        focal_dict(py, self.inner.rows(), self.inner.cols(), &all)
    }

    /// Focal sheet 1 (of t1) or 2 (of t2) as a mesh: ``positions`` (V, 3), ``indices`` (T, 3),
    /// ``normals`` (V, 3), the box ``min``, ``max`` of its drawn vertices: the grid's quads whose
    /// four focal points are real and within three bounding-box diagonals of the lines' centre.
    fn focal_sheet<'py>(&self, py: Python<'py>, sheet: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyDict>> {
        let all = self.focal_all(py);
        sheet_dict(py, "LineCongruence.focal_sheet", &self.inner, &all, sheet)
    }

    /// Strokes on the director surface d₁ along the real torsal directions, p ± scale·(du·p_i +
    /// dv·p_j) (``scale`` default 0.35 of a grid step), (S, 6).
    #[pyo3(signature = (scale=None))]
    fn torsal_strokes<'py>(&self, py: Python<'py>, scale: Option<&Bound<'py, PyAny>>) -> PyResult<Bound<'py, PyAny>> {
        let all = self.focal_all(py);
        strokes(py, "LineCongruence.torsal_strokes", &self.inner, &all, scale)
    }

    /// The lines (i, j) with i or j not a multiple of ``stride`` (after k steps, 2^k: the
    /// inserted lines), (M, 6).
    fn inserted<'py>(&self, py: Python<'py>, stride: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let stride = args::integer("LineCongruence.inserted", "stride", stride, 1, MAX_STRIDE)?;
        let flat = Self::segments_flat(&self.inner.inserted(stride));
        let n = flat.len() / 6;
        arrays::array(py, flat, &[n, 6])
    }

    // --- the linear complex, and the lines as data

    /// The linear complex that fits the lines best (see ``ruledlab.linear_complex``).
    #[pyo3(signature = (*, tolerance=None))]
    fn linear_complex<'py>(
        &self,
        py: Python<'py>,
        tolerance: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let c = &self.inner;
        let segments: Vec<Segment> = (0..c.rows() * c.cols()).map(|k| c.line(k / c.cols(), k % c.cols())).collect();
        complex_dict(py, "LineCongruence.linear_complex", &segments, tolerance)
    }

    /// The lines as text: "json" (``{"rows", "cols", "segments": [[…], …]}``), "csv" (row-major;
    /// the grid's shape is not kept) or "obj" (vertices and line elements; ``name``).
    #[pyo3(signature = (format, *, name=None))]
    fn export(&self, format: &Bound<'_, PyAny>, name: Option<&Bound<'_, PyAny>>) -> PyResult<String> {
        let c = &self.inner;
        export("LineCongruence.export", format, name, c.flat(), Some((c.rows(), c.cols())), None)
    }
}
