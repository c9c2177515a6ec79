//! How good a tool path is: smoothness of the orientation and deviation from the target.
//!
//! **The machined surface** is the boundary of the solid the tool sweeps: at each pose the tool
//! is a capsule (a ball end: the segment from the ball's centre tip + r·a to tip + L·a,
//! thickened by r) or a cylinder (a flat end: radius r from the tip over the length L along the
//! axis). Between two poses the controller moves the tip along the chord and turns the axis
//! along the arc; each block is cut into sub-blocks short enough that the axis turns by at most
//! [`ENVELOPE_STEP`] of the radius at the tool's far end, and over a sub-block the tool keeps the
//! sub-block's first axis while its tip slides along the chord. A ball's centre segment then
//! sweeps a parallelogram, and the distance from it less r is the sub-block's distance, exactly;
//! a flat end's signed distance is convex along the chord and golden-section search finds its
//! least value, the sub-blocks tried nearest first (the parallelogram its axis segment sweeps,
//! less r, bounds it from below). The **deviation** of a target
//! point q is its signed distance from the swept solid, the least over the sub-blocks: > 0 the
//! tool leaves material there, < 0 it cuts into the target (a gouge). Where the axis is
//! constant the answer is exact (the tests' circle).

use crate::{Pose, ToolEnd, ToolPath};
use glam::DVec3;

/// The largest turn of the axis within a sub-block of the envelope, as a share of the tool's
/// radius at its far end.
pub const ENVELOPE_STEP: f64 = 0.25;

/// The signed distance of `q` from the tool at pose `p` (module documentation).
pub fn tool_distance(q: DVec3, p: &Pose, radius: f64, length: f64, end: ToolEnd) -> f64 {
    let a = p.axis;
    match end {
        ToolEnd::Ball => {
            let c = p.tip + radius * a;
            let top = p.tip + length.max(radius) * a;
            let ab = top - c;
            let t =
                if ab.length_squared() > 0.0 { ((q - c).dot(ab) / ab.length_squared()).clamp(0.0, 1.0) } else { 0.0 };
            (q - (c + t * ab)).length() - radius
        }
        ToolEnd::Flat => {
            let v = q - p.tip;
            let h = v.dot(a);
            let rho = (v - h * a).length();
            let (dr, da) = (rho - radius, (-h).max(h - length));
            dr.max(0.0).hypot(da.max(0.0)) + dr.max(da).min(0.0)
        }
    }
}

/// The deviation of target points from the machined surface (module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct EnvelopeDeviation {
    /// Per target point: its signed distance from the swept tool.
    pub points: Vec<f64>,
    /// Per target point: where along the path the nearest tool is (k + s between poses k and k
    /// + 1).
    pub at: Vec<f64>,
    /// The target point of the largest |deviation|.
    pub worst: usize,
}

impl EnvelopeDeviation {
    /// Per pose of the path (`poses` of them): the deviation of largest size among the target
    /// points nearest it (within half a block); NaN where none is.
    pub fn per_pose(&self, poses: usize) -> Vec<f64> {
        let mut out = vec![f64::NAN; poses];
        for (d, at) in self.points.iter().zip(&self.at) {
            let k = (at.round() as usize).min(poses.saturating_sub(1));
            if out[k].is_nan() || d.abs() > out[k].abs() {
                out[k] = *d;
            }
        }
        out
    }
}

/// Minimises a function convex on [0, 1] by golden-section search: (argument, value).
fn golden(f: impl Fn(f64) -> f64) -> (f64, f64) {
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = (0.0f64, 1.0f64);
    let (mut x1, mut x2) = (b - g * (b - a), a + g * (b - a));
    let (mut f1, mut f2) = (f(x1), f(x2));
    for _ in 0..60 {
        if f1 <= f2 {
            b = x2;
            (x2, f2) = (x1, f1);
            x1 = b - g * (b - a);
            f1 = f(x1);
        } else {
            a = x1;
            (x1, f1) = (x2, f2);
            x2 = a + g * (b - a);
            f2 = f(x2);
        }
    }
    [(0.0, f(0.0)), (1.0, f(1.0)), (x1, f1), (x2, f2)].into_iter().fold((0.0, f64::INFINITY), |m, x| {
        if x.1 < m.1 {
            x
        } else {
            m
        }
    })
}

