//! A five-axis machine as the G-code post sees it (Example 6's tool paths on a real machine):
//! two rotary axes, each on the table or on the head, their limits, where they turn, the travel
//! of the linear axes, and where the part's zero sits on the table.
//!
//! **Frames.** The machine frame has the axes X, Y, Z of the linear slides; lengths in mm,
//! angles in degrees. With every rotary axis at its zero the part frame is the machine frame
//! moved by `partZero` (axes parallel), and the tool points along +Z from its tip into the
//! spindle. The tool tip then sits at the machine position (X, Y, Z) the program gives (the
//! controller's tool-length offset puts the controlled point at the tip).
//!
//! **A rotary axis** A, B or C turns about a line parallel to machine X, Y or Z through its
//! `pivot`. A controller value v turns by the geometric angle θ = direction · (v − zero) about
//! that line, counter-clockwise seen from its positive end: x ↦ c + R(u, θ)(x − c), u the unit
//! vector of X, Y or Z and c the pivot. A table axis turns the part; its pivot is a point in the
//! machine frame (rotary axes at zero). A head axis turns the tool; its pivot is measured from the
//! spindle nose (the gauge line) with the head at zero, so the tip of a tool of length L sits at
//! −L·Z from the nose and the distance pivot–tip grows with the tool.
//!
//! **Order.** `rotary[0]` is the first axis of the chain from the machine's base: when both
//! axes are on the same side, the first carries the second (a trunnion's tilt axis carries the
//! rotary table; a fork head's C carries its A).
//!
//! **Presets** (values in the table of docs/src/cam/machines.md): `table-table-ac` (a trunnion: A tilts the table
//! about X, C turns it about Z), `table-table-bc` (B tilts about Y, C on it), `head-table-bc`
//! (the head swivels B about Y, the table turns C), `head-head-ac` (a fork head: C about Z carries
//! A about X).

use crate::tolerance::MAX_MACHINE_VALUE;
use glam::{DMat3, DVec3};
use ruledlab::{Error, Result};

/// The name of a rotary axis: A turns about a line parallel to X, B to Y, C to Z.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "tsify", derive(tsify_next::Tsify))]
pub enum AxisName {
    /// About X.
    A,
    /// About Y.
    B,
    /// About Z.
    C,
}

impl AxisName {
    /// The unit vector of the machine axis it turns about.
    pub fn direction(self) -> DVec3 {
        match self {
            AxisName::A => DVec3::X,
            AxisName::B => DVec3::Y,
            AxisName::C => DVec3::Z,
        }
    }

    /// "A", "B" or "C".
    pub fn letter(self) -> &'static str {
        match self {
            AxisName::A => "A",
            AxisName::B => "B",
            AxisName::C => "C",
        }
    }
}

/// What a rotary axis turns: the part (table) or the tool (head).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "kebab-case"))]
#[cfg_attr(feature = "tsify", derive(tsify_next::Tsify))]
pub enum Carrier {
    /// The axis turns the table and the part on it.
    Table,
    /// The axis turns the spindle head and the tool in it.
    Head,
}

/// One rotary axis of a machine.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "camelCase", deny_unknown_fields))]
#[cfg_attr(feature = "tsify", derive(tsify_next::Tsify))]
pub struct RotaryAxis {
    /// "A" (about a line parallel to X), "B" (Y) or "C" (Z); also the word of the G-code.
    pub name: AxisName,
    /// "table" (turns the part) or "head" (turns the tool).
    pub on: Carrier,
    /// +1: a growing value turns counter-clockwise seen from the positive end of the axis; −1:
    /// clockwise (default +1).
    #[cfg_attr(feature = "serde", serde(default = "plus_one"))]
    pub direction: f64,
    /// The controller value (degrees) at which the axis stands at its zero position (default 0).
    #[cfg_attr(feature = "serde", serde(default))]
    pub zero: f64,
    /// The smallest controller value (degrees); absent or null: no limit (a continuous axis).
    #[cfg_attr(feature = "serde", serde(default))]
    pub min: Option<f64>,
    /// The largest controller value (degrees); absent or null: no limit.
    #[cfg_attr(feature = "serde", serde(default))]
    pub max: Option<f64>,
    /// A point on the axis of rotation, mm: in the machine frame for a table axis, from the
    /// spindle nose for a head axis (all axes at zero; default [0, 0, 0]).
    #[cfg_attr(feature = "serde", serde(default))]
    pub pivot: [f64; 3],
    /// Its largest speed, degrees per minute; absent or null: no limit. The post slows every
    /// block that would turn the axis faster.
    #[cfg_attr(feature = "serde", serde(default))]
    pub speed: Option<f64>,
    /// Its largest acceleration, degrees per second²; absent or null: no limit. Blocks whose
    /// change of speed needs more are slowed.
    #[cfg_attr(feature = "serde", serde(default))]
    pub acceleration: Option<f64>,
}

