//! Discrete developable strips from a directrix polygon c_0 … c_{M−1} (Section 3: "if we apply
//! the procedure of Example 2 to a developable surface, we get its development"; the discrete
//! developables here are the strips whose consecutive rulings are coplanar, δ_{i,i+1} = 0 in (1)).
//!
//! Each construction makes consecutive rulings meet (or run parallel) *by construction*, so
//! δ_{i,i+1} = h/φ vanishes to rounding, not to a discretisation error: the exact tangents of a
//! smooth developable sampled at parameters u_i are skew at O(H³) (docs/src/conventions.md,
//! Section 3), the rulings built here are not.
//!
//! - **Tangent surface.** The ruling of edge i is the line of c_i c_{i+1}, t_i its unit
//!   direction; consecutive edge lines meet at c_{i+1}, and the face between them lies in the
//!   osculating plane of c_i, c_{i+1}, c_{i+2}. The strip is the forward half,
//!   R_i: c_{i+1} + v t_i, v ∈ [from, to], from ≥ 0; for from = 0 its edge a is the directrix
//!   itself, the edge of regression. It develops into a polygon with the same edge lengths
//!   |c_{i+1} − c_i| and turning angles φ_{i,i+1} = ∠(t_i, t_{i+1}): the discrete form of the
//!   fact that a tangent developable develops onto the plane curve of the same curvature κ(s),
//!   whatever its torsion (a helix of radius r and pitch p, κ = r/(r² + p²), onto a circle of
//!   radius (r² + p²)/r).
//! - **Cone.** R_i: A + s (c_i − A), s ∈ [from, to], 0 ≤ from (s = 1 on the directrix, 0 at the
//!   apex A). Every ruling passes through A. A right circular cone of half-angle α develops into
//!   a circular sector of angle 2π sin α; the discrete one into a fan of the angles
//!   φ_{i,i+1} = 2 arcsin(sin α sin(Δ/2)) for directrix points Δ apart about the axis.
//! - **Cylinder.** R_i: c_i + v d, v ∈ [from, to], d a unit direction: parallel rulings (sin φ = 0
//!   exactly). It develops onto the plane by unrolling the directrix's projection orthogonal to
//!   d; a circular cylinder cut by an inclined plane onto a sine curve.
//! - **Rectifying developable.** The developable that holds the directrix as a geodesic: its
//!   rulings run along the Darboux vector τT + κB. Discretely, the polygon is a geodesic of the
//!   strip when at every interior vertex c_i the ruling r_i makes equal angles with the edges
//!   meeting there, r_i ⊥ (T_i − T_{i−1}); consecutive rulings are coplanar when r_i lies in the
//!   plane of T_{i−1} and r_{i−1}. The two conditions fix r_i from r_{i−1}:
//!   r_i ∥ (T_{i−1} × r_{i−1}) × (T_i − T_{i−1}). Every start r_k (k the first turning vertex,
//!   r_k ⊥ T_k − T_{k−1}) gives a discrete developable holding the polygon as a geodesic, but all
//!   except one zig-zag along the strip with an amplitude that does not die out; the start chosen
//!   is the one with the least Σ|r_{i+1} − 2r_i + r_{i−1}|² (a scan of the angle and golden
//!   sections around each of its dips), whose rulings tend to the Darboux vector (for a helix: its axis, so the strip is a
//!   cylinder, as for the smooth helix). The end rulings repeat their neighbours. The directrix
//!   develops onto a straight line
//!   exactly.

use crate::error::{Error, Result};
use crate::msg;
use crate::ruled::RuledSurface;
use crate::tolerance::{PARALLEL_SIN, ZERO_LENGTH_REL};
use glam::DVec3;

/// The span of a strip along its rulings: `from` < `to`, both finite (what each number measures
/// is the construction's: a length along the tangent, a factor towards the apex, a length along a
/// direction).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Span {
    /// Where each ruling's segment begins (its end a).
    pub from: f64,
    /// Where it ends (its end b).
    pub to: f64,
}

impl Span {
    /// The span [from, to]; `nonnegative`: whether `from` must be 0 or more (the tangent surface and
    /// the cone stop at their edge of regression and apex).
    fn checked(self, nonnegative: bool) -> Result<Span> {
        let Span { from, to } = self;
        if !from.is_finite() || !to.is_finite() {
            return Err(Error::parameter("span", msg!("interval-not-finite", lo = from, hi = to)));
        }
        if from >= to {
            return Err(Error::parameter("span", msg!("interval-order", lo = from, hi = to)));
        }
        if nonnegative && from < 0.0 {
            return Err(Error::parameter("span", msg!("span-crosses-regression", from = from)));
        }
        Ok(self)
    }
}

