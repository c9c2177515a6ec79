//! Approximate development of a ruled surface and its non-developability measure
//! (Section 3, Fig. 6).
//!
//! First compute the isometric conoidal model (Example 2), then project it orthogonally
//! onto a plane parallel to its rulings: the plane through a_0 spanned by e_0 and e_1,
//! with 2D coordinates x along e_0 and y along n_{0,1} × e_0 (so e_1 makes the angle
//! +φ_{0,1} with the x-axis). The map is isometric on every ruling. The common perpendiculars
//! of the conoidal model are all parallel to n_{0,1}, so the two footpoints of a pair land on
//! one point, where the two projected rulings meet: these N − 1 points, the images of the
//! perpendiculars' midpoints (Example 1's polygon), form the polygon the projected rulings
//! envelop. The striction polygon m_i = (f_{i,i−1} + f_{i,i+1})/2 is *inscribed* in it: both
//! footpoints of ruling i project to consecutive corners of the envelope polygon on the
//! projected ruling i, so the image of m_i is the midpoint of that edge.
//!
//! The conoidal rulings lie at heights ζ_i = Σ_{k<i} h_{k,k+1} along n_{0,1} (docs/src/conventions.md, Section 3);
//! a parallel pair is coplanar and adds no height, as a meeting pair does (its body turns about
//! the normal of its plane, [`HingeChain`]). The *non-developability measure* is max ζ_i − min ζ_i,
//! the "height" of the conoidal model. It is 0 for a cone or a cylinder (whose development is the
//! strip of its chords, unrolled) and O(H²) for a sampled tangent surface.

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

    /// The plane coordinates of the orthogonal projection of `p` onto the reference plane.
    pub fn plane_coordinates(&self, p: DVec3) -> DVec2 {
        DVec2::new((p - self.origin).dot(self.x), (p - self.origin).dot(self.y))
    }
}

/// The approximate development and the conoidal model it was projected from.
#[derive(Debug, Clone, PartialEq)]
pub struct Development {
    /// The isometric conoidal model.
    pub conoidal: RuledSurface,
    /// Images of a_0, b_0, a_1, b_1, … in the plane.
    pub points: Vec<DVec2>,
    /// Height ζ_i of each conoidal ruling along n_{0,1}, relative to R_0.
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

    /// max ζ_i − min ζ_i: how far the surface is from developable (0 when developable).
    pub fn non_developability(&self) -> f64 {
        let (lo, hi) =
            self.heights.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &h| (lo.min(h), hi.max(h)));
        hi - lo
    }

    /// The polygon the developed rulings envelop: the N − 1 points where consecutive developed
    /// rulings meet, each the image of both footpoints f_{i,i+1}, f_{i+1,i} of a pair of the
    /// conoidal model (so of the perpendicular's midpoint too, a vertex of Example 1's polygon).
    pub fn envelope_polygon(&self) -> Vec<DVec2> {
        let frame = Frame::of(&self.conoidal);
        self.conoidal.invariants().footpoints.iter().step_by(2).map(|&f| frame.plane_coordinates(f)).collect()
    }

    /// The image of the striction polygon m_i (N − 2 points, one per interior ruling): inscribed
    /// in [`Development::envelope_polygon`], each point the midpoint of the edge that lies on
    /// the developed ruling i. NaN beside a parallel pair, as m_i.
    pub fn striction_image(&self) -> Vec<DVec2> {
        let frame = Frame::of(&self.conoidal);
        self.conoidal.invariants().striction.iter().map(|&m| frame.plane_coordinates(m)).collect()
    }

    /// The plane coordinates as a flat array: x, y of a'_i, then of b'_i, per ruling.
    pub fn flat(&self) -> &[f64] {
        bytemuck::cast_slice(&self.points)
    }
}

