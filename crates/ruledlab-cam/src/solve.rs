//! The axis values of a whole tool path on a five-axis [`Machine`] (Example 6's paths on a real
//! machine; the kinematics of one pose in `kinematics.rs`): which of each pose's two settings,
//! which turn of a limited axis, where a limited axis unwinds, and what happens near the pole.
//!
//! **Choice.** Each pose has two settings of the rotary axes (one on the pole) and, for a
//! limited axis, every value v + 360°·n within its limits; a continuous axis is unwrapped to the
//! value nearest the previous pose. A dynamic programme over the whole path picks the
//! candidates that keep every axis within its limits and **move least** (the sum of |Δv| over
//! both axes and all blocks, the first pose measured from 0).
//!
//! **Unwinding.** With `unwind` on, a block that would turn a limited axis by more than half a
//! turn may instead unwind it at the block's first pose: the axis turns there by whole turns
//! to the value of the same angle nearest the next pose (within its limits) while the tool is
//! out of the part (the post retracts along the tool axis, turns, and comes back), and the block
//! then turns it the short way. The programme counts an unwind as [`UNWIND_COST`] degrees of
//! motion, a block longer than half a turn as twice that: it unwinds as seldom as it can and
//! never cuts along the long way round where an unwind is possible.
//!
//! **The pole and its cone.** Where the tool axis p is parallel to the free axis's direction u
//! (`kinematics.rs`: the pole) that axis's angle is undetermined; near it, it is determined but
//! turns fast: a path passing 0.008° from the pole turns C by 180° over a few hundredths of a
//! millimetre. Inside the **pole cone** (the poses whose axis is within `cone` of ±u) the
//! programme gives the free angle the values it has at the nearest poses outside the cone, and
//! afterwards the free axis is interpolated linearly (by the tip's distance along the path)
//! from its value at the last pose before the cone to its value at the first pose after it;
//! the other axis takes, at each of those poses, the angle that brings the tool axis nearest
//! to the given one ([`nearest_tilt`]). The tool axis then departs from the given one by at
//! most about the cone's angle (reported per pose); where the branch of the solution can flip
//! (an axis that may pass through zero) the free axis is simply **kept**. A ball-end tool keeps
//! its ball centre (the machined surface is unchanged), a flat end its tip. With `cone` = 0
//! only the exact pole (within `POLE_SIN` of `tolerance.rs`) is free, and it keeps the neighbour's value.
//!
//! A pose without a candidate within limits, or whose machine position leaves the travel of X, Y
//! or Z, is an [`Error::Unreachable`] naming the pose and the axis.

use crate::kinematics::{
    check_travel, frame, from_zero, limit, machine_position, nearest_tilt, nearest_violation, orientations, pole_angle,
    step, tool_axis, values, wrap, Joints, Orientation, Value,
};
use crate::machine::Machine;
use crate::Pose;
use glam::DVec3;
use ruledlab::{Error, Result};

/// The motion (degrees) an unwind counts as in the choice of solutions: more than any path's
/// motion between two unwinds, so that the fewest unwinds win.
pub const UNWIND_COST: f64 = 1e5;

/// With unwinding on, what a block counts per degree its interpolated tool axis strays, at its
/// middle, from the middle of the path's arc: a block that turns the axes over (the other
/// solution's branch, the axis swung through the pole between two nearby poses) costs more
/// than an unwind.
pub const TURN_OVER_COST: f64 = 1e4;

/// A block whose rotary axes turn less than this (degrees) is not priced for straying: its
/// axis strays by a fraction of a degree at most.
pub const STRAY_STEP: f64 = 20.0;

/// How [`solve`] treats the pole and the limits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveOptions {
    /// Half-angle of the pole cone, radians (0: only the pole itself).
    pub cone: f64,
    /// Whether a limited axis may unwind between two poses (see the module documentation).
    pub unwind: bool,
    /// The tool's radius for a ball end (its centre is kept where the cone changes the tool
    /// axis); `None`: the tip is kept (a flat end).
    pub ball: Option<f64>,
}

impl SolveOptions {
    /// The exact inverse kinematics: no cone, no unwinding.
    pub fn exact() -> Self {
        SolveOptions { cone: 0.0, unwind: false, ball: None }
    }
}

/// The axis values of a path and what the pole cone and the limits made of it.
#[derive(Debug, Clone, PartialEq)]
pub struct Solved {
    /// The axis values at each pose (as the block arriving there ends).
    pub joints: Vec<Joints>,
    /// At a pose where a limited axis unwinds: the rotary values after the unwinding (the block
    /// leaving the pose starts from them; X, Y, Z are those of `joints`).
    pub unwound: Vec<Option<[f64; 2]>>,
    /// The poses the axis values give: the given ones, or in the pole cone the tool axis of the
    /// interpolated rotary values (and the tip that keeps the cut).
    pub poses: Vec<Pose>,
    /// Angle between each given tool axis and the one written, radians (0 outside the cone).
    pub adjusted: Vec<f64>,
    /// Whether each pose lies in the pole cone.
    pub in_cone: Vec<bool>,
}

