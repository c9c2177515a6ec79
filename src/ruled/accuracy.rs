//! How far the discrete invariants of a sampled analytic surface are from the exact ones, at
//! the sampled rulings themselves (the readouts of the striction scene, Figs. 2–3):
//!
//! - `footpoint`: max |f_{i,i+1} − s(u_i)| (Proposition 1, first order (3));
//! - `midpoint`: max |m_i − s(u_i)|, m_i = (f_{i,i−1} + f_{i,i+1})/2 (Proposition 2, (7));
//! - `perpendicular_midpoint`: max |(f_{i,i+1} + f_{i+1,i})/2 − s(u_i + H/2)| (Example 1's
//!   polygon, Fig. 3; docs/src/conventions.md, Example 1);
//! - `distribution_mean`: max |(δ_{i−1,i} + δ_{i,i+1})/2 − δ(u_i)| (7).
//!
//! Open samplings use the interior rulings; closed ones (R_{N−1} followed by R_0) every ruling.

use crate::base::{sample_parameters, Ranges};
use crate::error::Result;
use crate::ruled::SmoothRuled;
use glam::DVec3;

/// The largest errors of a sampling (see the module documentation); NaN where a surface has
/// no striction point (a cylinder) or a pair of rulings is parallel.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "camelCase"))]
#[cfg_attr(feature = "tsify", derive(tsify_next::Tsify))]
pub struct SamplingErrors {
    /// Rulings sampled.
    pub rulings: usize,
    /// Pairs flagged parallel.
    pub parallel_pairs: usize,
    /// max |f_{i,i+1} − s(u_i)|.
    pub footpoint: f64,
    /// max |m_i − s(u_i)|.
    pub midpoint: f64,
    /// max |(f_{i,i+1} + f_{i+1,i})/2 − s(u_i + H/2)|.
    pub perpendicular_midpoint: f64,
    /// max |δ̄_i − δ(u_i)|.
    pub distribution_mean: f64,
}

/// Errors of `count` rulings of `surface` sampled over `ranges`.
pub fn sampling_errors(surface: &(impl SmoothRuled + ?Sized), count: usize, ranges: Ranges) -> Result<SamplingErrors> {
    let sampled = surface.sample(count, ranges)?;
    let u = sample_parameters(count, ranges);
    // `sample` refuses fewer than 2 rulings
    let h = u[1] - u[0];
    let inv = if ranges.closed { sampled.invariants_closed() } else { sampled.invariants() };
    // the rulings that have a striction point, and the index of their m_i
    let rulings: Vec<(usize, usize)> =
        if ranges.closed { (0..count).map(|i| (i, i)).collect() } else { (1..count - 1).map(|i| (i, i - 1)).collect() };
    let nan = DVec3::splat(f64::NAN);
    let exact = |u: f64| surface.striction(u).unwrap_or(nan);
    let max = |values: &mut dyn Iterator<Item = f64>| {
        values.fold(0.0, |m: f64, x| if x.is_nan() || m.is_nan() { f64::NAN } else { m.max(x) })
    };
    Ok(SamplingErrors {
        rulings: count,
        parallel_pairs: inv.parallel.iter().filter(|&&p| p).count(),
        footpoint: max(&mut rulings.iter().map(|&(i, _)| (inv.footpoints[2 * i] - exact(u[i])).length())),
        midpoint: max(&mut rulings.iter().map(|&(i, m)| (inv.striction[m] - exact(u[i])).length())),
        perpendicular_midpoint: max(&mut (0..inv.perpendicular_midpoints.len())
            .map(|i| (inv.perpendicular_midpoints[i] - exact(u[i] + h / 2.0)).length())),
        distribution_mean: max(&mut rulings
            .iter()
            .map(|&(i, m)| (inv.distribution_mean[m] - surface.distribution(u[i])).abs())),
    })
}

/// Orders measured from a sampling of `count` rulings and one with the spacing halved
/// (2·count − 1 rulings on an open range, 2·count on a closed one): log₂ of the ratio of
/// [`SamplingErrors`]; NaN where an error is NaN or zero.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "camelCase"))]
#[cfg_attr(feature = "tsify", derive(tsify_next::Tsify))]
pub struct SamplingOrders {
    /// Rulings of the finer sampling.
    pub finer: usize,
    /// Order of max |f_{i,i+1} − s(u_i)| (1 by Proposition 1).
    pub footpoint: f64,
    /// Order of max |m_i − s(u_i)| (2 by Proposition 2).
    pub midpoint: f64,
    /// Order of the perpendicular midpoints (2: docs/src/conventions.md, Example 1).
    pub perpendicular_midpoint: f64,
    /// Order of max |δ̄_i − δ(u_i)| (2 by (7)).
    pub distribution_mean: f64,
}

/// log₂(coarse/fine): the order of an error that falls from `coarse` to `fine` when the
/// spacing is halved; NaN unless both are positive (an exact sampling has no order, and a NaN
/// error none either).
fn order(coarse: f64, fine: f64) -> f64 {
    if coarse > 0.0 && fine > 0.0 {
        (coarse / fine).log2()
    } else {
        f64::NAN
    }
}

