//! `RuledSurface` and `AnalyticSurface` for JavaScript (Section 2).

use super::args::{self, describe, fail, finite_option, integer, integer_option, numbers, options, to_js};
use super::catalogue::AnalyticSurface;
use super::live::Live;
use super::timing::Measure;
use crate::ruled::{self, convergence, Development, HingeChain};
use crate::tolerance::{INVARIANTS_BLOCK, MAX_SAMPLES, MAX_STUDY_LEVELS};
use js_sys::{Float32Array, Float64Array, Uint8Array};
use serde::{Deserialize, Serialize};
use std::cell::{OnceCell, RefCell};
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// Invariants kept in wasm memory, for the zero-copy path (`surface.invariantsInPlace(buffer)`).
/// Its getters are typed-array *views* of wasm memory, made when read, with the layout of
/// `invariants()`. A view is valid until the module's memory grows, which every later call into
/// ruledlab may do; an old view then reads as an empty (detached) array, never as wrong
/// numbers. So read the getters again after each computation, and copy (`slice()`) what
/// you keep. The next `invariantsInPlace` into the same buffer overwrites the numbers in place.
#[wasm_bindgen]
pub struct InvariantsBuffer {
    inner: ruled::Invariants,
    _live: Live,
}

impl Default for InvariantsBuffer {
    fn default() -> Self {
        Self::new()
    }
}

#[wasm_bindgen]
impl InvariantsBuffer {
    /// An empty buffer; it grows to the largest surface computed into it.
    #[wasm_bindgen(constructor)]
    pub fn new() -> InvariantsBuffer {
        InvariantsBuffer { inner: ruled::Invariants::default(), _live: Live::new() }
    }

    /// φ_{i,i+1}: a view of wasm memory.
    #[wasm_bindgen(getter)]
    pub fn angle(&self) -> Float64Array {
        view(&self.inner.angle)
    }

    /// h_{i,i+1}: a view of wasm memory.
    #[wasm_bindgen(getter)]
    pub fn distance(&self) -> Float64Array {
        view(&self.inner.distance)
    }

    /// δ_{i,i+1} (1): a view of wasm memory.
    #[wasm_bindgen(getter)]
    pub fn distribution(&self) -> Float64Array {
        view(&self.inner.distribution)
    }

    /// f_{i,i+1} then f_{i+1,i} per pair, 6 numbers: a view of wasm memory.
    #[wasm_bindgen(getter)]
    pub fn footpoints(&self) -> Float64Array {
        view(ruled::Invariants::flat(&self.inner.footpoints))
    }

    /// n_{i,i+1}, 3 numbers per pair: a view of wasm memory.
    #[wasm_bindgen(getter, js_name = centralNormal)]
    pub fn central_normal(&self) -> Float64Array {
        view(ruled::Invariants::flat(&self.inner.central_normal))
    }

    /// m_i (7), 3 numbers per interior ruling: a view of wasm memory.
    #[wasm_bindgen(getter)]
    pub fn striction(&self) -> Float64Array {
        view(ruled::Invariants::flat(&self.inner.striction))
    }

    /// (δ_{i−1,i} + δ_{i,i+1})/2 (7): a view of wasm memory.
    #[wasm_bindgen(getter, js_name = distributionMean)]
    pub fn distribution_mean(&self) -> Float64Array {
        view(&self.inner.distribution_mean)
    }

    /// (f_{i,i+1} + f_{i+1,i})/2, 3 numbers per pair: a view of wasm memory.
    #[wasm_bindgen(getter, js_name = perpendicularMidpoints)]
    pub fn perpendicular_midpoints(&self) -> Float64Array {
        view(ruled::Invariants::flat(&self.inner.perpendicular_midpoints))
    }

    /// 1 where pair (i, i+1) is parallel, else 0: a view of wasm memory.
    #[wasm_bindgen(getter)]
    pub fn parallel(&self) -> Uint8Array {
        // bool is one byte holding 0 or 1
        let bytes: &[u8] = bytemuck::cast_slice(&self.inner.parallel);
        // SAFETY: as in `view`
        #[allow(unsafe_code)] // a view of wasm memory is the point of this type (see `view`)
        unsafe {
            Uint8Array::view(bytes)
        }
    }
}

