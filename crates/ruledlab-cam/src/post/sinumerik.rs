//! The Siemens Sinumerik 840D dialect: the archive header `%_N_<NAME>_MPF` and
//! `;$PATH=/_N_MPF_DIR`, blocks numbered N10, N20, …, comments after `;`, `G17 G71 G90 G94 G64`
//! at the start (`G700` for inches: lengths and feeds), continuous-path mode with `CYCLE832`
//! (the chordal tolerance, machining type 1 finishing, plus 10 with the orientation tolerance as
//! its third parameter; deselected with type 0 at the end: the programming manual's "High speed
//! settings - CYCLE832") instead of modal exact stop `G60`, `G54`–`G57`, `G505`, `G506` (work
//! offsets 5 and 6), `T… D1 M6`, `S… M3`/`M4`, `G0 SUPA Z…` for the retract in machine
//! coordinates, `G93` inverse time (F in 1/min) on blocks that turn a rotary axis, `M30` at the
//! end. Tool-centre-point mode: `TRAORI` with `ORIWKS` (orientation
//! in the workpiece frame) and `ORIVECT` (the axis on a great circle), the tool axis written as
//! the vector `A3= B3= C3=`; `TRAFOOF` ends it. No Sinumerik ran these programs: they follow
//! Siemens' programming manual (fundamentals and job planning), checked by a test of their
//! syntax only.

use super::{comment_lines, number, speed, Context, Coolant, Mode, Op, Rate, SpindleDirection, Target, Units, Words};
use crate::tolerance::GCODE_VECTOR_DECIMALS;
use std::fmt::Write;

fn vector(x: f64) -> String {
    let s = format!("{x:.GCODE_VECTOR_DECIMALS$}");
    if s.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}

fn axes(t: &Target, c: &Context, words: Words) -> String {
    let xyz = format!("X{} Y{} Z{}", number(t.xyz.x, false), number(t.xyz.y, false), number(t.xyz.z, false));
    match (words, c.mode) {
        (Words::Xy, Mode::Machine) => return format!("X{} Y{}", number(t.xyz.x, false), number(t.xyz.y, false)),
        (Words::Z, Mode::Machine) => return format!("Z{}", number(t.xyz.z, false)),
        _ => {}
    }
    match c.mode {
        Mode::Tcp => format!("{xyz} A3={} B3={} C3={}", vector(t.axis.x), vector(t.axis.y), vector(t.axis.z)),
        Mode::Machine => format!(
            "{xyz} {}{} {}{}",
            c.letters[0],
            number(t.rotary[0], false),
            c.letters[1],
            number(t.rotary[1], false)
        ),
    }
}

/// The program text.
pub fn write(ops: &[Op], c: &Context) -> String {
    let mut g = String::new();
    let _ = writeln!(g, "%_N_{}_MPF", c.name);
    let _ = writeln!(g, ";$PATH=/_N_MPF_DIR");
    let mut n = 0;
    let mut inverse = false;
    let mut block = |g: &mut String, s: &str| {
        n += 10;
        let _ = writeln!(g, "N{n} {s}");
    };
    for op in ops {
        match op {
            Op::Comment(text) => {
                for l in comment_lines(text) {
                    let _ = writeln!(g, "; {l}");
                }
            }
            Op::Start => block(
                &mut g,
                match c.units {
                    Units::Mm => "G17 G71 G90 G94 G40 G64",
                    Units::Inch => "G17 G700 G90 G94 G40 G64",
                },
            ),
            Op::Tolerance { chordal, angular } => {
                let call = if *angular > 0.0 {
                    format!("CYCLE832({},11,{})", number(*chordal, false), number(*angular, false))
                } else {
                    format!("CYCLE832({},1,1)", number(*chordal, false))
                };
                block(&mut g, &call);
            }
            Op::ToleranceOff => block(&mut g, "CYCLE832(0,0,1)"),
            Op::WorkOffset(k) => block(&mut g, ["G54", "G55", "G56", "G57", "G505", "G506"][(*k as usize - 1).min(5)]),
            Op::ToolChange { tool, spindle, direction } => {
                block(&mut g, &format!("T{tool} D1 M6"));
                let m = match direction {
                    SpindleDirection::Clockwise => "M3",
                    SpindleDirection::CounterClockwise => "M4",
                };
                block(&mut g, &format!("S{} {m}", speed(*spindle)));
            }
            Op::RetractTop(z) => block(&mut g, &format!("G0 SUPA Z{}", number(*z, false))),
            Op::Rotate(r) => block(
                &mut g,
                &format!("G0 {}{} {}{}", c.letters[0], number(r[0], false), c.letters[1], number(r[1], false)),
            ),
            Op::Tcp(true) => block(&mut g, "TRAORI ORIWKS ORIVECT"),
            Op::Tcp(false) => block(&mut g, "TRAFOOF"),
            Op::Rapid(t, words) => {
                let mode = if inverse { "G94 " } else { "" };
                inverse = false;
                block(&mut g, &format!("{mode}G0 {}", axes(t, c, *words)));
            }
            Op::Feed(t, rate) => match rate {
                Rate::PerMinute(f) => {
                    let mode = if inverse { "G94 " } else { "" };
                    inverse = false;
                    block(&mut g, &format!("{mode}G1 {} F{}", axes(t, c, Words::All), number(*f, false)));
                }
                Rate::Simultaneous { minutes, .. } => {
                    let mode = if inverse { "" } else { "G93 " };
                    inverse = true;
                    let f = 1.0 / minutes.max(1e-9);
                    block(&mut g, &format!("{mode}G1 {} F{}", axes(t, c, Words::All), number(f, false)));
                }
            },
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Seven decimals, and no "−0": a component that rounds to zero is written unsigned.
    #[test]
    fn vector_components() {
        assert_eq!(vector(-0.5), "-0.5000000");
        assert_eq!(vector(0.25), "0.2500000");
        assert_eq!(vector(-1e-9), "0.0000000");
        assert_eq!(vector(-0.0), "0.0000000");
        assert_eq!(vector(-0.00000006), "-0.0000001");
    }
}