/// The sub-blocks of `path` (module documentation): (first pose, the chord's end tip, position
/// along the path at its start, its length in positions).
fn sub_blocks(path: &ToolPath) -> Vec<(Pose, DVec3, f64, f64)> {
    let (r, l) = (path.tool.radius, path.tool.length);
    let mut subs: Vec<(Pose, DVec3, f64, f64)> = Vec::new();
    let n = path.poses.len();
    for k in 0..n.saturating_sub(1) {
        let (a, b) = (&path.poses[k], &path.poses[k + 1]);
        let theta = a.axis.angle_between(b.axis);
        let pieces = ((theta * l.max(r) / (ENVELOPE_STEP * r)).ceil() as usize).clamp(1, 64);
        for j in 0..pieces {
            let (s0, s1) = (j as f64 / pieces as f64, (j + 1) as f64 / pieces as f64);
            let axis = slerp(a.axis, b.axis, theta, s0);
            let tip = a.tip.lerp(b.tip, s0);
            subs.push((Pose { tip, axis }, a.tip.lerp(b.tip, s1), k as f64 + s0, s1 - s0));
        }
    }
    if n == 1 {
        subs.push((path.poses[0], path.poses[0].tip, 0.0, 0.0));
    }
    subs
}

/// The deviation of `targets` from the surface `path`'s tool machines (module documentation).
pub fn envelope_deviation(path: &ToolPath, targets: &[DVec3]) -> EnvelopeDeviation {
    let (r, l, end) = (path.tool.radius, path.tool.length, path.tool.end);
    let subs = sub_blocks(path);
    let mut points = Vec::with_capacity(targets.len());
    let mut at = Vec::with_capacity(targets.len());
    // a flat end's sub-blocks, nearest bound first (reused per target point)
    let mut order: Vec<(f64, usize)> = Vec::with_capacity(subs.len());
    for &q in targets {
        let (mut best, mut where_) = (f64::INFINITY, 0.0);
        match end {
            // over a sub-block the ball's centre segment sweeps a parallelogram: the distance
            // from it less r is the sub-block's deviation, exactly
            ToolEnd::Ball => {
                for (p, to, start, span) in &subs {
                    let (d, s) = nearest_in_parallelogram(q, p.tip + r * p.axis, *to - p.tip, (l.max(r) - r) * p.axis);
                    if d - r < best {
                        (best, where_) = (d - r, start + s * span);
                    }
                }
            }
            // the cylinder lies within r of its axis segment: the distance from the parallelogram
            // that segment sweeps, less r, bounds the sub-block's deviation from below
            ToolEnd::Flat => {
                order.clear();
                order.extend(
                    subs.iter().enumerate().map(|(i, (p, to, _, _))| {
                        (nearest_in_parallelogram(q, p.tip, *to - p.tip, l * p.axis).0 - r, i)
                    }),
                );
                order.sort_by(|a, b| a.0.total_cmp(&b.0));
                for &(bound, i) in &order {
                    if bound >= best {
                        break;
                    }
                    let (p, to, start, span) = &subs[i];
                    let (s, d) =
                        golden(|s| tool_distance(q, &Pose { tip: p.tip.lerp(*to, s), axis: p.axis }, r, l, end));
                    if d < best {
                        (best, where_) = (d, start + s * span);
                    }
                }
            }
        }
        points.push(best);
        at.push(where_);
    }
    let worst = (0..points.len()).fold(0, |w, i| if points[i].abs() > points[w].abs() { i } else { w });
    EnvelopeDeviation { points, at, worst }
}

/// The unit vector a fraction `s` along the great-circle arc from unit `a` to unit `b` (θ apart).
fn slerp(a: DVec3, b: DVec3, theta: f64, s: f64) -> DVec3 {
    if theta < 1e-12 {
        return a;
    }
    (((1.0 - s) * theta).sin() * a + (s * theta).sin() * b) / theta.sin()
}

/// Orientation smoothness of a path.
#[derive(Debug, Clone, PartialEq)]
pub struct Quality {
    /// Angle between consecutive axes (radians), one per step.
    pub angle_step: Vec<f64>,
    /// Second difference of the axis, |a_{k−1} − 2a_k + a_{k+1}| (radians², as a measure of
    /// how unevenly the orientation turns), one per interior pose.
    pub second_difference: Vec<f64>,
}

impl Quality {
    /// Measures `path`.
    pub fn of(path: &ToolPath) -> Self {
        let a: Vec<DVec3> = path.poses.iter().map(|p| p.axis).collect();
        Quality {
            angle_step: a.windows(2).map(|w| w[0].angle_between(w[1])).collect(),
            second_difference: a.windows(3).map(|w| (w[0] - 2.0 * w[1] + w[2]).length()).collect(),
        }
    }

