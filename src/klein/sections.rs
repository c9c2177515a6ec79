//! Sections of the Klein quadric M: a regulus as a conic (the plane that three of its lines span
//! cuts M in it), a linear complex as a hyperplane section (Pottmann & Wallner, *Computational
//! Line Geometry*, §2.1 and §3.1; docs/src/conventions.md, "The Klein quadric").
//!
//! **Regulus.** Three pairwise skew lines L₁, L₂, L₃ of a regulus span a plane π of P⁵ (a
//! 3-dimensional subspace W of R⁶). Restricted to W the Klein form is a 3 × 3 symmetric matrix
//! Q_jk = Ω(b_j, b_k) in an orthonormal basis b of W whose first vector is the first line's point
//! P; the lines of the regulus are the points w ∈ W with wᵀQw = 0: a conic when det Q ≠ 0. The
//! line of π through P in the direction v meets it again in
//!   w(v) = Q(v, v) P − 2 Q(P, v) v,                                                      (K8)
//! and v = cos θ b₁ + sin θ b₂, θ ∈ [0, π), runs once round it. The cone wᵀQw = 0 of R³ has two
//! nappes (a line's two orientations ±L); two of its vectors lie on one nappe exactly when
//! Q(w₁, w₂) det Q ≥ 0 (K9: for the signature (2, 1), det Q < 0 and null vectors of one nappe
//! have Q(w₁, w₂) ≤ 0, as light-like vectors of one time-orientation do; for (1, 2) both signs
//! turn), which picks the nappe of the given orientation. Every other line of the regulus lies in π:
//! its distance from W (the sine of the angle between its 6-vector and W, [`RegulusPlane::distance`])
//! is 0 to rounding.
//!
//! **Linear complex.** A linear complex C = (c, c̄) is the hyperplane Ω(C, L) = 0 of P⁵ (C1 of
//! `linear_complex.rs` is this equation); the lines of a helical surface lie in one, and
//! [`complex_residuals`] reads how far each line's point lies from the hyperplane.

use crate::error::{Error, Result};
use crate::klein::point::{klein_form, KleinPoint};
use crate::tolerance::{COMPLEX_REGULUS_DET, KLEIN_TORSAL, MAX_KLEIN_OUTLINE_SAMPLES};
use glam::DMat3;
use std::f64::consts::PI;

/// A point of P⁵ as a vector of R⁶.
type V6 = [f64; 6];

fn dot(a: &V6, b: &V6) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn axpy(s: f64, x: &V6, y: &V6) -> V6 {
    std::array::from_fn(|k| s * x[k] + y[k])
}

/// The plane of P⁵ that three lines span, and the conic in which it cuts M.
#[derive(Debug, Clone, PartialEq)]
pub struct RegulusPlane {
    /// An orthonormal basis of W ⊂ R⁶ (Gram–Schmidt on the three lines' coordinates): the
    /// first is the first line's direction in R⁶.
    basis: [V6; 3],
}

impl RegulusPlane {
    /// The plane spanned by `lines` (their 6-vectors); an error when they are dependent (within
    /// [`COMPLEX_REGULUS_DET`] of the sine of an angle: two of them the same line, or the three in
    /// a pencil).
    pub fn through(lines: [&KleinPoint; 3]) -> Result<Self> {
        let mut basis = [[0.0; 6]; 3];
        for (k, l) in lines.iter().enumerate() {
            let v = l.to_array();
            let mut w = v;
            for b in &basis[..k] {
                w = axpy(-dot(b, &w), b, &w);
            }
            let n = dot(&w, &w).sqrt();
            if n.is_nan() || n <= COMPLEX_REGULUS_DET * dot(&v, &v).sqrt() {
                return Err(Error::degenerate(
                    "lines",
                    "the three lines span no plane of P⁵ (two are one line, or the three lie in a pencil)",
                ));
            }
            basis[k] = w.map(|x| x / n);
        }
        Ok(RegulusPlane { basis })
    }

