//! Where lines and planes meet (beyond the paper: the incidences a dragged handle is snapped
//! by, `snap/`): the closest points of two lines, a line through a plane, two planes in a line,
//! a point's shadow on a line or a plane.
//!
//! A line is p + t·u with u any non-zero vector (a ruling a_i → b_i is a_i + t·(b_i − a_i), so a
//! point found on it as a parameter t is on it to rounding, however the ruling is scaled); a
//! plane is n·(x − c) = 0 with n ≠ 0. Every function returns `None` where the answer does not
//! exist or is not unique (parallel lines, a line parallel to a plane, parallel planes), never a
//! NaN from a division by zero: the thresholds are the sines of [`PARALLEL_SIN`].

use crate::tolerance::PARALLEL_SIN;
use glam::DVec3;

/// The parameters (s, t) of the closest points p + s·u and q + t·v of two lines; `None` when
/// they are parallel (|sin| of their angle below [`PARALLEL_SIN`]) or a direction vanishes.
///
/// With w = p − q, a = u·u, b = u·v, c = v·v, d = u·w, e = v·w and D = ac − b² = |u × v|²:
///   s = (be − cd)/D,  t = (ae − bd)/D.                                                   (M1)
pub fn closest_on_lines(p: DVec3, u: DVec3, q: DVec3, v: DVec3) -> Option<(f64, f64)> {
    let (a, b, c) = (u.dot(u), u.dot(v), v.dot(v));
    let w = p - q;
    let (d, e) = (u.dot(w), v.dot(w));
    let den = u.cross(v).length_squared();
    if !den.is_finite() || den <= PARALLEL_SIN * PARALLEL_SIN * a * c {
        return None;
    }
    Some(((b * e - c * d) / den, (a * e - b * d) / den))
}

/// The parameter t of the shadow (orthogonal projection) of `x` on the line p + t·u:
/// t = u·(x − p)/(u·u); `None` when u vanishes.                                            (M2)
pub fn shadow_on_line(x: DVec3, p: DVec3, u: DVec3) -> Option<f64> {
    let a = u.dot(u);
    (a > 0.0 && a.is_finite()).then(|| u.dot(x - p) / a)
}

/// The shadow of `x` on the plane through `c` with normal `n`: x − (n·(x − c)/(n·n)) n.     (M3)
pub fn shadow_on_plane(x: DVec3, c: DVec3, n: DVec3) -> DVec3 {
    x - (n.dot(x - c) / n.dot(n)) * n
}

/// The distance of `x` from the plane through `c` with normal `n`: |n·(x − c)|/|n|.
pub fn plane_distance(x: DVec3, c: DVec3, n: DVec3) -> f64 {
    n.dot(x - c).abs() / n.length()
}

/// The distance of `x` from the line p + t·u: |(x − p) × u|/|u|.
pub fn line_distance(x: DVec3, p: DVec3, u: DVec3) -> f64 {
    (x - p).cross(u).length() / u.length()
}

/// The parameter t where the line p + t·u meets the plane n·(x − c) = 0:
/// t = n·(c − p)/(n·u); `None` when the line runs parallel to the plane.                  (M4)
pub fn line_through_plane(p: DVec3, u: DVec3, c: DVec3, n: DVec3) -> Option<f64> {
    let nu = n.dot(u);
    if nu.is_nan() || nu.abs() <= PARALLEL_SIN * n.length() * u.length() {
        return None;
    }
    Some(n.dot(c - p) / nu)
}

