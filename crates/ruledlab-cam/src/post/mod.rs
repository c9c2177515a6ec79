//! The G-code post of Example 6's tool paths: a program a five-axis controller runs, for a
//! [`Machine`], in one of three dialects and two modes, for a job of given units, tool, feeds,
//! tolerances and stock.
//!
//! **Modes.** *Tool-centre point* (`Tcp`): the controller does the kinematics — `TRAORI` on
//! Sinumerik (the axis as a vector `A3= B3= C3=` in part coordinates), `FUNCTION TCPM` on
//! Heidenhain, a switchable kinematics on LinuxCNC switched to its tool-centre-point type with
//! `M68 E3 Q1` / `M66 E0 L0` (LinuxCNC 2.9 has no `G43.4`); X Y Z are the tip in part
//! coordinates (the work offset holds the part's zero) and the rotary axes their angles.
//! *Machine coordinates* (`Machine`): ruledlab does the kinematics with the machine's pivots and
//! offsets (`kinematics.rs`); X Y Z are the machine position of the tip with the work offset at
//! zero.
//!
//! **The program** (`plan.rs`). A header of comments (machine, mode and what it assumes of the
//! controller, units, tool, feeds, tolerances, stock, the linearisation's and the axes'
//! numbers, warnings); the frame of the dialect with its continuous-path mode and tolerance,
//! the work offset, the tool change with its length offset, the spindle; the **safe start**: the
//! spindle retracted to the top of Z in machine coordinates, the rotary axes turned there, X Y
//! at the top, Z down to a point on the first pose's tool axis clear of the stock, down the axis
//! to the clearance outside the stock, coolant on, the approach along the axis at the approach
//! feed. The cut: one block per pose of the linearised path (`linearise.rs`), each timed so that
//! the tip keeps the feed where the machine's axes allow it (`motion.rs`), with inverse-time
//! feed (`G93`) or the feed word the controller reads on blocks that turn a rotary axis; where a
//! limited rotary axis would leave its range it **unwinds** (out along the tool axis, turned by
//! whole turns, back). The **safe end**: out along the tool axis, up, coolant and spindle off,
//! the spindle to the top of Z, the rotary axes to their zero (a continuous axis to its nearest
//! whole turn: no program ends with a multi-turn rapid).

mod header;
pub mod heidenhain;
pub mod linuxcnc;
mod plan;
pub mod sinumerik;

pub use plan::plan_reporting;

use crate::kinematics::Joints;
use crate::linearise::{Linearisation, Linearised};
use crate::machine::Machine;
use crate::motion::BlockMotion;
use crate::tolerance::{GCODE_DECIMALS, MAX_MACHINE_VALUE, MIN_LINEARISATION_TOLERANCE};
use crate::{Pose, ToolPath};
use glam::DVec3;
use ruledlab::Message;
use ruledlab::{Error, Result};

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

/// The units of the program and of the job's lengths.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Units {
    /// Millimetres (`G21`, `MM`, `G71`).
    Mm,
    /// Inches (`G20`, `INCH`, `G70`): 25.4 mm.
    Inch,
}

impl Units {
    /// Millimetres per unit.
    pub fn mm(self) -> f64 {
        match self {
            Units::Mm => 1.0,
            Units::Inch => 25.4,
        }
    }

    /// "mm" or "inch".
    pub fn word(self) -> &'static str {
        match self {
            Units::Mm => "mm",
            Units::Inch => "inch",
        }
    }
}

/// The spindle's direction seen from the spindle towards the tool.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpindleDirection {
    /// Clockwise (`M3`).
    Clockwise,
    /// Counter-clockwise (`M4`).
    CounterClockwise,
}

/// A tool holder: a cylinder ending at the gauge line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Holder {
    /// Radius (program units).
    pub radius: f64,
    /// Length along the axis, down from the gauge line (program units).
    pub length: f64,
}

/// How the input the path was refined from numbers its poses: errors and warnings name the
/// input's pose and its line.
#[derive(Debug, Clone, PartialEq)]
pub struct Numbering {
    /// Poses of the path per pose of the input (2^steps of refinement; 1: the input itself).
    pub stride: usize,
    /// The 1-based line of each input pose in its file (empty: not read from a file).
    pub lines: Vec<usize>,
}