    /// The distance of `line`'s point from the plane: |v − P v|/|v| for its 6-vector v (the sine
    /// of the angle between v and W); 0 for the lines of the regulus, NaN for the zero vector.
    pub fn distance(&self, line: &KleinPoint) -> f64 {
        let v = line.to_array();
        let mut w = v;
        for b in &self.basis {
            w = axpy(-dot(b, &w), b, &w);
        }
        (dot(&w, &w) / dot(&v, &v)).sqrt()
    }

    /// `samples` points of the conic π ∩ M (K8), on the branch of the first line, in order round
    /// it; an error when π does not cut M in a conic (the Klein form degenerate on π: the lines
    /// meet pairwise, a pencil's plane lies on M) or `samples` is below 3 or above
    /// [`MAX_KLEIN_OUTLINE_SAMPLES`].
    pub fn conic(&self, samples: usize) -> Result<Vec<KleinPoint>> {
        if !(3..=MAX_KLEIN_OUTLINE_SAMPLES).contains(&samples) {
            return Err(Error::parameter("samples", format!("from 3 to {MAX_KLEIN_OUTLINE_SAMPLES} points")));
        }
        let b = self.basis.map(KleinPoint::from_array);
        let q = |j: usize, k: usize| klein_form(&b[j], &b[k]);
        // Q in the basis; the first basis vector P is the first line's point, on M (Q₀₀ = 0)
        let det =
            DMat3::from_cols_array(&[q(0, 0), q(0, 1), q(0, 2), q(1, 0), q(1, 1), q(1, 2), q(2, 0), q(2, 1), q(2, 2)])
                .determinant();
        let scale = (0..3).flat_map(|j| (0..3).map(move |k| (j, k))).fold(0.0f64, |m, (j, k)| m.max(q(j, k).abs()));
        if det.is_nan() || scale <= KLEIN_TORSAL || det.abs() <= COMPLEX_REGULUS_DET * scale.powi(3) {
            return Err(Error::degenerate(
                "lines",
                "the plane of the three lines cuts the Klein quadric in no conic (the lines meet pairwise)",
            ));
        }
        // the second point on the conic of the line through P in the direction v = cos θ b₁ + sin θ b₂:
        // w = Q(v, v) P − 2 Q(P, v) v (K8); θ ∈ [0, π) runs once round the conic
        let mut out: Vec<[f64; 3]> = (0..samples)
            .map(|i| {
                let (s, c) = (PI * i as f64 / samples as f64).sin_cos();
                let qvv = c * c * q(1, 1) + 2.0 * s * c * q(1, 2) + s * s * q(2, 2);
                let qpv = c * q(0, 1) + s * q(0, 2);
                [qvv, -2.0 * qpv * c, -2.0 * qpv * s]
            })
            .collect();
        // one nappe of the cone over the conic: the one of P, where Q(w, P) det Q ≥ 0 (K9)
        let qp = |w: &[f64; 3]| w[1] * q(0, 1) + w[2] * q(0, 2);
        let far = out.iter().max_by(|a, b| qp(a).abs().total_cmp(&qp(b).abs())).copied().unwrap_or_default();
        if qp(&far) * det < 0.0 {
            out.iter_mut().for_each(|w| *w = w.map(|x| -x));
        }
        Ok(out
            .iter()
            .map(|w| {
                let v: V6 = std::array::from_fn(|k| {
                    w[0] * self.basis[0][k] + w[1] * self.basis[1][k] + w[2] * self.basis[2][k]
                });
                KleinPoint::from_array(v)
            })
            .collect())
    }
}

