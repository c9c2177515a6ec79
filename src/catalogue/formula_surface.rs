//! A ruled surface typed as formulas: x(u, v) = a(u) + v·e(u), each of the six coordinate
//! functions a[0..3], e[0..3] a [`Formula`] in u and the named parameters a, b, c.
//!
//! The exact invariants of Section 2 need a′ and e′: they come from evaluating the formulas on
//! dual numbers (forward-mode automatic differentiation), so the exact striction curve s(u),
//! distribution parameter δ(u) and central tangent (4) of a formula surface are as exact as
//! those of the built-in surfaces. When made, the surface is probed at
//! [`FORMULA_PROBES`] parameters: every value and derivative must be finite and e(u) must not
//! vanish there, so a division by zero or a degenerate direction is refused with a message
//! naming the formula and the parameter, never drawn as NaN.

use crate::base::{check_interval, Jet, Ranges};
use crate::error::{Error, Result};
use crate::formula::dual::Dual;
use crate::formula::{Formula, PARAMETERS};
use crate::tolerance::{FORMULA_PROBES, FORMULA_ZERO_DIRECTION, MAX_COORD};
use glam::DVec3;

/// What a formula surface is made from (texts as typed; numbers already evaluated).
#[derive(Debug, Clone, PartialEq)]
pub struct FormulaSpec {
    /// a(u): x, y, z.
    pub a: [String; 3],
    /// e(u): x, y, z (the ruling direction; need not be unit).
    pub e: [String; 3],
    /// Parameter interval of the rulings.
    pub u: (f64, f64),
    /// Interval of v: segments run from a + v₀e to a + v₁e.
    pub v: (f64, f64),
    /// Whether u wraps around (the surface is closed in u).
    pub closed: bool,
    /// Values of the named parameters a, b, c.
    pub parameters: [f64; 3],
}

/// A checked formula surface.
#[derive(Debug, Clone, PartialEq)]
pub struct FormulaSurface {
    a: [Formula; 3],
    e: [Formula; 3],
    ranges: Ranges,
    parameters: [f64; 3],
}

/// Checks the named parameters' values.
pub(crate) fn check_parameters(values: &[f64; 3]) -> Result<()> {
    for (name, &x) in PARAMETERS.iter().zip(values) {
        if !x.is_finite() || x.abs() > MAX_COORD {
            return Err(Error::parameter("parameters", crate::msg!("parameter-not-finite", name = *name, value = x)));
        }
    }
    Ok(())
}

/// Parses the three coordinate formulas of a vector field called `field`.
pub(crate) fn parse_vector(field: &str, texts: &[String; 3], variables: &[&str]) -> Result<[Formula; 3]> {
    let parse = |k: usize| Formula::parse(&format!("{field}[{k}]"), &texts[k], variables);
    Ok([parse(0)?, parse(1)?, parse(2)?])
}