/// Options of the post. Lengths are in the program's `units` (feeds per minute); the path's
/// model units are multiplied by `scale`.
#[derive(Debug, Clone, PartialEq)]
pub struct PostOptions {
    /// The dialect (default LinuxCNC).
    pub dialect: Dialect,
    /// The mode (default machine coordinates).
    pub mode: Mode,
    /// The machine (default the preset `table-table-ac`).
    pub machine: Machine,
    /// The program's units (default millimetres); every length of these options is in them.
    pub units: Units,
    /// Feed at the tool tip, units/min (default 1000).
    pub feed: f64,
    /// Feed of the approach along the tool axis, units/min (default a quarter of the feed).
    pub approach_feed: Option<f64>,
    /// Units per model unit of the path (default 1).
    pub scale: f64,
    /// Tool number (default 1).
    pub tool: u32,
    /// Spindle speed, 1/min (default 10000).
    pub spindle: f64,
    /// The spindle's direction (default clockwise).
    pub direction: SpindleDirection,
    /// Coolant (default flood).
    pub coolant: Coolant,
    /// Work offset 1–6: G54–G59, Heidenhain's datum 1–6 (default 1).
    pub work_offset: u32,
    /// Least height above the part's zero (part Z) of the point on the tool axis where the safe
    /// moves turn (default 25 above the highest tip plus the clearance); the point is raised
    /// further where the stock, turned by the rotary axes, stands higher.
    pub safe_height: Option<f64>,
    /// Distance kept from the stock along the tool axis, covered at the approach feed
    /// (default 5 mm).
    pub clearance: f64,
    /// Largest deviation of the controller's interpolation from the path, the tip's and the
    /// axis's times the gauge length (default 0.01 mm): the chordal tolerance.
    pub tolerance: f64,
    /// Largest angle of the interpolated tool axis from the path's, degrees (default none).
    pub angular_tolerance: Option<f64>,
    /// The gauge length: spindle nose to the tip, the length the kinematics and the
    /// controller's length offset use (default the tool's length times the scale).
    pub gauge: Option<f64>,
    /// The holder (default none: not checked).
    pub holder: Option<Holder>,
    /// The shank's radius, from the cutter's length up to the holder (default the tool's).
    pub shank: Option<f64>,
    /// The stock, a box in the part frame: [min, max] corners (default the tips' box grown by
    /// 1 mm).
    pub stock: Option<[[f64; 3]; 2]>,
    /// Half-angle of the pole cone, degrees (default 1; 0: only the pole itself).
    pub pole_cone: f64,
    /// The numbering of the input the path was refined from (default: the path's own).
    pub numbering: Option<Numbering>,
    /// Program name, letters, digits and `_` (default "RULEDLAB").
    pub name: String,
}

impl Default for PostOptions {
    fn default() -> Self {
        PostOptions {
            dialect: Dialect::LinuxCnc,
            mode: Mode::Machine,
            machine: Machine::preset("table-table-ac").unwrap_or_else(|| unreachable!("a preset")),
            units: Units::Mm,
            feed: 1000.0,
            approach_feed: None,
            scale: 1.0,
            tool: 1,
            spindle: 10000.0,
            direction: SpindleDirection::Clockwise,
            coolant: Coolant::Flood,
            work_offset: 1,
            safe_height: None,
            clearance: 5.0,
            tolerance: 0.01,
            angular_tolerance: None,
            gauge: None,
            holder: None,
            shank: None,
            stock: None,
            pole_cone: 1.0,
            numbering: None,
            name: "RULEDLAB".to_string(),
        }
    }
}

/// Something the post did or found that the machinist should know, naming the pose (of the
/// input where the post knows its numbering).
#[derive(Debug, Clone, PartialEq)]
pub struct Warning {
    /// The pose.
    pub pose: usize,
    /// Its line in the input file, where known.
    pub line: Option<usize>,
    /// What, with a reason the page says in its language.
    pub message: Message,
}

impl Warning {
    /// In English, with its line where known ("… (line 7)").
    pub fn text(&self) -> String {
        header::warning_text(self)
    }
}

