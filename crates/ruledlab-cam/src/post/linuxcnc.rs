//! The LinuxCNC dialect (rs274ngc, as LinuxCNC 2.9's interpreter `rs274` reads it): comments in
//! parentheses (never nested), no block numbers, `G21`/`G20 G90 G94 G17` at the start, `G64 P…
//! Q0` (path blending within the chordal tolerance, the naive CAM detector off: LinuxCNC's
//! G-code reference, "G64 Path Blending"), `G54`–`G59`, `T… M6` with `G43 H…`, `S… M3`/`M4`,
//! `M7`/`M8`/`M9`, `G53 G0 Z…` for the retract in machine coordinates, `G93` inverse time on
//! blocks that turn a rotary axis (every such block carries its F, as G93 requires) and `G94`
//! otherwise, `M30` at the end. Tool-centre-point mode switches a switchable kinematics to its
//! tool-centre point type with `M68 E3 Q1` and `M66 E0 L0` and back with `M68 E3 Q0` (LinuxCNC's
//! "Switchable Kinematics" chapter: the analog output 3 wired to `motion.switchkins-type`, the
//! wait forcing the interpreter and motion into step; its sim configs' `M428`/`M429` do the same).

use super::{comment_lines, number, speed, Context, Coolant, Mode, Op, Rate, SpindleDirection, Target, Units, Words};
use std::fmt::Write;

fn axes(t: &Target, c: &Context, words: Words) -> String {
    let rotary =
        || format!(" {}{} {}{}", c.letters[0], number(t.rotary[0], false), c.letters[1], number(t.rotary[1], false));
    match (words, c.mode) {
        (Words::Xy, Mode::Machine) => format!("X{} Y{}", number(t.xyz.x, false), number(t.xyz.y, false)),
        (Words::Z, Mode::Machine) => format!("Z{}", number(t.xyz.z, false)),
        _ => format!("X{} Y{} Z{}{}", number(t.xyz.x, false), number(t.xyz.y, false), number(t.xyz.z, false), rotary()),
    }
}

/// The program text.
pub fn write(ops: &[Op], c: &Context) -> String {
    let mut g = String::new();
    let mut inverse = false;
    let line = |g: &mut String, s: &str| {
        let _ = writeln!(g, "{s}");
    };
    for op in ops {
        match op {
            Op::Comment(text) => {
                for l in comment_lines(text) {
                    line(&mut g, &format!("({l})"));
                }
            }
            Op::Start => line(
                &mut g,
                match c.units {
                    Units::Mm => "G21 G90 G94 G17 G40 G49 G80",
                    Units::Inch => "G20 G90 G94 G17 G40 G49 G80",
                },
            ),
            Op::Tolerance { chordal, .. } => line(&mut g, &format!("G64 P{} Q0", number(*chordal, false))),
            Op::ToleranceOff => {}
            Op::WorkOffset(k) => line(&mut g, ["G54", "G55", "G56", "G57", "G58", "G59"][(*k as usize - 1).min(5)]),
            Op::ToolChange { tool, spindle, direction } => {
                line(&mut g, &format!("T{tool} M6"));
                line(&mut g, &format!("G43 H{tool}"));
                let m = match direction {
                    SpindleDirection::Clockwise => "M3",
                    SpindleDirection::CounterClockwise => "M4",
                };
                line(&mut g, &format!("S{} {m}", speed(*spindle)));
            }
            Op::RetractTop(z) => line(&mut g, &format!("G53 G0 Z{}", number(*z, false))),
            Op::Rotate(r) => line(
                &mut g,
                &format!("G0 {}{} {}{}", c.letters[0], number(r[0], false), c.letters[1], number(r[1], false)),
            ),
            Op::Tcp(on) => {
                let (comment, q) = if *on {
                    ("(TCP on: switchable kinematics to its tool-centre point, type 1)", "M68 E3 Q1")
                } else {
                    ("(TCP off: switchable kinematics back to the identity, type 0)", "M68 E3 Q0")
                };
                line(&mut g, comment);
                line(&mut g, q);
                line(&mut g, "M66 E0 L0");
            }
            Op::Rapid(t, words) => {
                if inverse {
                    line(&mut g, "G94");
                    inverse = false;
                }
                line(&mut g, &format!("G0 {}", axes(t, c, *words)));
            }
            Op::Feed(t, rate) => match rate {
                Rate::PerMinute(f) => {
                    let mode = if inverse { "G94 " } else { "" };
                    inverse = false;
                    line(&mut g, &format!("{mode}G1 {} F{}", axes(t, c, Words::All), number(*f, false)));
                }
                Rate::Simultaneous { minutes, .. } => {
                    let mode = if inverse { "" } else { "G93 " };
                    inverse = true;
                    let f = 1.0 / minutes.max(1e-9);
                    line(&mut g, &format!("{mode}G1 {} F{}", axes(t, c, Words::All), number(f, false)));
                }
            },
            Op::Coolant(k) => line(
                &mut g,
                match k {
                    Coolant::Flood => "M8",
                    Coolant::Mist => "M7",
                    Coolant::Off => "M9",
                },
            ),
            Op::SpindleOff => line(&mut g, "M5"),
            Op::End => {
                if inverse {
                    line(&mut g, "G94");
                    inverse = false;
                }
                line(&mut g, "M30");
            }
        }
    }
    g
}
