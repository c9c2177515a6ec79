//! The stock and the tool as solids for the G-code post's safety checks (Example 6's paths on
//! a real machine): the stock is a box in the part frame (the part is inside it, so a move that
//! keeps clear of the box keeps clear of the part); the tool is a chain of coaxial cylinders with
//! flat ends — the cutter (a flat end, or a ball end: its half ball and the cylinder above the
//! ball's centre), the shank, the holder. Whether a cylinder enters the box is exact
//! ([`Aabb::distance_from_axis`]): the box cut by the slab of the cylinder's heights is a convex
//! polytope, and the cylinder meets it where the polytope comes within its radius of the axis —
//! the distance, along the axis, of the polygon its vertices project to.

use glam::DVec3;

/// A box with faces parallel to the part frame's planes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb {
    /// The corner of least coordinates.
    pub min: DVec3,
    /// The corner of largest coordinates.
    pub max: DVec3,
}

impl Aabb {
    /// The box of `points` (empty input: the origin).
    pub fn around(points: impl IntoIterator<Item = DVec3>) -> Aabb {
        let mut b = Aabb { min: DVec3::splat(f64::INFINITY), max: DVec3::splat(f64::NEG_INFINITY) };
        for p in points {
            b.min = b.min.min(p);
            b.max = b.max.max(p);
        }
        if b.min.x > b.max.x {
            return Aabb { min: DVec3::ZERO, max: DVec3::ZERO };
        }
        b
    }

    /// The box grown by `d` on every side.
    pub fn grown(&self, d: f64) -> Aabb {
        Aabb { min: self.min - DVec3::splat(d), max: self.max + DVec3::splat(d) }
    }

    /// The distance of `p` from the box (0 inside).
    pub fn distance(&self, p: DVec3) -> f64 {
        (self.min - p).max(p - self.max).max(DVec3::ZERO).length()
    }

    /// The least distance from the line through `a` along unit `d` of the box's points whose
    /// height h = (x − a)·d lies in [0, `len`] (∞ where none does; module documentation): the
    /// vertices of that polytope are the box's corners within the slab and the points where its
    /// edges cross the planes h = 0 and h = len; projected along d they span a convex polygon,
    /// and the answer is the polygon's distance from the line's point (0 where it holds it).
    pub fn distance_from_axis(&self, a: DVec3, d: DVec3, len: f64) -> f64 {
        let corner = |i: usize| {
            DVec3::new(
                if i & 1 == 0 { self.min.x } else { self.max.x },
                if i & 2 == 0 { self.min.y } else { self.max.y },
                if i & 4 == 0 { self.min.z } else { self.max.z },
            )
        };
        let h = |p: DVec3| (p - a).dot(d);
        let mut points: Vec<DVec3> = (0..8).map(corner).filter(|&c| (0.0..=len).contains(&h(c))).collect();
        for i in 0..8 {
            for bit in [1, 2, 4] {
                let j = i | bit;
                if j == i {
                    continue;
                }
                let (p, q) = (corner(i), corner(j));
                let (hp, hq) = (h(p), h(q));
                for plane in [0.0, len] {
                    if (hp - plane) * (hq - plane) < 0.0 {
                        points.push(p + (plane - hp) / (hq - hp) * (q - p));
                    }
                }
            }
        }
        if points.is_empty() {
            return f64::INFINITY;
        }
        let e1 = d.any_orthonormal_vector();
        let e2 = d.cross(e1);
        let flat: Vec<(f64, f64)> = points.iter().map(|&p| ((p - a).dot(e1), (p - a).dot(e2))).collect();
        polygon_distance(&hull(flat))
    }

    /// The parameter t ≥ 0 where the ray `from` + t·`dir` leaves the box (0 if it starts outside
    /// and never enters; the slab method).
    pub fn exit(&self, from: DVec3, dir: DVec3) -> f64 {
        let (mut t0, mut t1) = (0.0f64, f64::INFINITY);
        for k in 0..3 {
            if dir[k].abs() < 1e-15 {
                if from[k] < self.min[k] || from[k] > self.max[k] {
                    return 0.0;
                }
                continue;
            }
            let (a, b) = ((self.min[k] - from[k]) / dir[k], (self.max[k] - from[k]) / dir[k]);
            t0 = t0.max(a.min(b));
            t1 = t1.min(a.max(b));
        }
        if t0 <= t1 && t1.is_finite() {
            t1.max(0.0)
        } else {
            0.0
        }
    }
}

