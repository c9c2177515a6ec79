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

use core::ops::{Add, Div, Mul, Neg, Sub};

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
use core::arch::wasm32 as w;

/// Two `f64` lanes (see the module documentation).
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub struct F64x2(Repr);

/// Per lane: all bits set (true) or none (false), as comparisons return it.
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub struct Mask2(MaskRepr);

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
type Repr = w::v128;
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
type MaskRepr = w::v128;

#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
type Repr = Portable;
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
type MaskRepr = [u64; 2];

/// The portable lanes, aligned like a vector register so the compiler may keep them in one.
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
#[derive(Clone, Copy, Debug)]
#[repr(C, align(16))]
pub struct Portable([f64; 2]);

/// Lane by lane, for the portable build.
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
macro_rules! lanes {
    (|$a:ident| $e:expr, $x:expr) => {{
        let x = $x;
        F64x2(Portable([
            {
                let $a = x.0 .0[0];
                $e
            },
            {
                let $a = x.0 .0[1];
                $e
            },
        ]))
    }};
    (|$a:ident, $b:ident| $e:expr, $x:expr, $y:expr) => {{
        let (x, y) = ($x, $y);
        F64x2(Portable([
            {
                let ($a, $b) = (x.0 .0[0], y.0 .0[0]);
                $e
            },
            {
                let ($a, $b) = (x.0 .0[1], y.0 .0[1]);
                $e
            },
        ]))
    }};
}

/// All bits of a lane for a comparison's answer.
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
#[inline(always)]
fn bits(b: bool) -> u64 {
    (b as u64).wrapping_neg()
}

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
impl F64x2 {
    /// (a, b).
    #[inline(always)]
    pub fn new(a: f64, b: f64) -> Self {
        F64x2(w::f64x2(a, b))
    }
    /// (x, x).
    #[inline(always)]
    pub fn splat(x: f64) -> Self {
        F64x2(w::f64x2_splat(x))
    }
    /// The lanes as an array: a reinterpretation, which stores the vector whole.
    #[inline(always)]
    pub fn to_array(self) -> [f64; 2] {
        bytemuck::cast(self.0)
    }
    /// From two consecutive numbers: one vector load.
    #[inline(always)]
    pub fn from_array(a: [f64; 2]) -> Self {
        F64x2(bytemuck::cast(a))
    }
    /// Lane 0.
    #[inline(always)]
    pub fn lo(self) -> f64 {
        w::f64x2_extract_lane::<0>(self.0)
    }
    /// Lane 1.
    #[inline(always)]
    pub fn hi(self) -> f64 {
        w::f64x2_extract_lane::<1>(self.0)
    }
    /// √x per lane.
    #[inline(always)]
    pub fn sqrt(self) -> Self {
        F64x2(w::f64x2_sqrt(self.0))
    }
    /// |x| per lane (the sign bit cleared).
    #[inline(always)]
    pub fn abs(self) -> Self {
        F64x2(w::f64x2_abs(self.0))
    }
    /// `if o < self { o } else { self }` per lane (`f64x2.pmin`: one instruction, for
    /// operands that are not NaN).
    #[inline(always)]
    pub fn min(self, o: Self) -> Self {
        F64x2(w::f64x2_pmin(self.0, o.0))
    }
    /// `if self < o { o } else { self }` per lane (`f64x2.pmax`).
    #[inline(always)]
    pub fn max(self, o: Self) -> Self {
        F64x2(w::f64x2_pmax(self.0, o.0))
    }
    /// self < o per lane.
    #[inline(always)]
    pub fn lt(self, o: Self) -> Mask2 {
        Mask2(w::f64x2_lt(self.0, o.0))
    }
    /// self ≤ o per lane.
    #[inline(always)]
    pub fn le(self, o: Self) -> Mask2 {
        Mask2(w::f64x2_le(self.0, o.0))
    }
    /// Lanes whose sign bit is set (negative numbers, −0, NaNs with the bit): the lanes'
    /// bits as signed integers below zero (one instruction; a shift by 63 would be six in V8).
    #[inline(always)]
    pub fn sign_bit(self) -> Mask2 {
        Mask2(w::i64x2_lt(self.0, w::i64x2_splat(0)))
    }
    /// `if m { a } else { b }` per lane.
    #[inline(always)]
    pub fn select(m: Mask2, a: Self, b: Self) -> Self {
        F64x2(w::v128_bitselect(a.0, b.0, m.0))
    }
    /// `if m { self } else { 0 }` per lane (one instruction).
    #[inline(always)]
    pub fn keep(self, m: Mask2) -> Self {
        F64x2(w::v128_and(self.0, m.0))
    }
    /// `if m { 0 } else { self }` per lane (one instruction).
    #[inline(always)]
    pub fn zero(self, m: Mask2) -> Self {
        F64x2(w::v128_andnot(self.0, m.0))
    }
    /// `if m { −self } else { self }` per lane: the sign bit flipped, exact.
    #[inline(always)]
    pub fn negate(self, m: Mask2) -> Self {
        F64x2(w::v128_xor(self.0, w::v128_and(m.0, w::f64x2_splat(-0.0))))
    }
    /// (a₀, b₀): the first lanes of two vectors.
    #[inline(always)]
    pub fn first_lanes(a: Self, b: Self) -> Self {
        F64x2(w::i64x2_shuffle::<0, 2>(a.0, b.0))
    }
    /// (a₁, b₁): the second lanes of two vectors.
    #[inline(always)]
    pub fn second_lanes(a: Self, b: Self) -> Self {
        F64x2(w::i64x2_shuffle::<1, 3>(a.0, b.0))
    }
    /// (a₁, b₀): the window one lane on, where `a` holds items k − 1, k and `b` items k + 1,
    /// k + 2.
    #[inline(always)]
    pub fn shift(a: Self, b: Self) -> Self {
        F64x2(w::i64x2_shuffle::<1, 2>(a.0, b.0))
    }
    /// (a₀, b₁).
    #[inline(always)]
    pub fn blend(a: Self, b: Self) -> Self {
        F64x2(w::i64x2_shuffle::<0, 3>(a.0, b.0))
    }
}

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
impl Mask2 {
    /// Both lanes' answers.
    #[inline(always)]
    pub fn to_array(self) -> [bool; 2] {
        [w::i64x2_extract_lane::<0>(self.0) != 0, w::i64x2_extract_lane::<1>(self.0) != 0]
    }
    /// Whether some lane is set.
    #[inline(always)]
    pub fn any(self) -> bool {
        w::v128_any_true(self.0)
    }
    /// Set where both are.
    #[inline(always)]
    pub fn and(self, o: Self) -> Self {
        Mask2(w::v128_and(self.0, o.0))
    }
    /// Set where either is.
    #[inline(always)]
    pub fn or(self, o: Self) -> Self {
        Mask2(w::v128_or(self.0, o.0))
    }
    /// Set where exactly one is.
    #[inline(always)]
    pub fn xor(self, o: Self) -> Self {
        Mask2(w::v128_xor(self.0, o.0))
    }
    /// Set where this is not.
    #[inline(always)]
    pub fn not(self) -> Self {
        Mask2(w::v128_not(self.0))
    }
}

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
macro_rules! binary {
    ($trait:ident, $f:ident, $op:ident) => {
        impl $trait for F64x2 {
            type Output = F64x2;
            #[inline(always)]
            fn $f(self, o: F64x2) -> F64x2 {
                F64x2(w::$op(self.0, o.0))
            }
        }
    };
}
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
binary!(Add, add, f64x2_add);
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
binary!(Sub, sub, f64x2_sub);
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
binary!(Mul, mul, f64x2_mul);
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
binary!(Div, div, f64x2_div);

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
impl Neg for F64x2 {
    type Output = F64x2;
    #[inline(always)]
    fn neg(self) -> F64x2 {
        F64x2(w::f64x2_neg(self.0))
    }
}

