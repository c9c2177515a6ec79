//! The exact unfolding of a discrete developable strip onto the plane (Section 3: the development
//! of a developable surface, here face by face rather than through its conoidal model).
//!
//! Each face a_i b_i b_{i+1} a_{i+1} of a developable strip is a plane quadrilateral (its rulings
//! are coplanar). The unfolding lays ruling 0 along the x-axis from the origin and then each face in
//! turn against the ruling it shares with the face before: in the face's own frame — u along ruling
//! i, w orthogonal to it in the face, towards ruling i + 1 — the points of ruling i + 1 have the
//! coordinates x = (p − a_i)·u, y = (p − a_i)·w, which the plane frame of ruling i's image takes
//! over. The face goes on the other side of the shared ruling than the face before it (a strip
//! unrolls, it does not fold back), the first one to the left of ruling 0. Every distance within a
//! face, and so every edge length and every angle, is kept to rounding.
//!
//! For a developable strip the unfolding is congruent to Section 3's development through the
//! conoidal model ([`crate::ruled::Development`], tested): bending the hinge chain of a strip whose
//! consecutive rulings meet flattens it, and the projection then changes nothing.

use super::coplanar::{max_off_plane, size_of};
use crate::error::{Error, Result};
use crate::msg;
use crate::ruled::RuledSurface;
use crate::tolerance::{TORSAL_HEIGHT, ZERO_LENGTH_REL};
use glam::{DVec2, DVec3};

/// A strip unfolded onto the plane: the images A_i, B_i of its ends a_i, b_i.
#[derive(Debug, Clone, PartialEq)]
pub struct Unfolding {
    /// A_0, B_0, A_1, B_1, ….
    pub points: Vec<DVec2>,
}

/// How far a flat pattern is from an isometry of the strip it was made from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IsometryError {
    /// The largest relative change of a distance between two corners of a face (its four edges and
    /// two diagonals), |ℓ′ − ℓ|/ℓ; distances below the rounding of the strip's size are compared
    /// absolutely.
    pub length: f64,
    /// The largest change of a corner angle of a face, radians.
    pub angle: f64,
}

impl Unfolding {
    /// The exact unfolding of a developable strip (see the module). Refuses a strip with a pair of
    /// rulings that is not torsal (the tetrahedron of its ends higher than [`TORSAL_HEIGHT`] of its
    /// size over its largest face, `coplanar::off_plane`: unfold it with
    /// Section 3's approximate development instead) and consecutive rulings on one line (a face
    /// without width). O(N).
    pub fn of(surface: &RuledSurface) -> Result<Unfolding> {
        let scale = size_of(surface.points());
        let (height, pair) = max_off_plane(surface);
        if let Some(i) = pair.filter(|_| height > TORSAL_HEIGHT * scale) {
            let delta = super::coplanar::pair_delta(&surface.invariants(), i);
            return Err(Error::degenerate(
                "strip",
                msg!("not-developable", i = i, j = i + 1, height = height, max = TORSAL_HEIGHT * scale, delta = delta),
            ));
        }
        let p = surface.points();
        let n = surface.len();
        let mut out = Vec::with_capacity(2 * n);
        out.push(DVec2::ZERO);
        out.push(DVec2::new((p[1] - p[0]).length(), 0.0));
        let mut side = 1.0;
        for i in 0..n - 1 {
            let (a, b) = (p[2 * i], p[2 * i + 1]);
            let (a1, b1) = (p[2 * i + 2], p[2 * i + 3]);
            let u = (b - a).normalize();
            // w: in the face, orthogonal to ruling i, towards ruling i + 1
            let w = [(a1 + b1) * 0.5, a1, b1]
                .into_iter()
                .map(|q| (q - a).reject_from_normalized(u))
                .find(|r| r.length() > ZERO_LENGTH_REL * scale)
                .ok_or_else(|| Error::degenerate("strip", msg!("rulings-collinear", i = i, j = i + 1)))?
                .normalize();
            let (a2, b2) = (out[2 * i], out[2 * i + 1]);
            let u2 = (b2 - a2).normalize();
            if i > 0 {
                // the face before lies on one side of ruling i's image: this one on the other
                let before = (out[2 * i - 2] + out[2 * i - 1]) * 0.5 - a2;
                side = if u2.perp_dot(before) > 0.0 { -1.0 } else { 1.0 };
            }
            let w2 = side * u2.perp();
            let image = |q: DVec3| a2 + (q - a).dot(u) * u2 + (q - a).dot(w) * w2;
            out.push(image(a1));
            out.push(image(b1));
        }
        Ok(Unfolding { points: out })
    }

