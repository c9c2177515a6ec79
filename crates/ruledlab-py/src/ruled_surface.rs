//! `RuledSurface` for Python: a discrete ruled surface (Section 2), its invariants, its
//! isometries and development (Section 3), its subdivision (Section 4, and in the space of
//! lines), its best-fitting linear complex and its export as data — the computations of the
//! JavaScript class of the same name (`crates/ruledlab-wasm/src/ruled_surface.rs`) without its
//! WebGL buffers, on NumPy arrays.

use crate::args;
use crate::arrays::{self, interleave};
use crate::error::{fail, fail_input};
use crate::export::export;
use crate::invariants::invariants_dict;
use crate::layout::Layout;
use crate::linear_complex::complex_dict;
use crate::scheme_options::{read, SchemeArgs, Space};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use ruledlab::tolerance::{MAX_PARTS, MAX_RULINGS, MAX_STRIDE};
use ruledlab::{Development, Frame, HingeChain, Segment, Triangulation};
use std::sync::OnceLock;

/// A discrete ruled surface: N ≥ 2 rulings, each the segment from a_i to b_i (Section 2 of
/// Odehnal & Pottmann). Immutable: every operation returns new arrays or a new surface.
///
/// ``RuledSurface(segments)`` takes an (N, 6) array (a_i then b_i in each row) or an (N, 2, 3)
/// one; ``RuledSurface.from_segments(a, b)`` two (N, 3) arrays. N is at most 4 194 304; every
/// coordinate must be finite and at most 1e150 in magnitude, and no ruling may have zero length
/// (``RuledlabError`` with code ``not-finite``, ``out-of-range``, ``degenerate`` otherwise).
#[pyclass(module = "ruledlab._core", frozen)]
pub struct RuledSurface {
    inner: ruledlab::RuledSurface,
    /// Built on first use by the isometries, so repeated `bend(t)` calls stay cheap.
    chain: OnceLock<HingeChain>,
}

impl RuledSurface {
    /// Wraps a core surface.
    pub fn from_core(inner: ruledlab::RuledSurface) -> Self {
        RuledSurface { inner, chain: OnceLock::new() }
    }

    /// The core surface.
    pub fn core(&self) -> &ruledlab::RuledSurface {
        &self.inner
    }

    fn chain(&self, py: Python<'_>) -> &HingeChain {
        if let Some(chain) = self.chain.get() {
            return chain;
        }
        let made = py.detach(|| HingeChain::new(&self.inner));
        self.chain.get_or_init(|| made)
    }

    /// A surface from two (N, 3) arrays (the arguments `names` of `func`).
    pub fn from_pair(
        py: Python<'_>,
        func: &str,
        names: [&str; 2],
        a: &Bound<'_, PyAny>,
        b: &Bound<'_, PyAny>,
    ) -> PyResult<ruledlab::RuledSurface> {
        let (na, nb) = (arrays::numbers(func, names[0], a)?, arrays::numbers(func, names[1], b)?);
        let n = arrays::rows(func, names[0], &na, 3, "point")?;
        arrays::rows(func, names[1], &nb, 3, "point")?;
        arrays::same_shape(func, names, &na, &nb)?;
        let (sa, sb) = (na.slice(), nb.slice());
        py.detach(|| ruledlab::RuledSurface::from_points(interleave(sa, sb)))
            .map_err(|e| fail_input(func, e, &Layout::Pair { names, lead: vec![n] }))
    }

    /// A surface from one (N, 6) or (N, 2, 3) array.
    pub fn from_array(
        py: Python<'_>,
        func: &str,
        name: &str,
        segments: &Bound<'_, PyAny>,
    ) -> PyResult<ruledlab::RuledSurface> {
        let s = arrays::numbers(func, name, segments)?;
        arrays::segment_rows(func, name, &s, "ruling")?;
        let flat = s.slice();
        py.detach(|| ruledlab::RuledSurface::from_flat(flat))
            .map_err(|e| fail_input(func, e, &Layout::One { name, shape: s.shape().to_vec(), lead: 1 }))
    }

