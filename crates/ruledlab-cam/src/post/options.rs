//! The options of the post: the controller's dialect, the mode (who does the kinematics), the
//! machine, the program's units, the job's tool, feeds, spindle, coolant, tolerances and stock,
//! each checked against its bounds and refused by its name.

use super::{Controller, Dialect};
use crate::machine::Machine;
use crate::tolerance::{MAX_MACHINE_VALUE, MIN_LINEARISATION_TOLERANCE};
use ruledlab::{Error, Result};

/// Who does the kinematics.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// The controller (tool-centre-point control).
    Tcp,
    /// ruledlab: machine coordinates.
    Machine,
}

/// The coolant switched on for the cut.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Coolant {
    /// Flood (`M8`).
    Flood,
    /// Mist (`M7`).
    Mist,
    /// None.
    Off,
}

/// The units of the program and of the job's lengths.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Units {
    /// Millimetres (`G21`, `MM`, `G71`).
    Mm,
    /// Inches (`G20`, `INCH`, `G70`): 25.4 mm.
    Inch,
}

impl Units {
    /// Millimetres per unit.
    pub fn mm(self) -> f64 {
        match self {
            Units::Mm => 1.0,
            Units::Inch => 25.4,
        }
    }

    /// "mm" or "inch".
    pub fn word(self) -> &'static str {
        match self {
            Units::Mm => "mm",
            Units::Inch => "inch",
        }
    }
}

/// The spindle's direction seen from the spindle towards the tool.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpindleDirection {
    /// Clockwise (`M3`).
    Clockwise,
    /// Counter-clockwise (`M4`).
    CounterClockwise,
}

/// A tool holder: a cylinder ending at the gauge line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Holder {
    /// Radius (program units).
    pub radius: f64,
    /// Length along the axis, down from the gauge line (program units).
    pub length: f64,
}

/// How the input the path was refined from numbers its poses: errors and warnings name the
/// input's pose and its line.
#[derive(Debug, Clone, PartialEq)]
pub struct Numbering {
    /// Poses of the path per pose of the input (2^steps of refinement; 1: the input itself).
    pub stride: usize,
    /// The 1-based line of each input pose in its file (empty: not read from a file).
    pub lines: Vec<usize>,
}

/// Options of the post. Lengths are in the program's `units` (feeds per minute); the path's
/// model units are multiplied by `scale`.
#[derive(Debug, Clone, PartialEq)]
pub struct PostOptions {
    /// The dialect (default LinuxCNC).
    pub dialect: Dialect,
    /// The mode (default machine coordinates).
    pub mode: Mode,
    /// The machine (default the preset `table-table-ac`).
    pub machine: Machine,
    /// The program's units (default millimetres); every length of these options is in them.
    pub units: Units,
    /// Feed at the tool tip, units/min (default 1000).
    pub feed: f64,
    /// Feed of the approach along the tool axis, units/min (default a quarter of the feed).
    pub approach_feed: Option<f64>,
    /// Units per model unit of the path (default 1).
    pub scale: f64,
    /// Tool number (default 1).
    pub tool: u32,
    /// Spindle speed, 1/min (default 10000).
    pub spindle: f64,
    /// The spindle's direction (default clockwise).
    pub direction: SpindleDirection,
    /// Coolant (default flood).
    pub coolant: Coolant,
    /// Work offset 1–6: G54–G59, Heidenhain's datum 1–6 (default 1).
    pub work_offset: u32,
    /// Least height above the part's zero (part Z) of the point on the tool axis where the safe
    /// moves turn (default 25 above the highest tip plus the clearance); the point is raised
    /// further where the stock, turned by the rotary axes, stands higher.
    pub safe_height: Option<f64>,
    /// Distance kept from the stock along the tool axis, covered at the approach feed
    /// (default 5 mm; 0.2 in, [`PostOptions::defaults_in`]).
    pub clearance: f64,
    /// Largest deviation of the controller's interpolation from the path, the tip's and the
    /// axis's times the gauge length (default 0.01 mm; 0.0004 in, [`PostOptions::defaults_in`]):
    /// the chordal tolerance.
    pub tolerance: f64,
    /// Largest angle of the interpolated tool axis from the path's, degrees (default none).
    pub angular_tolerance: Option<f64>,
    /// The gauge length: spindle nose to the tip, the length the kinematics and the
    /// controller's length offset use (default the tool's length times the scale).
    pub gauge: Option<f64>,
    /// The holder (default none: not checked).
    pub holder: Option<Holder>,
    /// The shank's radius, from the cutter's length up to the holder (default the tool's).
    pub shank: Option<f64>,
    /// The stock, a box in the part frame: [min, max] corners (default the tips' box grown by
    /// 1 mm).
    pub stock: Option<[[f64; 3]; 2]>,
    /// Half-angle of the pole cone, degrees (default 1; 0: only the pole itself).
    pub pole_cone: f64,
    /// The numbering of the input the path was refined from (default: the path's own).
    pub numbering: Option<Numbering>,
    /// Program name, letters, digits and `_` (default "RULEDLAB").
    pub name: String,
    /// The part's points the program is measured against, model units like the path (default
    /// none): the deviation of the program as posted (`sweep.rs`), in the result and the header.
    pub target: Option<Vec<glam::DVec3>>,
}