impl Solved {
    /// The axis values the block leaving pose `i` starts from.
    pub fn leaving(&self, i: usize) -> Joints {
        let j = self.joints[i];
        Joints { rotary: self.unwound[i].unwrap_or(j.rotary), ..j }
    }
}

/// Inverse kinematics of a path (part frame, mm; unit axes) for a tool of length `tool_length`
/// (mm): the axis values of every pose, chosen within the limits to move least (see the module
/// documentation). No pole cone and no unwinding: [`solve`] with [`SolveOptions::exact`].
pub fn inverse_kinematics(m: &Machine, poses: &[Pose], tool_length: f64) -> Result<Vec<Joints>> {
    solve(m, poses, tool_length, &SolveOptions::exact()).map(|s| s.joints)
}

/// The cost of going from candidate `a` to `b` on axis `k`, and whether it unwinds there.
fn transition(m: &Machine, k: usize, a: Value, b: Value, unwind: bool) -> (f64, bool) {
    match (a, b) {
        (Value::Fixed(x), Value::Fixed(y)) if (y - x).abs() > 180.0 + 1e-9 => {
            let short = wrap(y - x);
            if unwind && m.rotary[k].allows(y - short) {
                // the unwind's own turn counts too: the fewest turns back
                (UNWIND_COST + (y - short - x).abs() + short.abs(), true)
            } else {
                (2.0 * UNWIND_COST + (y - x).abs(), false)
            }
        }
        _ => (step(a, b), false),
    }
}

/// Solves the axis values of `poses` (see the module documentation).
pub fn solve(m: &Machine, poses: &[Pose], tool_length: f64, o: &SolveOptions) -> Result<Solved> {
    let raw: Vec<Vec<Orientation>> = poses.iter().map(|p| orientations(m, p.axis)).collect();
    let in_cone: Vec<bool> = poses.iter().map(|p| o.cone > 0.0 && pole_angle(m, p.axis) < o.cone).collect();
    let free_axis = frame(m).map(|f| f.iu);
    // a pose whose solutions fix both angles and lie outside the cone
    let determined = |i: usize| !in_cone[i] && raw[i].iter().all(|o| o[0].is_some() && o[1].is_some());
    let mut concrete: Vec<Vec<[f64; 2]>> = Vec::with_capacity(poses.len());
    for (i, sols) in raw.iter().enumerate() {
        if sols.is_empty() {
            return Err(Error::Unreachable {
                pose: i,
                line: None,
                message: crate::msg!("pose-orientation", pose = i, machine = m.name.as_str()),
            });
        }
        let mut out = Vec::new();
        for s in sols {
            // the free angle: the one the pole leaves undetermined, or in the cone the pole's axis
            let free = match (s[0], s[1]) {
                (None, _) => Some(0),
                (_, None) => Some(1),
                _ if in_cone[i] => free_axis,
                _ => None,
            };
            let Some(free) = free else {
                out.push([s[0].unwrap_or(0.0), s[1].unwrap_or(0.0)]);
                continue;
            };
            let before = (0..i).rev().find(|&k| determined(k)).map(|k| &raw[k]);
            let after = (i + 1..poses.len()).find(|&k| determined(k)).map(|k| &raw[k]);
            let mut fills: Vec<f64> = before.into_iter().chain(after).flatten().filter_map(|o| o[free]).collect();
            if fills.is_empty() {
                fills.push(m.rotary[free].angle(0.0));
            }
            for f in fills {
                let mut c = [s[0].unwrap_or(0.0), s[1].unwrap_or(0.0)];
                c[free] = f;
                out.push(c);
            }
        }
        concrete.push(out);
    }
    // the candidates within limits
    let mut candidates: Vec<Vec<[Value; 2]>> = Vec::with_capacity(poses.len());
    for (i, sols) in concrete.iter().enumerate() {
        let mut c = Vec::new();
        for s in sols {
            for v0 in values(m, 0, s[0]) {
                for v1 in values(m, 1, s[1]) {
                    c.push([v0, v1]);
                }
            }
        }
        if c.is_empty() {
            let (k, value) = nearest_violation(m, sols);
            let r = &m.rotary[k];
            return Err(Error::Unreachable {
                pose: i,
                line: None,
                message: crate::msg!(
                    "pose-unreachable",
                    pose = i,
                    axis = r.name.letter(),
                    value =
                        crate::kinematics::beyond(value, limit(r.min, f64::NEG_INFINITY), limit(r.max, f64::INFINITY)),
                    min = limit(r.min, f64::NEG_INFINITY),
                    max = limit(r.max, f64::INFINITY)
                ),
            });
        }
        candidates.push(c);
    }
    let axes: Vec<DVec3> = poses.iter().map(|p| p.axis).collect();
    let chosen = choose(m, &candidates, &axes, o.unwind);
    // unwrap the continuous axes towards the previous pose; note the unwinds
    let mut previous = [0.0, 0.0];
    let mut rotary: Vec<[f64; 2]> = Vec::with_capacity(poses.len());
    let mut unwound: Vec<Option<[f64; 2]>> = vec![None; poses.len()];
    for (i, c) in chosen.iter().enumerate() {
        let mut r = [0.0; 2];
        for a in 0..2 {
            r[a] = match c[a] {
                Value::Fixed(v) => v,
                Value::Turn(v) => v + 360.0 * ((previous[a] - v) / 360.0).round(),
            };
        }
        if i > 0 {
            let mut after = rotary[i - 1];
            let mut unwinds = false;
            for a in 0..2 {
                if let (Value::Fixed(x), Value::Fixed(y)) = (chosen[i - 1][a], c[a]) {
                    if transition(m, a, Value::Fixed(x), Value::Fixed(y), o.unwind).1 {
                        after[a] = y - wrap(y - x);
                        unwinds = true;
                    }
                }
            }
            if unwinds {
                unwound[i - 1] = Some(after);
            }
        }
        previous = r;
        rotary.push(r);
    }
    let mut out = poses.to_vec();
    let mut adjusted = vec![0.0; poses.len()];
    if o.cone > 0.0 {
        if let Some(free) = free_axis {
            smooth_the_cone(m, poses, &in_cone, free, &mut rotary, &unwound, o, &mut out, &mut adjusted);
        }
    }
    let mut joints = Vec::with_capacity(poses.len());
    for (i, (p, r)) in out.iter().zip(&rotary).enumerate() {
        let xyz = machine_position(m, p.tip, *r, tool_length);
        check_travel(m, i, xyz)?;
        joints.push(Joints { xyz, rotary: *r });
    }
    Ok(Solved { joints, unwound, poses: out, adjusted, in_cone })
}