/// The directrix checked: at least `min` points, no two consecutive ones equal.
fn checked_directrix(points: &[DVec3], min: usize) -> Result<()> {
    if points.len() < min {
        return Err(Error::TooFew { what: "directrix points", got: points.len(), min });
    }
    for (i, w) in points.windows(2).enumerate() {
        let len2 = (w[1] - w[0]).length_squared();
        if len2 <= ZERO_LENGTH_REL * ZERO_LENGTH_REL * w[0].length_squared().max(w[1].length_squared()) {
            return Err(Error::degenerate("directrix", msg!("directrix-edge-zero", edge = i, next = i + 1)));
        }
    }
    Ok(())
}

/// The unit edge directions T_i = (c_{i+1} − c_i)/|c_{i+1} − c_i| of a checked directrix.
fn edge_directions(points: &[DVec3]) -> Vec<DVec3> {
    points.windows(2).map(|w| (w[1] - w[0]).normalize()).collect()
}

/// The strip of the lines `point_i + v dir_i`, v ∈ span (directions need not be unit).
fn strip(points: impl Iterator<Item = (DVec3, DVec3)>, span: Span) -> Result<RuledSurface> {
    RuledSurface::from_points(points.flat_map(|(p, d)| [p + span.from * d, p + span.to * d]).collect())
}

/// The discrete tangent surface of the directrix (see the module): M − 1 rulings along its edges,
/// R_i: c_{i+1} + v t_i, v ∈ [from, to], from ≥ 0. Needs M ≥ 3 points and a turn at every
/// interior vertex (consecutive edge lines that coincide bound no face).
pub fn tangent_surface(points: &[DVec3], span: Span) -> Result<RuledSurface> {
    let span = span.checked(true)?;
    checked_directrix(points, 3)?;
    let t = edge_directions(points);
    for (i, w) in t.windows(2).enumerate() {
        if w[0].cross(w[1]).length() < PARALLEL_SIN {
            return Err(Error::degenerate("directrix", msg!("directrix-no-turn-at", point = i + 1)));
        }
    }
    strip(t.iter().enumerate().map(|(i, &d)| (points[i + 1], d)), span)
}

/// The cone over the directrix with apex `apex` (see the module): R_i: A + s (c_i − A),
/// s ∈ [from, to], from ≥ 0. Needs M ≥ 2 points, none at the apex, and no two consecutive ones
/// in line with it.
pub fn cone(points: &[DVec3], apex: DVec3, span: Span) -> Result<RuledSurface> {
    let span = span.checked(true)?;
    checked_directrix(points, 2)?;
    crate::base::check_coordinates(&apex.to_array(), 3)
        .map_err(|_| Error::parameter("apex", msg!("apex-not-finite")))?;
    let scale = points.iter().fold(apex.length(), |m, p| m.max(p.length()));
    for (i, p) in points.iter().enumerate() {
        if (*p - apex).length() <= ZERO_LENGTH_REL * scale {
            return Err(Error::degenerate("apex", msg!("apex-on-directrix", point = i)));
        }
    }
    for (i, w) in points.windows(2).enumerate() {
        if (w[0] - apex).normalize().cross((w[1] - apex).normalize()).length() < PARALLEL_SIN {
            return Err(Error::degenerate("apex", msg!("apex-in-line", edge = i, next = i + 1)));
        }
    }
    strip(points.iter().map(|&p| (apex, p - apex)), span)
}

/// The cylinder over the directrix with rulings along `direction` (see the module):
/// R_i: c_i + v d, v ∈ [from, to], d = direction/|direction|. Needs M ≥ 2 points and no edge of
/// the directrix along d.
pub fn cylinder(points: &[DVec3], direction: DVec3, span: Span) -> Result<RuledSurface> {
    let span = span.checked(false)?;
    checked_directrix(points, 2)?;
    let d = direction
        .try_normalize()
        .filter(|_| direction.is_finite())
        .ok_or_else(|| Error::parameter("direction", msg!("direction-zero")))?;
    for (i, t) in edge_directions(points).iter().enumerate() {
        if t.cross(d).length() < PARALLEL_SIN {
            return Err(Error::degenerate("direction", msg!("edge-along-rulings", edge = i)));
        }
    }
    strip(points.iter().map(|&p| (p, d)), span)
}