impl Default for PostOptions {
    fn default() -> Self {
        PostOptions {
            dialect: Dialect::LinuxCnc,
            mode: Mode::Machine,
            machine: Machine::preset("table-table-ac").unwrap_or_else(|| unreachable!("a preset")),
            units: Units::Mm,
            feed: 1000.0,
            approach_feed: None,
            scale: 1.0,
            tool: 1,
            spindle: 10000.0,
            direction: SpindleDirection::Clockwise,
            coolant: Coolant::Flood,
            work_offset: 1,
            safe_height: None,
            clearance: 5.0,
            tolerance: 0.01,
            angular_tolerance: None,
            gauge: None,
            holder: None,
            shank: None,
            stock: None,
            pole_cone: 1.0,
            numbering: None,
            name: "RULEDLAB".to_string(),
            target: None,
        }
    }
}

impl PostOptions {
    /// The defaults for a program in `units`: in millimetres [`PostOptions::default`]; in inches
    /// the tolerance 0.0004 in and the clearance 0.2 in a machinist writes (the millimetre
    /// defaults, 0.01 mm and 5 mm, to the nearest ten-thousandth and tenth of an inch: 0.01 mm is
    /// 0.000 39 in, 5 mm 0.197 in), the other lengths' defaults already derived from the job.
    pub fn defaults_in(units: Units) -> Self {
        match units {
            Units::Mm => PostOptions::default(),
            Units::Inch => PostOptions { units, tolerance: 0.0004, clearance: 0.2, ..PostOptions::default() },
        }
    }
}

fn check(name: &'static str, value: f64, positive: bool) -> Result<()> {
    let ok = value.is_finite() && value.abs() <= MAX_MACHINE_VALUE && (!positive || value > 0.0);
    if ok {
        Ok(())
    } else if positive {
        Err(Error::parameter(name, format!("must be a positive number of at most 1e7, got {value}")))
    } else {
        Err(Error::parameter(name, format!("must be a finite number of at most 1e7, got {value}")))
    }
}

