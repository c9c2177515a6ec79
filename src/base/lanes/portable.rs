//! [`F64x2`] and [`Mask2`] everywhere but `wasm32` with `simd128`: two `f64` written lane by
//! lane, which the compiler turns into the target's own vector instructions where it has them
//! (see `lanes/mod.rs` for what they promise).

use super::{F64x2, Mask2};
use core::ops::{Add, Div, Mul, Neg, Sub};

/// The lanes.
pub(super) type Repr = Portable;
/// A comparison's answer: all bits of a lane set or none.
pub(super) type MaskRepr = [u64; 2];

/// The portable lanes, aligned like a vector register so the compiler may keep them in one.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(16))]
pub(super) struct Portable([f64; 2]);

/// Lane by lane, for the portable build.
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
#[inline(always)]
fn bits(b: bool) -> u64 {
    (b as u64).wrapping_neg()
}

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
binary!(Add, add, +);
binary!(Sub, sub, -);
binary!(Mul, mul, *);
binary!(Div, div, /);

impl Neg for F64x2 {
    type Output = F64x2;
    #[inline(always)]
    fn neg(self) -> F64x2 {
        lanes!(|a| -a, self)
    }
}
