//! The G-code post of Example 6's tool paths: a program a five-axis controller runs, for a
//! [`Machine`], in one of three dialects and two modes.
//!
//! **Modes.** *Tool-centre point* (`Tcp`): the controller does the kinematics — `TRAORI` on
//! Sinumerik (the axis as a vector `A3= B3= C3=` in part coordinates), `FUNCTION TCPM` on
//! Heidenhain, a tool-centre-point kinematics on LinuxCNC (LinuxCNC 2.9 has no `G43.4`: its
//! interpreter rejects it, and TCP is a property of the configured kinematics, e.g.
//! `xyzac-trt-kins`); X Y Z are the tip in part coordinates (the work offset holds the part's
//! zero) and the rotary axes their angles. *Machine coordinates* (`Machine`): ruledlab does the
//! kinematics with the machine's pivots and offsets (`kinematics.rs`); X Y Z are the machine
//! position of the tip with the work offset at zero.
//!
//! **The program.** A header of comments (machine, mode, units, tool, the linearisation's
//! numbers), the frame of the dialect, the work offset, the tool change with its length offset,
//! the spindle; then the **safe start**: the spindle retracted to the top of Z in machine
//! coordinates, the rotary axes turned there to the first pose, a rapid move to the point on the
//! first pose's tool axis at the safe height, a rapid move down the axis to the clearance and the
//! approach along the axis at the approach feed, coolant on. The cut: one block per pose of the
//! linearised path (`linearise.rs`), with **inverse-time feed** (`G93`, F = feed / distance of
//! the tip, in 1/min) on every block that turns a rotary axis, so that the feed at the tool
//! tip is the one given; the **safe end**: out along the tool axis to the clearance and the safe
//! height, coolant and spindle off, the spindle to the top of Z, the rotary axes to 0, the end.

pub mod heidenhain;
pub mod linuxcnc;
pub mod sinumerik;

use crate::error::{Error, Result};
use crate::milling::kinematics::{check_travel, machine_position, Joints};
use crate::milling::linearise::{linearise, Interpolation, Linearisation, Linearised};
use crate::milling::machine::Machine;
use crate::milling::{Pose, ToolEnd, ToolPath};
use crate::tolerance::{GCODE_DECIMALS, MAX_MACHINE_VALUE, MIN_LINEARISATION_TOLERANCE, MIN_RETRACT_COS};
use glam::DVec3;

/// The controller's language.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dialect {
    /// LinuxCNC (rs274ngc): `( )` comments, no block numbers.
    LinuxCnc,
    /// Heidenhain TNC plain text (Klartext): `BEGIN PGM … MM`, numbered blocks, `;` comments.
    Heidenhain,
    /// Siemens Sinumerik 840D: `N10 …` blocks, `;` comments.
    Sinumerik,
}

/// Who does the kinematics.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// The controller (tool-centre-point control).
    Tcp,
    /// ruledlab: machine coordinates.
    Machine,
}

/// The coolant switched on for the cut.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Coolant {
    /// Flood (`M8`).
    Flood,
    /// Mist (`M7`).
    Mist,
    /// None.
    Off,
}

/// Options of the post.
#[derive(Debug, Clone, PartialEq)]
pub struct PostOptions {
    /// The dialect (default LinuxCNC).
    pub dialect: Dialect,
    /// The mode (default machine coordinates).
    pub mode: Mode,
    /// The machine (default the preset `table-table-ac`).
    pub machine: Machine,
    /// Feed at the tool tip, mm/min (default 1000).
    pub feed: f64,
    /// Feed of the approach along the tool axis, mm/min (default a quarter of the feed).
    pub approach_feed: Option<f64>,
    /// Millimetres per model unit (default 1).
    pub scale: f64,
    /// Tool number (default 1).
    pub tool: u32,
    /// Spindle speed, 1/min (default 10000).
    pub spindle: f64,
    /// Coolant (default flood).
    pub coolant: Coolant,
    /// Work offset 1–6: G54–G59, Heidenhain's datum 1–6 (default 1).
    pub work_offset: u32,
    /// Height above the part's zero (part Z, mm) of the point on the tool axis where the safe
    /// moves turn (default 25 mm above the highest tip plus the clearance).
    pub safe_height: Option<f64>,
    /// Distance along the tool axis from the tip over which the tool approaches and leaves at
    /// the approach feed, mm (default 5).
    pub clearance: f64,
    /// Largest deviation of the controller's interpolation from the path, mm (default 0.01).
    pub tolerance: f64,
    /// Program name, letters, digits and `_` (default "RULEDLAB").
    pub name: String,
}

