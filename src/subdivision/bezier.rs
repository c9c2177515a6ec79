//! Bézier subdivision by de Casteljau's algorithm (Section 4): the polygon p_0 … p_{N−1}
//! is the control polygon of a Bézier curve of degree N − 1; one step splits it at t = ½
//! into the control polygons of its two halves, which share the midpoint of the curve.
//! Repeating on every piece converges to the Bézier curve.
//!
//! A polygon of P pieces of degree m (N = P m + 1 points) → 2P pieces: 2N − 1 points.

use crate::subdivision::Affine;
#[cfg(test)]
use glam::DVec3;

/// One de Casteljau step on every Bézier piece of degree `degree` in `points`.
pub fn de_casteljau<T: Affine>(points: &[T], degree: usize) -> Vec<T> {
    let pieces = (points.len() - 1) / degree;
    let mut out = Vec::with_capacity(2 * points.len() - 1);
    out.push(points[0]);
    let mut work = vec![points[0]; degree + 1];
    let mut right = vec![points[0]; degree + 1];
    for k in 0..pieces {
        work.copy_from_slice(&points[k * degree..=(k + 1) * degree]);
        // after level r, work[0] is the left polygon's point r and work[degree − r] the right's
        right[degree] = work[degree];
        for r in 1..=degree {
            for i in 0..=degree - r {
                work[i] = (work[i] + work[i + 1]) * 0.5;
            }
            out.push(work[0]);
            right[degree - r] = work[degree - r];
        }
        out.extend_from_slice(&right[1..]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Degree 1: each edge of the polygon is a piece, split at its midpoint.
    #[test]
    fn degree_one_splits_every_edge() {
        let p = [DVec3::ZERO, DVec3::X * 2.0, DVec3::new(2.0, 4.0, 0.0)];
        let q = de_casteljau(&p, 1);
        assert_eq!(q, [p[0], DVec3::X, p[1], DVec3::new(2.0, 2.0, 0.0), p[2]]);
    }

    fn bezier(p: &[DVec3], t: f64) -> DVec3 {
        let mut w = p.to_vec();
        for r in 1..p.len() {
            for i in 0..p.len() - r {
                w[i] = (1.0 - t) * w[i] + t * w[i + 1];
            }
        }
        w[0]
    }

    #[test]
    fn halves_reproduce_the_curve() {
        let p = [DVec3::ZERO, DVec3::new(1.0, 3.0, 0.0), DVec3::new(3.0, -1.0, 1.0), DVec3::new(4.0, 1.0, 2.0)];
        let q = de_casteljau(&p, 3);
        assert_eq!(q.len(), 7);
        assert!((q[3] - bezier(&p, 0.5)).length() < 1e-15);
        for t in [0.1, 0.3, 0.77] {
            assert!((bezier(&q[..4], t) - bezier(&p, t / 2.0)).length() < 1e-14);
            assert!((bezier(&q[3..], t) - bezier(&p, 0.5 + t / 2.0)).length() < 1e-14);
        }
        // a second step works piecewise
        let r = de_casteljau(&q, 3);
        assert_eq!(r.len(), 13);
        assert!((r[3] - bezier(&p, 0.25)).length() < 1e-14);
        assert!((r[9] - bezier(&p, 0.75)).length() < 1e-14);
    }
}