/// How far (degrees) the tool axis of the block from candidate `a` to `b`, at its middle, strays
/// from `middle` (the middle of the path's arc), with the unwinds `transition` makes.
fn stray(m: &Machine, a: [Value; 2], b: [Value; 2], middle: DVec3, unwind: bool) -> f64 {
    let mut r = [0.0; 2];
    let mut big = false;
    for k in 0..2 {
        let (x, y) = match (a[k], b[k]) {
            (Value::Fixed(x), Value::Fixed(y)) => {
                if transition(m, k, a[k], b[k], unwind).1 {
                    (y - wrap(y - x), y)
                } else {
                    (x, y)
                }
            }
            (Value::Fixed(x) | Value::Turn(x), Value::Fixed(y) | Value::Turn(y)) => (x, x + wrap(y - x)),
        };
        r[k] = 0.5 * (x + y);
        big |= (y - x).abs() > STRAY_STEP;
    }
    // a block that turns each axis by a few degrees strays by their square: only the big ones can
    // turn the tool over
    if !big {
        return 0.0;
    }
    let axis = tool_axis(m, r);
    axis.cross(middle).length().atan2(axis.dot(middle)).to_degrees()
}

/// The dynamic programme: least total motion over the candidates (see the module documentation).
fn choose(m: &Machine, candidates: &[Vec<[Value; 2]>], axes: &[DVec3], unwind: bool) -> Vec<[Value; 2]> {
    let mut cost: Vec<f64> = candidates[0].iter().map(|c| from_zero(c[0]) + from_zero(c[1])).collect();
    let mut back: Vec<Vec<usize>> = vec![vec![0; candidates[0].len()]];
    for i in 1..candidates.len() {
        let (prev, cur) = (&candidates[i - 1], &candidates[i]);
        let middle = (axes[i - 1] + axes[i]).try_normalize().unwrap_or(axes[i]);
        let mut next = Vec::with_capacity(cur.len());
        let mut from = Vec::with_capacity(cur.len());
        for c in cur {
            let (mut best, mut arg) = (f64::INFINITY, 0);
            for (j, p) in prev.iter().enumerate() {
                let strays = if unwind { TURN_OVER_COST * stray(m, *p, *c, middle, unwind) } else { 0.0 };
                let total =
                    cost[j] + transition(m, 0, p[0], c[0], unwind).0 + transition(m, 1, p[1], c[1], unwind).0 + strays;
                if total < best - 1e-9 {
                    (best, arg) = (total, j);
                }
            }
            next.push(best);
            from.push(arg);
        }
        cost = next;
        back.push(from);
    }
    let mut k = (0..cost.len()).fold(0, |b, j| if cost[j] < cost[b] - 1e-9 { j } else { b });
    let mut chosen = vec![[Value::Fixed(0.0); 2]; candidates.len()];
    for i in (0..candidates.len()).rev() {
        chosen[i] = candidates[i][k];
        k = back[i][k];
    }
    chosen
}

