//! The flat pattern of a skew ruled surface: Section 3's approximate development, and the gaps it
//! leaves (Fig. 6).
//!
//! A skew strip has no development: its faces are not plane. Section 3 bends it isometrically into
//! its conoidal model — every pair of consecutive rulings, with its common perpendicular, moved as a
//! rigid body — and projects that orthogonally onto a plane parallel to the rulings
//! ([`crate::ruled::Development`]). The pattern keeps the length of every ruling and the angle
//! φ_{i,i+1} between consecutive ones; it does not keep the distance h_{i,i+1} of consecutive
//! rulings, which the conoidal model stacks up as heights ζ_{i+1} = ζ_i + h_{i,i+1} along the
//! common normal n_{0,1}, and which the projection drops.
//!
//! So a paper strip cut from the pattern cannot take the surface's shape: paper bends without
//! stretching, its faces stay plane, and ruling i + 1 lies h_{i,i+1} off the plane of the paper face
//! that should hold it — the *gap* of each pair. Along the strip the gaps add up to the climb
//! ζ_{N−1} − ζ_0 of the conoidal model; the extremal height max ζ − min ζ is Section 3's measure of
//! non-developability. Where the strip closes on the surface (a hyperboloid all round, its last
//! ruling its first), the paper's two ends stay the climb apart: the pattern cannot close. The
//! projection also shortens every edge that crosses the rulings, from ℓ to about √(ℓ² − h²).

use super::unfold::{isometry_error, IsometryError};
use crate::ruled::{Development, RuledSurface};
use glam::DVec2;

/// Section 3's approximate development of a strip with the gaps it leaves (see the module).
#[derive(Debug, Clone, PartialEq)]
pub struct ApproximatePattern {
    /// The images A_i, B_i of the ends a_i, b_i.
    pub points: Vec<DVec2>,
    /// The gap of each pair: ζ_{i+1} − ζ_i (h_{i,i+1} for a pair that is not parallel), N − 1 values.
    pub gaps: Vec<f64>,
    /// The climb ζ_{N−1} − ζ_0: the sum of the gaps.
    pub climb: f64,
    /// max ζ − min ζ: Section 3's measure of non-developability.
    pub height: f64,
    /// How far the pattern is from an isometry of the strip (its rulings keep their lengths; the
    /// edges across them are shortened).
    pub isometry: IsometryError,
}

impl ApproximatePattern {
    /// The approximate development of `surface` and its gaps (O(N)).
    pub fn of(surface: &RuledSurface) -> Self {
        let dev = Development::of(surface);
        let gaps: Vec<f64> = dev.heights.windows(2).map(|w| w[1] - w[0]).collect();
        let climb = dev.heights.last().copied().unwrap_or(0.0) - dev.heights[0];
        let height = dev.non_developability();
        let isometry = isometry_error(surface, &dev.points);
        ApproximatePattern { points: dev.points, gaps, climb, height, isometry }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;
    use crate::base::Ranges;
    use crate::catalogue::AnalyticSurface;
    use crate::ruled::SmoothRuled;
    use std::f64::consts::TAU;

    /// Example 1's hyperboloid all round: the gaps are the distances h of consecutive rulings, they
    /// add up to the climb, and the pattern's ends stay that far apart although the strip closes
    /// on the surface (its last ruling is its first).
    #[test]
    fn the_hyperboloid_all_round_cannot_close() {
        let hyperboloid = AnalyticSurface::by_name("hyperboloid").unwrap();
        let ranges = Ranges { u: (0.0, TAU), v: (-1.0, 1.0), closed: false };
        let s = hyperboloid.sample(49, ranges).unwrap();
        assert_near!(s.segment(48).a, s.segment(0).a, 1e-12);
        let p = ApproximatePattern::of(&s);
        let h = s.invariants().distance;
        for (g, h) in p.gaps.iter().zip(&h) {
            assert_near!(*g, *h, 1e-12);
        }
        assert_near!(p.climb, h.iter().sum::<f64>(), 1e-12);
        // δ keeps its sign along the regulus: the climb is the height, and it is far from 0
        assert!(h.iter().all(|&x| x > 0.0) || h.iter().all(|&x| x < 0.0));
        assert_near!(p.climb.abs(), p.height, 1e-12);
        assert!(p.height > 1.0, "{}", p.height);
        // the rulings keep their lengths; the edges across them are shortened
        for i in 0..49 {
            let (a, b) = (p.points[2 * i], p.points[2 * i + 1]);
            assert_near!((b - a).length(), s.segment(i).length(), 1e-12);
        }
        assert!(p.isometry.length > 1e-3, "{:?}", p.isometry);
    }

    /// The climb is ∫ δ dφ in the limit: the sum of δ_{i,i+1} φ_{i,i+1}, whatever the sampling.
    #[test]
    fn the_climb_is_the_sum_of_delta_times_phi_and_converges() {
        let hyperboloid = AnalyticSurface::by_name("hyperboloid").unwrap();
        let ranges = Ranges { u: (0.0, TAU), v: (-1.0, 1.0), closed: false };
        let climbs: Vec<f64> = [25, 49, 97, 193]
            .iter()
            .map(|&n| ApproximatePattern::of(&hyperboloid.sample(n, ranges).unwrap()).climb)
            .collect();
        let inv = hyperboloid.sample(49, ranges).unwrap().invariants();
        let sum: f64 = inv.distribution.iter().zip(&inv.angle).map(|(d, a)| d * a).sum();
        assert_near!(climbs[1], sum, 1e-12);
        // differences shrink by about 4: a limit at order 2
        let d: Vec<f64> = climbs.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
        for w in d.windows(2) {
            assert!(((w[0] / w[1]).log2() - 2.0).abs() < 0.2, "{climbs:?}");
        }
        // the exact ∫ δ(u) φ′(u) du, by the midpoint rule on a fine grid
        let m = 20000;
        let mut integral = 0.0;
        for k in 0..m {
            let (u0, u1) = (TAU * k as f64 / m as f64, TAU * (k + 1) as f64 / m as f64);
            let (e0, e1) = (hyperboloid.line(u0).dir, hyperboloid.line(u1).dir);
            integral += hyperboloid.distribution((u0 + u1) / 2.0) * e0.angle_between(e1);
        }
        assert!((climbs[3] - integral).abs() < 1e-3, "{climbs:?} vs {integral}");
    }

    /// A developable strip leaves no gaps: its approximate development is its development.
    #[test]
    fn a_developable_strip_leaves_no_gap() {
        use crate::developable::construct::{tangent_surface, Span};
        let c: Vec<glam::DVec3> =
            (0..20).map(|i| i as f64 * 0.2).map(|u| glam::DVec3::new(u.cos(), u.sin(), 0.4 * u)).collect();
        let s = tangent_surface(&c, Span { from: 0.1, to: 1.0 }).unwrap();
        let p = ApproximatePattern::of(&s);
        assert!(p.gaps.iter().all(|g| g.abs() < 1e-13) && p.height < 1e-13);
        assert!(p.isometry.length < 1e-12, "{:?}", p.isometry);
    }
}
