//! The stock and the tool as solids for the G-code post's safety checks (Example 6's paths on
//! a real machine): the stock is a box in the part frame (the part is inside it, so a move that
//! keeps clear of the box keeps clear of the part); the tool is a chain of coaxial cylinders —
//! the cutter (its ball or flat end), the shank, the holder — each checked as the capsule
//! around its stretch of the axis: the points within its radius ρ of the segment, the cylinder
//! with a half ball on each end. It contains the cylinder, so a move it finds clear is clear; a
//! ball end is its lower half ball exactly. Whether a capsule enters the box is exact: the
//! distance of a segment from a box (below) is at most ρ.

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

    /// The distance of the segment a → b from the box (0 if it meets it): the least over
    /// t ∈ [0, 1] of the distance of p(t) = a + t·(b − a). Its square is Σₖ eₖ(t)², eₖ the
    /// excess of coordinate k beyond the box's slab (0 inside it), so convex and piecewise
    /// quadratic, its pieces cut where a coordinate crosses a face's plane; on each piece the
    /// excesses are linear, eₖ = cₖ + dₖ·t, and the least is at t = −Σcₖdₖ / Σdₖ², kept
    /// within the piece.
    pub fn distance_from_segment(&self, a: DVec3, b: DVec3) -> f64 {
        let d = b - a;
        let mut cuts = vec![0.0, 1.0];
        for k in 0..3 {
            if d[k] != 0.0 {
                cuts.extend(
                    [self.min[k], self.max[k]]
                        .map(|plane| (plane - a[k]) / d[k])
                        .into_iter()
                        .filter(|t| (0.0..=1.0).contains(t)),
                );
            }
        }
        cuts.sort_by(f64::total_cmp);
        let mut least = self.distance(a).min(self.distance(b));
        for w in cuts.windows(2) {
            let mid = a + 0.5 * (w[0] + w[1]) * d;
            let (mut cd, mut dd) = (0.0, 0.0);
            for k in 0..3 {
                // the excess's slope: −dₖ below the slab, dₖ above it, 0 within
                let (c, slope) = if mid[k] < self.min[k] {
                    (self.min[k] - a[k], -d[k])
                } else if mid[k] > self.max[k] {
                    (a[k] - self.max[k], d[k])
                } else {
                    continue;
                };
                cd += c * slope;
                dd += slope * slope;
            }
            if dd > 0.0 {
                let t = (-cd / dd).clamp(w[0], w[1]);
                least = least.min(self.distance(a + t * d));
            }
        }
        least
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

    /// The first part of the tool (of `parts`) that enters the box at this pose, if one does:
    /// its capsule comes nearer the box than its radius less 10⁻⁹ mm (a touch is clear), or its
    /// axis meets the box (however thin the part).
    pub fn enters(&self, tip: DVec3, axis: DVec3, parts: &[&str], stock: &Aabb) -> Option<&'static str> {
        self.stretches(tip, axis, parts)
            .into_iter()
            .find(|&(a, b, r, _)| stock.distance_from_segment(a, b) < (r - 1e-9).max(f64::MIN_POSITIVE))
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

    /// The segment's distance from the box: exact cases (a segment passing over an edge, one
    /// along a face, one through it) and, for segments of every kind, the least of a fine
    /// sampling never below it and within the sampling's step of it.
    #[test]
    fn a_segment_is_as_far_from_the_box_as_its_nearest_point() {
        let b = Aabb { min: DVec3::ZERO, max: DVec3::new(2.0, 2.0, 1.0) };
        // over the edge y = 2, z = 1 at (1, 3, 2) → (1, 2, 3) ... from (1, 4, 1.5) to (1, 2.5, 4): nearest
        // the edge: the line through them at distance |(1.5, −0.5)·n| from the edge's point
        let (p, q) = (DVec3::new(1.0, 4.0, 1.5), DVec3::new(1.0, 2.5, 4.0));
        let (u, v) = (p - DVec3::new(1.0, 2.0, 1.0), q - p);
        let line = u.cross(v).length() / v.length();
        assert!((b.distance_from_segment(p, q) - line).abs() < 1e-15, "{}", b.distance_from_segment(p, q));
        // along the top face, 0.5 above it; through the box; ending short of it
        assert_eq!(b.distance_from_segment(DVec3::new(-3.0, 1.0, 1.5), DVec3::new(5.0, 1.0, 1.5)), 0.5);
        assert_eq!(b.distance_from_segment(DVec3::new(-3.0, 1.0, 0.5), DVec3::new(5.0, 1.0, 0.5)), 0.0);
        assert_eq!(b.distance_from_segment(DVec3::new(-3.0, 1.0, 0.5), DVec3::new(-1.0, 1.0, 0.5)), 1.0);
        assert_eq!(b.distance_from_segment(DVec3::new(4.0, 5.0, 3.0), DVec3::new(4.0, 5.0, 3.0)), 17f64.sqrt());
        let mut seed = 7u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 10.0 - 4.0
        };
        for _ in 0..2000 {
            let (p, q) = (DVec3::new(next(), next(), next()), DVec3::new(next(), next(), next()));
            let exact = b.distance_from_segment(p, q);
            let n = 4000;
            let sampled = (0..=n).map(|k| b.distance(p.lerp(q, k as f64 / n as f64))).fold(f64::INFINITY, f64::min);
            let step = (q - p).length() / n as f64;
            assert!(exact <= sampled + 1e-12 && sampled <= exact + step, "{p} {q}: {exact} {sampled}");
        }
    }

    /// A tool of radius 10⁻³²² (a fuzzer's) is checked as quickly as any: its capsules, not
    /// balls a quarter radius apart.
    #[test]
    fn a_tool_of_any_radius_is_checked_at_once() {
        let stock = Aabb { min: DVec3::new(-50.0, -50.0, -10.0), max: DVec3::new(50.0, 50.0, 0.0) };
        let tiny = 1.9e-322;
        let tool = ToolShape { ball: true, cutter: Stretch { from: 0.0, to: 1.5, radius: tiny }, above: vec![] };
        assert_eq!(tool.enters(DVec3::new(0.0, 0.0, 0.5), DVec3::Z, &["cutter"], &stock), None);
        assert_eq!(tool.enters(DVec3::new(0.0, 0.0, -1.0), DVec3::Z, &["cutter"], &stock), Some("cutter"));
    }
}