    /// The coordinates as a flat array: x, y of A_i, then of B_i, per ruling.
    pub fn flat(&self) -> &[f64] {
        bytemuck::cast_slice(&self.points)
    }
}

/// How far the flat `points` (A_i, B_i per ruling) are from an isometry of `surface` (see
/// [`IsometryError`]); `points` must have two per ruling.
pub fn isometry_error(surface: &RuledSurface, points: &[DVec2]) -> IsometryError {
    let p = surface.points();
    let floor = ZERO_LENGTH_REL * size_of(p);
    let mut out = IsometryError { length: 0.0, angle: 0.0 };
    for i in 0..surface.len() - 1 {
        let q3 = [p[2 * i], p[2 * i + 1], p[2 * i + 3], p[2 * i + 2]];
        let q2 = [points[2 * i], points[2 * i + 1], points[2 * i + 3], points[2 * i + 2]];
        for (j, k) in [(0, 1), (1, 2), (2, 3), (3, 0), (0, 2), (1, 3)] {
            let (l3, l2) = ((q3[j] - q3[k]).length(), (q2[j] - q2[k]).length());
            let error = if l3 > floor { (l2 - l3).abs() / l3 } else { (l2 - l3).abs() / floor.max(1.0) };
            out.length = out.length.max(error);
        }
        for j in 0..4 {
            let (e3, f3) = (q3[(j + 1) % 4] - q3[j], q3[(j + 3) % 4] - q3[j]);
            let (e2, f2) = (q2[(j + 1) % 4] - q2[j], q2[(j + 3) % 4] - q2[j]);
            if e3.length() > floor && f3.length() > floor {
                let a3 = e3.cross(f3).length().atan2(e3.dot(f3));
                let a2 = e2.perp_dot(f2).abs().atan2(e2.dot(f2));
                out.angle = out.angle.max((a3 - a2).abs());
            }
        }
    }
    out
}

