//! `InvariantsBuffer` for JavaScript (Section 2): the invariants of a surface kept in wasm
//! memory, read through views (`surface.invariantsInPlace(buffer)`).

use js_sys::{Float64Array, Uint8Array};
use ruledlab_js::live::Live;
use wasm_bindgen::prelude::*;

/// Invariants kept in wasm memory, for the zero-copy path (`surface.invariantsInPlace(buffer)`).
/// Its getters are typed-array *views* of wasm memory, made when read, with the layout of
/// `invariants()`. A view is valid until the module's memory grows, which every later call into
/// ruledlab may do; an old view then reads as an empty (detached) array, never as wrong
/// numbers. So read the getters again after each computation, and copy (`slice()`) what
/// you keep. The next `invariantsInPlace` into the same buffer overwrites the numbers in place.
#[wasm_bindgen]
pub struct InvariantsBuffer {
    inner: ruledlab::Invariants,
    _live: Live,
}

impl Default for InvariantsBuffer {
    fn default() -> Self {
        Self::new()
    }
}

impl InvariantsBuffer {
    /// The core's invariants it holds, to compute into.
    pub(super) fn core_mut(&mut self) -> &mut ruledlab::Invariants {
        &mut self.inner
    }
}

#[wasm_bindgen]
impl InvariantsBuffer {
    /// An empty buffer; it grows to the largest surface computed into it.
    #[wasm_bindgen(constructor)]
    pub fn new() -> InvariantsBuffer {
        InvariantsBuffer { inner: ruledlab::Invariants::default(), _live: Live::new() }
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
        view(ruledlab::Invariants::flat(&self.inner.footpoints))
    }

    /// n_{i,i+1}, 3 numbers per pair: a view of wasm memory.
    #[wasm_bindgen(getter, js_name = centralNormal)]
    pub fn central_normal(&self) -> Float64Array {
        view(ruledlab::Invariants::flat(&self.inner.central_normal))
    }

    /// m_i (7), 3 numbers per interior ruling: a view of wasm memory.
    #[wasm_bindgen(getter)]
    pub fn striction(&self) -> Float64Array {
        view(ruledlab::Invariants::flat(&self.inner.striction))
    }

    /// (δ_{i−1,i} + δ_{i,i+1})/2 (7): a view of wasm memory.
    #[wasm_bindgen(getter, js_name = distributionMean)]
    pub fn distribution_mean(&self) -> Float64Array {
        view(&self.inner.distribution_mean)
    }

    /// (f_{i,i+1} + f_{i+1,i})/2, 3 numbers per pair: a view of wasm memory.
    #[wasm_bindgen(getter, js_name = perpendicularMidpoints)]
    pub fn perpendicular_midpoints(&self) -> Float64Array {
        view(ruledlab::Invariants::flat(&self.inner.perpendicular_midpoints))
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