/// Ω(C, L) for each line L (unit direction) and the linear complex C = (c, c̄) (`plucker` as
/// [`crate::LinearComplex::plucker`]): how far each line's point lies from the
/// complex's hyperplane, a length when |c| = 1.
pub fn complex_residuals(plucker: [f64; 6], lines: &[KleinPoint]) -> Vec<f64> {
    let c = KleinPoint::from_array(plucker);
    lines.iter().map(|l| klein_form(&c, l)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalogue::AnalyticSurface;
    use crate::klein::polygon::KleinPolygon;
    use crate::line::{Line, Segment};
    use crate::linear_complex::fit_linear_complex;
    use crate::ruled::smooth::SmoothRuled;
    use glam::DVec3;

    /// The hyperboloid's rulings are one regulus: three span a plane holding all the others,
    /// and the conic (K8) lies on M and passes through them.
    #[test]
    fn a_regulus_is_a_conic() {
        let s = AnalyticSurface::by_name("hyperboloid").unwrap();
        let k = KleinPolygon::of(&s.sample(30, s.ranges()).unwrap(), true);
        let plane = RegulusPlane::through([&k.points[0], &k.points[10], &k.points[20]]).unwrap();
        for p in &k.points {
            assert!(plane.distance(p) < 1e-14, "{}", plane.distance(p));
        }
        let conic = plane.conic(400).unwrap();
        for w in &conic {
            assert!(klein_form(w, w).abs() < 1e-13 * (w.d.length_squared() + w.m.length_squared()));
            assert!(plane.distance(w) < 1e-14);
        }
        // each ruling is (a positive multiple of) a point of the conic: near one of the samples
        let unit = |p: &KleinPoint| {
            let v = p.to_array();
            let n = dot(&v, &v).sqrt();
            v.map(|x| x / n)
        };
        for p in &k.points {
            let nearest = conic
                .iter()
                .map(|w| {
                    let (a, b) = (unit(w), unit(p));
                    (0..6).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>().sqrt()
                })
                .fold(f64::INFINITY, f64::min);
            assert!(nearest < 0.02, "{nearest}");
        }
        // a line of the other regulus (through the point (1, 0, 0), direction (0, 2, −3)) is not in the plane
        let other = KleinPoint::of_line(&Line { point: DVec3::X, dir: DVec3::new(0.0, 2.0, -3.0).normalize() });
        assert!(plane.distance(&other) > 0.1);
    }

    /// Three lines of a pencil span a plane lying on M: no conic. Two equal lines span no plane.
    #[test]
    fn a_pencil_spans_no_conic() {
        let l = |d: DVec3| KleinPoint::of_line(&Line { point: DVec3::new(1.0, 2.0, 3.0), dir: d.normalize() });
        let (a, b) = (l(DVec3::X), l(DVec3::Y));
        let c = l(DVec3::new(1.0, 1.0, 0.0));
        let plane = RegulusPlane::through([&a, &b, &l(DVec3::Z)]).unwrap();
        assert!(plane.conic(16).is_err());
        assert!(RegulusPlane::through([&a, &b, &c]).is_err());
        assert!(RegulusPlane::through([&a, &a, &b]).is_err());
    }

    /// The helicoid's rulings lie in linear complexes (they meet the axis at right angles): the
    /// fitted complex's hyperplane holds their points.
    #[test]
    fn the_helicoid_lies_in_a_hyperplane() {
        let segs: Vec<Segment> = (0..30)
            .map(|i| {
                let u = 0.3 * i as f64;
                let a = DVec3::new(0.0, 0.0, 0.5 * u);
                Segment::new(a, a + DVec3::new(u.cos(), u.sin(), 0.0))
            })
            .collect();
        let fit = fit_linear_complex(&segs, None);
        let points: Vec<KleinPoint> = segs.iter().map(KleinPoint::of_segment).collect();
        let r = complex_residuals(fit.plucker, &points);
        assert!(r.iter().all(|x| x.abs() < 1e-10), "{r:?}");
    }

    /// Three rulings of the catalogue's elliptic cone (the first, middle and last of 24 round
    /// it, as the Klein scene takes them) meet pairwise at its apex: their plane lies on M, the
    /// Klein form vanishes on it but for rounding (not exactly, as with integer coordinates),
    /// and it holds no conic; the other rulings lie in it all the same. (The determinant of
    /// rounding noise, measured against the noise itself, had passed for a conic, drawn.)
    #[test]
    fn a_cone_spans_a_plane_on_m_and_no_conic() {
        let apex = DVec3::new(0.5, -0.2, 1.0);
        let ruling = |u: f64| {
            let d = DVec3::new(2.0 * u.cos(), u.sin(), 1.0);
            KleinPoint::of_segment(&Segment::new(apex + 0.2 * d, apex + 1.2 * d))
        };
        let plane = RegulusPlane::through([&ruling(0.0), &ruling(PI), &ruling(23.0 * PI / 12.0)]).unwrap();
        assert!(plane.conic(64).is_err());
        for k in 0..24 {
            assert!(plane.distance(&ruling(0.27 * k as f64)) < 1e-14);
        }
    }

    /// The distance is the sine of the angle between a 6-vector and the plane's subspace W:
    /// 2b₀ + 3u with u a unit vector orthogonal to W lies 3/√13 off it, whatever its length.
    #[test]
    fn the_distance_is_the_sine_of_the_angle_to_the_plane() {
        let l = |p: DVec3, d: DVec3| KleinPoint::of_line(&Line { point: p, dir: d.normalize() });
        let plane = RegulusPlane::through([
            &l(DVec3::new(0.3, 1.0, -0.2), DVec3::new(1.0, 0.2, 0.5)),
            &l(DVec3::new(-1.0, 0.4, 0.9), DVec3::new(0.1, 1.0, -0.3)),
            &l(DVec3::new(0.2, -0.7, 1.1), DVec3::new(-0.4, 0.3, 1.0)),
        ])
        .unwrap();
        let mut u = [0.3, -1.2, 0.5, 0.8, 0.1, -0.6];
        for b in &plane.basis {
            u = axpy(-dot(b, &u), b, &u);
        }
        let n = dot(&u, &u).sqrt();
        let u = u.map(|x| x / n);
        for scale in [1.0, 1e-3, 250.0] {
            let v: V6 = std::array::from_fn(|k| scale * (2.0 * plane.basis[0][k] + 3.0 * u[k]));
            let d = plane.distance(&KleinPoint::from_array(v));
            assert!((d - 3.0 / 13f64.sqrt()).abs() < 1e-14, "{scale}: {d}");
        }
        assert!(plane.distance(&KleinPoint::from_array(u)) > 1.0 - 1e-15);
    }

    /// The conic is on the nappe of the first line's orientation, whichever way the rulings run
    /// and whichever three are taken: every ruling is near a positive multiple of a sample.
    #[test]
    fn the_conic_keeps_the_rulings_orientation() {
        let unit = |v: V6| {
            let n = dot(&v, &v).sqrt();
            v.map(|x| x / n)
        };
        for name in ["hyperboloid", "hyperbolic-paraboloid"] {
            let s = AnalyticSurface::by_name(name).unwrap();
            let k = KleinPolygon::of(&s.sample(24, s.ranges()).unwrap(), false);
            for reversed in [false, true] {
                let points: Vec<KleinPoint> = k
                    .points
                    .iter()
                    .map(|p| if reversed { KleinPoint::from_array(p.to_array().map(|x| -x)) } else { *p })
                    .collect();
                for [i, j, l] in [[0, 11, 23], [3, 17, 8], [20, 2, 12]] {
                    let plane = RegulusPlane::through([&points[i], &points[j], &points[l]]).unwrap();
                    let conic = plane.conic(600).unwrap();
                    for p in &points {
                        let b = unit(p.to_array());
                        let nearest = conic.iter().map(|w| dot(&unit(w.to_array()), &b)).fold(f64::MIN, f64::max);
                        assert!(nearest > 0.999, "{name} {reversed} {i} {j} {l}: {nearest}");
                    }
                }
            }
        }
    }

    /// Three rulings close together (a tenth of a radian apart) still span a regulus's plane:
    /// the Klein form on it is small, and the test of its determinant is relative to that.
    #[test]
    fn three_close_rulings_still_give_the_conic() {
        let s = AnalyticSurface::by_name("hyperboloid").unwrap();
        let k = KleinPolygon::of(&s.sample(200, s.ranges()).unwrap(), true);
        let plane = RegulusPlane::through([&k.points[0], &k.points[3], &k.points[6]]).unwrap();
        assert!(plane.conic(64).is_ok());
        assert!(k.points.iter().all(|p| plane.distance(p) < 1e-9));
        // three pairwise skew lines 10⁻³ apart (x-axis; along y at height ε; along z through
        // (ε, ε, 0)): the Klein form on their plane is about ε, its determinant ε³, and they
        // span a regulus all the same, whose conic passes through each of them (up to its
        // orientation: lines given at random need not run as one regulus runs)
        let eps = 1e-3;
        let l = |at: DVec3, d: DVec3| KleinPoint::of_line(&Line { point: at, dir: d });
        let three =
            [l(DVec3::ZERO, DVec3::X), l(DVec3::new(0.0, 0.0, eps), DVec3::Y), l(DVec3::new(eps, eps, 0.0), DVec3::Z)];
        let plane = RegulusPlane::through([&three[0], &three[1], &three[2]]).unwrap();
        let conic = plane.conic(720).unwrap();
        for line in &three {
            let b = line.to_array();
            let nearest = conic
                .iter()
                .map(|w| {
                    let a = w.to_array();
                    dot(&a, &b).abs() / (dot(&a, &a) * dot(&b, &b)).sqrt()
                })
                .fold(f64::MIN, f64::max);
            assert!(nearest > 0.9999, "{nearest}");
        }
    }

    /// Three lines of a pencil far from the origin (|m| about 10³), the third moved 10⁻⁴ out of
    /// the pencil's plane: dependent within 10⁻⁶ of the length of its 6-vector, so no plane.
    #[test]
    fn nearly_dependent_lines_far_away_span_no_plane() {
        let p = DVec3::new(1000.0, 0.0, 0.0);
        let l = |at: DVec3, d: DVec3| KleinPoint::of_line(&Line { point: at, dir: d.normalize() });
        let (a, b) = (l(p, DVec3::Y), l(p, DVec3::new(0.0, 1.0, 1.0)));
        let c = l(p + DVec3::new(1e-4, 0.0, 0.0), DVec3::new(0.0, 1.0, -1.0));
        assert!(RegulusPlane::through([&a, &b, &c]).is_err());
        // (50 out of the plane is not: its 6-vector leaves the span by 5·10⁻⁵ of its length)
        let c = l(p + DVec3::new(50.0, 0.0, 0.0), DVec3::new(0.0, 1.0, -1.0));
        assert!(RegulusPlane::through([&a, &b, &c]).is_ok());
    }

    /// Ω(C, L) line by line: the complex C = (ẑ, 0) holds the lines meeting the z-axis; a line
    /// through (1, 0, 0) along y is its unit moment's z, 1, off it; one through the origin, 0.
    #[test]
    fn complex_residuals_line_by_line() {
        let l = |at: DVec3, d: DVec3| KleinPoint::of_line(&Line { point: at, dir: d });
        let r = complex_residuals([0.0, 0.0, 1.0, 0.0, 0.0, 0.0], &[l(DVec3::X, DVec3::Y), l(DVec3::ZERO, DVec3::X)]);
        assert_eq!(r, vec![1.0, 0.0]);
        let r = complex_residuals([0.0, 0.0, 0.0, 0.0, 0.0, 2.0], &[l(DVec3::X, DVec3::Z)]);
        assert_eq!(r, vec![2.0]);
    }
}