impl FormulaSurface {
    /// The variables of a surface's formulas, in evaluation order.
    pub const VARIABLES: [&'static str; 4] = ["u", PARAMETERS[0], PARAMETERS[1], PARAMETERS[2]];

    /// Parses, checks the ranges and probes the surface (see the module documentation).
    pub fn new(spec: &FormulaSpec) -> Result<Self> {
        check_interval("u", spec.u, false)?;
        check_interval("v", spec.v, true)?;
        check_parameters(&spec.parameters)?;
        let surface = FormulaSurface {
            a: parse_vector("a", &spec.a, &Self::VARIABLES)?,
            e: parse_vector("e", &spec.e, &Self::VARIABLES)?,
            ranges: Ranges { u: spec.u, v: spec.v, closed: spec.closed },
            parameters: spec.parameters,
        };
        let (u0, u1) = spec.u;
        let mut largest = 0.0f64;
        let mut jets = Vec::with_capacity(FORMULA_PROBES);
        for k in 0..FORMULA_PROBES {
            let u = u0 + (u1 - u0) * k as f64 / (FORMULA_PROBES - 1) as f64;
            let jet = surface.checked_jet(u)?;
            largest = largest.max(jet.d.length());
            jets.push((u, jet));
        }
        for (u, jet) in jets {
            if jet.d.length() <= FORMULA_ZERO_DIRECTION * largest {
                return Err(vanishing(u));
            }
        }
        Ok(surface)
    }

    /// The texts it was made from.
    pub fn spec(&self) -> FormulaSpec {
        let texts = |f: &[Formula; 3]| [f[0].text().to_string(), f[1].text().to_string(), f[2].text().to_string()];
        FormulaSpec {
            a: texts(&self.a),
            e: texts(&self.e),
            u: self.ranges.u,
            v: self.ranges.v,
            closed: self.ranges.closed,
            parameters: self.parameters,
        }
    }

    /// Its parameter ranges.
    pub fn ranges(&self) -> Ranges {
        self.ranges
    }

    /// a(u), a′(u), e(u), e′(u), with NaN where a formula is undefined.
    pub fn jet(&self, u: f64) -> Jet {
        let mut stack = Vec::new();
        let [pa, pb, pc] = self.parameters;
        let vars = [Dual::u(u), Dual::constant(pa), Dual::constant(pb), Dual::constant(pc)];
        let mut eval = |f: &[Formula; 3]| {
            let x = [f[0].eval(&vars, &mut stack), f[1].eval(&vars, &mut stack), f[2].eval(&vars, &mut stack)];
            (DVec3::new(x[0].re, x[1].re, x[2].re), DVec3::new(x[0].du, x[1].du, x[2].du))
        };
        let (a, da) = eval(&self.a);
        let (d, dd) = eval(&self.e);
        Jet { a, da, d, dd }
    }

    /// [`FormulaSurface::jet`], refused where a value or derivative is not finite or e(u) = 0.
    pub fn checked_jet(&self, u: f64) -> Result<Jet> {
        let jet = self.jet(u);
        for (field, value, slope) in [("a", jet.a, jet.da), ("e", jet.d, jet.dd)] {
            for k in 0..3 {
                if !value[k].is_finite() || value[k].abs() > MAX_COORD {
                    return Err(Error::NotFiniteAt {
                        what: format!("{field}[{k}]"),
                        u: six(u),
                        v: None,
                        value: value[k],
                        derivative: false,
                    });
                }
                if !slope[k].is_finite() {
                    return Err(Error::NotFiniteAt {
                        what: format!("{field}[{k}]"),
                        u: six(u),
                        v: None,
                        value: slope[k],
                        derivative: true,
                    });
                }
            }
        }
        if jet.d == DVec3::ZERO {
            return Err(vanishing(u));
        }
        Ok(jet)
    }
}

fn vanishing(u: f64) -> Error {
    Error::degenerate("e", crate::msg!("direction-vanishes-u", u = six(u)))
}

/// A parameter value for messages, rounded to 6 decimals (as [`short`] writes it).
pub(crate) fn six(x: f64) -> f64 {
    short(x).parse().unwrap_or(x)
}

/// A parameter value for messages: 6 decimals, without trailing zeros (and no "-0").
pub(crate) fn short(x: f64) -> String {
    let s = format!("{x:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.into()
    }
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

    fn spec(a: [&str; 3], e: [&str; 3], u: (f64, f64)) -> FormulaSpec {
        FormulaSpec {
            a: a.map(String::from),
            e: e.map(String::from),
            u,
            v: (-1.0, 1.0),
            closed: false,
            parameters: [1.0, 2.0, 3.0],
        }
    }

    /// Example 1's hyperboloid typed as formulas, with the parameters a, b, c as its semi-axes,
    /// has exactly the built-in surface's jet, striction curve and distribution parameter.
    #[test]
    fn formulas_reproduce_the_built_in_hyperboloid() {
        let typed =
            FormulaSurface::new(&spec(["a*cos(u)", "b*sin(u)", "0"], ["-a*sin(u)", "b*cos(u)", "c"], (0.0, 6.0)))
                .unwrap();
        let built = AnalyticSurface::Hyperboloid { a: 1.0, b: 2.0, c: 3.0 };
        let typed = AnalyticSurface::Formula(std::sync::Arc::new(typed));
        for u in [0.1, 0.7, 2.0, 4.5] {
            let (j, k) = (typed.jet(u), built.jet(u));
            assert_near!(j.a, k.a, EXACT);
            assert_near!(j.da, k.da, EXACT);
            assert_near!(j.d, k.d, EXACT);
            assert_near!(j.dd, k.dd, EXACT);
            assert_near!(typed.striction(u).unwrap(), built.striction(u).unwrap(), EXACT);
            assert_near!(typed.distribution(u), built.distribution(u), EXACT);
        }
    }

    #[test]
    fn the_quartic_of_example_3() {
        let typed = FormulaSurface::new(&spec(["1", "u^2/2", "u"], ["u^2", "u", "-1"], (-1.0, 1.0))).unwrap();
        let typed = AnalyticSurface::Formula(std::sync::Arc::new(typed));
        for u in [-0.9, 0.0, 0.4] {
            assert_near!(typed.striction(u).unwrap(), AnalyticSurface::Quartic.striction(u).unwrap(), EXACT);
            assert_near!(typed.distribution(u), AnalyticSurface::Quartic.distribution(u), EXACT);
        }
    }

    #[test]
    fn singular_formulas_are_refused_with_the_place() {
        let e = FormulaSurface::new(&spec(["1/u", "0", "0"], ["0", "0", "1"], (-1.0, 1.0))).unwrap_err();
        assert_eq!(e.code(), "not-finite");
        assert_eq!(
            e.to_string(),
            "a[0] is not finite at u = 0 (value inf: a division by zero, or a function outside its domain?)"
        );
        let e = FormulaSurface::new(&spec(["u", "0", "0"], ["u", "u", "0"], (-1.0, 1.0))).unwrap_err();
        assert_eq!(e.code(), "degenerate");
        assert_eq!(e.to_string(), "e: e(u) vanishes at u = 0, so the ruling there has no direction");
        let e = FormulaSurface::new(&spec(["sqrt(u)", "0", "0"], ["0", "0", "1"], (0.0, 1.0))).unwrap_err();
        assert!(e.to_string().starts_with("a[0]: the derivative is not finite at u = 0"), "{e}");
        let e = FormulaSurface::new(&spec(["u", "sni(u)", "0"], ["0", "0", "1"], (0.0, 1.0))).unwrap_err();
        assert!(e.to_string().starts_with("a[1]: unknown function \"sni\" at column 1"), "{e}");
        assert!(FormulaSurface::new(&spec(["u", "0", "0"], ["0", "0", "1"], (1.0, 1.0))).is_err());
        assert!(FormulaSurface::new(&spec(["u", "0", "0"], ["0", "0", "1"], (0.0, f64::NAN))).is_err());
    }

    #[test]
    fn parameter_values_in_messages_have_six_decimals_at_most() {
        assert_eq!(short(0.1234567), "0.123457");
        assert_eq!((short(2.0), short(-1.5), short(-0.0000001)), ("2".into(), "-1.5".into(), "0".into()));
        assert_eq!(six(0.1234567), 0.123457);
        assert_eq!(six(-2.25), -2.25);
    }

    #[test]
    fn parameters_and_values_beyond_the_coordinate_limit_are_refused() {
        assert!(check_parameters(&[1.0, -MAX_COORD, MAX_COORD]).is_ok());
        for bad in [[f64::NAN, 0.0, 0.0], [0.0, 2.0 * MAX_COORD, 0.0], [0.0, 0.0, f64::NEG_INFINITY]] {
            assert_eq!(check_parameters(&bad).unwrap_err().details().option.as_deref(), Some("parameters"));
        }
        // a(u) = (a·u, 0, 0) with a = 1e149 stays within 1e150 over its range [0, 1], not at u = 20
        let f = FormulaSurface::new(&spec(["a*u", "0", "0"], ["0", "0", "1"], (0.0, 1.0))).unwrap();
        assert!(f.checked_jet(0.5).is_ok());
        let limit = FormulaSurface::new(&spec(["1e150", "-1e150", "0"], ["0", "0", "1"], (0.0, 1.0))).unwrap();
        assert!(limit.checked_jet(0.5).is_ok());
        let big = FormulaSurface::new(&FormulaSpec {
            parameters: [1e149, 0.0, 0.0],
            ..spec(["a*u", "0", "0"], ["0", "0", "1"], (0.0, 1.0))
        });
        let e = big.map(|b| b.checked_jet(20.0).unwrap_err()).unwrap();
        assert_eq!((e.code(), e.details().option.as_deref()), ("not-finite", Some("a[0]")));
    }
}