/// The signed radius of curvature of the envelope of the developed rulings at each interior
/// ruling (beyond the paper: when Fig. 5's caption holds),
///
/// ρ_i = (f_{i,i+1} − f_{i,i−1})·e_i / ((φ_{i−1,i} + φ_{i,i+1})/2),
///
/// the step between the two footpoints on R_i over the turn of the rulings there. The
/// isometry keeps both, and in the development the step is the chord of the envelope between
/// two consecutive contact points while the projected rulings turn by φ, so ρ_i is its radius of
/// curvature. By (6) as corrected in docs/src/conventions.md (Section 2), f_{i,i±1} = s ± (H/2)(e·ṡ) e + O(H²) and φ = H|ė| + O(H²),
/// so ρ_i → (e·ṡ)/|ė| at second order (the O(H²) terms of the two footpoints are symmetric).
/// For the ruled helical surface of Fig. 5 (radius r, pitch p, rulings at slope β) that is
/// r + p tan β: the conoidal rulings touch a cylinder of that radius about the axis, and meet
/// the axis, as the caption says, only when tan β = −r/p (e·ṡ = 0). N − 2 values; NaN where a
/// neighbouring pair is parallel.
pub fn envelope_radii(surface: &RuledSurface) -> Vec<f64> {
    let inv = surface.invariants();
    let n = surface.len();
    (1..n.saturating_sub(1))
        .map(|i| {
            if inv.parallel[i - 1] || inv.parallel[i] {
                return f64::NAN;
            }
            let e = surface.segment(i).line().dir;
            let step = (inv.footpoints[2 * i] - inv.footpoints[2 * i - 1]).dot(e);
            step / (0.5 * (inv.angle[i - 1] + inv.angle[i]))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;
    #[allow(unused_imports)]
    use crate::congruence::SmoothCongruence;
    #[allow(unused_imports)]
    use crate::ruled::SmoothRuled;
    use crate::tolerance::test::EXACT;

    /// Four skew rulings in general position.
    fn four_skew_rulings() -> RuledSurface {
        RuledSurface::from_flat(&[
            0.0, 0.0, 0.0, 1.0, 0.0, 0.0, //
            0.0, 0.1, 1.0, 0.0, 1.0, 1.0, //
            0.3, 0.0, 2.5, 1.0, 1.0, 2.0, //
            0.0, 0.4, 3.0, 0.0, -1.0, 3.7,
        ])
        .unwrap()
    }

    /// The frame and the development of the rulings moved by a translation: the frame moves
    /// along, the development is the same (a rigid motion changes no distance or angle).
    #[test]
    fn the_frame_moves_with_the_rulings_and_the_development_does_not() {
        let s = four_skew_rulings();
        let shift = DVec3::new(5.0, -2.0, 3.0);
        let moved: Vec<f64> = s.points().iter().flat_map(|&p| (p + shift).to_array()).collect();
        let moved = RuledSurface::from_flat(&moved).unwrap();
        let frame = Frame::of(&moved);
        let m = frame.world_to_frame();
        let a0 = moved.segment(0).a;
        assert_near!(m.transform_point3(a0), DVec3::ZERO, EXACT);
        for (axis, unit) in [(frame.x, DVec3::X), (frame.y, DVec3::Y), (frame.z, DVec3::Z)] {
            assert_near!(m.transform_point3(a0 + axis), unit, EXACT);
        }
        // plane points and plane coordinates are inverse; the plane is z = 0 in the frame
        let p = DVec2::new(2.0, -3.0);
        assert_near!(frame.plane_coordinates(frame.plane_point(p)), p, EXACT);
        assert_near!(m.transform_point3(frame.plane_point(p)), p.extend(0.0), EXACT);
        let (dev, still) = (Development::of(&moved), Development::of(&s));
        assert_eq!((dev.points.len(), dev.heights.len()), (8, 4));
        assert_eq!((still.points.len(), still.heights.len()), (8, 4));
        for (a, b) in dev.points.iter().zip(&still.points) {
            assert_near!(*a, *b, EXACT);
        }
        for (a, b) in dev.heights.iter().zip(&still.heights) {
            assert_near!(*a, *b, EXACT);
        }
        // flat: x, y of each point in turn
        let flat: Vec<f64> = dev.points.iter().flat_map(|p| p.to_array()).collect();
        assert_eq!(dev.flat(), flat);
    }

    /// A parallel pair has no envelope between its rulings: NaN at both rulings it joins.
    #[test]
    fn envelope_radii_are_nan_beside_a_parallel_pair() {
        let s = RuledSurface::from_flat(&[
            0.0, 0.0, 0.0, 1.0, 0.0, 0.0, //
            0.0, 0.1, 1.0, 0.0, 1.0, 1.0, //
            0.5, 0.1, 2.0, 0.5, 1.0, 2.0, //
            0.3, 0.0, 2.5, 1.0, 1.0, 2.0, //
            0.0, 0.4, 3.0, 0.0, -1.0, 3.7,
        ])
        .unwrap();
        assert_eq!(s.invariants().parallel, [false, true, false, false]);
        let radii = envelope_radii(&s);
        assert_eq!(radii.len(), 3);
        assert!(radii[0].is_nan() && radii[1].is_nan(), "{radii:?}");
        assert!(radii[2].is_finite(), "{radii:?}");
    }

    #[test]
    fn heights_are_running_sums_of_h() {
        let s = four_skew_rulings();
        let dev = Development::of(&s);
        // the frame maps a_0 to the origin and e_0 to the x-axis
        let m = Frame::of(&s).world_to_frame();
        assert_near!(m.transform_point3(s.segment(0).a), DVec3::ZERO, EXACT);
        assert_near!(m.transform_point3(s.segment(0).b), DVec3::new(1.0, 0.0, 0.0), EXACT);
        // the envelope polygon: the projected rulings i and i + 1 meet at its corner i
        let envelope = dev.envelope_polygon();
        assert_eq!(envelope.len(), 3);
        for (i, q) in envelope.iter().enumerate() {
            for k in [i, i + 1] {
                let (a, b) = (dev.points[2 * k], dev.points[2 * k + 1]);
                assert_near!((b - a).perp_dot(*q - a) / (b - a).length(), 0.0, 1e-12);
            }
        }
        // the image of the striction polygon m_i is inscribed in it: the midpoint of its edge
        // on the projected ruling i, not a corner
        let image = dev.striction_image();
        assert_eq!(image.len(), 2);
        for (j, m) in image.iter().enumerate() {
            assert_near!(*m, (envelope[j] + envelope[j + 1]) / 2.0, 1e-12);
            assert!((*m - envelope[j]).length() > 1e-3 && (*m - envelope[j + 1]).length() > 1e-3);
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

    /// A cylinder is developable: its parallel pairs add no height, so the measure is 0, and
    /// the development lays its rulings side by side at the chord distances.
    #[test]
    fn a_cylinder_is_developable_and_develops_into_its_chords() {
        // five parallel rulings on an arc of 1 rad of the unit circle: chords 2 sin(1/8)
        let arc: Vec<f64> = (0..5)
            .flat_map(|k| {
                let (s, c) = (0.25 * k as f64).sin_cos();
                [c, s, 0.0, c, s, 1.0]
            })
            .collect();
        let dev = Development::of(&RuledSurface::from_flat(&arc).unwrap());
        // 0 (it was the sum of the chords, 8 sin(1/8) = 0.997, while a parallel pair added its
        // distance), up to rounding in the turns
        assert!(dev.non_developability() <= EXACT, "heights {:?}", dev.heights);
        let chord = 2.0 * 0.125f64.sin();
        for k in 0..5 {
            let y = k as f64 * chord;
            assert_near!(dev.points[2 * k], DVec2::new(0.0, y), EXACT);
            assert_near!(dev.points[2 * k + 1], DVec2::new(1.0, y), EXACT);
        }
        // the catalogue's elliptic cylinder (cos u, 0.7 sin u, v), 24 rulings round it (v from −1
        // to 1): all at height 0, at the summed chords of the ellipse
        let cylinder = crate::catalogue::AnalyticSurface::by_name("cylinder").unwrap();
        let ranges = cylinder.ranges();
        let s = cylinder.sample(24, ranges).unwrap();
        let dev = Development::of(&s);
        assert!(dev.heights.iter().all(|h| h.abs() <= EXACT), "heights {:?}", dev.heights);
        // (5.18 while a parallel pair added its distance: the 23 chords)
        assert!(dev.non_developability() <= EXACT, "{}", dev.non_developability());
        let mut y = 0.0;
        for k in 0..24 {
            assert_near!(dev.points[2 * k], DVec2::new(0.0, y), EXACT);
            assert_near!(dev.points[2 * k + 1], DVec2::new(2.0, y), EXACT);
            if k < 23 {
                let at = |j: usize| {
                    let (s, c) = (std::f64::consts::TAU * j as f64 / 24.0).sin_cos();
                    DVec2::new(c, 0.7 * s)
                };
                y += (at(k + 1) - at(k)).length();
            }
        }
    }

    /// Fig. 6's strip of Example 1's hyperboloid (24 rulings, u from 0 to 2.4): the image of
    /// the striction polygon lies on the developed rulings, at the midpoints of the envelope
    /// polygon's edges, and keeps the distances along each ruling.
    #[test]
    fn the_striction_image_is_inscribed_in_the_envelope_polygon() {
        let hyperboloid = crate::catalogue::AnalyticSurface::by_name("hyperboloid").unwrap();
        let ranges = crate::base::Ranges { u: (0.0, 2.4), v: (-1.0, 1.0), closed: false };
        let s = hyperboloid.sample(24, ranges).unwrap();
        let dev = Development::of(&s);
        let (envelope, image) = (dev.envelope_polygon(), dev.striction_image());
        assert_eq!((envelope.len(), image.len()), (23, 22));
        let inv = s.invariants();
        for (j, m) in image.iter().enumerate() {
            let i = j + 1; // the interior ruling
            assert_near!(*m, (envelope[i - 1] + envelope[i]) / 2.0, 1e-12);
            let (a, b) = (dev.points[2 * i], dev.points[2 * i + 1]);
            assert_near!((b - a).perp_dot(*m - a) / (b - a).length(), 0.0, 1e-12);
            // isometric on the ruling: m_i is as far from a_i in the plane as on the surface
            assert_near!((*m - a).length(), (inv.striction[j] - s.segment(i).a).length(), 1e-12);
        }
    }

    /// ρ at the middle ruling of the helical surface sampled with `n` rulings over [0, 9].
    fn middle_radius(slope: f64, n: usize) -> f64 {
        let helical = crate::catalogue::AnalyticSurface::HelicalRuled { radius: 1.0, pitch: 0.4, slope };
        let ranges = crate::base::Ranges { u: (0.0, 9.0), v: (-1.0, 1.0), closed: false };
        let radii = envelope_radii(&helical.sample(n, ranges).unwrap());
        radii[radii.len() / 2]
    }

    #[test]
    fn envelope_radius_of_the_helical_surfaces_is_r_plus_p_tan_beta_at_second_order() {
        use crate::catalogue::ORTHOGONAL_SLOPE;
        for (slope, exact) in
            [(std::f64::consts::FRAC_PI_4, 1.4), (ORTHOGONAL_SLOPE, 0.0), (0.3, 1.0 + 0.4 * 0.3f64.tan())]
        {
            let errors: Vec<f64> = [13, 25, 49, 97].iter().map(|&n| (middle_radius(slope, n) - exact).abs()).collect();
            for w in errors.windows(2) {
                let order = (w[0] / w[1]).log2();
                assert!((1.8..2.3).contains(&order), "slope {slope}: errors {errors:?}");
            }
            assert!(errors[3] < 2e-3, "slope {slope}: errors {errors:?}");
        }
    }

    #[test]
    fn envelope_radii_move_with_rigid_motions_and_flip_with_the_orientation() {
        let s = four_skew_rulings();
        let radii = envelope_radii(&s);
        assert_eq!(radii.len(), 2);
        let motion = DMat4::from_rotation_translation(
            glam::DQuat::from_axis_angle(DVec3::new(1.0, 2.0, -0.5).normalize(), 0.9),
            DVec3::new(3.0, -1.0, 2.0),
        );
        let flat: Vec<f64> = s.points().iter().flat_map(|&p| motion.transform_point3(p).to_array()).collect();
        for (a, b) in radii.iter().zip(envelope_radii(&RuledSurface::from_flat(&flat).unwrap())) {
            assert_near!(*a, b, 1e-12);
        }
        // the same lines in the opposite order: the step and the radius change sign
        let reversed: Vec<f64> =
            s.points().chunks(2).rev().flat_map(|p| [p[0].to_array(), p[1].to_array()]).flatten().collect();
        let back = envelope_radii(&RuledSurface::from_flat(&reversed).unwrap());
        assert_near!(radii[0], -back[1], 1e-12);
    }
}
