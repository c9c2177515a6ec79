//! Uniform B-spline subdivision of degree d by Lane and Riesenfeld (Section 4, after de
//! Boor): double every point, then average neighbours d times. The polygons converge to the
//! uniform B-spline of degree d with the input as control polygon. d = 1 inserts midpoints,
//! d = 2 is Chaikin's algorithm, d = 3 the cubic B-spline.
//!
//! Open polygons: N points → 2N − d (every averaging pass drops one point; the limit is the
//! unclamped uniform B-spline). Closed polygons: N → 2N, the result shifted so that it
//! stays aligned with the input.

use crate::subdivision::Affine;
#[cfg(test)]
use glam::DVec3;

/// One step of degree-`degree` uniform B-spline subdivision.
pub fn bspline<T: Affine>(points: &[T], degree: usize, closed: bool) -> Vec<T> {
    let mut q: Vec<T> = points.iter().flat_map(|&p| [p, p]).collect();
    for _ in 0..degree {
        if closed {
            let first = q[0];
            for i in 0..q.len() {
                let next = if i + 1 < q.len() { q[i + 1] } else { first };
                q[i] = (q[i] + next) * 0.5;
            }
        } else {
            for i in 0..q.len() - 1 {
                q[i] = (q[i] + q[i + 1]) * 0.5;
            }
            q.pop();
        }
    }
    if closed {
        // each averaging pass moves the points half a step forward; undo the drift
        q.rotate_right(degree / 2);
    }
    q
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::subdivision::chaikin::chaikin;

    fn poly() -> Vec<DVec3> {
        vec![
            DVec3::ZERO,
            DVec3::new(1.0, 2.0, 0.5),
            DVec3::new(3.0, 2.5, 1.0),
            DVec3::new(4.0, 0.0, 2.0),
            DVec3::new(6.0, 1.0, 0.0),
        ]
    }

    #[test]
    fn degree_two_is_chaikin_and_degree_one_inserts_midpoints() {
        let p = poly();
        assert_eq!(bspline(&p, 2, false), chaikin(&p, false));
        let q = bspline(&p, 1, false);
        assert_eq!(q.len(), 9);
        assert_eq!(q[1], 0.5 * (p[0] + p[1]));
        assert_eq!(q[2], p[1]);
        let c = bspline(&p, 2, true);
        let mut expected = chaikin(&p, true);
        expected.rotate_right(1);
        assert_eq!(c, expected);
    }

    /// Cubic B-spline rules: vertex points (p_{i−1} + 6p_i + p_{i+1})/8, edge points
    /// (p_i + p_{i+1})/2.
    #[test]
    fn cubic_rules() {
        let p = poly();
        let q = bspline(&p, 3, false);
        assert_eq!(q.len(), 2 * 5 - 3);
        assert!((q[1] - (p[0] + 6.0 * p[1] + p[2]) / 8.0).length() < 1e-15);
        assert!((q[2] - (p[1] + p[2]) / 2.0).length() < 1e-15);
        let c = bspline(&p, 3, true);
        assert_eq!(c.len(), 10);
        assert!((c[0] - (p[4] + 6.0 * p[0] + p[1]) / 8.0).length() < 1e-15);
        assert!((c[1] - (p[0] + p[1]) / 2.0).length() < 1e-15);
    }
}
