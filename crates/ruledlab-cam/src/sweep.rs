//! The sweep of a program as the controller moves the tool through it, and the deviation of the
//! part from it: the measure of flank milling (C. Li, S. Mann, S. Bedi, *Error measurements for
//! flank milling*, Computer-Aided Design 37, 2005) — the signed distance of the design surface
//! from the envelope of the moving tool — taken of the program as posted.
//!
//! **The tool** at a pose is a capsule (a ball end: the segment from tip + r·a to tip + L·a
//! thickened by r) or a cylinder (a flat end: radius r from the tip over the cutter's length L);
//! [`tool_distance`] is the signed distance of a point from it.
//!
//! **The blocks** ([`SweptBlock`]) are what the controller moves the tool through, each at s ∈
//! [0, 1] ([`pose_at`]):
//! - [`Move::Joints`], machine coordinates: every axis linear between the blocks' values, the
//!   pose the forward kinematics of (1 − s)·J₀ + s·J₁ (the controller interpolates its joints);
//! - [`Move::Angles`], tool-centre point given the rotary angles (LinuxCNC's TCP kinematics, whose
//!   trajectory planner interpolates the world coordinates X Y Z A C linearly, LinuxCNC 2.9
//!   *Kinematics*, "switchkins"; Heidenhain `FUNCTION TCPM … AXIS POS PATHCTRL AXIS`, TNC 640
//!   user's manual, "the rotary axes move linearly, the tool tip on a straight line"): the tip
//!   linear in the part frame, the axis the kinematics' of the linearly interpolated angles;
//! - [`Move::Vector`], tool-centre point given the axis as a vector (Sinumerik `ORIVECT`, 840D
//!   sl programming manual, job planning, "orientation interpolation: large-circle interpolation"):
//!   the tip linear, the axis on the great circle;
//! - [`Move::Straight`]: the tip linear, the axis held (the approach, the retract, an
//!   unwinding's way out along the tool axis and back).
//!
//! A program's blocks carry the pole cone's axes, the inserted poses, the unwinding and the
//! slowed blocks (their speed changes nothing here) as the post wrote them.
//!
//! **The deviation** of a target point q is D(q) = min over the blocks and s of the signed
//! distance of q from the tool at pose(s): > 0 the tool leaves material there, < 0 it cuts into
//! the part (a gouge). For a point on the part's surface near the machined one this is its
//! distance along the part's normal to first order. It is found per block by sampling s so that
//! the tool's ends move at most [`SWEEP_STEP`]·min(r, L) between samples, then golden-section
//! search about each sample that is a local least and could beat the best found, nearest first
//! (the distance is 1-Lipschitz in the tool's motion); a block is skipped when a sphere holding
//! its every tool is farther than the nearest sample found. Where the axis is held the distance is convex in s and the search
//! exact; the tests compare it with ≥ 10⁴ samples a block.

use crate::kinematics::{forward_kinematics, tool_axis, Joints};
use crate::machine::Machine;
use crate::{Pose, Tool, ToolEnd, ToolPath};
use glam::DVec3;

/// Most a tool's ends move between two samples of a block, as a share of min(r, L): fine, so
/// that the bound below prunes all but the nearest samples.
pub const SWEEP_STEP: f64 = 0.02;

/// What the tool may come nearer between a sample and its neighbours, as a share of the larger
/// move of its ends to them (the motion between samples is nearly linear; the share covers its
/// bend).
const SLACK: f64 = 1.25;

/// Most samples of one block.
pub const MAX_SWEEP_SAMPLES: usize = 4096;

/// How a block moves the tool (module documentation).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Move {
    /// The tip linear, the axis held.
    Straight,
    /// Every machine axis linear (machine coordinates).
    Joints,
    /// Tool-centre point: the tip and the rotary angles linear.
    Angles,
    /// Tool-centre point: the tip linear, the axis on the great circle.
    Vector,
}

/// One block the tool moves through: its poses (part frame), its axis values, how it moves,
/// and where it lies along the program (position `start + s·span`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweptBlock {
    /// The pose it starts at.
    pub from: Pose,
    /// The pose it ends at.
    pub to: Pose,
    /// The axis values it leaves and reaches (read by [`Move::Joints`] and [`Move::Angles`]).
    pub joints: (Joints, Joints),
    /// How it moves.
    pub how: Move,
    /// Where it starts along the program (pose k of the cut: k).
    pub start: f64,
    /// How far along it goes (a block of the cut: 1; an approach or retract: 0).
    pub span: f64,
}

/// The pose of block `b` at s ∈ [0, 1] (module documentation); `gauge` is the tool length the
/// kinematics use.
pub fn pose_at(m: &Machine, gauge: f64, b: &SweptBlock, s: f64) -> Pose {
    let (ja, jb) = b.joints;
    let rotary =
        || [ja.rotary[0] + s * (jb.rotary[0] - ja.rotary[0]), ja.rotary[1] + s * (jb.rotary[1] - ja.rotary[1])];
    match b.how {
        Move::Straight => Pose { tip: b.from.tip.lerp(b.to.tip, s), axis: b.from.axis },
        Move::Joints => forward_kinematics(m, &Joints { xyz: ja.xyz.lerp(jb.xyz, s), rotary: rotary() }, gauge),
        Move::Angles => Pose { tip: b.from.tip.lerp(b.to.tip, s), axis: tool_axis(m, rotary()) },
        Move::Vector => Pose { tip: b.from.tip.lerp(b.to.tip, s), axis: slerp(b.from.axis, b.to.axis, s) },
    }
}

