//! Keeping a strip developable while its rulings are dragged (beyond the paper; its measure is
//! Section 2's distribution parameter δ = h/φ (1), which vanishes exactly for coplanar rulings).
//!
//! A pair of consecutive rulings is *torsal* when its rulings are coplanar: they meet, or run
//! parallel. A strip edited by hand breaks this at the dragged ruling: the repair finds the runs of
//! consecutive pairs that are not torsal (the tetrahedron of the pair's ends higher than
//! [`TORSAL_HEIGHT`] of the strip's size over its largest face: [`super::coplanar`]),
//! keeps one ruling of each run as given — its *anchor* — and moves the ends b of the other rulings
//! as little as possible until every pair is torsal again. The ends a (the strip's directrix) never
//! move, nor do the anchors; every ruling keeps its length.
//!
//! **The nearest developable strip.** With the ends a fixed, pair (j, j + 1) is torsal when
//!
//! c_j = det(a_{j+1} − a_j, b_j − a_j, b_{j+1} − a_{j+1}) = 0,
//!
//! one equation in the ends b_j, b_{j+1}. The repair solves c(b) = 0 by Gauss–Newton steps of least
//! norm, Δb = −Jᵀ (J Jᵀ)⁻¹ c, with the anchors' ends held: J Jᵀ is tridiagonal (c_j and c_{j+1} share
//! b_{j+1}), so a step costs O(N), and the steps converge quadratically to the strip nearest the
//! edit (in the sum of the squared moves of the ends b, to first order). The move is largest at the
//! neighbours of the dragged ruling and fades along the strip. Each ruling is then brought back to
//! its length along its new direction, which changes no line. Should the steps not reach the
//! tolerance (a strip folded onto itself), a sweep outwards from the anchors turns each ruling of a
//! broken pair into the plane of its predecessor on the way and its own end a by the least angle;
//! between two anchors the sweeps from both meet at the middle ruling, which is turned onto the
//! line where its two neighbours' planes meet. That makes every pair torsal by construction.
//!
//! **The anchor** of a run of broken pairs is its middle ruling: a dragged interior ruling breaks
//! the two pairs it belongs to, and is their middle. A run of one pair at an end of the strip is
//! anchored at the end ruling (the end was dragged); where a run has two middle rulings, the one
//! whose repair moves the strip less is kept. The repair is a function of the rulings alone: the
//! same input gives the same strip, bit for bit, and a strip that is already developable comes back
//! unchanged.

use super::coplanar::{is_torsal, size_of};
use crate::ruled::RuledSurface;
#[cfg(doc)]
use crate::tolerance::TORSAL_HEIGHT;
use crate::tolerance::{REPAIR_STEPS, ZERO_LENGTH_REL};
use glam::DVec3;

/// A strip made developable, and what the repair did.
#[derive(Debug, Clone, PartialEq)]
pub struct Repair {
    /// The strip, every pair of consecutive rulings torsal.
    pub surface: RuledSurface,
    /// The rulings that were turned (ascending).
    pub turned: Vec<usize>,
    /// The rulings kept as given as anchors of the broken runs (ascending).
    pub anchors: Vec<usize>,
    /// Gauss–Newton steps taken.
    pub steps: usize,
}

/// Whether the pair (j, j + 1) of `p` (endpoints a_0, b_0, a_1, …) is not torsal.
fn broken(p: &[DVec3], j: usize, scale: f64) -> bool {
    !is_torsal(p, j, scale)
}

/// Ruling i of `p` as a line.
fn line(p: &[DVec3], i: usize) -> crate::line::Line {
    crate::line::Segment::new(p[2 * i], p[2 * i + 1]).line()
}

/// The anchors of the runs of broken pairs of `p` (see the module).
fn anchors(p: &[DVec3], n: usize, scale: f64) -> Vec<usize> {
    let mut out = Vec::new();
    let mut j = 0;
    while j + 1 < n {
        if !broken(p, j, scale) {
            j += 1;
            continue;
        }
        // pairs s ..= e are broken: rulings s ..= t
        let s = j;
        let mut e = j;
        while e + 2 < n && broken(p, e + 1, scale) {
            e += 1;
        }
        let t = e + 1;
        let k = if s == 0 && t == 1 {
            0
        } else if t == n - 1 && s == n - 2 {
            n - 1
        } else if (t - s) % 2 == 0 {
            (s + t) / 2
        } else {
            // two middles: the one whose repair (of this run alone) moves the ends b less
            let k = (s + t) / 2;
            let moved = |k: usize| {
                let mut q = p.to_vec();
                solve(&mut q, n, &[k]);
                q.iter().zip(p).map(|(x, y)| (*x - *y).length_squared()).sum::<f64>()
            };
            if moved(k + 1) < moved(k) {
                k + 1
            } else {
                k
            }
        };
        out.push(k);
        j = t;
    }
    out
}