#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
impl F64x2 {
    /// (a, b).
    #[inline(always)]
    pub fn new(a: f64, b: f64) -> Self {
        F64x2(Portable([a, b]))
    }
    /// (x, x).
    #[inline(always)]
    pub fn splat(x: f64) -> Self {
        F64x2(Portable([x, x]))
    }
    /// The lanes as an array.
    #[inline(always)]
    pub fn to_array(self) -> [f64; 2] {
        self.0 .0
    }
    /// From two consecutive numbers.
    #[inline(always)]
    pub fn from_array(a: [f64; 2]) -> Self {
        F64x2(Portable(a))
    }
    /// Lane 0.
    #[inline(always)]
    pub fn lo(self) -> f64 {
        self.0 .0[0]
    }
    /// Lane 1.
    #[inline(always)]
    pub fn hi(self) -> f64 {
        self.0 .0[1]
    }
    /// √x per lane.
    #[inline(always)]
    pub fn sqrt(self) -> Self {
        lanes!(|a| a.sqrt(), self)
    }
    /// |x| per lane (the sign bit cleared).
    #[inline(always)]
    pub fn abs(self) -> Self {
        lanes!(|a| a.abs(), self)
    }
    /// `if o < self { o } else { self }` per lane.
    #[inline(always)]
    pub fn min(self, o: Self) -> Self {
        lanes!(|a, b| if b < a { b } else { a }, self, o)
    }
    /// `if self < o { o } else { self }` per lane.
    #[inline(always)]
    pub fn max(self, o: Self) -> Self {
        lanes!(|a, b| if a < b { b } else { a }, self, o)
    }
    /// self < o per lane.
    #[inline(always)]
    pub fn lt(self, o: Self) -> Mask2 {
        let (a, b) = (self.0 .0, o.0 .0);
        Mask2([bits(a[0] < b[0]), bits(a[1] < b[1])])
    }
    /// self ≤ o per lane.
    #[inline(always)]
    pub fn le(self, o: Self) -> Mask2 {
        let (a, b) = (self.0 .0, o.0 .0);
        Mask2([bits(a[0] <= b[0]), bits(a[1] <= b[1])])
    }
    /// Lanes whose sign bit is set (negative numbers, −0, NaNs with the bit).
    #[inline(always)]
    pub fn sign_bit(self) -> Mask2 {
        let a = self.0 .0;
        Mask2([bits(a[0].is_sign_negative()), bits(a[1].is_sign_negative())])
    }
    /// `if m { a } else { b }` per lane.
    #[inline(always)]
    pub fn select(m: Mask2, a: Self, b: Self) -> Self {
        let pick = |i: usize| f64::from_bits((a.0 .0[i].to_bits() & m.0[i]) | (b.0 .0[i].to_bits() & !m.0[i]));
        F64x2(Portable([pick(0), pick(1)]))
    }
    /// `if m { self } else { 0 }` per lane.
    #[inline(always)]
    pub fn keep(self, m: Mask2) -> Self {
        let pick = |i: usize| f64::from_bits(self.0 .0[i].to_bits() & m.0[i]);
        F64x2(Portable([pick(0), pick(1)]))
    }
    /// `if m { 0 } else { self }` per lane.
    #[inline(always)]
    pub fn zero(self, m: Mask2) -> Self {
        let pick = |i: usize| f64::from_bits(self.0 .0[i].to_bits() & !m.0[i]);
        F64x2(Portable([pick(0), pick(1)]))
    }
    /// `if m { −self } else { self }` per lane: the sign bit flipped, exact.
    #[inline(always)]
    pub fn negate(self, m: Mask2) -> Self {
        let pick = |i: usize| f64::from_bits(self.0 .0[i].to_bits() ^ (m.0[i] & (1 << 63)));
        F64x2(Portable([pick(0), pick(1)]))
    }
    /// (a₀, b₀): the first lanes of two vectors.
    #[inline(always)]
    pub fn first_lanes(a: Self, b: Self) -> Self {
        F64x2(Portable([a.0 .0[0], b.0 .0[0]]))
    }
    /// (a₁, b₁): the second lanes of two vectors.
    #[inline(always)]
    pub fn second_lanes(a: Self, b: Self) -> Self {
        F64x2(Portable([a.0 .0[1], b.0 .0[1]]))
    }
    /// (a₁, b₀): the window one lane on, where `a` holds items k − 1, k and `b` items k + 1,
    /// k + 2.
    #[inline(always)]
    pub fn shift(a: Self, b: Self) -> Self {
        F64x2(Portable([a.0 .0[1], b.0 .0[0]]))
    }
    /// (a₀, b₁).
    #[inline(always)]
    pub fn blend(a: Self, b: Self) -> Self {
        F64x2(Portable([a.0 .0[0], b.0 .0[1]]))
    }
}

