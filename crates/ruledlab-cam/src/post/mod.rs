//! The G-code post of Example 6's tool paths: a program a five-axis controller runs, for a
//! [`Machine`], in one of three dialects and two modes, for a job of given units, tool, feeds,
//! tolerances and stock.
//!
//! **Modes.** *Tool-centre point* (`Tcp`): the controller does the kinematics — `TRAORI` on
//! Sinumerik (the axis as a vector `A3= B3= C3=` in part coordinates), `FUNCTION TCPM` on
//! Heidenhain, a switchable kinematics on LinuxCNC switched to its tool-centre-point type with
//! `M68 E3 Q1` / `M66 E0 L0` (LinuxCNC 2.9 has no `G43.4`); X Y Z are the tip in part
//! coordinates (the work offset holds the part's zero) and the rotary axes their angles.
//! *Machine coordinates* (`Machine`): ruledlab does the kinematics with the machine's pivots and
//! offsets (`kinematics.rs`); X Y Z are the machine position of the tip with the work offset at
//! zero.
//!
//! **The program** (`plan.rs`). A header of comments (machine, mode and what it assumes of the
//! controller, units, tool, feeds, tolerances, stock, the linearisation's and the axes'
//! numbers, warnings); the frame of the dialect with its continuous-path mode and tolerance,
//! the work offset, the tool change with its length offset, the spindle; the **safe start**: the
//! spindle retracted to the top of Z in machine coordinates, the rotary axes turned there, X Y
//! at the top, Z down to a point on the first pose's tool axis clear of the stock, down the axis
//! to the clearance outside the stock, coolant on, the approach along the axis at the approach
//! feed. The cut: one block per pose of the linearised path (`linearise.rs`), each timed so that
//! the tip keeps the feed where the machine's axes allow it (`motion.rs`), with inverse-time
//! feed (`G93`) or the feed word the controller reads on blocks that turn a rotary axis; where a
//! limited rotary axis would leave its range it **unwinds** (out along the tool axis, turned by
//! whole turns, back). The **safe end**: out along the tool axis, up, coolant and spindle off,
//! the spindle to the top of Z, the rotary axes to their zero (a continuous axis to its nearest
//! whole turn: no program ends with a multi-turn rapid).
//!
//! **The controller** (`controller.rs`): a [`Controller`] writes the plan's steps in its words
//! and says how it interpolates and what its feed word reads; one file each (`linuxcnc.rs`,
//! `heidenhain.rs`, `sinumerik.rs`), LinuxCNC and Sinumerik through the one ISO writer
//! (`iso.rs`). The steps are in `ops.rs`, the words every dialect writes alike in `text.rs`, the
//! options and their checks in `options.rs`, the header in `header.rs`.

pub mod controller;
mod header;
mod heidenhain;
pub mod iso;
mod linuxcnc;
mod ops;
mod options;
mod plan;
mod sinumerik;
mod text;

pub use controller::{Controller, Dialect};
pub use ops::{Context, Op, Rate, Waypoint, Words};
pub use options::{validate, Coolant, Holder, Mode, Numbering, PostOptions, SpindleDirection, Units};
pub use plan::plan_reporting;
pub use text::{comment_lines, decimals, number, speed};

use crate::kinematics::Joints;
use crate::linearise::{Linearisation, Linearised};
use crate::motion::BlockMotion;
use crate::sweep::{EnvelopeDeviation, SweptBlock};
use crate::{Pose, ToolPath};
use ruledlab::{Message, Result};

/// Something the post did or found that the machinist should know, naming the pose (of the
/// input where the post knows its numbering).
#[derive(Debug, Clone, PartialEq)]
pub struct Warning {
    /// The pose.
    pub pose: usize,
    /// Its line in the input file, where known.
    pub line: Option<usize>,
    /// What, with a reason the page says in its language.
    pub message: Message,
}

impl Warning {
    /// In English, with its line where known ("… (line 7)").
    pub fn text(&self) -> String {
        header::warning_text(self)
    }
}

