//! When two consecutive rulings are coplanar (Section 2: the distribution parameter
//! δ_{i,i+1} = h_{i,i+1}/φ_{i,i+1} (1) vanishes exactly for a pair that meets or runs parallel).
//!
//! **Why not |δ| itself.** δ is the measure of the paper, but as a test of coplanarity of rulings
//! stored in `f64` it is ill-conditioned where the rulings meet at small angles: moving an end b of
//! a ruling of length L by ε changes δ by up to |d| ε / (L φ²) (d = a_{i+1} − a_i). The ends are
//! rounded to ε ≈ 2⁻⁵³ |p|, so a coplanar pair at φ = 10⁻⁶ — a cylinder's rulings after one drag —
//! has |δ| ≈ 10⁻⁵ of pure rounding: no strip of `f64` points does better. The measure the points
//! resolve is the **height** of the tetrahedron of the pair's four ends a_i, b_i, a_{i+1}, b_{i+1}
//! over its largest face:
//!
//! η_{i,i+1} = |det(b_i − a_i, a_{i+1} − a_i, b_{i+1} − a_i)| / N_max = 3V / A_max,
//!
//! N_max the largest of the four faces' normals (each twice the face's area A), that is the distance
//! of the end opposite the largest face from that face's plane — the least of the tetrahedron's four
//! heights, taken over the plane that its three ends define best. η = 0 exactly when the rulings are
//! coplanar, it is a length (rigid-motion invariant, of the order of ε where the pair is coplanar
//! to rounding), and where both are defined
//!
//! |δ| = η N_max / (|a_i b_i| |a_{i+1} b_{i+1}| sin φ · φ)
//!
//! (the determinant is |a_i b_i| |a_{i+1} b_{i+1}| h sin φ). A pair is **torsal** when η ≤
//! [`TORSAL_HEIGHT`] times the strip's size; [`max_abs_delta`] reports δ of the pairs that are not,
//! so that a strip the core finds developable reads δ = 0, not its rounding.

use crate::ruled::RuledSurface;
use crate::tolerance::TORSAL_HEIGHT;
use glam::DVec3;

/// The diagonal of the bounding box of `points`, at least 1: the size against which η is judged.
pub fn size_of(points: &[DVec3]) -> f64 {
    let (lo, hi) = points
        .iter()
        .fold((DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)), |(lo, hi), &p| (lo.min(p), hi.max(p)));
    (hi - lo).length().max(1.0)
}

/// η (see the module): the height of the tetrahedron a0 b0 a1 b1 over its largest face (its least
/// height); 0 when all four points lie on one line.
pub fn off_plane(a0: DVec3, b0: DVec3, a1: DVec3, b1: DVec3) -> f64 {
    let (u, d, w) = (b0 - a0, a1 - a0, b1 - a0);
    let volume = u.dot(d.cross(w)).abs();
    let face =
        u.cross(d).length().max(u.cross(w).length()).max(d.cross(w).length()).max((a1 - b0).cross(b1 - b0).length());
    if face > 0.0 {
        volume / face
    } else {
        0.0
    }
}

/// η of the pair (j, j + 1) of the endpoints `p` (a_0, b_0, a_1, …).
pub fn pair_off_plane(p: &[DVec3], j: usize) -> f64 {
    off_plane(p[2 * j], p[2 * j + 1], p[2 * j + 2], p[2 * j + 3])
}

/// Whether the pair (j, j + 1) of `p` is torsal: η ≤ [`TORSAL_HEIGHT`] · `scale`.
pub fn is_torsal(p: &[DVec3], j: usize, scale: f64) -> bool {
    pair_off_plane(p, j) <= TORSAL_HEIGHT * scale
}

/// The largest η of a pair of `surface` (0 for fewer than two rulings), and the pair where it is.
pub fn max_off_plane(surface: &RuledSurface) -> (f64, Option<usize>) {
    let p = surface.points();
    (0..surface.len().saturating_sub(1)).fold((0.0, None), |worst, j| {
        let h = pair_off_plane(p, j);
        if h > worst.0 {
            (h, Some(j))
        } else {
            worst
        }
    })
}

