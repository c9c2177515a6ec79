//! Convergence study of the discrete invariants (Propositions 1 and 2, Section 2).
//!
//! Around a parameter u of an analytic surface, take the rulings R(u − H), R(u), R(u + H)
//! for H = H₀, H₀/2, H₀/4, … and compare with the exact values at u:
//!
//! | quantity            | discrete                     | exact  | expected order |
//! |---------------------|------------------------------|--------|----------------|
//! | `footpoint`         | f_{i,i+1}                    | s(u)   | 1 (3), (6)     |
//! | `midpoint`          | (f_{i,i−1} + f_{i,i+1})/2    | s(u)   | 2 (7)          |
//! | `distribution`      | δ_{i,i+1} (1)                | δ(u)   | 1 (2), (5)     |
//! | `distributionMean`  | (δ_{i−1,i} + δ_{i,i+1})/2    | δ(u)   | 2 (7)          |
//! | `centralNormal`     | ∠(n_{i,i+1}, e₃(u))          | 0      | 1 (4)          |
//! | `perpendicularMidpoint` | (f_{i,i+1} + f_{i+1,i})/2 | s(u + H/2) | 2 (conventions: Example 1) |
//!
//! Orders are log₂ of successive error ratios; the fitted order is the least-squares slope
//! of log(error) against log(H). Errors at the rounding floor carry no order (NaN).

use crate::error::{Error, Result};
use crate::ruled::invariants::PairInvariants;
use crate::ruled::SmoothRuled;
use crate::tolerance::{CONVERGENCE_NOISE_FLOOR, MAX_STUDY_LEVELS};

/// One quantity's errors over the refinement levels.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "camelCase"))]
#[cfg_attr(feature = "tsify", derive(tsify_next::Tsify))]
pub struct ConvergenceSeries {
    /// Name of the quantity (see the module table).
    #[cfg_attr(
        feature = "tsify",
        tsify(
            type = "\"footpoint\" | \"midpoint\" | \"distribution\" | \"distributionMean\" | \"centralNormal\" | \"perpendicularMidpoint\""
        )
    )]
    pub name: &'static str,
    /// The order Propositions 1 and 2 predict.
    pub expected_order: f64,
    /// Error at each step H.
    pub errors: Vec<f64>,
    /// `log₂(errors[k]/errors[k+1])`, one fewer than the errors.
    pub orders: Vec<f64>,
    /// Least-squares slope of log error against log H.
    pub fitted_order: f64,
}

/// The result of [`convergence_study`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "camelCase"))]
#[cfg_attr(feature = "tsify", derive(tsify_next::Tsify))]
pub struct ConvergenceStudy {
    /// Surface name.
    pub surface: String,
    /// The parameter u studied.
    pub u: f64,
    /// The steps H₀, H₀/2, ….
    pub steps: Vec<f64>,
    /// One series per quantity.
    pub series: Vec<ConvergenceSeries>,
}

/// Runs the study at `u` with steps `h0 · 2^{−k}`, k = 0 … levels − 1.
pub fn convergence_study(
    surface: &(impl SmoothRuled + ?Sized),
    u: f64,
    h0: f64,
    levels: usize,
) -> Result<ConvergenceStudy> {
    if !u.is_finite() {
        return Err(Error::parameter("u", format!("must be a finite number, got {u}")));
    }
    if !(h0.is_finite() && h0 > 0.0 && h0 <= 1.0) {
        return Err(Error::parameter("h0", format!("must be in (0, 1], got {h0}")));
    }
    if !(2..=MAX_STUDY_LEVELS).contains(&levels) {
        return Err(Error::parameter(
            "levels",
            format!("must be an integer from 2 to {MAX_STUDY_LEVELS}, got {levels}"),
        ));
    }
    let (Some(s), Some(e3)) = (surface.striction(u), surface.central_tangent(u)) else {
        return Err(Error::parameter("surface", crate::msg!("no-striction-point", name = surface.name(), u = u)));
    };
    let delta = surface.distribution(u);
    let steps: Vec<f64> = (0..levels).map(|k| h0 / f64::powi(2.0, k as i32)).collect();
    let names = [
        ("footpoint", 1.0),
        ("midpoint", 2.0),
        ("distribution", 1.0),
        ("distributionMean", 2.0),
        ("centralNormal", 1.0),
        ("perpendicularMidpoint", 2.0),
    ];
    let mut errors = vec![Vec::with_capacity(levels); names.len()];
    for &h in &steps {
        let (rm, r0, rp) = (surface.line(u - h), surface.line(u), surface.line(u + h));
        let (prev, next) = (PairInvariants::of(&rm, &r0), PairInvariants::of(&r0, &rp));
        let (Some((_, f_back)), Some((f_fwd, f_next)), Some(n)) = (prev.feet, next.feet, next.normal) else {
            return Err(Error::degenerate("h0", crate::msg!("parallel-at-step", h = h)));
        };
        let s_mid = surface.striction(u + h / 2.0).unwrap_or(s);
        let values = [
            (f_fwd - s).length(),
            (0.5 * (f_back + f_fwd) - s).length(),
            (next.distribution() - delta).abs(),
            (0.5 * (prev.distribution() + next.distribution()) - delta).abs(),
            n.angle_between(e3),
            (0.5 * (f_fwd + f_next) - s_mid).length(),
        ];
        for (series, v) in errors.iter_mut().zip(values) {
            series.push(v);
        }
    }
    let series = names
        .iter()
        .zip(errors)
        .map(|(&(name, expected_order), errors)| {
            let orders = errors
                .windows(2)
                .map(|w| if w[1] > CONVERGENCE_NOISE_FLOOR { (w[0] / w[1]).log2() } else { f64::NAN })
                .collect();
            ConvergenceSeries { name, expected_order, fitted_order: fit_order(&steps, &errors), errors, orders }
        })
        .collect();
    Ok(ConvergenceStudy { surface: surface.name().to_string(), u, steps, series })
}

