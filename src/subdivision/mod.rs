//! Subdivision of polygons and of discrete ruled surfaces (Section 4).
//!
//! Curve schemes act on polygons in 3D, open or closed: [`chaikin`], [`bspline`]
//! (Lane–Riesenfeld), [`bezier`] (de Casteljau) and the interpolatory [`four_point`] scheme.
//! A ruled strip is refined by applying a curve scheme to both boundary polygons a_i and
//! b_i ([`strip`]), or by the variational interpolatory scheme of [`variational`].
//! [`turning`] measures how smooth the refined polygons become (their largest turning angle
//! after each step).
//! Output sizes are computed and checked against [`MAX_RULINGS`] before anything is
//! allocated.

pub mod accuracy;
pub mod bezier;
pub mod bspline;
pub mod chaikin;
pub mod four_point;
pub(crate) mod kernel;
pub mod line_space;
pub mod strip;
pub mod triangulation;
pub mod turning;
pub mod variational;

use crate::error::{Error, Result};
use crate::tolerance::{MAX_BEZIER_POINTS, MAX_BSPLINE_DEGREE, MAX_RULINGS, MAX_SUBDIVISION_STEPS};
use glam::DVec3;
use std::ops::{Add, Mul, Sub};

/// What the linear schemes need of their elements: affine combinations, written `p * w`.
pub trait Affine: Copy + Add<Output = Self> + Sub<Output = Self> + Mul<f64, Output = Self> {}
impl<T: Copy + Add<Output = T> + Sub<Output = T> + Mul<f64, Output = T>> Affine for T {}

/// Two points refined with the same weights: both endpoints of a ruling (a strip is a polygon
/// of pairs), or the real and dual parts of a line.
/// Laid out as two `DVec3`s, so a surface's endpoints a_0, b_0, a_1, … *are* a slice of pairs
/// and a refined polygon of pairs becomes the endpoints of the new surface without a copy.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Pair(pub DVec3, pub DVec3);

impl Add for Pair {
    type Output = Pair;
    fn add(self, o: Pair) -> Pair {
        Pair(self.0 + o.0, self.1 + o.1)
    }
}

impl Sub for Pair {
    type Output = Pair;
    fn sub(self, o: Pair) -> Pair {
        Pair(self.0 - o.0, self.1 - o.1)
    }
}

impl Mul<f64> for Pair {
    type Output = Pair;
    fn mul(self, w: f64) -> Pair {
        Pair(self.0 * w, self.1 * w)
    }
}

pub use strip::{recut, subdivide_strip};
pub use variational::Variant;

/// A subdivision scheme with its parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Scheme {
    /// Chaikin's corner cutting (quadratic B-spline limit).
    Chaikin,
    /// Uniform B-spline subdivision of the given degree (1 … 7).
    BSpline {
        /// Degree d.
        degree: usize,
    },
    /// de Casteljau subdivision of the whole polygon as one Bézier control polygon.
    Bezier,
    /// The four-point scheme (8) with tension w.
    FourPoint {
        /// Tension w (the limit is C¹ at least for 0 < w < (√5 − 1)/8, Dyn, Gregory and Levin 1991).
        w: f64,
    },
    /// Variational interpolatory subdivision of a ruled strip (strips only).
    Variational {
        /// Each segment is divided into n parts (n ≥ 3).
        n: usize,
        /// Coupled (umbrellas at all interior vertices) or literal (new vertices only).
        variant: Variant,
    },
}

impl Scheme {
    /// Checks the parameters.
    pub fn validate(&self) -> Result<()> {
        match *self {
            Scheme::BSpline { degree } if !(1..=MAX_BSPLINE_DEGREE).contains(&degree) => Err(Error::parameter(
                "degree",
                format!("must be an integer from 1 to {}, got {degree}", MAX_BSPLINE_DEGREE),
            )),
            Scheme::FourPoint { w } if !(w.is_finite() && (-0.25..=0.25).contains(&w)) => {
                Err(Error::parameter("w", format!("must be a number in [−1/4, 1/4], got {w}")))
            }
            Scheme::Variational { n, .. } if !(3..=1000).contains(&n) => Err(Error::parameter(
                "n",
                format!("must be an integer from 3 to 1000 (n = 2 leaves the energy singular), got {n}"),
            )),
            _ => Ok(()),
        }
    }