/// The faces whose two rulings cross inside their segments (the strip runs through its edge of
/// regression there: a paper model would have to pass through itself). Rulings that only share an
/// end, as at a cone's apex, do not cross.
pub fn crossed_faces(points: &[DVec2]) -> Vec<usize> {
    let n = points.len() / 2;
    let size = points.iter().fold(0.0f64, |m, p| m.max(p.length())).max(1.0);
    let tol = ZERO_LENGTH_REL * size;
    (0..n.saturating_sub(1))
        .filter(|&i| {
            let (a, b, c, d) = (points[2 * i], points[2 * i + 1], points[2 * i + 2], points[2 * i + 3]);
            let (d1, d2) = ((b - a).perp_dot(c - a), (b - a).perp_dot(d - a));
            let (d3, d4) = ((d - c).perp_dot(a - c), (d - c).perp_dot(b - c));
            let scale1 = (b - a).length();
            let scale2 = (d - c).length();
            d1 * d2 < 0.0
                && d3 * d4 < 0.0
                && d1.abs().min(d2.abs()) > tol * scale1
                && d3.abs().min(d4.abs()) > tol * scale2
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;
    use crate::developable::construct::{cone, cylinder, rectifying_developable, tangent_surface, Span};
    use crate::ruled::Development;
    use std::f64::consts::{PI, TAU};

    use crate::developable::construct::tests::helix;

    /// The discrete tangent surface of a helix develops its regression polygon onto a regular
    /// polygon: equal edges ℓ and turns θ, on the circle of radius ℓ/(2 sin(θ/2)).
    #[test]
    fn the_tangent_surface_of_a_helix_unfolds_its_edge_onto_a_circle() {
        let (r, p, m) = (1.0, 0.3, 40);
        let c = helix(m, r, p, 1.5);
        let s = tangent_surface(&c, Span { from: 0.0, to: 1.0 }).unwrap();
        let flat = Unfolding::of(&s).unwrap();
        let e = isometry_error(&s, &flat.points);
        assert!(e.length <= 1e-12 && e.angle <= 1e-12, "{e:?}");
        // the images of c_1 … c_{M−1} (the ends a) on a circle
        let l = (c[1] - c[0]).length();
        let theta = ((c[1] - c[0]).normalize()).angle_between((c[2] - c[1]).normalize());
        let radius = l / (2.0 * (theta / 2.0).sin());
        let a: Vec<DVec2> = (0..m - 1).map(|i| flat.points[2 * i]).collect();
        // the centre: on the bisector of the first edge, at the distance of the circle
        let (p0, p1) = (a[0], a[1]);
        let mid = (p0 + p1) / 2.0;
        let toward = (a[2] - mid).reject_from((p1 - p0).normalize()).normalize();
        let centre = mid + toward * (radius * radius - l * l / 4.0).sqrt();
        for q in &a {
            assert_near!((*q - centre).length(), radius, 1e-12);
        }
        // the radius tends to (r² + p²)/r, the development of the smooth helix, at order 2
        let radius_of = |m: usize| {
            let c = helix(m, r, p, 1.5);
            let l = (c[1] - c[0]).length();
            let theta = (c[1] - c[0]).normalize().angle_between((c[2] - c[1]).normalize());
            l / (2.0 * (theta / 2.0).sin())
        };
        let exact = (r * r + p * p) / r;
        let errors: Vec<f64> = [20, 40, 80].iter().map(|&m| (radius_of(m) - exact).abs()).collect();
        for w in errors.windows(2) {
            assert!(((w[0] / w[1]).log2() - 2.0).abs() < 0.1, "{errors:?}");
        }
    }

    /// A right circular cone of half-angle α: the rulings unfold into a fan of total angle
    /// N·2 arcsin(sin α sin(π/N)) exactly, which tends to the sector 2π sin α.
    #[test]
    fn a_right_circular_cone_unfolds_into_a_sector_of_angle_two_pi_sin_alpha() {
        let (radius, height): (f64, f64) = (1.0, 2.0);
        let sin_alpha = radius / f64::hypot(radius, height);
        let fan = |n: usize| {
            let c: Vec<DVec3> = (0..=n)
                .map(|i| {
                    let u = TAU * i as f64 / n as f64;
                    DVec3::new(radius * u.cos(), radius * u.sin(), 0.0)
                })
                .collect();
            let s = cone(&c, DVec3::new(0.0, 0.0, height), Span { from: 0.0, to: 1.0 }).unwrap();
            let flat = Unfolding::of(&s).unwrap();
            let e = isometry_error(&s, &flat.points);
            assert!(e.length <= 1e-12 && e.angle <= 1e-12, "{e:?}");
            // every A_i at the apex's image, the B_i at slant height from it
            let slant = (radius * radius + height * height).sqrt();
            for i in 0..=n {
                assert_near!(flat.points[2 * i], DVec2::ZERO, 1e-14);
                assert_near!(flat.points[2 * i + 1].length(), slant, 1e-12);
            }
            let (first, last) = (flat.points[1], flat.points[2 * n + 1]);
            // the angle from the first ruling to the last, counter-clockwise (the fan turns left)
            let mut angle = first.angle_to(last);
            if angle <= 0.0 {
                angle += TAU;
            }
            angle
        };
        for n in [12, 24, 48] {
            let exact = n as f64 * 2.0 * (sin_alpha * (PI / n as f64).sin()).asin();
            assert_near!(fan(n), exact, 1e-12);
        }
        let errors: Vec<f64> = [24, 48, 96].iter().map(|&n| (fan(n) - TAU * sin_alpha).abs()).collect();
        for w in errors.windows(2) {
            assert!(((w[0] / w[1]).log2() - 2.0).abs() < 0.1, "{errors:?}");
        }
    }

    /// A circular cylinder cut by the plane z = m x: the cut unrolls onto z = m R cos(s/R),
    /// s the arc length (discretely: the chord lengths summed).
    #[test]
    fn an_obliquely_cut_cylinder_unrolls_its_cut_onto_a_cosine() {
        let (r, m, n) = (1.5, 0.4, 60);
        let c: Vec<DVec3> = (0..=n)
            .map(|i| {
                let u = TAU * i as f64 / n as f64;
                DVec3::new(r * u.cos(), r * u.sin(), m * r * u.cos())
            })
            .collect();
        let s = cylinder(&c, DVec3::Z, Span { from: 0.0, to: 1.0 }).unwrap();
        let flat = Unfolding::of(&s).unwrap();
        let chord = 2.0 * r * (PI / n as f64).sin();
        // the rulings along ±y, the cut at x = arc length (in chords) and height z
        let dir = (flat.points[1] - flat.points[0]).normalize();
        for i in 0..=n {
            let q = flat.points[2 * i];
            let along = q.dot(dir);
            let across = q.perp_dot(dir).abs();
            let u = TAU * i as f64 / n as f64;
            assert_near!(across, i as f64 * chord, 1e-12);
            assert_near!(along, m * r * u.cos() - m * r, 1e-12);
        }
    }

    /// The rectifying developable holds the directrix as a geodesic: it unfolds onto a line.
    #[test]
    fn the_rectifying_developable_unfolds_its_directrix_onto_a_straight_line() {
        let c: Vec<DVec3> =
            (0..80).map(|i| i as f64 / 79.0 * 4.0).map(|u| DVec3::new(u.cos() + u, u.sin(), 0.2 * u * u)).collect();
        let s = rectifying_developable(&c, Span { from: -0.25, to: 0.25 }).unwrap();
        let flat = Unfolding::of(&s).unwrap();
        let e = isometry_error(&s, &flat.points);
        assert!(e.length <= 1e-10 && e.angle <= 1e-10, "{e:?}");
        // the directrix's point on ruling i is its midpoint (v = 0 in [−0.25, 0.25])
        let d: Vec<DVec2> = (0..80).map(|i| (flat.points[2 * i] + flat.points[2 * i + 1]) / 2.0).collect();
        let dir = (d[79] - d[0]).normalize();
        for q in &d {
            assert!((*q - d[0]).perp_dot(dir).abs() < 1e-12, "{}", (*q - d[0]).perp_dot(dir));
        }
    }

    /// Rigid motions change nothing, and Section 3's development through the conoidal model gives
    /// the same pattern (all distances between the corners of the pattern equal).
    #[test]
    fn the_unfolding_is_invariant_and_agrees_with_the_development_of_section_3() {
        let s = tangent_surface(&helix(30, 1.0, 0.5, 1.0), Span { from: 0.2, to: 1.5 }).unwrap();
        let q = glam::DQuat::from_axis_angle(DVec3::new(1.0, -2.0, 0.5).normalize(), 1.1);
        let moved = s.map_points(|p| q * p + DVec3::new(4.0, 5.0, -6.0)).unwrap();
        let (a, b) = (Unfolding::of(&s).unwrap(), Unfolding::of(&moved).unwrap());
        for (x, y) in a.points.iter().zip(&b.points) {
            assert_near!(*x, *y, 1e-12);
        }
        let d = Development::of(&s).points;
        for i in (0..a.points.len()).step_by(3) {
            for j in (0..a.points.len()).step_by(5) {
                let (l1, l2) = ((a.points[i] - a.points[j]).length(), (d[i] - d[j]).length());
                assert_near!(l1, l2, 1e-9);
            }
        }
    }

    #[test]
    fn a_skew_strip_and_collinear_rulings_are_refused() {
        let skew = RuledSurface::from_flat(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0]).unwrap();
        let e = Unfolding::of(&skew).unwrap_err();
        assert_eq!((e.code(), e.message().reason), ("degenerate", "not-developable"));
        let collinear = RuledSurface::from_flat(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 2.0, 0.0, 0.0, 3.0, 0.0, 0.0]).unwrap();
        assert_eq!(Unfolding::of(&collinear).unwrap_err().message().reason, "rulings-collinear");
    }

    #[test]
    fn crossed_faces_are_found_and_a_shared_apex_is_no_crossing() {
        let bow = [DVec2::ZERO, DVec2::new(0.0, 2.0), DVec2::new(-1.0, 1.0), DVec2::new(1.0, 1.5)];
        assert_eq!(crossed_faces(&bow), [0]);
        let fan = [DVec2::ZERO, DVec2::new(0.0, 2.0), DVec2::ZERO, DVec2::new(1.0, 2.0)];
        assert!(crossed_faces(&fan).is_empty());
        // turned and moved off the origin: the same; a face whose rulings do not meet, and one
        // whose second ruling ends on the first, are no crossing either
        let apart = [DVec2::ZERO, DVec2::new(0.0, 2.0), DVec2::new(1.0, 0.0), DVec2::new(1.5, 2.0)];
        let touching = [DVec2::ZERO, DVec2::new(0.0, 2.0), DVec2::new(0.0, 1.0), DVec2::new(1.0, 1.5)];
        for (angle, shift) in [(0.0, DVec2::ZERO), (0.7, DVec2::new(30.0, -20.0)), (-2.0, DVec2::new(-5.0, 8.0))] {
            let turn = DVec2::from_angle(angle);
            let moved = |q: &[DVec2; 4]| q.map(|p| turn.rotate(p) + shift);
            assert_eq!(crossed_faces(&moved(&bow)), [0], "{angle} {shift}");
            assert!(crossed_faces(&moved(&fan)).is_empty(), "{angle} {shift}");
            assert!(crossed_faces(&moved(&apart)).is_empty(), "{angle} {shift}");
            assert!(crossed_faces(&moved(&touching)).is_empty(), "{angle} {shift}");
        }
        // two faces: only the second crossed
        let two = [apart[0], apart[1], apart[2], apart[3], DVec2::new(0.0, 2.5), DVec2::new(2.0, -0.5)];
        assert_eq!(crossed_faces(&two), [1]);
    }

    /// A 20 × 10 rectangle (two rulings of length 10, 20 apart) laid flat with B₁ one unit too
    /// high: its edge A₁B₁ is 10 % long (the largest relative error; in absolute terms 1, so a
    /// relative error is what is said), the corners at B₀ and B₁ are off by atan(1/20).
    #[test]
    fn the_isometry_error_of_a_flat_image_one_corner_off() {
        let a = |x: f64, y: f64| DVec3::new(x, y, 0.0);
        let s = RuledSurface::from_points(vec![a(0.0, 0.0), a(0.0, 10.0), a(20.0, 0.0), a(20.0, 10.0)]).unwrap();
        let exact = [DVec2::new(0.0, 0.0), DVec2::new(0.0, 10.0), DVec2::new(20.0, 0.0), DVec2::new(20.0, 10.0)];
        assert_eq!(isometry_error(&s, &exact), IsometryError { length: 0.0, angle: 0.0 });
        let mut off = exact;
        off[3].y = 11.0;
        let e = isometry_error(&s, &off);
        assert_near!(e.length, 0.1, 1e-15);
        assert_near!(e.angle, (1.0f64 / 20.0).atan(), 1e-15);
        // a cone's apex (A₀ = A₁, an edge of no length) split by 1.5 in the image: that edge's
        // error is said in absolute terms (of at least a unit), 1.5, the largest
        let c = RuledSurface::from_points(vec![a(0.0, 0.0), a(10.0, 0.0), a(0.0, 0.0), a(0.0, 10.0)]).unwrap();
        let split = [DVec2::new(0.0, 0.0), DVec2::new(10.0, 0.0), DVec2::new(0.0, -1.5), DVec2::new(0.0, 10.0)];
        assert_near!(isometry_error(&c, &split).length, 1.5, 1e-15);
    }

    /// A flat rectangle 200 × 100 with one end lifted off its plane: by half of TORSAL_HEIGHT of
    /// its size it is still unfolded (and `flat()` gives its image's x, y per point), by twice it
    /// is refused as not developable.
    #[test]
    fn a_strip_is_unfolded_up_to_the_torsal_height_of_its_size() {
        let a = |x: f64, y: f64, z: f64| DVec3::new(x, y, z);
        let lifted = |z: f64| {
            RuledSurface::from_points(vec![
                a(0.0, 0.0, 0.0),
                a(0.0, 100.0, 0.0),
                a(200.0, 0.0, 0.0),
                a(200.0, 100.0, z),
            ])
            .unwrap()
        };
        let size = size_of(lifted(0.0).points());
        let u = Unfolding::of(&lifted(0.5 * TORSAL_HEIGHT * size)).unwrap();
        assert_eq!(u.flat().len(), 8);
        for (k, p) in u.points.iter().enumerate() {
            assert_eq!([u.flat()[2 * k], u.flat()[2 * k + 1]], [p.x, p.y]);
        }
        assert_near!(u.points[3], DVec2::new(100.0, 200.0), 1e-9); // ruling 0 along x, the strip to +y
        let e = Unfolding::of(&lifted(2.0 * TORSAL_HEIGHT * size)).unwrap_err();
        assert_eq!(e.message().reason, "not-developable");
    }

    /// A crossing is counted only when each ruling's ends lie off the other's line by more than
    /// ZERO_LENGTH_REL of the pattern's size (at least 1) per unit of that line's length: exactly at
    /// the tolerance is no crossing, twice it is one. The same with the two rulings' roles swapped,
    /// for a ruling of length ½ (the tolerance scales with it) and off the origin (it scales with
    /// the pattern's size, not with the distance from the origin).
    #[test]
    fn a_crossing_is_counted_beyond_the_tolerance_of_the_size_and_the_ruling() {
        let p = DVec2::new;
        let crossed =
            |q: [DVec2; 4]| (!crossed_faces(&q).is_empty(), !crossed_faces(&[q[2], q[3], q[0], q[1]]).is_empty());
        let tol = ZERO_LENGTH_REL;
        // unit rulings within the unit disc: the tolerance is ZERO_LENGTH_REL itself
        let unit = |y: f64| [p(0.0, 0.0), p(1.0, 0.0), p(0.5, y), p(0.5, -0.5)];
        assert_eq!(crossed(unit(tol)), (false, false));
        assert_eq!(crossed(unit(2.0 * tol)), (true, true));
        // a ruling of length ½: its tolerance is halved
        let half = |y: f64| [p(-0.25, 0.0), p(0.25, 0.0), p(0.0, y), p(0.0, -0.5)];
        assert_eq!(crossed(half(0.5 * tol)), (false, false));
        assert_eq!(crossed(half(2.0 * tol)), (true, true));
        // a unit ruling 100 from the origin: the pattern's size is |(100.5, −1)|, the tolerance
        // about 1.005e-10
        let far = |y: f64| [p(100.0, 0.0), p(101.0, 0.0), p(100.5, y), p(100.5, -1.0)];
        let size = p(100.5, -1.0).length();
        assert_eq!(crossed(far(0.5 * tol * size)), (false, false));
        assert_eq!(crossed(far(2.0 * tol * size)), (true, true));
    }

    /// Distances at the rounding of the strip's size: an edge exactly ZERO_LENGTH_REL long in a
    /// strip of size 1 is compared absolutely (1e-12 too long is an error of 1e-12, not 100 %) and
    /// has no corner angle (turned by 45° in the image, no angle changes); a cone 1e14 across
    /// whose apex is split by 1.5 times the rounding of its size has that edge's error said in
    /// units of that rounding, 1.5.
    #[test]
    fn the_isometry_error_measures_short_edges_against_the_rounding_of_the_size() {
        let a = |x: f64, y: f64| DVec3::new(x, y, 0.0);
        let floor = ZERO_LENGTH_REL;
        let s = RuledSurface::from_points(vec![a(0.0, 0.0), a(0.0, 0.5), a(floor, 0.0), a(0.5, 0.5)]).unwrap();
        assert_eq!(size_of(s.points()), 1.0);
        let image = |a1: DVec2| [DVec2::new(0.0, 0.0), DVec2::new(0.0, 0.5), a1, DVec2::new(0.5, 0.5)];
        let longer = isometry_error(&s, &image(DVec2::new(2.0 * floor, 0.0)));
        assert!(longer.length > 0.5 * floor && longer.length < 4.0 * floor, "{longer:?}");
        let turned = isometry_error(&s, &image(floor * DVec2::from_angle(-PI / 4.0)));
        assert!(turned.angle < 1e-11, "{turned:?}");
        let k = 1e13;
        let c = RuledSurface::from_points(vec![a(0.0, 0.0), a(10.0 * k, 0.0), a(0.0, 0.0), a(0.0, 10.0 * k)]).unwrap();
        let floor = ZERO_LENGTH_REL * size_of(c.points());
        let split =
            [DVec2::new(0.0, 0.0), DVec2::new(10.0 * k, 0.0), DVec2::new(0.0, -1.5 * floor), DVec2::new(0.0, 10.0 * k)];
        assert_near!(isometry_error(&c, &split).length, 1.5, 1e-12);
    }

    /// A face whose next ruling crosses the line of ruling i at its midpoint (to within the
    /// rounding of the strip's size): the face's side is taken from that ruling's end a_{i+1}, so
    /// A₁ lands where a₁ is, to the left of ruling 0.
    #[test]
    fn a_next_ruling_through_the_line_of_the_last_is_laid_out_from_its_end() {
        let a = |x: f64, y: f64| DVec3::new(x, y, 0.0);
        let d = -1e-10; // the midpoint of ruling 1, off ruling 0's line by far less than 1e-12 × 1414
        let s =
            RuledSurface::from_points(vec![a(0.0, 0.0), a(0.0, 1000.0), a(500.0, 0.0), a(-500.0 + 2.0 * d, 1000.0)])
                .unwrap();
        let u = Unfolding::of(&s).unwrap();
        assert_near!(u.points[2], DVec2::new(0.0, 500.0), 1e-9);
        assert_near!(u.points[3], DVec2::new(1000.0, -500.0), 1e-9);
    }
}
