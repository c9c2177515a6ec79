//! Analytic ruled surfaces x(u, v) = a(u) + v d(u) (Section 2) in closed form, to test the
//! discrete invariants against and to draw the paper's figures from; their exact striction
//! curve, distribution parameter and central tangent come from their jets
//! ([`crate::ruled::SmoothRuled`]). Several surfaces also have closed forms for s and δ, which
//! the tests check the general formulas against.

use super::formula_surface::{FormulaSpec, FormulaSurface};
use crate::base::{Jet, Ranges};
use crate::error::{Error, Result};
use crate::ruled::SmoothRuled;
use glam::DVec3;
use std::f64::consts::{FRAC_PI_4, TAU};
use std::sync::Arc;

/// The ruled surfaces ruledlab knows in closed form, and surfaces typed as formulas.
#[derive(Debug, Clone, PartialEq)]
pub enum AnalyticSurface {
    /// One regulus of the hyperboloid x²/A² + y²/B² − z²/C² = 1 (Example 1: A=1, B=2, C=3):
    /// a = (A cos u, B sin u, 0), d = (−A sin u, B cos u, C).
    Hyperboloid {
        /// Semi-axis A.
        a: f64,
        /// Semi-axis B.
        b: f64,
        /// C.
        c: f64,
    },
    /// Example 3's quartic surface R(u, v) = (1 + vu², u²/2 + uv, u − v).
    Quartic,
    /// Right helicoid a = (0, 0, pu), d = (cos u, sin u, 0): s = a, δ = p.
    Helicoid {
        /// Pitch p (height per radian).
        pitch: f64,
    },
    /// Ruled helical surface (Fig. 5): a = (r cos u, r sin u, pu),
    /// d = (−cos β sin u, cos β cos u, sin β): s = a, δ = p − r tan β (developable iff 0).
    HelicalRuled {
        /// Radius r of the helix the rulings leave from.
        radius: f64,
        /// Pitch p, the height per radian (z = pu; 2πp per turn).
        pitch: f64,
        /// Slope β of the rulings against the xy-plane.
        slope: f64,
    },
    /// Plücker's conoid a = (0, 0, sin 2u), d = (cos u, sin u, 0): s = a, δ = 2 cos 2u.
    PlueckerConoid,
    /// Hyperbolic paraboloid z = xy: a = (u, 0, 0), d = (0, 1, u): s = a, δ = 1 + u².
    HyperbolicParaboloid,
    /// Elliptic cone with apex (½, −⅕, 1) and d = (2 cos u, sin u, 1): s = apex, δ = 0.
    Cone,
    /// Elliptic cylinder a = (cos u, 0.7 sin u, 0), d = (0, 0, 1): all rulings parallel,
    /// no striction point, δ = 0.
    Cylinder,
    /// Tangent surface of the helix a = (r cos u, r sin u, pu), d = a′: s = a, δ = 0.
    HelixTangent {
        /// Radius r.
        radius: f64,
        /// Pitch p.
        pitch: f64,
    },
    /// a(u) and e(u) typed as formulas ([`FormulaSurface`]), differentiated exactly.
    Formula(Arc<FormulaSurface>),
}

/// β = −atan(r/p) for r = 1, p = 0.4: rulings orthogonal to the striction helix.
pub const ORTHOGONAL_SLOPE: f64 = -1.190_289_949_682_531_7;

impl AnalyticSurface {
    /// Every surface, with the parameters of the paper's examples.
    pub const ALL: [AnalyticSurface; 10] = [
        AnalyticSurface::Hyperboloid { a: 1.0, b: 2.0, c: 3.0 },
        AnalyticSurface::Quartic,
        AnalyticSurface::Helicoid { pitch: 0.5 },
        AnalyticSurface::HelicalRuled { radius: 1.0, pitch: 0.4, slope: FRAC_PI_4 },
        // the helical surface of Fig. 5 with rulings orthogonal to its striction helix
        // (e·ṡ = 0 for tan β = −r/p): the case in which the figure's caption holds
        AnalyticSurface::HelicalRuled { radius: 1.0, pitch: 0.4, slope: ORTHOGONAL_SLOPE },
        AnalyticSurface::PlueckerConoid,
        AnalyticSurface::HyperbolicParaboloid,
        AnalyticSurface::Cone,
        AnalyticSurface::Cylinder,
        AnalyticSurface::HelixTangent { radius: 1.0, pitch: 0.3 },
    ];