/// The unit vector a fraction `s` along the great-circle arc from unit `a` to unit `b`.
pub fn slerp(a: DVec3, b: DVec3, s: f64) -> DVec3 {
    let theta = a.angle_between(b);
    if theta < 1e-12 {
        return a;
    }
    ((((1.0 - s) * theta).sin() * a + (s * theta).sin() * b) / theta.sin()).normalize()
}

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

/// The deviation of target points from the swept tool (module documentation), lengths in the
/// units of the blocks.
#[derive(Debug, Clone, PartialEq)]
pub struct EnvelopeDeviation {
    /// Per target point: its signed distance from the swept tool.
    pub points: Vec<f64>,
    /// Per target point: where along the program (or path) the nearest tool is (k + s between
    /// poses k and k + 1).
    pub at: Vec<f64>,
    /// The target point of the largest |deviation|.
    pub worst: usize,
    /// The deepest gouge: the least deviation, or 0 where none is negative.
    pub gouge: f64,
    /// The most material left: the largest deviation, or 0 where none is positive.
    pub leave: f64,
    /// The root mean square of the deviations.
    pub rms: f64,
}

impl EnvelopeDeviation {
    /// Per pose of the path (`poses` of them): the deviation of largest size among the target
    /// points nearest it (within half a block); NaN where none is.
    pub fn per_pose(&self, poses: usize) -> Vec<f64> {
        let mut out = vec![f64::NAN; poses];
        for (d, at) in self.points.iter().zip(&self.at) {
            let k = (at.round().max(0.0) as usize).min(poses.saturating_sub(1));
            if out[k].is_nan() || d.abs() > out[k].abs() {
                out[k] = *d;
            }
        }
        out
    }

    /// The deviation of largest size.
    pub fn largest(&self) -> f64 {
        self.points.get(self.worst).copied().unwrap_or(0.0)
    }
}

