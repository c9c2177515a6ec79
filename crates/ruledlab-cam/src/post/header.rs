//! The header of a program: comments that say what the program assumes and what went into it
//! (machine, mode and the controller's setup it needs, units, tool, feeds, tolerances, stock,
//! the linearisation's and the axes' numbers, warnings), in the program's units.

use super::{number, Controller, Mode, Op, PostOptions, SpindleDirection, Warning};
use crate::linearise::Linearisation;
use crate::motion::{BlockMotion, Limit};
use crate::stock::Aabb;
use crate::sweep::EnvelopeDeviation;
use crate::{ToolEnd, ToolPath};
use glam::DVec3;

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
    /// The target's deviation from the sweep of the program, its worst point (mm) and pose.
    pub deviation: Option<(&'a EnvelopeDeviation, DVec3, usize)>,
}

/// The header's comment lines, in `controller`'s words where they are about its setup.
pub(super) fn header(
    path: &ToolPath,
    o: &PostOptions,
    controller: &dyn Controller,
    l: &Linearisation,
    f: &HeaderFacts,
) -> Vec<Op> {
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
    match o.mode {
        Mode::Machine => {
            lines.push(controller.machine_mode());
            lines.push(format!(
                "work offset {} is called below and must hold 0 in X Y Z: the program's X Y Z are machine positions",
                o.work_offset
            ));
        }
        Mode::Tcp => {
            lines.extend(controller.tcp_mode(&o.machine));
            lines.push(format!("work offset {} is called below and must hold the part's zero", o.work_offset));
        }
    }
    let feed_word = controller.feed_words(o.mode);
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
    if let Some((d, q, pose)) = f.deviation {
        // a micrometre in either units: 4 decimals of mm, 5 of inch
        let fine = |x: f64| super::decimals(x / u, if u > 1.0 { 5 } else { 4 }, false);
        lines.push(format!(
            "deviation of the program as posted from the target, {} points: gouge {} {w}, leave {} {w}, rms {} {w}",
            d.points.len(),
            fine(d.gouge),
            fine(d.leave),
            fine(d.rms)
        ));
        lines.push(format!(
            "largest deviation {} {w} at X {} Y {} Z {} near pose {pose}",
            fine(d.largest()),
            len(q.x),
            len(q.y),
            len(q.z)
        ));
    }
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