impl Default for PostOptions {
    fn default() -> Self {
        PostOptions {
            dialect: Dialect::LinuxCnc,
            mode: Mode::Machine,
            machine: Machine::preset("table-table-ac").unwrap_or_else(|| unreachable!("a preset")),
            feed: 1000.0,
            approach_feed: None,
            scale: 1.0,
            tool: 1,
            spindle: 10000.0,
            coolant: Coolant::Flood,
            work_offset: 1,
            safe_height: None,
            clearance: 5.0,
            tolerance: 0.01,
            name: "RULEDLAB".to_string(),
        }
    }
}

/// A program and what went into it.
#[derive(Debug, Clone, PartialEq)]
pub struct Program {
    /// The program text.
    pub text: String,
    /// The poses of the cut, part frame, mm: the path's and the inserted ones, in order.
    pub poses: Vec<Pose>,
    /// Their axis values (machine frame).
    pub joints: Vec<Joints>,
    /// Where each pose lies on the given path (k + s between poses k and k + 1).
    pub origin: Vec<f64>,
    /// The linearisation check.
    pub linearisation: Linearisation,
}

/// Where a block goes: X Y Z as written (part frame in TCP mode, machine frame otherwise), the
/// rotary values, the tool axis in the part frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Target {
    /// X, Y, Z as written.
    pub xyz: DVec3,
    /// The rotary axes' values.
    pub rotary: [f64; 2],
    /// The tool axis, part frame.
    pub axis: DVec3,
}

/// The feed of a block.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Rate {
    /// Units per minute, no rotary axis moving (or TCP with the feed at the tip).
    PerMinute(f64),
    /// A block that turns a rotary axis: `feed` (mm/min at the tip) over `distance` (mm, the
    /// tip's), and the machine's linear axes' distance `linear` (mm).
    Simultaneous {
        /// mm/min at the tip.
        feed: f64,
        /// The tip's distance, mm.
        distance: f64,
        /// The distance of X, Y, Z as written, mm.
        linear: f64,
    },
}

impl Rate {
    /// Inverse time, 1/min: the block takes distance / feed minutes.
    pub fn inverse_time(feed: f64, distance: f64) -> f64 {
        feed / distance.max(1e-6)
    }
}

/// One step of a program, written by each dialect in its own words.
#[derive(Debug, Clone, PartialEq)]
pub enum Op {
    /// A comment.
    Comment(String),
    /// The program's start: units, absolute coordinates, plane.
    Start,
    /// The work offset 1–6.
    WorkOffset(u32),
    /// Tool change with length offset, and the spindle on.
    ToolChange {
        /// Tool number.
        tool: u32,
        /// Spindle speed.
        spindle: f64,
    },
    /// Rapid to the top of Z in machine coordinates.
    RetractTop(f64),
    /// Rapid of the rotary axes only.
    Rotate([f64; 2]),
    /// Tool-centre-point control on or off.
    Tcp(bool),
    /// Rapid move.
    Rapid(Target),
    /// Feed move.
    Feed(Target, Rate),
    /// Coolant on (the kind) or off.
    Coolant(Coolant),
    /// Spindle off.
    SpindleOff,
    /// Program end.
    End,
}

/// What a dialect needs to know besides the ops.
#[derive(Debug, Clone, PartialEq)]
pub struct Context {
    /// The rotary axes' letters.
    pub letters: [&'static str; 2],
    /// The mode.
    pub mode: Mode,
    /// The program's name.
    pub name: String,
    /// The tips' box (part frame, mm): the blank for Heidenhain's BLK FORM.
    pub bounds: (DVec3, DVec3),
}

/// A number with [`GCODE_DECIMALS`] decimals ("-0.0000" written "0.0000"); `plus`: a sign always.
pub fn number(x: f64, plus: bool) -> String {
    let s = format!("{x:.GCODE_DECIMALS$}");
    let s = if s.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') {
        s.trim_start_matches('-').to_string()
    } else {
        s
    };
    if plus && !s.starts_with('-') {
        format!("+{s}")
    } else {
        s
    }
}

/// A spindle speed: a whole number as one ("10000"), else with the program's decimals.
pub fn speed(x: f64) -> String {
    if x.fract() == 0.0 {
        format!("{x}")
    } else {
        number(x, false)
    }
}

/// A comment's text made safe for every dialect: printable ASCII without parentheses or `;`.
pub fn clean(text: &str) -> String {
    text.chars()
        .map(|c| match c {
            '(' | '[' | '{' => '<',
            ')' | ']' | '}' => '>',
            ';' => ',',
            c if c.is_ascii_graphic() || c == ' ' => c,
            _ => ' ',
        })
        .collect()
}

fn check(name: &'static str, value: f64, positive: bool) -> Result<()> {
    let ok = value.is_finite() && value.abs() <= MAX_MACHINE_VALUE && (!positive || value > 0.0);
    if ok {
        Ok(())
    } else if positive {
        Err(Error::parameter(name, format!("must be a positive number of at most 1e7, got {value}")))
    } else {
        Err(Error::parameter(name, format!("must be a finite number of at most 1e7, got {value}")))
    }
}

