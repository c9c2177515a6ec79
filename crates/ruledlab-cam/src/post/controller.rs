//! A controller's language: what the post asks of a dialect, one implementor per file
//! (`linuxcnc.rs`, `heidenhain.rs`, `sinumerik.rs`), and the [`Dialect`] a job picks them by.
//!
//! The post plans a program in no dialect (`plan.rs`: [`Op`]s with a [`Context`]) and asks the
//! controller four things on the way:
//! - **how it interpolates the tool axis** under tool-centre-point control
//!   ([`Controller::orientation`]): the rotary angles linearly (Heidenhain's `FUNCTION TCPM …
//!   AXIS POS`, LinuxCNC's switchable kinematics) or the axis as a vector on a great circle
//!   (Sinumerik's `ORIVECT`). The linearisation checks that interpolation against the path
//!   (`linearise.rs`), and a controller that reads the axis as a vector cannot be told a turn by
//!   whole turns: it unwinds with its transformation off (X Y Z held), the others with the tip
//!   held in the part;
//! - **its feed word**: unbounded (inverse time `G93`, F = 1/T in 1/min, on the blocks that turn
//!   a rotary axis), or bounded ([`Controller::max_feed`]), then a block's F is its measure
//!   ([`Controller::feed_measure`]: the tip's distance, or what the controller refers F to)
//!   over its time, and a block is slowed rather than written with more (`motion.rs`); a feed
//!   beyond the bound is refused by the options' check;
//! - **what the header says** of the controller's setup ([`Controller::machine_mode`],
//!   [`Controller::tcp_mode`], [`Controller::feed_words`]);
//! - **the program's text** ([`Controller::write`]): LinuxCNC and Sinumerik write ISO G-code
//!   with one writer ([`iso::program`]) and their own words ([`Iso`]).
//!
//! Adding a controller is one file with its implementor, plus a variant of [`Dialect`] and its
//! arm in [`Dialect::controller`] (and the name the bindings read). A controller of one's own
//! posts with [`gcode_with`](super::gcode_with) without being registered.

use crate::machine::Machine;

// the controllers of the dialects: to post with, or to build another on (one that says most
// words as one of them does)
pub use super::heidenhain::Heidenhain;
pub use super::linuxcnc::LinuxCnc;
pub use super::sinumerik::Sinumerik;

// what a controller is given and writes with
pub use super::iso::{self, Iso};
pub use super::ops::{Context, Op, Rate, Waypoint, Words};
pub use super::options::{Coolant, Mode, SpindleDirection, Units};
pub use super::text::{clean, comment_lines, decimals, number, speed, COMMENT_WIDTH};

/// How a controller under tool-centre-point control is given the tool axis, and so how it
/// interpolates it between two blocks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Orientation {
    /// The rotary axes' angles, interpolated linearly with the tip.
    Angles,
    /// The axis as a vector in the part frame, interpolated on a great circle: the controller
    /// picks the rotary values.
    Vector,
}

/// What a block covers, for a bounded feed word: lengths in mm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Travel {
    /// Whether the block turns a rotary axis (a change at the program's decimals).
    pub turning: bool,
    /// The tip's distance (the tool's far end's for a still tip that turns).
    pub distance: f64,
    /// The distance of X, Y, Z as written.
    pub linear: f64,
    /// The rotary axes' turn: the length of the vector of their moves, degrees.
    pub turn: f64,
}

/// The header's words for machine coordinates where the controller assumes nothing more.
pub const MACHINE_MODE: &str =
    "mode: machine coordinates - X Y Z are the machine position of the tip, the work offset must be 0";

/// A five-axis controller's language (module documentation). Object safe: the post takes a
/// `&dyn Controller`.
pub trait Controller {
    /// The controller as a message names it after "for": "a Heidenhain TNC", "LinuxCNC".
    fn name(&self) -> &str;

    /// How it interpolates the tool axis under tool-centre-point control.
    fn orientation(&self) -> Orientation;

    /// The largest F its feed word reads, program units per minute (`None`, the default: not
    /// bounded; the blocks that turn a rotary axis then carry inverse time).
    fn max_feed(&self) -> Option<f64> {
        None
    }

    /// The measure a block's F divides by its time where the feed word is bounded, in program
    /// units (`units`), or degrees where the controller refers F to the rotary axes. The
    /// default: the tip's distance.
    fn feed_measure(&self, mode: Mode, travel: &Travel, units: Units) -> f64 {
        let _ = mode;
        travel.distance / units.mm()
    }

    /// The header's words on the feed of rotary moves, as "inverse time G93 on rotary moves".
    fn feed_words(&self, mode: Mode) -> &'static str;

    /// The header's line on machine coordinates: what the controller must be set to (the
    /// default: [`MACHINE_MODE`]).
    fn machine_mode(&self) -> String {
        MACHINE_MODE.to_string()
    }

    /// The header's lines on tool-centre-point control: how it is switched, what the controller
    /// must be set up with for `machine`.
    fn tcp_mode(&self, machine: &Machine) -> Vec<String>;

    /// The program's text.
    fn write(&self, ops: &[Op], context: &Context) -> String;
}

/// The controller's language a job picks ([`PostOptions::dialect`](super::PostOptions)).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dialect {
    /// LinuxCNC (rs274ngc): `( )` comments, no block numbers.
    LinuxCnc,
    /// Heidenhain TNC plain text (Klartext): `BEGIN PGM … MM`, numbered blocks, `;` comments.
    Heidenhain,
    /// Siemens Sinumerik 840D: `N10 …` blocks, `;` comments.
    Sinumerik,
}

impl Dialect {
    /// Its controller: the registry of the dialects.
    pub fn controller(self) -> &'static dyn Controller {
        match self {
            Dialect::LinuxCnc => &LinuxCnc,
            Dialect::Heidenhain => &Heidenhain,
            Dialect::Sinumerik => &Sinumerik,
        }
    }
}
