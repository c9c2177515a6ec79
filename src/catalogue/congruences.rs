//! Analytic line congruences: the congruences of Examples 4 and 5 (Section 5, Figs. 13 and
//! 15) in closed form, and congruences typed as formulas. A line L(u, v) passes through
//! p(u, v) on the director surface d₁ with direction d(u, v); the segment of a grid runs to
//! q = p + d (the paper gives no length: docs/src/conventions.md, choices).
//!
//! - `sphere` (Fig. 13 left): d₁ the unit sphere p = (cos v cos u, cos v sin u, sin v),
//!   d = normal + 0.3 (sin 2v, cos 3u, uv): a generalised offset, not a normal congruence.
//! - `hyperbolic-paraboloid` (Fig. 13 right): d₁: z = xy, p = (u, v, uv),
//!   d = (−v, −u, 1) + 0.3 (cos 2v, sin u, 0).
//! - `example5` (Fig. 15): d₁ = (u, v, ½ sin(2u + 1.5v)), d = (u, v, sin u + 1.3 cos v),
//!   an 8 × 7 grid on [−1.1, 1.1]², K = 6.
//!
//! Every congruence is evaluated on dual numbers ([`Dual`]), so besides p and d it yields their
//! exact partial derivatives p_u, p_v, d_u, d_v ([`CongruenceJet`]), which the focal geometry
//! of a congruence needs.

use super::formula_surface::{check_parameters, parse_vector, six};
use crate::base::{check_interval, CongruenceJet};
use crate::congruence::SmoothCongruence;
use crate::error::{Error, Result};
use crate::formula::dual::Dual;
use crate::formula::{Formula, PARAMETERS};
use crate::tolerance::{CONGRUENCE_FORMULA_PROBES, FORMULA_ZERO_DIRECTION, MAX_COORD};
use glam::DVec3;
use std::sync::Arc;

/// The jet of p and d evaluated on dual numbers (values and both partial derivatives).
fn jet_of(p: [Dual; 3], d: [Dual; 3]) -> CongruenceJet {
    let re = |x: [Dual; 3]| DVec3::new(x[0].re, x[1].re, x[2].re);
    let du = |x: [Dual; 3]| DVec3::new(x[0].du, x[1].du, x[2].du);
    let dv = |x: [Dual; 3]| DVec3::new(x[0].dv, x[1].dv, x[2].dv);
    CongruenceJet { p: re(p), p_u: du(p), p_v: dv(p), d: re(d), d_u: du(d), d_v: dv(d) }
}

/// What a formula congruence is made from.
#[derive(Debug, Clone, PartialEq)]
pub struct CongruenceSpec {
    /// p(u, v): x, y, z.
    pub p: [String; 3],
    /// e(u, v): the line direction, x, y, z.
    pub e: [String; 3],
    /// u interval.
    pub u: (f64, f64),
    /// v interval.
    pub v: (f64, f64),
    /// Values of the named parameters a, b, c.
    pub parameters: [f64; 3],
    /// Default grid size (rows along u, cols along v), each 2 … 1000.
    pub grid: (usize, usize),
}

/// A congruence typed as formulas in u, v and the parameters a, b, c.
#[derive(Debug, Clone, PartialEq)]
pub struct FormulaCongruence {
    p: [Formula; 3],
    e: [Formula; 3],
    spec: CongruenceSpec,
}

