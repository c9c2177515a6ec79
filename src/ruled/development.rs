//! Approximate development of a ruled surface and its non-developability measure
//! (Section 3, Fig. 6).
//!
//! First compute the isometric conoidal model (Example 2), then project it orthogonally
//! onto a plane parallel to its rulings: the plane through a_0 spanned by e_0 and e_1,
//! with 2D coordinates x along e_0 and y along n_{0,1} × e_0 (so e_1 makes the angle
//! +φ_{0,1} with the x-axis). The map is isometric on every ruling; the two footpoints of a
//! pair land on one point, which lies on both projected rulings, so the striction polygon
//! becomes the polygon that the projected rulings envelop.
//!
//! The conoidal rulings lie at heights H_i = Σ_{k<i} h_{k,k+1} along n_{0,1} (ERRATA.md 7);
//! the *non-developability measure* is max H_i − min H_i, the "height" of the conoidal
//! model. It is 0 for a cone or a cylinder and O(H²) for a sampled tangent surface.

use crate::ruled::{HingeChain, RuledSurface};
use glam::DVec2;

/// The approximate development and the conoidal model it was projected from.
#[derive(Debug, Clone, PartialEq)]
pub struct Development {
    /// The isometric conoidal model.
    pub conoidal: RuledSurface,
    /// Images of a_0, b_0, a_1, b_1, … in the plane.
    pub points: Vec<DVec2>,
    /// Height H_i of each conoidal ruling along n_{0,1}, relative to R_0.
    pub heights: Vec<f64>,
}

impl Development {
    /// Develops `surface` approximately (O(N)).
    pub fn of(surface: &RuledSurface) -> Self {
        let chain = HingeChain::new(surface);
        let conoidal = chain.conoidal();
        let n = chain.first_normal();
        let s0 = conoidal.segment(0);
        let (origin, x) = (s0.a, s0.line().dir);
        let y = n.cross(x);
        let points = conoidal.points().iter().map(|&p| DVec2::new((p - origin).dot(x), (p - origin).dot(y))).collect();
        let heights = conoidal.segments().map(|s| (s.a - origin).dot(n)).collect();
        Development { conoidal, points, heights }
    }

    /// max H_i − min H_i: how far the surface is from developable (0 when developable).
    pub fn non_developability(&self) -> f64 {
        let (lo, hi) =
            self.heights.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &h| (lo.min(h), hi.max(h)));
        hi - lo
    }

    /// The plane coordinates as a flat array: x, y of a'_i, then of b'_i, per ruling.
    pub fn flat(&self) -> &[f64] {
        bytemuck::cast_slice(&self.points)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;
    use crate::tolerance::test::EXACT;

    #[test]
    fn heights_are_running_sums_of_h() {
        let s = RuledSurface::from_flat(&[
            0.0, 0.0, 0.0, 1.0, 0.0, 0.0, //
            0.0, 0.0, 1.0, 0.0, 1.0, 1.0, //
            0.3, 0.0, 2.5, 1.0, 1.0, 2.0, //
            0.0, 0.4, 3.0, 0.0, -1.0, 3.7,
        ])
        .unwrap();
        let dev = Development::of(&s);
        let h = s.invariants().distance;
        let mut sum = 0.0;
        for (i, height) in dev.heights.iter().enumerate() {
            assert_near!(*height, sum, EXACT);
            sum += h.get(i).copied().unwrap_or(0.0);
        }
        let (lo, hi) = (0.0f64.min(h[0]).min(h[0] + h[1]).min(sum), 0.0f64.max(h[0]).max(h[0] + h[1]).max(sum));
        assert_near!(dev.non_developability(), hi - lo, EXACT);
        // first ruling along +x from the origin, second at angle +φ
        assert_near!(dev.points[1], DVec2::new(1.0, 0.0), EXACT);
        let e1 = (dev.points[3] - dev.points[2]).normalize();
        assert_near!(e1.y.atan2(e1.x), s.invariants().angle[0], EXACT);
    }
}
