//! Two `f64` lanes, the width of WebAssembly's `f64x2` (and of SSE2): the vocabulary of the
//! SIMD kernels of Section 2's invariants (`ruled/kernel.rs`, equations (1)–(7)) and of
//! Section 4's strip steps (`subdivision/kernel.rs`, equation (8), Chaikin, Lane–Riesenfeld).
//!
//! Built for `wasm32` with `simd128` (`.cargo/config.toml`), [`F64x2`] is a `v128` and every
//! operation one `core::arch::wasm32` instruction. Everywhere else it is a `[f64; 2]` whose
//! operations are written lane by lane; the compiler turns them into the target's own vector
//! instructions where it has them (SSE2 on x86-64, always present; NEON on aarch64).
//!
//! **Both builds compute the same bits.** Every operation is one IEEE-754 operation per lane
//! (add, sub, mul, div, sqrt: correctly rounded, so there is nothing for a target to do
//! differently), and nothing is fused: a kernel written with these operations in the order of
//! the scalar code gives that code's results to the last bit, natively and in the browser.
//! Only the NaN a lane holds may differ in sign or payload (IEEE leaves it open; wasm and x86
//! choose differently), so tests compare NaNs as NaN, never by their bits.
//!
//! The two builds are two files: `simd128.rs` (wasm32 with simd128) and `portable.rs`
//! (everything else). Mutation testing (scripts/mutants.sh) runs the first in the browser.

use core::ops::Mul;

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
mod simd128;
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
use simd128::{MaskRepr, Repr};

#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
mod portable;
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
use portable::{MaskRepr, Repr};

/// Two `f64` lanes (see the module documentation).
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub struct F64x2(Repr);

/// Per lane: all bits set (true) or none (false), as comparisons return it.
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub struct Mask2(MaskRepr);

impl Mul<F64x2> for f64 {
    type Output = F64x2;
    #[inline(always)]
    fn mul(self, o: F64x2) -> F64x2 {
        F64x2::splat(self) * o
    }
}

/// Three coordinates of two items (structure of arrays): x = (x₀, x₁), y, z.
#[derive(Clone, Copy, Debug)]
pub struct V3x2 {
    /// x of both items.
    pub x: F64x2,
    /// y of both items.
    pub y: F64x2,
    /// z of both items.
    pub z: F64x2,
}

