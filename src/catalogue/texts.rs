//! Every surface and congruence of the catalogue as formula texts, in the grammar of
//! `crate::formula` with the named parameters a, b, c: the presets of the page's formula scenes
//! ("Your surface", "Your congruence", the focal scene's extra congruences) come from here, so
//! the page and the core cannot disagree. Each closed-form entry's texts equal its jets to
//! rounding, its ranges exactly (tested below and in `tests/formula.rs`); a few entries exist
//! only as formulas (the Möbius strip; the normals of an ellipsoid, the lines meeting two skew
//! lines, an elliptic linear congruence).

use super::{CongruenceSpec, FormulaSpec};
use crate::error::Result;
use crate::formula::{Formula, PARAMETERS};

/// A ruled surface x(u, v) = a(u) + v·e(u) as texts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceTexts {
    /// The entry's name (a name of [`super::AnalyticSurface`] for the closed forms).
    pub name: &'static str,
    /// a(u): x, y, z.
    pub a: [&'static str; 3],
    /// e(u): x, y, z.
    pub e: [&'static str; 3],
    /// The interval of u, its ends as formulas of the parameters.
    pub u: [&'static str; 2],
    /// The interval of v.
    pub v: [&'static str; 2],
    /// Whether u wraps around.
    pub closed: bool,
    /// The values of a, b, c.
    pub parameters: [f64; 3],
}

/// A line congruence p(u, v) + t·e(u, v) as texts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CongruenceTexts {
    /// The entry's name (a name of [`super::AnalyticCongruence`] for the closed forms).
    pub name: &'static str,
    /// p(u, v): x, y, z.
    pub p: [&'static str; 3],
    /// e(u, v): x, y, z.
    pub e: [&'static str; 3],
    /// The interval of u.
    pub u: [&'static str; 2],
    /// The interval of v.
    pub v: [&'static str; 2],
    /// The grid of the entry's figure: rows along u, columns along v.
    pub grid: (usize, usize),
    /// The values of a, b, c.
    pub parameters: [f64; 3],
    /// Segment length along e in the focal scene: long enough to pass the focal points.
    pub reach: f64,
}

/// The surfaces as formulas, in the order of the page's menu.
pub const SURFACES: &[SurfaceTexts] = &[
    SurfaceTexts {
        name: "hyperboloid",
        a: ["a*cos(u)", "b*sin(u)", "0"],
        e: ["-a*sin(u)", "b*cos(u)", "c"],
        u: ["0", "2*pi"],
        v: ["-1", "1"],
        closed: true,
        parameters: [1.0, 2.0, 3.0],
    },
    SurfaceTexts {
        name: "quartic",
        a: ["1", "u^2/2", "u"],
        e: ["u^2", "u", "-1"],
        u: ["-1", "1"],
        v: ["-1", "1"],
        closed: false,
        parameters: [1.0, 1.0, 1.0],
    },
    SurfaceTexts {
        name: "helicoid",
        a: ["0", "0", "a*u"],
        e: ["cos(u)", "sin(u)", "0"],
        u: ["0", "4*pi"],
        v: ["-1", "1"],
        closed: false,
        parameters: [0.5, 1.0, 1.0],
    },
    // a: pitch p, b: slope β of the rulings (π/4), c: radius r
    SurfaceTexts {
        name: "helical",
        a: ["c*cos(u)", "c*sin(u)", "a*u"],
        e: ["-cos(b)*sin(u)", "cos(b)*cos(u)", "sin(b)"],
        u: ["0", "4*pi"],
        v: ["-0.8", "0.8"],
        closed: false,
        parameters: [0.4, std::f64::consts::FRAC_PI_4, 1.0],
    },
    // the rulings orthogonal to the striction helix: tan β = −r/p
    SurfaceTexts {
        name: "helical-orthogonal",
        a: ["c*cos(u)", "c*sin(u)", "a*u"],
        e: ["-cos(b)*sin(u)", "cos(b)*cos(u)", "sin(b)"],
        u: ["0", "4*pi"],
        v: ["-0.8", "0.8"],
        closed: false,
        parameters: [0.4, super::ORTHOGONAL_SLOPE, 1.0],
    },
    SurfaceTexts {
        name: "pluecker-conoid",
        a: ["0", "0", "sin(2*u)"],
        e: ["cos(u)", "sin(u)", "0"],
        u: ["0", "2*pi"],
        v: ["-1", "1"],
        closed: true,
        parameters: [1.0, 1.0, 1.0],
    },
    SurfaceTexts {
        name: "hyperbolic-paraboloid",
        a: ["u", "0", "0"],
        e: ["0", "1", "u"],
        u: ["-1", "1"],
        v: ["-1", "1"],
        closed: false,
        parameters: [1.0, 1.0, 1.0],
    },
    SurfaceTexts {
        name: "cone",
        a: ["0.5", "-0.2", "1"],
        e: ["2*cos(u)", "sin(u)", "1"],
        u: ["0", "2*pi"],
        v: ["0.2", "1.2"],
        closed: true,
        parameters: [1.0, 1.0, 1.0],
    },
    SurfaceTexts {
        name: "cylinder",
        a: ["cos(u)", "a*sin(u)", "0"],
        e: ["0", "0", "1"],
        u: ["0", "2*pi"],
        v: ["-1", "1"],
        closed: true,
        parameters: [0.7, 1.0, 1.0],
    },
    // a: pitch p, c: radius r
    SurfaceTexts {
        name: "helix-tangent",
        a: ["c*cos(u)", "c*sin(u)", "a*u"],
        e: ["-c*sin(u)", "c*cos(u)", "a"],
        u: ["0", "2*pi"],
        v: ["0.1", "1.2"],
        closed: false,
        parameters: [0.3, 1.0, 1.0],
    },
    // only as formulas: a Möbius strip (open in u: its rulings come back reversed)
    SurfaceTexts {
        name: "moebius",
        a: ["cos(u)", "sin(u)", "0"],
        e: ["cos(u/2)*cos(u)", "cos(u/2)*sin(u)", "sin(u/2)"],
        u: ["0", "2*pi"],
        v: ["-0.35", "0.35"],
        closed: false,
        parameters: [1.0, 1.0, 1.0],
    },
];

/// The congruences as formulas, in the order of the page's menus.
pub const CONGRUENCES: &[CongruenceTexts] = &[
    CongruenceTexts {
        name: "example5",
        p: ["u", "v", "sin(2*u + 1.5*v)/2"],
        e: ["u", "v", "sin(u) + 1.3*cos(v)"],
        u: ["-1.1", "1.1"],
        v: ["-1.1", "1.1"],
        grid: (8, 7),
        parameters: [1.0, 1.0, 1.0],
        reach: 1.0,
    },
    CongruenceTexts {
        name: "sphere",
        p: ["cos(v)*cos(u)", "cos(v)*sin(u)", "sin(v)"],
        e: ["cos(v)*cos(u) + 0.3*sin(2*v)", "cos(v)*sin(u) + 0.3*cos(3*u)", "sin(v) + 0.3*u*v"],
        u: ["-0.8", "0.8"],
        v: ["-0.6", "0.6"],
        grid: (6, 6),
        parameters: [1.0, 1.0, 1.0],
        reach: 1.2,
    },
    CongruenceTexts {
        name: "hyperbolic-paraboloid",
        p: ["u", "v", "u*v"],
        e: ["-v + 0.3*cos(2*v)", "-u + 0.3*sin(u)", "1"],
        u: ["-1", "1"],
        v: ["-1", "1"],
        grid: (6, 6),
        parameters: [1.0, 1.0, 1.0],
        reach: 1.5,
    },
    // only as formulas: the normals of an ellipsoid with semi-axes a, b, c
    CongruenceTexts {
        name: "ellipsoid-normals",
        p: ["a*cos(v)*cos(u)", "b*cos(v)*sin(u)", "c*sin(v)"],
        e: ["-cos(v)*cos(u)/a", "-cos(v)*sin(u)/b", "-sin(v)/c"],
        u: ["-1", "1"],
        v: ["-0.7", "0.7"],
        grid: (8, 8),
        parameters: [1.6, 1.2, 0.8],
        reach: 2.2,
    },
    // the lines meeting two skew lines: the x-axis lifted to z = −1, and the line through
    // (0, 0, 1) along (1, a, 0) (p on the first, p + e on the second)
    CongruenceTexts {
        name: "two-lines",
        p: ["u", "0", "-1"],
        e: ["v - u", "a*v", "2"],
        u: ["-1", "1"],
        v: ["-1", "1"],
        grid: (7, 7),
        parameters: [1.0, 1.0, 1.0],
        reach: 1.0,
    },
    // an elliptic linear congruence: no real focal point anywhere
    CongruenceTexts {
        name: "elliptic",
        p: ["u", "v", "0"],
        e: ["-0.7*v", "0.7*u", "1"],
        u: ["-1", "1"],
        v: ["-1", "1"],
        grid: (8, 8),
        parameters: [1.0, 1.0, 1.0],
        reach: 1.5,
    },
];

impl SurfaceTexts {
    /// The formula surface these texts describe (interval ends evaluated with a, b, c).
    pub fn spec(&self) -> Result<FormulaSpec> {
        let owned = |t: [&str; 3]| t.map(str::to_string);
        Ok(FormulaSpec {
            a: owned(self.a),
            e: owned(self.e),
            u: interval("u", self.u, &self.parameters)?,
            v: interval("v", self.v, &self.parameters)?,
            closed: self.closed,
            parameters: self.parameters,
        })
    }
}

impl CongruenceTexts {
    /// The formula congruence these texts describe.
    pub fn spec(&self) -> Result<CongruenceSpec> {
        let owned = |t: [&str; 3]| t.map(str::to_string);
        Ok(CongruenceSpec {
            p: owned(self.p),
            e: owned(self.e),
            u: interval("u", self.u, &self.parameters)?,
            v: interval("v", self.v, &self.parameters)?,
            grid: self.grid,
            parameters: self.parameters,
        })
    }
}

/// An interval whose ends are formulas of a, b, c.
fn interval(name: &str, ends: [&str; 2], parameters: &[f64; 3]) -> Result<(f64, f64)> {
    let end = |k: usize| Formula::parse(&format!("{name}[{k}]"), ends[k], &PARAMETERS).map(|f| f.value(parameters));
    Ok((end(0)?, end(1)?))
}

/// The texts of the surface called `name`.
pub fn surface(name: &str) -> Option<&'static SurfaceTexts> {
    SURFACES.iter().find(|t| t.name == name)
}

/// The texts of the congruence called `name`.
pub fn congruence(name: &str) -> Option<&'static CongruenceTexts> {
    CONGRUENCES.iter().find(|t| t.name == name)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalogue::{AnalyticCongruence, AnalyticSurface};
    use crate::congruence::SmoothCongruence;
    use crate::ruled::SmoothRuled;

    /// |x − y| ≤ 1e-12 · max(1, |x|, |y|) for every coordinate of two vectors.
    fn near(x: glam::DVec3, y: glam::DVec3) -> bool {
        (x - y).abs().max_element() <= 1e-12 * 1f64.max(x.abs().max_element()).max(y.abs().max_element())
    }

    /// Every closed-form surface's formulas evaluate to it: the same jets (to 1e-12) over its
    /// range, and the same range; the formula-only entries exist only here.
    #[test]
    fn each_surface_preset_is_its_analytic_surface() {
        for s in AnalyticSurface::ALL {
            let texts = surface(s.name()).unwrap_or_else(|| panic!("no formulas for {}", s.name()));
            let typed = AnalyticSurface::from_formulas(&texts.spec().unwrap()).unwrap();
            assert_eq!(typed.ranges(), s.ranges(), "{}", s.name());
            let r = s.ranges();
            for k in 0..=20 {
                let u = r.u.0 + (r.u.1 - r.u.0) * k as f64 / 20.0;
                let (a, b) = (SmoothRuled::jet(&s, u), SmoothRuled::jet(&typed, u));
                for (x, y, what) in [(a.a, b.a, "a"), (a.da, b.da, "a′"), (a.d, b.d, "e"), (a.dd, b.dd, "e′")] {
                    assert!(near(x, y), "{} at u = {u}: {what} {x} vs {y}", s.name());
                }
            }
        }
        let only: Vec<&str> =
            SURFACES.iter().map(|t| t.name).filter(|n| AnalyticSurface::ALL.iter().all(|s| s.name() != *n)).collect();
        assert_eq!(only, ["moebius"]);
    }

    /// Every closed-form congruence's formulas evaluate to it, partial derivatives included.
    #[test]
    fn each_congruence_preset_is_its_analytic_congruence() {
        for c in AnalyticCongruence::ALL {
            let texts = congruence(c.name()).unwrap_or_else(|| panic!("no formulas for {}", c.name()));
            let typed = AnalyticCongruence::from_formulas(&texts.spec().unwrap()).unwrap();
            assert_eq!(typed.domain(), c.domain(), "{}", c.name());
            for k in 0..=36 {
                let (u, v) = c.parameters(k / 6, k % 6, 6, 6);
                let (a, b) = (SmoothCongruence::jet(&c, u, v), SmoothCongruence::jet(&typed, u, v));
                for (x, y) in [(a.p, b.p), (a.p_u, b.p_u), (a.p_v, b.p_v), (a.d, b.d), (a.d_u, b.d_u), (a.d_v, b.d_v)] {
                    assert!(near(x, y), "{} at ({u}, {v}): {x} vs {y}", c.name());
                }
            }
        }
    }

    #[test]
    fn names_are_unique() {
        for list in [SURFACES.iter().map(|t| t.name).collect::<Vec<_>>(), CONGRUENCES.iter().map(|t| t.name).collect()]
        {
            for (i, n) in list.iter().enumerate() {
                assert!(!list[..i].contains(n), "{n} twice");
            }
        }
    }
}