#[cfg(feature = "serde")]
fn plus_one() -> f64 {
    1.0
}

impl RotaryAxis {
    /// The geometric angle (radians) of controller value `v` (degrees): direction · (v − zero).
    pub fn angle(&self, v: f64) -> f64 {
        (self.direction * (v - self.zero)).to_radians()
    }

    /// The controller value (degrees) of geometric angle `theta` (radians), before unwrapping.
    pub fn value(&self, theta: f64) -> f64 {
        self.zero + self.direction * theta.to_degrees()
    }

    /// The rotation R(u, θ) of controller value `v`.
    pub fn rotation(&self, v: f64) -> DMat3 {
        DMat3::from_axis_angle(self.name.direction(), self.angle(v))
    }

    /// Whether `v` is within the limits.
    pub fn allows(&self, v: f64) -> bool {
        self.min.is_none_or(|m| v >= m - 1e-9) && self.max.is_none_or(|m| v <= m + 1e-9)
    }
}

/// A five-axis machine for the G-code post: its two rotary axes (`rotary`, the first of the
/// chain from the base first), the travel of X, Y, Z and where the part's zero sits on the table.
/// Lengths in mm, angles in degrees; at zero the part frame is the machine frame moved by
/// `partZero`, and the tool points along +Z (docs/src/cam/machines.md).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "camelCase", deny_unknown_fields))]
#[cfg_attr(feature = "tsify", derive(tsify_next::Tsify))]
pub struct Machine {
    /// A name for the program's header (default "custom").
    #[cfg_attr(feature = "serde", serde(default = "custom"))]
    pub name: String,
    /// The two rotary axes, the first of the chain from the machine's base first (when both are
    /// on the same side, the first carries the second).
    pub rotary: [RotaryAxis; 2],
    /// Travel of X, Y and Z, [[min, max] × 3] in mm (machine frame, tool tip with the rotary axes
    /// at zero).
    pub travel: [[f64; 2]; 3],
    /// Where the part's zero sits, in the machine frame with the rotary axes at zero, mm.
    pub part_zero: [f64; 3],
    /// The largest speeds of X, Y and Z, mm/min; absent or null: no limit.
    #[cfg_attr(feature = "serde", serde(default))]
    pub speed: Option<[f64; 3]>,
    /// The largest accelerations of X, Y and Z, mm/s²; absent or null: no limit.
    #[cfg_attr(feature = "serde", serde(default))]
    pub acceleration: Option<[f64; 3]>,
}

#[cfg(feature = "serde")]
fn custom() -> String {
    "custom".to_string()
}

/// The names of the presets, in the order of [`Machine::preset`].
pub const MACHINE_PRESETS: [&str; 4] = ["table-table-ac", "table-table-bc", "head-table-bc", "head-head-ac"];

/// A preset's rotary axis: its limits (degrees), pivot (mm), speed (degrees/min) and
/// acceleration (degrees/s²).
fn axis(
    name: AxisName,
    on: Carrier,
    limits: (Option<f64>, Option<f64>),
    pivot: [f64; 3],
    dynamics: [f64; 2],
) -> RotaryAxis {
    let [speed, acceleration] = dynamics.map(Some);
    RotaryAxis { name, on, direction: 1.0, zero: 0.0, min: limits.0, max: limits.1, pivot, speed, acceleration }
}

