//! The steps of a program in no dialect yet (the module documentation of `post` says what they
//! are). Everything is computed in millimetres and converted to the program's units at the end.

use super::controller::{Orientation, Travel};
use super::header::{header, HeaderFacts};
use super::{
    validate, Context, Controller, Coolant, Mode, Numbering, Op, Plan, PostOptions, Rate, Units, Warning, Waypoint,
    Words,
};
use crate::kinematics::{forward_kinematics, machine_position, tool_axis, Joints};
use crate::linearise::{linearise_reporting, Interpolation, LineariseOptions, Linearised};
use crate::machine::Machine;
use crate::motion::{time_blocks, BlockMotion, BlockNeed, Limit};
use crate::solve::SolveOptions;
use crate::stock::{Aabb, Stretch, ToolShape};
use crate::sweep::{sweep_deviation, Move, SweptBlock};
use crate::tolerance::{GCODE_DECIMALS, MIN_RETRACT_COS};
use crate::{Pose, Tool, ToolEnd, ToolPath};
use glam::DVec3;
use ruledlab::{Arg, Error, Message, Result};

/// Samples of a rapid move or a turn checked against the stock.
const MOTION_SAMPLES: usize = 48;
/// Steps of raising a safe point before the post gives up (each the clearance, at least 1 mm).
const RAISE_STEPS: usize = 400;

/// Where a pose of the path is named: the input's pose and its line.
struct Namer<'a>(Option<&'a Numbering>);

impl Namer<'_> {
    /// The input pose at or before path pose `i`, and its line.
    fn at(&self, i: usize) -> (usize, Option<usize>) {
        match self.0 {
            None => (i, None),
            Some(n) => {
                let k = i / n.stride;
                (k, n.lines.get(k).copied())
            }
        }
    }

    /// The input pose after path pose `i` (for "between poses k and k + 1").
    fn next(&self, i: usize) -> usize {
        match self.0 {
            None => i + 1,
            Some(n) => (i + 1).div_ceil(n.stride),
        }
    }

    /// An error of the path's pose numbering in the input's.
    fn error(&self, e: Error) -> Error {
        match e {
            Error::Unreachable { pose, line: _, mut message } => {
                let (k, line) = self.at(pose);
                let next = self.next(pose);
                for (name, value) in &mut message.args {
                    match *name {
                        "pose" => *value = Arg::Number(k as f64),
                        "next" => *value = Arg::Number(next as f64),
                        _ => {}
                    }
                }
                Error::Unreachable { pose: k, line, message }
            }
            other => other,
        }
    }

    fn warning(&self, path_pose: usize, message: Message) -> Warning {
        let (pose, line) = self.at(path_pose);
        let mut message = message;
        for (name, value) in &mut message.args {
            if matches!(*name, "pose" | "previous") {
                if let Arg::Number(x) = value {
                    *value = Arg::Number(self.at(*x as usize).0 as f64);
                }
            }
        }
        Warning { pose, line, message }
    }
}

/// The job's quantities in millimetres.
struct Job {
    radius: f64,
    cutter: f64,
    gauge: f64,
    clearance: f64,
    feed: f64,
    approach: f64,
    tolerance: f64,
    stock: Aabb,
    stock_given: bool,
    shape: ToolShape,
    safe_height: f64,
}

/// The steps of `path`'s program for the options' dialect, in no dialect yet (see the module
/// documentation).
#[cfg(test)]
pub fn plan(path: &ToolPath, o: &PostOptions) -> Result<Plan> {
    plan_reporting(path, o, o.dialect.controller(), &mut |_| {})
}

/// [`plan`] for `controller` (how it interpolates, what its feed word reads), telling `progress`
/// how far it is (0 to 1; the linearisation's rounds take most of the time, each halving what is
/// left before 0.8).
pub fn plan_reporting(
    path: &ToolPath,
    o: &PostOptions,
    controller: &dyn Controller,
    progress: &mut dyn FnMut(f64),
) -> Result<Plan> {
    validate(o, controller)?;
    let namer = Namer(o.numbering.as_ref());
    plan_named(path, o, controller, &namer, progress).map_err(|e| namer.error(e))
}

