//! The linearisation check of the G-code post: between two blocks a controller moves its axes
//! linearly, so the tool strays from the path; this measures by how much and inserts poses
//! until it is within a tolerance.
//!
//! **The path between two poses** P_k, P_{k+1} of the refined path is the strip of its discrete
//! ruled surface: the tip on the chord tip_k → tip_{k+1}, the axis on the great-circle arc
//! axis_k → axis_{k+1}.
//!
//! **What the controller does** between the blocks, at s ∈ [0, 1]:
//! - machine coordinates: every axis linear, (X, Y, Z, v₁, v₂)(s) = (1 − s)·J_k + s·J_{k+1};
//!   the pose is the forward kinematics of that;
//! - tool-centre point with rotary angles (LinuxCNC, Heidenhain): the tip linear in the part
//!   frame, the angles linear, the axis from the angles;
//! - tool-centre point with vectors (Sinumerik `A3= B3= C3=` under `ORIVECT`): the tip linear,
//!   the axis on the great circle: the path itself.
//!
//! **The deviation** of a block is the largest, over LINEARISATION_SAMPLES values of s, of the
//! tip's distance from the chord and of the axis's angle from the arc times the tool length L
//! (the distance at the far end of a tool of that length), both in mm. A block above the
//! tolerance is halved (the new pose: the chord's midpoint and the arc's midpoint), the
//! kinematics solved again, up to MAX_LINEARISATION_ROUNDS rounds; a block still above it then
//! is an error naming its poses (the axes turn over or pass the pole there). A block where the
//! rotary axes flip from one solution to the other (`flip.rs`) is refused in every mode, naming
//! the axis whose limit forces it.

use crate::flip::flip;
use crate::kinematics::{forward_kinematics, tool_axis, Joints};
use crate::machine::Machine;
use crate::solve::{solve, SolveOptions};
use crate::tolerance::{LINEARISATION_SAMPLES, MAX_LINEARISATION_ROUNDS, MAX_POST_POSES};
use crate::Pose;
use glam::DVec3;
use ruledlab::{Arg, Error, Result};

/// How the controller interpolates between two blocks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Interpolation {
    /// Every machine axis linear (machine coordinates).
    Machine,
    /// Tool-centre point, the tip and the rotary angles linear.
    TcpAngles,
    /// Tool-centre point, the tip linear and the axis vector on a great circle.
    TcpVector,
}

/// The deviation of one block, mm.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BlockDeviation {
    /// Largest distance of the interpolated tip from the chord.
    pub tip: f64,
    /// Largest angle of the interpolated axis from the arc times the tool length.
    pub axis: f64,
    /// That angle, radians.
    pub angle: f64,
}

impl BlockDeviation {
    /// The larger of the two.
    pub fn max(&self) -> f64 {
        self.tip.max(self.axis)
    }
}

/// What the check found and did.
#[derive(Debug, Clone, PartialEq)]
pub struct Linearisation {
    /// The tolerance, mm.
    pub tolerance: f64,
    /// Largest deviations of the path as given (before inserting poses).
    pub before: BlockDeviation,
    /// Largest deviations of the program written.
    pub after: BlockDeviation,
    /// Poses inserted.
    pub inserted: usize,
    /// Rounds of halving.
    pub rounds: usize,
    /// The deviation of each block of the program written.
    pub blocks: Vec<BlockDeviation>,
}

/// The poses with their axis values after the check: the path's poses and the inserted ones,
/// `origin[i]` the position of pose i along the given path (k + s between poses k and k + 1).
#[derive(Debug, Clone, PartialEq)]
pub struct Linearised {
    /// The poses (part frame, mm).
    pub poses: Vec<Pose>,
    /// Their axis values.
    pub joints: Vec<Joints>,
    /// Where each pose lies on the given path.
    pub origin: Vec<f64>,
    /// At a pose where a limited axis unwinds, its rotary values after unwinding.
    pub unwound: Vec<Option<[f64; 2]>>,
    /// Angle between each pose's given tool axis and the one written (the pole cone), radians.
    pub adjusted: Vec<f64>,
    /// Whether each pose lies in the pole cone.
    pub in_cone: Vec<bool>,
    /// The report.
    pub report: Linearisation,
}