/// A Float64Array over `data` in wasm memory, without copying.
#[allow(unsafe_code)] // js_sys's view is unsafe: it aliases wasm memory; the contract is documented on InvariantsBuffer
fn view(data: &[f64]) -> Float64Array {
    // SAFETY: the view aliases memory owned by a buffer object that JS holds; it is only
    // invalidated by the memory growing (the view then detaches and reads as empty) or by the
    // next computation into the same buffer (which JS starts) — the documented contract.
    unsafe { Float64Array::view(data) }
}

/// A discrete ruled surface: N ≥ 2 rulings, each a segment a_i → b_i.
#[wasm_bindgen]
pub struct RuledSurface {
    inner: ruled::RuledSurface,
    /// Built on first use by the isometries, so repeated `bend(t)` calls stay cheap.
    chain: OnceCell<HingeChain>,
    _live: Live,
}

/// Options of `invariants()`.
#[derive(Deserialize, Default, Tsify)]
#[serde(default)]
struct InvariantsOptions {
    /// Read R_{N−1} as followed by R_0 (a closed surface).
    closed: bool,
}

/// The discrete invariants of Section 2 for N rulings (N − 1 pairs, N − 2 interior rulings),
/// as typed arrays (the core's [`ruled::Invariants`], flattened).
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
struct Invariants {
    /// φ_{i,i+1} ∈ [0, π], N − 1 values.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    angle: Float64Array,
    /// Signed distance h_{i,i+1} = det(a_{i+1} − a_i, e_i, e_{i+1}) / |e_i × e_{i+1}|, N − 1
    /// values.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    distance: Float64Array,
    /// Discrete distribution parameter δ_{i,i+1} = h/φ (1), N − 1 values.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    distribution: Float64Array,
    /// f_{i,i+1} then f_{i+1,i} (x, y, z each) per pair: 6(N − 1) numbers.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    footpoints: Float64Array,
    /// n_{i,i+1} = (e_i × e_{i+1}) / |e_i × e_{i+1}|, 3(N − 1) numbers.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    central_normal: Float64Array,
    /// Striction polygon (f_{i,i−1} + f_{i,i+1})/2 for rulings 1 … N − 2: 3(N − 2) numbers (7).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    striction: Float64Array,
    /// (δ_{i−1,i} + δ_{i,i+1})/2 for rulings 1 … N − 2 (7).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    distribution_mean: Float64Array,
    /// Example 1's polygon (f_{i,i+1} + f_{i+1,i})/2: 3(N − 1) numbers.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    perpendicular_midpoints: Float64Array,
    /// 1 where rulings i, i+1 are parallel (|sin φ| < 1e-9): there `distance` is the unsigned
    /// distance, and distribution, footpoints, centralNormal and the striction quantities that
    /// use the pair are NaN.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Uint8Array")]
    parallel: Uint8Array,
}

/// Options of `AnalyticSurface.convergence` (Propositions 1 and 2).
#[derive(Deserialize, Default, Tsify)]
#[serde(default)]
struct ConvergenceOptions {
    /// Parameter u to study (default 0.7).
    u: Option<f64>,
    /// Largest step H₀ ∈ (0, 1] (default 0.2).
    h0: Option<f64>,
    /// Number of steps H₀, H₀/2, … (2 … 20, default 8).
    levels: Option<f64>,
}

impl RuledSurface {
    /// Pairs and interior rulings of the invariants (closed or not): the arrays' lengths.
    fn sizes(&self, closed: bool) -> (usize, usize) {
        let n = self.inner.len();
        if closed {
            (n, n)
        } else {
            (n - 1, n - 2)
        }
    }

