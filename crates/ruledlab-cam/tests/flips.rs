//! A flip of the rotary axes inside a cut is refused in every dialect and mode, naming the axis
//! and its limit: on a table–table B/C machine with C limited to −90…90 a tool tilted 17.36° whose
//! C would run from −80° to −100° must swing B to −17.36° and C round by 180° to stay within
//! C's limits (the other solution of the orientation); with C continuous the same path posts.
//! Sinumerik's `ORIVECT` (the tool axis as a vector, its own axes) makes the same jump: "Siemens
//! SINUMERIK 840D sl, Programming Manual Job Planning, 'Orientation axes, ORIVECT'" — the
//! controller's transformation picks the rotary values, and only one of its two solutions stays
//! within C's limits.
#![cfg(not(target_family = "wasm"))]

use glam::DVec3;
use ruledlab::{Arg, Error};
use ruledlab_cam::{gcode, tool_axis, Dialect, Machine, Mode, Pose, PostOptions, Tool, ToolEnd, ToolPath};

fn machine(limited: bool) -> Machine {
    let mut m = Machine::preset("table-table-bc").unwrap();
    let c = m.rotary.iter().position(|r| r.name.letter() == "C").unwrap();
    if limited {
        (m.rotary[c].min, m.rotary[c].max) = (Some(-90.0), Some(90.0));
    }
    m
}

/// 11 poses 3 mm apart along X, the tool axis that of B 17.36°, C −80° … −100°.
fn path(m: &Machine) -> ToolPath {
    let b = m.rotary.iter().position(|r| r.name.letter() == "B").unwrap();
    let poses = (0..=10)
        .map(|k| {
            let mut rotary = [0.0; 2];
            rotary[b] = 17.36;
            rotary[1 - b] = -80.0 - 2.0 * k as f64;
            Pose { tip: DVec3::new(3.0 * k as f64, 0.0, 0.0), axis: tool_axis(m, rotary) }
        })
        .collect();
    ToolPath { poses, tool: Tool::new(3.0, 30.0, ToolEnd::Ball).unwrap() }
}

#[test]
fn a_flip_inside_the_cut_is_refused_naming_the_axis_and_its_limit() {
    let free = machine(false);
    let p = path(&free);
    for dialect in [Dialect::LinuxCnc, Dialect::Heidenhain, Dialect::Sinumerik] {
        for mode in [Mode::Machine, Mode::Tcp] {
            // with C continuous: no flip, the program is written
            let o = PostOptions { dialect, mode, machine: free.clone(), ..Default::default() };
            assert!(gcode(&p, &o).is_ok(), "{dialect:?} {mode:?}: {:?}", gcode(&p, &o).err());
            let o = PostOptions { dialect, mode, machine: machine(true), ..Default::default() };
            let e = gcode(&p, &o).unwrap_err();
            let Error::Unreachable { pose, message, .. } = &e else { panic!("{dialect:?} {mode:?}: {e}") };
            assert_eq!(message.reason, "flip-in-cut", "{dialect:?} {mode:?}: {e}");
            let arg = |n: &str| message.arg(n).cloned();
            assert_eq!(arg("axis"), Some(Arg::Text("C".into())), "{e}");
            assert_eq!(arg("tilt"), Some(Arg::Text("B".into())), "{e}");
            assert_eq!((arg("min"), arg("max")), (Some(Arg::Number(-90.0)), Some(Arg::Number(90.0))), "{e}");
            // C reaches −90 at pose 5 and would pass it after: the flip comes at pose 4 or 5, C
            // on the side it leaves at −88 … −92
            assert!((4..=5).contains(pose), "{e}");
            let Some(Arg::Number(v)) = arg("value") else { panic!("{e}") };
            assert!((-92.0..=-88.0).contains(&v), "{e}");
            let text = e.to_string();
            assert!(
                text.contains("at or beyond its limits -90 to 90") && text.contains("B from 17.36 to -17.36"),
                "{text}"
            );
        }
    }
}