/// The convex hull of points in the plane, counter-clockwise (Andrew's monotone chain; fewer
/// than three points, or points on a line: its ends).
fn hull(mut p: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    p.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let cross = |o: (f64, f64), a: (f64, f64), b: (f64, f64)| (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0);
    let mut h: Vec<(f64, f64)> = Vec::with_capacity(2 * p.len());
    for pass in 0..2 {
        let start = h.len();
        let points: Box<dyn Iterator<Item = &(f64, f64)>> =
            if pass == 0 { Box::new(p.iter()) } else { Box::new(p.iter().rev()) };
        for &q in points {
            while h.len() >= start + 2 && cross(h[h.len() - 2], h[h.len() - 1], q) <= 0.0 {
                h.pop();
            }
            h.push(q);
        }
        h.pop();
    }
    h
}

/// The distance of the origin from a convex polygon given counter-clockwise (0 inside; a point or
/// a segment as such).
fn polygon_distance(h: &[(f64, f64)]) -> f64 {
    let to_segment = |a: (f64, f64), b: (f64, f64)| {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let l2 = dx * dx + dy * dy;
        let t = if l2 > 0.0 { (-(a.0 * dx + a.1 * dy) / l2).clamp(0.0, 1.0) } else { 0.0 };
        (a.0 + t * dx).hypot(a.1 + t * dy)
    };
    match h.len() {
        0 => f64::INFINITY,
        1 => h[0].0.hypot(h[0].1),
        _ => {
            let n = h.len();
            let inside = n >= 3
                && (0..n).all(|i| {
                    let (a, b) = (h[i], h[(i + 1) % n]);
                    (b.0 - a.0) * (-a.1) - (b.1 - a.1) * (-a.0) >= 0.0
                });
            if inside {
                0.0
            } else {
                (0..n).map(|i| to_segment(h[i], h[(i + 1) % n])).fold(f64::INFINITY, f64::min)
            }
        }
    }
}

/// A stretch of the tool along its axis: from `from` to `to` (distance from the tip) with
/// radius `radius`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stretch {
    /// Start, along the axis from the tip.
    pub from: f64,
    /// End.
    pub to: f64,
    /// Radius.
    pub radius: f64,
}

/// The tool as solids along its axis: what checks the stock.
#[derive(Debug, Clone, PartialEq)]
pub struct ToolShape {
    /// A ball end of the cutter's radius (else flat).
    pub ball: bool,
    /// The cutter.
    pub cutter: Stretch,
    /// The shank and the holder, where they are given (empty stretches left out).
    pub above: Vec<(&'static str, Stretch)>,
}

impl ToolShape {
    /// The stretches named `parts` ("cutter", "shank", "holder") as segments of the axis with
    /// their radius, from the tip up; a ball end's cutter from its centre, a radius up the axis.
    pub fn stretches(&self, tip: DVec3, axis: DVec3, parts: &[&str]) -> Vec<(DVec3, DVec3, f64, &'static str)> {
        let c = self.cutter;
        let cutter = Stretch { from: if self.ball { c.radius.min(c.to) } else { c.from }, ..c };
        std::iter::once(("cutter", cutter))
            .chain(self.above.iter().copied())
            .filter(|(name, s)| parts.contains(name) && s.to >= s.from && s.radius > 0.0)
            .map(|(name, s)| (tip + s.from * axis, tip + s.to * axis, s.radius, name))
            .collect()
    }

    /// How far the part named `part` reaches into the box at this pose: its radius less its
    /// axis's distance from the box (the ball's centre's too for a ball end's cutter), the largest
    /// over its stretches — > 0 where it enters; `None` for a part the tool has not.
    pub fn depth(&self, tip: DVec3, axis: DVec3, part: &str, stock: &Aabb) -> Option<f64> {
        self.stretches(tip, axis, &[part])
            .into_iter()
            .map(|(a, b, r, name)| {
                let axis_distance = stock.distance_from_axis(a, axis, (b - a).length());
                let ball = if name == "cutter" && self.ball { stock.distance(a) } else { f64::INFINITY };
                r - axis_distance.min(ball)
            })
            .reduce(f64::max)
    }

