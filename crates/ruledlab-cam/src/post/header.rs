//! The header of a program: comments that say what the program assumes and what went into it
//! (machine, mode and the controller's setup it needs, units, tool, feeds, tolerances, stock,
//! the linearisation's and the axes' numbers, warnings), in the program's units.

use super::{number, Dialect, Mode, Op, PostOptions, SpindleDirection, Warning};
use crate::linearise::Linearisation;
use crate::machine::{AxisName, Carrier, Machine};
use crate::motion::{BlockMotion, Limit};
use crate::stock::Aabb;
use crate::{ToolEnd, ToolPath};

/// What the plan found, for the header (lengths in mm).
pub(super) struct HeaderFacts<'a> {
    pub poses: usize,
    pub job_feed: f64,
    pub approach: f64,
    pub safe: f64,
    pub stock: Aabb,
    pub stock_given: bool,
    pub radius: f64,
    pub cutter: f64,
    pub gauge: f64,
    pub motion: &'a [BlockMotion],
    pub unwinds: usize,
    pub warnings: &'a [Warning],
}

/// The LinuxCNC 2.9 kinematics module that is this machine's tool-centre point, if one is:
/// `xyzac-trt-kins` and `xyzbc-trt-kins` for a tilting table (A or B) carrying a rotary table
/// (C), `5axiskins` for a bridge mill's head (C carrying B). LinuxCNC's "Switchable Kinematics"
/// chapter lists these as switchable; its man page kins(9) describes them.
pub fn linuxcnc_kinematics(m: &Machine) -> Option<&'static str> {
    let [a, b] = &m.rotary;
    match ((a.on, a.name), (b.on, b.name)) {
        ((Carrier::Table, AxisName::A), (Carrier::Table, AxisName::C)) => Some("xyzac-trt-kins"),
        ((Carrier::Table, AxisName::B), (Carrier::Table, AxisName::C)) => Some("xyzbc-trt-kins"),
        ((Carrier::Head, AxisName::C), (Carrier::Head, AxisName::B)) => Some("5axiskins"),
        _ => None,
    }
}

/// The header's comment lines.
pub(super) fn header(path: &ToolPath, o: &PostOptions, l: &Linearisation, f: &HeaderFacts) -> Vec<Op> {
    let u = o.units.mm();
    let w = o.units.word();
    let len = |x: f64| number(x / u, false);
    let mut lines = vec![
        format!(
            "ruledlab tool path: {} poses, {} of the path and {} inserted",
            f.poses,
            f.poses - l.inserted,
            l.inserted
        ),
        format!("machine {}", o.machine.describe()),
    ];
    lines.extend(mode_lines(o));
    let feed_word = match (o.dialect, o.mode) {
        (Dialect::Heidenhain, Mode::Tcp) => "F at the tip with FUNCTION TCPM F TCP",
        (Dialect::Heidenhain, Mode::Machine) => "rotary moves get the F of X Y Z that keeps the feed at the tip",
        _ => "inverse time G93 on rotary moves",
    };
    lines.push(format!(
        "units {w}, {} {w} per model unit, feed {} {w}/min at the tip, {feed_word}, approach {} {w}/min",
        o.scale,
        f.job_feed / u,
        f.approach / u
    ));
    let end = match path.tool.end {
        ToolEnd::Ball => "ball end",
        ToolEnd::Flat => "flat end",
    };
    let mut tool = format!(
        "tool {}: {end}, radius {} {w}, length {} {w}, gauge length {} {w}",
        o.tool,
        len(f.radius),
        len(f.cutter),
        len(f.gauge)
    );
    if let Some(h) = o.holder {
        tool.push_str(&format!(", holder radius {} length {} {w}", number(h.radius, false), number(h.length, false)));
    }
    lines.push(tool);
    let (dir, m) = match o.direction {
        SpindleDirection::Clockwise => ("clockwise", "M3"),
        SpindleDirection::CounterClockwise => ("counter-clockwise", "M4"),
    };
    let coolant = match o.coolant {
        super::Coolant::Flood => "flood (M8)",
        super::Coolant::Mist => "mist (M7)",
        super::Coolant::Off => "off",
    };
    lines.push(format!("spindle {} 1/min {dir} ({m}), coolant {coolant}", super::speed(o.spindle)));
    let (a, b) = (f.stock.min, f.stock.max);
    lines.push(format!(
        "stock X {} to {} Y {} to {} Z {} to {} {w}{}",
        len(a.x),
        len(b.x),
        len(a.y),
        len(b.y),
        len(a.z),
        len(b.z),
        if f.stock_given { "" } else { ", the tips' box grown by 1 mm" }
    ));
    lines.push(format!(
        "safe height {} {w} above the part zero or higher where the stock stands higher, clearance {} {w} along the tool axis",
        len(f.safe),
        number(o.clearance, false)
    ));
    lines.push(format!(
        "tolerance chordal {} {w}{}, pole cone {} deg",
        number(l.tolerance / u, false),
        o.angular_tolerance.map_or(String::new(), |t| format!(", angular {} deg", number(t, false))),
        o.pole_cone
    ));
    lines.push(format!(
        "linearisation: tolerance {} {w}, largest deviation tip {} {w} axis {} {w}, before inserting tip {} {w} axis {} {w}",
        len(l.tolerance),
        len(l.after.tip),
        len(l.after.axis),
        len(l.before.tip),
        len(l.before.axis)
    ));
    lines.push(axes_line(o, f));
    for warning in f.warnings {
        lines.push(format!("warning: {}", warning_text(warning)));
    }
    lines.into_iter().map(Op::Comment).collect()
}

