//! The LinuxCNC dialect (rs274ngc, as LinuxCNC 2.9's interpreter `rs274` reads it): comments in
//! parentheses (never nested), no block numbers, `G21`/`G20 G90 G94 G17` at the start, `G64 P…
//! Q0` (path blending within the chordal tolerance, the naive CAM detector off: LinuxCNC's
//! G-code reference, "G64 Path Blending"), `G54`–`G59`, `T… M6` with `G43 H…`, `S… M3`/`M4`,
//! `M7`/`M8`/`M9`, `G53 G0 Z…` for the retract in machine coordinates, `G93` inverse time on
//! blocks that turn a rotary axis (every such block carries its F, as G93 requires) and `G94`
//! otherwise, `M30` at the end. Tool-centre-point mode switches a switchable kinematics to its
//! tool-centre point type with `M68 E3 Q1` and `M66 E0 L0` and back with `M68 E3 Q0` (LinuxCNC's
//! "Switchable Kinematics" chapter: the analog output 3 wired to `motion.switchkins-type`, the
//! wait forcing the interpreter and motion into step; its sim configs' `M428`/`M429` do the same);
//! the kinematics interpolates the rotary angles. The program is ISO G-code (`iso.rs`).

use super::controller::{Controller, Orientation, MACHINE_MODE};
use super::iso::{self, Iso};
use super::{number, Context, Mode, Op, Units};
use crate::machine::{AxisName, Carrier, Machine};

/// LinuxCNC 2.9.
pub struct LinuxCnc;

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

impl Controller for LinuxCnc {
    fn name(&self) -> &str {
        "LinuxCNC"
    }

    fn orientation(&self) -> Orientation {
        Orientation::Angles
    }

    fn feed_words(&self, _: Mode) -> &'static str {
        "inverse time G93 on rotary moves"
    }

    fn machine_mode(&self) -> String {
        format!(
            "{MACHINE_MODE}, the kinematics the identity (trivkins, or the identity type of a switchable kinematics)"
        )
    }

    fn tcp_mode(&self, m: &Machine) -> Vec<String> {
        let mut v = vec![
            "mode: tool-centre point - X Y Z the tip in part coordinates, LinuxCNC 2.9 has no G43.4: its switchable kinematics is switched to the tool-centre point with M68 E3 Q1 and M66 E0 L0, as M428 of its sim configs, and back with M68 E3 Q0".to_string(),
        ];
        match linuxcnc_kinematics(m) {
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

    fn write(&self, ops: &[Op], context: &Context) -> String {
        iso::program(self, ops, context)
    }
}

impl Iso for LinuxCnc {
    fn numbered(&self) -> bool {
        false
    }

    fn comment(&self, text: &str) -> String {
        format!("({text})")
    }

    fn start(&self, units: Units) -> &'static str {
        match units {
            Units::Mm => "G21 G90 G94 G17 G40 G49 G80",
            Units::Inch => "G20 G90 G94 G17 G40 G49 G80",
        }
    }

    fn tolerance(&self, chordal: f64, _: f64) -> String {
        format!("G64 P{} Q0", number(chordal, false))
    }

    fn work_offset(&self, k: u32) -> &'static str {
        ["G54", "G55", "G56", "G57", "G58", "G59"][(k as usize - 1).min(5)]
    }

    fn tool_change(&self, tool: u32) -> Vec<String> {
        vec![format!("T{tool} M6"), format!("G43 H{tool}")]
    }

    fn retract(&self, z: &str) -> String {
        format!("G53 G0 Z{z}")
    }

    fn tcp(&self, on: bool) -> Vec<&'static str> {
        if on {
            vec!["(TCP on: switchable kinematics to its tool-centre point, type 1)", "M68 E3 Q1", "M66 E0 L0"]
        } else {
            vec!["(TCP off: switchable kinematics back to the identity, type 0)", "M68 E3 Q0", "M66 E0 L0"]
        }
    }

    fn g94_alone(&self) -> bool {
        true
    }
}