    /// The first part of the tool (of `parts`) that enters the box at this pose, if one does:
    /// its cylinder (flat ends; a ball end's half ball too) comes nearer the box than its radius
    /// less 10⁻⁹ mm (a touch is clear), or its axis meets the box (however thin the part).
    pub fn enters(&self, tip: DVec3, axis: DVec3, parts: &[&str], stock: &Aabb) -> Option<&'static str> {
        self.stretches(tip, axis, parts)
            .into_iter()
            .find(|&(a, b, r, name)| {
                let within = (r - 1e-9).max(f64::MIN_POSITIVE);
                let ball = name == "cutter" && self.ball && stock.distance(a) < within;
                ball || stock.distance_from_axis(a, axis, (b - a).length()) < within
            })
            .map(|(_, _, _, n)| n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_box_measures_distances_and_exits() {
        let b = Aabb { min: DVec3::ZERO, max: DVec3::new(2.0, 2.0, 1.0) };
        assert_eq!(b.distance(DVec3::new(1.0, 1.0, 0.5)), 0.0);
        assert_eq!(b.distance(DVec3::new(1.0, 1.0, 4.0)), 3.0);
        assert_eq!(b.distance(DVec3::new(5.0, 6.0, 0.5)), 5.0);
        // from inside straight up: out at z = 1; along (0, 0.6, 0.8) from (1, 1, 0): y = 2 at t = 5/3,
        // z = 1 at t = 1.25, so at 1.25
        assert_eq!(b.exit(DVec3::new(1.0, 1.0, 0.25), DVec3::Z), 0.75);
        assert!((b.exit(DVec3::new(1.0, 1.0, 0.0), DVec3::new(0.0, 0.6, 0.8)) - 1.25).abs() < 1e-15);
        // a ray that misses it, or starts beyond it
        assert_eq!(b.exit(DVec3::new(5.0, 1.0, 0.5), DVec3::Z), 0.0);
        assert_eq!(b.exit(DVec3::new(1.0, 1.0, 3.0), DVec3::Z), 0.0);
        assert_eq!(Aabb::around([DVec3::X, DVec3::Y]).grown(1.0).max, DVec3::new(2.0, 2.0, 1.0));
        // out through the floor and a side on the way down (negative slopes): z = 0 at t = 1.5
        // first, y = 0 only at t = 4
        assert_eq!(b.exit(DVec3::new(1.0, 1.0, 0.75), DVec3::new(0.0, -0.25, -0.5)), 1.5);
    }

    /// The parts named, from the tip up, each a segment of the axis with its radius: a ball end's
    /// cutter from the ball's centre (a radius up), a flat end's from its face; a part left out
    /// of `parts`, or ending below its start or without radius, is not there.
    #[test]
    fn a_tool_is_its_stretches_along_the_axis() {
        let (tip, axis) = (DVec3::new(1.0, 2.0, 3.0), DVec3::new(0.0, 0.6, 0.8));
        let mut tool = ToolShape {
            ball: true,
            cutter: Stretch { from: 0.0, to: 10.0, radius: 2.0 },
            above: vec![
                ("shank", Stretch { from: 10.0, to: 20.0, radius: 1.5 }),
                ("holder", Stretch { from: 20.0, to: 20.0, radius: 8.0 }),
            ],
        };
        let s = tool.stretches(tip, axis, &["cutter", "shank", "holder"]);
        assert_eq!(s.iter().map(|x| x.3).collect::<Vec<_>>(), ["cutter", "shank", "holder"]);
        assert_eq!(s[0], (tip + 2.0 * axis, tip + 10.0 * axis, 2.0, "cutter"));
        assert_eq!(s[1], (tip + 10.0 * axis, tip + 20.0 * axis, 1.5, "shank"));
        assert_eq!(tool.stretches(tip, axis, &["shank"]).len(), 1);
        tool.ball = false;
        tool.above[1].1.radius = 0.0;
        let s = tool.stretches(tip, axis, &["cutter", "holder"]);
        assert_eq!(s, vec![(tip, tip + 10.0 * axis, 2.0, "cutter")]);
        // a ball longer than its cutter: the cutter is the ball, from its centre
        tool.ball = true;
        tool.cutter.to = 1.0;
        assert_eq!(tool.stretches(tip, axis, &["cutter"])[0].0, tip + axis);
        tool.above[0].1.to = 5.0;
        assert!(tool.stretches(tip, axis, &["shank"]).is_empty());
    }

    /// A tool of radius 1 standing 0.5 above the box's top: the ball end clear; tilted into a
    /// wall, the holder (radius 10 from 20 to 40 up the axis) enters it first.
    #[test]
    fn the_tool_enters_the_stock_by_its_parts() {
        let stock = Aabb { min: DVec3::new(-50.0, -50.0, -10.0), max: DVec3::new(50.0, 50.0, 0.0) };
        let tool = ToolShape {
            ball: true,
            cutter: Stretch { from: 0.0, to: 10.0, radius: 1.0 },
            above: vec![
                ("shank", Stretch { from: 10.0, to: 20.0, radius: 1.0 }),
                ("holder", Stretch { from: 20.0, to: 40.0, radius: 10.0 }),
            ],
        };
        let all = ["cutter", "shank", "holder"];
        assert_eq!(tool.enters(DVec3::new(0.0, 0.0, 0.5), DVec3::Z, &all, &stock), None);
        assert_eq!(tool.enters(DVec3::new(0.0, 0.0, -0.5), DVec3::Z, &all, &stock), Some("cutter"));
        // lying almost flat, 2 above the top: the holder's radius reaches down into it
        let flat = DVec3::new(1.0, 0.0, 0.05).normalize();
        assert_eq!(tool.enters(DVec3::new(0.0, 0.0, 2.0), flat, &all, &stock), Some("holder"));
        assert_eq!(tool.enters(DVec3::new(0.0, 0.0, 2.0), flat, &["cutter", "shank"], &stock), None);
    }

    /// How deep a part reaches into the stock: its radius less its axis's distance from the box.
    #[test]
    fn a_part_reaches_into_the_stock_by_its_radius_less_its_distance() {
        let stock = Aabb { min: DVec3::new(-50.0, -50.0, -10.0), max: DVec3::new(50.0, 50.0, 0.0) };
        let tool = ToolShape {
            ball: false,
            cutter: Stretch { from: 0.0, to: 10.0, radius: 1.0 },
            above: vec![("holder", Stretch { from: 20.0, to: 40.0, radius: 10.0 })],
        };
        // lying flat 4 above the top: the holder's axis is 4 from the box, so it reaches 6 in
        let flat = DVec3::X;
        let depth = tool.depth(DVec3::new(0.0, 0.0, 4.0), flat, "holder", &stock).unwrap();
        assert!((depth - 6.0).abs() < 1e-12, "{depth}");
        // upright: the cutter's axis stands on the top (distance 0); no point of the box lies
        // beside the holder, 20 up: it reaches nowhere (−∞)
        assert_eq!(tool.depth(DVec3::ZERO, DVec3::Z, "holder", &stock), Some(f64::NEG_INFINITY));
        assert_eq!(tool.depth(DVec3::ZERO, DVec3::Z, "cutter", &stock), Some(1.0));
        assert_eq!(tool.depth(DVec3::ZERO, DVec3::Z, "shank", &stock), None);
        // a ball end: its centre, a radius up, touches the top at the radius: depth 0
        let ball = ToolShape { ball: true, ..tool };
        assert!(ball.depth(DVec3::ZERO, DVec3::Z, "cutter", &stock).unwrap().abs() < 1e-12);
    }

    /// A tool of radius 10⁻³²² (a fuzzer's) is checked as quickly as any: its cylinders, not
    /// balls a quarter radius apart.
    #[test]
    fn a_tool_of_any_radius_is_checked_at_once() {
        let stock = Aabb { min: DVec3::new(-50.0, -50.0, -10.0), max: DVec3::new(50.0, 50.0, 0.0) };
        let tiny = 1.9e-322;
        let tool = ToolShape { ball: true, cutter: Stretch { from: 0.0, to: 1.5, radius: tiny }, above: vec![] };
        assert_eq!(tool.enters(DVec3::new(0.0, 0.0, 0.5), DVec3::Z, &["cutter"], &stock), None);
        assert_eq!(tool.enters(DVec3::new(0.0, 0.0, -1.0), DVec3::Z, &["cutter"], &stock), Some("cutter"));
    }

    /// The cylinder check is exact: for random boxes and cylinders, the distance it finds is the
    /// radius at which the solid cylinder starts to meet the box — 2 % larger and a fine sampling
    /// of the cylinder finds a point in the box (within its spacing), 2 % smaller and none.
    #[test]
    fn a_cylinder_meets_the_box_at_the_distance_of_its_axis() {
        let mut seed = 5;
        let mut u = || ruledlab::tolerance::test::uniform(&mut seed) * 2.0 - 1.0;
        let b = Aabb { min: DVec3::new(-1.0, -2.0, -0.5), max: DVec3::new(1.0, 2.0, 0.5) };
        let mut checked = 0;
        for _ in 0..40 {
            let a = DVec3::new(3.0 * u(), 3.0 * u(), 2.0 * u());
            let d = DVec3::new(u(), u(), u()).normalize();
            let len = 1.0 + 2.0 * (u() + 1.0);
            let dist = b.distance_from_axis(a, d, len);
            if !dist.is_finite() || !(0.05..2.0).contains(&dist) {
                continue;
            }
            checked += 1;
            let e1 = d.any_orthonormal_vector();
            let e2 = d.cross(e1);
            let nearest = |rho: f64| {
                let mut best = f64::INFINITY;
                for i in 0..=60 {
                    for j in 0..=24 {
                        for k in 0..72 {
                            let (t, s, f) =
                                (len * i as f64 / 60.0, rho * j as f64 / 24.0, k as f64 * std::f64::consts::TAU / 72.0);
                            best = best.min(b.distance(a + t * d + s * (f.cos() * e1 + f.sin() * e2)));
                        }
                    }
                }
                best
            };
            let spacing = (len / 60.0).max(1.02 * dist * std::f64::consts::TAU / 72.0);
            assert!(nearest(1.02 * dist) <= spacing, "{a} {d} {len}: {dist}");
            assert!(nearest(0.98 * dist) > 0.0, "{a} {d} {len}: {dist}");
        }
        assert!(checked >= 5, "{checked}");
        // beyond the slab: a cylinder wholly above the box is ∞ from it along its heights
        assert_eq!(b.distance_from_axis(DVec3::new(0.0, 0.0, 1.0), DVec3::Z, 5.0), f64::INFINITY);
        // straight down into it: its axis meets it
        assert_eq!(b.distance_from_axis(DVec3::new(0.0, 0.0, 2.0), -DVec3::Z, 5.0), 0.0);
    }

    /// A holder of radius 16 and length 40 standing 6 above the stock's top, its axis vertical:
    /// clear (the capsule reached 16 below its end and entered); 6 lower it enters.
    #[test]
    fn a_holder_above_the_stock_is_clear_by_its_flat_end() {
        let stock = Aabb { min: DVec3::new(-50.0, -50.0, -10.0), max: DVec3::new(50.0, 50.0, 0.0) };
        let tool = ToolShape {
            ball: true,
            cutter: Stretch { from: 0.0, to: 20.0, radius: 3.0 },
            above: vec![("holder", Stretch { from: 60.0, to: 100.0, radius: 16.0 })],
        };
        let tip = |z: f64| DVec3::new(0.0, 0.0, z);
        assert_eq!(tool.enters(tip(-54.0), DVec3::Z, &["holder"], &stock), None);
        assert_eq!(tool.enters(tip(-60.5), DVec3::Z, &["holder"], &stock), Some("holder"));
    }

    /// The box of points: of none, the origin; of one, that point; a ray along a face of the box
    /// (its direction below 1e-15 across it) runs inside it, just outside it never enters; a ray
    /// whose slabs it crosses one after the other misses the box.
    #[test]
    fn boxes_of_few_points_and_rays_along_their_faces() {
        let p = DVec3::new(3.0, -2.0, 5.0);
        assert_eq!(Aabb::around([]), Aabb { min: DVec3::ZERO, max: DVec3::ZERO });
        assert_eq!(Aabb::around([p]), Aabb { min: p, max: p });
        let b = Aabb { min: DVec3::ZERO, max: DVec3::ONE };
        // along x on the faces y = 0 and y = 1: out at x = 1; just outside them: never in
        for y in [0.0, 1.0] {
            assert_eq!(b.exit(DVec3::new(0.5, y, 0.5), DVec3::X), 0.5, "y = {y}");
        }
        for y in [-1e-9, 1.0 + 1e-9] {
            assert_eq!(b.exit(DVec3::new(0.5, y, 0.5), DVec3::X), 0.0, "y = {y}");
        }
        // a direction of 1e-16 across the y slab is along it (1e-17 outside: never in); one of
        // 1e-15 is not (1e-16 outside: in at t = 0.1, out at x = 1)
        assert_eq!(b.exit(DVec3::new(0.5, -1e-17, 0.5), DVec3::new(1.0, 1e-16, 0.0)), 0.0);
        assert_eq!(b.exit(DVec3::new(0.5, -1e-16, 0.5), DVec3::new(1.0, 1e-15, 0.0)), 0.5);
        // in the x slab for t in [1, 2], in the y slab for t in [3, 4]: never in both
        assert_eq!(b.exit(DVec3::new(-1.0, -3.0, 0.5), DVec3::new(1.0, 1.0, 0.0)), 0.0);
    }

    /// The hull is counter-clockwise from its lowest-leftmost point, also of three points given
    /// clockwise; the polygon distance reads it so (0 inside).
    #[test]
    fn the_hull_is_counter_clockwise() {
        let square = vec![(1.0, 1.0), (-1.0, -1.0), (0.0, 0.0), (-1.0, 1.0), (1.0, -1.0)];
        assert_eq!(hull(square), [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]);
        let clockwise = vec![(-1.0, -1.0), (0.0, 1.0), (1.0, -1.0)];
        assert_eq!(hull(clockwise.clone()), [(-1.0, -1.0), (1.0, -1.0), (0.0, 1.0)]);
        assert_eq!(polygon_distance(&hull(clockwise)), 0.0);
        assert_eq!(hull(vec![(2.0, 0.0), (1.0, 0.0)]), [(1.0, 0.0), (2.0, 0.0)]);
    }

    /// A flat cutter (radius 5, 30 long) and a holder (radius 20, from 40 to 80 up the axis): a
    /// flat end 1 above the stock is nowhere in it (its depth −∞: no point of the stock lies
    /// between its ends' planes); its side touching the stock is clear, 0.001 nearer enters. Far
    /// from the origin, only what lies between a part's ends counts: with the cutter's top 20
    /// below the stock the holder enters first, with the cutter reaching into it the cutter does.
    #[test]
    fn a_part_meets_the_stock_only_between_its_ends() {
        let tool = ToolShape {
            ball: false,
            cutter: Stretch { from: 0.0, to: 30.0, radius: 5.0 },
            above: vec![("holder", Stretch { from: 40.0, to: 80.0, radius: 20.0 })],
        };
        let all = ["cutter", "holder"];
        let stock = Aabb { min: DVec3::ZERO, max: DVec3::new(100.0, 100.0, 10.0) };
        let above = DVec3::new(50.0, 50.0, 11.0);
        assert_eq!(tool.depth(above, DVec3::Z, "cutter", &stock), Some(f64::NEG_INFINITY));
        assert_eq!(tool.enters(above, DVec3::Z, &all, &stock), None);
        assert_eq!(tool.enters(DVec3::new(105.0, 50.0, 5.0), DVec3::Z, &all, &stock), None);
        assert_eq!(tool.enters(DVec3::new(104.999, 50.0, 5.0), DVec3::Z, &all, &stock), Some("cutter"));
        let far = Aabb { min: DVec3::new(1000.0, 1000.0, 0.0), max: DVec3::new(1100.0, 1100.0, 10.0) };
        let below = DVec3::new(1104.0, 1050.0, -50.0);
        assert_eq!(tool.depth(below, DVec3::Z, "cutter", &far), Some(f64::NEG_INFINITY));
        assert_eq!(tool.enters(below, DVec3::Z, &all, &far), Some("holder"));
        let into = DVec3::new(1104.0, 1050.0, -25.0);
        assert_eq!(tool.depth(into, DVec3::Z, "cutter", &far), Some(1.0));
        assert_eq!(tool.enters(into, DVec3::Z, &all, &far), Some("cutter"));
    }
}