#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
impl Mask2 {
    /// Both lanes' answers.
    #[inline(always)]
    pub fn to_array(self) -> [bool; 2] {
        [self.0[0] != 0, self.0[1] != 0]
    }
    /// Whether some lane is set.
    #[inline(always)]
    pub fn any(self) -> bool {
        (self.0[0] | self.0[1]) != 0
    }
    /// Set where both are.
    #[inline(always)]
    pub fn and(self, o: Self) -> Self {
        Mask2([self.0[0] & o.0[0], self.0[1] & o.0[1]])
    }
    /// Set where either is.
    #[inline(always)]
    pub fn or(self, o: Self) -> Self {
        Mask2([self.0[0] | o.0[0], self.0[1] | o.0[1]])
    }
    /// Set where exactly one is.
    #[inline(always)]
    pub fn xor(self, o: Self) -> Self {
        Mask2([self.0[0] ^ o.0[0], self.0[1] ^ o.0[1]])
    }
    /// Set where this is not.
    #[inline(always)]
    pub fn not(self) -> Self {
        Mask2([!self.0[0], !self.0[1]])
    }
}

#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
macro_rules! binary {
    ($trait:ident, $f:ident, $op:tt) => {
        impl $trait for F64x2 {
            type Output = F64x2;
            #[inline(always)]
            fn $f(self, o: F64x2) -> F64x2 {
                lanes!(|a, b| a $op b, self, o)
            }
        }
    };
}
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
binary!(Add, add, +);
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
binary!(Sub, sub, -);
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
binary!(Mul, mul, *);
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
binary!(Div, div, /);

#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
impl Neg for F64x2 {
    type Output = F64x2;
    #[inline(always)]
    fn neg(self) -> F64x2 {
        lanes!(|a| -a, self)
    }
}

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
}
