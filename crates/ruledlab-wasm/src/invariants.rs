//! The discrete invariants of Section 2 as JavaScript's typed arrays: the options and result
//! types of `RuledSurface.invariants` and `invariantsInto`, and the copy of the core's
//! [`ruledlab::Invariants::by_blocks`] into them. No JS class: `ruled_surface.rs` calls it.

use js_sys::{Float64Array, Uint8Array};
use ruledlab::tolerance::INVARIANTS_BLOCK;
use ruledlab_js::args::fail;
use serde::{Deserialize, Serialize};
use std::cell::RefCell;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// Options of `invariants()`.
#[derive(Deserialize, Default, Tsify)]
#[serde(default)]
pub(super) struct InvariantsOptions {
    /// Read R_{N−1} as followed by R_0 (a closed surface).
    pub(super) closed: bool,
}

/// The discrete invariants of Section 2 for N rulings (N − 1 pairs, N − 2 interior rulings),
/// as typed arrays (the core's [`ruledlab::Invariants`], flattened).
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub(super) struct Invariants {
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

/// Pairs and interior rulings of the invariants (closed or not): the arrays' lengths.
fn sizes(surface: &ruledlab::RuledSurface, closed: bool) -> (usize, usize) {
    let n = surface.len();
    if closed {
        (n, n)
    } else {
        (n - 1, n - 2)
    }
}

impl Invariants {
    /// Fresh arrays of the lengths the invariants of `surface` have.
    pub(super) fn fresh(surface: &ruledlab::RuledSurface, closed: bool) -> Invariants {
        let (pairs, interior) = sizes(surface, closed);
        Invariants {
            angle: Float64Array::new_with_length(pairs as u32),
            distance: Float64Array::new_with_length(pairs as u32),
            distribution: Float64Array::new_with_length(pairs as u32),
            footpoints: Float64Array::new_with_length(6 * pairs as u32),
            central_normal: Float64Array::new_with_length(3 * pairs as u32),
            striction: Float64Array::new_with_length(3 * interior as u32),
            distribution_mean: Float64Array::new_with_length(interior as u32),
            perpendicular_midpoints: Float64Array::new_with_length(3 * pairs as u32),
            parallel: Uint8Array::new_with_length(pairs as u32),
        }
    }

    /// The arrays of `out` (an object, as returned by `invariants()`), checked to have the
    /// types and lengths the invariants of `surface` have; `func` names the export in messages.
    pub(super) fn of_object(
        func: &str,
        out: &JsValue,
        surface: &ruledlab::RuledSurface,
        closed: bool,
    ) -> Result<Invariants, JsValue> {
        let (pairs, interior) = sizes(surface, closed);
        let target = |key: &str, len: usize| -> Result<JsValue, JsValue> {
            let v = js_sys::Reflect::get(out, &key.into()).map_err(|_| fail(func, format!("out.{key} is missing")))?;
            let got = js_sys::Reflect::get(&v, &"length".into()).ok().and_then(|l| l.as_f64());
            if got != Some(len as f64) {
                return Err(fail(
                    func,
                    format!(
                        "out.{key} must be a typed array of length {len} (this surface has {} rulings)",
                        surface.len()
                    ),
                ));
            }
            Ok(v)
        };
        let f64s = |key: &str, len: usize| -> Result<Float64Array, JsValue> {
            target(key, len)?
                .dyn_into::<Float64Array>()
                .map_err(|_| fail(func, format!("out.{key} must be a Float64Array")))
        };
        Ok(Invariants {
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
                .map_err(|_| fail(func, "out.parallel must be a Uint8Array"))?,
        })
    }

    /// Computes the invariants of `surface` into these arrays (of the right lengths and types),
    /// a block at a time: the kernel writes a block into wasm memory, where it stays in the
    /// processor's cache, and each array's part is copied out before the next block.
    pub(super) fn fill(&self, surface: &ruledlab::RuledSurface, closed: bool) {
        fn put(a: &Float64Array, at: usize, whole: usize, data: &[f64]) {
            if data.len() == whole {
                a.copy_from(data);
            } else if !data.is_empty() {
                a.subarray(at as u32, (at + data.len()) as u32).copy_from(data);
            }
        }
        let out = self;
        let (pairs, interior) = sizes(surface, closed);
        // the blocks' arrays (at most INVARIANTS_BLOCK pairs, about 600 KiB) are kept from call
        // to call: allocating them zeroed would cost a small call as much as its work. Should a
        // call come in while they are in use (an array of `out` whose own `set` calls ruledlab
        // again), it gets fresh ones instead of a panic.
        thread_local!(static SCRATCH: RefCell<ruledlab::Invariants> = RefCell::default());
        SCRATCH.with(|cell| {
            let mut fresh = ruledlab::Invariants::default();
            let mut kept = cell.try_borrow_mut();
            let scratch = match kept.as_deref_mut() {
                Ok(kept) => kept,
                Err(_) => &mut fresh,
            };
            ruledlab::Invariants::by_blocks(surface.points(), closed, INVARIANTS_BLOCK, scratch, |b| {
                let (p, m, inv) = (b.pairs_from, b.interior_from, b.inv);
                let flat = ruledlab::Invariants::flat;
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
}