    /// Largest angle step.
    pub fn max_angle_step(&self) -> f64 {
        self.angle_step.iter().copied().fold(0.0, f64::max)
    }

    /// Largest second difference.
    pub fn max_second_difference(&self) -> f64 {
        self.second_difference.iter().copied().fold(0.0, f64::max)
    }
}

/// Signed deviation of each target point from the surface the tool leaves: its distance to
/// the cutting-centre polyline minus r for a ball end (> 0: material left, < 0: gouge).
/// For a flat end the distance to the polyline of disk centres minus r approximates the
/// same for a tool swept sideways.
pub fn deviation(path: &ToolPath, targets: &[DVec3]) -> Vec<f64> {
    let c = path.cutting_centres();
    targets
        .iter()
        .map(|&q| {
            let d = c.windows(2).map(|w| distance_to_segment(q, w[0], w[1])).fold(f64::INFINITY, f64::min);
            d - path.tool.radius
        })
        .collect()
}

/// Per pose of the path: the distance of its cutting centre from the target polyline minus r
/// (for a ball end, how far the ball stands off the target curve at that pose: > 0 material
/// left, < 0 a gouge; 0 where the ball touches it) — the deviation along the path.
pub fn deviation_per_pose(path: &ToolPath, targets: &[DVec3]) -> Vec<f64> {
    path.cutting_centres()
        .iter()
        .map(|&c| {
            let d = targets.windows(2).map(|w| distance_to_segment(c, w[0], w[1])).fold(f64::INFINITY, f64::min);
            d - path.tool.radius
        })
        .collect()
}

/// The point of the parallelogram o + s·u + t·v (s, t ∈ [0, 1]) nearest `q`: its distance and s.
/// Inside, the distance from the plane; else the nearest of the four edges (also where u and v
/// are parallel or zero).
fn nearest_in_parallelogram(q: DVec3, o: DVec3, u: DVec3, v: DVec3) -> (f64, f64) {
    let w = q - o;
    let (uu, uv, vv) = (u.dot(u), u.dot(v), v.dot(v));
    let det = uu * vv - uv * uv;
    if det > 1e-24 * uu * vv && det > 0.0 {
        let (wu, wv) = (w.dot(u), w.dot(v));
        let (s, t) = ((wu * vv - wv * uv) / det, (wv * uu - wu * uv) / det);
        if (0.0..=1.0).contains(&s) && (0.0..=1.0).contains(&t) {
            return (w.dot(u.cross(v)).abs() / det.sqrt(), s);
        }
    }
    let along = |a: DVec3, d: DVec3| {
        let t = if d.length_squared() > 0.0 { ((q - a).dot(d) / d.length_squared()).clamp(0.0, 1.0) } else { 0.0 };
        ((q - (a + t * d)).length(), t)
    };
    let (bottom, top) = (along(o, u), along(o + v, u));
    let (first, last) = ((along(o, v).0, 0.0), (along(o + u, v).0, 1.0));
    [bottom, top, first, last].into_iter().fold((f64::INFINITY, 0.0), |m, e| if e.0 < m.0 { e } else { m })
}

