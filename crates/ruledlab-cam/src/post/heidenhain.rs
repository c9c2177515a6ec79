//! The Heidenhain TNC plain-text (Klartext) dialect: `0 BEGIN PGM <NAME> MM` … `N END PGM <NAME>
//! MM` (`INCH` for inches), every block numbered from 0, comments as `; …` blocks, the stock as
//! `BLK FORM 0.1 Z` / `0.2`, the datum with cycle 247 (`Q339` the preset's number), `TOOL CALL <T>
//! Z S…` (the length offset comes with the tool call), cycle 32 `TOLERANCE` (`T` the chordal
//! tolerance, `HSC-MODE:0` finishing, `TA` the rotary axes' tolerance in degrees; reset by the
//! cycle without `T` at the end), straight moves `L X+… Y+… Z+… A+… C+… R0 F…`, `FMAX` for
//! rapids, `M140 MB MAX` for the retract along the tool axis to the travel's end, `M3`/`M4`/`M5`,
//! `M7`/`M8`/`M9` and `M30` on the blocks that need them. The feed word has 3 decimals and at
//! most 99 999.999 (the TNC's input range: `motion.rs` slows a block rather than write more).
//! Tool-centre-point mode: `FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS` (the feed at the tip,
//! the rotary axes as angles; the older M128 does the same) and `FUNCTION RESET TCPM`. In
//! machine coordinates a block that turns a rotary axis gets the F of the linear axes that makes
//! it last the block's time (F × time = |ΔXYZ|; the control refers F to the linear axes there),
//! or, where the linear axes stand still, the F of the rotary axes in degrees per minute. No
//! Heidenhain control ran these programs: they follow the TNC 640 user's manual for Klartext
//! programming, checked by a test of their syntax only.

use super::controller::{Controller, Orientation, Travel};
use super::{
    comment_lines, decimals, number, speed, Context, Coolant, Mode, Op, Rate, SpindleDirection, Units, Waypoint, Words,
};
use crate::machine::Machine;
use std::fmt::Write;

/// The largest feed a Heidenhain TNC reads: its feed word has 5 places before the point and 3
/// after (the TNC user's manual, "Input format and unit of TNC functions": feed rates 0 to
/// 99 999.999 mm/min).
pub const HEIDENHAIN_MAX_FEED: f64 = 99_999.999;

/// A Heidenhain TNC (the TNC 640's Klartext).
pub struct Heidenhain;

impl Controller for Heidenhain {
    fn name(&self) -> &str {
        "a Heidenhain TNC"
    }

    /// `FUNCTION TCPM … AXIS POS`: the rotary axes' angles.
    fn orientation(&self) -> Orientation {
        Orientation::Angles
    }

    fn max_feed(&self) -> Option<f64> {
        Some(HEIDENHAIN_MAX_FEED)
    }

    /// The tip's distance, but in machine coordinates on a block that turns a rotary axis: X Y
    /// Z's distance, or where they stand still (under 0.01 mm) the rotary axes' degrees (module
    /// documentation; `feed_of` writes the same word).
    fn feed_measure(&self, mode: Mode, b: &Travel, units: Units) -> f64 {
        let u = units.mm();
        match mode {
            Mode::Machine if b.turning => {
                if b.linear >= 0.01 {
                    b.linear / u
                } else {
                    b.turn
                }
            }
            _ => b.distance / u,
        }
    }

    fn feed_words(&self, mode: Mode) -> &'static str {
        match mode {
            Mode::Tcp => "F at the tip with FUNCTION TCPM F TCP",
            Mode::Machine => "rotary moves get the F of X Y Z that keeps the feed at the tip",
        }
    }

    fn tcp_mode(&self, _: &Machine) -> Vec<String> {
        vec!["mode: tool-centre point - FUNCTION TCPM, X Y Z the tip in part coordinates".into()]
    }

    fn write(&self, ops: &[Op], context: &Context) -> String {
        write(ops, context)
    }
}

