//! The Heidenhain TNC plain-text (Klartext) dialect: `0 BEGIN PGM <NAME> MM` … `N END PGM <NAME>
//! MM`, every block numbered from 0, comments as `; …` blocks, the blank as `BLK FORM 0.1 Z` /
//! `0.2`, the datum with cycle 247 (`Q339` the preset's number), `TOOL CALL <T> Z S…` (the
//! length offset comes with the tool call), straight moves `L X+… Y+… Z+… A+… C+… R0 F…`,
//! `FMAX` for rapids, `M91` for the retract in machine coordinates, `M3`/`M5`, `M7`/`M8`/`M9`
//! and `M30` on the blocks that need them. Tool-centre-point mode: `FUNCTION TCPM F TCP AXIS POS
//! PATHCTRL AXIS` (the feed at the tip, the rotary axes as angles; the older M128 does the same)
//! and `FUNCTION RESET TCPM`. In machine coordinates a block that turns a rotary axis gets the F
//! of the linear axes that makes it last as long as the tip at the given feed (F × |ΔXYZ| / tip
//! distance; the control refers F to the linear axes there). No Heidenhain control ran these
//! programs: they follow the TNC 640 user's manual for Klartext programming, checked by a test
//! of their syntax only.

use super::{clean, number, speed, Context, Coolant, Mode, Op, Rate, Target};
use std::fmt::Write;

fn axes(t: &Target, c: &Context) -> String {
    format!(
        "X{} Y{} Z{} {}{} {}{}",
        number(t.xyz.x, true),
        number(t.xyz.y, true),
        number(t.xyz.z, true),
        c.letters[0],
        number(t.rotary[0], true),
        c.letters[1],
        number(t.rotary[1], true)
    )
}

/// The program text.
pub fn write(ops: &[Op], c: &Context) -> String {
    let mut g = String::new();
    let mut n = 0;
    let mut block = |g: &mut String, s: &str| {
        let _ = writeln!(g, "{n} {s}");
        n += 1;
    };
    block(&mut g, &format!("BEGIN PGM {} MM", c.name));
    // a pending M function for the next positioning block (spindle on, coolant)
    let mut pending: Vec<&str> = Vec::new();
    let m = |pending: &mut Vec<&str>| {
        let s: String = pending.iter().map(|m| format!(" {m}")).collect();
        pending.clear();
        s
    };
    for (i, op) in ops.iter().enumerate() {
        let last = matches!(ops.get(i + 1), Some(Op::End));
        match op {
            Op::Comment(text) => block(&mut g, &format!("; {}", clean(text))),
            Op::Start => {
                let (lo, hi) = c.bounds;
                let (lo, hi) = (lo - glam::DVec3::splat(1.0), hi + glam::DVec3::splat(1.0));
                block(
                    &mut g,
                    &format!("BLK FORM 0.1 Z X{} Y{} Z{}", number(lo.x, true), number(lo.y, true), number(lo.z, true)),
                );
                block(
                    &mut g,
                    &format!("BLK FORM 0.2 X{} Y{} Z{}", number(hi.x, true), number(hi.y, true), number(hi.z, true)),
                );
            }
            Op::WorkOffset(k) => {
                block(&mut g, "CYCL DEF 247 DATUM SETTING ~");
                let _ = writeln!(g, "  Q339=+{k} ;DATUM NUMBER");
            }
            Op::ToolChange { tool, spindle } => {
                block(&mut g, &format!("TOOL CALL {tool} Z S{}", speed(*spindle)));
                pending.push("M3");
            }
            Op::RetractTop(z) => {
                let extra = m(&mut pending);
                block(&mut g, &format!("L Z{} R0 FMAX M91{extra}", number(*z, true)));
            }
            Op::Rotate(r) => {
                if last {
                    pending.push("M30");
                }
                let extra = m(&mut pending);
                block(
                    &mut g,
                    &format!(
                        "L {}{} {}{} R0 FMAX{extra}",
                        c.letters[0],
                        number(r[0], true),
                        c.letters[1],
                        number(r[1], true)
                    ),
                );
            }
            Op::Tcp(true) => block(&mut g, "FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS"),
            Op::Tcp(false) => block(&mut g, "FUNCTION RESET TCPM"),
            Op::Rapid(t) => {
                let extra = m(&mut pending);
                block(&mut g, &format!("L {} R0 FMAX{extra}", axes(t, c)));
            }
            Op::Feed(t, rate) => {
                let f = match (rate, c.mode) {
                    (Rate::PerMinute(f), _) | (Rate::Simultaneous { feed: f, .. }, Mode::Tcp) => *f,
                    (Rate::Simultaneous { feed, distance, linear }, Mode::Machine) => {
                        if *linear > 1e-4 {
                            feed * linear / distance.max(1e-6)
                        } else {
                            *feed
                        }
                    }
                };
                let extra = m(&mut pending);
                block(&mut g, &format!("L {} R0 F{}{extra}", axes(t, c), number(f, false)));
            }
            Op::Coolant(k) => match k {
                Coolant::Flood => pending.push("M8"),
                Coolant::Mist => pending.push("M7"),
                Coolant::Off => pending.push("M9"),
            },
            Op::SpindleOff => pending.push("M5"),
            // M30 went with the block before (the rotary axes to 0)
            Op::End => {}
        }
    }
    block(&mut g, &format!("END PGM {} MM", c.name));
    g
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    fn context(mode: Mode) -> Context {
        Context {
            letters: ["A", "C"],
            mode,
            name: "T".into(),
            bounds: (DVec3::new(0.0, -2.0, -3.0), DVec3::new(10.0, 2.0, 5.0)),
        }
    }

    /// The blank is the box of the tips, 1 mm larger on every side.
    #[test]
    fn the_blank_is_the_tips_box_and_a_millimetre() {
        let g = write(&[Op::Start], &context(Mode::Tcp));
        assert!(g.contains("BLK FORM 0.1 Z X-1.0000 Y-3.0000 Z-4.0000\n"), "{g}");
        assert!(g.contains("BLK FORM 0.2 X+11.0000 Y+3.0000 Z+6.0000\n"), "{g}");
    }

    /// In machine coordinates a simultaneous move's feed is scaled by the linear share of its
    /// distance (the controller applies F to the linear axes): 1000 · 0.5/2 = 250; a move with no
    /// linear part keeps the feed; with tool-centre-point control F is the tip's feed.
    #[test]
    fn feeds_of_simultaneous_moves() {
        let t = Target { xyz: DVec3::ZERO, rotary: [0.0, 0.0], axis: DVec3::Z };
        let feed = |mode, linear| {
            let g = write(&[Op::Feed(t, Rate::Simultaneous { feed: 1000.0, distance: 2.0, linear })], &context(mode));
            g.lines()
                .find(|l| l.contains(" L "))
                .map(|l| l.split_whitespace().find(|w| w.starts_with('F')).unwrap().to_string())
        };
        assert_eq!(feed(Mode::Machine, 0.5).as_deref(), Some("F250.0000"));
        assert_eq!(feed(Mode::Machine, 0.0).as_deref(), Some("F1000.0000"));
        assert_eq!(feed(Mode::Tcp, 0.5).as_deref(), Some("F1000.0000"));
    }
}
