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
use glam::{DMat4, DVec2, DVec3, DVec4};

/// The reference frame of the conoidal model and the development: origin a_0, x = e_0,
/// z = n_{0,1}, y = z × x (Fig. 6); the reference plane is z = 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// a_0.
    pub origin: DVec3,
    /// e_0.
    pub x: DVec3,
    /// n_{0,1} × e_0.
    pub y: DVec3,
    /// n_{0,1}.
    pub z: DVec3,
}

impl Frame {
    /// The frame of `surface` (R_0 and R_1 must not be parallel for n_{0,1} to exist; for
    /// parallel rulings the chain's fallback normal is used).
    pub fn of(surface: &RuledSurface) -> Self {
        let z = HingeChain::new(surface).first_normal();
        let s0 = surface.segment(0);
        let x = s0.line().dir;
        Frame { origin: s0.a, x, y: z.cross(x), z }
    }

    /// The rigid motion taking world coordinates to frame coordinates ((p − o)·x, (p − o)·y,
    /// (p − o)·z), as a 4 × 4 matrix (column-major when flattened, as WebGL wants it).
    pub fn world_to_frame(&self) -> DMat4 {
        let rotation = DMat4::from_cols(
            DVec4::new(self.x.x, self.y.x, self.z.x, 0.0),
            DVec4::new(self.x.y, self.y.y, self.z.y, 0.0),
            DVec4::new(self.x.z, self.y.z, self.z.z, 0.0),
            DVec4::W,
        );
        rotation * DMat4::from_translation(-self.origin)
    }

    /// The point of the reference plane with plane coordinates `p`.
    pub fn plane_point(&self, p: DVec2) -> DVec3 {
        self.origin + p.x * self.x + p.y * self.y
    }
}

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

    /// The images of the striction polygon: the footpoints f_{i,i+1} of the conoidal model
    /// projected onto the plane (both feet of a pair land on one point), N − 1 points where
    /// the projected rulings meet; the polygon they envelop.
    pub fn striction_image(&self) -> Vec<DVec2> {
        let frame = Frame::of(&self.conoidal);
        self.conoidal
            .invariants()
            .footpoints
            .iter()
            .step_by(2)
            .map(|&f| DVec2::new((f - frame.origin).dot(frame.x), (f - frame.origin).dot(frame.y)))
            .collect()
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
        // the frame maps a_0 to the origin and e_0 to the x-axis
        let m = Frame::of(&s).world_to_frame();
        assert_near!(m.transform_point3(s.segment(0).a), DVec3::ZERO, EXACT);
        assert_near!(m.transform_point3(s.segment(0).b), DVec3::new(1.0, 0.0, 0.0), EXACT);
        // the striction image: the projected rulings i and i + 1 meet at image point i
        for (i, q) in dev.striction_image().iter().enumerate() {
            for k in [i, i + 1] {
                let (a, b) = (dev.points[2 * k], dev.points[2 * k + 1]);
                assert_near!((b - a).perp_dot(*q - a) / (b - a).length(), 0.0, 1e-12);
            }
        }
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
