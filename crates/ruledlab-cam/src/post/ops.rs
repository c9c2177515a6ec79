//! A program in no dialect yet: its steps ([`Op`]), where each block goes ([`Waypoint`]), its feed
//! ([`Rate`]), and what a controller needs to know besides ([`Context`]). The plan (`plan.rs`)
//! makes them; a [`Controller`](super::Controller) writes them in its words.

use super::{Coolant, Mode, SpindleDirection, Units};
use glam::DVec3;

/// Where a block goes: X Y Z as written (part frame in TCP mode, machine frame otherwise), the
/// rotary values, the tool axis in the part frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Waypoint {
    /// X, Y, Z as written.
    pub xyz: DVec3,
    /// The rotary axes' values.
    pub rotary: [f64; 2],
    /// The tool axis, part frame.
    pub axis: DVec3,
}

/// The feed of a block.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Rate {
    /// Units per minute, no rotary axis moving (or TCP with the feed at the tip).
    PerMinute(f64),
    /// A block that turns a rotary axis: it takes `minutes`; the tip's distance (the far end's
    /// for a still tip), the distance of X, Y, Z as written, and the rotary axes' turn (the
    /// length of the vector of their moves, degrees) for the dialects whose feed word refers
    /// to one of them.
    Simultaneous {
        /// The block's time, minutes.
        minutes: f64,
        /// The tip's distance.
        distance: f64,
        /// The distance of X, Y, Z as written.
        linear: f64,
        /// The rotary axes' turn, degrees.
        turn: f64,
    },
}

/// Which words a rapid writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Words {
    /// X and Y (machine mode; in TCP mode all).
    Xy,
    /// Z (machine mode; in TCP mode all).
    Z,
    /// X, Y, Z and the orientation.
    All,
}

/// One step of a program, written by each dialect in its own words.
#[derive(Debug, Clone, PartialEq)]
pub enum Op {
    /// A comment.
    Comment(String),
    /// The program's start: units, absolute coordinates, plane.
    Start,
    /// The controller's continuous-path mode with the chordal tolerance (program units) and
    /// the angular one (degrees).
    Tolerance {
        /// Chordal tolerance.
        chordal: f64,
        /// Tolerance of the tool axis, degrees.
        angular: f64,
    },
    /// The end of that mode (where a dialect has one).
    ToleranceOff,
    /// The work offset 1–6.
    WorkOffset(u32),
    /// Tool change with length offset, and the spindle on.
    ToolChange {
        /// Tool number.
        tool: u32,
        /// Spindle speed.
        spindle: f64,
        /// Its direction.
        direction: SpindleDirection,
    },
    /// Rapid to the top of Z in machine coordinates (or out along the tool axis to the limit).
    RetractTop(f64),
    /// Rapid of the rotary axes only.
    Rotate([f64; 2]),
    /// Tool-centre-point control on or off.
    Tcp(bool),
    /// Rapid move, with the words it writes.
    Rapid(Waypoint, Words),
    /// Feed move.
    Feed(Waypoint, Rate),
    /// Coolant on (the kind) or off.
    Coolant(Coolant),
    /// Spindle off.
    SpindleOff,
    /// Program end.
    End,
}

/// What a dialect needs to know besides the ops.
#[derive(Debug, Clone, PartialEq)]
pub struct Context {
    /// The rotary axes' letters.
    pub letters: [&'static str; 2],
    /// The mode.
    pub mode: Mode,
    /// The program's name.
    pub name: String,
    /// The stock's box (part frame, program units): the blank for Heidenhain's BLK FORM.
    pub bounds: (DVec3, DVec3),
    /// The program's units.
    pub units: Units,
}