/// The line where two planes meet, as a point and a direction (m = n₁ × n₂); the point is the
/// one nearest the origin of the frame `near` (so that it is well scaled); `None` when the
/// planes are parallel.
///
/// The point x on both planes nearest `near` solves n₁·x = n₁·c₁, n₂·x = n₂·c₂, m·x = m·near:
///   x = near + (h₁ (n₂ × m) + h₂ (m × n₁))/|m|²,  h_k = n_k·(c_k − near)                 (M5)
/// (n₁·(n₂ × m) = n₂·(m × n₁) = |m|², and the other products vanish).
pub fn planes_meet(c1: DVec3, n1: DVec3, c2: DVec3, n2: DVec3, near: DVec3) -> Option<(DVec3, DVec3)> {
    let m = n1.cross(n2);
    let mm = m.length_squared();
    if !mm.is_finite() || mm <= PARALLEL_SIN * PARALLEL_SIN * n1.length_squared() * n2.length_squared() {
        return None;
    }
    let (h1, h2) = (n1.dot(c1 - near), n2.dot(c2 - near));
    let x = near + (h1 * n2.cross(m) + h2 * m.cross(n1)) / mm;
    Some((x, m))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;
    use crate::tolerance::test::EXACT;

    #[test]
    fn closest_points_of_skew_lines() {
        // the x-axis and the line through (0, 0, 1) along y: closest at the origin and (0, 0, 1)
        let (s, t) = closest_on_lines(DVec3::new(-2.0, 0.0, 0.0), DVec3::X, DVec3::new(0.0, 3.0, 1.0), DVec3::Y)
            .expect("skew lines have closest points");
        assert_eq!((s, t), (2.0, -3.0));
        // intersecting lines: the closest points coincide
        let p = DVec3::new(1.0, 2.0, 3.0);
        let (s, t) = closest_on_lines(p, DVec3::new(1.0, 1.0, 0.0), p + DVec3::new(0.0, 0.0, 5.0), DVec3::Z).unwrap();
        assert_near!(p + s * DVec3::new(1.0, 1.0, 0.0), p + DVec3::new(0.0, 0.0, 5.0) + t * DVec3::Z, EXACT);
    }

    #[test]
    fn parallel_or_degenerate_lines_have_no_closest_points() {
        assert_eq!(closest_on_lines(DVec3::ZERO, DVec3::X, DVec3::Y, 2.0 * DVec3::X), None);
        assert_eq!(closest_on_lines(DVec3::ZERO, DVec3::ZERO, DVec3::Y, DVec3::X), None);
        assert_eq!(closest_on_lines(DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::splat(f64::NAN)), None);
        // a sine of 1e-12: parallel
        assert_eq!(closest_on_lines(DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::new(1.0, 1e-12, 0.0)), None);
    }

    #[test]
    fn oblique_skew_lines_meet_their_common_normal() {
        // directions neither orthogonal nor of unit length (u·v ≠ 0 in (M1)): the segment between
        // the closest points is orthogonal to both lines, and its length is their distance
        let (p, u) = (DVec3::new(1.0, -2.0, 0.5), DVec3::new(2.0, 1.0, -1.0));
        let (q, v) = (DVec3::new(-3.0, 0.0, 4.0), DVec3::new(0.5, -1.5, 3.0));
        let (s, t) = closest_on_lines(p, u, q, v).unwrap();
        let (x, y) = (p + s * u, q + t * v);
        let scale = (x - y).length() * u.length().max(v.length());
        assert!((x - y).dot(u).abs() <= 1e-14 * scale && (x - y).dot(v).abs() <= 1e-14 * scale);
        let n = u.cross(v).normalize();
        assert!(((x - y).length() - (p - q).dot(n).abs()).abs() <= 1e-14);
    }

    #[test]
    fn a_line_and_a_plane_or_two_planes_are_parallel_by_the_sine_whatever_the_lengths() {
        // a line at a sine of 2e-9 to a plane meets it, at 5e-10 not; two planes likewise — with
        // vectors of lengths 10³ and 10⁻³ as with unit ones
        for (ln, lu) in [(1.0f64, 1.0f64), (1e3, 1e-3), (1e-3, 1e3)] {
            for (sine, meets) in [(2e-9f64, true), (5e-10, false)] {
                let u = DVec3::new((1.0 - sine * sine).sqrt(), 0.0, sine) * lu;
                let found = line_through_plane(DVec3::Z, u, DVec3::ZERO, ln * DVec3::Z);
                assert_eq!(found.is_some(), meets, "line: sine {sine}, lengths {ln} and {lu}");
                let n2 = DVec3::new(0.0, sine, (1.0 - sine * sine).sqrt()) * lu;
                let met = planes_meet(DVec3::ZERO, ln * DVec3::Z, DVec3::X, n2, DVec3::ZERO);
                assert_eq!(met.is_some(), meets, "planes: sine {sine}, lengths {ln} and {lu}");
            }
        }
    }

    #[test]
    fn the_parallel_threshold_is_the_sine_of_the_angle_whatever_the_lengths() {
        // a sine of 2e-9 (above PARALLEL_SIN = 1e-9) has closest points, 5e-10 not — with
        // directions of lengths 10³ and 10⁻³ as with unit ones
        for (lu, lv) in [(1.0f64, 1.0f64), (1e3, 1e-3), (1e-3, 1e3)] {
            for (sine, meets) in [(2e-9f64, true), (5e-10, false)] {
                let v = DVec3::new((1.0 - sine * sine).sqrt(), sine, 0.0) * lv;
                let found = closest_on_lines(DVec3::ZERO, lu * DVec3::X, DVec3::Z, v);
                assert_eq!(found.is_some(), meets, "sine {sine}, lengths {lu} and {lv}");
            }
        }
    }

    #[test]
    fn shadows_and_distances() {
        let t = shadow_on_line(DVec3::new(3.0, 4.0, 0.0), DVec3::ZERO, DVec3::new(2.0, 0.0, 0.0)).unwrap();
        assert_eq!(t, 1.5);
        assert_eq!(shadow_on_line(DVec3::X, DVec3::ZERO, DVec3::ZERO), None);
        assert_eq!(
            shadow_on_plane(DVec3::new(1.0, 2.0, 7.0), DVec3::Z, DVec3::new(0.0, 0.0, 2.0)),
            DVec3::new(1.0, 2.0, 1.0)
        );
        assert_eq!(plane_distance(DVec3::new(1.0, 2.0, 7.0), DVec3::Z, DVec3::new(0.0, 0.0, 2.0)), 6.0);
        assert_eq!(line_distance(DVec3::new(1.0, 2.0, 7.0), DVec3::ZERO, DVec3::new(0.0, 0.0, 3.0)), 5f64.sqrt());
    }

    #[test]
    fn a_line_through_a_plane() {
        let t = line_through_plane(DVec3::new(1.0, 1.0, 5.0), DVec3::new(0.0, 1.0, -2.0), DVec3::ZERO, DVec3::Z);
        assert_eq!(t, Some(2.5));
        // parallel to it: no point
        assert_eq!(line_through_plane(DVec3::Z, DVec3::X, DVec3::ZERO, DVec3::Z), None);
        assert_eq!(line_through_plane(DVec3::Z, DVec3::X, DVec3::ZERO, DVec3::ZERO), None);
    }

    #[test]
    fn two_planes_meet_in_a_line() {
        // z = 1 and x = 2: the line (2, y, 1) along ±y; the point nearest (5, 7, 9) is (2, 7, 1)
        let near = DVec3::new(5.0, 7.0, 9.0);
        let (x, m) = planes_meet(DVec3::Z, DVec3::Z, DVec3::new(2.0, 0.0, 0.0), DVec3::X, near).unwrap();
        assert_near!(x, DVec3::new(2.0, 7.0, 1.0), EXACT);
        assert_eq!(m.cross(DVec3::Y), DVec3::ZERO);
        // oblique planes: the point is on both
        let (c1, n1, c2, n2) =
            (DVec3::new(1.0, 0.0, 0.0), DVec3::new(1.0, 2.0, 3.0), DVec3::Y, DVec3::new(-1.0, 0.5, 2.0));
        let (x, m) = planes_meet(c1, n1, c2, n2, DVec3::ZERO).unwrap();
        assert!(plane_distance(x, c1, n1) < EXACT && plane_distance(x, c2, n2) < EXACT);
        assert!(m.dot(n1).abs() < EXACT && m.dot(n2).abs() < EXACT);
        assert_eq!(planes_meet(DVec3::ZERO, DVec3::Z, DVec3::Z, DVec3::Z, DVec3::ZERO), None);
    }
}