/// Validates the options.
pub fn validate(o: &PostOptions) -> Result<()> {
    check("feed", o.feed, true)?;
    if let Some(f) = o.approach_feed {
        check("approachFeed", f, true)?;
    }
    check("scale", o.scale, true)?;
    check("spindle", o.spindle, true)?;
    check("clearance", o.clearance, true)?;
    check("tolerance", o.tolerance, true)?;
    if o.tolerance < MIN_LINEARISATION_TOLERANCE {
        return Err(Error::parameter(
            "tolerance",
            format!(
                "must be at least {MIN_LINEARISATION_TOLERANCE} mm (the programs print 1e-4 mm), got {}",
                o.tolerance
            ),
        ));
    }
    if let Some(h) = o.safe_height {
        check("safeHeight", h, false)?;
    }
    if !(1..=99999).contains(&o.tool) {
        return Err(Error::parameter("tool", format!("must be an integer from 1 to 99999, got {}", o.tool)));
    }
    if !(1..=6).contains(&o.work_offset) {
        return Err(Error::parameter("workOffset", format!("must be an integer from 1 to 6, got {}", o.work_offset)));
    }
    let n = &o.name;
    if n.is_empty() || n.len() > 24 || !n.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Err(Error::parameter("name", format!("must be 1 to 24 letters, digits or _, got \"{n}\"")));
    }
    o.machine.validate()
}

/// The point on pose p's tool axis at part height `h`, as a pose (the tip moved there).
fn on_axis(p: &Pose, h: f64, index: usize) -> Result<Pose> {
    if p.axis.z < MIN_RETRACT_COS {
        return Err(Error::Unreachable { pose: index, message: crate::msg!("retract-horizontal", pose = index) });
    }
    Ok(Pose { tip: p.tip + ((h - p.tip.z) / p.axis.z) * p.axis, axis: p.axis })
}

/// A program before a dialect writes it: its steps, what the dialect needs besides, and the
/// linearised path they follow.
#[derive(Debug, Clone, PartialEq)]
pub struct Plan {
    /// The steps, in order.
    pub ops: Vec<Op>,
    /// What the dialect needs besides.
    pub context: Context,
    /// The poses of the cut and their axis values.
    pub linearised: Linearised,
}

/// The G-code program of `path` (see the module documentation).
pub fn gcode(path: &ToolPath, o: &PostOptions) -> Result<Program> {
    let Plan { ops, context, linearised: lin } = plan(path, o)?;
    let text = match o.dialect {
        Dialect::LinuxCnc => linuxcnc::write(&ops, &context),
        Dialect::Heidenhain => heidenhain::write(&ops, &context),
        Dialect::Sinumerik => sinumerik::write(&ops, &context),
    };
    Ok(Program { text, poses: lin.poses, joints: lin.joints, origin: lin.origin, linearisation: lin.report })
}