/// The orders of the sampling errors of `surface` at `count` rulings (see [`SamplingOrders`]).
pub fn sampling_orders(surface: &(impl SmoothRuled + ?Sized), count: usize, ranges: Ranges) -> Result<SamplingOrders> {
    // the coarse sampling first: it refuses a count of 0 or 1 (2·count − 1 would underflow) and
    // one above MAX_SAMPLES (2·count could overflow)
    let coarse = sampling_errors(surface, count, ranges)?;
    let finer = if ranges.closed { 2 * count } else { 2 * count - 1 };
    let fine = sampling_errors(surface, finer, ranges)?;
    Ok(SamplingOrders {
        finer,
        footpoint: order(coarse.footpoint, fine.footpoint),
        midpoint: order(coarse.midpoint, fine.midpoint),
        perpendicular_midpoint: order(coarse.perpendicular_midpoint, fine.perpendicular_midpoint),
        distribution_mean: order(coarse.distribution_mean, fine.distribution_mean),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalogue::AnalyticSurface;
    #[allow(unused_imports)]
    use crate::congruence::SmoothCongruence;
    #[allow(unused_imports)]
    use crate::ruled::SmoothRuled;

    /// Propositions 1 and 2 on Example 1's hyperboloid, halving the spacing exactly: orders 1,
    /// 2, 2, 2 (open and closed samplings).
    #[test]
    fn measured_orders_are_the_propositions() {
        for (s, n, slack) in [(AnalyticSurface::ALL[0].clone(), 40, 0.1), (AnalyticSurface::Quartic, 40, 0.25)] {
            let r = s.ranges();
            let o = sampling_orders(&s, n, r).unwrap();
            assert_eq!(o.finer, if r.closed { 2 * n } else { 2 * n - 1 });
            for (got, want) in
                [(o.footpoint, 1.0), (o.midpoint, 2.0), (o.perpendicular_midpoint, 2.0), (o.distribution_mean, 2.0)]
            {
                assert!((got - want).abs() < slack, "{}: {o:?}", s.name());
            }
        }
        // a cylinder has no striction point: NaN, never a made-up order
        assert!(sampling_orders(&AnalyticSurface::Cylinder, 20, AnalyticSurface::Cylinder.ranges())
            .unwrap()
            .midpoint
            .is_nan());
    }

    #[test]
    fn an_order_needs_two_positive_errors() {
        assert_eq!(order(8.0, 2.0), 2.0);
        assert_eq!(order(3.0, 6.0), -1.0);
        assert_eq!(order(1.0, 1.0), 0.0);
        for (coarse, fine) in [(0.0, 1.0), (1.0, 0.0), (0.0, 0.0), (-4.0, -1.0), (f64::NAN, 1.0), (1.0, f64::NAN)] {
            assert!(order(coarse, fine).is_nan(), "order({coarse}, {fine})");
        }
    }

    /// Fewer than two rulings have no errors to measure: refused, like the sampling.
    #[test]
    fn one_ruling_is_refused() {
        let hyp = AnalyticSurface::ALL[0].clone();
        for closed in [false, true] {
            let r = Ranges { closed, ..hyp.ranges() };
            for count in [0, 1] {
                assert!(matches!(
                    sampling_errors(&hyp, count, r),
                    Err(crate::error::Error::TooFew { what: "rulings", got, min: 2 }) if got == count
                ));
                assert!(matches!(
                    sampling_orders(&hyp, count, r),
                    Err(crate::error::Error::TooFew { what: "rulings", got, min: 2 }) if got == count
                ));
            }
        }
    }

    /// On the hyperboloid of Example 1 the midpoint errors fall 4× when N doubles (second
    /// order), the footpoint errors 2× (first order), and closing the surface changes nothing
    /// in the interior.
    #[test]
    fn orders_of_the_sampled_polygons() {
        let hyp = AnalyticSurface::ALL[0].clone();
        let r = hyp.ranges();
        let (a, b) = (sampling_errors(&hyp, 64, r).unwrap(), sampling_errors(&hyp, 128, r).unwrap());
        assert!(((a.midpoint / b.midpoint).log2() - 2.0).abs() < 0.1, "{a:?} {b:?}");
        assert!(((a.perpendicular_midpoint / b.perpendicular_midpoint).log2() - 2.0).abs() < 0.1, "{a:?} {b:?}");
        assert!(((a.footpoint / b.footpoint).log2() - 1.0).abs() < 0.1, "{a:?} {b:?}");
        assert!(((a.distribution_mean / b.distribution_mean).log2() - 2.0).abs() < 0.15, "{a:?} {b:?}");
        assert_eq!(a.parallel_pairs, 0);
        // the cylinder has no striction point: NaN, not a number that looks right
        let cyl = AnalyticSurface::Cylinder;
        assert!(sampling_errors(&cyl, 12, cyl.ranges()).unwrap().midpoint.is_nan());
        // the helicoid's footpoints are exact
        let hel = AnalyticSurface::Helicoid { pitch: 0.5 };
        assert!(sampling_errors(&hel, 20, hel.ranges()).unwrap().footpoint < 1e-12);
    }
}