/// c_j (see the module) and its gradients with respect to b_j and b_{j+1}, and the product of the
/// three lengths it is relative to.
fn constraint(p: &[DVec3], j: usize) -> (f64, DVec3, DVec3, f64) {
    let d = p[2 * j + 2] - p[2 * j];
    let (u, v) = (p[2 * j + 1] - p[2 * j], p[2 * j + 3] - p[2 * j + 2]);
    // det(d, u, v) = u · (v × d) = v · (d × u)
    (u.dot(v.cross(d)), v.cross(d), d.cross(u), d.length() * u.length() * v.length())
}

/// Gauss–Newton steps of least norm on the ends b of `p`, the rulings `held` fixed, until every c_j
/// is at rounding level (or [`REPAIR_STEPS`] steps); then each ruling back to its length. Returns
/// the steps taken.
fn solve(p: &mut [DVec3], n: usize, held: &[usize]) -> usize {
    let lengths: Vec<f64> = (0..n).map(|i| (p[2 * i + 1] - p[2 * i]).length()).collect();
    let free = |i: usize| !held.contains(&i);
    let m = n - 1;
    let (mut diag, mut off, mut rhs) = (vec![0.0; m], vec![0.0; m], vec![0.0; m]);
    let mut grads = vec![(DVec3::ZERO, DVec3::ZERO); m];
    let mut steps = 0;
    for _ in 0..REPAIR_STEPS {
        let mut worst = 0.0f64;
        for j in 0..m {
            let (c, gj, gk) = {
                let (c, gj, gk, size) = constraint(p, j);
                worst = worst.max(c.abs() / size.max(f64::MIN_POSITIVE));
                (c, if free(j) { gj } else { DVec3::ZERO }, if free(j + 1) { gk } else { DVec3::ZERO })
            };
            grads[j] = (gj, gk);
            rhs[j] = c;
        }
        // at rounding level: c relative to the lengths it is made of
        if worst <= 4.0 * f64::EPSILON {
            break;
        }
        for j in 0..m {
            diag[j] = grads[j].0.length_squared() + grads[j].1.length_squared();
            off[j] = if j + 1 < m { grads[j].1.dot(grads[j + 1].0) } else { 0.0 };
        }
        // (J Jᵀ) λ = c by the tridiagonal elimination; a pair both of whose rulings are held (or
        // whose gradients vanish) cannot move and is left out
        let tiny = 1e-300 + 1e-24 * diag.iter().fold(0.0f64, |a, &b| a.max(b));
        let mut lambda = rhs.clone();
        let mut pivot = diag.clone();
        for j in 1..m {
            if pivot[j - 1] > tiny {
                let f = off[j - 1] / pivot[j - 1];
                pivot[j] -= f * off[j - 1];
                lambda[j] -= f * lambda[j - 1];
            }
        }
        for j in (0..m).rev() {
            if pivot[j] <= tiny {
                lambda[j] = 0.0;
                continue;
            }
            let next = if j + 1 < m { off[j] * lambda[j + 1] } else { 0.0 };
            lambda[j] = (lambda[j] - next) / pivot[j];
        }
        for j in 0..m {
            p[2 * j + 1] -= lambda[j] * grads[j].0;
            p[2 * j + 3] -= lambda[j] * grads[j].1;
        }
        steps += 1;
    }
    for i in (0..n).filter(|&i| free(i)) {
        let dir = (p[2 * i + 1] - p[2 * i]).try_normalize().unwrap_or(DVec3::X);
        p[2 * i + 1] = p[2 * i] + lengths[i] * dir;
    }
    steps
}

/// The unit normal of the plane through the line of ruling `f` and the end a of ruling `j`; `None`
/// where a lies on that line (to rounding of the strip's size `scale`): the two rulings meet there,
/// torsal whatever the direction of `j`.
fn plane_normal(p: &[DVec3], j: usize, f: usize, scale: f64) -> Option<DVec3> {
    let lf = line(p, f);
    let n = lf.dir.cross(p[2 * j] - lf.point);
    (n.length() > ZERO_LENGTH_REL * scale).then(|| n.normalize())
}

