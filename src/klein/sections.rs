//! Sections of the Klein quadric M: a regulus as a conic (the plane that three of its lines span
//! cuts M in it), a linear complex as a hyperplane section (Pottmann & Wallner, *Computational
//! Line Geometry*, §2.1 and §3.1; docs/src/conventions.md, "The Klein quadric").
//!
//! **Regulus.** Three pairwise skew lines L₁, L₂, L₃ of a regulus span a plane π of P⁵ (a
//! 3-dimensional subspace W of R⁶). Restricted to W the Klein form is a 3 × 3 symmetric matrix
//! Q_jk = Ω(b_j, b_k) in an orthonormal basis b of W; the lines of the regulus are the points
//! w ∈ W with wᵀQw = 0: a conic, when Q has two eigenvalues of one sign and one of the other,
//!   w(t) = cos t v₁/√|λ₁| + sin t v₂/√|λ₂| ± v₃/√|λ₃|,                                   (K8)
//! (v_k the unit eigenvectors, λ₃ the eigenvalue of the lone sign; the sign of the last term
//! picks the branch of the given lines' orientation). Every other line of the regulus lies in π:
//! its distance from W (the sine of the angle between its 6-vector and W, [`RegulusPlane::distance`])
//! is 0 to rounding.
//!
//! **Linear complex.** A linear complex C = (c, c̄) is the hyperplane Ω(C, L) = 0 of P⁵ (C1 of
//! `linear_complex.rs` is this equation); the lines of a helical surface lie in one, and
//! [`complex_residuals`] reads how far each line's point lies from the hyperplane.

use crate::error::{Error, Result};
use crate::klein::point::{klein_form, KleinPoint};
use crate::tolerance::{COMPLEX_REGULUS_DET, MAX_KLEIN_OUTLINE_SAMPLES};
use nalgebra::{Matrix3, SymmetricEigen, Vector6};
use std::f64::consts::TAU;

fn vec6(p: &KleinPoint) -> Vector6<f64> {
    Vector6::from_row_slice(&p.to_array())
}

fn point6(v: &Vector6<f64>) -> KleinPoint {
    KleinPoint::from_array([v[0], v[1], v[2], v[3], v[4], v[5]])
}

/// The plane of P⁵ that three lines span, and the conic in which it cuts M.
#[derive(Debug, Clone, PartialEq)]
pub struct RegulusPlane {
    /// An orthonormal basis of W ⊂ R⁶ (Gram–Schmidt on the three lines' coordinates).
    basis: [Vector6<f64>; 3],
    /// The first line's coordinates in the basis (which branch of the conic it is on).
    first: [f64; 3],
}

impl RegulusPlane {
    /// The plane spanned by `lines` (their 6-vectors); an error when they are dependent (within
    /// [`COMPLEX_REGULUS_DET`] of the sine of an angle: two of them the same line, or the three in
    /// a pencil).
    pub fn through(lines: [&KleinPoint; 3]) -> Result<Self> {
        let mut basis = [Vector6::zeros(); 3];
        for (k, l) in lines.iter().enumerate() {
            let v = vec6(l);
            let mut w = v;
            for b in &basis[..k] {
                w -= b * b.dot(&w);
            }
            let n = w.norm();
            if n.is_nan() || n <= COMPLEX_REGULUS_DET * v.norm() {
                return Err(Error::degenerate(
                    "lines",
                    "the three lines span no plane of P⁵ (two are one line, or the three lie in a pencil)",
                ));
            }
            basis[k] = w / n;
        }
        let v = vec6(lines[0]);
        Ok(RegulusPlane { basis, first: [basis[0].dot(&v), basis[1].dot(&v), basis[2].dot(&v)] })
    }

    /// The distance of `line`'s point from the plane: |v − P v|/|v| for its 6-vector v (the sine
    /// of the angle between v and W); 0 for the lines of the regulus, NaN for the zero vector.
    pub fn distance(&self, line: &KleinPoint) -> f64 {
        let v = vec6(line);
        let mut w = v;
        for b in &self.basis {
            w -= b * b.dot(&w);
        }
        w.norm() / v.norm()
    }

    /// `samples` points of the conic π ∩ M (K8), on the branch of the first line, in order round
    /// it; an error when π does not cut M in a conic (the three lines meet pairwise: a pencil's
    /// plane lies on M) or `samples` is below 3 or above [`MAX_KLEIN_OUTLINE_SAMPLES`].
    pub fn conic(&self, samples: usize) -> Result<Vec<KleinPoint>> {
        if !(3..=MAX_KLEIN_OUTLINE_SAMPLES).contains(&samples) {
            return Err(Error::parameter("samples", format!("from 3 to {MAX_KLEIN_OUTLINE_SAMPLES} points")));
        }
        let points: Vec<KleinPoint> = self.basis.iter().map(point6).collect();
        let q = Matrix3::from_fn(|j, k| klein_form(&points[j], &points[k]));
        let eig = SymmetricEigen::new(q);
        let scale = eig.eigenvalues.iter().fold(0.0f64, |m, l| m.max(l.abs()));
        let positive: Vec<usize> = (0..3).filter(|&k| eig.eigenvalues[k] > COMPLEX_REGULUS_DET * scale).collect();
        let negative: Vec<usize> = (0..3).filter(|&k| eig.eigenvalues[k] < -COMPLEX_REGULUS_DET * scale).collect();
        let (pair, lone) = match (positive.len(), negative.len()) {
            (2, 1) => ([positive[0], positive[1]], negative[0]),
            (1, 2) => ([negative[0], negative[1]], positive[0]),
            _ => {
                return Err(Error::degenerate(
                    "lines",
                    "the plane of the three lines cuts the Klein quadric in no conic (the lines meet pairwise)",
                ))
            }
        };
        let axis = |k: usize| -> [f64; 3] {
            let v = eig.eigenvectors.column(k);
            let s = 1.0 / eig.eigenvalues[k].abs().sqrt();
            [s * v[0], s * v[1], s * v[2]]
        };
        let (a, b, mut c) = (axis(pair[0]), axis(pair[1]), axis(lone));
        if c[0] * self.first[0] + c[1] * self.first[1] + c[2] * self.first[2] < 0.0 {
            c = [-c[0], -c[1], -c[2]];
        }
        Ok((0..samples)
            .map(|i| {
                let (s, co) = (TAU * i as f64 / samples as f64).sin_cos();
                let w: Vector6<f64> =
                    (0..3).map(|k| self.basis[k] * (co * a[k] + s * b[k] + c[k])).fold(Vector6::zeros(), |x, y| x + y);
                point6(&w)
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
        let unit = |p: &KleinPoint| vec6(p).normalize();
        for p in &k.points {
            let nearest = conic.iter().map(|w| (unit(w) - unit(p)).norm()).fold(f64::INFINITY, f64::min);
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
}