/// The steps of `path`'s program, in no dialect yet (see the module documentation).
pub fn plan(path: &ToolPath, o: &PostOptions) -> Result<Plan> {
    validate(o)?;
    let m = &o.machine;
    let length = path.tool.length * o.scale;
    let poses: Vec<Pose> = path.poses.iter().map(|p| Pose { tip: o.scale * p.tip, axis: p.axis.normalize() }).collect();
    let top = poses.iter().map(|p| p.tip.z).fold(f64::NEG_INFINITY, f64::max);
    let safe = o.safe_height.unwrap_or(top + o.clearance + 25.0);
    if safe < top + o.clearance {
        return Err(Error::parameter(
            "safeHeight",
            format!(
                "must be at least the highest tip plus the clearance, {} mm, got {safe}",
                number(top + o.clearance, false)
            ),
        ));
    }
    let how = match (o.mode, o.dialect) {
        (Mode::Machine, _) => Interpolation::Machine,
        (Mode::Tcp, Dialect::Sinumerik) => Interpolation::TcpVector,
        (Mode::Tcp, _) => Interpolation::TcpAngles,
    };
    let lin = linearise(m, &poses, length, how, o.tolerance)?;
    let target = |p: &Pose, j: &Joints| Target {
        xyz: if o.mode == Mode::Tcp { p.tip } else { j.xyz },
        rotary: j.rotary,
        axis: p.axis,
    };
    let n = lin.poses.len();
    let (first, last) = (&lin.poses[0], &lin.poses[n - 1]);
    let (j0, jn) = (lin.joints[0], lin.joints[n - 1]);
    // the safe moves' points on the first and last tool axes, checked against the travel
    let at = |p: &Pose, j: &Joints, index: usize| -> Result<Target> {
        let xyz = machine_position(m, p.tip, j.rotary, length);
        check_travel(m, index, xyz)?;
        Ok(target(p, &Joints { xyz, rotary: j.rotary }))
    };
    let start_safe = at(&on_axis(first, safe, 0)?, &j0, 0)?;
    let start_near = at(&Pose { tip: first.tip + o.clearance * first.axis, axis: first.axis }, &j0, 0)?;
    let end_near = at(&Pose { tip: last.tip + o.clearance * last.axis, axis: last.axis }, &jn, path.poses.len() - 1)?;
    let end_safe = at(&on_axis(last, safe, path.poses.len() - 1)?, &jn, path.poses.len() - 1)?;
    let z_top = m.travel[2][1];
    let approach = o.approach_feed.unwrap_or(o.feed / 4.0);

    let mut ops = header(path, o, &lin.report, n, safe, approach);
    ops.extend([
        Op::Start,
        Op::WorkOffset(o.work_offset),
        Op::ToolChange { tool: o.tool, spindle: o.spindle },
        Op::Comment("safe start: spindle to the top of Z, rotary axes turned there".into()),
        Op::RetractTop(z_top),
        Op::Rotate(j0.rotary),
    ]);
    if o.mode == Mode::Tcp {
        ops.push(Op::Tcp(true));
    }
    ops.extend([
        Op::Comment("over the first pose on its tool axis at the safe height, down the axis".into()),
        Op::Rapid(start_safe),
        Op::Rapid(start_near),
        Op::Coolant(o.coolant),
        Op::Feed(target(first, &j0), Rate::PerMinute(approach)),
        Op::Comment("cut".into()),
    ]);
    let digits = 10f64.powi(GCODE_DECIMALS as i32);
    let rounded = |v: f64| (v * digits).round();
    for i in 1..n {
        let (a, b) = (&lin.poses[i - 1], &lin.poses[i]);
        let (ja, jb) = (&lin.joints[i - 1], &lin.joints[i]);
        let (ta, tb) = (target(a, ja), target(b, jb));
        let turns = (0..2).any(|k| rounded(ja.rotary[k]) != rounded(jb.rotary[k]));
        let rate = if turns {
            // a block with a still tip: the far end of the tool sets the time
            let tip = (b.tip - a.tip).length();
            let distance = if tip > 1e-3 { tip } else { tip.max(length * a.axis.angle_between(b.axis)) };
            Rate::Simultaneous { feed: o.feed, distance, linear: (tb.xyz - ta.xyz).length() }
        } else {
            Rate::PerMinute(o.feed)
        };
        ops.push(Op::Feed(tb, rate));
    }
    ops.extend([
        Op::Comment("end of cut".into()),
        Op::Comment("safe end: out along the tool axis, spindle to the top of Z, rotary axes to 0".into()),
        Op::Feed(end_near, Rate::PerMinute(approach)),
        Op::Rapid(end_safe),
        Op::Coolant(Coolant::Off),
        Op::SpindleOff,
    ]);
    if o.mode == Mode::Tcp {
        ops.push(Op::Tcp(false));
    }
    ops.extend([Op::RetractTop(z_top), Op::Rotate([0.0, 0.0]), Op::End]);

    let lo = lin.poses.iter().fold(DVec3::splat(f64::INFINITY), |b, p| b.min(p.tip));
    let hi = lin.poses.iter().fold(DVec3::splat(f64::NEG_INFINITY), |b, p| b.max(p.tip));
    let context = Context {
        letters: [m.rotary[0].name.letter(), m.rotary[1].name.letter()],
        mode: o.mode,
        name: o.name.clone(),
        bounds: (lo, hi),
    };
    Ok(Plan { ops, context, linearised: lin })
}