/// Turns ruling `j` about its end a, by the least angle, into the plane through ruling `f` and a_j.
fn turn_into_plane(p: &mut [DVec3], j: usize, f: usize, scale: f64) {
    let (a, b) = (p[2 * j], p[2 * j + 1]);
    let (old, length) = ((b - a).normalize(), (b - a).length());
    let Some(normal) = plane_normal(p, j, f, scale) else {
        return; // ruling j meets the line of f at its end a: torsal already
    };
    let dir = old.reject_from_normalized(normal).try_normalize().unwrap_or(line(p, f).dir);
    p[2 * j + 1] = a + length * dir;
}

/// Turns ruling `j` about its end a onto the line where the planes through its two neighbours'
/// lines and a_j meet (the way along it nearer its own), which makes both of its pairs torsal;
/// where the two planes are one, into that plane; where a neighbour's line passes through a_j
/// (torsal with it whatever), into the other's plane.
fn turn_onto_meeting(p: &mut [DVec3], j: usize, scale: f64) {
    let (a, b) = (p[2 * j], p[2 * j + 1]);
    let (old, length) = ((b - a).normalize(), (b - a).length());
    match (plane_normal(p, j, j - 1, scale), plane_normal(p, j, j + 1, scale)) {
        (Some(left), Some(right)) => {
            // the sine of the angle between the two planes
            let meet = left.cross(right);
            if meet.length() > ZERO_LENGTH_REL {
                let dir = meet.normalize();
                p[2 * j + 1] = a + length * if dir.dot(old) < 0.0 { -dir } else { dir };
            } else {
                turn_into_plane(p, j, j - 1, scale);
            }
        }
        (Some(_), None) => turn_into_plane(p, j, j - 1, scale),
        (None, Some(_)) => turn_into_plane(p, j, j + 1, scale),
        (None, None) => {}
    }
}

/// The safety net (see the module): outwards from the first anchor to the strip's start and from
/// the last to its end, and from both anchors of each pair of neighbouring anchors towards the
/// middle ruling between them, every ruling of a broken pair turned into the plane of the ruling
/// before it on the way and its own end a; the middle ruling, where two sweeps meet, onto the
/// line where its two neighbours' planes meet.
fn sweep(p: &mut [DVec3], n: usize, anchors: &[usize], scale: f64) {
    let (Some(&first), Some(&last)) = (anchors.first(), anchors.last()) else { return };
    for j in (0..first).rev() {
        if broken(p, j, scale) {
            turn_into_plane(p, j, j + 1, scale);
        }
    }
    for j in last + 1..n {
        if broken(p, j - 1, scale) {
            turn_into_plane(p, j, j - 1, scale);
        }
    }
    for w in anchors.windows(2) {
        let (k, l) = (w[0], w[1]);
        if l < k + 2 {
            continue;
        }
        let middle = (k + l) / 2;
        for j in k + 1..middle {
            if broken(p, j - 1, scale) {
                turn_into_plane(p, j, j - 1, scale);
            }
        }
        for j in (middle + 1..l).rev() {
            if broken(p, j, scale) {
                turn_into_plane(p, j, j + 1, scale);
            }
        }
        if broken(p, middle - 1, scale) || broken(p, middle, scale) {
            turn_onto_meeting(p, middle, scale);
        }
    }
}