fn plan_named(
    path: &ToolPath,
    o: &PostOptions,
    controller: &dyn Controller,
    namer: &Namer,
    progress: &mut dyn FnMut(f64),
) -> Result<Plan> {
    let m = &o.machine;
    let u = o.units.mm();
    let s = o.scale * u;
    let poses: Vec<Pose> = path.poses.iter().map(|p| Pose { tip: s * p.tip, axis: p.axis.normalize() }).collect();
    let job = job(path, o, &poses)?;
    let mut warnings = input_warnings(&poses, namer);
    let how = match (o.mode, controller.orientation()) {
        (Mode::Machine, _) => Interpolation::Machine,
        (Mode::Tcp, Orientation::Vector) => Interpolation::TcpVector,
        (Mode::Tcp, Orientation::Angles) => Interpolation::TcpAngles,
    };
    let lo = LineariseOptions {
        how,
        tolerance: job.tolerance,
        angular: o.angular_tolerance.map(f64::to_radians),
        lever: Some(job.cutter),
        solve: SolveOptions {
            cone: o.pole_cone.to_radians(),
            unwind: true,
            ball: (path.tool.end == ToolEnd::Ball).then_some(job.radius),
        },
    };
    progress(0.05);
    let lin = linearise_reporting(m, &poses, job.gauge, &lo, &mut |round| {
        progress(0.05 + 0.75 * (1.0 - 0.5f64.powi(round as i32 + 1)))
    })?;
    let n = lin.poses.len();
    let path_pose = |i: usize| lin.origin[i].floor() as usize;

    // the blocks' times
    let rounded = |v: f64| (v * 10f64.powi(GCODE_DECIMALS as i32)).round();
    let waypoint = |p: &Pose, j: &Joints| Waypoint {
        xyz: if o.mode == Mode::Tcp { p.tip } else { j.xyz },
        rotary: j.rotary,
        axis: p.axis,
    };
    let mut needs = Vec::with_capacity(n.saturating_sub(1));
    let mut turns = Vec::with_capacity(n.saturating_sub(1));
    for i in 1..n {
        let (a, b) = (&lin.poses[i - 1], &lin.poses[i]);
        let (ja, jb) = (lin.leaving(i - 1), lin.joints[i]);
        let turning = (0..2).any(|k| rounded(ja.rotary[k]) != rounded(jb.rotary[k]));
        let tip = (b.tip - a.tip).length();
        let distance = if tip > 1e-3 || !turning { tip } else { tip.max(job.cutter * a.axis.angle_between(b.axis)) };
        let linear = (waypoint(b, &jb).xyz - waypoint(a, &ja).xyz).length();
        let turn = DVec3::new(jb.rotary[0] - ja.rotary[0], jb.rotary[1] - ja.rotary[1], 0.0).length();
        let travel = Travel { turning, distance, linear, turn };
        let word = controller.max_feed().map(|max| (controller.feed_measure(o.mode, &travel, o.units), max));
        needs.push(BlockNeed { from: ja, to: jb, distance, word });
        turns.push((turning, distance, linear, turn));
    }
    let motion = time_blocks(m, &needs, job.feed);
    progress(0.85);
    warnings.extend(motion_warnings(&motion, &needs, (job.feed, o.units), &lin, namer, m));
    warnings.extend(cone_warnings(&lin, o.pole_cone, namer));

    // the safe start and end, and the unwinds, clear of the stock
    let start = safe_point(m, &job, &lin.poses[0], lin.joints[0].rotary, path_pose(0))?;
    let end = safe_point(m, &job, &lin.poses[n - 1], lin.leaving(n - 1).rotary, path_pose(n - 1))?;
    let z_top = m.travel[2][1];
    let at = |p: DVec3, a: DVec3, rotary: [f64; 2]| -> Waypoint {
        let xyz = machine_position(m, p, rotary, job.gauge);
        Waypoint { xyz: if o.mode == Mode::Tcp { p } else { xyz }, rotary, axis: a }
    };
    let first = &lin.poses[0];
    let j0 = lin.joints[0];
    let mut ops = vec![
        Op::Start,
        Op::WorkOffset(o.work_offset),
        Op::ToolChange { tool: o.tool, spindle: o.spindle, direction: o.direction },
        Op::Tolerance { chordal: job.tolerance, angular: o.angular_tolerance.unwrap_or(0.0) },
        Op::Comment("safe start: spindle to the top of Z, rotary axes turned there, X Y, then Z".into()),
        Op::RetractTop(z_top),
        Op::Rotate(j0.rotary),
    ];
    if o.mode == Mode::Tcp {
        ops.push(Op::Tcp(true));
    }
    let top = top_of(m, o, &job, start.point, j0.rotary, z_top);
    ops.extend([
        Op::Rapid(top, Words::Xy),
        Op::Rapid(at(start.point, first.axis, j0.rotary), Words::Z),
        Op::Comment("down the tool axis to the clearance outside the stock".into()),
        Op::Rapid(at(start.near, first.axis, j0.rotary), Words::All),
        Op::Coolant(o.coolant),
        Op::Feed(waypoint(first, &j0), Rate::PerMinute(job.approach)),
        Op::Comment("cut".into()),
    ]);
    for i in 1..n {
        let (turning, distance, linear, turn) = turns[i - 1];
        let bm = motion[i - 1];
        let jb = lin.joints[i];
        let still = distance < 1e-9 && !turning;
        if still {
            // a pose repeated: no empty block (its warning names it)
            continue;
        }
        let rate = if turning {
            Rate::Simultaneous { minutes: bm.minutes, distance, linear, turn }
        } else {
            Rate::PerMinute(distance / bm.minutes.max(1e-12))
        };
        ops.push(Op::Feed(waypoint(&lin.poses[i], &jb), rate));
        if let Some(after) = lin.unwound[i] {
            ops.extend(unwind(m, o, controller.orientation(), &job, &lin, i, after, namer, path_pose(i))?);
        }
    }
    let last = &lin.poses[n - 1];
    let jn = lin.leaving(n - 1);
    let home = home_of(m, jn.rotary);
    ops.extend([
        Op::Comment("end of cut".into()),
        Op::Comment("safe end: out along the tool axis, spindle to the top of Z, rotary axes to 0".into()),
        Op::Feed(at(end.near, last.axis, jn.rotary), Rate::PerMinute(job.approach)),
        Op::Coolant(Coolant::Off),
        Op::SpindleOff,
        Op::Rapid(at(end.point, last.axis, jn.rotary), Words::All),
    ]);
    if o.mode == Mode::Tcp {
        ops.push(Op::Tcp(false));
    }
    ops.push(Op::RetractTop(z_top));
    for k in 0..2 {
        if home[k] != 0.0 && m.rotary[k].min.is_none() && m.rotary[k].max.is_none() {
            ops.push(Op::Comment(format!(
                "{} ends at {}, its zero a whole number of turns on: no unwinding rapid",
                m.rotary[k].name.letter(),
                super::number(home[k], false)
            )));
        }
    }
    ops.extend([Op::ToleranceOff, Op::Rotate(home), Op::End]);
    warnings.extend(tool_warnings(&job, &lin, o.units, namer));

    // the sweep of the program as posted, and the target's deviation from it
    let sweep = swept_blocks(&lin, how, &job, (start.near, end.near));
    let deviation = o.target.as_ref().map(|t| {
        let targets: Vec<DVec3> = t.iter().map(|&q| s * q).collect();
        let tool = Tool { radius: job.radius, length: job.cutter, end: path.tool.end };
        let d = sweep_deviation(m, job.gauge, &tool, &sweep, &targets, &mut |f| progress(0.85 + 0.1 * f));
        let pose = namer.at(path_pose((d.at[d.worst].floor().max(0.0) as usize).min(n - 1))).0;
        let point = targets[d.worst];
        (d, point, pose)
    });

    let facts = HeaderFacts {
        poses: n,
        job_feed: job.feed,
        approach: job.approach,
        safe: start.height,
        stock: job.stock,
        stock_given: job.stock_given,
        radius: job.radius,
        cutter: job.cutter,
        gauge: job.gauge,
        motion: &motion,
        unwinds: lin.unwound.iter().filter(|x| x.is_some()).count(),
        warnings: &warnings,
        deviation: deviation.as_ref().map(|(d, q, pose)| (d, *q, *pose)),
    };
    let mut all = header(path, o, controller, &lin.report, &facts);
    all.extend(ops);
    let ops: Vec<Op> = all.into_iter().map(|op| in_units(op, 1.0 / u)).collect();
    let context = Context {
        letters: [m.rotary[0].name.letter(), m.rotary[1].name.letter()],
        mode: o.mode,
        name: o.name.clone(),
        bounds: (job.stock.min / u, job.stock.max / u),
        units: o.units,
    };
    let deviation = deviation.map(|d| d.0);
    Ok(Plan { ops, context, linearised: lin, motion, warnings, sweep, deviation })
}

