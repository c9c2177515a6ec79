//! The angle φ_{i,i+1} = atan2(|e_i × e_{i+1}|, e_i · e_{i+1}) ∈ [0, π] of Section 2 (Fig. 1;
//! the φ of δ = h/φ, (1)), two at a time in [`F64x2`] lanes, without a library `atan2`.
//!
//! `atan2` is a software routine in wasm (Rust's port of fdlibm, branches on the bits of both
//! arguments) and cannot run in two lanes. Here it is written for the upper half-plane y ≥ 0,
//! which is all φ needs (|e_i × e_{i+1}| ≥ 0), branch-free:
//!
//! - lo = min(y, |x|), hi = max(y, |x|): the angle is atan(lo/hi) ∈ [0, π/4] moved into its
//!   octant, θ = B + σ atan(lo/hi) with B ∈ {0, π/2, π} and σ = ±1 (y > |x|: π/2 − …; x < 0:
//!   π − …; both: π/2 + …);
//! - atan(lo/hi) as fdlibm's `atan` computes it: an interval by the ratio (below 7/16: c = 0;
//!   below 11/16: c = ½; else c = 1), t = (lo − c·hi)/(hi + c·lo) — one division, where fdlibm
//!   divides twice (y/x, then (z − c)/(1 + cz)); lo − c·hi is exact there (Sterbenz) — and
//!   atan(lo/hi) = atan(c) + t − t·p(t²), with fdlibm's odd polynomial of degree 22;
//! - θ = C_hi + (C_lo + σ(t − t·p(t²))), where C_hi + C_lo = B + σ atan(c) is summed exactly
//!   first (B and atan(c) as sums of two doubles, Fast2Sum), so that the only rounding at the
//!   size of θ is the last addition.
//!
//! **Accuracy.** Against the exact angle (mpmath at 200 bits, 10⁶ arguments: angles of unit
//! vectors, ratios at the interval borders, random bits, small angles) the largest error is
//! 1.40 ulp, the same as fdlibm's own `atan2` at the same argument (at small angles both compute
//! t = y/x, whose rounding carries through); elsewhere 0.94 ulp, fdlibm's 1.30, glibc's 0.51.
//! Against `f64::atan2` ([`KERNEL_ANGLE_ULPS`]): within 1 ulp of glibc's (natively) and 2 ulp of
//! fdlibm's (in wasm: the two can err by about an ulp in opposite directions). `tests/kernels.rs` checks random arguments over every
//! binade, the interval borders, the octant borders (y = |x|, y = 0, x = ±0), and the angles of
//! unit vectors φ ∈ [0, π], natively and in the browser. Lanes outside the fast path's domain —
//! y with its sign bit set, hi outside [2⁻¹⁰⁰⁰, 2¹⁰⁰⁰] (zeros, subnormals, huge numbers,
//! infinities), NaN — get `f64::atan2` itself. For φ, hi ≥ 1/√2 always (unit directions), so
//! the kernel never takes that path.
//!
//! [`KERNEL_ANGLE_ULPS`]: crate::tolerance::test::KERNEL_ANGLE_ULPS

use crate::base::lanes::{F64x2, Mask2};

/// fdlibm's coefficients of atan(t) = t − t·(s₁ + s₂), s₁ + s₂ = Σ AT[k] t^{2k+2}.
const AT: [u64; 11] = [
    0x3FD5_5555_5555_550D,
    0xBFC9_9999_9998_EBC4,
    0x3FC2_4924_9200_83FF,
    0xBFBC_71C6_FE23_1671,
    0x3FB7_45CD_C54C_206E,
    0xBFB3_B0F2_AF74_9A6D,
    0x3FB1_0D66_A0D0_3D51,
    0xBFAD_DE2D_52DE_FD9A,
    0x3FA9_7B4B_2476_0DEB,
    0xBFA2_B444_2C6A_6C2F,
    0x3F90_AD3A_E322_DA11,
];
/// atan(½) = hi + lo.
const ATAN_HALF: (u64, u64) = (0x3FDD_AC67_0561_BB4F, 0x3C7A_2B7F_222F_65E2);
/// atan(1) = π/4 = hi + lo.
const ATAN_ONE: (u64, u64) = (0x3FE9_21FB_5444_2D18, 0x3C81_A626_3314_5C07);
/// π/2 = hi + lo.
const PIO2: (u64, u64) = (0x3FF9_21FB_5444_2D18, 0x3C91_A626_3314_5C07);
/// π = hi + lo.
const PI: (u64, u64) = (0x4009_21FB_5444_2D18, 0x3CA1_A626_3314_5C07);
/// The fast path's domain: max(y, |x|) in [2⁻¹⁰⁰⁰, 2¹⁰⁰⁰], where ½·hi, 16·lo, hi + lo are
/// exact or cannot overflow.
const SMALL: f64 = 9.332636185032189e-302; // 2^-1000
const LARGE: f64 = 1.0715086071862673e301; // 2^1000