/// The pole cone: each run of poses inside it gets the free axis interpolated from the last pose
/// before it to the first after it, the other axis the angle nearest the given tool axis, and
/// the pose the axis those give with the cut kept (module documentation).
#[allow(clippy::too_many_arguments)]
fn smooth_the_cone(
    m: &Machine,
    poses: &[Pose],
    in_cone: &[bool],
    free: usize,
    rotary: &mut [[f64; 2]],
    unwound: &[Option<[f64; 2]>],
    o: &SolveOptions,
    out: &mut [Pose],
    adjusted: &mut [f64],
) {
    let other = 1 - free;
    let n = poses.len();
    let mut i = 0;
    while i < n {
        if !in_cone[i] {
            i += 1;
            continue;
        }
        let start = i;
        while i < n && in_cone[i] {
            i += 1;
        }
        let end = i; // the run is start..end
        let entry = start.checked_sub(1).map(|k| unwound[k].unwrap_or(rotary[k]));
        let exit = (end < n).then(|| rotary[end]);
        let (from, to) = match (entry, exit) {
            (Some(a), Some(b)) => (a, b),
            (Some(a), None) => (a, a),
            (None, Some(b)) => (b, b),
            (None, None) => (rotary[start], rotary[start]),
        };
        // the tip's distance along the run, from the pose before it to the pose after it
        let first = start.saturating_sub(1);
        let last = end.min(n - 1);
        let mut along = vec![0.0; last - first + 1];
        for k in first + 1..=last {
            along[k - first] = along[k - 1 - first] + (poses[k].tip - poses[k - 1].tip).length();
        }
        let total = along[last - first];
        let span = (last - first) as f64;
        for k in start..end {
            let s = if total > 1e-12 { along[k - first] / total } else { (k - first) as f64 / span.max(1.0) };
            let v = from[free] + s * (to[free] - from[free]);
            let theta = m.rotary[free].angle(v);
            let Some(tilt) = nearest_tilt(m, poses[k].axis, theta) else { continue };
            // of the tilt's values within the limits, the one nearest the path's own
            let near = rotary[k][other];
            let Some(t) = values(m, other, tilt)
                .into_iter()
                .map(|c| match c {
                    Value::Fixed(x) => x,
                    Value::Turn(x) => x + 360.0 * ((near - x) / 360.0).round(),
                })
                .min_by(|a, b| (a - near).abs().total_cmp(&(b - near).abs()))
            else {
                continue;
            };
            let mut r = [0.0; 2];
            r[free] = v;
            r[other] = t;
            let axis = tool_axis(m, r);
            let given = poses[k];
            let tip = match o.ball {
                Some(radius) => given.tip + radius * given.axis - radius * axis,
                None => given.tip,
            };
            rotary[k] = r;
            out[k] = Pose { tip, axis };
            adjusted[k] = axis.cross(given.axis).length().atan2(axis.dot(given.axis));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::forward_kinematics;

    fn tilted(tilt: f64, turn: f64) -> DVec3 {
        let (t, f) = (tilt.to_radians(), turn.to_radians());
        DVec3::new(t.sin() * f.cos(), t.sin() * f.sin(), t.cos())
    }

    fn pose(x: f64, axis: DVec3) -> Pose {
        Pose { tip: DVec3::new(x, 0.0, 0.0), axis }
    }

    /// A path through the pole's neighbourhood on the fork head: 2° tilted towards +X, then
    /// towards −X shifted by δ = 0.458°, so that the great circle between them passes 0.008°
    /// from the pole. Exactly solved, C swings by about 180° between the two middle poses of a
    /// refined path; in the cone of 1° the free axis C is kept (A passes through zero, from +2°
    /// to −2°), and every pose's axis stays within the cone of the given one.
    #[test]
    fn the_cone_keeps_c_where_a_can_pass_through_zero() {
        let m = Machine::preset("head-head-ac").unwrap();
        let steps = 40;
        let poses: Vec<Pose> = (0..=steps)
            .map(|k| {
                let s = k as f64 / steps as f64;
                let (a, b) = (tilted(2.0, 90.0), tilted(2.0, 270.0 - 0.458));
                pose(s * 40.0, (a * (1.0 - s) + b * s).normalize())
            })
            .collect();
        let exact = solve(&m, &poses, 40.0, &SolveOptions::exact()).unwrap();
        let c = |s: &Solved, k: usize| s.joints[k].rotary[0];
        let swing = (1..poses.len()).map(|k| (c(&exact, k) - c(&exact, k - 1)).abs()).fold(0.0, f64::max);
        assert!(swing > 60.0, "the exact solution swings C by {swing}° in one block");
        let cone =
            solve(&m, &poses, 40.0, &SolveOptions { cone: 1f64.to_radians(), unwind: true, ball: None }).unwrap();
        let swing = (1..poses.len()).map(|k| (c(&cone, k) - c(&cone, k - 1)).abs()).fold(0.0, f64::max);
        assert!(swing < 1.0, "in the cone C moves {swing}° at most per block");
        assert!(cone.in_cone.iter().any(|&b| b) && cone.in_cone.iter().any(|&b| !b));
        for (k, p) in cone.poses.iter().enumerate() {
            let back = forward_kinematics(&m, &cone.joints[k], 40.0);
            assert!((back.tip - p.tip).length() < 1e-9 && (back.axis - p.axis).length() < 1e-12, "pose {k}");
            assert!(cone.adjusted[k] <= 2f64.to_radians(), "pose {k}: {}", cone.adjusted[k].to_degrees());
            if !cone.in_cone[k] {
                assert_eq!(cone.adjusted[k], 0.0);
                assert_eq!(*p, poses[k]);
            }
        }
    }

    /// Where the branch cannot flip (A of the trunnion limited to 0…120°), C is interpolated
    /// across the cone instead of jumping: its largest step is the cone's share of the turn.
    #[test]
    fn the_cone_spreads_the_turn_where_the_branch_cannot_flip() {
        let mut m = Machine::preset("table-table-ac").unwrap();
        m.rotary[0].min = Some(0.0);
        let steps = 40;
        let poses: Vec<Pose> = (0..=steps)
            .map(|k| {
                let s = k as f64 / steps as f64;
                let (a, b) = (tilted(3.0, 0.0), tilted(3.0, 180.0 - 0.3));
                pose(s * 40.0, (a * (1.0 - s) + b * s).normalize())
            })
            .collect();
        let exact = solve(&m, &poses, 40.0, &SolveOptions::exact()).unwrap();
        let smooth =
            solve(&m, &poses, 40.0, &SolveOptions { cone: 1f64.to_radians(), unwind: true, ball: Some(3.0) }).unwrap();
        let largest = |s: &Solved| {
            (1..poses.len()).map(|k| (s.joints[k].rotary[1] - s.joints[k - 1].rotary[1]).abs()).fold(0.0, f64::max)
        };
        let inside = smooth.in_cone.iter().filter(|&&b| b).count();
        assert!(inside >= 2, "{inside} poses in the cone");
        assert!(largest(&exact) > 45.0, "{}", largest(&exact));
        assert!(largest(&smooth) < 180.0 / inside as f64 * 1.5 + 5.0, "{}", largest(&smooth));
        // the ball's centre is kept
        for (k, p) in smooth.poses.iter().enumerate() {
            let (given, got) = (poses[k].tip + 3.0 * poses[k].axis, p.tip + 3.0 * p.axis);
            assert!((given - got).length() < 1e-12, "pose {k}");
        }
    }

    /// Three turns around a wall on the fork head (C from −360° to 360°): C runs out of its range
    /// in the middle of the path; with unwinding on it turns back by whole turns there, once
    /// (the same angle, within the limits), and no block turns it by more than a step's 10° —
    /// with the steps on whole tens of degrees; and over two turns 5° off them, so that the
    /// unwind does not start at a multiple of 180°.
    #[test]
    fn a_limited_axis_unwinds_where_it_would_leave_its_range() {
        let m = Machine::preset("head-head-ac").unwrap();
        for (offset, steps) in [(0.0, 3 * 36), (5.0, 2 * 36)] {
            unwinds_once(&m, offset, steps);
        }
    }

    fn unwinds_once(m: &Machine, offset: f64, steps: usize) {
        let poses: Vec<Pose> = (0..=steps)
            .map(|k| {
                let turn = offset + 10.0 * k as f64;
                Pose { tip: DVec3::new(0.0, 0.0, -0.1 * k as f64), axis: tilted(30.0, turn) }
            })
            .collect();
        let s = solve(m, &poses, 40.0, &SolveOptions { cone: 0.0, unwind: true, ball: None }).unwrap();
        let unwinds: Vec<usize> = (0..poses.len()).filter(|&i| s.unwound[i].is_some()).collect();
        assert_eq!(unwinds.len(), 1, "{unwinds:?}");
        for i in 1..poses.len() {
            let (a, b) = (s.leaving(i - 1).rotary, s.joints[i].rotary);
            assert!((b[0] - a[0]).abs() < 10.0 + 1e-9, "block {i}: C {} → {}", a[0], b[0]);
            assert!(m.rotary[0].allows(a[0]) && m.rotary[0].allows(b[0]));
        }
        for &i in &unwinds {
            let (before, after) = (s.joints[i].rotary, s.unwound[i].unwrap());
            let turns = (before[0] - after[0]) / 360.0;
            assert!(turns.abs() >= 1.0 - 1e-12 && (turns - turns.round()).abs() < 1e-12, "{before:?} → {after:?}");
            assert_eq!(before[1], after[1]);
        }
        // the exact choice (no unwinding, no price on a block's straying) turns the head over
        // instead: A from +30° to −30° and C by 180° in one block, the tool axis swung
        // through the vertical between two poses 10° apart (the job the issue tracker saw
        // refused for "the pole")
        let exact = solve(m, &poses, 40.0, &SolveOptions::exact()).unwrap();
        let flips = (1..poses.len()).any(|i| (exact.joints[i].rotary[1] - exact.joints[i - 1].rotary[1]).abs() > 50.0);
        assert!(flips);
    }

    /// The price of a block on a limited axis (C of the fork head, −360° … 360°), worked out by
    /// hand: 170° → −170° is 340° the long way; with unwinding it turns back by the short way's
    /// 20° at the start (to −190°, within the limits) and then the 20°, so it counts the unwind,
    /// |−190° − 170°| = 360° of turning back and 20°; without it, twice the unwind and 340°.
    /// 300° → −300° cannot unwind (−300° − 120° = −420° is beyond −360°). Up to half a turn and
    /// a rounding margin of 1e-9°, a block turns the way it is given, unpriced.
    #[test]
    fn a_block_is_priced_by_its_turn_its_unwind_or_its_long_way() {
        let m = Machine::preset("head-head-ac").unwrap();
        let f = Value::Fixed;
        assert_eq!(transition(&m, 0, f(170.0), f(-170.0), true), (UNWIND_COST + 360.0 + 20.0, true));
        assert_eq!(transition(&m, 0, f(170.0), f(-170.0), false), (2.0 * UNWIND_COST + 340.0, false));
        assert_eq!(transition(&m, 0, f(300.0), f(-300.0), true), (2.0 * UNWIND_COST + 600.0, false));
        let half = 180.0 + 1e-9;
        for (y, want) in [(180.0, 180.0), (half, half), (-half, half)] {
            assert_eq!(transition(&m, 0, f(0.0), f(y), true), (want, false), "0° → {y}°");
        }
        // a continuous axis takes the short way: no long way, no unwind
        assert_eq!(transition(&m, 0, Value::Turn(170.0), Value::Turn(-170.0), true), (20.0, false));
    }

    /// On the pole itself (the tool along the fork head's C axis, A = 0) C is free: with no cone
    /// the pose keeps the C of the nearest poses off the pole, so that the head does not turn
    /// there and back — one pose on the pole, or three in a row.
    #[test]
    fn on_the_pole_the_free_axis_keeps_its_neighbours_value() {
        let m = Machine::preset("head-head-ac").unwrap();
        for on in [1, 3] {
            let axes = std::iter::once(tilted(10.0, 40.0))
                .chain(std::iter::repeat_n(DVec3::Z, on))
                .chain(std::iter::once(tilted(10.0, 40.0)));
            let poses: Vec<Pose> = axes.enumerate().map(|(k, a)| pose(k as f64, a)).collect();
            let s = solve(&m, &poses, 40.0, &SolveOptions::exact()).unwrap();
            let c = s.joints[0].rotary[0];
            assert!(c.abs() > 1.0, "the neighbours' C is {c}°");
            for k in 1..=on {
                assert_eq!(s.joints[k].rotary, [c, 0.0], "{on} on the pole: pose {k}");
            }
            assert_eq!(s.joints[on + 1].rotary, s.joints[0].rotary);
        }
    }

    /// The pole cone holds the poses strictly within its angle of the pole: a pose exactly at
    /// the cone's angle is outside it (given as the pose's own pole angle, to the last bit).
    #[test]
    fn the_cone_holds_the_poses_strictly_within_its_angle() {
        let m = Machine::preset("head-head-ac").unwrap();
        let poses: Vec<Pose> =
            [5.0, 2.0, 1.0, 5.0].iter().enumerate().map(|(k, &t)| pose(k as f64, tilted(t, 30.0))).collect();
        let cone = pole_angle(&m, poses[1].axis);
        let s = solve(&m, &poses, 40.0, &SolveOptions { cone, unwind: false, ball: None }).unwrap();
        assert_eq!(s.in_cone, [false, false, true, false]);
    }

    /// How far a block's middle axis strays, on the fork head: C 160° → −160° unwinds first (to
    /// −200°, then 40° on), so its middle is C = −180°; A 0° → 50° has its middle at 25°. The
    /// middle axis is then that of (−180°, 25°): 0° from it, and 25° from the vertical (the
    /// head's tilt). A continuous axis turns the short way: 170° → −170° has its middle at 180°.
    /// A block whose axes each turn at most 20° strays by nothing worth a price.
    #[test]
    fn a_block_strays_by_the_angle_of_its_middle_axis() {
        let m = Machine::preset("head-head-ac").unwrap();
        let (f, t) = (Value::Fixed, Value::Turn);
        let at = |c: f64, a: f64| tool_axis(&m, [c, a]);
        let unwinding = ([f(160.0), f(0.0)], [f(-160.0), f(50.0)]);
        assert_eq!(stray(&m, unwinding.0, unwinding.1, at(-180.0, 25.0), true), 0.0);
        let tilt = stray(&m, unwinding.0, unwinding.1, DVec3::Z, true);
        assert!((tilt - 25.0).abs() < 1e-12, "{tilt}");
        // without unwinding the block turns C the long way, through 0°
        assert_eq!(stray(&m, unwinding.0, unwinding.1, at(0.0, 25.0), false), 0.0);
        assert_eq!(stray(&m, [t(170.0), f(0.0)], [t(-170.0), f(50.0)], at(180.0, 25.0), true), 0.0);
        assert_eq!(stray(&m, [f(0.0), f(0.0)], [f(20.0), f(-20.0)], -DVec3::Z, true), 0.0);
    }

    /// Of settings that move alike, to within 1e-9°, the first listed is kept, at the first pose
    /// and between poses: rounding never flips the choice. C = ±5° (the later 1e-12° nearer 0)
    /// before C = 0°: the first; one pose with C = ±90°: the first.
    #[test]
    fn of_settings_that_move_alike_the_first_is_kept() {
        let m = Machine::preset("head-head-ac").unwrap();
        let f = Value::Fixed;
        let both = vec![[f(5.0), f(0.0)], [f(-5.0 + 1e-12), f(0.0)]];
        let chosen = choose(&m, &[both.clone(), vec![[f(0.0), f(0.0)]]], &[DVec3::Z, DVec3::Z], false);
        assert_eq!(chosen[0], both[0]);
        let start = [[f(90.0), f(30.0)], [f(-90.0 + 1e-12), f(-30.0)]];
        assert_eq!(choose(&m, &[start.to_vec()], &[DVec3::Z], false), [start[0]]);
    }

    /// Inside the pole cone the free axis (C of the fork head) runs linearly in the tip's distance
    /// along the path, from its value at the pose before the cone to the one at the pose after
    /// it (held where the cone begins or ends the path, or holds all of it); the tilt A brings
    /// the tool axis nearest the given one (a hundredth of a degree either way is farther), and
    /// the pose reports the angle between them. Tips spaced unevenly (x = k²) so that the
    /// distance, not the index, counts; where the tip stands still (the tool turned on the spot),
    /// the index.
    #[test]
    fn in_the_cone_the_free_axis_runs_linearly_along_the_tip() {
        let m = Machine::preset("head-head-ac").unwrap();
        let cone = 1.5f64.to_radians();
        // (tilt, turn) of each pose; tilts under 1.5° are in the cone
        let path = [(3.0, 10.0), (3.0, 20.0), (1.0, 40.0), (0.5, 150.0), (1.2, 250.0), (3.0, 260.0)];
        // the cone in the middle, at the end, at the start, everywhere; then on the spot
        let runs = [(1..6, 1.0), (1..5, 1.0), (2..6, 1.0), (2..5, 1.0), (0..6, 0.0)];
        for (run, moving) in runs {
            let poses: Vec<Pose> = path[run.clone()]
                .iter()
                .enumerate()
                .map(|(k, &(tilt, turn))| Pose {
                    tip: DVec3::new(moving * (k * k) as f64, 0.0, 0.0),
                    axis: tilted(tilt, turn),
                })
                .collect();
            let s = solve(&m, &poses, 40.0, &SolveOptions { cone, unwind: false, ball: None }).unwrap();
            let inside: Vec<usize> = (0..poses.len()).filter(|&k| s.in_cone[k]).collect();
            let want: Vec<usize> = (0..poses.len()).filter(|&k| path[run.start + k].0 < 1.5).collect();
            assert!(inside == want && !inside.is_empty(), "{run:?}: {inside:?}");
            let (a, b) = (inside[0], inside[inside.len() - 1] + 1);
            let c = |k: usize| s.joints[k].rotary[0];
            let (from, to) = match (a.checked_sub(1), (b < poses.len()).then_some(b)) {
                (Some(i), Some(j)) => (c(i), c(j)),
                (Some(i), None) => (c(i), c(i)),
                (None, Some(j)) => (c(j), c(j)),
                (None, None) => (c(a), c(a)),
            };
            let (lo, hi) = (a.saturating_sub(1), b.min(poses.len() - 1));
            let along = |k: usize| match moving > 0.0 {
                true => (poses[k].tip.x - poses[lo].tip.x) / (poses[hi].tip.x - poses[lo].tip.x),
                false => (k - lo) as f64 / (hi - lo) as f64,
            };
            for k in a..b {
                let want = if hi > lo { from + along(k) * (to - from) } else { from };
                assert!((c(k) - want).abs() < 1e-9, "{run:?}, pose {k}: C {} against {want}", c(k));
                let off = |da: f64| tool_axis(&m, [c(k), s.joints[k].rotary[1] + da]).angle_between(poses[k].axis);
                assert!(off(0.0) < off(0.01) && off(0.0) < off(-0.01), "{run:?}, pose {k}: A is not the nearest");
                assert!((s.adjusted[k] - off(0.0)).abs() < 1e-12, "{run:?}, pose {k}");
                assert_eq!(s.poses[k].tip, poses[k].tip, "a flat end keeps its tip");
            }
        }
    }

    /// A tilt axis that may turn past a whole turn (A of the fork head from −400° to 400°, or
    /// continuous): the tool tilts about X through a turn and a bit, in 12° steps, and passes the
    /// pole's two ends, upside down at 180° and upright again at 360° (two poses in the cone of
    /// 1° at each, 0.5° and 0.6° from it). In the cone A is the tilt's value nearest the path's
    /// own — 180.6°, not −179.4°; 359.5°, not −0.5° or −360.5° — so A runs on without a jump.
    #[test]
    fn in_the_cone_a_tilt_past_a_turn_takes_the_value_nearest_the_path() {
        let about_x = |alpha: f64| DVec3::new(0.0, -alpha.to_radians().sin(), alpha.to_radians().cos());
        let steps = |ks: std::ops::Range<i32>| ks.map(|k| 5.0 + 12.0 * k as f64);
        let alphas: Vec<f64> =
            steps(0..15).chain([179.5, 180.6]).chain(steps(15..30)).chain([359.5, 360.6, 367.0, 379.0]).collect();
        let poses: Vec<Pose> = alphas.iter().map(|&a| pose(0.0, about_x(a))).collect();
        for (min, max) in [(Some(-400.0), Some(400.0)), (None, None)] {
            let mut m = Machine::preset("head-head-ac").unwrap();
            (m.rotary[1].min, m.rotary[1].max) = (min, max);
            let s =
                solve(&m, &poses, 40.0, &SolveOptions { cone: 1f64.to_radians(), unwind: false, ball: None }).unwrap();
            assert_eq!(s.in_cone.iter().filter(|&&b| b).count(), 4);
            for (k, j) in s.joints.iter().enumerate() {
                let (c, a) = (j.rotary[0], j.rotary[1]);
                assert!(c.abs() < 1e-9, "{min:?}: pose {k}: C {c}");
                assert!((a.abs() - alphas[k]).abs() < 1e-9, "{min:?}: pose {k}: A {a} for {}", alphas[k]);
            }
        }
    }

    /// With unwinding on, a big block is priced by how far its middle axis strays from the middle
    /// of the path's arc: from upright (C, A) = (0°, 0°) to A = 60°, the block to A = 60° passes
    /// A = 30°, the arc's middle, and is kept. Each of the others would stray by nothing were the
    /// middle taken elsewhere: A = 120° passes the arc's end (A = 60°), C = 180° the vertical,
    /// A = −120° passes A = −60°.
    #[test]
    fn a_big_block_is_priced_from_the_middle_of_the_arc() {
        let m = Machine::preset("head-head-ac").unwrap();
        let f = Value::Fixed;
        let end = tool_axis(&m, [0.0, 60.0]);
        let candidates = [
            vec![[f(0.0), f(0.0)]],
            vec![[f(0.0), f(120.0)], [f(180.0), f(0.0)], [f(0.0), f(-120.0)], [f(0.0), f(60.0)]],
        ];
        let chosen = choose(&m, &candidates, &[DVec3::Z, end], true);
        assert_eq!(chosen[1], [f(0.0), f(60.0)]);
    }

    /// A path that starts inside the pole cone (1.2° from the pole, the cone 2°) and leaves it
    /// towards a 3° tilt at 200°: the poses in the cone take C from the first pose outside it,
    /// whose two settings are C = −70° with A = 3° and C = 110° with A = −3° at the end; of the
    /// two branches the one that moves least from zero is kept, C near −70° throughout.
    #[test]
    fn a_path_starting_in_the_cone_takes_the_branch_that_moves_least() {
        let m = Machine::preset("head-head-ac").unwrap();
        let (a, b) = (tilted(1.2, 0.0), tilted(3.0, 200.0));
        for steps in [4, 7] {
            let poses: Vec<Pose> = (0..=steps)
                .map(|k| {
                    let s = k as f64 / steps as f64;
                    pose(s * 40.0, (a * (1.0 - s) + b * s).normalize())
                })
                .collect();
            let s =
                solve(&m, &poses, 40.0, &SolveOptions { cone: 2f64.to_radians(), unwind: false, ball: None }).unwrap();
            assert!(s.in_cone[0] && !s.in_cone[steps], "{:?}", s.in_cone);
            for (k, j) in s.joints.iter().enumerate() {
                assert!((-90.0..-50.0).contains(&j.rotary[0]), "{steps} steps, pose {k}: C {}", j.rotary[0]);
            }
            let last = s.joints[steps].rotary;
            assert!((last[0] + 70.0).abs() < 1e-9 && (last[1] - 3.0).abs() < 1e-9, "{last:?}");
        }
    }

    /// The same nearest value where it is not the path's own: A of the fork head limited to
    /// ±800° (five values of every angle), the tool tilted about X past a turn (from 6°, in 12°
    /// steps), and at 360° two poses in the cone of 5° tilted 3° the other way, about Y. There C
    /// keeps its neighbours' 0°, the path's own A is the exact 363° or 357°, and A is the tilt
    /// nearest the axis with C = 0°, 0° modulo a turn: 360°, the value nearest the path's own,
    /// not 720° or 0°.
    #[test]
    fn in_the_cone_the_nearest_of_many_turns_is_taken() {
        let about_x = |alpha: f64| DVec3::new(0.0, -alpha.to_radians().sin(), alpha.to_radians().cos());
        let about_y = tilted(3.0, 0.0);
        let axes: Vec<DVec3> =
            (0..30).map(|k| about_x(6.0 + 12.0 * k as f64)).chain([about_y, about_y, about_x(367.0)]).collect();
        let poses: Vec<Pose> = axes.iter().map(|&a| pose(0.0, a)).collect();
        let mut m = Machine::preset("head-head-ac").unwrap();
        (m.rotary[1].min, m.rotary[1].max) = (Some(-800.0), Some(800.0));
        let s = solve(&m, &poses, 40.0, &SolveOptions { cone: 5f64.to_radians(), unwind: false, ball: None }).unwrap();
        assert_eq!(s.in_cone.iter().filter(|&&b| b).count(), 2);
        for k in [30, 31] {
            assert!(s.in_cone[k]);
            assert!((s.joints[k].rotary[1].abs() - 360.0).abs() < 1e-9, "pose {k}: A {}", s.joints[k].rotary[1]);
        }
    }
}