/// The blocks the controller moves the tool through (`sweep.rs`): the approach down the first
/// pose's axis from the clearance point, the cut as the controller interpolates it, an
/// unwinding's way out along the tool axis and back (its turn is clear of the stock), the
/// retract; all in mm, positions along the program's poses.
fn swept_blocks(lin: &Linearised, how: Interpolation, job: &Job, (near0, near1): (DVec3, DVec3)) -> Vec<SweptBlock> {
    let n = lin.poses.len();
    let cut = match how {
        Interpolation::Machine => Move::Joints,
        Interpolation::TcpAngles => Move::Angles,
        Interpolation::TcpVector => Move::Vector,
    };
    let straight = |p: Pose, to: DVec3, j: Joints, at: f64| SweptBlock {
        from: Pose { tip: to, axis: p.axis },
        to: p,
        joints: (j, j),
        how: Move::Straight,
        start: at,
        span: 0.0,
    };
    let mut out = vec![straight(lin.poses[0], near0, lin.joints[0], 0.0)];
    for i in 1..n {
        out.push(SweptBlock {
            from: lin.poses[i - 1],
            to: lin.poses[i],
            joints: (lin.leaving(i - 1), lin.joints[i]),
            how: cut,
            start: (i - 1) as f64,
            span: 1.0,
        });
        if lin.unwound[i].is_some() {
            let p = lin.poses[i];
            let near = p.tip + clear_out(job, &p) * p.axis;
            out.push(straight(p, near, lin.joints[i], i as f64));
        }
    }
    out.push(straight(lin.poses[n - 1], near1, lin.leaving(n - 1), (n - 1) as f64));
    out
}