impl Linearised {
    /// The axis values the block leaving pose `i` starts from (after an unwinding there).
    pub fn leaving(&self, i: usize) -> Joints {
        let j = self.joints[i];
        Joints { rotary: self.unwound[i].unwrap_or(j.rotary), ..j }
    }
}

/// How [`linearise_with`] checks and solves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineariseOptions {
    /// How the controller interpolates.
    pub how: Interpolation,
    /// Largest deviation of the tip, and of the axis times the tool length, mm.
    pub tolerance: f64,
    /// Largest angle of the interpolated axis from the arc, radians (`None`: no such bound).
    pub angular: Option<f64>,
    /// The length the axis's angle is multiplied by (`None`: the tool length of the
    /// kinematics).
    pub lever: Option<f64>,
    /// The pole cone and unwinding.
    pub solve: SolveOptions,
}

fn angle(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b))
}

/// The angle of unit `v` from the great-circle arc a → b: from the arc's great circle where `v`
/// projects onto the arc (between a and b: a × v and v × b both along a × b), else from the
/// nearer end.
fn angle_from_arc(v: DVec3, a: DVec3, b: DVec3) -> f64 {
    let n = a.cross(b);
    if n.length() < 1e-12 {
        return angle(v, a);
    }
    let n = n.normalize();
    let off = v.dot(n);
    let inside = v - off * n;
    if inside.length() >= 1e-12 && a.cross(inside).dot(n) >= 0.0 && inside.cross(b).dot(n) >= 0.0 {
        return off.abs().min(1.0).asin();
    }
    angle(v, a).min(angle(v, b))
}