impl Machine {
    /// A preset by name (see [`MACHINE_PRESETS`]), or `None`.
    pub fn preset(name: &str) -> Option<Machine> {
        use AxisName::{A, B, C};
        use Carrier::{Head, Table};
        let free = (None, None);
        let (rotary, travel) = match name {
            // a trunnion: the tilt axis 80 mm below the table top, the rotary table on it; the
            // tilt 15 turns a minute (5400°/min), the table 30 (10800°/min)
            "table-table-ac" => (
                [
                    axis(A, Table, (Some(-30.0), Some(120.0)), [0.0, 0.0, -80.0], [5400.0, 720.0]),
                    axis(C, Table, free, [0.0; 3], [10800.0, 1440.0]),
                ],
                [[-500.0, 500.0], [-400.0, 400.0], [-400.0, 400.0]],
            ),
            "table-table-bc" => (
                [
                    axis(B, Table, (Some(-110.0), Some(110.0)), [0.0, 0.0, -80.0], [5400.0, 720.0]),
                    axis(C, Table, free, [0.0; 3], [10800.0, 1440.0]),
                ],
                [[-500.0, 500.0], [-400.0, 400.0], [-400.0, 400.0]],
            ),
            // a swivel head, its B axis 150 mm above the spindle nose; a rotary table
            "head-table-bc" => (
                [
                    axis(B, Head, (Some(-95.0), Some(95.0)), [0.0, 0.0, 150.0], [3600.0, 540.0]),
                    axis(C, Table, free, [0.0; 3], [10800.0, 1440.0]),
                ],
                [[-800.0, 800.0], [-600.0, 600.0], [-500.0, 600.0]],
            ),
            // a fork head: C (two turns of cable) carries A, whose axis is 120 mm above the nose
            "head-head-ac" => (
                [
                    axis(C, Head, (Some(-360.0), Some(360.0)), [0.0; 3], [7200.0, 720.0]),
                    axis(A, Head, (Some(-110.0), Some(110.0)), [0.0, 0.0, 120.0], [7200.0, 720.0]),
                ],
                [[-1500.0, 1500.0], [-1000.0, 1000.0], [-600.0, 800.0]],
            ),
            _ => return None,
        };
        Some(Machine {
            name: name.to_string(),
            rotary,
            travel,
            part_zero: [10.0, -5.0, 25.0],
            // X, Y, Z: 30 m/min, 3 m/s²
            speed: Some([30000.0; 3]),
            acceleration: Some([3000.0; 3]),
        })
    }

    /// Checks the description: distinct axes, direction ±1, finite numbers below 1e7, min < max.
    pub fn validate(&self) -> Result<()> {
        let bad = |what: String| Err(Error::parameter("machine", what));
        let [r0, r1] = &self.rotary;
        if r0.name == r1.name {
            return bad(format!("the two rotary axes must differ, both are {}", r0.name.letter()));
        }
        let finite = |x: f64| x.is_finite() && x.abs() <= MAX_MACHINE_VALUE;
        for r in &self.rotary {
            let n = r.name.letter();
            if r.direction != 1.0 && r.direction != -1.0 {
                return bad(format!("rotary axis {n}: direction must be 1 or -1, got {}", r.direction));
            }
            if !finite(r.zero) || !r.pivot.iter().all(|&x| finite(x)) {
                return bad(format!("rotary axis {n}: zero and pivot must be finite numbers of at most 1e7"));
            }
            if !r.min.is_none_or(finite) || !r.max.is_none_or(finite) {
                return bad(format!("rotary axis {n}: limits must be finite numbers of at most 1e7, or null"));
            }
            if let (Some(lo), Some(hi)) = (r.min, r.max) {
                if lo >= hi {
                    return bad(format!("rotary axis {n}: min must be below max, got [{lo}, {hi}]"));
                }
            }
            for (what, v) in [("speed", r.speed), ("acceleration", r.acceleration)] {
                if !v.is_none_or(|x| finite(x) && x > 0.0) {
                    return bad(format!("rotary axis {n}: {what} must be a positive number of at most 1e7, or null"));
                }
            }
        }
        for (what, v) in [("speed", self.speed), ("acceleration", self.acceleration)] {
            if !v.is_none_or(|xyz| xyz.iter().all(|&x| finite(x) && x > 0.0)) {
                return bad(format!("{what} must be three positive numbers of at most 1e7 (X, Y, Z), or null"));
            }
        }
        for (k, [lo, hi]) in self.travel.iter().enumerate() {
            let n = ["X", "Y", "Z"][k];
            if !finite(*lo) || !finite(*hi) || lo >= hi {
                return bad(format!("travel of {n} must be [min, max] with finite min < max, got [{lo}, {hi}]"));
            }
        }
        if !self.part_zero.iter().all(|&x| finite(x)) {
            return bad("partZero must be three finite numbers of at most 1e7".to_string());
        }
        Ok(())
    }

