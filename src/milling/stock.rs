//! The stock and the tool as solids for the G-code post's safety checks (Example 6's paths on
//! a real machine): the stock is a box in the part frame (the part is inside it, so a move that
//! keeps clear of the box keeps clear of the part); the tool is a chain of coaxial cylinders —
//! the cutter (its ball or flat end), the shank, the holder — approximated by balls along the
//! axis no further apart than a quarter of their radius (a ball of radius ρ every ρ/4 covers
//! the cylinder but for scallops of 0.8 % of ρ).

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
    /// The balls that cover the stretches named `parts` ("cutter", "shank", "holder"): centre
    /// and radius, from the tip up.
    pub fn balls(&self, tip: DVec3, axis: DVec3, parts: &[&str]) -> Vec<(DVec3, f64, &'static str)> {
        let mut out = Vec::new();
        let mut stretch = |name: &'static str, s: &Stretch| {
            if s.to <= s.from || s.radius <= 0.0 {
                return;
            }
            let step = s.radius / 4.0;
            let n = ((s.to - s.from) / step).ceil().max(1.0) as usize;
            for k in 0..=n {
                let t = s.from + (s.to - s.from) * k as f64 / n as f64;
                out.push((tip + t * axis, s.radius, name));
            }
        };
        if parts.contains(&"cutter") {
            let c = self.cutter;
            // a ball end: its centre a radius up the axis; the cylinder above
            let from = if self.ball { c.radius.min(c.to) } else { c.from };
            stretch("cutter", &Stretch { from, ..c });
        }
        for (name, s) in &self.above {
            if parts.contains(name) {
                stretch(name, s);
            }
        }
        out
    }

    /// The first part of the tool (of `parts`) that enters the box at this pose, if one does.
    pub fn enters(&self, tip: DVec3, axis: DVec3, parts: &[&str], stock: &Aabb) -> Option<&'static str> {
        self.balls(tip, axis, parts).into_iter().find(|(c, r, _)| stock.distance(*c) < r - 1e-9).map(|(_, _, n)| n)
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
        // the balls are at most a quarter radius apart along every stretch
        let balls = tool.balls(DVec3::ZERO, DVec3::Z, &all);
        for w in balls.windows(2) {
            let gap = (w[1].0 - w[0].0).length();
            assert!(gap <= w[0].1.min(w[1].1) / 4.0 + 1e-12 || w[0].2 != w[1].2, "{w:?}");
        }
    }
}