/// The job in millimetres, checked.
fn job(path: &ToolPath, o: &PostOptions, poses: &[Pose]) -> Result<Job> {
    let u = o.units.mm();
    let s = o.scale * u;
    let radius = path.tool.radius * s;
    let cutter = path.tool.length * s;
    let gauge = o.gauge.map_or(cutter, |g| g * u);
    if gauge < cutter * (1.0 - 1e-12) {
        return Err(Error::parameter(
            "gauge",
            format!("must be at least the tool's length, {}, got {}", cutter / u, gauge / u),
        ));
    }
    let shank = o.shank.map_or(radius, |r| r * u);
    let mut above = Vec::new();
    let holder_from = o.holder.map_or(gauge, |h| (gauge - h.length * u).max(cutter));
    if holder_from > cutter {
        above.push(("shank", Stretch { from: cutter, to: holder_from, radius: shank }));
    }
    if let Some(h) = o.holder {
        above.push(("holder", Stretch { from: holder_from, to: gauge, radius: h.radius * u }));
    }
    let shape =
        ToolShape { ball: path.tool.end == ToolEnd::Ball, cutter: Stretch { from: 0.0, to: cutter, radius }, above };
    let (stock, stock_given) = match o.stock {
        Some([a, b]) => (Aabb { min: DVec3::from(a) * u, max: DVec3::from(b) * u }, true),
        None => (Aabb::around(poses.iter().map(|p| p.tip)).grown(1.0), false),
    };
    let clearance = o.clearance * u;
    let top = poses.iter().map(|p| p.tip.z).fold(f64::NEG_INFINITY, f64::max);
    let safe_height = match o.safe_height {
        Some(h) => {
            if h * u < top + clearance {
                return Err(Error::parameter(
                    "safeHeight",
                    format!(
                        "must be at least the highest tip plus the clearance, {} {}, got {h}",
                        super::number((top + clearance) / u, false),
                        o.units.word()
                    ),
                ));
            }
            h * u
        }
        None => top + clearance + 25.0,
    };
    let feed = o.feed * u;
    Ok(Job {
        radius,
        cutter,
        gauge,
        clearance,
        feed,
        approach: o.approach_feed.map_or(feed / 4.0, |f| f * u),
        tolerance: o.tolerance * u,
        stock,
        stock_given,
        shape,
        safe_height,
    })
}