    /// Whether the old points are kept (at even indices).
    pub fn is_interpolatory(&self) -> bool {
        matches!(self, Scheme::FourPoint { .. } | Scheme::Variational { .. })
    }

    /// Points after one step from `n` points; an error if the polygon is too short.
    pub fn output_len(&self, n: usize, closed: bool) -> Result<usize> {
        let min = match (*self, closed) {
            (_, true) => 3,
            (Scheme::BSpline { degree }, false) => degree / 2 + 1,
            (Scheme::Bezier, false) => 2,
            _ => 2,
        };
        if n < min {
            return Err(Error::TooFew { what: "points (rulings) for this scheme", got: n, min });
        }
        if closed && matches!(self, Scheme::Bezier | Scheme::Variational { .. }) {
            return Err(Error::parameter("closed", "this scheme refines open polygons and strips only"));
        }
        Ok(match (*self, closed) {
            (_, true) => 2 * n,
            (Scheme::Chaikin, false) => 2 * n - 2,
            (Scheme::BSpline { degree }, false) => 2 * n - degree,
            _ => 2 * n - 1,
        })
    }

    /// Points after `steps` steps, checked against [`MAX_RULINGS`] before any work.
    pub fn output_len_after(&self, n: usize, closed: bool, steps: usize) -> Result<usize> {
        if *self == Scheme::Bezier && n > MAX_BEZIER_POINTS {
            return Err(Error::TooMany {
                what: "points of one Bézier control polygon (its degree + 1)",
                got: n,
                max: MAX_BEZIER_POINTS,
            });
        }
        let mut len = n;
        for _ in 0..steps {
            len = self.output_len(len, closed)?;
            if len > MAX_RULINGS {
                return Err(Error::TooMany { what: "rulings after subdivision", got: len, max: MAX_RULINGS });
            }
        }
        Ok(len)
    }
}

/// `steps` steps of a curve scheme on a polygon (not [`Scheme::Variational`], which needs a
/// strip: see [`subdivide_strip`]).
pub fn subdivide_polygon(points: &[DVec3], scheme: Scheme, closed: bool, steps: usize) -> Result<Vec<DVec3>> {
    scheme.validate()?;
    check_steps(steps)?;
    if matches!(scheme, Scheme::Variational { .. }) {
        return Err(Error::parameter("scheme", "\"variational\" refines ruled strips, not polygons"));
    }
    scheme.output_len_after(points.len(), closed, steps)?;
    let bezier_degree = points.len() - 1;
    // the first step reads the caller's points where they lie (no copy of the input)
    let mut p = match steps {
        0 => return Ok(points.to_vec()),
        _ => polygon_step(points, scheme, closed, bezier_degree),
    };
    for _ in 1..steps {
        p = polygon_step(&p, scheme, closed, bezier_degree);
    }
    Ok(p)
}

/// Checks the step count.
pub fn check_steps(steps: usize) -> Result<()> {
    if steps > MAX_SUBDIVISION_STEPS {
        return Err(Error::parameter(
            "steps",
            format!("must be an integer from 0 to {MAX_SUBDIVISION_STEPS}, got {steps}"),
        ));
    }
    Ok(())
}