/// Least-squares slope of log(error) against log(H) over the errors above the noise floor.
pub fn fit_order(steps: &[f64], errors: &[f64]) -> f64 {
    let pts: Vec<(f64, f64)> = steps
        .iter()
        .zip(errors)
        .filter(|(_, &e)| e > CONVERGENCE_NOISE_FLOOR)
        .map(|(&h, &e)| (h.ln(), e.ln()))
        .collect();
    if pts.len() < 2 {
        return f64::NAN;
    }
    let n = pts.len() as f64;
    let (mx, my) = pts.iter().fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
    let (sxy, sxx) = pts.iter().fold((0.0, 0.0), |(a, b), (x, y)| (a + (x - mx) * (y - my), b + (x - mx) * (x - mx)));
    sxy / sxx
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;
    use crate::catalogue::AnalyticSurface;
    #[allow(unused_imports)]
    use crate::congruence::SmoothCongruence;
    #[allow(unused_imports)]
    use crate::ruled::SmoothRuled;
    use crate::tolerance::test::EXACT;

    #[test]
    fn fit_recovers_a_power_law() {
        let steps = [0.1, 0.05, 0.025, 0.0125];
        let errors: Vec<f64> = steps.iter().map(|h: &f64| 3.0 * h.powf(2.5)).collect();
        assert_near!(fit_order(&steps, &errors), 2.5, EXACT);
        assert!(fit_order(&steps, &[0.0; 4]).is_nan());
    }

    #[test]
    fn rejects_bad_parameters() {
        let s = AnalyticSurface::Quartic;
        assert!(convergence_study(&s, f64::NAN, 0.1, 5).is_err());
        assert!(convergence_study(&s, 0.3, 0.0, 5).is_err());
        assert!(convergence_study(&s, 0.3, 0.1, 1).is_err());
        assert!(convergence_study(&s, 0.3, 0.1, 99).is_err());
        assert!(convergence_study(&AnalyticSurface::Cylinder, 0.3, 0.1, 5).is_err());
    }

    #[test]
    fn each_parameter_is_refused_by_name_at_its_bounds() {
        let s = AnalyticSurface::Quartic;
        let option =
            |u: f64, h0: f64, levels: usize| convergence_study(&s, u, h0, levels).unwrap_err().details().option;
        assert_eq!(option(f64::INFINITY, 0.1, 5).as_deref(), Some("u"));
        for h0 in [0.0, -0.1, 1.000001, f64::NAN, f64::INFINITY] {
            assert_eq!(option(0.3, h0, 5).as_deref(), Some("h0"), "h0 = {h0}");
        }
        for levels in [1, MAX_STUDY_LEVELS + 1] {
            assert_eq!(option(0.3, 0.1, levels).as_deref(), Some("levels"));
        }
        // h0 = 1 and both ends of the levels are accepted; the steps halve from h0
        let ok = convergence_study(&s, 0.3, 1.0, 2).unwrap();
        assert_eq!((ok.u, ok.steps.clone()), (0.3, vec![1.0, 0.5]));
        assert_eq!(convergence_study(&s, 0.3, 0.1, MAX_STUDY_LEVELS).unwrap().steps.len(), MAX_STUDY_LEVELS);
    }

    #[test]
    fn two_errors_above_the_floor_are_enough_for_an_order() {
        // errors 4e-2 and 1e-2 at H = 0.2 and 0.1: order log₂ 4 = 2; one error alone has none
        assert_near!(fit_order(&[0.2, 0.1], &[4e-2, 1e-2]), 2.0, EXACT);
        assert!(fit_order(&[0.2, 0.1], &[4e-2, 0.0]).is_nan());
    }

    /// A step of 0 is refused as a parameter before any ruling is taken (not as the parallel
    /// rulings it would give).
    #[test]
    fn a_zero_step_is_a_bad_parameter() {
        for h0 in [0.0, -0.0] {
            assert!(matches!(
                convergence_study(&AnalyticSurface::Quartic, 0.3, h0, 5),
                Err(Error::InvalidParameter { name: "h0", .. })
            ));
        }
    }
}