impl V3x2 {
    /// The two points one after the other: (x₀, y₀), (z₀, x₁), (y₁, z₁).
    #[inline(always)]
    pub fn to_interleaved(self) -> [F64x2; 3] {
        [F64x2::first_lanes(self.x, self.y), F64x2::blend(self.z, self.x), F64x2::second_lanes(self.y, self.z)]
    }
    /// Every coordinate as both lanes of `v`.
    #[inline(always)]
    pub fn splat(v: F64x2) -> Self {
        V3x2 { x: v, y: v, z: v }
    }
    /// The same three lanes' operation on each coordinate.
    #[inline(always)]
    pub fn map(self, f: impl Fn(F64x2) -> F64x2) -> Self {
        V3x2 { x: f(self.x), y: f(self.y), z: f(self.z) }
    }
    /// self − o, coordinate by coordinate.
    #[inline(always)]
    pub fn sub(self, o: Self) -> Self {
        V3x2 { x: self.x - o.x, y: self.y - o.y, z: self.z - o.z }
    }
    /// self + o, coordinate by coordinate.
    #[inline(always)]
    pub fn add(self, o: Self) -> Self {
        V3x2 { x: self.x + o.x, y: self.y + o.y, z: self.z + o.z }
    }
    /// s·self (s first, as glam's `f64 * DVec3`; the product is the same either way).
    #[inline(always)]
    pub fn scale(self, s: F64x2) -> Self {
        V3x2 { x: s * self.x, y: s * self.y, z: s * self.z }
    }
    /// self·o in glam's order: (x·x′ + y·y′) + z·z′.
    #[inline(always)]
    pub fn dot(self, o: Self) -> F64x2 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }
    /// self × o in glam's order: (y z′ − y′ z, z x′ − z′ x, x y′ − x′ y).
    #[inline(always)]
    pub fn cross(self, o: Self) -> Self {
        V3x2 { x: self.y * o.z - o.y * self.z, y: self.z * o.x - o.z * self.x, z: self.x * o.y - o.x * self.y }
    }
    /// Coordinate by coordinate, `if m { a } else { b }`.
    #[inline(always)]
    pub fn select(m: Mask2, a: Self, b: Self) -> Self {
        V3x2 { x: F64x2::select(m, a.x, b.x), y: F64x2::select(m, a.y, b.y), z: F64x2::select(m, a.z, b.z) }
    }
    /// (a₁, b₀) of each coordinate ([`F64x2::shift`]).
    #[inline(always)]
    pub fn shift(a: Self, b: Self) -> Self {
        V3x2 { x: F64x2::shift(a.x, b.x), y: F64x2::shift(a.y, b.y), z: F64x2::shift(a.z, b.z) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interleaving_puts_two_points_one_after_the_other() {
        let v = V3x2 { x: F64x2::new(1.0, 4.0), y: F64x2::new(2.0, 5.0), z: F64x2::new(3.0, 6.0) };
        let back: Vec<f64> = v.to_interleaved().iter().flat_map(|l| l.to_array()).collect();
        assert_eq!(back, [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    }

    #[test]
    fn lanes_do_what_they_say() {
        let a = F64x2::new(1.0, -0.0);
        let b = F64x2::new(2.0, -3.0);
        assert_eq!(F64x2::shift(a, b).to_array().map(f64::to_bits), [(-0.0f64).to_bits(), 2.0f64.to_bits()]);
        assert_eq!(a.sign_bit().to_array(), [false, true]);
        assert_eq!(a.lt(b).to_array(), [true, false]);
        assert_eq!(F64x2::select(a.lt(b), a, b).to_array(), [1.0, -3.0]);
        assert_eq!(a.max(b).to_array(), [2.0, -0.0]);
        assert_eq!(b.min(a).to_array(), [1.0, -3.0]);
        assert_eq!((b / a.abs()).to_array(), [2.0, f64::NEG_INFINITY]);
        assert!(a.lt(b).any() && !b.lt(a).and(a.lt(b)).any());
    }

    #[test]
    fn lanes_are_scaled_by_a_number() {
        let v = F64x2::new(3.5, -0.25);
        assert_eq!((2.0 * v).to_array(), [7.0, -0.5]);
        assert_eq!(F64x2::splat(-2.0).to_array(), [-2.0, -2.0]);
        assert_eq!(F64x2::from_array([1.0, 2.0]).to_array(), [1.0, 2.0]);
    }

    #[test]
    fn masks_combine_lane_by_lane_and_negate_flips_the_sign_where_set() {
        let (t, f) = (F64x2::splat(0.0).le(F64x2::splat(1.0)), F64x2::splat(2.0).le(F64x2::splat(1.0)));
        let tf = F64x2::new(0.0, 2.0).le(F64x2::splat(1.0));
        assert_eq!((t.to_array(), f.to_array(), tf.to_array()), ([true, true], [false, false], [true, false]));
        assert_eq!(t.or(tf).to_array(), [true, true]);
        assert_eq!(f.or(tf).to_array(), [true, false]);
        assert_eq!(t.xor(tf).to_array(), [false, true]);
        assert_eq!(t.and(tf).to_array(), [true, false]);
        assert_eq!(tf.not().to_array(), [false, true]);
        assert_eq!(F64x2::new(-1.5, 2.0).negate(t).to_array(), [1.5, -2.0]);
        assert_eq!(F64x2::new(-1.5, 2.0).negate(tf).to_array(), [1.5, 2.0]);
        assert_eq!(F64x2::new(-1.5, 2.0).keep(tf).to_array(), [-1.5, 0.0]);
        assert_eq!(F64x2::new(-1.5, 2.0).zero(tf).to_array(), [0.0, 2.0]);
    }
}
