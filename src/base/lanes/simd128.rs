//! [`F64x2`] and [`Mask2`] built for `wasm32` with `simd128`: a `v128` each, every operation
//! one `core::arch::wasm32` instruction (see `lanes/mod.rs` for what they promise).

use super::{F64x2, Mask2};
use core::arch::wasm32 as w;
use core::ops::{Add, Div, Mul, Neg, Sub};

/// The lanes: one vector.
pub(super) type Repr = w::v128;
/// A comparison's answer: one vector.
pub(super) type MaskRepr = w::v128;

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
binary!(Add, add, f64x2_add);
binary!(Sub, sub, f64x2_sub);
binary!(Mul, mul, f64x2_mul);
binary!(Div, div, f64x2_div);

impl Neg for F64x2 {
    type Output = F64x2;
    #[inline(always)]
    fn neg(self) -> F64x2 {
        F64x2(w::f64x2_neg(self.0))
    }
}
