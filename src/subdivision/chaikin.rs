//! Chaikin's corner cutting (Section 4, Fig. 7): every edge p_i p_{i+1} is replaced by the
//! points ¾ p_i + ¼ p_{i+1} and ¼ p_i + ¾ p_{i+1}. The polygons converge to the uniform
//! quadratic B-spline with control points p_i, which touches every interior edge at its
//! midpoint.
//!
//! Open polygons: N points → 2(N − 1) (pure corner cutting, no end rule: the limit runs from
//! the midpoint of the first edge to the midpoint of the last, exactly the uniform B-spline).
//! Closed polygons: N → 2N.

use crate::subdivision::Affine;
#[cfg(test)]
use glam::DVec3;

/// One step of Chaikin's algorithm.
pub fn chaikin<T: Affine>(points: &[T], closed: bool) -> Vec<T> {
    let n = points.len();
    let edges = if closed { n } else { n - 1 };
    let mut out = Vec::with_capacity(2 * edges);
    for i in 0..edges {
        let (p, q) = (points[i], points[(i + 1) % n]);
        out.push(p * 0.75 + q * 0.25);
        out.push(p * 0.25 + q * 0.75);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;
    use crate::tolerance::test::EXACT;

    #[test]
    fn cuts_corners_at_a_quarter() {
        let p = [DVec3::ZERO, DVec3::new(4.0, 0.0, 0.0), DVec3::new(4.0, 4.0, 0.0)];
        let q = chaikin(&p, false);
        assert_eq!(
            q,
            vec![
                DVec3::new(1.0, 0.0, 0.0),
                DVec3::new(3.0, 0.0, 0.0),
                DVec3::new(4.0, 1.0, 0.0),
                DVec3::new(4.0, 3.0, 0.0)
            ]
        );
        assert_eq!(chaikin(&p, true).len(), 6);
    }

    /// The limit curve touches each edge at its midpoint: that midpoint stays, at every
    /// step, the midpoint of a refined edge lying along the original edge, whose length
    /// halves each time. (The end edges' midpoints are the limit's endpoints.)
    #[test]
    fn limit_touches_edge_midpoints() {
        let p = [DVec3::ZERO, DVec3::new(1.0, 2.0, 0.0), DVec3::new(3.0, 2.5, 1.0), DVec3::new(4.0, 0.0, 2.0)];
        let mut q = p.to_vec();
        let steps = 10;
        for _ in 0..steps {
            q = chaikin(&q, false);
        }
        for i in 0..3 {
            let (mid, dir) = (0.5 * (p[i] + p[i + 1]), (p[i + 1] - p[i]).normalize());
            let edge = q.windows(2).find(|w| (0.5 * (w[0] + w[1]) - mid).length() < 1e-12);
            let edge = edge.unwrap_or_else(|| panic!("no refined edge centred at the midpoint of edge {i}"));
            assert_near!((edge[1] - edge[0]).normalize(), dir, EXACT);
            assert_near!((edge[1] - edge[0]).length(), (p[i + 1] - p[i]).length() / f64::powi(2.0, steps), EXACT);
        }
    }
}