#[inline(always)]
fn c(bits: u64) -> F64x2 {
    F64x2::splat(f64::from_bits(bits))
}

/// atan2(y, x) for y ≥ 0 in both lanes (see the module documentation): within 2 ulp of
/// `f64::atan2`; lanes outside the fast path's domain get `f64::atan2` itself.
#[inline(always)]
pub fn atan2_upper(y: F64x2, x: F64x2) -> F64x2 {
    let (theta, inside) = atan2_fast(y, x);
    if inside.not().any() {
        return outside(theta, inside, y, x);
    }
    theta
}

/// The fast path of [`atan2_upper`] alone, and the lanes where it holds: a loop that calls it
/// has no call in it (a call, even one never made, makes V8 keep the loop's vectors on the
/// stack: 11 % more instructions in the invariants kernel), and redoes its work with
/// [`atan2_upper`] in the rare case that a lane was outside.
#[inline(always)]
pub fn atan2_fast(y: F64x2, x: F64x2) -> (F64x2, Mask2) {
    let ax = x.abs();
    let hi = y.max(ax);
    let lo = y.min(ax);
    let swap = ax.lt(y);
    // the interval of the ratio lo/hi, compared without dividing (16·lo is exact; a rounded
    // 7·hi only moves the border by an ulp, inside the polynomial's range)
    let lo16 = F64x2::splat(16.0) * lo;
    let first = lo16.lt(F64x2::splat(7.0) * hi);
    let second = lo16.lt(F64x2::splat(11.0) * hi);
    let cc = F64x2::select(second, F64x2::splat(0.5), F64x2::splat(1.0)).zero(first);
    let t = (lo - cc * hi) / (hi + cc * lo);
    let z = t * t;
    let w = z * z;
    let s1 = z * (c(AT[0]) + w * (c(AT[2]) + w * (c(AT[4]) + w * (c(AT[6]) + w * (c(AT[8]) + w * c(AT[10]))))));
    let s2 = w * (c(AT[1]) + w * (c(AT[3]) + w * (c(AT[5]) + w * (c(AT[7]) + w * c(AT[9])))));
    let h_hi = F64x2::select(second, c(ATAN_HALF.0), c(ATAN_ONE.0)).zero(first);
    let h_lo = F64x2::select(second, c(ATAN_HALF.1), c(ATAN_ONE.1)).zero(first);
    // atan(t) ≈ t − t·p(t²), the part that is not a constant
    let small = t - t * (s1 + s2);
    // the octant: θ = B + σ(atan(c) + atan(t)), with B + σ atan(c) = C_hi + C_lo summed first,
    // exactly (Fast2Sum: |B_hi| ≥ π/2 > |atan(c)| unless B = 0, where the sum is exact anyway), so
    // that only the last addition rounds at the size of θ
    let negative = x.sign_bit();
    let minus = swap.xor(negative);
    let b_hi = F64x2::select(swap, c(PIO2.0), c(PI.0).keep(negative));
    let b_lo = F64x2::select(swap, c(PIO2.1), c(PI.1).keep(negative));
    let (sh_hi, sh_lo) = (h_hi.negate(minus), h_lo.negate(minus));
    let c_hi = b_hi + sh_hi;
    let c_lo = (b_lo + sh_lo) + ((b_hi - c_hi) + sh_hi);
    let theta = c_hi + (c_lo + small.negate(minus));
    // (a NaN fails a comparison: in y through hi, in x through |x|)
    let large = F64x2::splat(LARGE);
    let inside = F64x2::splat(SMALL).le(hi).and(hi.le(large)).and(ax.le(large)).and(y.sign_bit().not());
    (theta, inside)
}