/// Duplicate poses and tool axes that turn over between two poses of the path.
fn input_warnings(poses: &[Pose], namer: &Namer) -> Vec<Warning> {
    let mut out = Vec::new();
    for i in 1..poses.len() {
        let (a, b) = (&poses[i - 1], &poses[i]);
        if (b.tip - a.tip).length() < 1e-9 && (b.axis - a.axis).length() < 1e-12 {
            out.push(namer.warning(i, crate::msg!("warn-duplicate-pose", pose = i, previous = i - 1)));
        } else if a.axis.dot(b.axis) < 0.0 {
            let angle = a.axis.angle_between(b.axis).to_degrees();
            out.push(namer.warning(
                i,
                crate::msg!("warn-flipped-axis", pose = i, angle = (angle * 10.0).round() / 10.0, previous = i - 1),
            ));
        }
    }
    // the same input pose named once
    out.dedup_by(|b, a| a.pose == b.pose && a.message.reason == b.message.reason);
    out
}

/// Blocks the machine's axes slowed, and accelerations still beyond the limits.
/// The warnings of the blocks' timing: those slowed by the axes' limits (the slowest one's feed
/// at the tip and the feed asked for, per minute in the program's units), those that would need
/// more acceleration than an axis has. `feed` is in mm per minute.
fn motion_warnings(
    motion: &[BlockMotion],
    needs: &[BlockNeed],
    (feed, units): (f64, Units),
    lin: &Linearised,
    namer: &Namer,
    m: &Machine,
) -> Vec<Warning> {
    let mut out = Vec::new();
    let pose = |i: usize| lin.origin[i].floor() as usize;
    let slowed: Vec<usize> = (0..motion.len()).filter(|&i| motion[i].limit != Limit::Feed).collect();
    if let Some(&worst) = slowed.iter().min_by(|&&a, &&b| {
        let f = |i: usize| needs[i].distance / motion[i].minutes.max(1e-300);
        f(a).total_cmp(&f(b))
    }) {
        let tip = needs[worst].distance / motion[worst].minutes.max(1e-300) / units.mm();
        let axis = motion[worst].limit.axis().map_or("F".to_string(), |k| axis_letter(m, k).to_string());
        out.push(namer.warning(
            pose(worst),
            crate::msg!(
                "warn-slowed",
                count = slowed.len(),
                feed = (tip * 10.0).round() / 10.0,
                wanted = feed / units.mm(),
                units = units.word(),
                axis = axis,
                pose = pose(worst)
            ),
        ));
    }
    let over: Vec<usize> = (0..motion.len()).filter(|&i| motion[i].over).collect();
    if let Some(&first) = over.first() {
        out.push(namer.warning(pose(first), crate::msg!("warn-acceleration", count = over.len(), pose = pose(first))));
    }
    out
}