/// A program and what went into it.
#[derive(Debug, Clone, PartialEq)]
pub struct Program {
    /// The program text.
    pub text: String,
    /// The poses of the cut, part frame, mm: the path's and the inserted ones, in order (in the
    /// pole cone as written: the tool axis of the interpolated rotary values).
    pub poses: Vec<Pose>,
    /// Their axis values (machine frame).
    pub joints: Vec<Joints>,
    /// Where each pose lies on the given path (k + s between poses k and k + 1).
    pub origin: Vec<f64>,
    /// At a pose where a limited axis unwinds: its rotary values after unwinding.
    pub unwound: Vec<Option<[f64; 2]>>,
    /// Angle between each pose's given tool axis and the one written (the pole cone), radians.
    pub adjusted: Vec<f64>,
    /// Each block's motion: its time and what set it (one per block of the cut).
    pub motion: Vec<BlockMotion>,
    /// The linearisation check.
    pub linearisation: Linearisation,
    /// What the machinist should know.
    pub warnings: Vec<Warning>,
    /// The stock the rapids were checked against, part frame, mm.
    pub stock: [[f64; 3]; 2],
    /// The blocks the controller moves the tool through, part frame, mm (`sweep.rs`): the
    /// approach, the cut, the unwindings' ways out and back, the retract.
    pub sweep: Vec<SweptBlock>,
    /// Where the options give a target: its deviation from the sweep of the program as posted,
    /// mm (positions along the program's poses).
    pub deviation: Option<EnvelopeDeviation>,
}

impl Program {
    /// Per pose its axis values as written, lengths in units of `mm` millimetres (the program's:
    /// 1 or 25.4): X, Y, Z, then the two rotary axes in degrees; 5 numbers a pose.
    pub fn axis_values(&self, mm: f64) -> Vec<f64> {
        self.joints.iter().flat_map(|j| [j.xyz.x / mm, j.xyz.y / mm, j.xyz.z / mm, j.rotary[0], j.rotary[1]]).collect()
    }

    /// Per block of the cut the feed at the tool tip it moves at, units of `mm` millimetres per
    /// minute: the tip's way over the block's time.
    pub fn block_feeds(&self, mm: f64) -> Vec<f64> {
        self.motion
            .iter()
            .enumerate()
            .map(|(i, b)| (self.poses[i + 1].tip - self.poses[i].tip).length() / mm / b.minutes.max(1e-300))
            .collect()
    }

    /// Per block of the cut the speeds of the two rotary axes, degrees per minute; 2 numbers a block.
    pub fn rotary_speeds(&self) -> Vec<f64> {
        self.motion.iter().flat_map(|b| [b.speed(3), b.speed(4)]).collect()
    }
}

/// A program before a dialect writes it: its steps, what the dialect needs besides, and the
/// linearised path they follow.
#[derive(Debug, Clone, PartialEq)]
pub struct Plan {
    /// The steps, in order.
    pub ops: Vec<Op>,
    /// What the dialect needs besides.
    pub context: Context,
    /// The poses of the cut and their axis values.
    pub linearised: Linearised,
    /// Each block's motion.
    pub motion: Vec<BlockMotion>,
    /// What the machinist should know.
    pub warnings: Vec<Warning>,
    /// The blocks the controller moves the tool through.
    pub sweep: Vec<SweptBlock>,
    /// The target's deviation from their sweep, where a target is given.
    pub deviation: Option<EnvelopeDeviation>,
}

/// The G-code program of `path` in the dialect of the options (see the module documentation).
pub fn gcode(path: &ToolPath, o: &PostOptions) -> Result<Program> {
    gcode_reporting(path, o, &mut |_| {})
}

/// [`gcode`] telling `progress` how far it is (0 to 1), for a long job's progress bar.
pub fn gcode_reporting(path: &ToolPath, o: &PostOptions, progress: &mut dyn FnMut(f64)) -> Result<Program> {
    gcode_with(path, o, o.dialect.controller(), progress)
}

/// [`gcode_reporting`] in the words of `controller` (the options' `dialect` is not read): a
/// controller of one's own, registered as a [`Dialect`] or not.
pub fn gcode_with(
    path: &ToolPath,
    o: &PostOptions,
    controller: &dyn Controller,
    progress: &mut dyn FnMut(f64),
) -> Result<Program> {
    let Plan { ops, context, linearised: lin, motion, warnings, sweep, deviation } =
        plan_reporting(path, o, controller, progress)?;
    let u = o.units.mm();
    let stock = [(context.bounds.0 * u).to_array(), (context.bounds.1 * u).to_array()];
    let text = controller.write(&ops, &context);
    progress(1.0);
    Ok(Program {
        text,
        poses: lin.poses,
        joints: lin.joints,
        origin: lin.origin,
        unwound: lin.unwound,
        adjusted: lin.adjusted,
        motion,
        linearisation: lin.report,
        warnings,
        stock,
        sweep,
        deviation,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_warning_in_english_names_its_line_where_known() {
        let message = crate::msg!("target-three-numbers", found = 2);
        let at = Warning { pose: 3, line: Some(7), message: message.clone() };
        assert_eq!(at.text(), "expected 3 numbers for a target point (x, y, z), found 2 (line 7)");
        let anywhere = Warning { pose: 3, line: None, message };
        assert_eq!(anywhere.text(), "expected 3 numbers for a target point (x, y, z), found 2");
    }
}
