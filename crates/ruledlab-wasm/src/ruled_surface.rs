//! `RuledSurface` for JavaScript: a discrete ruled surface (Section 2), its invariants, its
//! isometries and development (Section 3), its subdivision (Section 4), the buffers the page
//! draws of it, its best-fitting linear complex and its export as data.

use super::export::export;
use super::invariants::{Invariants, InvariantsOptions};
use super::invariants_buffer::InvariantsBuffer;
use super::linear_complex::complex_js;
use js_sys::{Float32Array, Float64Array};
use ruledlab::tolerance::{MAX_PARTS, MAX_RULINGS, MAX_STRIDE};
use ruledlab::Frame;
use ruledlab::Segment;
use ruledlab::Triangulation;
use ruledlab::{Development, HingeChain};
use ruledlab_js::args::{self, fail, integer, numbers, to_js};
use ruledlab_js::buffers::{self, segments_f32, Lines};
use ruledlab_js::line_buffers;
use ruledlab_js::live::Live;
use ruledlab_js::subdivide_options::{read, Space};
use ruledlab_js::timing::Measure;
use std::borrow::Cow;
use std::cell::OnceCell;
use wasm_bindgen::prelude::*;

/// A discrete ruled surface: N ≥ 2 rulings, each a segment a_i → b_i.
#[wasm_bindgen]
pub struct RuledSurface {
    inner: ruledlab::RuledSurface,
    /// Built on first use by the isometries, so repeated `bend(t)` calls stay cheap.
    chain: OnceCell<HingeChain>,
    _live: Live,
}

impl RuledSurface {
    /// Wraps a core surface.
    pub fn from_core(inner: ruledlab::RuledSurface) -> Self {
        RuledSurface { inner, chain: OnceCell::new(), _live: Live::new() }
    }

    fn chain(&self) -> &HingeChain {
        self.chain.get_or_init(|| HingeChain::new(&self.inner))
    }

    /// The core surface.
    pub fn core(&self) -> &ruledlab::RuledSurface {
        &self.inner
    }
}

#[wasm_bindgen]
impl RuledSurface {
    // --- making one, and its rulings