/// The letter of axis k of the five (X, Y, Z, then the rotary axes).
fn axis_letter(m: &Machine, k: usize) -> &'static str {
    match k {
        0 => "X",
        1 => "Y",
        2 => "Z",
        _ => m.rotary[k - 3].name.letter(),
    }
}

/// Poses whose tool axis the pole cone changed.
fn cone_warnings(lin: &Linearised, cone: f64, namer: &Namer) -> Vec<Warning> {
    let inside: Vec<usize> = (0..lin.poses.len()).filter(|&i| lin.in_cone[i]).collect();
    let Some(&first) = inside.first() else { return Vec::new() };
    let largest = lin.adjusted.iter().copied().fold(0.0, f64::max).to_degrees();
    vec![namer.warning(
        lin.origin[first].floor() as usize,
        crate::msg!(
            "warn-pole-cone",
            count = inside.len(),
            cone = cone,
            angle = (largest * 1e4).round() / 1e4,
            pose = lin.origin[first].floor() as usize
        ),
    )]
}

/// The shank or holder entering the stock along the cut: the first pose, how many, and how deep
/// the part reaches in (its radius less its axis's distance from the stock), in `units`.
fn tool_warnings(job: &Job, lin: &Linearised, units: Units, namer: &Namer) -> Vec<Warning> {
    let mut out = Vec::new();
    for part in ["shank", "holder"] {
        let hits: Vec<usize> = (0..lin.poses.len())
            .filter(|&i| job.shape.enters(lin.poses[i].tip, lin.poses[i].axis, &[part], &job.stock).is_some())
            .collect();
        if let Some(&first) = hits.first() {
            let pose = lin.origin[first].floor() as usize;
            let depth = hits
                .iter()
                .filter_map(|&i| job.shape.depth(lin.poses[i].tip, lin.poses[i].axis, part, &job.stock))
                .fold(0.0f64, f64::max);
            out.push(namer.warning(
                pose,
                crate::msg!(
                    "warn-tool-in-stock",
                    part = part,
                    pose = pose,
                    count = hits.len(),
                    depth = (depth / units.mm() * 1e4).round() / 1e4,
                    units = units.word()
                ),
            ));
        }
    }
    out
}

/// How far up `p`'s tool axis the tool must go for the whole cutter — not only its tip's line —
/// to be out of the stock, plus the clearance: from where the tip's line leaves the box, on by
/// half the cutter's radius until the cutter is clear, then halved down to 10⁻⁶ mm.
fn clear_out(job: &Job, p: &Pose) -> f64 {
    let out = |t: f64| job.shape.enters(p.tip + t * p.axis, p.axis, &["cutter"], &job.stock).is_none();
    let step = (0.5 * job.radius).max(0.01);
    let (mut inside, mut t) = (None, job.stock.exit(p.tip, p.axis));
    for _ in 0..RAISE_STEPS * 100 {
        if out(t) {
            break;
        }
        inside = Some(t);
        t += step;
    }
    if let Some(mut lo) = inside {
        while t - lo > 1e-6 {
            let mid = 0.5 * (lo + t);
            if out(mid) {
                t = mid;
            } else {
                lo = mid;
            }
        }
    }
    t + job.clearance
}

/// A safe point on a pose's tool axis: where the rapid down the axis turns (`point`, part
/// frame), its part height, and the clearance point outside the stock (`near`).
struct SafePoint {
    point: DVec3,
    near: DVec3,
    height: f64,
}

