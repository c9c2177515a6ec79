//! The LinuxCNC dialect (rs274ngc, as LinuxCNC 2.9's interpreter `rs274` reads it): comments in
//! parentheses (never nested), no block numbers, `G21 G90 G94 G17` at the start, `G54`–`G59`,
//! `T… M6` with `G43 H…`, `S… M3`, `M7`/`M8`/`M9`, `G53 G0 Z…` for the retract in machine
//! coordinates, `G93` inverse time on blocks that turn a rotary axis (every such block carries
//! its F, as G93 requires) and `G94` otherwise, `M30` at the end. Tool-centre-point mode writes
//! the same words (LinuxCNC has no `G43.4`; the TCP is the configured kinematics').

use super::{clean, number, speed, Context, Coolant, Op, Rate, Target};
use std::fmt::Write;

fn axes(t: &Target, c: &Context) -> String {
    format!(
        "X{} Y{} Z{} {}{} {}{}",
        number(t.xyz.x, false),
        number(t.xyz.y, false),
        number(t.xyz.z, false),
        c.letters[0],
        number(t.rotary[0], false),
        c.letters[1],
        number(t.rotary[1], false)
    )
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
            Op::Comment(text) => line(&mut g, &format!("({})", clean(text))),
            Op::Start => line(&mut g, "G21 G90 G94 G17 G40 G49 G80"),
            Op::WorkOffset(k) => line(&mut g, ["G54", "G55", "G56", "G57", "G58", "G59"][(*k as usize - 1).min(5)]),
            Op::ToolChange { tool, spindle } => {
                line(&mut g, &format!("T{tool} M6"));
                line(&mut g, &format!("G43 H{tool}"));
                line(&mut g, &format!("S{} M3", speed(*spindle)));
            }
            Op::RetractTop(z) => line(&mut g, &format!("G53 G0 Z{}", number(*z, false))),
            Op::Rotate(r) => line(
                &mut g,
                &format!("G0 {}{} {}{}", c.letters[0], number(r[0], false), c.letters[1], number(r[1], false)),
            ),
            Op::Tcp(on) => line(
                &mut g,
                if *on { "(TCP on: the kinematics must be the tool-centre-point type from here)" } else { "(TCP off)" },
            ),
            Op::Rapid(t) => {
                if inverse {
                    line(&mut g, "G94");
                    inverse = false;
                }
                line(&mut g, &format!("G0 {}", axes(t, c)));
            }
            Op::Feed(t, rate) => match rate {
                Rate::PerMinute(f) => {
                    let mode = if inverse { "G94 " } else { "" };
                    inverse = false;
                    line(&mut g, &format!("{mode}G1 {} F{}", axes(t, c), number(*f, false)));
                }
                Rate::Simultaneous { feed, distance, .. } => {
                    let mode = if inverse { "" } else { "G93 " };
                    inverse = true;
                    let f = Rate::inverse_time(*feed, *distance);
                    line(&mut g, &format!("{mode}G1 {} F{}", axes(t, c), number(f, false)));
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