    /// Short machine name, as used by the JS API ("hyperboloid", "quartic", …).
    pub fn name(&self) -> &'static str {
        match self {
            AnalyticSurface::Hyperboloid { .. } => "hyperboloid",
            AnalyticSurface::Quartic => "quartic",
            AnalyticSurface::Helicoid { .. } => "helicoid",
            AnalyticSurface::HelicalRuled { slope, .. } if *slope == ORTHOGONAL_SLOPE => "helical-orthogonal",
            AnalyticSurface::HelicalRuled { .. } => "helical",
            AnalyticSurface::PlueckerConoid => "pluecker-conoid",
            AnalyticSurface::HyperbolicParaboloid => "hyperbolic-paraboloid",
            AnalyticSurface::Cone => "cone",
            AnalyticSurface::Cylinder => "cylinder",
            AnalyticSurface::HelixTangent { .. } => "helix-tangent",
            AnalyticSurface::Formula(_) => "formula",
        }
    }

    /// Human title with the formula.
    pub fn title(&self) -> &'static str {
        match self {
            AnalyticSurface::Hyperboloid { .. } => "Hyperboloid x² + y²/4 − z²/9 = 1 (Example 1)",
            AnalyticSurface::Quartic => "Quartic surface (1 + vu², u²/2 + uv, u − v) (Example 3)",
            AnalyticSurface::Helicoid { .. } => "Right helicoid (v cos u, v sin u, u/2)",
            AnalyticSurface::HelicalRuled { slope, .. } if *slope == ORTHOGONAL_SLOPE => {
                "Ruled helical surface, rulings orthogonal to the striction helix (ruledlab's, for Fig. 5)"
            }
            AnalyticSurface::HelicalRuled { slope, .. } if *slope == FRAC_PI_4 => {
                "Ruled helical surface, rulings at 45° (ruledlab's, for Fig. 5)"
            }
            AnalyticSurface::HelicalRuled { .. } => "Ruled helical surface (ruledlab's, for Fig. 5)",
            AnalyticSurface::PlueckerConoid => "Plücker's conoid z = sin 2u",
            AnalyticSurface::HyperbolicParaboloid => "Hyperbolic paraboloid z = xy",
            AnalyticSurface::Cone => "Elliptic cone",
            AnalyticSurface::Cylinder => "Elliptic cylinder",
            AnalyticSurface::HelixTangent { .. } => "Tangent surface of a helix",
            AnalyticSurface::Formula(_) => "Your surface a(u) + v·e(u)",
        }
    }

    /// A surface typed as formulas (see [`FormulaSurface`]).
    pub fn from_formulas(spec: &FormulaSpec) -> Result<Self> {
        FormulaSurface::new(spec).map(|f| AnalyticSurface::Formula(Arc::new(f)))
    }

    /// The surface of that [`name`](AnalyticSurface::name), or an entry of the catalogue that
    /// exists only as formulas ([`super::texts::SURFACES`], e.g. "moebius").
    pub fn by_name(name: &str) -> Result<Self> {
        if let Some(s) = Self::ALL.into_iter().find(|s| s.name() == name) {
            return Ok(s);
        }
        match super::texts::surface(name) {
            Some(texts) => Self::from_formulas(&texts.spec()?),
            None => {
                let names: Vec<&str> = super::texts::SURFACES.iter().map(|t| t.name).collect();
                Err(Error::parameter("name", format!("unknown surface \"{name}\"; known: {}", names.join(", "))))
            }
        }
    }

    /// Default sampling ranges.
    pub fn ranges(&self) -> Ranges {
        let open = |u0, u1, v0, v1| Ranges { u: (u0, u1), v: (v0, v1), closed: false };
        match self {
            AnalyticSurface::Hyperboloid { .. } => Ranges { u: (0.0, TAU), v: (-1.0, 1.0), closed: true },
            AnalyticSurface::Quartic => open(-1.0, 1.0, -1.0, 1.0),
            AnalyticSurface::Helicoid { .. } => open(0.0, 2.0 * TAU, -1.0, 1.0),
            AnalyticSurface::HelicalRuled { .. } => open(0.0, 2.0 * TAU, -0.8, 0.8),
            AnalyticSurface::PlueckerConoid => Ranges { u: (0.0, TAU), v: (-1.0, 1.0), closed: true },
            AnalyticSurface::HyperbolicParaboloid => open(-1.0, 1.0, -1.0, 1.0),
            AnalyticSurface::Cone => Ranges { u: (0.0, TAU), v: (0.2, 1.2), closed: true },
            AnalyticSurface::Cylinder => Ranges { u: (0.0, TAU), v: (-1.0, 1.0), closed: true },
            AnalyticSurface::HelixTangent { .. } => open(0.0, TAU, 0.1, 1.2),
            AnalyticSurface::Formula(f) => f.ranges(),
        }
    }

    /// a(u), a′(u), d(u), d′(u).
    pub fn jet(&self, u: f64) -> Jet {
        let (s, c) = u.sin_cos();
        let v = DVec3::new;
        match *self {
            AnalyticSurface::Formula(ref f) => f.jet(u),
            AnalyticSurface::Hyperboloid { a, b, c: h } => Jet {
                a: v(a * c, b * s, 0.0),
                da: v(-a * s, b * c, 0.0),
                d: v(-a * s, b * c, h),
                dd: v(-a * c, -b * s, 0.0),
            },
            AnalyticSurface::Quartic => {
                Jet { a: v(1.0, u * u / 2.0, u), da: v(0.0, u, 1.0), d: v(u * u, u, -1.0), dd: v(2.0 * u, 1.0, 0.0) }
            }
            AnalyticSurface::Helicoid { pitch } => {
                Jet { a: v(0.0, 0.0, pitch * u), da: v(0.0, 0.0, pitch), d: v(c, s, 0.0), dd: v(-s, c, 0.0) }
            }
            AnalyticSurface::HelicalRuled { radius: r, pitch: p, slope } => {
                let (sb, cb) = slope.sin_cos();
                Jet {
                    a: v(r * c, r * s, p * u),
                    da: v(-r * s, r * c, p),
                    d: v(-cb * s, cb * c, sb),
                    dd: v(-cb * c, -cb * s, 0.0),
                }
            }
            AnalyticSurface::PlueckerConoid => Jet {
                a: v(0.0, 0.0, (2.0 * u).sin()),
                da: v(0.0, 0.0, 2.0 * (2.0 * u).cos()),
                d: v(c, s, 0.0),
                dd: v(-s, c, 0.0),
            },
            AnalyticSurface::HyperbolicParaboloid => {
                Jet { a: v(u, 0.0, 0.0), da: v(1.0, 0.0, 0.0), d: v(0.0, 1.0, u), dd: v(0.0, 0.0, 1.0) }
            }
            AnalyticSurface::Cone => {
                Jet { a: v(0.5, -0.2, 1.0), da: DVec3::ZERO, d: v(2.0 * c, s, 1.0), dd: v(-2.0 * s, c, 0.0) }
            }
            AnalyticSurface::Cylinder => {
                Jet { a: v(c, 0.7 * s, 0.0), da: v(-s, 0.7 * c, 0.0), d: DVec3::Z, dd: DVec3::ZERO }
            }
            AnalyticSurface::HelixTangent { radius: r, pitch: p } => Jet {
                a: v(r * c, r * s, p * u),
                da: v(-r * s, r * c, p),
                d: v(-r * s, r * c, p),
                dd: v(-r * c, -r * s, 0.0),
            },
        }
    }
}