/// One step of a curve scheme (sizes already checked).
pub(crate) fn polygon_step<T: Affine>(p: &[T], scheme: Scheme, closed: bool, bezier_degree: usize) -> Vec<T> {
    match scheme {
        Scheme::Chaikin => chaikin::chaikin(p, closed),
        Scheme::BSpline { degree } => bspline::bspline(p, degree, closed),
        Scheme::Bezier => bezier::de_casteljau(p, bezier_degree),
        Scheme::FourPoint { w } => four_point::four_point(p, w, closed),
        Scheme::Variational { .. } => unreachable!("variational is a strip scheme"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_are_checked_before_work() {
        let p = vec![DVec3::ZERO; 5];
        assert!(subdivide_polygon(&p, Scheme::FourPoint { w: 0.0625 }, false, 30).is_err());
        let err = subdivide_polygon(&p, Scheme::FourPoint { w: 0.0625 }, false, 22).unwrap_err();
        assert!(matches!(err, Error::TooMany { .. }), "{err}");
        assert_eq!(Scheme::Chaikin.output_len_after(5, false, 2).unwrap(), 14);
        assert_eq!(Scheme::BSpline { degree: 3 }.output_len(5, false).unwrap(), 7);
        assert!(Scheme::Bezier.output_len(5, true).is_err());
        assert!(Scheme::Bezier.output_len_after(1002, false, 1).unwrap_err().to_string().contains("Bézier"));
        assert!(Scheme::FourPoint { w: f64::NAN }.validate().is_err());
        assert!(Scheme::BSpline { degree: 0 }.validate().is_err());
        assert!(Scheme::Variational { n: 2, variant: Variant::Coupled }.validate().is_err());
    }

    #[test]
    fn parameters_are_checked_at_both_ends() {
        let ok = |s: Scheme| s.validate().is_ok();
        assert!((1..=MAX_BSPLINE_DEGREE).all(|degree| ok(Scheme::BSpline { degree })));
        assert!(!ok(Scheme::BSpline { degree: MAX_BSPLINE_DEGREE + 1 }));
        for w in [-0.25, 0.0, 0.0625, 0.25] {
            assert!(ok(Scheme::FourPoint { w }), "w = {w}");
        }
        for w in [-0.2501, 0.2501, f64::INFINITY] {
            assert!(!ok(Scheme::FourPoint { w }), "w = {w}");
        }
        for (n, valid) in [(3, true), (1000, true), (1001, false), (0, false)] {
            assert_eq!(ok(Scheme::Variational { n, variant: Variant::Literal }), valid, "n = {n}");
        }
        assert!(ok(Scheme::Chaikin) && ok(Scheme::Bezier));
        let e = Scheme::BSpline { degree: 8 }.validate().unwrap_err();
        assert_eq!((e.code(), e.to_string().contains("from 1 to 7, got 8")), ("invalid-argument", true), "{e}");
    }

    #[test]
    fn interpolatory_schemes_keep_the_old_points() {
        let variational = Scheme::Variational { n: 4, variant: Variant::Coupled };
        assert!(Scheme::FourPoint { w: 0.0625 }.is_interpolatory() && variational.is_interpolatory());
        assert!(![Scheme::Chaikin, Scheme::BSpline { degree: 3 }, Scheme::Bezier].iter().any(Scheme::is_interpolatory));
    }

    /// Points after one step, open and closed, from the fewest each scheme takes.
    #[test]
    fn points_after_one_step() {
        let four = Scheme::FourPoint { w: 0.0625 };
        let variational = Scheme::Variational { n: 4, variant: Variant::Coupled };
        let open = [
            (Scheme::Chaikin, 2, 2),
            (Scheme::Chaikin, 5, 8),
            (Scheme::BSpline { degree: 1 }, 2, 3),
            (Scheme::BSpline { degree: 3 }, 2, 1),
            (Scheme::BSpline { degree: 4 }, 3, 2),
            (Scheme::BSpline { degree: 7 }, 4, 1),
            (Scheme::BSpline { degree: 7 }, 9, 11),
            (Scheme::Bezier, 2, 3),
            (Scheme::Bezier, 5, 9),
            (four, 2, 3),
            (four, 5, 9),
            (variational, 5, 9),
        ];
        for (scheme, n, want) in open {
            assert_eq!(scheme.output_len(n, false).unwrap(), want, "{scheme:?} from {n}");
        }
        for (scheme, n, min) in [
            (Scheme::Chaikin, 1, 2),
            (Scheme::BSpline { degree: 4 }, 2, 3),
            (Scheme::BSpline { degree: 7 }, 3, 4),
            (Scheme::Bezier, 1, 2),
            (four, 1, 2),
        ] {
            assert_eq!(
                scheme.output_len(n, false),
                Err(Error::TooFew { what: "points (rulings) for this scheme", got: n, min })
            );
        }
        for scheme in [Scheme::Chaikin, Scheme::BSpline { degree: 5 }, four] {
            assert_eq!(scheme.output_len(3, true).unwrap(), 6, "{scheme:?}");
            assert_eq!(scheme.output_len(7, true).unwrap(), 14, "{scheme:?}");
            assert!(matches!(scheme.output_len(2, true), Err(Error::TooFew { got: 2, min: 3, .. })));
        }
        for scheme in [Scheme::Bezier, variational] {
            assert!(matches!(scheme.output_len(5, true), Err(Error::InvalidParameter { name: "closed", .. })));
        }
    }

    #[test]
    fn points_after_steps_up_to_the_limits() {
        assert_eq!(Scheme::FourPoint { w: 0.0625 }.output_len_after(5, false, 3).unwrap(), 33);
        assert_eq!(Scheme::Chaikin.output_len_after(5, true, 0).unwrap(), 5);
        // exactly MAX_RULINGS is allowed, one more is not
        assert_eq!(Scheme::Chaikin.output_len_after(MAX_RULINGS / 4, true, 2).unwrap(), MAX_RULINGS);
        assert_eq!(
            Scheme::Bezier.output_len_after(MAX_RULINGS / 2 + 1, false, 1),
            Err(Error::TooMany {
                what: "points of one Bézier control polygon (its degree + 1)",
                got: MAX_RULINGS / 2 + 1,
                max: MAX_BEZIER_POINTS
            })
        );
        assert!(matches!(
            Scheme::FourPoint { w: 0.0 }.output_len_after(MAX_RULINGS / 2 + 1, false, 1),
            Err(Error::TooMany { what: "rulings after subdivision", got, .. }) if got == MAX_RULINGS + 1
        ));
        // the Bézier limit is on its control polygon, not on other schemes' polygons
        assert_eq!(Scheme::Bezier.output_len_after(MAX_BEZIER_POINTS, false, 1).unwrap(), 2 * MAX_BEZIER_POINTS - 1);
        assert_eq!(Scheme::Chaikin.output_len_after(MAX_BEZIER_POINTS + 1, false, 1).unwrap(), 2 * MAX_BEZIER_POINTS);
    }

    #[test]
    fn steps_up_to_the_limit() {
        assert!(check_steps(0).is_ok() && check_steps(MAX_SUBDIVISION_STEPS).is_ok());
        let e = check_steps(MAX_SUBDIVISION_STEPS + 1).unwrap_err();
        assert!(e.to_string().contains("from 0 to 24, got 25"), "{e}");
    }

    /// One de Casteljau step of a quadratic Bézier polygon: the halves' control points.
    #[test]
    fn a_bezier_polygon_of_degree_two() {
        let p = [DVec3::ZERO, DVec3::new(1.0, 2.0, 0.0), DVec3::new(2.0, 0.0, 0.0)];
        let q = subdivide_polygon(&p, Scheme::Bezier, false, 1).unwrap();
        let want = [(0.0, 0.0), (0.5, 1.0), (1.0, 1.0), (1.5, 1.0), (2.0, 0.0)].map(|(x, y)| DVec3::new(x, y, 0.0));
        assert_eq!(q, want);
    }
}