fn distance_to_segment(q: DVec3, a: DVec3, b: DVec3) -> f64 {
    let ab = b - a;
    let t = if ab.length_squared() > 0.0 { ((q - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0) } else { 0.0 };
    (q - (a + t * ab)).length()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Tool;
    use std::f64::consts::{FRAC_PI_2, PI};

    /// A ball end of radius r = 2 and length 20 around a circle: N = 24 poses, the ball's centre
    /// on the circle of radius R = 30 at height h = 2 (the tip at 0), the axis vertical. The
    /// machine cuts the chords, so the centre runs on the 24-gon. A target point q at angle φ
    /// on the circle of radius R_t = 28 at height z_t = −1 lies nearest the chord whose middle
    /// is at the angle m of φ's block: in that block's plane, at distance R cos(π/N) −
    /// R_t cos(φ − m) across the chord and z_t − h below it, so its deviation is
    /// √((R cos(π/N) − R_t cos(φ − m))² + (h − z_t)²) − r exactly. A flat end of the same size
    /// with its tip at height h: its bottom disk sweeps the same chords, so the point is
    /// √(max(0, R cos(π/N) − R_t cos(φ − m) − r)² + (h − z_t)²) from it.
    #[test]
    fn a_tool_around_a_circle_deviates_by_the_distance_in_closed_form() {
        let (n, big_r, r, h, rt, zt) = (24usize, 30.0, 2.0, 2.0, 28.0, -1.0);
        let poses = |tip_z: f64| -> Vec<Pose> {
            (0..=n)
                .map(|k| {
                    let f = 2.0 * PI * k as f64 / n as f64;
                    Pose { tip: DVec3::new(big_r * f.cos(), big_r * f.sin(), tip_z), axis: DVec3::Z }
                })
                .collect()
        };
        let ball = ToolPath { poses: poses(h - r), tool: Tool::new(r, 20.0, ToolEnd::Ball).unwrap() };
        let flat = ToolPath { poses: poses(h), tool: Tool::new(r, 20.0, ToolEnd::Flat).unwrap() };
        let phis: Vec<f64> = (0..50).map(|k| 0.123 + 2.0 * PI * k as f64 / 50.0).collect();
        let targets: Vec<DVec3> = phis.iter().map(|f| DVec3::new(rt * f.cos(), rt * f.sin(), zt)).collect();
        let block = 2.0 * PI / n as f64;
        let across = |f: f64| {
            let m = (f / block).floor() * block + block / 2.0;
            big_r * (PI / n as f64).cos() - rt * (f - m).cos()
        };
        let b = envelope_deviation(&ball, &targets);
        let fl = envelope_deviation(&flat, &targets);
        for (k, &f) in phis.iter().enumerate() {
            let want = across(f).hypot(h - zt) - r;
            assert!((b.points[k] - want).abs() < 1e-9, "ball at φ = {f}: {} vs {want}", b.points[k]);
            let want = (across(f) - r).max(0.0).hypot(h - zt);
            assert!((fl.points[k] - want).abs() < 1e-9, "flat at φ = {f}: {} vs {want}", fl.points[k]);
            // the nearest tool is in φ's block
            assert!((b.at[k] - f / block).abs() < 1.0, "{} vs {}", b.at[k], f / block);
        }
        // the worst point is where the chord is farthest from the target: φ at a block's end
        let worst = b.points[b.worst];
        assert!(b.points.iter().all(|d| d.abs() <= worst.abs()));
        // per pose: each pose's nearest target points, their largest deviation
        let per = b.per_pose(n + 1);
        assert_eq!(per.len(), n + 1);
        assert!(per.iter().filter(|d| d.is_finite()).count() >= n - 1);
        // a target inside the tool is cut into: negative
        let gouge = envelope_deviation(&ball, &[DVec3::new(big_r, 0.0, h)]);
        assert!((gouge.points[0] + r).abs() < 1e-12, "{}", gouge.points[0]);
    }

    /// A helix: the ball's centre on the helix (R cos t, R sin t, c t) with a vertical axis, the
    /// target the helix's axis line point (0, 0, z): its distance from every centre is at least
    /// R; with dense poses the deviation tends to R − r (to the chords' sag, R(1 − cos(π/N))).
    #[test]
    fn a_ball_along_a_helix_is_r_minus_its_radius_from_the_axis() {
        let (n, big_r, c, r) = (720usize, 10.0, 1.0, 1.5);
        let poses: Vec<Pose> = (0..=n)
            .map(|k| {
                let t = 4.0 * PI * k as f64 / n as f64;
                Pose { tip: DVec3::new(big_r * t.cos(), big_r * t.sin(), c * t - r), axis: DVec3::Z }
            })
            .collect();
        let path = ToolPath { poses, tool: Tool::new(r, 10.0, ToolEnd::Ball).unwrap() };
        let d = envelope_deviation(&path, &[DVec3::new(0.0, 0.0, 2.0 * PI * c)]);
        let sag = big_r * (1.0 - (PI / (n as f64 / 2.0)).cos());
        assert!(d.points[0] <= big_r - r + 1e-12 && d.points[0] >= big_r - r - sag - 1e-12, "{}", d.points[0]);
    }

    /// The fast ways agree with trying every sub-block by golden-section search: a ball's
    /// parallelogram to rounding, a flat end's bound never skips the nearest sub-block (equal).
    #[test]
    fn the_parallelogram_and_the_bound_agree_with_every_sub_block_searched() {
        let mut seed = 7;
        let mut u = || ruledlab::tolerance::test::uniform(&mut seed) * 2.0 - 1.0;
        let poses: Vec<(DVec3, DVec3)> = (0..7)
            .map(|k| {
                let tip = DVec3::new(k as f64, 0.3 * (k as f64).sin(), 0.1 * k as f64);
                (tip, DVec3::new(0.4 * u(), 0.4 * u(), 1.0).normalize())
            })
            .collect();
        for end in [ToolEnd::Ball, ToolEnd::Flat] {
            let p = path(&poses, end);
            let targets: Vec<DVec3> = (0..300).map(|k| DVec3::new(6.0 * k as f64 / 299.0, u(), u() + 0.5)).collect();
            let fast = envelope_deviation(&p, &targets);
            let subs = sub_blocks(&p);
            for (q, got) in targets.iter().zip(&fast.points) {
                let all = subs
                    .iter()
                    .map(|(s, to, _, _)| {
                        golden(|x| tool_distance(*q, &Pose { tip: s.tip.lerp(*to, x), axis: s.axis }, 0.5, 2.0, end)).1
                    })
                    .fold(f64::INFINITY, f64::min);
                match end {
                    ToolEnd::Ball => assert!((got - all).abs() < 1e-9, "{q}: {got} against {all}"),
                    ToolEnd::Flat => assert_eq!(*got, all, "{q}"),
                }
            }
        }
    }

    fn path(poses: &[(DVec3, DVec3)], end: ToolEnd) -> ToolPath {
        ToolPath {
            poses: poses.iter().map(|&(tip, axis)| Pose { tip, axis }).collect(),
            tool: Tool::new(0.5, 2.0, end).unwrap(),
        }
    }

    /// Axes Z, X, Z: two right-angle steps, and |Z − 2X + Z| = 2√2.
    #[test]
    fn smoothness_of_the_orientation() {
        let p = path(&[(DVec3::ZERO, DVec3::Z), (DVec3::X, DVec3::X), (2.0 * DVec3::X, DVec3::Z)], ToolEnd::Ball);
        let q = Quality::of(&p);
        assert_eq!(q.angle_step, [FRAC_PI_2, FRAC_PI_2]);
        assert_eq!(q.second_difference, [2.0 * 2f64.sqrt()]);
        assert_eq!((q.max_angle_step(), q.max_second_difference()), (FRAC_PI_2, 2.0 * 2f64.sqrt()));
        let straight = Quality::of(&path(&[(DVec3::ZERO, DVec3::Z), (DVec3::X, DVec3::Z)], ToolEnd::Ball));
        assert_eq!((straight.max_angle_step(), straight.max_second_difference()), (0.0, 0.0));
    }

    /// A ball of radius ½ whose centre runs from (0, 0, ½) to (2, 0, ½): targets below the
    /// centre line by ¾ leave ¼ of material, above it by ¼ are gouged by ¼; beyond the ends the
    /// distance is to the end.
    #[test]
    fn deviation_from_the_targets() {
        let p = path(&[(DVec3::ZERO, DVec3::Z), (2.0 * DVec3::X, DVec3::Z)], ToolEnd::Ball);
        let targets = [
            DVec3::new(1.0, 0.0, -0.25),
            DVec3::new(1.0, 0.0, 0.25),
            DVec3::new(3.0, 0.0, 0.5),
            DVec3::new(-1.0, 0.0, 0.5),
        ];
        assert_eq!(deviation(&p, &targets), [0.25, -0.25, 0.5, 0.5]);
        // per pose: the centres (0, 0, ½) and (2, 0, ½) against the target line z = 0: they touch it
        assert_eq!(deviation_per_pose(&p, &[DVec3::ZERO, 4.0 * DVec3::X]), [0.0, 0.0]);
        let raised =
            path(&[(DVec3::new(1.0, 0.0, 0.25), DVec3::Z), (DVec3::new(5.0, 0.0, 0.0), DVec3::Z)], ToolEnd::Ball);
        assert_eq!(deviation_per_pose(&raised, &[DVec3::ZERO, 4.0 * DVec3::X]), [0.25, 1f64.hypot(0.5) - 0.5]);
        // a flat end cuts with the tip itself
        let flat = path(&[(DVec3::ZERO, DVec3::Z), (2.0 * DVec3::X, DVec3::Z)], ToolEnd::Flat);
        assert_eq!(deviation(&flat, &[DVec3::new(1.0, 0.0, -0.75)]), [0.25]);
        // a path that does not start at x = 0: the foot on the centre line is at x = 2
        let shifted = path(&[(DVec3::X, DVec3::Z), (3.0 * DVec3::X, DVec3::Z)], ToolEnd::Ball);
        assert_eq!(deviation(&shifted, &[DVec3::new(2.0, 0.0, -0.25)]), [0.25]);
        // a target segment of no length is its point
        assert_eq!(deviation_per_pose(&p, &[DVec3::new(0.0, 0.0, 2.0), DVec3::new(0.0, 0.0, 2.0)])[0], 1.0);
    }
}