/// The point on `p`'s tool axis the safe moves turn at (module documentation): at least the
/// safe height, and raised until the vertical move from the top of Z to it and the rapid down
/// the axis from it are clear of the stock.
fn safe_point(m: &Machine, job: &Job, p: &Pose, rotary: [f64; 2], pose: usize) -> Result<SafePoint> {
    if p.axis.z < MIN_RETRACT_COS {
        return Err(Error::Unreachable { pose, line: None, message: crate::msg!("retract-horizontal", pose = pose) });
    }
    let t_near = clear_out(job, p);
    let near = p.tip + t_near * p.axis;
    let t_height = (job.safe_height - p.tip.z) / p.axis.z;
    let z_top = m.travel[2][1];
    let step = job.clearance.max(1.0);
    let mut t = t_height.max(t_near);
    // what kept the tool in the stock at the last point tried: the part (none: the travel)
    let mut blocking = "travel";
    for _ in 0..RAISE_STEPS {
        let point = p.tip + t * p.axis;
        let xyz = machine_position(m, point, rotary, job.gauge);
        if !within_travel(m, xyz) || xyz.z > z_top {
            break;
        }
        let top = DVec3::new(xyz.x, xyz.y, z_top);
        let all = ["cutter", "shank", "holder"];
        let descent = (0..=MOTION_SAMPLES).find_map(|k| {
            let q = forward_kinematics(
                m,
                &Joints { xyz: top.lerp(xyz, k as f64 / MOTION_SAMPLES as f64), rotary },
                job.gauge,
            );
            job.shape.enters(q.tip, q.axis, &all, &job.stock)
        });
        let down = (0..=MOTION_SAMPLES).find_map(|k| {
            job.shape.enters(point.lerp(near, k as f64 / MOTION_SAMPLES as f64), p.axis, &all, &job.stock)
        });
        match descent.or(down) {
            None => return Ok(SafePoint { point, near, height: point.z }),
            Some(part) => blocking = part,
        }
        t += step;
    }
    Err(Error::Unreachable { pose, line: None, message: crate::msg!("approach-blocked", pose = pose, part = blocking) })
}

fn within_travel(m: &Machine, xyz: DVec3) -> bool {
    (0..3).all(|k| (m.travel[k][0] - 1e-9..=m.travel[k][1] + 1e-9).contains(&xyz[k]))
}

/// The point above `point` at the top of Z, as the program writes it.
fn top_of(m: &Machine, o: &PostOptions, job: &Job, point: DVec3, rotary: [f64; 2], z_top: f64) -> Waypoint {
    let xyz = machine_position(m, point, rotary, job.gauge);
    let top = DVec3::new(xyz.x, xyz.y, z_top);
    let part = forward_kinematics(m, &Joints { xyz: top, rotary }, job.gauge);
    Waypoint { xyz: if o.mode == Mode::Tcp { part.tip } else { top }, rotary, axis: part.axis }
}

/// The rotary axes' home as the book documents it: a limited axis to 0 (its range holds no
/// multi-turn rapid; a range without 0, to its limit nearest 0), a continuous axis to the whole
/// turn nearest where it stands (no program ends with a multi-turn rapid).
fn home_of(m: &Machine, rotary: [f64; 2]) -> [f64; 2] {
    [0, 1].map(|k| {
        let r = &m.rotary[k];
        let home = if r.min.is_none() && r.max.is_none() {
            360.0 * (rotary[k] / 360.0).round()
        } else {
            0f64.clamp(r.min.unwrap_or(f64::NEG_INFINITY), r.max.unwrap_or(f64::INFINITY))
        };
        home + 0.0
    })
}