/// A warning in English, naming its line where known.
pub fn warning_text(w: &Warning) -> String {
    let text = w.message.english();
    match w.line {
        Some(line) => format!("{text} (line {line})"),
        None => text,
    }
}

/// What each mode assumes of the controller, in its words.
fn mode_lines(o: &PostOptions) -> Vec<String> {
    let m = &o.machine;
    match (o.mode, o.dialect) {
        (Mode::Machine, Dialect::LinuxCnc) => vec![
            "mode: machine coordinates - X Y Z are the machine position of the tip, the work offset must be 0, the kinematics the identity (trivkins, or the identity type of a switchable kinematics)".into(),
        ],
        (Mode::Machine, _) => vec![
            "mode: machine coordinates - X Y Z are the machine position of the tip, the work offset must be 0".into(),
        ],
        (Mode::Tcp, Dialect::LinuxCnc) => {
            let mut v = vec![
                "mode: tool-centre point - X Y Z the tip in part coordinates, LinuxCNC 2.9 has no G43.4: its switchable kinematics is switched to the tool-centre point with M68 E3 Q1 and M66 E0 L0, as M428 of its sim configs, and back with M68 E3 Q0".to_string(),
            ];
            match super::header::linuxcnc_kinematics(m) {
                Some(kins) => {
                    v.push(format!(
                        "LinuxCNC INI: [KINS] KINEMATICS = {kins} sparm=identityfirst, [HAL] HALCMD = net :kinstype-select <= motion.analog-out-03 => motion.switchkins-type"
                    ));
                    v.push(format!(
                        "LinuxCNC HAL: {kins} rot-point and offset pins set to this machine's pivots, its tool-offset pin from motion.tooloffset.z"
                    ));
                }
                None => v.push(
                    "LinuxCNC: no kinematics module of LinuxCNC 2.9 is this machine's tool-centre point - xyzac-trt-kins and xyzbc-trt-kins are tilting tables carrying a rotary table, 5axiskins a head with C carrying B - so it needs a switchable kinematics of its own whose type 1 is its tool-centre point".into(),
                ),
            }
            v
        }
        (Mode::Tcp, Dialect::Heidenhain) => {
            vec!["mode: tool-centre point - FUNCTION TCPM, X Y Z the tip in part coordinates".into()]
        }
        (Mode::Tcp, Dialect::Sinumerik) => vec![
            "mode: tool-centre point - TRAORI, X Y Z the tip and A3 B3 C3 the tool axis in part coordinates".into(),
        ],
    }
}

/// The axes' numbers: the largest rotary speeds, the blocks the axes slowed, the unwinds.
fn axes_line(o: &PostOptions, f: &HeaderFacts) -> String {
    let m = &o.machine;
    let fastest = |k: usize| f.motion.iter().map(|b| b.speed(k)).fold(0.0, f64::max);
    let slowed = f.motion.iter().filter(|b| b.limit != Limit::Feed).count();
    let over = f.motion.iter().filter(|b| b.over).count();
    format!(
        "axes: largest speed {} {} deg/min, {} {} deg/min; {slowed} blocks slowed by the axes' limits{}; {} unwinds",
        m.rotary[0].name.letter(),
        number(fastest(3), false),
        m.rotary[1].name.letter(),
        number(fastest(4), false),
        if over > 0 { format!(", {over} still beyond an acceleration limit") } else { String::new() },
        f.unwinds
    )
}