/// The same flip on a B axis whose controller counts from another zero, or the other way round:
/// the same poses, the same axis and limit named, B's values as the controller writes them.
#[test]
fn a_flip_is_found_and_said_whatever_the_tilting_axis_counts_from() {
    for (zero, direction) in [(-30.0, 1.0), (25.0, -1.0), (-30.0, -1.0)] {
        let counted = |mut m: Machine| {
            let b = m.rotary.iter().position(|r| r.name.letter() == "B").unwrap();
            (m.rotary[b].zero, m.rotary[b].direction) = (zero, direction);
            // its limits, −110° … 110°, as it counts them
            let (lo, hi) = (-110.0 * direction + zero, 110.0 * direction + zero);
            (m.rotary[b].min, m.rotary[b].max) = (Some(f64::min(lo, hi)), Some(f64::max(lo, hi)));
            (m, b)
        };
        let (m, b) = counted(machine(true));
        // the path of the first test: B tilted 17.36°, as this B counts it
        let p = ToolPath { poses: path(&machine(true)).poses, tool: Tool::new(3.0, 30.0, ToolEnd::Ball).unwrap() };
        let o =
            PostOptions { dialect: Dialect::LinuxCnc, mode: Mode::Machine, machine: m.clone(), ..Default::default() };
        let e = gcode(&p, &o).unwrap_err();
        let Error::Unreachable { pose, message, .. } = &e else { panic!("{zero} {direction}: {e}") };
        assert_eq!(message.reason, "flip-in-cut", "{zero} {direction}: {e}");
        let arg = |n: &str| message.arg(n).cloned();
        assert_eq!(arg("axis"), Some(Arg::Text("C".into())), "{e}");
        assert!((4..=5).contains(pose), "{e}");
        let Some(Arg::Number(v)) = arg("value") else { panic!("{e}") };
        assert!((-92.0..=-88.0).contains(&v), "{zero} {direction}: {e}");
        // B from +17.36° to −17.36°, in the controller's counting
        let value = |degrees: f64| m.rotary[b].value(f64::to_radians(degrees));
        let near = |a: Option<Arg>, want: f64| matches!(a, Some(Arg::Number(x)) if (x - want).abs() < 0.01);
        assert!(near(arg("from"), value(17.36)) && near(arg("to"), value(-17.36)), "{zero} {direction}: {e}");
        // with C continuous, the same path posts
        let (free, _) = counted(machine(false));
        assert!(gcode(&p, &PostOptions { machine: free, ..o }).is_ok(), "{zero} {direction}");
    }
}

/// C limited to 270° … 450° (−90° … 90° a turn on): the same flip, C's value said within the
/// turn of its limits (268°, where staying on the same side would take it below 270°).
#[test]
fn the_limited_axis_is_said_within_the_turn_of_its_limits() {
    let mut m = machine(true);
    let c = m.rotary.iter().position(|r| r.name.letter() == "C").unwrap();
    (m.rotary[c].min, m.rotary[c].max) = (Some(270.0), Some(450.0));
    let p = path(&machine(true));
    let o = PostOptions { dialect: Dialect::LinuxCnc, mode: Mode::Machine, machine: m, ..Default::default() };
    let e = gcode(&p, &o).unwrap_err();
    let Error::Unreachable { pose, message, .. } = &e else { panic!("{e}") };
    assert_eq!(message.reason, "flip-in-cut", "{e}");
    assert!((4..=5).contains(pose), "{e}");
    let arg = |n: &str| message.arg(n).cloned();
    assert_eq!((arg("min"), arg("max")), (Some(Arg::Number(270.0)), Some(Arg::Number(450.0))), "{e}");
    let Some(Arg::Number(v)) = arg("value") else { panic!("{e}") };
    assert!((268.0..=272.0).contains(&v), "{e}");
}