    /// The rotary axes on the table, the first of the chain first.
    pub fn table_axes(&self) -> Vec<usize> {
        (0..2).filter(|&k| self.rotary[k].on == Carrier::Table).collect()
    }

    /// The rotary axes on the head, the first of the chain first.
    pub fn head_axes(&self) -> Vec<usize> {
        (0..2).filter(|&k| self.rotary[k].on == Carrier::Head).collect()
    }

    /// A short description for a program's header: "table-table-ac: A on the table about X
    /// (-30 to 120 deg), C on the table about Z (continuous)".
    pub fn describe(&self) -> String {
        let one = |r: &RotaryAxis| {
            let on = match r.on {
                Carrier::Table => "table",
                Carrier::Head => "head",
            };
            let about = ["X", "Y", "Z"][r.name as usize];
            let limits = match (r.min, r.max) {
                (None, None) => "continuous".to_string(),
                (lo, hi) => format!(
                    "{} to {} deg",
                    lo.map_or("-inf".to_string(), |v| format!("{v}")),
                    hi.map_or("inf".to_string(), |v| format!("{v}"))
                ),
            };
            format!("{} on the {on} about {about} ({limits})", r.name.letter())
        };
        format!("{}: {}, {}", self.name, one(&self.rotary[0]), one(&self.rotary[1]))
    }
}