/// Validates the options for a program in `controller`'s words (its feed word's range).
pub fn validate(o: &PostOptions, controller: &dyn Controller) -> Result<()> {
    check("feed", o.feed, true)?;
    if let Some(f) = o.approach_feed {
        check("approachFeed", f, true)?;
    }
    if let Some(max) = controller.max_feed() {
        for (name, f) in [("feed", Some(o.feed)), ("approachFeed", o.approach_feed)] {
            if let Some(f) = f.filter(|&f| f > max) {
                return Err(Error::parameter(
                    name,
                    format!("must be at most {max} a minute for {}, got {f}", controller.name()),
                ));
            }
        }
    }
    check("scale", o.scale, true)?;
    check("spindle", o.spindle, true)?;
    check("clearance", o.clearance, true)?;
    check("tolerance", o.tolerance, true)?;
    if o.tolerance * o.units.mm() < MIN_LINEARISATION_TOLERANCE {
        return Err(Error::parameter(
            "tolerance",
            format!(
                "must be at least {MIN_LINEARISATION_TOLERANCE} mm (the programs print 1e-4 mm), got {}",
                o.tolerance
            ),
        ));
    }
    if let Some(a) = o.angular_tolerance {
        check("angularTolerance", a, true)?;
    }
    if let Some(h) = o.safe_height {
        check("safeHeight", h, false)?;
    }
    if let Some(g) = o.gauge {
        check("gauge", g, true)?;
    }
    if let Some(h) = o.holder {
        check("holder.radius", h.radius, true)?;
        check("holder.length", h.length, true)?;
    }
    if let Some(s) = o.shank {
        check("shank", s, true)?;
    }
    if let Some([lo, hi]) = o.stock {
        for k in 0..3 {
            check("stock", lo[k], false)?;
            check("stock", hi[k], false)?;
            if lo[k] >= hi[k] {
                return Err(Error::parameter(
                    "stock",
                    format!("must be [min, max] corners with min < max, got {lo:?}, {hi:?}"),
                ));
            }
        }
    }
    if !(o.pole_cone.is_finite() && (0.0..=30.0).contains(&o.pole_cone)) {
        return Err(Error::parameter(
            "poleCone",
            format!("must be a number of degrees from 0 to 30, got {}", o.pole_cone),
        ));
    }
    if !(1..=99999).contains(&o.tool) {
        return Err(Error::parameter("tool", format!("must be an integer from 1 to 99999, got {}", o.tool)));
    }
    if !(1..=6).contains(&o.work_offset) {
        return Err(Error::parameter("workOffset", format!("must be an integer from 1 to 6, got {}", o.work_offset)));
    }
    let n = &o.name;
    if n.is_empty() || n.len() > 24 || !n.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Err(Error::parameter("name", format!("must be 1 to 24 letters, digits or _, got \"{n}\"")));
    }
    if let Some(t) = &o.target {
        if t.is_empty() || t.iter().any(|q| !q.is_finite() || q.abs().max_element() > MAX_MACHINE_VALUE) {
            return Err(Error::parameter("target", "must be at least one point of finite coordinates of at most 1e7"));
        }
    }
    if let Some(nb) = &o.numbering {
        if nb.stride == 0 {
            return Err(Error::parameter("numbering", "the stride must be at least 1".to_string()));
        }
    }
    o.machine.validate()
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn units() {
        assert_eq!((Units::Inch.mm(), Units::Mm.word()), (25.4, "mm"));
    }

    /// The inch defaults are the millimetre ones to a machinist's round inches: 0.0004 in within
    /// 0.0001 in of 0.01 mm, 0.2 in within 0.01 in of 5 mm.
    #[test]
    fn inch_defaults_are_the_millimetre_ones_in_round_inches() {
        let (mm, inch) = (PostOptions::defaults_in(Units::Mm), PostOptions::defaults_in(Units::Inch));
        assert_eq!(mm, PostOptions::default());
        assert_eq!((inch.units, inch.tolerance, inch.clearance), (Units::Inch, 0.0004, 0.2));
        assert!((inch.tolerance * 25.4 - mm.tolerance).abs() < 0.0001 * 25.4);
        assert!((inch.clearance * 25.4 - mm.clearance).abs() < 0.01 * 25.4);
        assert_eq!(validate(&inch, inch.dialect.controller()).err(), None);
    }

    #[test]
    fn options_are_refused_by_name_at_their_bounds() {
        let option = |o: PostOptions| validate(&o, o.dialect.controller()).err().and_then(|e| e.details().option);
        let base = PostOptions::default;
        assert_eq!(option(base()), None);
        // positive numbers of at most 1e7
        for (name, set) in [
            ("feed", (|o: &mut PostOptions, x| o.feed = x) as fn(&mut PostOptions, f64)),
            ("approachFeed", |o, x| o.approach_feed = Some(x)),
            ("scale", |o, x| o.scale = x),
            ("spindle", |o, x| o.spindle = x),
            ("clearance", |o, x| o.clearance = x),
            ("angularTolerance", |o, x| o.angular_tolerance = Some(x)),
            ("gauge", |o, x| o.gauge = Some(x)),
            ("shank", |o, x| o.shank = Some(x)),
            ("holder.radius", |o, x| o.holder = Some(Holder { radius: x, length: 10.0 })),
            ("holder.length", |o, x| o.holder = Some(Holder { radius: 10.0, length: x })),
        ] {
            for bad in [0.0, -1.0, 1e7 * (1.0 + 1e-15), f64::NAN, f64::INFINITY] {
                let mut o = base();
                set(&mut o, bad);
                assert_eq!(option(o).as_deref(), Some(name), "{name} = {bad}");
            }
            let mut o = base();
            set(&mut o, 1e7);
            assert_eq!(option(o), None, "{name} = 1e7");
        }
        // the safe height may be zero or negative, not beyond 1e7
        for (h, ok) in [(0.0, true), (-20.0, true), (-1e7, true), (-2e7, false), (f64::NAN, false)] {
            assert_eq!(option(PostOptions { safe_height: Some(h), ..base() }).is_none(), ok, "safe height {h}");
        }
        // the tolerance from 1e-4 mm (in inches: from 1e-4 / 25.4)
        assert_eq!(option(PostOptions { tolerance: 1e-4, ..base() }), None);
        assert_eq!(option(PostOptions { tolerance: 0.99e-4, ..base() }).as_deref(), Some("tolerance"));
        assert_eq!(option(PostOptions { tolerance: 1e-5, units: Units::Inch, ..base() }), None);
        assert_eq!(option(PostOptions { tolerance: 3e-6, units: Units::Inch, ..base() }).as_deref(), Some("tolerance"));
        // the pole cone 0–30°, a stock with min < max
        for (cone, ok) in [(0.0, true), (30.0, true), (-0.1, false), (31.0, false), (f64::NAN, false)] {
            assert_eq!(option(PostOptions { pole_cone: cone, ..base() }).is_none(), ok, "cone {cone}");
        }
        assert_eq!(
            option(PostOptions { stock: Some([[0.0; 3], [1.0, 1.0, 0.0]]), ..base() }).as_deref(),
            Some("stock")
        );
        assert_eq!(option(PostOptions { stock: Some([[0.0; 3], [1.0; 3]]), ..base() }), None);
        // a Heidenhain feed word reads up to 99 999.999 mm/min
        let tnc = |feed: f64, units| PostOptions { dialect: Dialect::Heidenhain, feed, units, ..base() };
        assert_eq!(option(tnc(99_999.999, Units::Mm)), None);
        assert_eq!(option(tnc(100_000.0, Units::Mm)).as_deref(), Some("feed"));
        assert_eq!(option(tnc(100_000.0, Units::Inch)).as_deref(), Some("feed"));
        let e = validate(&tnc(100_000.0, Units::Mm), &super::super::heidenhain::Heidenhain).unwrap_err();
        assert_eq!(e.to_string(), "feed: must be at most 99999.999 a minute for a Heidenhain TNC, got 100000");
        // tool 1–99999, work offset 1–6, a name of 1 to 24 letters, digits or _
        for (o, name) in [
            (PostOptions { tool: 0, ..base() }, "tool"),
            (PostOptions { tool: 100_000, ..base() }, "tool"),
            (PostOptions { work_offset: 0, ..base() }, "workOffset"),
            (PostOptions { work_offset: 7, ..base() }, "workOffset"),
            (PostOptions { name: String::new(), ..base() }, "name"),
            (PostOptions { name: "A".repeat(25), ..base() }, "name"),
            (PostOptions { name: "A B".into(), ..base() }, "name"),
            (PostOptions { numbering: Some(Numbering { stride: 0, lines: vec![] }), ..base() }, "numbering"),
        ] {
            assert_eq!(option(o).as_deref(), Some(name));
        }
        // target points: at least one, every coordinate finite and of at most 1e7
        let target = |t: Vec<DVec3>| option(PostOptions { target: Some(t), ..base() });
        assert_eq!(target(vec![]).as_deref(), Some("target"));
        assert_eq!(target(vec![DVec3::ZERO, DVec3::new(-1e7, 1e7, 0.0)]), None);
        for bad in
            [DVec3::new(0.0, 0.0, 1e7 * (1.0 + 1e-15)), DVec3::new(-2e7, 0.0, 0.0), DVec3::new(0.0, f64::NAN, 0.0)]
        {
            assert_eq!(target(vec![DVec3::ONE, bad]).as_deref(), Some("target"), "{bad}");
        }
        for o in [
            PostOptions { tool: 99_999, work_offset: 6, name: "Z_9".repeat(8), ..base() },
            PostOptions { tool: 1, work_offset: 1, name: "a".into(), ..base() },
        ] {
            assert_eq!(option(o), None);
        }
    }
}