/// A program and what went into it.
#[derive(Debug, Clone, PartialEq)]
pub struct Program {
    /// The program text.
    pub text: String,
    /// The poses of the cut, part frame, mm: the path's and the inserted ones, in order (in the
    /// pole cone as written: the tool axis of the interpolated rotary values).
    pub poses: Vec<Pose>,
    /// Their axis values (machine frame).
    pub joints: Vec<Joints>,
    /// Where each pose lies on the given path (k + s between poses k and k + 1).
    pub origin: Vec<f64>,
    /// At a pose where a limited axis unwinds: its rotary values after unwinding.
    pub unwound: Vec<Option<[f64; 2]>>,
    /// Angle between each pose's given tool axis and the one written (the pole cone), radians.
    pub adjusted: Vec<f64>,
    /// Each block's motion: its time and what set it (one per block of the cut).
    pub motion: Vec<BlockMotion>,
    /// The linearisation check.
    pub linearisation: Linearisation,
    /// What the machinist should know.
    pub warnings: Vec<Warning>,
    /// The stock the rapids were checked against, part frame, mm.
    pub stock: [[f64; 3]; 2],
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
    /// A block that turns a rotary axis: it takes `minutes`; the tip's distance (the far end's
    /// for a still tip), the distance of X, Y, Z as written, and the rotary axes' turn (the
    /// length of the vector of their moves, degrees) for the dialects whose feed word refers
    /// to one of them.
    Simultaneous {
        /// The block's time, minutes.
        minutes: f64,
        /// The tip's distance.
        distance: f64,
        /// The distance of X, Y, Z as written.
        linear: f64,
        /// The rotary axes' turn, degrees.
        turn: f64,
    },
}

/// Which words a rapid writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Words {
    /// X and Y (machine mode; in TCP mode all).
    Xy,
    /// Z (machine mode; in TCP mode all).
    Z,
    /// X, Y, Z and the orientation.
    All,
}

/// One step of a program, written by each dialect in its own words.
#[derive(Debug, Clone, PartialEq)]
pub enum Op {
    /// A comment.
    Comment(String),
    /// The program's start: units, absolute coordinates, plane.
    Start,
    /// The controller's continuous-path mode with the chordal tolerance (program units) and
    /// the angular one (degrees).
    Tolerance {
        /// Chordal tolerance.
        chordal: f64,
        /// Tolerance of the tool axis, degrees.
        angular: f64,
    },
    /// The end of that mode (where a dialect has one).
    ToleranceOff,
    /// The work offset 1–6.
    WorkOffset(u32),
    /// Tool change with length offset, and the spindle on.
    ToolChange {
        /// Tool number.
        tool: u32,
        /// Spindle speed.
        spindle: f64,
        /// Its direction.
        direction: SpindleDirection,
    },
    /// Rapid to the top of Z in machine coordinates (or out along the tool axis to the limit).
    RetractTop(f64),
    /// Rapid of the rotary axes only.
    Rotate([f64; 2]),
    /// Tool-centre-point control on or off.
    Tcp(bool),
    /// Rapid move, with the words it writes.
    Rapid(Target, Words),
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
    /// The stock's box (part frame, program units): the blank for Heidenhain's BLK FORM.
    pub bounds: (DVec3, DVec3),
    /// The program's units.
    pub units: Units,
}

/// A number with [`GCODE_DECIMALS`] decimals ("-0.0000" written "0.0000"); `plus`: a sign always.
pub fn number(x: f64, plus: bool) -> String {
    decimals(x, GCODE_DECIMALS, plus)
}

/// A number with `places` decimals ("-0.000" written "0.000"); `plus`: a sign always. Rounded
/// as `format!` rounds (to the nearest, exactly): where x·10^places is not within 10⁻⁶ of a half
/// (so rounding it cannot fall the other way) from its integer, else by `format!` itself — a
/// program of a million blocks spends most of its time writing numbers.
pub fn decimals(x: f64, places: usize, plus: bool) -> String {
    let scale = 10f64.powi(places as i32);
    let y = x * scale;
    let s = if y.abs() < 1e9 && (y.fract().abs() - 0.5).abs() > 1e-6 {
        let r = y.round() as i64;
        let (whole, part) = (r.unsigned_abs() / scale as u64, r.unsigned_abs() % scale as u64);
        let sign = if r < 0 { "-" } else { "" };
        if places == 0 {
            format!("{sign}{whole}")
        } else {
            format!("{sign}{whole}.{part:0places$}")
        }
    } else {
        format!("{x:.places$}")
    };
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

/// A comment's text made safe for every dialect: printable ASCII without parentheses, braces
/// or `;` (square brackets stay: an INI section's name is written as LinuxCNC's INI file has it),
/// a degree sign written `deg`.
pub fn clean(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '(' | '{' => out.push('<'),
            ')' | '}' => out.push('>'),
            ';' => out.push(','),
            '°' => out.push_str(" deg"),
            c if c.is_ascii_graphic() || c == ' ' => out.push(c),
            _ => out.push(' '),
        }
    }
    out
}

/// The longest comment line a program writes (LinuxCNC's interpreter refuses lines of 256
/// characters and more: "Command too long").
pub const COMMENT_WIDTH: usize = 120;