/// x ↦ c + R(x − c) for the rotary axis `r` at controller value `v`.
pub(crate) fn turn(r: &RotaryAxis, v: f64, x: DVec3, pivot: DVec3) -> DVec3 {
    pivot + r.rotation(v) * (x - pivot)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_are_valid_and_named() {
        for name in MACHINE_PRESETS {
            let m = Machine::preset(name).unwrap();
            m.validate().unwrap();
            assert_eq!(m.name, name);
        }
        assert!(Machine::preset("table-table-xy").is_none());
    }

    #[test]
    fn validation_names_what_is_wrong() {
        let mut m = Machine::preset("table-table-ac").unwrap();
        m.rotary[1].name = AxisName::A;
        assert!(m.validate().unwrap_err().to_string().contains("must differ"));
        let mut m = Machine::preset("table-table-ac").unwrap();
        m.rotary[0].direction = 2.0;
        assert!(m.validate().unwrap_err().to_string().contains("direction must be 1 or -1"));
        let mut m = Machine::preset("table-table-ac").unwrap();
        m.travel[2] = [5.0, -5.0];
        assert!(m.validate().unwrap_err().to_string().contains("travel of Z"));
        let mut m = Machine::preset("table-table-ac").unwrap();
        m.rotary[0].min = Some(f64::NAN);
        assert!(m.validate().is_err());
    }

    #[test]
    fn a_value_and_its_angle_agree() {
        let r = RotaryAxis {
            name: AxisName::B,
            on: Carrier::Head,
            direction: -1.0,
            zero: 90.0,
            min: None,
            max: None,
            pivot: [0.0; 3],
            speed: None,
            acceleration: None,
        };
        assert!((r.value(r.angle(37.0)) - 37.0).abs() < 1e-12);
        assert!((r.angle(90.0)).abs() < 1e-15);
    }

    #[test]
    fn presets_describe_their_axes_and_limits() {
        let described: Vec<String> = MACHINE_PRESETS.iter().map(|n| Machine::preset(n).unwrap().describe()).collect();
        assert_eq!(
            described,
            [
                "table-table-ac: A on the table about X (-30 to 120 deg), C on the table about Z (continuous)",
                "table-table-bc: B on the table about Y (-110 to 110 deg), C on the table about Z (continuous)",
                "head-table-bc: B on the head about Y (-95 to 95 deg), C on the table about Z (continuous)",
                "head-head-ac: C on the head about Z (-360 to 360 deg), A on the head about X (-110 to 110 deg)",
            ]
        );
        let mut one_sided = Machine::preset("table-table-ac").unwrap();
        one_sided.rotary[0].min = None;
        assert!(one_sided.describe().contains("A on the table about X (-inf to 120 deg)"));
        one_sided.rotary[0] = RotaryAxis { min: Some(-30.0), max: None, ..one_sided.rotary[0] };
        assert!(one_sided.describe().contains("(-30 to inf deg)"));
    }

    /// Each check alone refuses its machine: numbers up to 1e7 in size, not beyond; direction
    /// −1 is as good as 1; a bad zero with a good pivot, a bad travel minimum with a good maximum.
    #[test]
    fn each_check_of_a_machine_stands_alone() {
        let ok = || Machine::preset("table-table-ac").unwrap();
        let refused = |change: &dyn Fn(&mut Machine)| {
            let mut m = ok();
            change(&mut m);
            m.validate().is_err()
        };
        assert!(!refused(&|m| m.rotary[0].direction = -1.0));
        assert!(!refused(&|m| m.rotary[0].zero = -1e7));
        assert!(refused(&|m| m.rotary[0].zero = 1e7 * (1.0 + 1e-15)));
        assert!(refused(&|m| m.rotary[1].zero = f64::NAN));
        assert!(refused(&|m| m.rotary[1].pivot[2] = f64::INFINITY));
        assert!(refused(&|m| m.rotary[0].max = Some(2e7)));
        assert!(refused(&|m| m.travel[0] = [f64::NAN, 100.0]));
        assert!(refused(&|m| m.travel[1] = [-100.0, f64::INFINITY]));
        assert!(refused(&|m| m.part_zero[2] = -2e7));
        // speeds and accelerations positive, or no limit
        assert!(!refused(&|m| m.rotary[0].speed = None));
        assert!(!refused(&|m| m.speed = None));
        assert!(refused(&|m| m.rotary[1].speed = Some(0.0)));
        assert!(refused(&|m| m.rotary[0].acceleration = Some(-1.0)));
        assert!(refused(&|m| m.speed = Some([1000.0, f64::NAN, 1000.0])));
        assert!(refused(&|m| m.acceleration = Some([1000.0, 1000.0, 0.0])));
    }

    /// Limits are kept to within 1e-9°, a value's rounding, and no further.
    #[test]
    fn limits_allow_a_rounding_beyond_them() {
        let a = Machine::preset("table-table-ac").unwrap().rotary[0];
        for (v, allowed) in
            [(-30.0 - 0.5e-9, true), (120.0 + 0.5e-9, true), (-30.0 - 2e-9, false), (120.0 + 2e-9, false)]
        {
            assert_eq!(a.allows(v), allowed, "{v}");
        }
        assert!(!a.allows(-31.0) && !a.allows(121.0) && a.allows(45.0));
    }

    /// The presets are the machines their comments describe: a trunnion's tilt axis 80 mm
    /// below the table top, a swivel head's B 150 mm and a fork head's A 120 mm above the
    /// spindle nose, the C axes through the origin; every part's zero at (10, −5, 25).
    #[test]
    fn presets_have_their_pivots_and_part_zero() {
        let pivots = |name: &str| Machine::preset(name).unwrap().rotary.map(|r| r.pivot);
        assert_eq!(pivots("table-table-ac"), [[0.0, 0.0, -80.0], [0.0; 3]]);
        assert_eq!(pivots("table-table-bc"), [[0.0, 0.0, -80.0], [0.0; 3]]);
        assert_eq!(pivots("head-table-bc"), [[0.0, 0.0, 150.0], [0.0; 3]]);
        assert_eq!(pivots("head-head-ac"), [[0.0; 3], [0.0, 0.0, 120.0]]);
        for name in MACHINE_PRESETS {
            assert_eq!(Machine::preset(name).unwrap().part_zero, [10.0, -5.0, 25.0], "{name}");
        }
    }
}