/// The discrete rectifying developable of the directrix (see the module): a ruling r_i through
/// every c_i, R_i: c_i + v r_i, v ∈ [from, to] (r_i unit). Needs M ≥ 3 points and a turn at some
/// vertex; no edge may run along the ruling at its start.
pub fn rectifying_developable(points: &[DVec3], span: Span) -> Result<RuledSurface> {
    let span = span.checked(false)?;
    checked_directrix(points, 3)?;
    let r = rectifying_rulings(points)?;
    strip(points.iter().copied().zip(r), span)
}

/// The unit rulings r_0 … r_{M−1} of the rectifying developable (see the module).
fn rectifying_rulings(points: &[DVec3]) -> Result<Vec<DVec3>> {
    let t = edge_directions(points);
    let m = points.len();
    // the turn at interior vertex i (1 … M − 2): T_i − T_{i−1}
    let turn = |i: usize| t[i] - t[i - 1];
    let turning = |i: usize| t[i - 1].cross(t[i]).length() >= PARALLEL_SIN;
    let k =
        (1..m - 1).find(|&k| turning(k)).ok_or_else(|| Error::degenerate("directrix", msg!("directrix-straight")))?;
    // the plane of the rulings that keep the equal angles at c_k: spanned by the binormal and the
    // mean tangent there; the ruling at angle θ in it
    let b = t[k - 1].cross(t[k]).normalize();
    let mean = (t[k - 1] + t[k]).normalize();
    let start = |theta: f64| b * theta.cos() + mean * theta.sin();
    let rough = |theta: f64| match propagate(&t, k, start(theta), &turn) {
        Ok(r) => r.windows(3).map(|w| (w[2] - 2.0 * w[1] + w[0]).length_squared()).sum::<f64>(),
        Err(_) => f64::INFINITY,
    };
    // the recurrence has a one-parameter family of solutions (every start at c_k); all but one
    // zig-zag with an amplitude that persists along the strip. The smooth one, whose limit is the
    // Darboux vector, is the start with the least second differences. The roughness is periodic
    // in θ with period π (the start −r gives the rulings −r_i), narrow at its least and not
    // unimodal: a steep helix, or the cubic (u, −0.4u², −0.1u³), has a second dip, wider, whose
    // samples lie below those beside the narrow least. A scan of one period, then golden sections
    // around each of its samples below both neighbours, the least of those kept
    const SCAN: usize = 180;
    let step = std::f64::consts::PI / SCAN as f64;
    let theta = |j: usize| -std::f64::consts::FRAC_PI_2 + j as f64 * step;
    let sampled: Vec<f64> = (0..SCAN).map(|j| rough(theta(j))).collect();
    let dips = (0..SCAN).filter(|&j| {
        let (before, after) = (sampled[(j + SCAN - 1) % SCAN], sampled[(j + 1) % SCAN]);
        sampled[j].is_finite() && sampled[j] <= before && sampled[j] <= after
    });
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let refine = |centre: f64| {
        let (mut lo, mut hi) = (centre - step, centre + step);
        for _ in 0..60 {
            let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
            if rough(x1) <= rough(x2) {
                hi = x2;
            } else {
                lo = x1;
            }
        }
        let best = (lo + hi) / 2.0;
        (best, rough(best))
    };
    let best = dips.map(|j| refine(theta(j))).fold((0.0, f64::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
    propagate(&t, k, start(best.0), &turn)
}

/// The rulings from `rk` at vertex k along the recurrence (see the module), forwards and
/// backwards; a vertex without a turn (and an end) repeats the ruling before it on the way.
fn propagate(t: &[DVec3], k: usize, rk: DVec3, turn: &dyn Fn(usize) -> DVec3) -> Result<Vec<DVec3>> {
    let m = t.len() + 1;
    let mut r = vec![DVec3::ZERO; m];
    r[k] = rk;
    // r_i in the plane of T_j and r_j (j the vertex before, on the way), orthogonal to the turn at i
    let next = |previous: DVec3, edge: DVec3, turn_here: Option<DVec3>, vertex: usize| -> Result<DVec3> {
        let plane = edge.cross(previous);
        if plane.length() < PARALLEL_SIN {
            return Err(Error::degenerate("directrix", msg!("edge-along-ruling", point = vertex)));
        }
        // no turn here (the end, or a straight vertex): the equal angles hold for any ruling
        let Some(g) = turn_here.filter(|g| g.length() >= PARALLEL_SIN).map(DVec3::normalize) else {
            return Ok(previous);
        };
        let d = plane.normalize().cross(g);
        // the plane of T and the previous ruling is orthogonal to the turn: every direction of
        // it keeps the equal angles, the ruling repeats
        if d.length() < PARALLEL_SIN {
            return Ok(previous);
        }
        let d = d.normalize();
        Ok(if d.dot(previous) < 0.0 { -d } else { d })
    };
    for i in k + 1..m {
        let g = (i < m - 1).then(|| turn(i));
        r[i] = next(r[i - 1], t[i - 1], g, i - 1)?;
    }
    for i in (0..k).rev() {
        let g = (i > 0).then(|| turn(i));
        r[i] = next(r[i + 1], t[i], g, i + 1)?;
    }
    Ok(r)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::assert_near;
    use std::f64::consts::TAU;

    /// M points of the helix (r cos u, r sin u, p u), u from 0 to `turns` turns.
    pub(crate) fn helix(m: usize, r: f64, p: f64, turns: f64) -> Vec<DVec3> {
        (0..m)
            .map(|i| {
                let u = turns * TAU * i as f64 / (m - 1) as f64;
                DVec3::new(r * u.cos(), r * u.sin(), p * u)
            })
            .collect()
    }

    use crate::developable::coplanar::raw_max_abs_delta as max_abs_delta;

    #[test]
    fn every_construction_makes_consecutive_rulings_coplanar() {
        let c = helix(41, 1.0, 0.3, 1.5);
        let span = Span { from: 0.0, to: 0.8 };
        let strips = [
            tangent_surface(&c, span).unwrap(),
            cone(&c, DVec3::new(0.2, -0.1, 3.0), span).unwrap(),
            cylinder(&c, DVec3::new(0.1, 0.2, 1.0), Span { from: -0.4, to: 0.4 }).unwrap(),
            rectifying_developable(&c, Span { from: -0.4, to: 0.4 }).unwrap(),
        ];
        for s in &strips {
            assert!(max_abs_delta(s) <= 1e-13, "|δ| = {}", max_abs_delta(s));
        }
        // the exact tangents of the helix at the same points are skew: δ of order H² there
        let sampled: Vec<DVec3> = c
            .iter()
            .enumerate()
            .flat_map(|(i, &p)| {
                let u = 1.5 * TAU * i as f64 / 40.0;
                [p, p + 0.8 * DVec3::new(-u.sin(), u.cos(), 0.3)]
            })
            .collect();
        assert!(max_abs_delta(&RuledSurface::from_points(sampled).unwrap()) > 1e-4);
    }

    #[test]
    fn the_tangent_surface_follows_the_edges_and_starts_at_the_edge_of_regression() {
        let c = helix(9, 1.0, 0.3, 1.0);
        let s = tangent_surface(&c, Span { from: 0.0, to: 2.0 }).unwrap();
        assert_eq!(s.len(), 8);
        for i in 0..8 {
            let seg = s.segment(i);
            assert_near!(seg.a, c[i + 1], 1e-15);
            assert_near!(seg.line().dir, (c[i + 1] - c[i]).normalize(), 1e-15);
            assert_near!(seg.length(), 2.0, 1e-14);
        }
    }

    #[test]
    fn the_cone_passes_through_its_apex_and_the_cylinder_runs_parallel() {
        let c = helix(7, 1.0, 0.0, 0.5);
        let apex = DVec3::new(0.0, 0.0, 2.0);
        let s = cone(&c, apex, Span { from: 0.25, to: 1.0 }).unwrap();
        for (i, seg) in s.segments().enumerate() {
            assert_near!(seg.b, c[i], 1e-15);
            assert_near!(seg.a, apex + 0.25 * (c[i] - apex), 1e-15);
        }
        let s = cylinder(&c, DVec3::new(0.0, 0.0, 3.0), Span { from: -1.0, to: 2.0 }).unwrap();
        assert!(s.invariants().parallel.iter().all(|&p| p));
        for (i, seg) in s.segments().enumerate() {
            assert_eq!(seg.a, c[i] - DVec3::Z);
            assert_eq!(seg.b, c[i] + 2.0 * DVec3::Z);
        }
    }

    /// The rectifying developable of a helix is the cylinder over it along its axis (the helix's
    /// Darboux vector is constant), and of a plane curve the cylinder over it along the normal.
    #[test]
    fn the_rectifying_developable_of_a_helix_is_a_cylinder_along_its_axis() {
        for (r, p) in [(1.0, 0.3), (0.5, -0.8), (2.0, 0.0)] {
            let c = helix(60, r, p, 1.2);
            let s = rectifying_developable(&c, Span { from: -0.5, to: 0.5 }).unwrap();
            for seg in s.segments() {
                assert_near!(seg.line().dir, DVec3::Z, 1e-9);
            }
        }
    }

    #[test]
    fn the_rectifying_rulings_make_equal_angles_with_the_edges() {
        // a curve with varying curvature and torsion
        let c: Vec<DVec3> =
            (0..50).map(|i| i as f64 / 49.0 * 3.0).map(|u| DVec3::new(u, 0.4 * u * u, 0.1 * u * u * u)).collect();
        let s = rectifying_developable(&c, Span { from: -0.3, to: 0.3 }).unwrap();
        for i in 1..49 {
            let r = s.segment(i).line().dir;
            let (t0, t1) = ((c[i] - c[i - 1]).normalize(), (c[i + 1] - c[i]).normalize());
            assert_near!(r.dot(t0), r.dot(t1), 1e-13);
        }
        // consecutive rulings coplanar: the tetrahedron of a face's corners flat to rounding
        // (δ itself is ill-conditioned here: the smooth strip's rulings are nearly parallel)
        let (height, _) = crate::developable::coplanar::max_off_plane(&s);
        assert!(height <= 1e-14, "{height}");
    }

    /// The start kept is the least roughness Σ|r_{i+1} − 2r_i + r_{i−1}|² over all starts: a
    /// brute-force search over 0.005° does no better, on curves whose roughness has more than one
    /// dip (a steep helix, two cubics, a Lissajous curve, a zig-zag) — and the steep helix's strip
    /// is the cylinder along its axis.
    #[test]
    fn the_rectifying_start_is_the_least_roughness_of_all() {
        let rough = |r: &[DVec3]| r.windows(3).map(|w| (w[2] - 2.0 * w[1] + w[0]).length_squared()).sum::<f64>();
        let curve = |n: usize, to: f64, f: &dyn Fn(f64) -> DVec3| -> Vec<DVec3> {
            (0..n).map(|i| f(to * i as f64 / (n - 1) as f64)).collect()
        };
        let steep = helix(8, 1.0, 10.0, 0.3);
        let curves = [
            steep.clone(),
            curve(50, 3.0, &|u| DVec3::new(u, 0.4 * u * u, 0.1 * u * u * u)),
            curve(23, 3.6, &|u| DVec3::new(u, -0.4 * u * u, -0.1 * u * u * u)),
            curve(30, 6.0, &|u| DVec3::new(u.cos(), (2.0 * u).sin(), (3.0 * u).cos())),
            vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::ONE, DVec3::new(2.0, 1.0, 1.0)],
        ];
        for c in &curves {
            let kept = rough(&rectifying_rulings(c).unwrap());
            let t = edge_directions(c);
            let k = (1..c.len() - 1).find(|&k| t[k - 1].cross(t[k]).length() >= PARALLEL_SIN).unwrap();
            let (b, mean) = (t[k - 1].cross(t[k]).normalize(), (t[k - 1] + t[k]).normalize());
            let brute = (0..36_000)
                .map(|j| (j as f64 / 36_000.0 - 0.5) * std::f64::consts::PI)
                .filter_map(|a| propagate(&t, k, b * a.cos() + mean * a.sin(), &|i| t[i] - t[i - 1]).ok())
                .map(|r| rough(&r))
                .fold(f64::INFINITY, f64::min);
            assert!(kept <= brute * (1.0 + 1e-9), "{kept} > {brute}");
        }
        for seg in rectifying_developable(&steep, Span { from: -0.5, to: 0.5 }).unwrap().segments() {
            assert_near!(seg.line().dir, DVec3::Z, 1e-9);
        }
    }

    /// Every construction commutes with rigid motions: the strip of the moved directrix (and apex,
    /// and direction) is the moved strip.
    #[test]
    fn the_constructions_are_invariant_under_rigid_motions() {
        let c = helix(33, 1.0, 0.3, 1.2);
        let q = glam::DQuat::from_axis_angle(DVec3::new(1.0, 2.0, -0.5).normalize(), 0.9);
        let t = DVec3::new(2.0, -1.0, 4.0);
        let m: Vec<DVec3> = c.iter().map(|p| q * *p + t).collect();
        let (apex, dir) = (DVec3::new(0.2, -0.1, 3.0), DVec3::new(0.1, 0.2, 1.0));
        let span = Span { from: 0.1, to: 0.9 };
        let pairs = [
            (tangent_surface(&c, span).unwrap(), tangent_surface(&m, span).unwrap()),
            (cone(&c, apex, span).unwrap(), cone(&m, q * apex + t, span).unwrap()),
            (cylinder(&c, dir, span).unwrap(), cylinder(&m, q * dir, span).unwrap()),
            (rectifying_developable(&c, span).unwrap(), rectifying_developable(&m, span).unwrap()),
        ];
        for (k, (s, moved)) in pairs.iter().enumerate() {
            for (x, y) in s.points().iter().zip(moved.points()) {
                assert!((q * *x + t - *y).length() < 1e-9, "construction {k}: {x} {y}");
            }
        }
    }

    #[test]
    fn degenerate_directrices_and_spans_are_refused_with_their_reasons() {
        let c = helix(9, 1.0, 0.3, 1.0);
        let span = Span { from: 0.0, to: 1.0 };
        let reason = |e: Error| e.message().reason;
        assert_eq!(reason(tangent_surface(&c, Span { from: -0.1, to: 1.0 }).unwrap_err()), "span-crosses-regression");
        assert_eq!(reason(tangent_surface(&c, Span { from: 1.0, to: 1.0 }).unwrap_err()), "interval-order");
        assert_eq!(
            reason(cylinder(&c, DVec3::Z, Span { from: f64::NAN, to: 1.0 }).unwrap_err()),
            "interval-not-finite"
        );
        let straight = [DVec3::ZERO, DVec3::X, 2.0 * DVec3::X, DVec3::new(3.0, 1.0, 0.0)];
        assert_eq!(reason(tangent_surface(&straight, span).unwrap_err()), "directrix-no-turn-at");
        let twice = [DVec3::ZERO, DVec3::X, DVec3::X, DVec3::Y];
        assert_eq!(reason(cone(&twice, DVec3::Z, span).unwrap_err()), "directrix-edge-zero");
        assert_eq!(reason(cone(&c, c[3], span).unwrap_err()), "apex-on-directrix");
        assert_eq!(reason(cone(&[DVec3::X, 2.0 * DVec3::X], DVec3::ZERO, span).unwrap_err()), "apex-in-line");
        assert_eq!(reason(cylinder(&c, DVec3::ZERO, span).unwrap_err()), "direction-zero");
        assert_eq!(reason(cylinder(&[DVec3::ZERO, DVec3::Z], DVec3::Z, span).unwrap_err()), "edge-along-rulings");
        let line = [DVec3::ZERO, DVec3::X, 2.0 * DVec3::X];
        assert_eq!(reason(rectifying_developable(&line, span).unwrap_err()), "directrix-straight");
        assert!(matches!(tangent_surface(&c[..2], span), Err(Error::TooFew { min: 3, .. })));
        assert_eq!(tangent_surface(&c, span).map(|s| s.len()), Ok(8));
    }

    /// What counts as no edge, an apex on the directrix or in line with an edge is relative to
    /// where the points are (ZERO_LENGTH_REL of their size): far from the origin, near it, and
    /// with the apex off the origin.
    #[test]
    fn degenerate_is_relative_to_where_the_points_are() {
        let span = Span { from: 0.0, to: 1.0 };
        let reason = |e: Error| e.message().reason;
        // edges of 1 a thousand from the origin, and edges of 1e-8 at distance 1: both real edges
        let far = [DVec3::new(1000.0, 0.0, 0.0), DVec3::new(1001.0, 0.0, 0.0), DVec3::new(1001.0, 1.0, 0.0)];
        assert_eq!(cylinder(&far, DVec3::Z, span).map(|s| s.len()), Ok(3));
        let small = [DVec3::X, DVec3::new(1.0, 1e-8, 0.0), DVec3::new(1.0 + 1e-8, 1e-8, 0.0)];
        assert_eq!(cylinder(&small, DVec3::Z, span).map(|s| s.len()), Ok(3));
        // near the origin: an edge of 1e-14 at 1e-3 is one (1e-11 of the size), 1e-16 is none
        let tiny = |e: f64| [DVec3::new(1e-3, 0.0, 0.0), DVec3::new(1e-3, e, 0.0), DVec3::new(1e-3 + e, e, 0.0)];
        assert_eq!(cylinder(&tiny(1e-14), DVec3::Z, span).map(|s| s.len()), Ok(3));
        assert_eq!(reason(cylinder(&tiny(1e-16), DVec3::Z, span).unwrap_err()), "directrix-edge-zero");
        // a directrix point 1e-10 from an apex among points a thousand out: on it (1e-12 · 1000)
        let apex = DVec3::new(1000.0, 0.0, 0.0);
        let on = [apex + DVec3::new(0.0, 1e-10, 0.0), DVec3::new(1000.0, 5.0, 3.0), DVec3::new(990.0, 0.0, 4.0)];
        assert_eq!(reason(cone(&on, apex, span).unwrap_err()), "apex-on-directrix");
        // an edge in line with an apex off the origin
        let apex = DVec3::new(5.0, 5.0, 5.0);
        let in_line = [apex + DVec3::X, apex + 2.0 * DVec3::X, apex + DVec3::new(2.0, 1.0, 0.0)];
        assert_eq!(reason(cone(&in_line, apex, span).unwrap_err()), "apex-in-line");
    }

    /// The recurrence from a given ruling at vertex k, both ways (the unit tangents T_i given):
    /// an edge along the ruling it starts from (or within PARALLEL_SIN of it) is refused, naming
    /// the vertex (the ruling's own, forwards and backwards), and a turn out of the face's plane by less than
    /// PARALLEL_SIN repeats the ruling.
    #[test]
    fn the_recurrence_refuses_an_edge_along_the_ruling_and_repeats_it_past_a_turn_too_small() {
        use crate::error::Arg;
        let (x, y, z) = (DVec3::X, DVec3::Y, DVec3::Z);
        let turn_of = |t: &[DVec3]| {
            let t = t.to_vec();
            move |i: usize| t[i] - t[i - 1]
        };
        // the vertex a refusal names
        let point = |r: Result<Vec<DVec3>>| {
            let e = r.unwrap_err();
            assert_eq!(e.message().reason, "edge-along-ruling");
            e.message().arg("point").cloned()
        };
        let t = [y, x];
        let from = |v: DVec3| propagate(&t, 1, v, &turn_of(&t));
        // along T₁ (the edge after vertex 1), exactly or within PARALLEL_SIN: refused at vertex 1
        assert_eq!(point(from(x)), Some(Arg::Number(1.0)));
        assert_eq!(point(from((x + 1e-12 * y).normalize())), Some(Arg::Number(1.0)));
        // along T₀ (the edge before it): refused on the way back, at vertex 1 too
        assert_eq!(point(from(y)), Some(Arg::Number(1.0)));
        assert_eq!(from((x + y).normalize()).map(|r| r.len()), Ok(3));
        // the face of T₁ = x and the ruling (x + y)/√2 is the xy-plane; T₂ leaves it by 1.5e-9
        let phi: f64 = 1.5e-9;
        let t = [y, x, x * phi.cos() + z * phi.sin()];
        let r1 = (x + y).normalize();
        assert_eq!(propagate(&t, 1, r1, &turn_of(&t)).unwrap(), [r1, r1, r1, r1]);
    }

    /// From a vertex k past others that turn, the recurrence keeps equal angles at each of them
    /// backwards as forwards: r_i · T_{i−1} = r_i · T_i.
    #[test]
    fn the_recurrence_keeps_equal_angles_on_both_sides_of_its_start() {
        let c = helix(12, 1.0, 0.4, 0.8);
        let t: Vec<DVec3> = c.windows(2).map(|w| (w[1] - w[0]).normalize()).collect();
        let k = 6;
        let rk = (t[k - 1].cross(t[k]).normalize() + 0.3 * (t[k - 1] + t[k]).normalize()).normalize();
        let r = propagate(&t, k, rk, &|i| t[i] - t[i - 1]).unwrap();
        for i in 1..c.len() - 1 {
            assert_near!(r[i].dot(t[i - 1]), r[i].dot(t[i]), 1e-14);
        }
    }
}