    fn segments_of(&self, rulings: &[Segment]) -> Vec<f64> {
        let _ = self;
        rulings.iter().flat_map(|s| [s.a, s.b]).flat_map(|p| p.to_array()).collect()
    }
}

#[pymethods]
impl RuledSurface {
    // --- making one, and its rulings

    #[new]
    fn new(py: Python<'_>, segments: &Bound<'_, PyAny>) -> PyResult<Self> {
        Self::from_array(py, "RuledSurface", "segments", segments).map(Self::from_core)
    }

    /// The rulings from ``a[i]`` to ``b[i]`` (two (N, 3) arrays), as ``View.from_segments(a, b)``
    /// shows them.
    #[staticmethod]
    fn from_segments(py: Python<'_>, a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>) -> PyResult<Self> {
        Self::from_pair(py, "RuledSurface.from_segments", ["a", "b"], a, b).map(Self::from_core)
    }

    /// Number of rulings N.
    fn __len__(&self) -> usize {
        self.inner.len()
    }

    fn __repr__(&self) -> String {
        format!("<ruledlab.RuledSurface of {} rulings>", self.inner.len())
    }

    /// The segments, (N, 6): a_i then b_i in each row (a copy).
    fn segments<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        arrays::array(py, self.inner.flat().to_vec(), &[self.inner.len(), 6])
    }

    /// The unit directions e_i = (b_i − a_i)/‖b_i − a_i‖, (N, 3).
    fn directions<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        arrays::points(py, self.inner.directions())
    }

    /// Mean length ‖b_i − a_i‖ of the segments.
    fn mean_length(&self) -> f64 {
        self.inner.mean_length()
    }

    /// The same lines with other segments: a_i moved by ``amounts[i, 0]`` and b_i by
    /// ``amounts[i, 1]`` along e_i ((N, 2); the lines themselves do not change).
    fn slide(&self, amounts: &Bound<'_, PyAny>) -> PyResult<Self> {
        const F: &str = "RuledSurface.slide";
        let m = arrays::numbers(F, "amounts", amounts)?;
        let n = arrays::rows(F, "amounts", &m, 2, "ruling")?;
        if n != self.inner.len() {
            return Err(crate::error::fail_option(
                F,
                "amounts",
                format!("amounts must have one row per ruling, ({}, 2), got ({n}, 2)", self.inner.len()),
            ));
        }
        self.inner.slide(m.slice()).map(Self::from_core).map_err(|e| fail(F, e))
    }

    // --- the invariants of Section 2

    /// All discrete invariants of Section 2 (equations (1)–(7)) as a dict of float64 arrays:
    /// ``angle`` φ (P,), ``distance`` h (P,), ``distribution`` δ = h/φ (P,) (1), ``footpoints``
    /// (P, 6) (f_{i,i+1} then f_{i+1,i}), ``central_normal`` (P, 3), ``striction`` (M, 3) (7),
    /// ``distribution_mean`` (M,) (7), ``perpendicular_midpoints`` (P, 3), ``parallel`` (P,)
    /// bool; P = N − 1 pairs and M = N − 2 interior rulings, or P = M = N with ``closed=True``
    /// (R_{N−1} followed by R_0). The computation releases the GIL.
    #[pyo3(signature = (*, closed=None))]
    fn invariants<'py>(&self, py: Python<'py>, closed: Option<&Bound<'py, PyAny>>) -> PyResult<Bound<'py, PyDict>> {
        let closed = args::flag("RuledSurface.invariants", "closed", closed, false)?;
        let inv = py.detach(|| {
            let mut inv = ruledlab::Invariants::default();
            self.inner.invariants_into(&mut inv, closed);
            inv
        });
        invariants_dict(py, inv)
    }

    /// The largest relative change of an edge length of the boundary polygons (a_i), (b_i)
    /// from this surface to ``other`` (0 to rounding for an isometric deformation).
    fn max_edge_change(&self, other: &RuledSurface) -> PyResult<f64> {
        self.inner.max_edge_change(&other.inner).map_err(|e| fail("RuledSurface.max_edge_change", e))
    }

    /// Largest angle (radians) between corresponding rulings of this surface and ``other``,
    /// as unoriented lines.
    fn max_angle_to(&self, other: &RuledSurface) -> PyResult<f64> {
        self.inner.max_angle_to(&other.inner).map_err(|e| fail("RuledSurface.max_angle_to", e))
    }

    // --- isometries and the development (Section 3)

    /// The hinge angles τ_i of the discrete Minding isometries (Section 3): the signed angle
    /// about e_i from n_{i−1,i} to n_{i,i+1}, (N − 2,) for R_1 … R_{N−2}.
    fn hinge_angles<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let tau = self.chain(py).hinge_angles().to_vec();
        let n = tau.len();
        arrays::array(py, tau, &[n])
    }

    /// The surface with each interior hinge R_k turned by ``angles[k − 1]`` (radians, (N − 2,));
    /// R_0 and R_1 stay put. An isometry: every polygon p_i ∈ R_i keeps its edge lengths.
    fn hinge(&self, py: Python<'_>, angles: &Bound<'_, PyAny>) -> PyResult<Self> {
        const F: &str = "RuledSurface.hinge";
        let a = arrays::numbers(F, "angles", angles)?;
        arrays::vector(F, "angles", &a)?;
        let chain = self.chain(py);
        let angles = a.slice();
        py.detach(|| chain.deform(angles)).map(Self::from_core).map_err(|e| fail(F, e))
    }

    /// The isometric conoidal model (Example 2): all common normals turned parallel to
    /// n_{0,1}, so every ruling is parallel to the plane of R_0 and R_1.
    fn conoidal(&self, py: Python<'_>) -> Self {
        let chain = self.chain(py);
        Self::from_core(py.detach(|| chain.conoidal()))
    }

    /// The bending from this surface (t = 0) to its conoidal model (t = 1), the hinge angles
    /// scaled by t (0 ≤ t ≤ 1).
    fn bend(&self, py: Python<'_>, t: &Bound<'_, PyAny>) -> PyResult<Self> {
        const F: &str = "RuledSurface.bend";
        let t = args::number(F, "t", t)?;
        let chain = self.chain(py);
        py.detach(|| chain.bend(t)).map(Self::from_core).map_err(|e| fail(F, e))
    }

    /// The approximate development (Fig. 6): the conoidal model projected onto the plane of
    /// R_0 and R_1, (N, 4): x, y of a′_i then of b′_i.
    fn development<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let flat = py.detach(|| Development::of(&self.inner).flat().to_vec());
        arrays::array(py, flat, &[self.inner.len(), 4])
    }

    /// The non-developability measure: the extremal height difference of the conoidal model's
    /// rulings (0 for cones and cylinders).
    fn non_developability(&self, py: Python<'_>) -> f64 {
        py.detach(|| Development::of(&self.inner).non_developability())
    }

    /// The signed radius of curvature ρ_i of the envelope of the developed rulings at each
    /// interior ruling, (f_{i,i+1} − f_{i,i−1})·e_i over the mean angle there: (N − 2,) (NaN
    /// beside a parallel pair).
    fn envelope_radii<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let radii = py.detach(|| ruledlab::envelope_radii(&self.inner));
        let n = radii.len();
        arrays::array(py, radii, &[n])
    }

    /// The reference frame of the conoidal model and the development (origin a_0, x = e_0,
    /// z = n_{0,1}): the 4 × 4 matrix M taking world to frame coordinates, M @ (x, y, z, 1).
    fn reference_frame<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        // glam's columns are the rows of the transpose: row-major M
        let m = Frame::of(&self.inner).world_to_frame().transpose().to_cols_array();
        arrays::array(py, m.to_vec(), &[4, 4])
    }

    /// The development (Fig. 6) in space: its rulings as segments of the reference plane, (N, 6)
    /// in world coordinates (``reference_frame()`` maps them to z = 0).
    fn development_in_space<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let flat: Vec<f64> = py.detach(|| {
            let dev = Development::of(&self.inner);
            let frame = Frame::of(&self.inner);
            dev.points.iter().flat_map(|&p| frame.plane_point(p).to_array()).collect()
        });
        arrays::array(py, flat, &[self.inner.len(), 6])
    }

    /// The image of the striction polygon in the development: (N − 2, 2), x, y in the reference
    /// plane, each the midpoint of the edge on its ruling of the polygon the developed rulings
    /// envelop.
    fn development_striction<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        arrays::points2(py, py.detach(|| Development::of(&self.inner).striction_image()))
    }

    /// ``development_striction()`` in space, (N − 2, 3) in world coordinates.
    fn development_striction_in_space<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let frame = Frame::of(&self.inner);
        let image = py.detach(|| Development::of(&self.inner).striction_image());
        arrays::points(py, image.into_iter().map(|p| frame.plane_point(p)).collect())
    }

    /// The polygon the developed rulings envelop: the N − 1 points where consecutive developed
    /// rulings meet, (N − 1, 2) in the reference plane.
    fn development_envelope<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        arrays::points2(py, py.detach(|| Development::of(&self.inner).envelope_polygon()))
    }

    /// ``development_envelope()`` in space, (N − 1, 3) in world coordinates.
    fn development_envelope_in_space<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let frame = Frame::of(&self.inner);
        let corners = py.detach(|| Development::of(&self.inner).envelope_polygon());
        arrays::points(py, corners.into_iter().map(|p| frame.plane_point(p)).collect())
    }

    // --- subdivision (Section 4)

    // its first keywords (scheme, steps, w) are LineCongruence.subdivide's too: PyO3 binds each
    // method's own signature; what reads a scheme's keywords is one (scheme_options)
    /// The surface refined by a scheme of Section 4: ``scheme`` "chaikin", "bspline" (of
    /// ``degree`` 1 … 7, default 3), "bezier", "four-point" (Dyn–Levin–Gregory (8), tension
    /// ``w`` ∈ [−1/4, 1/4], default 1/16) or "variational" ((13)/(14): ``n`` parts per segment,
    /// default 12, ``variant`` "coupled", "literal" or "averaged"); ``steps`` 0 … 24 (default 1);
    /// ``closed``; ``space`` "points" (on a_i, b_i) or "lines" (on the lines as dual unit
    /// vectors, the output cut to ``length``). Interpolatory schemes return 2N − 1 rulings per
    /// step (2N closed) with the old ones at even indices, unchanged. Releases the GIL.
    #[pyo3(signature = (*, scheme, steps=None, w=None, n=None, variant=None, degree=None, closed=None, space=None, length=None))]
    #[allow(clippy::too_many_arguments)]
    fn subdivide(
        &self,
        py: Python<'_>,
        scheme: &Bound<'_, PyAny>,
        steps: Option<&Bound<'_, PyAny>>,
        w: Option<&Bound<'_, PyAny>>,
        n: Option<&Bound<'_, PyAny>>,
        variant: Option<&Bound<'_, PyAny>>,
        degree: Option<&Bound<'_, PyAny>>,
        closed: Option<&Bound<'_, PyAny>>,
        space: Option<&Bound<'_, PyAny>>,
        length: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        const F: &str = "RuledSurface.subdivide";
        let a = SchemeArgs { scheme: Some(scheme), steps, w, n, variant, degree, closed, space, length };
        let (scheme, closed, steps, space) = read(F, &a, None)?;
        let core = &self.inner;
        py.detach(|| match space {
            Space::Points => ruledlab::subdivide_strip(core, scheme, closed, steps),
            Space::Lines(length) => ruledlab::subdivide_lines(core, scheme, closed, steps, length),
        })
        .map(Self::from_core)
        .map_err(|e| fail(F, e))
    }

    /// The rulings re-cut to segments of one ``length`` (default: the mean length), centred
    /// on the striction points: for data given as lines, before subdividing.
    #[pyo3(signature = (length=None))]
    fn recut(&self, length: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        const F: &str = "RuledSurface.recut";
        let length = args::optional_number(F, "length", length)?;
        ruledlab::recut(&self.inner, length).map(Self::from_core).map_err(|e| fail(F, e))
    }

    /// z_{i,k} = ((n − k)/n) a_i + (k/n) b_i (9): the point k/n of the way along ruling i, (3,).
    fn division_point<'py>(
        &self,
        py: Python<'py>,
        i: &Bound<'py, PyAny>,
        k: &Bound<'py, PyAny>,
        n: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        const F: &str = "RuledSurface.division_point";
        let i = args::integer(F, "i", i, 0, self.inner.len() - 1)?;
        let n = args::integer(F, "n", n, 1, MAX_STRIDE)?;
        let k = args::integer(F, "k", k, 0, n)?;
        arrays::array(py, ruledlab::division_point(&self.inner, i, k, n).to_array().to_vec(), &[3])
    }

    /// The edges of the first (``which`` = 1, neighbours (11)) or second (2, (12))
    /// triangulation of Fig. 9 with every segment divided into ``n`` parts, (E, 6).
    fn triangulation<'py>(
        &self,
        py: Python<'py>,
        n: &Bound<'py, PyAny>,
        which: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        const F: &str = "RuledSurface.triangulation";
        let n = args::integer(F, "n", n, 1, MAX_PARTS)?;
        let which = match args::integer(F, "which", which, 1, 2)? {
            1 => Triangulation::First,
            _ => Triangulation::Second,
        };
        let edges = (self.inner.len() - 1).saturating_mul(2 * n + 1);
        if edges > MAX_RULINGS {
            return Err(fail(F, ruledlab::Error::TooMany { what: "edges", got: edges, max: MAX_RULINGS }));
        }
        let flat: Vec<f64> = py.detach(|| {
            ruledlab::triangulation_edges(&self.inner, n, which)
                .into_iter()
                .flatten()
                .flat_map(|p| p.to_array())
                .collect()
        });
        let count = flat.len() / 6;
        arrays::array(py, flat, &[count, 6])
    }

    /// The rulings whose index is not a multiple of ``stride`` (after k interpolatory steps,
    /// stride 2^k: the inserted ones), (M, 6).
    fn inserted<'py>(&self, py: Python<'py>, stride: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let stride = args::integer("RuledSurface.inserted", "stride", stride, 1, MAX_STRIDE)?;
        let flat = self.segments_of(&self.inner.inserted(stride));
        let count = flat.len() / 6;
        arrays::array(py, flat, &[count, 6])
    }

    // --- the linear complex, and the surface as data

    /// The linear complex that fits the rulings best (a helical surface: its screw axis; a
    /// regulus: nullity 3); see ``ruledlab.linear_complex``.
    #[pyo3(signature = (*, tolerance=None))]
    fn linear_complex<'py>(
        &self,
        py: Python<'py>,
        tolerance: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        complex_dict(py, "RuledSurface.linear_complex", &self.inner.segments().collect::<Vec<_>>(), tolerance)
    }

    /// The surface as text: "csv" (header ``ax,ay,az,bx,by,bz``), "json" (``{"segments":
    /// [[…], …]}``), "obj" (vertices, ruling lines and the quads between them; ``name``), or its
    /// invariants (Section 2) as "invariants-csv" or "invariants-json"; full precision.
    #[pyo3(signature = (format, *, name=None))]
    fn export(&self, format: &Bound<'_, PyAny>, name: Option<&Bound<'_, PyAny>>) -> PyResult<String> {
        export("RuledSurface.export", format, name, self.inner.flat(), None, Some(&self.inner))
    }
}