impl FormulaCongruence {
    /// The variables of a congruence's formulas, in evaluation order.
    pub const VARIABLES: [&'static str; 5] = ["u", "v", PARAMETERS[0], PARAMETERS[1], PARAMETERS[2]];

    /// Parses, checks and probes (values and derivatives finite, e ≠ 0 on a 33 × 33 grid).
    pub fn new(spec: &CongruenceSpec) -> Result<Self> {
        check_interval("u", spec.u, false)?;
        check_interval("v", spec.v, false)?;
        check_parameters(&spec.parameters)?;
        for (name, n) in [("rows", spec.grid.0), ("cols", spec.grid.1)] {
            if !(2..=1000).contains(&n) {
                return Err(Error::parameter(name, crate::msg!("grid-size", min = 2usize, max = 1000usize, value = n)));
            }
        }
        let c = FormulaCongruence {
            p: parse_vector("p", &spec.p, &Self::VARIABLES)?,
            e: parse_vector("e", &spec.e, &Self::VARIABLES)?,
            spec: spec.clone(),
        };
        let mut largest = 0.0f64;
        let mut probes = Vec::with_capacity(CONGRUENCE_FORMULA_PROBES * CONGRUENCE_FORMULA_PROBES);
        for i in 0..CONGRUENCE_FORMULA_PROBES {
            for j in 0..CONGRUENCE_FORMULA_PROBES {
                let u = spec.u.0 + (spec.u.1 - spec.u.0) * i as f64 / (CONGRUENCE_FORMULA_PROBES - 1) as f64;
                let v = spec.v.0 + (spec.v.1 - spec.v.0) * j as f64 / (CONGRUENCE_FORMULA_PROBES - 1) as f64;
                let jet = c.checked_jet(u, v)?;
                largest = largest.max(jet.d.length());
                probes.push((u, v, jet.d.length()));
            }
        }
        if let Some(&(u, v, _)) = probes.iter().find(|p| p.2 <= FORMULA_ZERO_DIRECTION * largest) {
            return Err(vanishing(u, v));
        }
        Ok(c)
    }

    /// What it was made from.
    pub fn spec(&self) -> &CongruenceSpec {
        &self.spec
    }

    /// p, d and their derivatives (NaN where a formula is undefined).
    pub fn jet(&self, u: f64, v: f64) -> CongruenceJet {
        let [a, b, c] = self.spec.parameters;
        let vars = [Dual::u(u), Dual::v(v), Dual::constant(a), Dual::constant(b), Dual::constant(c)];
        let mut stack = Vec::new();
        let mut eval = |f: &[Formula; 3]| {
            [f[0].eval(&vars, &mut stack), f[1].eval(&vars, &mut stack), f[2].eval(&vars, &mut stack)]
        };
        let p = eval(&self.p);
        let d = eval(&self.e);
        jet_of(p, d)
    }

    /// [`FormulaCongruence::jet`], refused where a value or derivative is not finite or e = 0.
    pub fn checked_jet(&self, u: f64, v: f64) -> Result<CongruenceJet> {
        let jet = self.jet(u, v);
        for (field, value, slopes) in [("p", jet.p, [jet.p_u, jet.p_v]), ("e", jet.d, [jet.d_u, jet.d_v])] {
            for k in 0..3 {
                if !value[k].is_finite() || value[k].abs() > MAX_COORD {
                    return Err(Error::NotFiniteAt {
                        what: format!("{field}[{k}]"),
                        u: six(u),
                        v: Some(six(v)),
                        value: value[k],
                        derivative: false,
                    });
                }
                if let Some(bad) = slopes.iter().map(|s| s[k]).find(|x| !x.is_finite()) {
                    return Err(Error::NotFiniteAt {
                        what: format!("{field}[{k}]"),
                        u: six(u),
                        v: Some(six(v)),
                        value: bad,
                        derivative: true,
                    });
                }
            }
        }
        if jet.d == DVec3::ZERO {
            return Err(vanishing(u, v));
        }
        Ok(jet)
    }
}

fn vanishing(u: f64, v: f64) -> Error {
    Error::degenerate("e", crate::msg!("direction-vanishes-uv", u = six(u), v = six(v)))
}

/// The congruences of the paper's examples, and congruences typed as formulas.
#[derive(Debug, Clone, PartialEq)]
pub enum AnalyticCongruence {
    /// Lines on a part of the unit sphere (Example 4, Fig. 13 left).
    Sphere,
    /// Lines on the hyperbolic paraboloid z = xy (Example 4, Fig. 13 right).
    HyperbolicParaboloid,
    /// Example 5 (Fig. 15).
    Example5,
    /// p(u, v) and e(u, v) typed as formulas.
    Formula(Arc<FormulaCongruence>),
}

impl AnalyticCongruence {
    /// Every built-in congruence.
    pub const ALL: [AnalyticCongruence; 3] = [Self::Sphere, Self::HyperbolicParaboloid, Self::Example5];

    /// A congruence typed as formulas.
    pub fn from_formulas(spec: &CongruenceSpec) -> Result<Self> {
        FormulaCongruence::new(spec).map(|c| Self::Formula(Arc::new(c)))
    }