/// The strip made developable (see the module): every pair of consecutive rulings torsal, the ends
/// a unmoved, the anchors kept. O(N) per step.
pub fn make_developable(surface: &RuledSurface) -> Repair {
    let n = surface.len();
    let mut p = surface.points().to_vec();
    let scale = size_of(&p);
    let anchors = anchors(&p, n, scale);
    if anchors.is_empty() {
        return Repair { surface: surface.clone(), turned: Vec::new(), anchors, steps: 0 };
    }
    let steps = solve(&mut p, n, &anchors);
    if (0..n - 1).any(|j| broken(&p, j, scale)) {
        sweep(&mut p, n, &anchors, scale);
    }
    let turned = (0..n).filter(|&i| p[2 * i + 1] != surface.points()[2 * i + 1]).collect();
    Repair { surface: RuledSurface::from_trusted_points(p), turned, anchors, steps }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::developable::construct::{cone, tangent_surface, Span};
    use crate::developable::coplanar::{max_off_plane, raw_max_abs_delta};
    use crate::tolerance::TORSAL_HEIGHT;
    use glam::DVec3;
    use std::f64::consts::TAU;

    fn helix(m: usize) -> Vec<DVec3> {
        (0..m)
            .map(|i| {
                let u = 1.5 * TAU * i as f64 / (m - 1) as f64;
                DVec3::new(u.cos(), u.sin(), 0.3 * u)
            })
            .collect()
    }

    /// How far keeping ruling `anchor` alone moves the ends of the strip `p` (the sum of the squared
    /// moves of its points): what `anchors` weighs between two middles.
    fn moved_by_keeping(p: &[DVec3], anchor: usize) -> f64 {
        let mut q = p.to_vec();
        solve(&mut q, p.len() / 2, &[anchor]);
        q.iter().zip(p).map(|(x, y)| (*x - *y).length_squared()).sum()
    }

    /// `s` with the end b of ruling `k` moved by `by`.
    fn dragged(s: &RuledSurface, k: usize, by: DVec3) -> RuledSurface {
        let mut p = s.points().to_vec();
        p[2 * k + 1] += by;
        RuledSurface::from_points(p).unwrap()
    }

    #[test]
    fn a_dragged_ruling_stays_and_the_strip_follows_it_nearby() {
        let s = tangent_surface(&helix(30), Span { from: 0.1, to: 1.0 }).unwrap();
        for k in [0, 1, 14, 27, 28] {
            let edit = dragged(&s, k, DVec3::new(0.05, -0.03, 0.04));
            assert!(raw_max_abs_delta(&edit) > 1e-3);
            let r = make_developable(&edit);
            assert!(raw_max_abs_delta(&r.surface) <= 1e-13, "ruling {k}: {:?}", raw_max_abs_delta(&r.surface));
            assert_eq!(r.anchors, [k]);
            assert!((1..=8).contains(&r.steps), "{} steps", r.steps);
            assert_eq!(r.surface.segment(k), edit.segment(k), "the dragged ruling is kept as given");
            let turned: Vec<usize> = (0..29).filter(|&i| r.surface.segment(i).b != edit.segment(i).b).collect();
            assert_eq!(r.turned, turned, "the rulings turned, named");
            let moved: Vec<f64> = (0..29).map(|i| (r.surface.segment(i).b - edit.segment(i).b).length()).collect();
            for i in 0..29 {
                assert_eq!(r.surface.segment(i).a, s.segment(i).a, "the ends a stay");
                assert!((r.surface.segment(i).length() - edit.segment(i).length()).abs() < 1e-14);
            }
            // the move is largest beside the dragged ruling and fades along the strip
            let near = moved[k.saturating_sub(1)].max(moved[(k + 1).min(28)]);
            let far = (0..29usize).filter(|&i| i.abs_diff(k) >= 4).fold(0.0f64, |m, i| m.max(moved[i]));
            assert!(near > 2.0 * far, "ruling {k}: {moved:?}");
        }
    }

    /// The least-norm steps move the strip less than turning every ruling after the dragged one
    /// into its predecessor's plane (the safety net) does.
    #[test]
    fn the_repair_moves_the_strip_less_than_the_sweep() {
        let s = cone(&helix(25), DVec3::new(0.0, 0.0, 4.0), Span { from: 0.2, to: 1.0 }).unwrap();
        let edit = dragged(&s, 12, DVec3::new(0.1, 0.05, -0.08));
        let moved = |q: &[DVec3]| q.iter().zip(edit.points()).map(|(x, y)| (*x - *y).length_squared()).sum::<f64>();
        let repaired = make_developable(&edit).surface;
        let mut swept = edit.points().to_vec();
        let scale = size_of(&swept);
        sweep(&mut swept, 25, &[12], scale);
        let swept = RuledSurface::from_points(swept).unwrap();
        assert!(raw_max_abs_delta(&swept) <= 1e-13);
        assert!(moved(repaired.points()) < 0.5 * moved(swept.points()));
        // the sweep keeps the anchor, turns each other ruling into the plane, does not turn it round
        assert_eq!(swept.segment(12), edit.segment(12));
        for i in 0..25 {
            let (was, now) = (edit.segment(i), swept.segment(i));
            assert!((now.b - now.a).dot(was.b - was.a) > 0.0, "ruling {i} turned round");
            assert!((now.length() - was.length()).abs() < 1e-14, "ruling {i} keeps its length");
        }
    }

    #[test]
    fn a_developable_strip_comes_back_unchanged_and_the_repair_is_idempotent() {
        let s = cone(&helix(25), DVec3::new(0.0, 0.0, 4.0), Span { from: 0.2, to: 1.0 }).unwrap();
        let r = make_developable(&s);
        assert_eq!(r.surface, s);
        assert!(r.turned.is_empty() && r.anchors.is_empty());
        let edit = dragged(&s, 7, DVec3::new(0.2, 0.1, -0.1));
        let once = make_developable(&edit).surface;
        assert_eq!(make_developable(&once).surface, once);
    }

    /// Random rulings, nowhere torsal: one run, repaired from its middle outwards.
    #[test]
    fn rulings_in_general_position_become_a_developable_strip() {
        let mut seed = 7u64;
        let mut r = || crate::tolerance::test::uniform(&mut seed) * 2.0 - 1.0;
        let points: Vec<DVec3> = (0..40)
            .flat_map(|i| {
                let a = DVec3::new(i as f64 * 0.1, r() * 0.05, r() * 0.05);
                [a, a + DVec3::new(r() * 0.3, 1.0, r() * 0.3)]
            })
            .collect();
        let s = RuledSurface::from_points(points).unwrap();
        let out = make_developable(&s);
        // 39 broken pairs, rulings 0 … 39: two middles, 19 and 20
        assert!(out.anchors == [19] || out.anchors == [20], "{:?}", out.anchors);
        // every pair torsal by its height; δ itself is resolved to 1e-12 only where the repaired
        // rulings meet at angles that are not small (δ = h/φ magnifies the ends' rounding by 1/φ²)
        let size = size_of(out.surface.points());
        assert!(max_off_plane(&out.surface).0 <= TORSAL_HEIGHT * size, "{:?} {size}", max_off_plane(&out.surface));
    }

    /// The repair commutes with rigid motions: repairing a moved edit gives the moved repair.
    #[test]
    fn the_repair_is_invariant_under_rigid_motions() {
        let s = tangent_surface(&helix(30), Span { from: 0.1, to: 1.0 }).unwrap();
        let edit = dragged(&s, 9, DVec3::new(0.04, 0.07, -0.05));
        let q = glam::DQuat::from_axis_angle(DVec3::new(0.3, -1.0, 2.0).normalize(), 2.3);
        let t = DVec3::new(-3.0, 1.5, 7.0);
        let moved = edit.map_points(|p| q * p + t).unwrap();
        let (a, b) = (make_developable(&edit), make_developable(&moved));
        assert_eq!(a.anchors, b.anchors);
        for (x, y) in a.surface.points().iter().zip(b.surface.points()) {
            assert!((q * *x + t - *y).length() < 1e-12, "{x} {y}");
        }
    }

    /// A flat strip of parallel rulings, one of them tilted out of its plane: the strip twists to
    /// follow it.
    #[test]
    fn a_flat_strip_twists_to_follow_a_tilted_ruling() {
        let points: Vec<DVec3> =
            (0..10).flat_map(|i| [DVec3::new(i as f64, 0.0, 0.0), DVec3::new(i as f64 + 0.1, 1.0, 0.0)]).collect();
        let s = RuledSurface::from_points(points).unwrap();
        let r = make_developable(&dragged(&s, 3, DVec3::new(0.0, 0.0, 0.2)));
        assert_eq!(r.anchors, [3]);
        assert!(max_off_plane(&r.surface).0 <= 1e-15, "{:?}", max_off_plane(&r.surface));
        // δ where the twisted rulings meet at angles that resolve it (far from ruling 3 they stay
        // all but parallel, and δ there is the ends' rounding magnified by 1/φ²)
        let inv = r.surface.invariants();
        for (j, (d, phi)) in inv.distribution.iter().zip(&inv.angle).enumerate() {
            if *phi >= 1e-2 {
                assert!(d.abs() <= 1e-12, "pair {j}: δ {d} at φ {phi}");
            }
        }
        assert!(inv.angle[2] >= 1e-2 && inv.angle[3] >= 1e-2, "the dragged ruling's pairs are resolved");
        assert!(r.turned.contains(&2) && r.turned.contains(&4));
    }

    /// Two neighbouring rulings dragged: the run of broken pairs has two middle rulings, and the
    /// one whose repair moves the ends b less is kept — the first in one case, the second in the
    /// other.
    #[test]
    fn of_two_middle_rulings_the_one_whose_repair_moves_the_strip_less_is_kept() {
        let s = tangent_surface(&helix(30), Span { from: 0.1, to: 1.0 }).unwrap();
        let (near, far) = (DVec3::new(0.002, 0.0, 0.001), DVec3::new(0.08, -0.05, 0.06));
        let mut kept = Vec::new();
        for (k, other) in [(11, 10), (10, 11)] {
            let mut p = s.points().to_vec();
            p[2 * k + 1] += far;
            p[2 * other + 1] += near;
            let moved = |anchor: usize| moved_by_keeping(&p, anchor);
            let (m10, m11) = (moved(10), moved(11));
            assert!((m10 - m11).abs() > 0.1 * m10.min(m11), "{m10} {m11}");
            let r = make_developable(&RuledSurface::from_points(p).unwrap());
            assert_eq!(r.anchors, [if m11 < m10 { 11 } else { 10 }], "{m10} {m11}");
            kept.push(r.anchors[0]);
        }
        kept.sort();
        assert_eq!(kept, [10, 11], "each of the two middles kept once");
    }

    /// A run of one broken pair at either end of the strip is anchored at the end ruling, which
    /// was dragged, even where keeping its neighbour would move the strip less: a flat strip whose
    /// end ruling is short (0.1) has it lifted by 0.05 out of the plane. Keeping the neighbour
    /// would only undo the drag (0.05); keeping the end turns the neighbour by about 0.45 and
    /// the strip after it.
    #[test]
    fn a_dragged_end_ruling_is_kept_even_where_keeping_its_neighbour_moves_less() {
        for (end, next) in [(0, 1), (7, 6)] {
            let mut p: Vec<DVec3> =
                (0..8).flat_map(|i| [DVec3::new(i as f64, 0.0, 0.0), DVec3::new(i as f64, 1.0, 0.0)]).collect();
            p[2 * end + 1] = DVec3::new(end as f64, 0.1, 0.05);
            let edit = RuledSurface::from_points(p.clone()).unwrap();
            let moved = |anchor: usize| moved_by_keeping(&p, anchor);
            assert!(moved(next) < 0.01 && moved(end) > 0.1, "{} {}", moved(next), moved(end));
            let r = make_developable(&edit);
            assert_eq!(r.anchors, [end]);
            assert_eq!(r.surface.segment(end), edit.segment(end));
            assert!(raw_max_abs_delta(&r.surface) <= 1e-13);
        }
    }

    /// The repair does not depend on the units: scaled by a power of two (exactly, in floating
    /// point), a dragged strip is repaired in as many steps to the same strip scaled, bit for
    /// bit — the steps stop on c_j relative to the three lengths it is the product of, and the
    /// elimination's threshold is relative to its largest pivot.
    #[test]
    fn the_repair_does_not_depend_on_the_units() {
        let s = tangent_surface(&helix(30), Span { from: 0.1, to: 1.0 }).unwrap();
        let edit = dragged(&s, 9, DVec3::new(0.04, 0.07, -0.05));
        let r = make_developable(&edit);
        assert!(r.steps >= 2, "{} steps", r.steps);
        for k in [-20, -7, 9, 30] {
            let f = 2f64.powi(k);
            let scaled = make_developable(&edit.map_points(|p| f * p).unwrap());
            assert_eq!((scaled.steps, &scaled.anchors, &scaled.turned), (r.steps, &r.anchors, &r.turned), "2^{k}");
            for (x, y) in r.surface.points().iter().zip(scaled.surface.points()) {
                assert_eq!(f * *x, *y, "2^{k}");
            }
        }
    }

    /// Two runs whose anchors stand side by side, so that the pair between them cannot move (its
    /// two rulings held, its row of the elimination zero): a flat strip of six parallel rulings,
    /// the two middle ones lifted alike (still parallel to each other), the two beside them short
    /// (0.05), so that moving them is dear.
    /// Each lifted ruling is its run's anchor; the strip comes out developable with both kept.
    #[test]
    fn anchors_side_by_side_hold_the_pair_between_them() {
        let lengths = [1.0, 0.05, 1.0, 1.0, 0.05, 1.0];
        let mut p: Vec<DVec3> = lengths
            .iter()
            .enumerate()
            .flat_map(|(i, &l)| [DVec3::new(i as f64, 0.0, 0.0), DVec3::new(i as f64, l, 0.0)])
            .collect();
        for i in [2, 3] {
            p[2 * i + 1].z = 0.1;
        }
        let moved = |anchor: usize| moved_by_keeping(&p, anchor);
        // keeping the lifted ruling moves the strip less than keeping the short one beside it
        assert!(moved(2) < 0.75 * moved(1) && moved(3) < 0.75 * moved(4), "{} {}", moved(2), moved(1));
        let edit = RuledSurface::from_points(p).unwrap();
        let r = make_developable(&edit);
        assert_eq!(r.anchors, [2, 3]);
        for i in [2, 3] {
            assert_eq!(r.surface.segment(i), edit.segment(i));
        }
        assert!(raw_max_abs_delta(&r.surface) <= 1e-13, "{}", raw_max_abs_delta(&r.surface));
    }

    /// The safety net's turn of a ruling whose end a lies on the line of the ruling before it (to
    /// rounding of the strip's size, here 10⁶): the two meet there, coplanar already, and the
    /// ruling is left as it is — not turned a quarter turn into a plane through the line and a's
    /// rounding error.
    #[test]
    fn a_ruling_through_the_line_before_it_is_left_by_the_safety_net() {
        let mut p = vec![DVec3::ZERO, DVec3::new(1e6, 0.0, 0.0), DVec3::new(5e5, 1e-9, 0.0), DVec3::new(5e5, 0.0, 1e6)];
        let was = p[3];
        let scale = size_of(&p);
        turn_into_plane(&mut p, 1, 0, scale);
        assert!((p[3] - was).length() < 1e-6, "{} moved to {}", was, p[3]);
    }

    /// The safety net from one anchor (ruling 12 of a cone, with ruling 10 dragged as well):
    /// outwards from the anchor each ruling of a broken pair is turned once, by the least angle
    /// from where it was, into the plane through the line of its neighbour towards the anchor and
    /// its own end a; a ruling of a pair torsal already is left.
    #[test]
    fn the_safety_net_turns_each_ruling_once_by_the_least_angle() {
        let s = cone(&helix(25), DVec3::new(0.0, 0.0, 4.0), Span { from: 0.2, to: 1.0 }).unwrap();
        let edit = dragged(&dragged(&s, 12, DVec3::new(0.1, 0.05, -0.08)), 10, DVec3::new(-0.06, 0.04, 0.05));
        let was = edit.points().to_vec();
        let mut p = was.clone();
        let scale = size_of(&p);
        sweep(&mut p, 25, &[12], scale);
        let swept = RuledSurface::from_points(p.clone()).unwrap();
        assert!(raw_max_abs_delta(&swept) <= 1e-13);
        assert_eq!(swept.segment(12), edit.segment(12));
        for j in (0..25).filter(|&j| j != 12) {
            let towards = if j > 12 { j - 1 } else { j + 1 };
            let (a, old) = (p[2 * j], (was[2 * j + 1] - was[2 * j]).normalize());
            let lf = line(&p, towards);
            let normal = lf.dir.cross(a - lf.point).normalize();
            let want = old.reject_from_normalized(normal).normalize();
            let now = (p[2 * j + 1] - a).normalize();
            assert!((now - want).length() < 1e-12 || now == old, "ruling {j}: {now} against {want}");
        }
    }

    /// The safety net from two anchors (rulings 6 and 12 of a cone, both dragged): the rulings
    /// between them are turned from each side in turn, and neither anchor is turned when the
    /// other's sweep reaches it.
    #[test]
    fn the_safety_net_keeps_every_anchor() {
        let s = cone(&helix(25), DVec3::new(0.0, 0.0, 4.0), Span { from: 0.2, to: 1.0 }).unwrap();
        let edit = dragged(&dragged(&s, 12, DVec3::new(0.1, 0.05, -0.08)), 6, DVec3::new(-0.06, 0.04, 0.05));
        let mut p = edit.points().to_vec();
        let scale = size_of(&p);
        sweep(&mut p, 25, &[6, 12], scale);
        let swept = RuledSurface::from_points(p).unwrap();
        assert!(raw_max_abs_delta(&swept) <= 1e-13);
        for k in [6, 12] {
            assert_eq!(swept.segment(k), edit.segment(k), "anchor {k}");
        }
        // the middle ruling 9, where the two sweeps meet, lies on the line where its neighbours'
        // planes (each with a_9) meet, the way nearer where it was
        let q = swept.points();
        let (a, dir) = (q[18], (q[19] - q[18]).normalize());
        for f in [8, 10] {
            let lf = line(q, f);
            assert!(lf.dir.cross(a - lf.point).normalize().dot(dir).abs() < 1e-12, "ruling 9 off the plane of {f}");
        }
        assert!(dir.dot(edit.segment(9).b - edit.segment(9).a) > 0.0);
        for i in 0..25 {
            assert!(
                (swept.segment(i).length() - edit.segment(i).length()).abs() < 1e-14,
                "ruling {i} keeps its length"
            );
        }
    }

    /// Between anchors two apart the middle ruling is all there is: where the planes of its two
    /// neighbours meet in a line it turns onto it; where they are one plane (a flat strip, its
    /// middle ruling lifted), it turns back into that plane by the least angle.
    #[test]
    fn the_safety_net_between_anchors_two_apart() {
        let flat = |i: usize| [DVec3::new(i as f64, 0.0, 0.0), DVec3::new(i as f64 + 0.2 * i as f64, 1.0, 0.0)];
        let mut p: Vec<DVec3> = (0..5).flat_map(flat).collect();
        p[7] += DVec3::new(0.0, 0.0, 0.5);
        let scale = size_of(&p);
        let mut swept = p.clone();
        sweep(&mut swept, 5, &[2, 4], scale);
        let back = (swept[7] - swept[6]).normalize();
        let want = (p[7] - p[6]).reject_from_normalized(DVec3::Z).normalize();
        assert!((back - want).length() < 1e-15, "{back} against {want}");
        // the neighbours twisted out of the plane: their planes meet in a line, which the middle
        // ruling takes the way nearer its own, keeping its length; the strip in either order (the
        // line's two ways swap)
        p[5] += DVec3::new(0.0, 0.0, 0.3);
        p[9] -= DVec3::new(0.0, 0.0, 0.2);
        let reversed: Vec<DVec3> = p.chunks(2).rev().flatten().copied().collect();
        for (given, anchors, middle) in [(p, [2, 4], 3), (reversed, [0, 2], 1)] {
            let mut q = given.clone();
            sweep(&mut q, 5, &anchors, size_of(&given));
            let (was, now) = (given[2 * middle + 1] - given[2 * middle], q[2 * middle + 1] - q[2 * middle]);
            assert!(now.dot(was) > 0.0 && (now.length() - was.length()).abs() < 1e-15, "{was} to {now}");
            let swept = RuledSurface::from_points(q).unwrap();
            assert!(raw_max_abs_delta(&swept) <= 1e-13, "{}", raw_max_abs_delta(&swept));
        }
    }

    /// Where the two sweeps meet at a ruling whose end a lies on one neighbour's line (torsal with
    /// it whatever), the ruling turns by the least angle into the other neighbour's plane — here
    /// the line of ruling 0 is the x axis through a_1, and ruling 2's plane with a_1 is z = 0 —
    /// either way round.
    #[test]
    fn a_meeting_ruling_on_a_neighbours_line_turns_into_the_other_plane() {
        let strip = [
            DVec3::ZERO,
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 0.5),
            DVec3::new(2.0, 0.1, 0.0),
            DVec3::new(2.0, 1.0, 0.0),
        ];
        let want = DVec3::new(1.0, 1.25f64.sqrt(), 0.0);
        let mut p = strip.to_vec();
        turn_onto_meeting(&mut p, 1, size_of(&strip));
        assert!((p[3] - want).length() < 1e-15, "{}", p[3]);
        // mirrored: the rulings in the other order
        let mut q = vec![strip[4], strip[5], strip[2], strip[3], strip[0], strip[1]];
        turn_onto_meeting(&mut q, 1, size_of(&strip));
        assert!((q[3] - want).length() < 1e-15, "{}", q[3]);
    }

    /// The safety net between anchors two apart on a flat fan of six rulings: whichever anchors
    /// (1 and 3, or 3 and 5), the middle ruling lifted out of the plane comes back into it; and
    /// where only one of its pairs is broken (an anchor beside it lifted instead) it still turns,
    /// onto the line where both neighbours' planes meet. The anchors stay as they were.
    #[test]
    fn the_safety_net_fixes_the_middle_between_any_anchors_two_apart() {
        let fan: Vec<DVec3> =
            (0..6).flat_map(|i| [DVec3::new(i as f64, 0.0, 0.0), DVec3::new(1.2 * i as f64, 1.0, 0.0)]).collect();
        for (k, lifted) in [(1, 2), (3, 4), (1, 3), (3, 5), (1, 1), (3, 3)] {
            let mut given = fan.clone();
            given[2 * lifted + 1].z = 0.5;
            let scale = size_of(&given);
            assert!((0..5).any(|j| broken(&given, j, scale)));
            let mut p = given.clone();
            sweep(&mut p, 6, &[k, k + 2], scale);
            let swept = RuledSurface::from_points(p.clone()).unwrap();
            assert!(raw_max_abs_delta(&swept) <= 1e-13, "anchors {k}, {}: {}", k + 2, raw_max_abs_delta(&swept));
            for anchor in [k, k + 2] {
                assert_eq!((p[2 * anchor], p[2 * anchor + 1]), (given[2 * anchor], given[2 * anchor + 1]));
            }
        }
    }
}