    /// A surface from a Float64Array of 6 numbers per ruling: a.x a.y a.z b.x b.y b.z.
    /// Throws if the array is not a Float64Array, its length is not a multiple of 6, it
    /// holds fewer than 2 rulings or more than 4 194 304, a number is NaN, infinite or
    /// above 1e150 in magnitude, or a ruling has zero length.
    #[wasm_bindgen(js_name = fromSegments)]
    pub fn from_segments(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] coords: JsValue,
    ) -> Result<RuledSurface, JsValue> {
        let coords = numbers("RuledSurface.fromSegments", "coords", &coords)?;
        ruledlab::RuledSurface::from_flat(&coords)
            .map(Self::from_core)
            .map_err(|e| fail("RuledSurface.fromSegments", e))
    }

    /// Number of rulings N.
    #[wasm_bindgen(getter)]
    pub fn length(&self) -> usize {
        self.inner.len()
    }

    /// The segments, 6 numbers per ruling (a copy).
    pub fn segments(&self) -> Float64Array {
        Float64Array::from(self.inner.flat())
    }

    /// The unit directions e_i = (b_i − a_i)/|b_i − a_i|, 3 numbers per ruling.
    pub fn directions(&self) -> Float64Array {
        Float64Array::from(ruledlab::Invariants::flat(&self.inner.directions()))
    }

    /// Mean length |b_i − a_i| of the segments.
    #[wasm_bindgen(js_name = meanLength)]
    pub fn mean_length(&self) -> f64 {
        self.inner.mean_length()
    }

    /// The same lines with other segments: a_i moved by `amounts[2i]` and b_i by
    /// `amounts[2i + 1]` along e_i (the lines themselves do not change).
    pub fn slide(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] amounts: JsValue,
    ) -> Result<RuledSurface, JsValue> {
        const F: &str = "RuledSurface.slide";
        let amounts = numbers(F, "amounts", &amounts)?;
        self.inner.slide(&amounts).map(Self::from_core).map_err(|e| fail(F, e))
    }

    // --- the invariants of Section 2

    /// All discrete invariants of Section 2 as typed arrays. With `{ closed: true }` the
    /// surface is read as closed (R_{N−1} followed by R_0): N pairs, and N striction points,
    /// one per ruling, so the striction polygon closes.
    #[wasm_bindgen(unchecked_return_type = "Invariants")]
    pub fn invariants(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "InvariantsOptions")] options: Option<js_sys::Object>,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "RuledSurface.invariants";
        let _measure = Measure::start(F);
        let o: InvariantsOptions = args::options(F, options.map(JsValue::from).unwrap_or_default())?;
        let out = Invariants::fresh(&self.inner, o.closed);
        out.fill(&self.inner, o.closed);
        to_js(F, &out)
    }

    /// As `invariants()`, but written into the arrays of `out` (an object returned by an
    /// earlier `invariants()` call on a surface with as many rulings, and the same `closed`):
    /// no allocation, for animation loops and large models. Throws if an array is missing or
    /// has the wrong length.
    #[wasm_bindgen(js_name = invariantsInto)]
    pub fn invariants_into(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Invariants")] out: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "InvariantsOptions")] options: Option<js_sys::Object>,
    ) -> Result<(), JsValue> {
        let options = options.map(JsValue::from).unwrap_or_default();
        const F: &str = "RuledSurface.invariantsInto";
        if !out.is_object() {
            return Err(fail(F, format!("out must be an Invariants object, got {}", args::describe(&out))));
        }
        let o: InvariantsOptions = args::options(F, options)?;
        let out = Invariants::of_object(F, &out, &self.inner, o.closed)?;
        out.fill(&self.inner, o.closed);
        Ok(())
    }

    /// As `invariants()`, computed into `buffer`, whose arrays stay in wasm memory: the
    /// zero-copy path. Nothing is allocated once the buffer has held a surface this large, and
    /// nothing is copied to JS; read the results through the buffer's getters, which are views
    /// of wasm memory (see `InvariantsBuffer` for how long a view stays valid).
    #[wasm_bindgen(js_name = invariantsInPlace)]
    pub fn invariants_in_place(
        &self,
        buffer: &mut InvariantsBuffer,
        #[wasm_bindgen(unchecked_optional_param_type = "InvariantsOptions")] options: Option<js_sys::Object>,
    ) -> Result<(), JsValue> {
        let o: InvariantsOptions =
            args::options("RuledSurface.invariantsInPlace", options.map(JsValue::from).unwrap_or_default())?;
        self.inner.invariants_into(buffer.core_mut(), o.closed);
        Ok(())
    }

    /// The largest relative change of an edge length of the boundary polygons (a_i), (b_i)
    /// from this surface to `other` (0 to rounding for an isometric deformation).
    #[wasm_bindgen(js_name = maxEdgeChange)]
    pub fn max_edge_change(&self, other: &RuledSurface) -> Result<f64, JsValue> {
        self.inner.max_edge_change(&other.inner).map_err(|e| fail("RuledSurface.maxEdgeChange", e))
    }

    /// Largest angle (radians) between corresponding rulings of this surface and `other`, as
    /// unoriented lines.
    #[wasm_bindgen(js_name = maxAngleTo)]
    pub fn max_angle_to(&self, other: &RuledSurface) -> Result<f64, JsValue> {
        self.inner.max_angle_to(&other.inner).map_err(|e| fail("RuledSurface.maxAngleTo", e))
    }

    // --- isometries and the development (Section 3)

    /// The hinge angles τ_i of the discrete Minding isometries (Section 3): the signed angle
    /// about e_i from n_{i−1,i} to n_{i,i+1}, N − 2 values for R_1 … R_{N−2}.
    #[wasm_bindgen(js_name = hingeAngles)]
    pub fn hinge_angles(&self) -> Float64Array {
        Float64Array::from(self.chain().hinge_angles())
    }

    /// The surface with each interior hinge R_k turned by `angles[k − 1]` (radians, N − 2
    /// values); R_0 and R_1 stay put. An isometry: every polygon p_i ∈ R_i keeps its length.
    pub fn hinge(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] angles: JsValue,
    ) -> Result<RuledSurface, JsValue> {
        const F: &str = "RuledSurface.hinge";
        let angles = numbers(F, "angles", &angles)?;
        self.chain().deform(&angles).map(Self::from_core).map_err(|e| fail(F, e))
    }

    /// The isometric conoidal model (Example 2): all common normals turned parallel to
    /// n_{0,1}, so every ruling is parallel to the plane of R_0 and R_1.
    pub fn conoidal(&self) -> RuledSurface {
        Self::from_core(self.chain().conoidal())
    }

    /// The bending from this surface (t = 0) to its conoidal model (t = 1), hinge angles
    /// scaled by t. Throws unless 0 ≤ t ≤ 1.
    pub fn bend(&self, #[wasm_bindgen(unchecked_param_type = "number")] t: JsValue) -> Result<RuledSurface, JsValue> {
        const F: &str = "RuledSurface.bend";
        let t = args::number(F, "t", &t)?;
        self.chain().bend(t).map(Self::from_core).map_err(|e| fail(F, e))
    }

    /// The approximate development (Fig. 6): the conoidal model projected onto the plane of
    /// its rulings; 4 numbers per ruling, x, y of a'_i then of b'_i.
    pub fn development(&self) -> Float64Array {
        let _measure = Measure::start("RuledSurface.development");
        Float64Array::from(Development::of(&self.inner).flat())
    }

    /// The non-developability measure: the extremal height difference of the conoidal
    /// model's rulings (0 for cones and cylinders).
    #[wasm_bindgen(js_name = nonDevelopability)]
    pub fn non_developability(&self) -> f64 {
        Development::of(&self.inner).non_developability()
    }

    /// The signed radius of curvature ρ_i of the envelope of the developed rulings at each
    /// interior ruling, (f_{i,i+1} − f_{i,i−1})·e_i over the mean angle there: N − 2 values
    /// (NaN beside a parallel pair). For a ruled helical surface it tends to the radius of the
    /// cylinder its conoidal rulings touch, r + p tan β; 0 when Fig. 5's caption holds.
    #[wasm_bindgen(js_name = envelopeRadii)]
    pub fn envelope_radii(&self) -> Float64Array {
        let _measure = Measure::start("RuledSurface.envelopeRadii");
        Float64Array::from(ruledlab::envelope_radii(&self.inner).as_slice())
    }

    /// The reference frame of the conoidal model and development (origin a_0, x = e_0,
    /// z = n_{0,1}): the 4 × 4 matrix taking world to frame coordinates, column-major (as
    /// `gl.uniformMatrix4fv` takes it).
    #[wasm_bindgen(js_name = referenceFrame)]
    pub fn reference_frame(&self) -> Float64Array {
        Float64Array::from(&Frame::of(self.core()).world_to_frame().to_cols_array()[..])
    }

    /// The development (Fig. 6) in space: its rulings as segments of the reference plane,
    /// 6 numbers per ruling in world coordinates (`referenceFrame()` maps them to z = 0).
    #[wasm_bindgen(js_name = developmentInSpace)]
    pub fn development_in_space(&self) -> Float64Array {
        let dev = Development::of(self.core());
        let frame = Frame::of(self.core());
        let out: Vec<f64> = dev.points.iter().flat_map(|&p| frame.plane_point(p).to_array()).collect();
        Float64Array::from(&out[..])
    }

    /// The image of the striction polygon m_i in the development: N − 2 points (one per
    /// interior ruling), x, y in the reference plane. It is inscribed in the polygon the
    /// developed rulings envelop (`developmentEnvelope`): each point the midpoint of the edge on
    /// its ruling.
    #[wasm_bindgen(js_name = developmentStriction)]
    pub fn development_striction(&self) -> Float64Array {
        let image = Development::of(self.core()).striction_image();
        Float64Array::from(bytemuck::cast_slice::<_, f64>(&image))
    }

    /// [`RuledSurface::development_striction`] in space (3 numbers per point, world coordinates).
    #[wasm_bindgen(js_name = developmentStrictionInSpace)]
    pub fn development_striction_in_space(&self) -> Float64Array {
        let frame = Frame::of(self.core());
        let out: Vec<f64> = Development::of(self.core())
            .striction_image()
            .into_iter()
            .flat_map(|p| frame.plane_point(p).to_array())
            .collect();
        Float64Array::from(&out[..])
    }

    /// The polygon the developed rulings envelop: the N − 1 points where consecutive developed
    /// rulings meet, each the image of both footpoints of a pair (and of Fig. 3's
    /// perpendicular midpoint), x, y in the reference plane.
    #[wasm_bindgen(js_name = developmentEnvelope)]
    pub fn development_envelope(&self) -> Float64Array {
        let corners = Development::of(self.core()).envelope_polygon();
        Float64Array::from(bytemuck::cast_slice::<_, f64>(&corners))
    }

    /// [`RuledSurface::development_envelope`] in space (3 numbers per point, world coordinates).
    #[wasm_bindgen(js_name = developmentEnvelopeInSpace)]
    pub fn development_envelope_in_space(&self) -> Float64Array {
        let frame = Frame::of(self.core());
        let out: Vec<f64> = Development::of(self.core())
            .envelope_polygon()
            .into_iter()
            .flat_map(|p| frame.plane_point(p).to_array())
            .collect();
        Float64Array::from(&out[..])
    }

    // --- subdivision (Section 4)

    /// The surface refined by a subdivision scheme (see `SubdivideOptions`). Interpolatory
    /// schemes ("four-point", "variational") return 2N − 1 rulings per step (2N closed) with
    /// the old ones at even indices, unchanged.
    pub fn subdivide(
        &self,
        #[wasm_bindgen(unchecked_param_type = "SubdivideOptions")] options: JsValue,
    ) -> Result<RuledSurface, JsValue> {
        const F: &str = "RuledSurface.subdivide";
        let _measure = Measure::start(F);
        let (scheme, closed, steps, space) = read(F, options, None)?;
        match space {
            Space::Points => ruledlab::subdivide_strip(self.core(), scheme, closed, steps),
            Space::Lines(length) => ruledlab::subdivide_lines(self.core(), scheme, closed, steps, length),
        }
        .map(RuledSurface::from_core)
        .map_err(|e| fail(F, e))
    }

    /// The rulings re-cut to segments of one length (default: the mean length), centred on
    /// the striction points: for data given as lines, before subdividing.
    pub fn recut(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "number")] length: JsValue,
    ) -> Result<RuledSurface, JsValue> {
        const F: &str = "RuledSurface.recut";
        let length = if length.is_undefined() { None } else { Some(args::number(F, "length", &length)?) };
        ruledlab::recut(self.core(), length).map(RuledSurface::from_core).map_err(|e| fail(F, e))
    }

    /// z_{i,k} = ((n − k)/n) a_i + (k/n) b_i (9): the point k/n of the way along ruling i.
    #[wasm_bindgen(js_name = divisionPoint)]
    pub fn division_point(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] i: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] k: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] n: JsValue,
    ) -> Result<Float64Array, JsValue> {
        const F: &str = "RuledSurface.divisionPoint";
        let i = integer(F, "i", &i, 0, self.length() - 1)?;
        let n = integer(F, "n", &n, 1, MAX_STRIDE)?;
        let k = integer(F, "k", &k, 0, n)?;
        Ok(Float64Array::from(&ruledlab::division_point(self.core(), i, k, n).to_array()[..]))
    }

    /// The edges of the first (`which` = 1, neighbours (11)) or second (2, (12)) triangulation
    /// of Fig. 9 with every segment divided into `n` parts, as f32 segments.
    #[wasm_bindgen(js_name = triangulationF32)]
    pub fn triangulation_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] n: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] which: JsValue,
    ) -> Result<Float32Array, JsValue> {
        const F: &str = "RuledSurface.triangulationF32";
        let n = integer(F, "n", &n, 1, MAX_PARTS)?;
        let which = match integer(F, "which", &which, 1, 2)? {
            1 => Triangulation::First,
            _ => Triangulation::Second,
        };
        if (self.length() - 1).saturating_mul(2 * n + 1) > MAX_RULINGS {
            return Err(fail(
                F,
                ruledlab::Error::TooMany { what: "edges", got: (self.length() - 1) * (2 * n + 1), max: MAX_RULINGS },
            ));
        }
        let edges: Vec<Segment> =
            ruledlab::triangulation_edges(self.core(), n, which).into_iter().map(|[a, b]| Segment::new(a, b)).collect();
        Ok(segments_f32(&edges))
    }

    // --- buffers for WebGL (and `segmentsF32()`, `insertedF32(stride)`: `line_buffers!` below)

    /// Every k-th ruling (indices 0, k, 2k, …, and the last), as f32 segments: a level of
    /// detail for drawing surfaces with more rulings than a view can show.
    #[wasm_bindgen(js_name = everyF32)]
    pub fn every_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] k: JsValue,
    ) -> Result<Float32Array, JsValue> {
        buffers::every_f32("RuledSurface", "k", &k, self.length(), |i| self.core().segment(i))
    }

    /// The endpoints a_i (`which` = 1) or b_i (2) of the rulings whose index is not a multiple
    /// of `stride` (stride 1: of every ruling), as f32 points.
    #[wasm_bindgen(js_name = endsF32)]
    pub fn ends_f32(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] which: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] stride: JsValue,
    ) -> Result<Float32Array, JsValue> {
        const F: &str = "RuledSurface.endsF32";
        let which = integer(F, "which", &which, 1, 2)?;
        let stride = integer(F, "stride", &stride, 1, MAX_STRIDE)?;
        let rulings: Vec<Segment> =
            if stride == 1 { self.core().segments().collect() } else { self.core().inserted(stride) };
        Ok(buffers::ends_f32(&rulings, which))
    }

    // --- the linear complex, and the surface as data

    /// The linear complex that fits the rulings best (a helical surface: its screw axis; a
    /// regulus: nullity 3).
    #[wasm_bindgen(js_name = linearComplex, unchecked_return_type = "LinearComplexFit")]
    pub fn linear_complex(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "LinearComplexOptions")] options: JsValue,
    ) -> Result<JsValue, JsValue> {
        complex_js("RuledSurface.linearComplex", &self.core().segments().collect::<Vec<_>>(), options)
    }

    /// The surface as data: "csv" (header `ax,ay,az,bx,by,bz`), "json" (`{ "segments": [[…],
    /// …] }`), "obj" (vertices, ruling lines and the quads between them; `options.name`), or its
    /// invariants (Section 2) as "invariants-csv" (a row per pair of rulings) or
    /// "invariants-json" (the arrays of `invariants()`, NaN as null); full precision.
    pub fn export(
        &self,
        #[wasm_bindgen(
            unchecked_param_type = "\"csv\" | \"json\" | \"obj\" | \"invariants-csv\" | \"invariants-json\""
        )]
        format: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "ExportOptions")] options: JsValue,
    ) -> Result<String, JsValue> {
        export("RuledSurface.export", &format, options, self.core().flat(), None, Some(self.core()))
    }
}

line_buffers!(RuledSurface);

// the same shape as LineCongruence's: both cores keep their lines as one flat array and insert by stride
impl Lines for RuledSurface {
    const CLASS: &'static str = "RuledSurface";
    fn coordinates(&self) -> Cow<'_, [f64]> {
        Cow::Borrowed(self.inner.flat())
    }
    fn inserted(&self, stride: usize) -> ruledlab::Result<Vec<Segment>> {
        Ok(self.core().inserted(stride))
    }
}