fn axes(t: &Waypoint, c: &Context, words: Words) -> String {
    match (words, c.mode) {
        (Words::Xy, Mode::Machine) => format!("X{} Y{}", number(t.xyz.x, true), number(t.xyz.y, true)),
        (Words::Z, Mode::Machine) => format!("Z{}", number(t.xyz.z, true)),
        _ => format!(
            "X{} Y{} Z{} {}{} {}{}",
            number(t.xyz.x, true),
            number(t.xyz.y, true),
            number(t.xyz.z, true),
            c.letters[0],
            number(t.rotary[0], true),
            c.letters[1],
            number(t.rotary[1], true)
        ),
    }
}

/// A feed word: 3 decimals, within 0.001 … 99 999.999.
pub fn feed_word(f: f64) -> String {
    decimals(f.clamp(0.001, HEIDENHAIN_MAX_FEED), 3, false)
}

/// The feed word of a block (module documentation).
pub fn feed_of(rate: &Rate, c: &Context) -> f64 {
    match (rate, c.mode) {
        (Rate::PerMinute(f), _) => *f,
        (Rate::Simultaneous { minutes, distance, .. }, Mode::Tcp) => distance / minutes.max(1e-12),
        (Rate::Simultaneous { minutes, linear, turn, .. }, Mode::Machine) => {
            if linear * c.units.mm() >= 0.01 {
                linear / minutes.max(1e-12)
            } else {
                turn / minutes.max(1e-12)
            }
        }
    }
}