    /// Computes the invariants into JavaScript's arrays (of the right lengths and types), a
    /// block at a time: the kernel writes a block into wasm memory, where it stays in the
    /// processor's cache, and each array's part is copied out before the next block.
    fn fill(&self, out: &Invariants, closed: bool) {
        fn put(a: &Float64Array, at: usize, whole: usize, data: &[f64]) {
            if data.len() == whole {
                a.copy_from(data);
            } else if !data.is_empty() {
                a.subarray(at as u32, (at + data.len()) as u32).copy_from(data);
            }
        }
        let (pairs, interior) = self.sizes(closed);
        // the blocks' arrays (at most INVARIANTS_BLOCK pairs, about 600 KiB) are kept from call
        // to call: allocating them zeroed would cost a small call as much as its work. Should a
        // call come in while they are in use (an array of `out` whose own `set` calls ruledlab
        // again), it gets fresh ones instead of a panic.
        thread_local!(static SCRATCH: RefCell<ruled::Invariants> = RefCell::default());
        SCRATCH.with(|cell| {
            let mut fresh = ruled::Invariants::default();
            let mut kept = cell.try_borrow_mut();
            let scratch = match kept.as_deref_mut() {
                Ok(kept) => kept,
                Err(_) => &mut fresh,
            };
            ruled::Invariants::by_blocks(self.inner.points(), closed, INVARIANTS_BLOCK, scratch, |b| {
                let (p, m, inv) = (b.pairs_from, b.interior_from, b.inv);
                let flat = ruled::Invariants::flat;
                put(&out.angle, p, pairs, &inv.angle);
                put(&out.distance, p, pairs, &inv.distance);
                put(&out.distribution, p, pairs, &inv.distribution);
                put(&out.footpoints, 6 * p, 6 * pairs, flat(&inv.footpoints));
                put(&out.central_normal, 3 * p, 3 * pairs, flat(&inv.central_normal));
                put(&out.perpendicular_midpoints, 3 * p, 3 * pairs, flat(&inv.perpendicular_midpoints));
                put(&out.striction, 3 * m, 3 * interior, flat(&inv.striction));
                put(&out.distribution_mean, m, interior, &inv.distribution_mean);
                // bool is one byte holding 0 or 1
                let parallel: &[u8] = bytemuck::cast_slice(&inv.parallel);
                if parallel.len() == pairs {
                    out.parallel.copy_from(parallel);
                } else if !parallel.is_empty() {
                    out.parallel.subarray(p as u32, (p + parallel.len()) as u32).copy_from(parallel);
                }
            })
        });
    }

    /// Wraps a core surface.
    pub fn from_core(inner: ruled::RuledSurface) -> Self {
        RuledSurface { inner, chain: OnceCell::new(), _live: Live::new() }
    }

    fn chain(&self) -> &HingeChain {
        self.chain.get_or_init(|| HingeChain::new(&self.inner))
    }

    /// The core surface.
    pub fn core(&self) -> &ruled::RuledSurface {
        &self.inner
    }
}

#[wasm_bindgen]
impl RuledSurface {
    /// A surface from a Float64Array of 6 numbers per ruling: a.x a.y a.z b.x b.y b.z.
    /// Throws if the array is not a Float64Array, its length is not a multiple of 6, it
    /// holds fewer than 2 rulings or more than 4 194 304, a number is NaN, infinite or
    /// above 1e150 in magnitude, or a ruling has zero length.
    #[wasm_bindgen(js_name = fromSegments)]
    pub fn from_segments(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] coords: JsValue,
    ) -> Result<RuledSurface, JsValue> {
        let coords = numbers("RuledSurface.fromSegments", "coords", &coords)?;
        ruled::RuledSurface::from_flat(&coords).map(Self::from_core).map_err(|e| fail("RuledSurface.fromSegments", e))
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

    /// The segments as 32-bit floats, ready for a WebGL buffer.
    #[wasm_bindgen(js_name = segmentsF32)]
    pub fn segments_f32(&self) -> Float32Array {
        Float32Array::from(&self.inner.flat_f32()[..])
    }

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
        let (pairs, interior) = self.sizes(o.closed);
        let out = Invariants {
            angle: Float64Array::new_with_length(pairs as u32),
            distance: Float64Array::new_with_length(pairs as u32),
            distribution: Float64Array::new_with_length(pairs as u32),
            footpoints: Float64Array::new_with_length(6 * pairs as u32),
            central_normal: Float64Array::new_with_length(3 * pairs as u32),
            striction: Float64Array::new_with_length(3 * interior as u32),
            distribution_mean: Float64Array::new_with_length(interior as u32),
            perpendicular_midpoints: Float64Array::new_with_length(3 * pairs as u32),
            parallel: Uint8Array::new_with_length(pairs as u32),
        };
        self.fill(&out, o.closed);
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
            return Err(fail(F, format!("out must be an Invariants object, got {}", describe(&out))));
        }
        let o: InvariantsOptions = args::options(F, options)?;
        let (pairs, interior) = self.sizes(o.closed);
        let target = |key: &str, len: usize| -> Result<JsValue, JsValue> {
            let v = js_sys::Reflect::get(&out, &key.into()).map_err(|_| fail(F, format!("out.{key} is missing")))?;
            let got = js_sys::Reflect::get(&v, &"length".into()).ok().and_then(|l| l.as_f64());
            if got != Some(len as f64) {
                return Err(fail(
                    F,
                    format!(
                        "out.{key} must be a typed array of length {len} (this surface has {} rulings)",
                        self.inner.len()
                    ),
                ));
            }
            Ok(v)
        };
        let f64s = |key: &str, len: usize| -> Result<Float64Array, JsValue> {
            target(key, len)?
                .dyn_into::<Float64Array>()
                .map_err(|_| fail(F, format!("out.{key} must be a Float64Array")))
        };
        let out = Invariants {
            angle: f64s("angle", pairs)?,
            distance: f64s("distance", pairs)?,
            distribution: f64s("distribution", pairs)?,
            footpoints: f64s("footpoints", 6 * pairs)?,
            central_normal: f64s("centralNormal", 3 * pairs)?,
            striction: f64s("striction", 3 * interior)?,
            distribution_mean: f64s("distributionMean", interior)?,
            perpendicular_midpoints: f64s("perpendicularMidpoints", 3 * pairs)?,
            parallel: target("parallel", pairs)?
                .dyn_into::<Uint8Array>()
                .map_err(|_| fail(F, "out.parallel must be a Uint8Array"))?,
        };
        self.fill(&out, o.closed);
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
        self.inner.invariants_into(&mut buffer.inner, o.closed);
        Ok(())
    }

    /// The unit directions e_i = (b_i − a_i)/|b_i − a_i|, 3 numbers per ruling.
    pub fn directions(&self) -> Float64Array {
        Float64Array::from(ruled::Invariants::flat(&self.inner.directions()))
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
        Float64Array::from(ruled::envelope_radii(&self.inner).as_slice())
    }
}