    /// Machine name.
    pub fn name(&self) -> &'static str {
        match self {
            Self::Sphere => "sphere",
            Self::HyperbolicParaboloid => "hyperbolic-paraboloid",
            Self::Example5 => "example5",
            Self::Formula(_) => "formula",
        }
    }

    /// Human title.
    pub fn title(&self) -> &'static str {
        match self {
            Self::Sphere => "Lines on a sphere (ruledlab's, for Example 4, Fig. 13 left)",
            Self::HyperbolicParaboloid => "Lines on a hyperbolic paraboloid (ruledlab's, for Example 4, Fig. 13 right)",
            Self::Example5 => "Example 5: d₁ = (u, v, ½ sin(2u + 1.5v)) (Fig. 15)",
            Self::Formula(_) => "Your congruence p(u, v) + t·e(u, v)",
        }
    }

    /// The congruence of that name, or an entry of the catalogue that exists only as formulas
    /// ([`super::texts::CONGRUENCES`], e.g. "ellipsoid-normals").
    pub fn by_name(name: &str) -> Result<Self> {
        if let Some(c) = Self::ALL.into_iter().find(|c| c.name() == name) {
            return Ok(c);
        }
        match super::texts::congruence(name) {
            Some(texts) => Self::from_formulas(&texts.spec()?),
            None => {
                let names: Vec<&str> = super::texts::CONGRUENCES.iter().map(|t| t.name).collect();
                Err(Error::parameter("name", format!("unknown congruence \"{name}\"; known: {}", names.join(", "))))
            }
        }
    }

    /// The parameter square of the paper's figure and its grid size.
    pub fn domain(&self) -> ((f64, f64), (f64, f64), usize, usize) {
        match self {
            Self::Sphere => ((-0.8, 0.8), (-0.6, 0.6), 6, 6),
            Self::HyperbolicParaboloid => ((-1.0, 1.0), (-1.0, 1.0), 6, 6),
            Self::Example5 => ((-1.1, 1.1), (-1.1, 1.1), 8, 7),
            Self::Formula(c) => (c.spec.u, c.spec.v, c.spec.grid.0, c.spec.grid.1),
        }
    }

    /// p, d and their partial derivatives at (u, v), exactly.
    pub fn jet(&self, u: f64, v: f64) -> CongruenceJet {
        let (u, v) = (Dual::u(u), Dual::v(v));
        let (p, d) = match self {
            Self::Sphere => {
                let p = [v.cos() * u.cos(), v.cos() * u.sin(), v.sin()];
                (p, [p[0] + 0.3 * (2.0 * v).sin(), p[1] + 0.3 * (3.0 * u).cos(), p[2] + 0.3 * u * v])
            }
            Self::HyperbolicParaboloid => {
                ([u, v, u * v], [-v + 0.3 * (2.0 * v).cos(), -u + 0.3 * u.sin(), Dual::constant(1.0)])
            }
            Self::Example5 => ([u, v, 0.5 * (2.0 * u + 1.5 * v).sin()], [u, v, u.sin() + 1.3 * v.cos()]),
            Self::Formula(c) => return c.jet(u.re, v.re),
        };
        jet_of(p, d)
    }
}

impl SmoothCongruence for AnalyticCongruence {
    fn name(&self) -> &str {
        AnalyticCongruence::name(self)
    }

    fn jet(&self, u: f64, v: f64) -> CongruenceJet {
        AnalyticCongruence::jet(self, u, v)
    }

    fn checked_jet(&self, u: f64, v: f64) -> Result<CongruenceJet> {
        match self {
            Self::Formula(c) => c.checked_jet(u, v),
            _ => Ok(AnalyticCongruence::jet(self, u, v)),
        }
    }

