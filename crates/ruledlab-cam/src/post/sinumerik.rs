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
//! syntax only. The program is ISO G-code (`iso.rs`).

use super::controller::{Controller, Orientation};
use super::iso::{self, Iso};
use super::{number, Context, Mode, Op, Units, Waypoint};
use crate::machine::Machine;
use crate::tolerance::GCODE_VECTOR_DECIMALS;

/// Siemens Sinumerik 840D.
pub struct Sinumerik;

fn vector(x: f64) -> String {
    let s = format!("{x:.GCODE_VECTOR_DECIMALS$}");
    if s.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}

impl Controller for Sinumerik {
    fn name(&self) -> &str {
        "a Sinumerik 840D"
    }

    fn orientation(&self) -> Orientation {
        Orientation::Vector
    }

    fn feed_words(&self, _: Mode) -> &'static str {
        "inverse time G93 on rotary moves"
    }

    fn tcp_mode(&self, _: &Machine) -> Vec<String> {
        vec!["mode: tool-centre point - TRAORI, X Y Z the tip and A3 B3 C3 the tool axis in part coordinates".into()]
    }

    fn write(&self, ops: &[Op], context: &Context) -> String {
        iso::program(self, ops, context)
    }
}

impl Iso for Sinumerik {
    fn preamble(&self, c: &Context) -> Vec<String> {
        vec![format!("%_N_{}_MPF", c.name), ";$PATH=/_N_MPF_DIR".into()]
    }

    fn numbered(&self) -> bool {
        true
    }

    fn comment(&self, text: &str) -> String {
        format!("; {text}")
    }

    fn start(&self, units: Units) -> &'static str {
        match units {
            Units::Mm => "G17 G71 G90 G94 G40 G64",
            Units::Inch => "G17 G700 G90 G94 G40 G64",
        }
    }

    fn tolerance(&self, chordal: f64, angular: f64) -> String {
        if angular > 0.0 {
            format!("CYCLE832({},11,{})", number(chordal, false), number(angular, false))
        } else {
            format!("CYCLE832({},1,1)", number(chordal, false))
        }
    }

    fn tolerance_off(&self) -> Option<&'static str> {
        Some("CYCLE832(0,0,1)")
    }

    fn work_offset(&self, k: u32) -> &'static str {
        ["G54", "G55", "G56", "G57", "G505", "G506"][(k as usize - 1).min(5)]
    }

    fn tool_change(&self, tool: u32) -> Vec<String> {
        vec![format!("T{tool} D1 M6")]
    }

    fn retract(&self, z: &str) -> String {
        format!("G0 SUPA Z{z}")
    }

    fn tcp(&self, on: bool) -> Vec<&'static str> {
        vec![if on { "TRAORI ORIWKS ORIVECT" } else { "TRAFOOF" }]
    }

    fn tcp_axis(&self, t: &Waypoint, _: &Context) -> String {
        format!("A3={} B3={} C3={}", vector(t.axis.x), vector(t.axis.y), vector(t.axis.z))
    }

    fn g94_alone(&self) -> bool {
        false
    }
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
