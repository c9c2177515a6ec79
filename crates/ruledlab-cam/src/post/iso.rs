//! ISO G-code (ISO 6983, RS-274) as LinuxCNC and Sinumerik read it: one writer, [`program`],
//! and the words each controller says its own way ([`Iso`]).
//!
//! What they share: `G0` rapids and `G1` feed moves with X Y Z and the rotary axes (machine
//! coordinates, or a controller's tool-centre point) and `F`; `G93` inverse time (F = 1/T, T the
//! block's time in minutes) on the blocks that turn a rotary axis — every such block carries its
//! F, as `G93` requires — and `G94` units per minute otherwise, each written where the mode
//! changes; `S… M3`/`M4` after the tool change, `M7`/`M8`/`M9`, `M5`, `M30` at the end (out of
//! inverse time first). What differs (the start's modal words, the continuous-path mode, work
//! offsets, the tool change, the retract in machine coordinates, tool-centre-point control and
//! how it is given the tool axis, comments, block numbers, a program's first lines) is the
//! controller's file.

use super::{comment_lines, number, speed, Context, Coolant, Mode, Op, Rate, SpindleDirection, Units, Waypoint, Words};
use std::fmt::Write;

/// The words an ISO controller says its own way. Lengths come as written (program units), the
/// numbers formatted with [`number`].
pub trait Iso {
    /// Lines before the first block (default none).
    fn preamble(&self, context: &Context) -> Vec<String> {
        let _ = context;
        Vec::new()
    }

    /// Whether blocks are numbered N10, N20, … (comments are not).
    fn numbered(&self) -> bool;

    /// A comment line holding `text` (made safe and wrapped already).
    fn comment(&self, text: &str) -> String;

    /// The first block: units, absolute coordinates, feed per minute, the XY plane, no cutter
    /// compensation.
    fn start(&self, units: Units) -> &'static str;

    /// The continuous-path mode with the chordal tolerance (program units) and the angular one
    /// (degrees; 0: none).
    fn tolerance(&self, chordal: f64, angular: f64) -> String;

    /// The end of that mode, where the controller has one (default none).
    fn tolerance_off(&self) -> Option<&'static str> {
        None
    }

    /// Work offset `k`, 1–6.
    fn work_offset(&self, k: u32) -> &'static str;

    /// The tool change with its length offset (the spindle's block follows).
    fn tool_change(&self, tool: u32) -> Vec<String>;

    /// The rapid to Z `z` (written) in machine coordinates.
    fn retract(&self, z: &str) -> String;

    /// The blocks that switch tool-centre-point control on or off.
    fn tcp(&self, on: bool) -> Vec<&'static str>;

    /// The words of the tool axis under tool-centre-point control (the default: the rotary
    /// axes' angles, as in machine coordinates).
    fn tcp_axis(&self, t: &Waypoint, context: &Context) -> String {
        angles(t.rotary, context)
    }

    /// Whether leaving inverse time before a rapid is a `G94` block of its own (else a word of
    /// the rapid's block).
    fn g94_alone(&self) -> bool;
}

/// The rotary axes' words: "A12.0000 C-3.5000".
pub fn angles(rotary: [f64; 2], c: &Context) -> String {
    format!("{}{} {}{}", c.letters[0], number(rotary[0], false), c.letters[1], number(rotary[1], false))
}

/// The axis words of a block.
fn axes(iso: &dyn Iso, t: &Waypoint, c: &Context, words: Words) -> String {
    let (x, y, z) = (number(t.xyz.x, false), number(t.xyz.y, false), number(t.xyz.z, false));
    match (words, c.mode) {
        (Words::Xy, Mode::Machine) => format!("X{x} Y{y}"),
        (Words::Z, Mode::Machine) => format!("Z{z}"),
        (_, Mode::Machine) => format!("X{x} Y{y} Z{z} {}", angles(t.rotary, c)),
        (_, Mode::Tcp) => format!("X{x} Y{y} Z{z} {}", iso.tcp_axis(t, c)),
    }
}

/// The program text of `ops` in `iso`'s words (module documentation).
pub fn program(iso: &dyn Iso, ops: &[Op], c: &Context) -> String {
    let mut g = String::new();
    for line in iso.preamble(c) {
        let _ = writeln!(g, "{line}");
    }
    let mut n = 0;
    let mut block = |g: &mut String, s: &str| {
        if iso.numbered() {
            n += 10;
            let _ = writeln!(g, "N{n} {s}");
        } else {
            let _ = writeln!(g, "{s}");
        }
    };
    let mut inverse = false;
    for op in ops {
        match op {
            Op::Comment(text) => {
                for l in comment_lines(text) {
                    let _ = writeln!(g, "{}", iso.comment(&l));
                }
            }
            Op::Start => block(&mut g, iso.start(c.units)),
            Op::Tolerance { chordal, angular } => block(&mut g, &iso.tolerance(*chordal, *angular)),
            Op::ToleranceOff => {
                if let Some(off) = iso.tolerance_off() {
                    block(&mut g, off);
                }
            }
            Op::WorkOffset(k) => block(&mut g, iso.work_offset(*k)),
            Op::ToolChange { tool, spindle, direction } => {
                for b in iso.tool_change(*tool) {
                    block(&mut g, &b);
                }
                let m = match direction {
                    SpindleDirection::Clockwise => "M3",
                    SpindleDirection::CounterClockwise => "M4",
                };
                block(&mut g, &format!("S{} {m}", speed(*spindle)));
            }
            Op::RetractTop(z) => block(&mut g, &iso.retract(&number(*z, false))),
            Op::Rotate(r) => block(&mut g, &format!("G0 {}", angles(*r, c))),
            Op::Tcp(on) => {
                for b in iso.tcp(*on) {
                    block(&mut g, b);
                }
            }
            Op::Rapid(t, words) => {
                let mode = match (inverse, iso.g94_alone()) {
                    (false, _) => "",
                    (true, true) => {
                        block(&mut g, "G94");
                        ""
                    }
                    (true, false) => "G94 ",
                };
                inverse = false;
                block(&mut g, &format!("{mode}G0 {}", axes(iso, t, c, *words)));
            }
            Op::Feed(t, rate) => {
                let (mode, f) = match rate {
                    Rate::PerMinute(f) => (if inverse { "G94 " } else { "" }, *f),
                    Rate::Simultaneous { minutes, .. } => (if inverse { "" } else { "G93 " }, 1.0 / minutes.max(1e-9)),
                };
                inverse = matches!(rate, Rate::Simultaneous { .. });
                block(&mut g, &format!("{mode}G1 {} F{}", axes(iso, t, c, Words::All), number(f, false)));
            }
            Op::Coolant(k) => block(
                &mut g,
                match k {
                    Coolant::Flood => "M8",
                    Coolant::Mist => "M7",
                    Coolant::Off => "M9",
                },
            ),
            Op::SpindleOff => block(&mut g, "M5"),
            Op::End => {
                if inverse {
                    block(&mut g, "G94");
                    inverse = false;
                }
                block(&mut g, "M30");
            }
        }
    }
    g
}