fn header(path: &ToolPath, o: &PostOptions, l: &Linearisation, n: usize, safe: f64, approach: f64) -> Vec<Op> {
    let end = match path.tool.end {
        ToolEnd::Ball => "ball end",
        ToolEnd::Flat => "flat end",
    };
    let mode = match (o.mode, o.dialect) {
        (Mode::Machine, _) => {
            "mode: machine coordinates - X Y Z are the machine position of the tip, the work offset must be 0"
        }
        (Mode::Tcp, Dialect::LinuxCnc) => {
            "mode: tool-centre point - X Y Z the tip in part coordinates, needs a TCP kinematics (xyzac-trt-kins or alike), LinuxCNC 2.9 has no G43.4"
        }
        (Mode::Tcp, Dialect::Heidenhain) => "mode: tool-centre point - FUNCTION TCPM, X Y Z the tip in part coordinates",
        (Mode::Tcp, Dialect::Sinumerik) => {
            "mode: tool-centre point - TRAORI, X Y Z the tip and A3 B3 C3 the tool axis in part coordinates"
        }
    };
    let mm = |x: f64| number(x, false);
    let feed = match (o.dialect, o.mode) {
        (Dialect::Heidenhain, Mode::Tcp) => "F at the tip with FUNCTION TCPM F TCP".to_string(),
        (Dialect::Heidenhain, Mode::Machine) => {
            "rotary moves get the F of X Y Z that keeps the feed at the tip".to_string()
        }
        _ => "inverse time G93 on rotary moves".to_string(),
    };
    [
        format!("ruledlab tool path: {n} poses, {} of the path and {} inserted", n - l.inserted, l.inserted),
        format!("machine {}", o.machine.describe()),
        mode.to_string(),
        format!(
            "units mm, {} mm per model unit, feed {} mm/min at the tip, {feed}, approach {} mm/min",
            o.scale, o.feed, approach
        ),
        format!("tool {}: {end}, radius {} mm, length {} mm", o.tool, mm(path.tool.radius * o.scale), mm(path.tool.length * o.scale)),
        format!("safe height {} mm above the part zero, clearance {} mm along the tool axis", mm(safe), mm(o.clearance)),
        format!(
            "linearisation: tolerance {} mm, largest deviation tip {} mm axis {} mm, before inserting tip {} mm axis {} mm",
            mm(l.tolerance),
            mm(l.after.tip),
            mm(l.after.axis),
            mm(l.before.tip),
            mm(l.before.axis)
        ),
    ]
    .into_iter()
    .map(Op::Comment)
    .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_and_comments() {
        assert_eq!(number(-0.00001, false), "0.0000");
        assert_eq!(number(1.5, true), "+1.5000");
        assert_eq!(number(-2.25, true), "-2.2500");
        assert_eq!(clean("a (b); [c] é"), "a <b>, <c>  ");
    }

    #[test]
    fn options_are_refused_by_name_at_their_bounds() {
        let option = |o: PostOptions| validate(&o).err().and_then(|e| e.details().option);
        let base = PostOptions::default;
        assert_eq!(option(base()), None);
        // positive numbers of at most 1e7
        for (name, set) in [
            ("feed", (|o: &mut PostOptions, x| o.feed = x) as fn(&mut PostOptions, f64)),
            ("approachFeed", |o, x| o.approach_feed = Some(x)),
            ("scale", |o, x| o.scale = x),
            ("spindle", |o, x| o.spindle = x),
            ("clearance", |o, x| o.clearance = x),
        ] {
            for bad in [0.0, -1.0, 1e7 * (1.0 + 1e-15), f64::NAN, f64::INFINITY] {
                let mut o = base();
                set(&mut o, bad);
                assert_eq!(option(o).as_deref(), Some(name), "{name} = {bad}");
            }
            let mut o = base();
            set(&mut o, 1e7);
            assert_eq!(option(o), None, "{name} = 1e7");
        }
        // the safe height may be zero or negative, not beyond 1e7
        for (h, ok) in [(0.0, true), (-20.0, true), (-1e7, true), (-2e7, false), (f64::NAN, false)] {
            assert_eq!(option(PostOptions { safe_height: Some(h), ..base() }).is_none(), ok, "safe height {h}");
        }
        // the tolerance from 1e-4 mm
        assert_eq!(option(PostOptions { tolerance: 1e-4, ..base() }), None);
        assert_eq!(option(PostOptions { tolerance: 0.99e-4, ..base() }).as_deref(), Some("tolerance"));
        // tool 1–99999, work offset 1–6, a name of 1 to 24 letters, digits or _
        for (o, name) in [
            (PostOptions { tool: 0, ..base() }, "tool"),
            (PostOptions { tool: 100_000, ..base() }, "tool"),
            (PostOptions { work_offset: 0, ..base() }, "workOffset"),
            (PostOptions { work_offset: 7, ..base() }, "workOffset"),
            (PostOptions { name: String::new(), ..base() }, "name"),
            (PostOptions { name: "A".repeat(25), ..base() }, "name"),
            (PostOptions { name: "A B".into(), ..base() }, "name"),
        ] {
            assert_eq!(option(o).as_deref(), Some(name));
        }
        for o in [
            PostOptions { tool: 99_999, work_offset: 6, name: "Z_9".repeat(8), ..base() },
            PostOptions { tool: 1, work_offset: 1, name: "a".into(), ..base() },
        ] {
            assert_eq!(option(o), None);
        }
    }

    #[test]
    fn retracts_follow_the_axis_and_spindles_print_whole_numbers_whole() {
        // up the axis (0.6, 0, 0.8) from (1, 2, 3) to height 7: 4 = 0.8·5, so 5 along it
        let p = Pose { tip: DVec3::new(1.0, 2.0, 3.0), axis: DVec3::new(0.6, 0.0, 0.8) };
        assert_eq!(on_axis(&p, 7.0, 0).unwrap().tip, DVec3::new(4.0, 2.0, 7.0));
        // an axis below 0.1 from the horizontal has no retract: named by its pose
        let flat = Pose { axis: DVec3::new(0.995, 0.0, 0.0999), ..p };
        assert_eq!(on_axis(&flat, 7.0, 3).unwrap_err().details().index, Some(3));
        assert!(on_axis(&Pose { axis: DVec3::new(0.995, 0.0, 0.1), ..p }, 7.0, 3).is_ok());
        assert_eq!((speed(10000.0), speed(12.5)), ("10000".to_string(), number(12.5, false)));
        // inverse time: a block of 2 mm at 100 mm/min takes 0.02 min, F 50; a zero block is 1e-6
        assert_eq!(Rate::inverse_time(100.0, 2.0), 50.0);
        assert_eq!(Rate::inverse_time(100.0, 0.0), 1e8);
    }

    /// A path on table-table-ac with every kind of block, scale 2, tool length 25 (50 mm): the
    /// tool axis (0, 0.6, 0.8) is A = atan(3/4) = 36.87°, (0, 0.8, 0.6) is 53.13°, C stays 0;
    /// the A-only turns keep the axis on a great circle, so with the angles interpolated (tool-
    /// centre point) nothing is inserted.
    fn path() -> ToolPath {
        let deg = std::f64::consts::PI / 180.0;
        let pose = |x: f64, a: DVec3| Pose { tip: DVec3::new(x, 0.0, 0.0), axis: a };
        let (up, over) = (DVec3::new(0.0, 0.6, 0.8), DVec3::new(0.0, 0.8, 0.6));
        let small = DVec3::new(0.0, (37.17 * deg).sin(), (37.17 * deg).cos());
        ToolPath {
            poses: vec![
                pose(0.0, up),
                pose(0.0, over),
                pose(1.0, up),
                pose(6.0, small),
                pose(11.0, up),
                pose(12.0, up),
            ],
            tool: crate::milling::Tool { radius: 3.0, length: 25.0, end: ToolEnd::Ball },
        }
    }

    fn motions(ops: &[Op]) -> Vec<Op> {
        ops.iter().filter(|op| !matches!(op, Op::Comment(_))).cloned().collect()
    }

    fn near(a: DVec3, b: DVec3) -> bool {
        (a - b).length() < 1e-12
    }

    /// Tool-centre point: X Y Z are the tips in part coordinates. The safe height is 25 mm above
    /// the highest tip (z = 0) plus the clearance 5: 30; the first axis reaches it at
    /// 30/0.8 = 37.5 mm from the tip, (0, 22.5, 30), and the clearance at 5 mm, (0, 3, 4). The
    /// approach runs at a quarter of the feed. A block that turns a rotary axis is timed by the
    /// tip's distance (10 mm), or, with the tip still, by the tool's far end: 50 mm × the turn,
    /// acos 0.96 = 0.28379 rad; a turn of 0.3° (above the program's 1e-4°) counts.
    #[test]
    fn a_tcp_program_takes_its_points_on_the_tool_axes_and_times_its_turns() {
        let o = PostOptions { scale: 2.0, mode: Mode::Tcp, ..PostOptions::default() };
        let p = plan(&path(), &o).unwrap();
        let (a0, a1, a2) = (36.86989764584402, 53.13010235415599, 37.17);
        let (up, over) = (DVec3::new(0.0, 0.6, 0.8), DVec3::new(0.0, 0.8, 0.6));
        let small = path().poses[3].axis;
        let at = |x: f64, y: f64, z: f64, a: f64| Target { xyz: DVec3::new(x, y, z), rotary: [a, 0.0], axis: up };
        let ops = motions(&p.ops);
        let expected = [
            Op::Start,
            Op::WorkOffset(1),
            Op::ToolChange { tool: 1, spindle: 10000.0 },
            Op::RetractTop(400.0),
            Op::Rotate([a0, 0.0]),
            Op::Tcp(true),
            Op::Rapid(at(0.0, 22.5, 30.0, a0)),
            Op::Rapid(at(0.0, 3.0, 4.0, a0)),
            Op::Coolant(Coolant::Flood),
            Op::Feed(at(0.0, 0.0, 0.0, a0), Rate::PerMinute(250.0)),
            Op::Feed(
                Target { axis: over, ..at(0.0, 0.0, 0.0, a1) },
                Rate::Simultaneous { feed: 1000.0, distance: 50.0 * 0.96f64.acos(), linear: 0.0 },
            ),
            Op::Feed(at(2.0, 0.0, 0.0, a0), Rate::Simultaneous { feed: 1000.0, distance: 2.0, linear: 2.0 }),
            Op::Feed(
                Target { axis: small, ..at(12.0, 0.0, 0.0, a2) },
                Rate::Simultaneous { feed: 1000.0, distance: 10.0, linear: 10.0 },
            ),
            Op::Feed(at(22.0, 0.0, 0.0, a0), Rate::Simultaneous { feed: 1000.0, distance: 10.0, linear: 10.0 }),
            Op::Feed(at(24.0, 0.0, 0.0, a0), Rate::PerMinute(1000.0)),
            Op::Feed(at(24.0, 3.0, 4.0, a0), Rate::PerMinute(250.0)),
            Op::Rapid(at(24.0, 22.5, 30.0, a0)),
            Op::Coolant(Coolant::Off),
            Op::SpindleOff,
            Op::Tcp(false),
            Op::RetractTop(400.0),
            Op::Rotate([0.0, 0.0]),
            Op::End,
        ];
        assert_eq!(ops.len(), expected.len(), "{ops:#?}");
        for (k, (got, want)) in ops.iter().zip(&expected).enumerate() {
            let same = match (got, want) {
                (Op::Rapid(g), Op::Rapid(w)) => near(g.xyz, w.xyz) && near(g.axis, w.axis) && near_rotary(g, w),
                (Op::Feed(g, gr), Op::Feed(w, wr)) => {
                    near(g.xyz, w.xyz) && near(g.axis, w.axis) && near_rotary(g, w) && near_rate(gr, wr)
                }
                (Op::Rotate(g), Op::Rotate(w)) => (g[0] - w[0]).abs() < 1e-9 && g[1] == w[1],
                _ => got == want,
            };
            assert!(same, "op {k}: {got:?}, expected {want:?}");
        }
        // the header: six poses, none inserted; the part's box
        assert!(p.ops.contains(&Op::Comment("ruledlab tool path: 6 poses, 6 of the path and 0 inserted".into())));
        assert!(p.ops.contains(&Op::Comment(
            "safe height 30.0000 mm above the part zero, clearance 5.0000 mm along the tool axis".into()
        )));
        assert_eq!(p.context.bounds, (DVec3::ZERO, DVec3::new(24.0, 0.0, 0.0)));
        assert_eq!((p.context.letters, p.context.mode), (["A", "C"], Mode::Tcp));
    }

    fn near_rotary(g: &Target, w: &Target) -> bool {
        (g.rotary[0] - w.rotary[0]).abs() < 1e-9 && g.rotary[1] == w.rotary[1]
    }

    fn near_rate(g: &Rate, w: &Rate) -> bool {
        match (g, w) {
            (Rate::PerMinute(a), Rate::PerMinute(b)) => a == b,
            (
                Rate::Simultaneous { feed: f, distance: d, linear: l },
                Rate::Simultaneous { feed: g, distance: e, linear: m },
            ) => f == g && (d - e).abs() < 1e-12 && (l - m).abs() < 1e-12,
            _ => false,
        }
    }

    /// Machine coordinates: the table tilts the axis (0, 0.6, 0.8) back to +Z, turning
    /// (y, z) to (0.8y − 0.6z, 0.6y + 0.8z) about A's pivot z = −80, after the part's zero
    /// (10, −5, 25) is added: the tip (0, 0, 0) is at (10, −67, 1), the clearance point (0, 3, 4) at
    /// (10, −67, 6), the safe point (0, 22.5, 30) at (10, −67, 38.5); the last tip (24, 0, 0)
    /// 24 further along X. No TCP switch; the still tip's turn is cut into blocks.
    #[test]
    fn a_machine_program_writes_machine_positions() {
        let p = plan(&path(), &PostOptions { scale: 2.0, ..PostOptions::default() }).unwrap();
        let ops = motions(&p.ops);
        assert!(!ops.iter().any(|op| matches!(op, Op::Tcp(_))));
        let xyz = |op: &Op| match op {
            Op::Rapid(t) | Op::Feed(t, _) => t.xyz,
            other => panic!("{other:?}"),
        };
        let v = DVec3::new;
        let n = ops.len();
        for (k, want) in [(5, v(10.0, -67.0, 38.5)), (6, v(10.0, -67.0, 6.0)), (8, v(10.0, -67.0, 1.0))] {
            assert!(near(xyz(&ops[k]), want), "op {k}: {:?}", ops[k]);
        }
        for (k, want) in [(n - 8, v(34.0, -67.0, 1.0)), (n - 7, v(34.0, -67.0, 6.0)), (n - 6, v(34.0, -67.0, 38.5))] {
            assert!(near(xyz(&ops[k]), want), "op {k}: {:?}", ops[k]);
        }
        let cut = p.linearised.poses.len();
        assert!(cut > 6, "the still tip's turn is cut");
        let header = format!("ruledlab tool path: {cut} poses, 6 of the path and {} inserted", cut - 6);
        assert!(p.ops.contains(&Op::Comment(header)));
    }

    /// The safe height may be the highest tip plus the clearance (5 mm here), not below.
    #[test]
    fn the_safe_height_clears_the_highest_tip_by_the_clearance() {
        let o = |h: f64| PostOptions { scale: 2.0, mode: Mode::Tcp, safe_height: Some(h), ..PostOptions::default() };
        let e = plan(&path(), &o(4.999)).unwrap_err();
        assert_eq!(e.details().option.as_deref(), Some("safeHeight"));
        let p = plan(&path(), &o(5.0)).unwrap();
        let Op::Rapid(t) = motions(&p.ops)[6] else { panic!() };
        assert!(near(t.xyz, DVec3::new(0.0, 3.75, 5.0)), "{t:?}");
    }

    /// Each dialect says how its rotary moves are fed.
    #[test]
    fn the_header_says_how_rotary_moves_are_fed() {
        for (dialect, mode, says) in [
            (Dialect::Heidenhain, Mode::Tcp, "F at the tip with FUNCTION TCPM F TCP"),
            (Dialect::Heidenhain, Mode::Machine, "rotary moves get the F of X Y Z that keeps the feed at the tip"),
            (Dialect::LinuxCnc, Mode::Machine, "inverse time G93 on rotary moves"),
            (Dialect::Sinumerik, Mode::Tcp, "inverse time G93 on rotary moves"),
        ] {
            let p = plan(&path(), &PostOptions { dialect, mode, ..PostOptions::default() }).unwrap();
            let line =
                format!("units mm, 1 mm per model unit, feed 1000 mm/min at the tip, {says}, approach 250 mm/min");
            assert!(p.ops.contains(&Op::Comment(line)), "{dialect:?} {mode:?}: {:?}", p.ops[3]);
        }
    }

    /// The safe moves at the end are checked against the travel (and the retract's slope) and
    /// named by the last pose of the given path. Table-table-ac turns the axis (0, 0.6, 0.8) to
    /// +Z, (y, z) ↦ (0.8y − 0.6z, 0.6y + 0.8z) about z = −80 after adding the part zero
    /// (10, −5, 25), so a point of part height z on that axis through a tip (x, 0, 0) is at
    /// machine Z 1 + 1.25z, and the tip (0, 500, 120) at Z 397, its clearance point 5 mm up
    /// the axis at 402, over the travel's 400. The first pose stands upright (machine Z is part
    /// Z + 25): its own safe moves stay within the travel.
    #[test]
    fn the_safe_moves_at_the_end_are_named_by_the_last_pose() {
        let tool = crate::milling::Tool { radius: 3.0, length: 25.0, end: ToolEnd::Ball };
        let path = |last: Pose| ToolPath {
            poses: vec![
                Pose { tip: DVec3::ZERO, axis: DVec3::Z },
                Pose { tip: DVec3::new(10.0, 0.0, 0.0), ..last },
                last,
            ],
            tool,
        };
        let tilted = DVec3::new(0.0, 0.6, 0.8);
        let o = |h: Option<f64>| PostOptions { mode: Mode::Tcp, safe_height: h, ..PostOptions::default() };
        let pose_of = |p: &ToolPath, o: &PostOptions| plan(p, o).unwrap_err().details().index;
        // the safe point at height 350: Z 438.5 at the end, 375 at the start
        let end_safe = path(Pose { tip: DVec3::new(20.0, 0.0, 0.0), axis: tilted });
        assert_eq!(pose_of(&end_safe, &o(Some(350.0))), Some(2));
        assert!(plan(&end_safe, &o(Some(319.0))).is_ok(), "Z 399.75");
        // the clearance point: Z 402
        let end_near = path(Pose { tip: DVec3::new(0.0, 500.0, 120.0), axis: tilted });
        assert_eq!(pose_of(&end_near, &o(None)), Some(2));
        // an axis within 0.1 of the horizontal has no way up
        let flat = path(Pose { tip: DVec3::new(20.0, 0.0, 0.0), axis: DVec3::new(0.0, 0.9959, 0.09).normalize() });
        let Err(Error::Unreachable { pose, message }) = plan(&flat, &o(None)) else { panic!("reachable") };
        assert_eq!((pose, message.reason), (2, "retract-horizontal"));
    }

    /// A turning block whose tip moves 1e-3 mm exactly is timed by the tool's far end: with the
    /// tool of 25 mm and the turn acos 0.96, 25 × 0.28379 = 7.09 mm, not the tip's 0.001 mm.
    #[test]
    fn a_turn_with_the_tip_moving_a_thousandth_is_timed_by_the_far_end() {
        let path = ToolPath {
            poses: vec![
                Pose { tip: DVec3::ZERO, axis: DVec3::new(0.0, 0.6, 0.8) },
                Pose { tip: DVec3::new(1e-3, 0.0, 0.0), axis: DVec3::new(0.0, 0.8, 0.6) },
            ],
            tool: crate::milling::Tool { radius: 3.0, length: 25.0, end: ToolEnd::Ball },
        };
        let p = plan(&path, &PostOptions { mode: Mode::Tcp, ..PostOptions::default() }).unwrap();
        let rates: Vec<Rate> = p
            .ops
            .iter()
            .filter_map(|op| match op {
                Op::Feed(_, r @ Rate::Simultaneous { .. }) => Some(*r),
                _ => None,
            })
            .collect();
        let [Rate::Simultaneous { distance, .. }] = rates[..] else { panic!("one turning block: {rates:?}") };
        assert!((distance - 25.0 * 0.96f64.acos()).abs() < 1e-12, "{distance}");
    }
}
