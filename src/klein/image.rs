//! The 3D image of P⁵ the reader steers, and the image of the Klein quadric M in it (the Klein
//! quadric's background; docs/src/guide/klein.md says why this image, docs/src/conventions.md
//! "The Klein quadric" its formulas).
//!
//! **Split.** With a unit of length ℓ, a point L = (d, m) of P⁵ is written as
//!   x = (d + m/ℓ)/s,  y = (d − m/ℓ)/s,  s = √(|d|² + |m/ℓ|²),                            (K4)
//! so that |x|² + |y|² = 2 and |x|² − |y|² = 4 (d·m/ℓ)/s² = 2 Ω(L, L)/(ℓ s²). The Klein form has
//! signature (3, 3), and in x, y it is the difference of two Euclidean products:
//! Ω(L₁, L₂) = (ℓ s₁ s₂/2)(x₁·x₂ − y₁·y₂). On M, |x| = |y| = 1: the lines are the pairs of points
//! of two unit spheres, M = S² × S² (each point of P⁵ taken once up to its sign ±L, the line's two
//! orientations). Two lines meet (or are parallel) exactly when the angle between their x-points
//! equals the angle between their y-points (K6).
//!
//! **Image.** The reader chooses a mixing angle α ∈ [0, π/2] and a turn β of the second sphere
//! about the z-axis, R_β; the image of L is
//!   q = cos α x + sin α R_β y.                                                           (K5)
//! It is a linear map of R⁶ to R³: a line of P⁵ (the chord of two points) is drawn straight, and
//! a chord joining two lines that meet lies on M. α = 0 shows the x-sphere alone, α = π/2 the
//! y-sphere; at α = π/4, β = 0, q = √2 d/s: the direction, drawn nearer the centre the farther
//! the line passes from the origin. Rotations about the origin turn both spheres alike (d and m
//! turn together) and so turn the image at β = 0; translations change m and move the points.
//! The image of M is the solid shell between the spheres of radii |cos α − sin α| and
//! cos α + sin α about the origin: those two spheres are its outline.

use crate::error::{Error, Result};
use crate::klein::point::KleinPoint;
use crate::tolerance::{MAX_KLEIN_OUTLINE_SAMPLES, MAX_KLEIN_UNIT, MIN_KLEIN_UNIT};
use glam::{DQuat, DVec3};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// The reader's choice of the 3D image (K5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Projection {
    /// α ∈ [0, π/2]: 0 the x-sphere, π/2 the y-sphere.
    pub mix: f64,
    /// β, radians: the turn of the y-sphere about the z-axis.
    pub turn: f64,
    /// ℓ > 0: the unit of length that makes m comparable with d in (K4).
    pub unit: f64,
}

impl Projection {
    /// The image of mixing angle `mix` ∈ [0, π/2], turn `turn` (any finite angle) and unit of
    /// length `unit` in [`MIN_KLEIN_UNIT`], [`MAX_KLEIN_UNIT`].
    pub fn new(mix: f64, turn: f64, unit: f64) -> Result<Self> {
        if !(0.0..=FRAC_PI_2).contains(&mix) {
            return Err(Error::parameter("mix", "the mixing angle must lie in [0, π/2]"));
        }
        if !turn.is_finite() {
            return Err(Error::parameter("turn", "the turn must be a finite angle"));
        }
        if !(MIN_KLEIN_UNIT..=MAX_KLEIN_UNIT).contains(&unit) {
            return Err(Error::parameter(
                "unit",
                format!("the unit of length must lie in [{MIN_KLEIN_UNIT:e}, {MAX_KLEIN_UNIT:e}]"),
            ));
        }
        Ok(Projection { mix, turn, unit })
    }