impl SmoothRuled for AnalyticSurface {
    fn name(&self) -> &str {
        AnalyticSurface::name(self)
    }

    fn jet(&self, u: f64) -> Jet {
        AnalyticSurface::jet(self, u)
    }

    fn checked_jet(&self, u: f64) -> Result<Jet> {
        match self {
            AnalyticSurface::Formula(f) => f.checked_jet(u),
            _ => Ok(AnalyticSurface::jet(self, u)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;
    use crate::tolerance::test::EXACT;

    const US: [f64; 5] = [-0.9, -0.3, 0.2, 0.7, 1.3];

    /// The helical surfaces are ruledlab's (the paper gives no data for Fig. 5), and each title
    /// names the slope it has.
    #[test]
    fn helical_titles_say_whose_they_are_and_their_slope() {
        for s in AnalyticSurface::ALL.iter().filter(|s| matches!(s, AnalyticSurface::HelicalRuled { .. })) {
            let AnalyticSurface::HelicalRuled { slope, .. } = s else { unreachable!() };
            assert!(s.title().contains("ruledlab's, for Fig. 5"), "{}", s.title());
            assert_eq!(s.title().contains("45°"), *slope == FRAC_PI_4, "{}", s.title());
            assert_eq!(s.title().contains("orthogonal"), *slope == ORTHOGONAL_SLOPE, "{}", s.title());
        }
        let other = AnalyticSurface::HelicalRuled { radius: 1.0, pitch: 0.4, slope: 0.3 };
        assert!(!other.title().contains("45°") && !other.title().contains("orthogonal"), "{}", other.title());
    }

    /// Central differences of a(u) and d(u) agree with the hand-written derivatives.
    #[test]
    fn jets_are_consistent_derivatives() {
        let h = 1e-5;
        for s in AnalyticSurface::ALL {
            for u in US {
                let (j, jp, jm) = (s.jet(u), s.jet(u + h), s.jet(u - h));
                assert_near!((jp.a - jm.a) / (2.0 * h), j.da, 1e-8);
                assert_near!((jp.d - jm.d) / (2.0 * h), j.dd, 1e-8);
            }
        }
    }

    #[test]
    fn general_formulas_match_closed_forms() {
        for u in US {
            let helicoid = AnalyticSurface::Helicoid { pitch: 0.5 };
            assert_near!(helicoid.striction(u).unwrap(), helicoid.jet(u).a, EXACT);
            assert_near!(helicoid.distribution(u), 0.5, EXACT);

            let helical = AnalyticSurface::HelicalRuled { radius: 1.0, pitch: 0.4, slope: 0.6 };
            assert_near!(helical.striction(u).unwrap(), helical.jet(u).a, EXACT);
            assert_near!(helical.distribution(u), 0.4 - 0.6f64.tan(), EXACT);

            let conoid = AnalyticSurface::PlueckerConoid;
            assert_near!(conoid.striction(u).unwrap(), DVec3::new(0.0, 0.0, (2.0 * u).sin()), EXACT);
            assert_near!(conoid.distribution(u), 2.0 * (2.0 * u).cos(), EXACT);

            let hypar = AnalyticSurface::HyperbolicParaboloid;
            assert_near!(hypar.striction(u).unwrap(), DVec3::new(u, 0.0, 0.0), EXACT);
            assert_near!(hypar.distribution(u), 1.0 + u * u, EXACT);

            assert_near!(AnalyticSurface::Cone.striction(u).unwrap(), DVec3::new(0.5, -0.2, 1.0), EXACT);
            assert_near!(AnalyticSurface::Cone.distribution(u), 0.0, EXACT);

            let tangent = AnalyticSurface::HelixTangent { radius: 1.0, pitch: 0.3 };
            assert_near!(tangent.striction(u).unwrap(), tangent.jet(u).a, EXACT);
            assert_near!(tangent.distribution(u), 0.0, EXACT);

            assert_eq!(AnalyticSurface::Cylinder.striction(u), None);
            assert_eq!(AnalyticSurface::Cylinder.distribution(u), 0.0);
        }
    }

    /// The striction point is where the ruling comes closest to its neighbour: the
    /// distance along R(u) to R(u + h) is stationary there (checked by brute force).
    #[test]
    fn striction_point_minimises_distance_to_neighbouring_rulings() {
        for s in AnalyticSurface::ALL.into_iter().filter(|s| *s != AnalyticSurface::Cylinder) {
            let u = 0.7;
            let sp = s.striction(u).unwrap();
            let l = s.line(u);
            let spread = |p: DVec3| s.line(u + 1e-4).distance_to(p) + s.line(u - 1e-4).distance_to(p);
            let at = spread(sp);
            for dv in [-1e-2, 1e-2] {
                assert!(spread(sp + dv * l.dir) > at, "{}", s.name());
            }
        }
    }

    #[test]
    fn distance_to_the_surface() {
        let hypar = AnalyticSurface::HyperbolicParaboloid;
        // z = xy: the point (0.3, 0.4, 0.12 + 0.05) lies 0.05 above the surface point
        let p = DVec3::new(0.3, 0.4, 0.12 + 0.05);
        let normal = DVec3::new(-0.4, -0.3, 1.0).normalize();
        let d = hypar.distance_to(p, -1.0, 1.0);
        assert!(d <= 0.05 * normal.z + 1e-12 && d > 0.04, "{d}");
        assert!(hypar.distance_to(hypar.point(0.37, -0.8), 0.0, 1.0) < 1e-12);
    }

    #[test]
    fn orthogonal_slope_is_minus_atan_r_over_p() {
        assert_near!(ORTHOGONAL_SLOPE, -(1.0f64 / 0.4).atan(), 1e-16);
        // e·ṡ = 0: the rulings cross the striction helix at right angles
        let s = AnalyticSurface::by_name("helical-orthogonal").unwrap();
        for u in US {
            let j = s.jet(u);
            assert_near!(j.d.normalize().dot(j.da), 0.0, 1e-15);
        }
    }

    #[test]
    fn hyperboloid_rulings_lie_on_the_quadric() {
        let s = AnalyticSurface::ALL[0].clone();
        for u in US {
            for v in [-2.0, 0.5, 3.0] {
                let p = s.point(u, v);
                assert_near!(p.x * p.x + p.y * p.y / 4.0 - p.z * p.z / 9.0, 1.0, EXACT);
            }
        }
    }

    #[test]
    fn sampling_closed_and_open() {
        let hyp = AnalyticSurface::by_name("hyperboloid").unwrap();
        let r = hyp.ranges();
        let s = hyp.sample(8, r).unwrap();
        assert_eq!(s.len(), 8);
        assert_near!(s.segment(0).a, hyp.point(0.0, -1.0), EXACT);
        assert_near!(s.segment(2).b, hyp.point(TAU / 4.0, 1.0), EXACT);
        let q = AnalyticSurface::Quartic.sample(5, AnalyticSurface::Quartic.ranges()).unwrap();
        assert_near!(q.segment(4).a, AnalyticSurface::Quartic.point(1.0, -1.0), EXACT);
        assert!(AnalyticSurface::by_name("klein-bottle").unwrap_err().to_string().contains("hyperboloid"));
        assert!(hyp.sample(1, r).is_err());
        assert!(hyp.sample(usize::MAX, r).is_err());
        assert!(hyp.sample(5, Ranges { v: (1.0, 1.0), ..r }).is_err());
        assert!(hyp.sample(5, Ranges { u: (f64::NAN, 1.0), ..r }).is_err());
    }

    #[test]
    fn as_a_smooth_ruled_surface_each_keeps_its_name_and_a_formula_its_checks() {
        for s in AnalyticSurface::ALL {
            assert_eq!(SmoothRuled::name(&s), s.name());
            assert_eq!(SmoothRuled::checked_jet(&s, 0.2).unwrap(), s.jet(0.2));
        }
        // a pole between the samples the constructor checks: the jet there is refused
        let texts = |t: [&str; 3]| t.map(String::from);
        let spec = FormulaSpec {
            a: texts(["1/(u - 0.1234567)", "0", "0"]),
            e: texts(["0", "0", "1"]),
            u: (0.0, 1.0),
            v: (-1.0, 1.0),
            closed: false,
            parameters: [1.0; 3],
        };
        let f = FormulaSurface::new(&spec).unwrap();
        let s = AnalyticSurface::Formula(std::sync::Arc::new(f));
        assert_eq!(SmoothRuled::name(&s), "formula");
        let e = SmoothRuled::checked_jet(&s, 0.1234567).unwrap_err();
        assert_eq!(e.code(), "not-finite");
    }
}