/// The lanes outside the fast path's domain, by `f64::atan2`.
#[cold]
#[inline(never)]
fn outside(theta: F64x2, inside: Mask2, y: F64x2, x: F64x2) -> F64x2 {
    let (mut t, keep, y, x) = (theta.to_array(), inside.to_array(), y.to_array(), x.to_array());
    for i in 0..2 {
        if !keep[i] {
            t[i] = y[i].atan2(x[i]);
        }
    }
    F64x2::from_array(t)
}

/// atan2(y, x) two at a time, as ruledlab's invariants kernel computes the angle φ of Section 2:
/// for y ≥ 0 without a library call, within 2 ulp of `f64::atan2` (1 ulp of glibc's, as
/// accurate as fdlibm's); for y < 0 (or −0), NaN, zeros, infinities and magnitudes beyond
/// 2¹⁰⁰⁰, `f64::atan2` itself.
pub fn atan2_x2(y: [f64; 2], x: [f64; 2]) -> [f64; 2] {
    atan2_upper(F64x2::from_array(y), F64x2::from_array(x)).to_array()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI as PI64};

    #[test]
    fn constants_are_their_values() {
        let hi_lo = |p: (u64, u64)| (f64::from_bits(p.0), f64::from_bits(p.1));
        assert_eq!(hi_lo(PIO2).0, FRAC_PI_2);
        assert_eq!(hi_lo(PI).0, PI64);
        assert_eq!(hi_lo(ATAN_ONE).0, FRAC_PI_4);
        assert_eq!(hi_lo(ATAN_HALF).0, 0.5f64.atan());
        assert_eq!(SMALL, 2f64.powi(-1000));
        assert_eq!(LARGE, 2f64.powi(1000));
        // the low parts are the next digits: hi + lo is π to about 2⁻¹⁰⁶
        assert!(hi_lo(PI).1 > 0.0 && hi_lo(PI).1 < PI64 * f64::EPSILON);
    }

    #[test]
    fn octant_borders_and_special_values() {
        let cases = [
            ([0.0, 0.0], [1.0, -1.0], [0.0, PI64]),
            ([1.0, 1.0], [0.0, -0.0], [FRAC_PI_2, FRAC_PI_2]),
            ([1.0, 2.0], [1.0, -2.0], [FRAC_PI_4, 3.0 * FRAC_PI_4]),
            ([0.0, 0.0], [0.0, -0.0], [0.0, PI64]),
            ([-1.0, f64::INFINITY], [1.0, 1.0], [-FRAC_PI_4, FRAC_PI_2]),
        ];
        for (y, x, want) in cases {
            let got = atan2_x2(y, x);
            for i in 0..2 {
                assert!(
                    (got[i] - want[i]).abs() <= f64::EPSILON * want[i].abs(),
                    "atan2({}, {}) = {}",
                    y[i],
                    x[i],
                    got[i]
                );
            }
        }
        assert!(atan2_x2([f64::NAN, 1.0], [1.0, f64::NAN]).iter().all(|v| v.is_nan()));
    }

    #[test]
    fn the_constants_rounding_error_is_carried_to_the_last_bit() {
        // θ = C_hi + (C_lo + …), where C_lo = (B_lo + σ·atan(c)_lo) + the rounding error of
        // B_hi + σ·atan(c)_hi. At the first two arguments (octant y > x > 0, B = π/2, c = ½)
        // dropping or negating that error moves θ by an ulp; at the last two (x > y > 0, B = 0,
        // c = 1) dropping or negating atan(1)_lo does. The kernel's θ is the exact angle rounded
        // (mpmath atan2 at 200 bits).
        let cases = [
            (0.8853447220829251, 0.46493518158976527, 1.087234929608245),
            (0.8277216789590154, 0.5611388617635288, 0.9750352680563323),
            (0.6417970014273561, 0.7668745718556942, 0.6968392540192497),
            (0.5657222818493397, 0.8245958402873351, 0.6013089129208825),
        ];
        for (y, x, exact) in cases {
            assert_eq!(atan2_x2([y, y], [x, x]), [exact, exact], "atan2({y}, {x})");
        }
    }
}