/// The mirror image: B tilted −17.36° (the other solution at B +17.36°, C 180° round), C from
/// −80° on: the flip is said from the side B starts on; with B limited to −15° and above, B
/// stands a turn away (342.64°) and the side is still its tilt's, −17.36°.
#[test]
fn a_flip_from_a_negative_tilt_is_said_from_that_side() {
    let mirror = |m: &Machine| {
        let b = m.rotary.iter().position(|r| r.name.letter() == "B").unwrap();
        let mut p = path(m);
        for (k, pose) in p.poses.iter_mut().enumerate() {
            let mut rotary = [0.0; 2];
            (rotary[b], rotary[1 - b]) = (-17.36, -80.0 - 2.0 * k as f64);
            pose.axis = tool_axis(m, rotary);
        }
        p
    };
    let mut above = machine(true);
    let b = above.rotary.iter().position(|r| r.name.letter() == "B").unwrap();
    (above.rotary[b].min, above.rotary[b].max) = (Some(-15.0), None);
    for (m, from, to) in [(machine(true), -17.36, 17.36), (above, 342.64, 377.36)] {
        let p = mirror(&machine(true));
        let o = PostOptions { dialect: Dialect::LinuxCnc, mode: Mode::Machine, machine: m, ..Default::default() };
        let e = gcode(&p, &o).unwrap_err();
        let Error::Unreachable { message, .. } = &e else { panic!("{e}") };
        assert_eq!(message.reason, "flip-in-cut", "{e}");
        let arg = |n: &str| message.arg(n).cloned();
        assert_eq!((arg("axis"), arg("tilt")), (Some(Arg::Text("C".into())), Some(Arg::Text("B".into()))), "{e}");
        let near = |a: Option<Arg>, want: f64| matches!(a, Some(Arg::Number(x)) if (x - want).abs() < 0.01);
        assert!(near(arg("from"), from) && near(arg("to"), to), "{e}");
        let Some(Arg::Number(v)) = arg("value") else { panic!("{e}") };
        assert!((-92.0..=-88.0).contains(&v), "{e}");
    }
}

/// B limited on one side only (B ≤ 15°): it takes a turn within that (B −342.64° for 17.36°:
/// the same orientation), so it blocks nothing, and the flip names C, the axis that does, on the
/// side B leaves.
#[test]
fn an_axis_limited_on_one_side_only_is_never_said_to_block() {
    let mut m = machine(true);
    let b = m.rotary.iter().position(|r| r.name.letter() == "B").unwrap();
    (m.rotary[b].min, m.rotary[b].max) = (None, Some(15.0));
    let p = path(&machine(true));
    let o = PostOptions { dialect: Dialect::LinuxCnc, mode: Mode::Machine, machine: m, ..Default::default() };
    let e = gcode(&p, &o).unwrap_err();
    let Error::Unreachable { message, .. } = &e else { panic!("{e}") };
    assert_eq!(message.reason, "flip-in-cut", "{e}");
    assert_eq!(message.arg("axis").cloned(), Some(Arg::Text("C".into())), "{e}");
    // the same side is B's +17.36° (which this B writes −342.64°): C there at −88° … −92°
    let Some(Arg::Number(v)) = message.arg("value").cloned() else { panic!("{e}") };
    assert!((-92.0..=-88.0).contains(&v), "{e}");
}

/// C the other way, from 80° up: the flip comes where C would pass its upper limit, 90°, and is
/// said with C on the side it leaves, at 88° … 92°.
#[test]
fn a_flip_at_the_upper_limit_names_it() {
    let m = machine(true);
    let b = m.rotary.iter().position(|r| r.name.letter() == "B").unwrap();
    let mut p = path(&m);
    for (k, pose) in p.poses.iter_mut().enumerate() {
        let mut rotary = [0.0; 2];
        (rotary[b], rotary[1 - b]) = (17.36, 80.0 + 2.0 * k as f64);
        pose.axis = tool_axis(&m, rotary);
    }
    let o = PostOptions { dialect: Dialect::LinuxCnc, mode: Mode::Machine, machine: m, ..Default::default() };
    let e = gcode(&p, &o).unwrap_err();
    let Error::Unreachable { pose, message, .. } = &e else { panic!("{e}") };
    assert_eq!((message.reason, message.arg("axis").cloned()), ("flip-in-cut", Some(Arg::Text("C".into()))), "{e}");
    assert!((4..=5).contains(pose), "{e}");
    let Some(Arg::Number(v)) = message.arg("value").cloned() else { panic!("{e}") };
    assert!((88.0..=92.0).contains(&v), "{e}");
}