/// The steps of an unwinding at pose `i`: out along the tool axis to a point where the turn is
/// clear of the stock, the turn, and back (module documentation of `solve.rs`).
#[allow(clippy::too_many_arguments)]
fn unwind(
    m: &Machine,
    o: &PostOptions,
    orientation: Orientation,
    job: &Job,
    lin: &Linearised,
    i: usize,
    after: [f64; 2],
    namer: &Namer,
    pose: usize,
) -> Result<Vec<Op>> {
    let p = &lin.poses[i];
    let before = lin.joints[i].rotary;
    let t_near = clear_out(job, p);
    let near = p.tip + t_near * p.axis;
    let step = job.clearance.max(1.0);
    let all = ["cutter", "shank", "holder"];
    let mut t = t_near;
    let mut found = None;
    for _ in 0..RAISE_STEPS {
        let point = p.tip + t * p.axis;
        let xyz = machine_position(m, point, before, job.gauge);
        if !within_travel(m, xyz) {
            break;
        }
        // the turn: X Y Z held (machine mode, and a controller given the tool axis as a vector,
        // with its transformation off), or the tip held in the part (the others' tool-centre
        // point)
        let tip_held = o.mode == Mode::Tcp && orientation == Orientation::Angles;
        let clear = (0..=MOTION_SAMPLES).all(|k| {
            let s = k as f64 / MOTION_SAMPLES as f64;
            let r = [before[0] + s * (after[0] - before[0]), before[1] + s * (after[1] - before[1])];
            let (tip, axis) = if tip_held {
                (point, tool_axis(m, r))
            } else {
                let q = forward_kinematics(m, &Joints { xyz, rotary: r }, job.gauge);
                (q.tip, q.axis)
            };
            let travel = !tip_held || within_travel(m, machine_position(m, tip, r, job.gauge));
            travel && job.shape.enters(tip, axis, &all, &job.stock).is_none()
        });
        let up = (0..=MOTION_SAMPLES).all(|k| {
            job.shape.enters(near.lerp(point, k as f64 / MOTION_SAMPLES as f64), p.axis, &all, &job.stock).is_none()
        });
        if clear && up {
            found = Some(point);
            break;
        }
        t += step;
    }
    let Some(point) = found else {
        return Err(Error::Unreachable { pose, line: None, message: crate::msg!("unwind-blocked", pose = pose) });
    };
    let at = |q: DVec3, rotary: [f64; 2]| Waypoint {
        xyz: if o.mode == Mode::Tcp { q } else { machine_position(m, q, rotary, job.gauge) },
        rotary,
        axis: p.axis,
    };
    let k = (0..2).find(|&k| before[k] != after[k]).unwrap_or(0);
    let (named, _) = namer.at(pose);
    let mut ops = vec![
        Op::Comment(format!(
            "unwind {} at pose {named}: out along the tool axis, {} to {}, back",
            m.rotary[k].name.letter(),
            super::number(before[k], false),
            super::number(after[k], false)
        )),
        Op::Feed(at(near, before), Rate::PerMinute(job.approach)),
        Op::Rapid(at(point, before), Words::All),
    ];
    // a controller given the tool axis as a vector cannot be told a turn by whole turns
    let transformation_off = o.mode == Mode::Tcp && orientation == Orientation::Vector;
    if transformation_off {
        ops.push(Op::Tcp(false));
    }
    ops.push(Op::Rotate(after));
    if transformation_off {
        ops.push(Op::Tcp(true));
    }
    ops.extend([
        Op::Rapid(at(point, after), Words::All),
        Op::Rapid(at(near, after), Words::All),
        Op::Feed(at(p.tip, after), Rate::PerMinute(job.approach)),
    ]);
    Ok(ops)
}

/// An op with its lengths multiplied by `k` (millimetres to the program's units).
fn in_units(op: Op, k: f64) -> Op {
    if k == 1.0 {
        return op;
    }
    let t = |t: Waypoint| Waypoint { xyz: t.xyz * k, ..t };
    match op {
        Op::Rapid(x, w) => Op::Rapid(t(x), w),
        Op::Feed(x, Rate::PerMinute(f)) => Op::Feed(t(x), Rate::PerMinute(f * k)),
        Op::Feed(x, Rate::Simultaneous { minutes, distance, linear, turn }) => {
            Op::Feed(t(x), Rate::Simultaneous { minutes, distance: distance * k, linear: linear * k, turn })
        }
        Op::RetractTop(z) => Op::RetractTop(z * k),
        Op::Tolerance { chordal, angular } => Op::Tolerance { chordal: chordal * k, angular },
        other => other,
    }
}

#[cfg(test)]
mod tests;