/// The program text.
fn write(ops: &[Op], c: &Context) -> String {
    let mut g = String::new();
    let mut n = 0;
    let mut block = |g: &mut String, s: &str| {
        let _ = writeln!(g, "{n} {s}");
        n += 1;
    };
    let unit = match c.units {
        Units::Mm => "MM",
        Units::Inch => "INCH",
    };
    block(&mut g, &format!("BEGIN PGM {} {unit}", c.name));
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
            Op::Comment(text) => {
                for l in comment_lines(text) {
                    block(&mut g, &format!("; {l}"));
                }
            }
            Op::Start => {
                let (lo, hi) = c.bounds;
                block(
                    &mut g,
                    &format!("BLK FORM 0.1 Z X{} Y{} Z{}", number(lo.x, true), number(lo.y, true), number(lo.z, true)),
                );
                block(
                    &mut g,
                    &format!("BLK FORM 0.2 X{} Y{} Z{}", number(hi.x, true), number(hi.y, true), number(hi.z, true)),
                );
            }
            Op::Tolerance { chordal, angular } => {
                block(&mut g, "CYCL DEF 32.0 TOLERANCE");
                block(&mut g, &format!("CYCL DEF 32.1 T{}", number(*chordal, false)));
                if *angular > 0.0 {
                    block(&mut g, &format!("CYCL DEF 32.2 HSC-MODE:0 TA{}", number(*angular, false)));
                } else {
                    block(&mut g, "CYCL DEF 32.2 HSC-MODE:0");
                }
            }
            Op::ToleranceOff => {
                block(&mut g, "CYCL DEF 32.0 TOLERANCE");
                block(&mut g, "CYCL DEF 32.1");
            }
            Op::WorkOffset(k) => {
                block(&mut g, "CYCL DEF 247 DATUM SETTING ~");
                let _ = writeln!(g, "  Q339=+{k} ;DATUM NUMBER");
            }
            Op::ToolChange { tool, spindle, direction } => {
                block(&mut g, &format!("TOOL CALL {tool} Z S{}", speed(*spindle)));
                pending.push(match direction {
                    SpindleDirection::Clockwise => "M3",
                    SpindleDirection::CounterClockwise => "M4",
                });
            }
            // out along the tool axis to the end of the travel (the M functions wait for the
            // next positioning block)
            Op::RetractTop(_) => block(&mut g, "L M140 MB MAX"),
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
            Op::Rapid(t, words) => {
                let extra = m(&mut pending);
                block(&mut g, &format!("L {} R0 FMAX{extra}", axes(t, c, *words)));
            }
            Op::Feed(t, rate) => {
                let extra = m(&mut pending);
                block(&mut g, &format!("L {} R0 F{}{extra}", axes(t, c, Words::All), feed_word(feed_of(rate, c))));
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
    block(&mut g, &format!("END PGM {} {unit}", c.name));
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
            units: Units::Mm,
        }
    }

    /// The blank is the stock's box.
    #[test]
    fn the_blank_is_the_stock() {
        let g = write(&[Op::Start], &context(Mode::Tcp));
        assert!(
            g.contains("BLK FORM 0.1 Z X0.0000 Y-2.0000 Z-3.0000\n")
                || g.contains("BLK FORM 0.1 Z X+0.0000 Y-2.0000 Z-3.0000\n"),
            "{g}"
        );
        assert!(g.contains("BLK FORM 0.2 X+10.0000 Y+2.0000 Z+5.0000\n"), "{g}");
    }

    /// In machine coordinates a simultaneous move's F is its linear distance over its time (the
    /// controller applies F to the linear axes): 0.5 mm in 0.002 min is F250; a move with no
    /// linear part gets the rotary axes' degrees per minute, 3° in 0.002 min F1500; with
    /// tool-centre-point control F is the tip's distance over the time, 2 mm: F1000.
    #[test]
    fn feeds_of_simultaneous_moves() {
        let t = Waypoint { xyz: DVec3::ZERO, rotary: [0.0, 0.0], axis: DVec3::Z };
        let feed = |mode, linear| {
            let rate = Rate::Simultaneous { minutes: 0.002, distance: 2.0, linear, turn: 3.0 };
            let g = write(&[Op::Feed(t, rate)], &context(mode));
            g.lines()
                .find(|l| l.contains(" L "))
                .map(|l| l.split_whitespace().find(|w| w.starts_with('F')).unwrap().to_string())
        };
        assert_eq!(feed(Mode::Machine, 0.5).as_deref(), Some("F250.000"));
        assert_eq!(feed(Mode::Machine, 0.0).as_deref(), Some("F1500.000"));
        assert_eq!(feed(Mode::Tcp, 0.5).as_deref(), Some("F1000.000"));
        // the word's range: 3 decimals, at most 99 999.999, at least 0.001
        assert_eq!(
            (feed_word(123_456.0), feed_word(0.0), feed_word(12.34567)),
            ("99999.999".into(), "0.001".into(), "12.346".into())
        );
    }

    /// What the feed word's bound is measured on (module documentation): the tip's distance; in
    /// machine coordinates on a block that turns, X Y Z's distance from 0.01 mm on, below it the
    /// turn in degrees; lengths in the program's units.
    #[test]
    fn the_feed_word_is_bounded_on_what_it_measures() {
        let travel = |turning, linear| Travel { turning, distance: 25.4, linear, turn: 3.0 };
        let measure = |mode, t: Travel, units| Heidenhain.feed_measure(mode, &t, units);
        assert_eq!(measure(Mode::Tcp, travel(true, 0.5), Units::Mm), 25.4);
        assert_eq!(measure(Mode::Machine, travel(false, 0.5), Units::Mm), 25.4);
        assert_eq!(measure(Mode::Machine, travel(true, 0.5), Units::Mm), 0.5);
        assert_eq!(measure(Mode::Machine, travel(true, 0.01), Units::Mm), 0.01);
        assert_eq!(measure(Mode::Machine, travel(true, 0.0099), Units::Mm), 3.0);
        assert_eq!(measure(Mode::Tcp, travel(true, 0.5), Units::Inch), 1.0);
        assert_eq!(measure(Mode::Machine, travel(true, 50.8), Units::Inch), 2.0);
        assert_eq!(measure(Mode::Machine, travel(true, 0.0099), Units::Inch), 3.0);
    }
}