fn distance_from_chord(q: DVec3, a: DVec3, b: DVec3) -> f64 {
    let ab = b - a;
    let t = if ab.length_squared() > 0.0 { ((q - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0) } else { 0.0 };
    (q - (a + t * ab)).length()
}

/// The midpoint of a block on the path: the chord's and the arc's.
pub fn midpoint(a: &Pose, b: &Pose) -> Pose {
    let axis = a.axis + b.axis;
    let axis = if axis.length() > 1e-12 { axis.normalize() } else { a.axis };
    Pose { tip: 0.5 * (a.tip + b.tip), axis }
}

/// The deviation of the block between poses a and b with axis values ja, jb.
#[cfg(test)]
pub fn block_deviation(
    m: &Machine,
    (a, b): (&Pose, &Pose),
    (ja, jb): (&Joints, &Joints),
    how: Interpolation,
    tool_length: f64,
) -> BlockDeviation {
    block_deviation_with(m, (a, b), (ja, jb), how, (tool_length, tool_length))
}

/// [`block_deviation`] with the tool length of the kinematics and the lever of the axis's angle
/// apart.
pub fn block_deviation_with(
    m: &Machine,
    (a, b): (&Pose, &Pose),
    (ja, jb): (&Joints, &Joints),
    how: Interpolation,
    (tool_length, lever): (f64, f64),
) -> BlockDeviation {
    let mut d = BlockDeviation::default();
    for k in 1..LINEARISATION_SAMPLES {
        let s = k as f64 / LINEARISATION_SAMPLES as f64;
        let rotary =
            [ja.rotary[0] + s * (jb.rotary[0] - ja.rotary[0]), ja.rotary[1] + s * (jb.rotary[1] - ja.rotary[1])];
        let (tip, axis) = match how {
            Interpolation::Machine => {
                let p = forward_kinematics(m, &Joints { xyz: ja.xyz.lerp(jb.xyz, s), rotary }, tool_length);
                (p.tip, p.axis)
            }
            Interpolation::TcpAngles => (a.tip.lerp(b.tip, s), tool_axis(m, rotary)),
            Interpolation::TcpVector => (a.tip.lerp(b.tip, s), a.axis),
        };
        d.tip = d.tip.max(distance_from_chord(tip, a.tip, b.tip));
        if how != Interpolation::TcpVector {
            let angle = angle_from_arc(axis, a.axis, b.axis);
            d.angle = d.angle.max(angle);
            d.axis = d.axis.max(angle * lever);
        }
    }
    d
}

fn largest(blocks: &[BlockDeviation]) -> BlockDeviation {
    blocks.iter().fold(BlockDeviation::default(), |m, b| BlockDeviation {
        tip: m.tip.max(b.tip),
        axis: m.axis.max(b.axis),
        angle: m.angle.max(b.angle),
    })
}

/// An error of pose `i` of the current list named by its pose of the given path.
fn renamed(e: Error, origin: &[f64]) -> Error {
    match e {
        Error::Unreachable { pose, line, mut message } => {
            let given = origin.get(pose).map_or(pose, |o| o.floor() as usize);
            for (name, value) in &mut message.args {
                if *name == "pose" {
                    *value = Arg::Number(given as f64);
                }
            }
            Error::Unreachable { pose: given, line, message }
        }
        other => other,
    }
}

/// Solves the kinematics of `poses` (part frame, mm) and halves the blocks whose interpolation
/// strays beyond `tolerance` (mm) until none does, in at most [`MAX_LINEARISATION_ROUNDS`]
/// rounds and [`MAX_POST_POSES`] poses.
#[cfg(test)]
pub fn linearise(
    m: &Machine,
    poses: &[Pose],
    tool_length: f64,
    how: Interpolation,
    tolerance: f64,
) -> Result<Linearised> {
    let o = LineariseOptions { how, tolerance, angular: None, lever: None, solve: SolveOptions::exact() };
    linearise_with(m, poses, tool_length, &o)
}

/// [`linearise`] with an angular tolerance, the pole cone and unwinding: a block is measured
/// against the poses the program writes (in the cone, the tool axis of the interpolated rotary
/// values), from the axis values it leaves its first pose with (after an unwinding there).
#[cfg(test)]
pub fn linearise_with(m: &Machine, poses: &[Pose], tool_length: f64, o: &LineariseOptions) -> Result<Linearised> {
    linearise_at_most(m, poses, tool_length, o, (MAX_LINEARISATION_ROUNDS, MAX_POST_POSES), &mut |_| {})
}

/// [`linearise_with`] telling `progress` the number of each round as it ends (0 first).
pub fn linearise_reporting(
    m: &Machine,
    poses: &[Pose],
    tool_length: f64,
    o: &LineariseOptions,
    progress: &mut dyn FnMut(usize),
) -> Result<Linearised> {
    linearise_at_most(m, poses, tool_length, o, (MAX_LINEARISATION_ROUNDS, MAX_POST_POSES), progress)
}

/// A block's ends: the axis values it leaves and reaches, and the poses it joins.
type BlockEnds = (Joints, Joints, Pose, Pose);

/// [`linearise_with`] with its limits, (rounds, poses), as a parameter.
fn linearise_at_most(
    m: &Machine,
    poses: &[Pose],
    tool_length: f64,
    o: &LineariseOptions,
    (max_rounds, max_poses): (usize, usize),
    progress: &mut dyn FnMut(usize),
) -> Result<Linearised> {
    let (how, tolerance) = (o.how, o.tolerance);
    let too_far = |b: &BlockDeviation| b.max() > tolerance || o.angular.is_some_and(|a| b.angle > a);
    let mut poses = poses.to_vec();
    let mut origin: Vec<f64> = (0..poses.len()).map(|i| i as f64).collect();
    let mut before = None;
    let mut round = 0;
    // the blocks of the previous round that were kept whole: new block i was old block carried[i]
    // (a pure function of its poses and axis values: where those are the same, so is its deviation)
    let mut previous: Option<(Vec<BlockEnds>, Vec<BlockDeviation>)> = None;
    let mut carried: Vec<Option<usize>> = Vec::new();
    loop {
        let solved = solve(m, &poses, tool_length, &o.solve).map_err(|e| renamed(e, &origin))?;
        let ends: Vec<BlockEnds> = (0..poses.len().saturating_sub(1))
            .map(|i| (solved.leaving(i), solved.joints[i + 1], solved.poses[i], solved.poses[i + 1]))
            .collect();
        let blocks: Vec<BlockDeviation> = ends
            .iter()
            .enumerate()
            .map(|(i, e)| {
                if let (Some((old_ends, old_blocks)), Some(&Some(j))) = (&previous, carried.get(i)) {
                    if old_ends[j] == *e {
                        return old_blocks[j];
                    }
                }
                let lever = o.lever.unwrap_or(tool_length);
                block_deviation_with(m, (&e.2, &e.3), (&e.0, &e.1), how, (tool_length, lever))
            })
            .collect();
        let before = *before.get_or_insert(largest(&blocks));
        progress(round);
        let bad: Vec<usize> = (0..blocks.len()).filter(|&i| too_far(&blocks[i])).collect();
        if bad.is_empty() || round == max_rounds {
            // a flip of the rotary axes inside the cut, in every mode (the halving cannot mend it)
            for (i, e) in ends.iter().enumerate() {
                if let Some(err) = flip(m, o.solve.cone, (&e.2, &e.3), (&e.0, &e.1), origin[i].floor() as usize) {
                    return Err(err);
                }
            }
        }
        if bad.is_empty() {
            let inserted = poses.len() - origin.iter().filter(|o| o.fract() == 0.0).count();
            let after = largest(&blocks);
            return Ok(Linearised {
                poses: solved.poses,
                joints: solved.joints,
                origin,
                unwound: solved.unwound,
                adjusted: solved.adjusted,
                in_cone: solved.in_cone,
                report: Linearisation { tolerance, before, after, inserted, rounds: round, blocks },
            });
        }
        if round == max_rounds {
            let worst = bad.iter().copied().fold(bad[0], |w, i| if blocks[i].max() > blocks[w].max() { i } else { w });
            let pose = origin[worst].floor() as usize;
            return Err(Error::Unreachable {
                pose,
                line: None,
                message: crate::msg!(
                    "linearisation-tolerance",
                    pose = pose,
                    next = pose + 1,
                    deviation = blocks[worst].max(),
                    rounds = round,
                    tolerance = tolerance
                ),
            });
        }
        if poses.len() + bad.len() > max_poses {
            return Err(Error::TooMany { what: "poses of the program", got: poses.len() + bad.len(), max: max_poses });
        }
        let (mut p, mut og) =
            (Vec::with_capacity(poses.len() + bad.len()), Vec::with_capacity(poses.len() + bad.len()));
        let mut c = Vec::with_capacity(poses.len() + bad.len());
        let mut next_bad = bad.iter().peekable();
        for i in 0..poses.len() {
            p.push(poses[i]);
            og.push(origin[i]);
            if next_bad.peek() == Some(&&i) {
                next_bad.next();
                p.push(midpoint(&poses[i], &poses[i + 1]));
                og.push(0.5 * (origin[i] + origin[i + 1]));
                c.extend([None, None]);
            } else {
                c.push(Some(i));
            }
        }
        (poses, origin, carried) = (p, og, c);
        previous = Some((ends, blocks));
        round += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solve::inverse_kinematics;

    #[test]
    fn an_arc_and_a_chord_measure_distances() {
        let (a, b) = (DVec3::X, DVec3::Y);
        assert!(angle_from_arc(DVec3::new(1.0, 1.0, 0.0).normalize(), a, b) < 1e-12);
        assert!(
            (angle_from_arc(DVec3::new(1.0, 1.0, 1.0).normalize(), a, b) - (1.0f64 / 3.0).sqrt().asin()).abs() < 1e-12
        );
        assert!((angle_from_arc(-DVec3::X, a, b) - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
        assert!((distance_from_chord(DVec3::new(0.5, 1.0, 0.0), DVec3::ZERO, DVec3::X) - 1.0).abs() < 1e-15);
    }

    #[test]
    fn halving_brings_every_block_within_the_tolerance() {
        let m = Machine::preset("table-table-ac").unwrap();
        let poses = [
            Pose { tip: DVec3::new(0.0, 0.0, 0.0), axis: DVec3::new(0.0, 0.3, 1.0).normalize() },
            Pose { tip: DVec3::new(30.0, 0.0, 0.0), axis: DVec3::new(0.5, -0.3, 1.0).normalize() },
        ];
        let l = linearise(&m, &poses, 50.0, Interpolation::Machine, 0.01).unwrap();
        assert!(l.report.before.max() > 0.01 && l.report.after.max() <= 0.01, "{:?}", l.report);
        assert_eq!(l.poses.len(), 2 + l.report.inserted);
        assert_eq!(l.report.blocks.len(), l.poses.len() - 1);
        assert_eq!((l.poses[0], *l.poses.last().unwrap()), (poses[0], poses[1]));
        // tool-centre point with vectors follows the path itself
        let v = linearise(&m, &poses, 50.0, Interpolation::TcpVector, 0.01).unwrap();
        assert_eq!(v.report.inserted, 0);
    }

    #[test]
    fn blocks_kept_from_round_to_round_are_the_blocks_computed_afresh() {
        // a path whose blocks need different numbers of halvings: some are kept whole in a round
        let m = Machine::preset("table-table-ac").unwrap();
        let poses: Vec<Pose> = (0..6)
            .map(|i| {
                let t = f64::from(i);
                Pose {
                    tip: DVec3::new(12.0 * t, 3.0 * t.sin(), 0.0),
                    axis: DVec3::new(0.4 * (t * t / 9.0).sin(), 0.2, 1.0).normalize(),
                }
            })
            .collect();
        for how in [Interpolation::Machine, Interpolation::TcpAngles] {
            let l = linearise(&m, &poses, 50.0, how, 0.005).unwrap();
            assert!(l.report.rounds >= 2 && l.report.inserted > 0, "{:?}", l.report);
            for (i, block) in l.report.blocks.iter().enumerate() {
                let fresh =
                    block_deviation(&m, (&l.poses[i], &l.poses[i + 1]), (&l.joints[i], &l.joints[i + 1]), how, 50.0);
                assert_eq!(*block, fresh, "block {i}");
            }
        }
    }

    #[test]
    fn distances_from_a_chord_and_an_arc_are_their_definitions() {
        // the chord (1, 1, 0) → (1, 3, 0): a point beside its middle is 1 from it, beyond its ends
        // the distance to the end; a chord of one point is that point
        let (a, b) = (DVec3::new(1.0, 1.0, 0.0), DVec3::new(1.0, 3.0, 0.0));
        assert_eq!(distance_from_chord(DVec3::new(0.0, 2.0, 0.0), a, b), 1.0);
        assert_eq!(distance_from_chord(DVec3::new(1.0, 5.0, 0.0), a, b), 2.0);
        assert_eq!(distance_from_chord(DVec3::new(4.0, 5.0, 0.0), a, a), 5.0);
        // the arc X → Y on the unit sphere: a direction above its middle at 30° is 30° from it,
        // one beside the arc is as far as the nearer end, and an arc of one point is that point
        let deg = std::f64::consts::PI / 180.0;
        let above = DVec3::new((45.0 * deg).cos() * (60.0 * deg).sin(), (45.0 * deg).sin() * (60.0 * deg).sin(), 0.5);
        assert!((angle_from_arc(above, DVec3::X, DVec3::Y) - 30.0 * deg).abs() < 1e-15);
        let beside = DVec3::new((-20.0 * deg).cos(), (-20.0 * deg).sin(), 0.0);
        assert!((angle_from_arc(beside, DVec3::X, DVec3::Y) - 20.0 * deg).abs() < 1e-15);
        assert!((angle_from_arc(DVec3::Y, DVec3::X, DVec3::X) - 90.0 * deg).abs() < 1e-15);
    }

    #[test]
    fn one_rotary_axis_turning_alone_keeps_the_tool_axis_on_the_great_circle() {
        // table-table-ac: A turning alone from 0° to 60° (C = 0), or C alone from 0° to 60° with A
        // at 90° (the axis then on the equator), turns the tool axis about one line, along the
        // great circle through its ends: no axis deviation with the angles interpolated
        let m = Machine::preset("table-table-ac").unwrap();
        for (from, to) in [([0.0, 0.0], [60.0, 0.0]), ([90.0, 0.0], [90.0, 60.0])] {
            let (ja, jb) = (Joints { xyz: DVec3::ZERO, rotary: from }, Joints { xyz: DVec3::ZERO, rotary: to });
            let (a, b) = (forward_kinematics(&m, &ja, 50.0), forward_kinematics(&m, &jb, 50.0));
            assert!(a.axis.angle_between(b.axis) > 1.0, "the ends are 60° apart");
            let d = block_deviation(&m, (&a, &b), (&ja, &jb), Interpolation::TcpAngles, 50.0);
            assert!(d.axis < 1e-12 && d.tip < 1e-12, "{from:?} → {to:?}: {d:?}");
        }
    }

    #[test]
    fn a_blocks_midpoint_halves_the_chord_and_the_arc() {
        let (a, b) = (
            Pose { tip: DVec3::new(1.0, 2.0, 3.0), axis: DVec3::X },
            Pose { tip: DVec3::new(3.0, 4.0, 5.0), axis: DVec3::Y },
        );
        let m = midpoint(&a, &b);
        assert_eq!(m.tip, DVec3::new(2.0, 3.0, 4.0));
        assert!((m.axis - DVec3::new(1.0, 1.0, 0.0) / 2f64.sqrt()).length() < 1e-16);
        // opposite axes have no arc between them: the first is kept
        assert_eq!(midpoint(&a, &Pose { axis: -DVec3::X, ..b }).axis, DVec3::X);
    }

    /// Ends within 1e-12 of opposite span no plane one can trust (their cross product is mostly
    /// rounding): like the midpoint, the arc keeps its start, and a direction square to it is
    /// 90° away, although a plane through (1, 0, 0) and (−1, 1e-13, 0) would hold it.
    #[test]
    fn an_arc_between_nearly_opposite_ends_is_its_start() {
        let b = DVec3::new(-1.0, 1e-13, 0.0);
        assert!((angle_from_arc(DVec3::Y, DVec3::X, b) - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    }

    /// An error at pose 5 of a list with poses inserted (origins 0, ½, 1, 1½, 2, 2½, 3) is at
    /// pose 2 of the given path: the error and its message's `pose` say so, its other numbers
    /// stay; a pose beyond the list keeps its number, and other errors pass unchanged.
    #[test]
    fn errors_name_the_pose_of_the_given_path() {
        let origin = [0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0];
        let at = |pose: usize| Error::Unreachable {
            pose,
            line: None,
            message: crate::msg!("pose-unreachable", pose = pose, axis = "A", value = 130.0),
        };
        let Error::Unreachable { pose, message, .. } = renamed(at(5), &origin) else { panic!("unreachable") };
        assert_eq!(pose, 2);
        assert_eq!(
            message.args,
            vec![("pose", Arg::Number(2.0)), ("axis", Arg::Text("A".into())), ("value", Arg::Number(130.0))]
        );
        assert!(matches!(renamed(at(9), &origin), Error::Unreachable { pose: 9, .. }));
        let other = Error::parameter("tolerance", "too small");
        assert_eq!(renamed(other.clone(), &origin), other);
    }

    /// Three poses 10 mm apart, the axis tilted about Y by 0°, 2° and 22°: a block that turns
    /// it 2°, then one that turns it 20°.
    fn two_turns() -> [Pose; 3] {
        let pose = |x: f64, a: f64| Pose {
            tip: DVec3::new(x, 0.0, 0.0),
            axis: DVec3::new(a.to_radians().sin(), 0.0, a.to_radians().cos()),
        };
        [pose(0.0, 0.0), pose(10.0, 2.0), pose(20.0, 22.0)]
    }

    /// The inserted poses' places on the given path increase and are multiples of 2^−r after
    /// r rounds of halving: the second block turns the axis 20°, the first 2°.
    #[test]
    fn inserted_poses_halve_their_blocks_of_the_given_path() {
        let (m, poses) = (Machine::preset("table-table-ac").unwrap(), two_turns());
        let l = linearise(&m, &poses, 50.0, Interpolation::Machine, 1e-3).unwrap();
        assert!(l.report.inserted >= 2 && l.report.rounds >= 2, "{:?}", l.report);
        assert_eq!((l.origin[0], l.origin[l.origin.len() - 1]), (0.0, 2.0));
        for k in 1..l.origin.len() - 1 {
            let (a, o, b) = (l.origin[k - 1], l.origin[k], l.origin[k + 1]);
            assert!(a < o && o < b, "{a} {o} {b}");
            if o.fract() != 0.0 {
                // an inserted pose: k/2^r with r ≤ the rounds, between the given poses ⌊o⌋ and ⌈o⌉
                let scaled = o * 2f64.powi(l.report.rounds as i32);
                assert_eq!(scaled.fract(), 0.0, "{o}");
            }
        }
    }

    /// A tolerance out of reach: after the last round the error names the worst block by its
    /// pose of the given path (the second block turns the axis 20°, the first 2°: pose 1) and
    /// the rounds; both blocks are halved each round (3, 5, 9, 17 poses), so a limit of 5 poses
    /// is met in round 0 and exceeded in round 1 (5 + 4 = 9), and one of 4 at once (3 + 2).
    #[test]
    fn the_limits_of_rounds_and_poses_are_kept() {
        let (m, poses) = (Machine::preset("table-table-ac").unwrap(), two_turns());
        let o = LineariseOptions {
            how: Interpolation::Machine,
            tolerance: 1e-300,
            angular: None,
            lever: None,
            solve: SolveOptions::exact(),
        };
        let run = |limits| linearise_at_most(&m, &poses, 50.0, &o, limits, &mut |_| {});
        let Err(Error::Unreachable { pose, message, .. }) = run((3, 100)) else { panic!("{:?}", run((3, 100))) };
        assert_eq!((pose, message.reason), (1, "linearisation-tolerance"));
        assert_eq!((message.arg("rounds"), message.arg("next")), (Some(&Arg::Number(3.0)), Some(&Arg::Number(2.0))));
        for (max, got) in [(5, 9), (4, 5), (16, 17)] {
            assert!(
                matches!(run((3, max)), Err(Error::TooMany { got: g, max: m, .. }) if g == got && m == max),
                "{max}: {:?}",
                run((3, max)).err()
            );
        }
        assert!(matches!(run((3, 17)), Err(Error::Unreachable { .. })));
    }

    /// Of equally bad blocks the error names the first: on the path a, b, a, b in tool-centre
    /// point with the angles interpolated, the axis deviation depends only on the axes and their
    /// rotary values, so the three blocks (the middle one reversed) are equally bad to the bit.
    #[test]
    fn of_equally_bad_blocks_the_first_is_named() {
        let m = Machine::preset("table-table-ac").unwrap();
        let (a, b) = (DVec3::new(0.0, 0.6, 0.8), DVec3::new(0.6, 0.0, 0.8));
        let poses: Vec<Pose> = [a, b, a, b]
            .iter()
            .enumerate()
            .map(|(k, &axis)| Pose { tip: DVec3::new(k as f64, 0.0, 0.0), axis })
            .collect();
        let joints = inverse_kinematics(&m, &poses, 50.0).unwrap();
        let d: Vec<f64> = (0..3)
            .map(|i| {
                block_deviation(
                    &m,
                    (&poses[i], &poses[i + 1]),
                    (&joints[i], &joints[i + 1]),
                    Interpolation::TcpAngles,
                    50.0,
                )
                .max()
            })
            .collect();
        assert!(d[0] > 1.0 && d[1] == d[0] && d[2] == d[0], "three equal blocks: {d:?}");
        let o = LineariseOptions {
            how: Interpolation::TcpAngles,
            tolerance: 1e-300,
            angular: None,
            lever: None,
            solve: SolveOptions::exact(),
        };
        let e = linearise_at_most(&m, &poses, 50.0, &o, (0, 100), &mut |_| {}).unwrap_err();
        assert!(matches!(e, Error::Unreachable { pose: 0, .. }), "{e:?}");
    }
}