/// Minimises `f` on [lo, hi] by golden-section search: (argument, value), the ends tried too.
pub(crate) fn golden(lo: f64, hi: f64, f: impl Fn(f64) -> f64) -> (f64, f64) {
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = (lo, hi);
    let (mut x1, mut x2) = (b - g * (b - a), a + g * (b - a));
    let (mut f1, mut f2) = (f(x1), f(x2));
    for _ in 0..32 {
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
    [(lo, f(lo)), (hi, f(hi)), (x1, f1), (x2, f2)]
        .into_iter()
        .fold((lo, f64::INFINITY), |m, x| if x.1 < m.1 { x } else { m })
}

/// A block sampled: its poses at s_j = j / n, the most the tool's ends move from sample j to
/// j + 1, and a sphere holding the tool everywhere on it.
struct Sampled {
    poses: Vec<Pose>,
    moves: Vec<f64>,
    centre: DVec3,
    reach: f64,
}

fn sample(m: &Machine, gauge: f64, tool: &Tool, b: &SweptBlock) -> Sampled {
    const COARSE: usize = 16;
    let l = tool.length;
    let ends = |p: &Pose| (p.tip, p.tip + l * p.axis);
    let moved = |p: &Pose, q: &Pose| {
        let ((a0, a1), (b0, b1)) = (ends(p), ends(q));
        (b0 - a0).length().max((b1 - a1).length())
    };
    let coarse: Vec<Pose> = (0..=COARSE).map(|k| pose_at(m, gauge, b, k as f64 / COARSE as f64)).collect();
    let motion: f64 = coarse.windows(2).map(|w| moved(&w[0], &w[1])).sum();
    let step = SWEEP_STEP * tool.radius.min(l);
    let n = ((motion / step).ceil() as usize).clamp(1, MAX_SWEEP_SAMPLES);
    let poses: Vec<Pose> =
        if n == COARSE { coarse } else { (0..=n).map(|k| pose_at(m, gauge, b, k as f64 / n as f64)).collect() };
    let moves: Vec<f64> = poses.windows(2).map(|w| moved(&w[0], &w[1])).collect();
    let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
    for p in &poses {
        let (a, e) = ends(p);
        (lo, hi) = (lo.min(a).min(e), hi.max(a).max(e));
    }
    let centre = 0.5 * (lo + hi);
    let far =
        poses.iter().map(|p| (ends(p).0 - centre).length().max((ends(p).1 - centre).length())).fold(0.0, f64::max);
    // between two samples the tool strays at most about the larger move from both
    let slack = moves.iter().copied().fold(0.0, f64::max);
    Sampled { poses, moves, centre, reach: far + tool.radius + slack }
}

/// The deviation of `targets` from the tool (`tool`, lengths as the blocks') swept through
/// `blocks` (module documentation), telling `progress` the share of targets done (0 to 1).
pub fn sweep_deviation(
    m: &Machine,
    gauge: f64,
    tool: &Tool,
    blocks: &[SweptBlock],
    targets: &[DVec3],
    progress: &mut dyn FnMut(f64),
) -> EnvelopeDeviation {
    let (r, l, end) = (tool.radius, tool.length, tool.end);
    let sampled: Vec<Sampled> = blocks.iter().map(|b| sample(m, gauge, tool, b)).collect();
    let mut points = Vec::with_capacity(targets.len());
    let mut at = Vec::with_capacity(targets.len());
    let mut order: Vec<(f64, usize)> = Vec::with_capacity(blocks.len());
    let mut values: Vec<f64> = Vec::new();
    let mut candidates: Vec<(f64, f64, usize, usize)> = Vec::new();
    let every = (targets.len() / 50).max(1);
    for (t, &q) in targets.iter().enumerate() {
        if t % every == 0 {
            progress(t as f64 / targets.len() as f64);
        }
        order.clear();
        order.extend(sampled.iter().enumerate().map(|(i, s)| ((q - s.centre).length() - s.reach, i)));
        order.sort_by(|a, b| a.0.total_cmp(&b.0));
        // the samples of every block that could come nearest, each a local least of its block:
        // (its value less what the tool can come nearer between its neighbours, block, sample)
        candidates.clear();
        let mut best_sample = f64::INFINITY;
        for &(bound, i) in &order {
            if bound >= best_sample {
                break;
            }
            let s = &sampled[i];
            let n = s.poses.len() - 1;
            values.clear();
            values.extend(s.poses.iter().map(|p| tool_distance(q, p, r, l, end)));
            for j in 0..=n {
                let v = values[j];
                best_sample = best_sample.min(v);
                let left = if j > 0 { values[j - 1] } else { f64::INFINITY };
                let right = if j < n { values[j + 1] } else { f64::INFINITY };
                if v <= left && v <= right {
                    let slack = SLACK * s.moves[j.saturating_sub(1)].max(s.moves[j.min(n - 1)]);
                    candidates.push((v - slack, v, i, j));
                }
            }
        }
        candidates.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (mut best, mut where_) = (f64::INFINITY, 0.0);
        for &(bound, v, i, j) in &candidates {
            if bound >= best {
                break;
            }
            let (b, n) = (&blocks[i], sampled[i].poses.len() - 1);
            let (lo, hi) = (j.saturating_sub(1) as f64 / n as f64, (j + 1).min(n) as f64 / n as f64);
            let (x, d) = golden(lo, hi, |x| tool_distance(q, &pose_at(m, gauge, b, x), r, l, end));
            let (x, d) = if v < d { (j as f64 / n as f64, v) } else { (x, d) };
            if d < best {
                (best, where_) = (d, b.start + x * b.span);
            }
        }
        points.push(best);
        at.push(where_);
    }
    progress(1.0);
    summed(points, at)
}

/// The deviation with its gouge, leave, RMS and worst point.
fn summed(points: Vec<f64>, at: Vec<f64>) -> EnvelopeDeviation {
    let worst = (0..points.len()).fold(0, |w, i| if points[i].abs() > points[w].abs() { i } else { w });
    let gouge = points.iter().copied().fold(0.0, f64::min);
    let leave = points.iter().copied().fold(0.0, f64::max);
    let rms =
        if points.is_empty() { 0.0 } else { (points.iter().map(|d| d * d).sum::<f64>() / points.len() as f64).sqrt() };
    EnvelopeDeviation { points, at, worst, gouge, leave, rms }
}

/// The blocks of a tool path itself: the tip on the chord, the axis on the great-circle arc
/// between poses ([`Move::Vector`]); a single pose, a block that stands still.
pub fn path_blocks(path: &ToolPath) -> Vec<SweptBlock> {
    let still = Joints { xyz: DVec3::ZERO, rotary: [0.0; 2] };
    let block = |k: usize, a: Pose, b: Pose| SweptBlock {
        from: a,
        to: b,
        joints: (still, still),
        how: Move::Vector,
        start: k as f64,
        span: 1.0,
    };
    match path.poses.len() {
        0 => Vec::new(),
        1 => vec![SweptBlock { span: 0.0, ..block(0, path.poses[0], path.poses[0]) }],
        _ => path.poses.windows(2).enumerate().map(|(k, w)| block(k, w[0], w[1])).collect(),
    }
}

/// The deviation of `targets` from the surface `path`'s tool machines moving through the path
/// itself (the tip on the chords, the axis on the arcs): [`sweep_deviation`] of [`path_blocks`].
pub fn envelope_deviation(path: &ToolPath, targets: &[DVec3]) -> EnvelopeDeviation {
    // no block of a path reads the machine: any does
    let m = Machine::preset("table-table-ac").unwrap_or_else(|| unreachable!("a preset"));
    sweep_deviation(&m, path.tool.length, &path.tool, &path_blocks(path), targets, &mut |_| {})
}

#[cfg(test)]
mod tests;