#[wasm_bindgen]
impl AnalyticSurface {
    /// How far the discrete invariants of `count` sampled rulings are from the exact ones at
    /// those rulings (closed surfaces read as closed).
    #[wasm_bindgen(js_name = samplingErrors, unchecked_return_type = "SamplingErrors")]
    pub fn sampling_errors(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] count: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "SampleOptions")] opts: JsValue,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "AnalyticSurface.samplingErrors";
        let _measure = Measure::start(F);
        let count = integer(F, "count", &count, 3, MAX_SAMPLES)?;
        let r = self.ranges(F, opts)?;
        let e = crate::ruled::accuracy::sampling_errors(self.core(), count, r).map_err(|e| fail(F, e))?;
        to_js(F, &e)
    }

    /// Orders measured from `count` rulings and the spacing halved (`SamplingOrders`): log₂ of
    /// the ratio of the two samplings' errors (Propositions 1 and 2: 1, 2, 2, 2).
    #[wasm_bindgen(js_name = samplingOrders, unchecked_return_type = "SamplingOrders")]
    pub fn sampling_orders(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] count: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "SampleOptions")] opts: JsValue,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "AnalyticSurface.samplingOrders";
        let _measure = Measure::start(F);
        let count = integer(F, "count", &count, 3, MAX_SAMPLES / 2)?;
        let r = self.ranges(F, opts)?;
        let o = crate::ruled::accuracy::sampling_orders(self.core(), count, r).map_err(|e| fail(F, e))?;
        to_js(F, &o)
    }

    /// Measured convergence orders of the discrete invariants (Propositions 1 and 2).
    #[wasm_bindgen(unchecked_return_type = "ConvergenceStudy")]
    pub fn convergence(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "ConvergenceOptions")] opts: JsValue,
    ) -> Result<JsValue, JsValue> {
        const F: &str = "AnalyticSurface.convergence";
        let _measure = Measure::start(F);
        let o: ConvergenceOptions = options(F, opts)?;
        let levels = integer_option(F, "levels", o.levels, 2, MAX_STUDY_LEVELS)?.unwrap_or(8);
        let u = finite_option(F, "u", o.u)?.unwrap_or(0.7);
        let h0 = finite_option(F, "h0", o.h0)?.unwrap_or(0.2);
        let study = convergence::study(self.core(), u, h0, levels).map_err(|e| fail(F, e))?;
        to_js(F, &study)
    }
}