    /// (x, y) of (K4): |x|² + |y|² = 2; |x| = |y| = 1 on M. Zero vectors for the zero 6-vector.
    pub fn split(&self, p: &KleinPoint) -> (DVec3, DVec3) {
        let m = p.m / self.unit;
        let s = (p.d.length_squared() + m.length_squared()).sqrt();
        if s == 0.0 || !s.is_finite() {
            return (DVec3::ZERO, DVec3::ZERO);
        }
        ((p.d + m) / s, (p.d - m) / s)
    }

    /// q = cos α x + sin α R_β y (K5).
    pub fn image(&self, p: &KleinPoint) -> DVec3 {
        let (x, y) = self.split(p);
        let (s, c) = self.mix.sin_cos();
        c * x + s * (DQuat::from_rotation_z(self.turn) * y)
    }

    /// The radii (inner, outer) = (|cos α − sin α|, cos α + sin α) of the shell that is M's image.
    pub fn radii(&self) -> (f64, f64) {
        let (s, c) = self.mix.sin_cos();
        ((c - s).abs(), c + s)
    }

    /// The outline of M's image as closed polylines (the first point repeated at the end): on
    /// the outer sphere `circles` parallels and `circles` half meridians, on the inner sphere
    /// (when its radius is above a thousandth of the outer one) its three great circles in the
    /// coordinate planes; each of `samples` chords. An error when `circles` or `samples` is 0 or
    /// above [`MAX_KLEIN_OUTLINE_SAMPLES`] (or `samples` below 3).
    pub fn outline(&self, circles: usize, samples: usize) -> Result<Vec<Vec<DVec3>>> {
        if circles == 0 || circles > MAX_KLEIN_OUTLINE_SAMPLES {
            return Err(Error::parameter("circles", format!("from 1 to {MAX_KLEIN_OUTLINE_SAMPLES} circles")));
        }
        if !(3..=MAX_KLEIN_OUTLINE_SAMPLES).contains(&samples) {
            return Err(Error::parameter("samples", format!("from 3 to {MAX_KLEIN_OUTLINE_SAMPLES} chords a circle")));
        }
        let (inner, outer) = self.radii();
        let mut out = Vec::new();
        let mut circle = |f: &dyn Fn(f64) -> DVec3, turn: f64| {
            out.push((0..=samples).map(|k| f(turn * k as f64 / samples as f64)).collect());
        };
        for j in 0..circles {
            // parallels at heights strictly between the poles
            let z = -1.0 + 2.0 * (j as f64 + 0.5) / circles as f64;
            let r = (1.0 - z * z).sqrt();
            circle(&|t: f64| outer * DVec3::new(r * t.cos(), r * t.sin(), z), TAU);
            let a = PI * j as f64 / circles as f64;
            let (sa, ca) = a.sin_cos();
            circle(&|t: f64| outer * DVec3::new(t.sin() * ca, t.sin() * sa, t.cos()), PI);
        }
        if inner > 1e-3 * outer {
            circle(&|t: f64| inner * DVec3::new(t.cos(), t.sin(), 0.0), TAU);
            circle(&|t: f64| inner * DVec3::new(t.cos(), 0.0, t.sin()), TAU);
            circle(&|t: f64| inner * DVec3::new(0.0, t.cos(), t.sin()), TAU);
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::klein::point::klein_form;
    use crate::line::Line;
    use crate::tolerance::test::uniform as rand;
    use std::f64::consts::FRAC_PI_4;

    fn random_line(seed: &mut u64) -> KleinPoint {
        let mut r = || 4.0 * rand(seed) - 2.0;
        let dir = DVec3::new(r(), r(), r()).normalize();
        KleinPoint::of_line(&Line { point: DVec3::new(r(), r(), r()), dir })
    }

    /// On M both halves of (K4) are unit vectors; off it their squares differ by 2Ω(L, L)/(ℓ s²),
    /// and Ω(L₁, L₂) = (ℓ s₁ s₂/2)(x₁·x₂ − y₁·y₂).
    #[test]
    fn the_split_puts_lines_on_two_unit_spheres_and_carries_the_klein_form() {
        let mut seed = 7;
        let p = Projection::new(0.3, 0.2, 1.7).unwrap();
        for _ in 0..50 {
            let (a, b) = (random_line(&mut seed), random_line(&mut seed));
            let (xa, ya) = p.split(&a);
            let (xb, yb) = p.split(&b);
            assert!((xa.length() - 1.0).abs() < 1e-15 && (ya.length() - 1.0).abs() < 1e-15);
            let s = |l: &KleinPoint| (l.d.length_squared() + (l.m / 1.7).length_squared()).sqrt();
            let omega = 1.7 * s(&a) * s(&b) / 2.0 * (xa.dot(xb) - ya.dot(yb));
            assert!((omega - klein_form(&a, &b)).abs() < 1e-13, "{omega} {}", klein_form(&a, &b));
        }
        let off = KleinPoint::new(DVec3::X, DVec3::X);
        let (x, y) = Projection::new(0.0, 0.0, 1.0).unwrap().split(&off);
        assert!((x - DVec3::new(2.0f64.sqrt(), 0.0, 0.0)).length() < 1e-15 && y == DVec3::ZERO);
    }

    /// At α = π/4, β = 0 the image is √2 d/s: lines through the origin on the sphere of radius √2.
    #[test]
    fn the_diagonal_image_shows_directions() {
        let p = Projection::new(FRAC_PI_4, 0.0, 1.0).unwrap();
        let l = KleinPoint::of_line(&Line { point: DVec3::ZERO, dir: DVec3::new(0.0, 0.6, 0.8) });
        assert!((p.image(&l) - 2f64.sqrt() * l.d).length() < 1e-15);
        let far = KleinPoint::of_line(&Line { point: DVec3::new(3.0, 0.0, 0.0), dir: DVec3::Z });
        assert!((p.image(&far) - 2f64.sqrt() / 10f64.sqrt() * DVec3::Z).length() < 1e-15);
        // the x-sphere and the y-sphere alone
        assert_eq!(
            Projection::new(0.0, 1.0, 1.0).unwrap().image(&far),
            Projection::new(0.0, 0.0, 1.0).unwrap().split(&far).0
        );
    }

    /// Every point of M is drawn in the shell between the radii, and the outline lies on them.
    #[test]
    fn the_image_of_m_is_the_shell_between_the_outline_spheres() {
        let mut seed = 3;
        for mix in [0.0, 0.2, FRAC_PI_4, 1.3, FRAC_PI_2] {
            let p = Projection::new(mix, 0.7, 0.8).unwrap();
            let (inner, outer) = p.radii();
            for _ in 0..100 {
                let r = p.image(&random_line(&mut seed)).length();
                assert!(r >= inner - 1e-12 && r <= outer + 1e-12, "{mix}: {inner} ≤ {r} ≤ {outer}");
            }
            let o = p.outline(4, 24).unwrap();
            assert!(o.len() >= 8 && o.iter().all(|c| c.len() == 25));
            assert!(o
                .iter()
                .flatten()
                .all(|q| (q.length() - outer).abs() < 1e-12 || (q.length() - inner).abs() < 1e-12));
        }
        let p = Projection::new(0.1, 0.0, 1.0).unwrap();
        assert!(p.outline(0, 24).is_err() && p.outline(4, 2).is_err());
        assert!(p.outline(4, MAX_KLEIN_OUTLINE_SAMPLES + 1).is_err());
        assert!(p.outline(MAX_KLEIN_OUTLINE_SAMPLES + 1, 3).is_err());
        assert_eq!(p.outline(MAX_KLEIN_OUTLINE_SAMPLES, 3).unwrap().len(), 2 * MAX_KLEIN_OUTLINE_SAMPLES + 3);
    }

    #[test]
    fn choices_out_of_range_are_errors() {
        assert!(Projection::new(-0.1, 0.0, 1.0).is_err());
        assert!(Projection::new(2.0, 0.0, 1.0).is_err());
        assert!(Projection::new(0.5, f64::NAN, 1.0).is_err());
        assert!(Projection::new(0.5, 0.0, 0.0).is_err());
        assert!(Projection::new(0.5, 0.0, f64::INFINITY).is_err());
    }

    /// The outline as its doc says, curve by curve: parallel j of the outer sphere at height
    /// outer·(−1 + (2j + 1)/circles), half meridian j from the north pole to the south pole at
    /// azimuth πj/circles, each of `samples` equal chords; the inner sphere's three great circles
    /// in the coordinate planes only while its radius is above a thousandth of the outer one.
    #[test]
    fn the_outline_is_parallels_half_meridians_and_the_inner_great_circles() {
        let (circles, samples) = (5, 12);
        let p = Projection::new(0.3, 0.0, 1.0).unwrap();
        let (inner, outer) = p.radii();
        let o = p.outline(circles, samples).unwrap();
        assert_eq!(o.len(), 2 * circles + 3);
        let near = |a: DVec3, b: DVec3| (a - b).length() < 1e-12;
        for j in 0..circles {
            let (parallel, meridian) = (&o[2 * j], &o[2 * j + 1]);
            let z = outer * (-1.0 + (2.0 * j as f64 + 1.0) / circles as f64);
            let r = (outer * outer - z * z).sqrt();
            for (k, q) in parallel.iter().enumerate() {
                let t = TAU * k as f64 / samples as f64;
                assert!(near(*q, DVec3::new(r * t.cos(), r * t.sin(), z)), "parallel {j}, point {k}: {q}");
            }
            let a = PI * j as f64 / circles as f64;
            for (k, q) in meridian.iter().enumerate() {
                let t = PI * k as f64 / samples as f64;
                let want = outer * DVec3::new(t.sin() * a.cos(), t.sin() * a.sin(), t.cos());
                assert!(near(*q, want), "meridian {j}, point {k}: {q}");
            }
        }
        let planes = [DVec3::Z, DVec3::Y, DVec3::X];
        for (circle, normal) in o[2 * circles..].iter().zip(planes) {
            assert!(near(circle[0], circle[samples]));
            assert!(circle.iter().all(|q| (q.length() - inner).abs() < 1e-12 && q.dot(normal).abs() < 1e-15));
            // equal chords, a turn in all
            let chord = (circle[1] - circle[0]).length();
            assert!((chord - 2.0 * inner * (PI / samples as f64).sin()).abs() < 1e-12);
        }
        // the inner sphere at a thousandth of the outer one, and below it: drawn, then not
        let at = |ratio: f64| {
            // |cos α − sin α| / (cos α + sin α) = ratio at α = π/4 − atan(ratio)
            Projection::new(FRAC_PI_4 - ratio.atan(), 0.0, 1.0).unwrap().outline(1, 3).unwrap().len()
        };
        assert_eq!(at(1.001e-3), 5);
        assert_eq!(at(0.999e-3), 2);
    }

    /// The zero 6-vector and one out of range split into zero vectors, not NaN.
    #[test]
    fn a_zero_or_infinite_point_splits_into_zero_vectors() {
        let p = Projection::new(0.3, 0.0, 1.0).unwrap();
        for d in [DVec3::ZERO, DVec3::new(f64::INFINITY, 0.0, 0.0), DVec3::new(1e300, 1e300, 0.0)] {
            let (x, y) = p.split(&KleinPoint { d, m: DVec3::ZERO });
            assert_eq!((x, y), (DVec3::ZERO, DVec3::ZERO), "{d}");
        }
        let (x, y) = p.split(&KleinPoint { d: DVec3::X, m: DVec3::ZERO });
        assert!(near_unit(x) && near_unit(y));
    }

    fn near_unit(v: DVec3) -> bool {
        (v.length() - 1.0).abs() < 1e-15
    }
}