/// A comment made safe ([`clean`]) and wrapped at spaces into lines of at most
/// [`COMMENT_WIDTH`] characters, the later ones indented by two spaces.
pub fn comment_lines(text: &str) -> Vec<String> {
    let text = clean(text);
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split(' ') {
        let room = COMMENT_WIDTH - if lines.is_empty() { 0 } else { 2 };
        if !line.is_empty() && line.len() + 1 + word.len() > room {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    lines.push(line);
    lines.into_iter().enumerate().map(|(k, l)| if k == 0 { l } else { format!("  {l}") }).collect()
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

/// The largest feed a Heidenhain TNC reads: its feed word has 5 places before the point and 3
/// after (the TNC user's manual, "Input format and unit of TNC functions": feed rates 0 to
/// 99 999.999 mm/min).
pub const HEIDENHAIN_MAX_FEED: f64 = 99_999.999;

/// Validates the options.
pub fn validate(o: &PostOptions) -> Result<()> {
    check("feed", o.feed, true)?;
    if let Some(f) = o.approach_feed {
        check("approachFeed", f, true)?;
    }
    if o.dialect == Dialect::Heidenhain {
        for (name, f) in [("feed", Some(o.feed)), ("approachFeed", o.approach_feed)] {
            if let Some(f) = f.filter(|&f| f > HEIDENHAIN_MAX_FEED) {
                return Err(Error::parameter(
                    name,
                    format!("must be at most {HEIDENHAIN_MAX_FEED} a minute for a Heidenhain TNC, got {f}"),
                ));
            }
        }
    }
    check("scale", o.scale, true)?;
    check("spindle", o.spindle, true)?;
    check("clearance", o.clearance, true)?;
    check("tolerance", o.tolerance, true)?;
    if o.tolerance * o.units.mm() < MIN_LINEARISATION_TOLERANCE {
        return Err(Error::parameter(
            "tolerance",
            format!(
                "must be at least {MIN_LINEARISATION_TOLERANCE} mm (the programs print 1e-4 mm), got {}",
                o.tolerance
            ),
        ));
    }
    if let Some(a) = o.angular_tolerance {
        check("angularTolerance", a, true)?;
    }
    if let Some(h) = o.safe_height {
        check("safeHeight", h, false)?;
    }
    if let Some(g) = o.gauge {
        check("gauge", g, true)?;
    }
    if let Some(h) = o.holder {
        check("holder.radius", h.radius, true)?;
        check("holder.length", h.length, true)?;
    }
    if let Some(s) = o.shank {
        check("shank", s, true)?;
    }
    if let Some([lo, hi]) = o.stock {
        for k in 0..3 {
            check("stock", lo[k], false)?;
            check("stock", hi[k], false)?;
            if lo[k] >= hi[k] {
                return Err(Error::parameter(
                    "stock",
                    format!("must be [min, max] corners with min < max, got {lo:?}, {hi:?}"),
                ));
            }
        }
    }
    if !(o.pole_cone.is_finite() && (0.0..=30.0).contains(&o.pole_cone)) {
        return Err(Error::parameter(
            "poleCone",
            format!("must be a number of degrees from 0 to 30, got {}", o.pole_cone),
        ));
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
    if let Some(nb) = &o.numbering {
        if nb.stride == 0 {
            return Err(Error::parameter("numbering", "the stride must be at least 1".to_string()));
        }
    }
    o.machine.validate()
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
    /// Each block's motion.
    pub motion: Vec<BlockMotion>,
    /// What the machinist should know.
    pub warnings: Vec<Warning>,
}

/// The G-code program of `path` (see the module documentation).
pub fn gcode(path: &ToolPath, o: &PostOptions) -> Result<Program> {
    gcode_reporting(path, o, &mut |_| {})
}

/// [`gcode`] telling `progress` how far it is (0 to 1), for a long job's progress bar.
pub fn gcode_reporting(path: &ToolPath, o: &PostOptions, progress: &mut dyn FnMut(f64)) -> Result<Program> {
    let Plan { ops, context, linearised: lin, motion, warnings } = plan_reporting(path, o, progress)?;
    let u = o.units.mm();
    let stock = [(context.bounds.0 * u).to_array(), (context.bounds.1 * u).to_array()];
    let text = match o.dialect {
        Dialect::LinuxCnc => linuxcnc::write(&ops, &context),
        Dialect::Heidenhain => heidenhain::write(&ops, &context),
        Dialect::Sinumerik => sinumerik::write(&ops, &context),
    };
    progress(1.0);
    Ok(Program {
        text,
        poses: lin.poses,
        joints: lin.joints,
        origin: lin.origin,
        unwound: lin.unwound,
        adjusted: lin.adjusted,
        motion,
        linearisation: lin.report,
        warnings,
        stock,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_and_comments() {
        assert_eq!(number(-0.00001, false), "0.0000");
        assert_eq!(number(1.5, true), "+1.5000");
        assert_eq!(number(-2.25, true), "-2.2500");
        assert_eq!(decimals(99_999.999_4, 3, false), "99999.999");
        // the fast way and format!'s agree, ties and near-ties included
        for x in [0.12345, -0.00005, 2.5e-5, 123456.78905, -7.0, 0.99995, 1e8 + 0.5, -3.24159265, 1.0000499999] {
            for places in [0, 3, 4] {
                let mut want = format!("{x:.places$}");
                if want.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') {
                    want = want.trim_start_matches('-').to_string();
                }
                assert_eq!(decimals(x, places, false), want, "{x} to {places}");
            }
        }
        assert_eq!(decimals(-0.0004, 3, true), "+0.000");
        assert_eq!(clean("a (b); [c] {d} é"), "a <b>, [c] <d>  ");
        assert_eq!(clean("within 1° of the pole"), "within 1 deg of the pole");
        let long = "word ".repeat(60);
        let lines = comment_lines(&long);
        assert!(lines.len() == 3 && lines.iter().all(|l| l.len() <= COMMENT_WIDTH), "{lines:?}");
        assert!(lines[1].starts_with("  word") && lines.concat().matches("word").count() == 60);
        assert_eq!((speed(10000.0), speed(12.5)), ("10000".to_string(), number(12.5, false)));
        assert_eq!((Units::Inch.mm(), Units::Mm.word()), (25.4, "mm"));
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
            ("angularTolerance", |o, x| o.angular_tolerance = Some(x)),
            ("gauge", |o, x| o.gauge = Some(x)),
            ("shank", |o, x| o.shank = Some(x)),
            ("holder.radius", |o, x| o.holder = Some(Holder { radius: x, length: 10.0 })),
            ("holder.length", |o, x| o.holder = Some(Holder { radius: 10.0, length: x })),
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
        // the tolerance from 1e-4 mm (in inches: from 1e-4 / 25.4)
        assert_eq!(option(PostOptions { tolerance: 1e-4, ..base() }), None);
        assert_eq!(option(PostOptions { tolerance: 0.99e-4, ..base() }).as_deref(), Some("tolerance"));
        assert_eq!(option(PostOptions { tolerance: 1e-5, units: Units::Inch, ..base() }), None);
        assert_eq!(option(PostOptions { tolerance: 3e-6, units: Units::Inch, ..base() }).as_deref(), Some("tolerance"));
        // the pole cone 0–30°, a stock with min < max
        for (cone, ok) in [(0.0, true), (30.0, true), (-0.1, false), (31.0, false), (f64::NAN, false)] {
            assert_eq!(option(PostOptions { pole_cone: cone, ..base() }).is_none(), ok, "cone {cone}");
        }
        assert_eq!(
            option(PostOptions { stock: Some([[0.0; 3], [1.0, 1.0, 0.0]]), ..base() }).as_deref(),
            Some("stock")
        );
        assert_eq!(option(PostOptions { stock: Some([[0.0; 3], [1.0; 3]]), ..base() }), None);
        // a Heidenhain feed word reads up to 99 999.999 mm/min
        let tnc = |feed: f64, units| PostOptions { dialect: Dialect::Heidenhain, feed, units, ..base() };
        assert_eq!(option(tnc(99_999.999, Units::Mm)), None);
        assert_eq!(option(tnc(100_000.0, Units::Mm)).as_deref(), Some("feed"));
        assert_eq!(option(tnc(100_000.0, Units::Inch)).as_deref(), Some("feed"));
        // tool 1–99999, work offset 1–6, a name of 1 to 24 letters, digits or _
        for (o, name) in [
            (PostOptions { tool: 0, ..base() }, "tool"),
            (PostOptions { tool: 100_000, ..base() }, "tool"),
            (PostOptions { work_offset: 0, ..base() }, "workOffset"),
            (PostOptions { work_offset: 7, ..base() }, "workOffset"),
            (PostOptions { name: String::new(), ..base() }, "name"),
            (PostOptions { name: "A".repeat(25), ..base() }, "name"),
            (PostOptions { name: "A B".into(), ..base() }, "name"),
            (PostOptions { numbering: Some(Numbering { stride: 0, lines: vec![] }), ..base() }, "numbering"),
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
}