    fn domain(&self) -> ((f64, f64), (f64, f64), usize, usize) {
        AnalyticCongruence::domain(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;
    #[allow(unused_imports)]
    use crate::congruence::SmoothCongruence;
    #[allow(unused_imports)]
    use crate::ruled::SmoothRuled;

    /// The paper gives no formulas for Example 4: its two congruences are ruledlab's, and
    /// their titles say so; Example 5 is the paper's.
    #[test]
    fn titles_say_whose_data_it_is() {
        for c in [AnalyticCongruence::Sphere, AnalyticCongruence::HyperbolicParaboloid] {
            assert!(c.title().contains("ruledlab's, for Example 4, Fig. 13"), "{}", c.title());
        }
        assert!(!AnalyticCongruence::Example5.title().contains("ruledlab's"));
    }

    /// The dual evaluation's derivatives agree with central differences of the values.
    #[test]
    fn jets_are_consistent_derivatives() {
        let h = 1e-6;
        for c in AnalyticCongruence::ALL {
            for (u, v) in [(0.3, -0.2), (-0.5, 0.4)] {
                let j = c.jet(u, v);
                let (pu, du) = (c.line(u + h, v), c.line(u - h, v));
                let (pv, dv) = (c.line(u, v + h), c.line(u, v - h));
                assert_near!((pu.0 - du.0) / (2.0 * h), j.p_u, 1e-8);
                assert_near!((pu.1 - du.1) / (2.0 * h), j.d_u, 1e-8);
                assert_near!((pv.0 - dv.0) / (2.0 * h), j.p_v, 1e-8);
                assert_near!((pv.1 - dv.1) / (2.0 * h), j.d_v, 1e-8);
            }
        }
    }

    fn example5_spec() -> CongruenceSpec {
        CongruenceSpec {
            p: ["u", "v", "sin(2*u + 1.5*v)/2"].map(String::from),
            e: ["u", "v", "sin(u) + 1.3*cos(v)"].map(String::from),
            u: (-1.1, 1.1),
            v: (-1.1, 1.1),
            parameters: [1.0, 1.0, 1.0],
            grid: (8, 7),
        }
    }

    #[test]
    fn example_5_typed_as_formulas_is_example_5() {
        let typed = AnalyticCongruence::from_formulas(&example5_spec()).unwrap();
        for (u, v) in [(0.3, -0.2), (-1.1, 1.1)] {
            let (a, b) = (typed.jet(u, v), AnalyticCongruence::Example5.jet(u, v));
            assert_eq!(a, b);
        }
        assert_eq!(typed.domain(), AnalyticCongruence::Example5.domain());
        assert_eq!(typed.grid(8, 7).unwrap(), AnalyticCongruence::Example5.grid(8, 7).unwrap());
    }

    #[test]
    fn bad_formulas_are_refused() {
        let mut s = example5_spec();
        s.e = ["u", "v", "0"].map(String::from);
        let e = AnalyticCongruence::from_formulas(&s).unwrap_err();
        assert_eq!(e.to_string(), "e: e(u, v) vanishes at (u, v) = (0, 0), so the line there has no direction");
        let mut s = example5_spec();
        s.p[2] = "1/(u - v)".into();
        let e = AnalyticCongruence::from_formulas(&s).unwrap_err();
        assert_eq!(e.code(), "not-finite");
        assert!(e.to_string().starts_with("p[2] is not finite at (u, v) = (-1.1, -1.1)"), "{e}");
        let mut s = example5_spec();
        s.p[0] = "w".into();
        assert!(AnalyticCongruence::from_formulas(&s).unwrap_err().to_string().contains("unknown name \"w\""));
        let mut s = example5_spec();
        s.grid = (1, 5);
        assert!(AnalyticCongruence::from_formulas(&s).is_err());
    }

    /// p, d and their partial derivatives of the three built-in congruences, written out by
    /// hand from the formulas of the module's head (ruledlab's for Example 4, the paper's for
    /// Example 5), at a point where no term vanishes.
    #[test]
    fn built_in_jets_are_the_formulas() {
        let (u, v) = (0.7f64, -0.4f64);
        let (cu, su, cv, sv) = (u.cos(), u.sin(), v.cos(), v.sin());
        let j = AnalyticCongruence::Sphere.jet(u, v);
        let p = DVec3::new(cv * cu, cv * su, sv);
        let (p_u, p_v) = (DVec3::new(-cv * su, cv * cu, 0.0), DVec3::new(-sv * cu, -sv * su, cv));
        assert_near!(j.p, p, 1e-15);
        assert_near!(j.p_u, p_u, 1e-15);
        assert_near!(j.p_v, p_v, 1e-15);
        assert_near!(j.d, p + 0.3 * DVec3::new((2.0 * v).sin(), (3.0 * u).cos(), u * v), 1e-15);
        assert_near!(j.d_u, p_u + 0.3 * DVec3::new(0.0, -3.0 * (3.0 * u).sin(), v), 1e-15);
        assert_near!(j.d_v, p_v + 0.3 * DVec3::new(2.0 * (2.0 * v).cos(), 0.0, u), 1e-15);

        let j = AnalyticCongruence::HyperbolicParaboloid.jet(u, v);
        assert_near!(j.p, DVec3::new(u, v, u * v), 1e-15);
        assert_near!(j.p_u, DVec3::new(1.0, 0.0, v), 1e-15);
        assert_near!(j.p_v, DVec3::new(0.0, 1.0, u), 1e-15);
        assert_near!(j.d, DVec3::new(-v + 0.3 * (2.0 * v).cos(), -u + 0.3 * su, 1.0), 1e-15);
        assert_near!(j.d_u, DVec3::new(0.0, -1.0 + 0.3 * cu, 0.0), 1e-15);
        assert_near!(j.d_v, DVec3::new(-1.0 - 0.6 * (2.0 * v).sin(), 0.0, 0.0), 1e-15);

        let j = AnalyticCongruence::Example5.jet(u, v);
        let w = 2.0 * u + 1.5 * v;
        assert_near!(j.p, DVec3::new(u, v, 0.5 * w.sin()), 1e-15);
        assert_near!(j.p_u, DVec3::new(1.0, 0.0, w.cos()), 1e-15);
        assert_near!(j.p_v, DVec3::new(0.0, 1.0, 0.75 * w.cos()), 1e-15);
        assert_near!(j.d, DVec3::new(u, v, su + 1.3 * cv), 1e-15);
        assert_near!(j.d_u, DVec3::new(1.0, 0.0, cu), 1e-15);
        assert_near!(j.d_v, DVec3::new(0.0, 1.0, -1.3 * sv), 1e-15);

        // the trait gives the same, and the built-ins' checked jets are their jets
        for c in AnalyticCongruence::ALL {
            assert_eq!(SmoothCongruence::jet(&c, u, v), c.jet(u, v));
            assert_eq!(SmoothCongruence::checked_jet(&c, u, v).unwrap(), c.jet(u, v));
        }
    }

    /// Names, titles and domains of every congruence, through the type and the trait; and
    /// `by_name` finds each built-in, a formulas-only catalogue entry, and names the known ones
    /// when it finds none.
    #[test]
    fn names_domains_and_lookup() {
        let typed = AnalyticCongruence::from_formulas(&example5_spec()).unwrap();
        let expected = [
            (AnalyticCongruence::Sphere, "sphere", ((-0.8, 0.8), (-0.6, 0.6), 6, 6)),
            (AnalyticCongruence::HyperbolicParaboloid, "hyperbolic-paraboloid", ((-1.0, 1.0), (-1.0, 1.0), 6, 6)),
            (AnalyticCongruence::Example5, "example5", ((-1.1, 1.1), (-1.1, 1.1), 8, 7)),
            (typed, "formula", ((-1.1, 1.1), (-1.1, 1.1), 8, 7)),
        ];
        for (c, name, domain) in expected {
            assert_eq!(c.name(), name);
            assert_eq!(SmoothCongruence::name(&c), name);
            assert_eq!(c.domain(), domain, "{name}");
            assert_eq!(SmoothCongruence::domain(&c), domain, "{name}");
            assert!(c.title().len() > 20, "{}", c.title());
            if name != "formula" {
                assert_eq!(AnalyticCongruence::by_name(name).unwrap(), c);
            }
        }
        assert_eq!(
            AnalyticCongruence::Formula(Arc::new(FormulaCongruence::new(&example5_spec()).unwrap())).title(),
            "Your congruence p(u, v) + t·e(u, v)"
        );
        let AnalyticCongruence::Formula(normals) = AnalyticCongruence::by_name("ellipsoid-normals").unwrap() else {
            panic!("ellipsoid-normals exists only as formulas")
        };
        assert_eq!(normals.spec(), &crate::catalogue::texts::congruence("ellipsoid-normals").unwrap().spec().unwrap());
        let e = AnalyticCongruence::by_name("torus").unwrap_err();
        assert_eq!(e.code(), "invalid-argument");
        assert!(e.to_string().contains("unknown congruence \"torus\"; known: "), "{e}");
        assert!(e.to_string().contains("ellipsoid-normals"), "{e}");
    }

    /// What `new` and `checked_jet` refuse, each on its own: a NaN value (not infinite: the
    /// check is `not finite or too large`), a value just above the coordinate limit (the
    /// limit itself is allowed), an infinite derivative of a finite value, a direction that
    /// vanishes at a point no probe meets (`checked_jet` takes any point), and one that is tiny
    /// next to the largest;
    /// grids of 2 and 1000 rows or columns are allowed, 1001 is not.
    #[test]
    fn formula_checks_one_by_one() {
        let spec = |p: [&str; 3], e: [&str; 3], u: (f64, f64)| CongruenceSpec {
            p: p.map(String::from),
            e: e.map(String::from),
            u,
            v: (0.1, 1.0),
            parameters: [1.0, 2.0, 3.0],
            grid: (2, 1000),
        };
        let at_limit = FormulaCongruence::new(&spec(["1e150", "v", "0"], ["1", "0", "0"], (0.0, 1.0))).unwrap();
        assert_eq!(at_limit.spec().grid, (2, 1000));
        assert_eq!(at_limit.checked_jet(0.5, 0.5).unwrap().p, DVec3::new(1e150, 0.5, 0.0));
        let refused = |p: [&str; 3], e: [&str; 3], u: (f64, f64)| FormulaCongruence::new(&spec(p, e, u)).unwrap_err();
        let e = refused(["1.0000001e150", "v", "0"], ["1", "0", "0"], (0.0, 1.0));
        assert!(matches!(e, Error::NotFiniteAt { ref what, derivative: false, .. } if what == "p[0]"), "{e:?}");
        let e = refused(["u", "sqrt(u - 2)", "0"], ["1", "0", "0"], (0.0, 1.0));
        assert!(
            matches!(e, Error::NotFiniteAt { ref what, value, derivative: false, .. } if what == "p[1]" && value.is_nan()),
            "{e:?}"
        );
        let e = refused(["u", "v", "0"], ["1", "0", "sqrt(u)"], (0.0, 1.0));
        assert!(
            matches!(e, Error::NotFiniteAt { ref what, u, value, derivative: true, .. } if what == "e[2]" && u == 0.0 && value.is_infinite()),
            "{e:?}"
        );
        // e = (u − 0.3, v, 0) vanishes at (0.3, 0), which no probe meets (v starts at 0.1)
        let between = FormulaCongruence::new(&spec(["u", "v", "0"], ["u - 0.3", "v", "0"], (0.0, 1.0))).unwrap();
        assert_eq!(between.jet(0.3, 0.0).d, DVec3::ZERO);
        let e = between.checked_jet(0.3, 0.0).unwrap_err();
        assert_eq!(e.to_string(), "e: e(u, v) vanishes at (u, v) = (0.3, 0), so the line there has no direction");
        let as_analytic = AnalyticCongruence::Formula(Arc::new(between));
        assert_eq!(SmoothCongruence::checked_jet(&as_analytic, 0.3, 0.0).unwrap_err().to_string(), e.to_string());
        // e⁻⁴⁰ next to e⁴⁰: the direction counts as vanishing at the first probe, u = −1
        let e = refused(["u", "v", "0"], ["exp(40*u)", "0", "0"], (-1.0, 1.0));
        assert_eq!(e.to_string(), "e: e(u, v) vanishes at (u, v) = (-1, 0.1), so the line there has no direction");
        for (grid, name) in [((1001, 5), "rows"), ((5, 1001), "cols"), ((1, 5), "rows")] {
            let mut s = spec(["u", "v", "0"], ["1", "0", "0"], (0.0, 1.0));
            s.grid = grid;
            let e = FormulaCongruence::new(&s).unwrap_err();
            assert!(matches!(e, Error::InvalidParameter { name: n, .. } if n == name), "{e:?}");
        }
    }
}