/// δ_{i,i+1} = h/φ (1) of pair `i`, also where the pair counts as parallel (then the unsigned
/// distance of the lines over their angle).
pub fn pair_delta(inv: &crate::ruled::invariants::Invariants, i: usize) -> f64 {
    if inv.parallel[i] {
        inv.distance[i] / inv.angle[i]
    } else {
        inv.distribution[i]
    }
}

/// The largest |δ_{i,i+1}| (1) of the pairs that are not torsal, and the pair where it is: (0, None)
/// for a strip whose pairs are all torsal (a developable: δ = 0 to the precision its points carry,
/// see the module). A pair that counts as parallel ([`crate::tolerance::PARALLEL_SIN`]) but is
/// not torsal — rulings 1e-10 apart in angle and a unit apart — has |δ| = distance / φ, huge.
pub fn max_abs_delta(surface: &RuledSurface) -> (f64, Option<usize>) {
    let p = surface.points();
    let scale = size_of(p);
    let inv = surface.invariants();
    let mut worst = (0.0, None);
    for i in 0..inv.distribution.len() {
        let d = pair_delta(&inv, i).abs();
        if d > worst.0 && !is_torsal(p, i, scale) {
            worst = (d, Some(i));
        }
    }
    worst
}

/// The largest |δ| (1) of the non-parallel pairs as computed, rounding and all: what the tests
/// hold against 1e-12 where the rulings meet at angles that resolve it.
#[cfg(test)]
pub(crate) fn raw_max_abs_delta(s: &RuledSurface) -> f64 {
    let inv = s.invariants();
    inv.distribution.iter().zip(&inv.parallel).filter(|(_, &p)| !p).fold(0.0, |m, (d, _)| m.max(d.abs()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_height_is_the_distance_of_an_end_from_the_plane_of_the_largest_face() {
        let (a0, b0, a1) = (DVec3::ZERO, DVec3::new(0.0, 2.0, 0.0), DVec3::new(1.0, 0.0, 0.0));
        // b1 at 1e-3 above the plane z = 0 of the other three, their face the largest (area 1;
        // the faces with b1 have areas ≈ 0.3, 0.15, 0.55)
        let b1 = DVec3::new(0.3, 0.3, 1e-3);
        let h = off_plane(a0, b0, a1, b1);
        // (the least height: b0 lies 3.3e-3 off the plane of a0 a1 b1, a1 6.7e-3 off that of a0 b0 b1)
        assert!((h - 1e-3).abs() < 1e-18, "{h}");
        // order and rigid motions do not change it
        assert_eq!(off_plane(a0, b0, a1, b1), off_plane(a1, b1, a0, b0));
        let q = glam::DQuat::from_axis_angle(DVec3::new(1.0, 2.0, -0.5).normalize(), 0.7);
        let m = |p: DVec3| q * p + DVec3::new(3.0, -1.0, 2.0);
        assert!((off_plane(m(a0), m(b0), m(a1), m(b1)) - h).abs() < 1e-15);
        // coplanar: meeting, parallel, all on one line
        assert_eq!(off_plane(a0, b0, a1, a1 + (b0 - a0) * 2.0), 0.0);
        assert_eq!(off_plane(a0, b0, a1, a0 + (b0 - a0) * 3.0), 0.0);
        assert_eq!(off_plane(a0, b0, 2.0 * b0, 3.0 * b0), 0.0);
    }

    #[test]
    fn a_pair_at_a_tiny_angle_is_torsal_by_its_height_though_its_delta_is_rounding() {
        // two coplanar rulings 2e-7 rad apart, their ends rounded: δ computed is noise of order
        // ε|d|/φ², η is of order ε
        let phi = 2e-7f64;
        let s = RuledSurface::from_points(vec![
            DVec3::new(0.1, 0.2, 0.3),
            DVec3::new(0.1, 0.2, 0.3) + DVec3::new(0.3, 1.0, 0.7).normalize() * 1.7,
            DVec3::new(0.35, 0.2, 0.3),
            DVec3::new(0.35, 0.2, 0.3)
                + glam::DQuat::from_axis_angle(DVec3::new(0.3, 1.0, 0.7).cross(DVec3::X).normalize(), phi)
                    * DVec3::new(0.3, 1.0, 0.7).normalize()
                    * 1.7,
        ])
        .unwrap();
        assert!(max_off_plane(&s).0 < 1e-15, "{:?}", max_off_plane(&s));
        assert_eq!(max_abs_delta(&s), (0.0, None));
    }

    #[test]
    fn a_skew_pair_reports_its_delta_and_a_parallel_pair_is_coplanar() {
        // the hyperboloid's rulings: h and φ known
        let s = RuledSurface::from_points(vec![
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 1.0),
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::new(-1.0, 1.0, 1.0),
        ])
        .unwrap();
        let inv = s.invariants();
        assert_eq!(max_abs_delta(&s), (inv.distribution[0].abs(), Some(0)));
        assert!(inv.distribution[0].abs() > 0.1);
        let parallel = RuledSurface::from_points(vec![
            DVec3::ZERO,
            DVec3::Y,
            DVec3::new(1.0, 0.0, 0.5),
            DVec3::new(1.0, 1.0, 0.5),
        ])
        .unwrap();
        assert_eq!(max_off_plane(&parallel), (0.0, None), "parallel rulings are coplanar");
        assert_eq!(max_abs_delta(&parallel), (0.0, None));
    }

    #[test]
    fn the_tolerance_grows_with_the_strips_size_and_the_first_worst_pair_is_named() {
        // a pair with an end 5e-10 off its plane: torsal in a strip 1 000 across (1e-9), not in
        // one of size 1 (1e-12)
        let pair = |s: f64| {
            [DVec3::ZERO, DVec3::new(0.0, s, 0.0), DVec3::new(s, 0.0, 0.0), DVec3::new(0.3 * s, 0.3 * s, 5e-10)]
        };
        let (big, small) = (pair(1000.0 / 2f64.sqrt()), pair(0.5));
        assert!(is_torsal(&big, 0, size_of(&big)), "{}", pair_off_plane(&big, 0));
        assert!(!is_torsal(&small, 0, size_of(&small)));
        // the size: the box's diagonal, at least 1
        assert_eq!(size_of(&[DVec3::ONE, DVec3::new(4.0, 5.0, 13.0)]), 13.0);
        assert_eq!(size_of(&[DVec3::new(-1.0, 0.0, 0.0), DVec3::new(-0.5, 0.0, 0.0)]), 1.0);
        // three rulings turned by a quarter turn each about z (exact in binary): two pairs with the
        // same |δ|, the first named
        let s = RuledSurface::from_points(vec![
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 1.0),
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::new(-1.0, 1.0, 1.0),
            DVec3::new(-1.0, 0.0, 0.0),
            DVec3::new(-1.0, -1.0, 1.0),
        ])
        .unwrap();
        let inv = s.invariants();
        assert_eq!(inv.distribution[0], inv.distribution[1]);
        assert_eq!(max_abs_delta(&s), (inv.distribution[0].abs(), Some(0)));
        let h = pair_off_plane(s.points(), 0);
        assert!(h > 0.1 && h == pair_off_plane(s.points(), 1));
        assert_eq!(max_off_plane(&s), (h, Some(0)));
    }

    #[test]
    fn rulings_that_count_as_parallel_but_leave_their_plane_report_their_huge_delta() {
        // φ = 5e-10 (below the parallel threshold), a unit apart: not coplanar, δ ≈ 1/φ
        let s = RuledSurface::from_points(vec![DVec3::ZERO, DVec3::Y, DVec3::X, DVec3::new(1.0, 1.0, 5e-10)]).unwrap();
        assert!(s.invariants().parallel[0]);
        let (d, at) = max_abs_delta(&s);
        assert_eq!(at, Some(0));
        assert!((d * 5e-10 - 1.0).abs() < 1e-6, "{d}");
        assert!(max_off_plane(&s).0 > 4e-10);
    }
}
