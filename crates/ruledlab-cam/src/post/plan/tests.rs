use super::*;
use crate::post::{Dialect, Holder, Numbering, SpindleDirection, Units};
use crate::Tool;

/// A path on table-table-ac with every kind of block, scale 2, tool length 25 (50 mm): the tool
/// axis (0, 0.6, 0.8) is A = atan(3/4) = 36.87°, (0, 0.8, 0.6) is 53.13°, C stays 0; the A-only
/// turns keep the axis on a great circle, so with the angles interpolated (tool-centre point)
/// nothing is inserted.
fn path() -> ToolPath {
    let deg = std::f64::consts::PI / 180.0;
    let pose = |x: f64, a: DVec3| Pose { tip: DVec3::new(x, 0.0, 0.0), axis: a };
    let (up, over) = (DVec3::new(0.0, 0.6, 0.8), DVec3::new(0.0, 0.8, 0.6));
    let small = DVec3::new(0.0, (37.17 * deg).sin(), (37.17 * deg).cos());
    ToolPath {
        poses: vec![pose(0.0, up), pose(0.0, over), pose(1.0, up), pose(6.0, small), pose(11.0, up), pose(12.0, up)],
        tool: Tool { radius: 3.0, length: 25.0, end: ToolEnd::Ball },
    }
}

fn motions(ops: &[Op]) -> Vec<Op> {
    ops.iter().filter(|op| !matches!(op, Op::Comment(_))).cloned().collect()
}

fn near(a: DVec3, b: DVec3) -> bool {
    (a - b).length() < 1e-9
}

/// How far up the axis (0, 0.6, 0.8) from the first tip of `path()` at scale 2 the clearance
/// point is: the whole cutter out of the stock, then 5 mm (the TCP test's documentation).
fn cleared() -> f64 {
    let s = (2.8 + (2.8f64 * 2.8 + 136.0).sqrt()) / 2.0;
    s - 6.0 + 5.0
}

/// The kind of each op, to compare sequences.
fn kind(op: &Op) -> String {
    match op {
        Op::Rapid(_, w) => format!("Rapid {w:?}"),
        Op::Feed(_, Rate::PerMinute(_)) => "Feed".into(),
        Op::Feed(_, Rate::Simultaneous { .. }) => "Feed turning".into(),
        other => format!("{other:?}").split(['(', ' ', '{']).next().unwrap_or("").to_string(),
    }
}

/// Tool-centre point: X Y Z are the tips in part coordinates. The machinist's order: the spindle
/// to the top of Z, the rotary axes turned there, tool-centre point on, X Y at the top of Z, Z
/// down to the safe point on the first tool axis — 25 mm above the highest tip (z = 0) plus the
/// clearance 5: part height 30, 37.5 mm up the axis, (0, 22.5, 30) —, down the axis to the
/// clearance outside the stock: the stock is the tips' box grown by 1 mm, |y|, |z| ≤ 1, which
/// the whole cutter (its ball of radius 6, centred s = t + 6 up the axis, the cylinder above)
/// leaves where the ball's centre is 6 from the box's edge (y, z) = (1, 1): (0.6s − 1)² +
/// (0.8s − 1)² = 36, s = (2.8 + √(2.8² + 136)) / 2, so 5 mm on, t = s − 1 (the tip's line alone
/// left it at t = 1.25). The approach runs at a quarter of the
/// feed. A block that turns a rotary axis takes the tip's distance at the feed (10 mm: 0.01 min),
/// or, with the tip still, the tool's far end: 50 mm × acos 0.96.
#[test]
fn a_tcp_program_takes_its_points_on_the_tool_axes_and_times_its_turns() {
    let o = PostOptions { scale: 2.0, mode: Mode::Tcp, ..PostOptions::default() };
    let p = plan(&path(), &o).unwrap();
    let ops = motions(&p.ops);
    let kinds: Vec<String> = ops.iter().map(kind).collect();
    assert_eq!(
        kinds,
        [
            "Start",
            "WorkOffset",
            "ToolChange",
            "Tolerance",
            "RetractTop",
            "Rotate",
            "Tcp",
            "Rapid Xy",
            "Rapid Z",
            "Rapid All",
            "Coolant",
            "Feed",
            "Feed turning",
            "Feed turning",
            "Feed turning",
            "Feed turning",
            "Feed",
            "Feed",
            "Coolant",
            "SpindleOff",
            "Rapid All",
            "Tcp",
            "RetractTop",
            "ToleranceOff",
            "Rotate",
            "End",
        ]
    );
    let a0 = 36.86989764584402;
    let target = |k: usize| match &ops[k] {
        Op::Rapid(t, _) | Op::Feed(t, _) => *t,
        other => panic!("{other:?}"),
    };
    assert_eq!(ops[2], Op::ToolChange { tool: 1, spindle: 10000.0, direction: SpindleDirection::Clockwise });
    assert_eq!(ops[3], Op::Tolerance { chordal: 0.01, angular: 0.0 });
    assert_eq!(ops[4], Op::RetractTop(400.0));
    let Op::Rotate(r) = ops[5] else { panic!() };
    assert!((r[0] - a0).abs() < 1e-9 && r[1] == 0.0, "{r:?}");
    // X Y at the top of Z over the safe point, on the machine's vertical through it
    let m = &o.machine;
    let (top, safe, clear) = (target(7), target(8), target(9));
    let (mt, ms) = (machine_position(m, top.xyz, r, 50.0), machine_position(m, safe.xyz, r, 50.0));
    assert!((mt.x - ms.x).abs() < 1e-9 && (mt.y - ms.y).abs() < 1e-9 && (mt.z - 400.0).abs() < 1e-9, "{mt} {ms}");
    assert!(near(safe.xyz, DVec3::new(0.0, 22.5, 30.0)), "{safe:?}");
    // (the cutter traced out of the stock to 10⁻⁶ mm)
    assert!((clear.xyz - cleared() * DVec3::new(0.0, 0.6, 0.8)).length() < 1e-5, "{clear:?}");
    assert!(near(target(11).xyz, DVec3::ZERO));
    assert_eq!(ops[11], Op::Feed(target(11), Rate::PerMinute(250.0)));
    let rate = |k: usize| match &ops[k] {
        Op::Feed(_, r) => *r,
        other => panic!("{other:?}"),
    };
    let Rate::Simultaneous { minutes, distance, linear, turn } = rate(12) else { panic!() };
    assert!((distance - 50.0 * 0.96f64.acos()).abs() < 1e-12 && linear == 0.0);
    assert!((minutes - distance / 1000.0).abs() < 1e-15 && (turn - (53.13010235415599 - a0)).abs() < 1e-9);
    // back from 53.13° to 36.87° over 2 mm: at 1000 mm/min A would turn 8130°/min; at its 5400
    // the block takes 16.26/5400 min, the tip slowed to 664 mm/min (a warning says so)
    let Rate::Simultaneous { minutes, .. } = rate(13) else { panic!() };
    assert!((minutes - (53.13010235415599 - a0) / 5400.0).abs() < 1e-12, "{minutes}");
    assert_eq!(p.warnings.len(), 1, "{:?}", p.warnings);
    assert_eq!((p.warnings[0].message.reason, p.warnings[0].pose), ("warn-slowed", 1));
    let Rate::Simultaneous { minutes, distance, .. } = rate(14) else { panic!() };
    assert!((distance - 10.0).abs() < 1e-12 && (minutes - 0.01).abs() < 1e-15);
    assert_eq!(rate(16), Rate::PerMinute(1000.0));
    // the end mirrors the start: out to the clearance, up the axis to the safe height
    let out = DVec3::new(24.0, 0.0, 0.0) + cleared() * DVec3::new(0.0, 0.6, 0.8);
    assert!((target(17).xyz - out).length() < 1e-5 && rate(17) == Rate::PerMinute(250.0));
    assert!(near(target(20).xyz, DVec3::new(24.0, 22.5, 30.0)));
    assert_eq!(ops[24], Op::Rotate([0.0, 0.0]));
    // the header: six poses, none inserted; the stock
    assert!(p.ops.contains(&Op::Comment("ruledlab tool path: 6 poses, 6 of the path and 0 inserted".into())));
    assert_eq!(p.context.bounds, (DVec3::splat(-1.0), DVec3::new(25.0, 1.0, 1.0)));
    assert_eq!((p.context.letters, p.context.mode), (["A", "C"], Mode::Tcp));
}

/// Machine coordinates: X Y Z are the machine positions, computed with the machine's pivots and
/// part zero; the rapids to the safe point write X Y, then Z; no TCP switch; the still tip's turn
/// is cut into blocks.
#[test]
fn a_machine_program_writes_machine_positions() {
    let o = PostOptions { scale: 2.0, ..PostOptions::default() };
    let p = plan(&path(), &o).unwrap();
    let ops = motions(&p.ops);
    assert!(!ops.iter().any(|op| matches!(op, Op::Tcp(_))));
    let m = &o.machine;
    let Op::Rotate(r) = ops[5] else { panic!() };
    let (Op::Rapid(xy, Words::Xy), Op::Rapid(z, Words::Z)) = (&ops[6], &ops[7]) else { panic!("{:?}", &ops[6..8]) };
    let safe = machine_position(m, DVec3::new(0.0, 22.5, 30.0), r, 50.0);
    assert!(near(xy.xyz, DVec3::new(safe.x, safe.y, 400.0)) && near(z.xyz, safe), "{xy:?} {z:?} {safe}");
    let Op::Feed(first, _) = &ops[10] else { panic!() };
    assert!(near(first.xyz, machine_position(m, DVec3::ZERO, r, 50.0)));
    let cut = p.linearised.poses.len();
    assert!(cut > 6, "the still tip's turn is cut");
    let header = format!("ruledlab tool path: {cut} poses, 6 of the path and {} inserted", cut - 6);
    assert!(p.ops.contains(&Op::Comment(header)));
}

/// The safe height may be the highest tip plus the clearance (5 mm here), not below.
#[test]
fn the_safe_height_clears_the_highest_tip_by_the_clearance() {
    let o = |h: f64| PostOptions { scale: 2.0, mode: Mode::Tcp, safe_height: Some(h), ..PostOptions::default() };
    let e = plan(&path(), &o(4.999)).unwrap_err();
    assert_eq!(e.details().option.as_deref(), Some("safeHeight"));
    let p = plan(&path(), &o(5.0)).unwrap();
    let Op::Rapid(t, Words::Z) = motions(&p.ops)[8] else { panic!() };
    // (the height 5 is t = 6.25 up the axis, short of where the whole cutter is out and clear)
    assert!((t.xyz - cleared() * DVec3::new(0.0, 0.6, 0.8)).length() < 1e-5, "{t:?}");
}

/// Each dialect says how its rotary moves are fed.
#[test]
fn the_header_says_how_rotary_moves_are_fed() {
    for (dialect, mode, says) in [
        (Dialect::Heidenhain, Mode::Tcp, "F at the tip with FUNCTION TCPM F TCP"),
        (Dialect::Heidenhain, Mode::Machine, "rotary moves get the F of X Y Z that keeps the feed at the tip"),
        (Dialect::LinuxCnc, Mode::Machine, "inverse time G93 on rotary moves"),
        (Dialect::Sinumerik, Mode::Tcp, "inverse time G93 on rotary moves"),
    ] {
        let p = plan(&path(), &PostOptions { dialect, mode, ..PostOptions::default() }).unwrap();
        let line = format!("units mm, 1 mm per model unit, feed 1000 mm/min at the tip, {says}, approach 250 mm/min");
        assert!(p.ops.contains(&Op::Comment(line)), "{dialect:?} {mode:?}: {:?}", p.ops[3]);
    }
}

/// The safe moves at the end are checked against the travel (and the retract's slope) and
/// named by the last pose of the given path. An axis within 0.1 of the horizontal has no way up.
#[test]
fn the_safe_moves_at_the_end_are_named_by_the_last_pose() {
    let tool = Tool { radius: 3.0, length: 25.0, end: ToolEnd::Ball };
    let path = |last: Pose| ToolPath {
        poses: vec![Pose { tip: DVec3::ZERO, axis: DVec3::Z }, Pose { tip: DVec3::new(10.0, 0.0, 0.0), ..last }, last],
        tool,
    };
    let o = PostOptions { mode: Mode::Tcp, ..PostOptions::default() };
    let flat = path(Pose { tip: DVec3::new(20.0, 0.0, 0.0), axis: DVec3::new(0.0, 0.9959, 0.09).normalize() });
    let Err(Error::Unreachable { pose, message, .. }) = plan(&flat, &o) else { panic!("reachable") };
    assert_eq!((pose, message.reason), (2, "retract-horizontal"));
    // the safe point beyond the top of Z: no clear approach within the travel
    let high = path(Pose { tip: DVec3::new(20.0, 0.0, 0.0), axis: DVec3::new(0.0, 0.6, 0.8) });
    let Err(Error::Unreachable { pose, message, .. }) = plan(&high, &PostOptions { safe_height: Some(450.0), ..o })
    else {
        panic!("reachable")
    };
    assert_eq!((pose, message.reason), (0, "approach-blocked"));
    // the travel stops it, and the message says so
    assert_eq!(message.arg("part"), Some(&ruledlab::Arg::Text("travel".into())));
}

/// The part in the way is named: a holder of radius 400 mm (wider than the stock's top) on a
/// tool tilted 37° reaches down into the stock wherever the tool comes down its axis.
#[test]
fn the_part_that_blocks_the_approach_is_named() {
    let p = path();
    let o = PostOptions {
        mode: Mode::Tcp,
        scale: 2.0,
        gauge: Some(60.0),
        holder: Some(Holder { radius: 400.0, length: 10.0 }),
        stock: Some([[-300.0, -300.0, -50.0], [300.0, 300.0, 1.0]]),
        ..PostOptions::default()
    };
    let Err(Error::Unreachable { message, .. }) = plan(&p, &o) else { panic!("reachable") };
    assert_eq!(message.reason, "approach-blocked");
    assert_eq!(message.arg("part"), Some(&ruledlab::Arg::Text("holder".into())), "{}", message.english());
}

/// Poses named in the input's numbering: with 4 poses of the path per input pose and the input
/// read from lines 3, 4, 5, an error at path pose 2 is at input pose 0, line 3; a warning at
/// path pose 5 (a duplicate) at input pose 1, line 4.
#[test]
fn errors_and_warnings_name_the_input_pose_and_its_line() {
    let mut p = path();
    p.poses[4] = p.poses[3];
    let numbering = Some(Numbering { stride: 4, lines: vec![3, 4, 5] });
    let o = PostOptions { mode: Mode::Tcp, numbering, ..PostOptions::default() };
    let plan = plan(&p, &o).unwrap();
    let dup: Vec<&Warning> = plan.warnings.iter().filter(|w| w.message.reason == "warn-duplicate-pose").collect();
    assert_eq!(dup.len(), 1, "{:?}", plan.warnings);
    assert_eq!((dup[0].pose, dup[0].line), (1, Some(4)));
    // no empty block: one feed fewer than poses after the approach
    let feeds = motions(&plan.ops).iter().filter(|op| matches!(op, Op::Feed(..))).count();
    assert_eq!(feeds, 1 + (plan.linearised.poses.len() - 2) + 1);
    // an axis turned to 130° from the vertical, at path pose 2: input pose 0, line 3
    let mut far = path();
    let t = 130f64.to_radians();
    far.poses[2].axis = DVec3::new(0.0, t.sin(), t.cos());
    let e = super::plan(&far, &o).unwrap_err();
    assert_eq!((e.details().index, e.details().line), (Some(0), Some(3)), "{e}");
    assert!(
        e.to_string().starts_with("pose 0 cannot be reached: A would be") && e.to_string().ends_with("(line 3)"),
        "{e}"
    );
    // the flipped axis is said
    let warned = super::plan(&far, &PostOptions { machine: Machine::preset("table-table-bc").unwrap(), ..o.clone() });
    if let Ok(w) = warned {
        assert!(w.warnings.iter().any(|w| w.message.reason == "warn-flipped-axis"), "{:?}", w.warnings);
    }
}

/// Inches: the program's lengths and feeds are the options' (25.4 mm each), the machine's
/// travel converted; the same path at 1 inch per unit gives the millimetre program's numbers at
/// 25.4 mm per unit divided by 25.4.
#[test]
fn an_inch_program_writes_inches() {
    let mm = plan(
        &path(),
        &PostOptions { scale: 25.4, feed: 2540.0, mode: Mode::Tcp, clearance: 25.4, ..PostOptions::default() },
    )
    .unwrap();
    let inch = plan(
        &path(),
        &PostOptions {
            scale: 1.0,
            feed: 100.0,
            units: Units::Inch,
            mode: Mode::Tcp,
            clearance: 1.0,
            ..PostOptions::default()
        },
    )
    .unwrap();
    assert_eq!(inch.context.units, Units::Inch);
    let (a, b) = (motions(&mm.ops), motions(&inch.ops));
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(&b) {
        match (x, y) {
            (Op::Feed(s, Rate::PerMinute(f)), Op::Feed(t, Rate::PerMinute(g))) => {
                assert!(near(s.xyz / 25.4, t.xyz) && (f / 25.4 - g).abs() < 1e-9, "{x:?} {y:?}")
            }
            (Op::Rapid(s, _), Op::Rapid(t, _)) | (Op::Feed(s, _), Op::Feed(t, _)) => {
                assert!(near(s.xyz / 25.4, t.xyz), "{x:?} {y:?}")
            }
            (Op::RetractTop(z), Op::RetractTop(w)) => assert!((z / 25.4 - w).abs() < 1e-12),
            _ => {}
        }
    }
    // the block of the first test slowed by A's speed (664 mm/min instead of 1000), in an inch
    // program: said in inches per minute
    let slowed = |o: &PostOptions| {
        let p = plan(&path(), o).unwrap();
        let w = p.warnings.iter().find(|w| w.message.reason == "warn-slowed").expect("a slowed block").clone();
        let arg = |name: &str| w.message.args.iter().find(|(n, _)| *n == name).map(|(_, v)| v.clone());
        match (arg("feed"), arg("wanted"), arg("units")) {
            (Some(Arg::Number(f)), Some(Arg::Number(w)), Some(Arg::Text(u))) => (f, w, u),
            other => panic!("{other:?}"),
        }
    };
    let (f_mm, w_mm, u_mm) = slowed(&PostOptions { scale: 2.0, mode: Mode::Tcp, ..PostOptions::default() });
    let (f_in, w_in, u_in) = slowed(&PostOptions {
        scale: 2.0 / 25.4,
        feed: 1000.0 / 25.4,
        units: Units::Inch,
        mode: Mode::Tcp,
        clearance: 5.0 / 25.4,
        ..PostOptions::default()
    });
    assert_eq!((w_mm, u_mm.as_str(), u_in.as_str()), (1000.0, "mm", "inch"));
    assert!((w_in - 1000.0 / 25.4).abs() < 1e-9 && (f_mm - 664.0).abs() < 1.0, "{w_in} {f_mm}");
    // (each rounded to a tenth)
    assert!((f_mm / 25.4 - f_in).abs() <= 0.05 + 0.05 / 25.4, "{f_mm} mm/min, {f_in} inch/min");
}

/// A holder that reaches into the stock along the cut is a warning naming the first pose; the
/// gauge length moves the head machines' positions, not the table machines'.
#[test]
fn the_holder_in_the_stock_is_said_and_the_gauge_length_is_the_kinematics() {
    // the holder from 50 to 60 mm up the axis (0, 0.6, 0.8) of the first pose: its lowest
    // point at 40 − 15 · 0.6 = 31 above the tip, below the stock's top at 36
    let stock = Some([[-10.0, -10.0, -50.0], [40.0, 40.0, 36.0]]);
    let o = PostOptions {
        mode: Mode::Tcp,
        scale: 2.0,
        gauge: Some(60.0),
        holder: Some(Holder { radius: 15.0, length: 10.0 }),
        stock,
        safe_height: Some(40.0),
        ..PostOptions::default()
    };
    let p = plan(&path(), &o).unwrap();
    let w: Vec<&Warning> = p.warnings.iter().filter(|w| w.message.reason == "warn-tool-in-stock").collect();
    assert!(
        !w.is_empty() && w.iter().any(|w| w.message.arg("part") == Some(&Arg::Text("holder".into()))),
        "{:?}",
        p.warnings
    );
    // how deep: at the first pose the holder's axis passes 2.4 mm from the stock's top edge
    // ((0, 30, 40) from (0, 30, 36), 4 mm, its part across the axis (0, 0.6, 0.8): 4 · 0.6), so
    // its radius of 15 reaches 12.6 mm in — at least, the deepest pose of the cut decides
    let holder = w.iter().find(|w| w.message.arg("part") == Some(&Arg::Text("holder".into()))).unwrap();
    let Some(Arg::Number(depth)) = holder.message.arg("depth") else { panic!("{holder:?}") };
    assert!(*depth >= 12.6 - 1e-9 && *depth <= 15.0, "{depth}");
    assert_eq!(holder.message.arg("units"), Some(&Arg::Text("mm".into())));
    assert!(p.ops.iter().any(|op| matches!(op, Op::Comment(c) if c.contains("gauge length 60.0000 mm, holder radius 15.0000 length 10.0000 mm"))));
    let head = |gauge: f64| {
        let o = PostOptions {
            machine: Machine::preset("head-table-bc").unwrap(),
            gauge: Some(gauge),
            scale: 2.0,
            ..PostOptions::default()
        };
        plan(&path(), &o).unwrap().linearised.joints[0].xyz
    };
    assert!((head(50.0) - head(80.0)).length() > 1.0);
}

/// A continuous axis ends at its nearest whole turn, a limited one at zero: the table-table
/// machine's C after a spiral of two and a half turns ends at 720° with no rapid back, the
/// fork head's limited C at 0.
#[test]
fn the_rotary_axes_end_without_a_multi_turn_rapid() {
    let poses: Vec<Pose> = (0..=90)
        .map(|k| {
            let (t, f) = (30f64.to_radians(), (10.0 * k as f64).to_radians());
            Pose {
                tip: DVec3::new(40.0 * f.cos(), 40.0 * f.sin(), 0.0),
                axis: DVec3::new(t.sin() * f.cos(), t.sin() * f.sin(), t.cos()),
            }
        })
        .collect();
    let path = ToolPath { poses, tool: Tool { radius: 3.0, length: 25.0, end: ToolEnd::Ball } };
    let p = plan(&path, &PostOptions { mode: Mode::Tcp, ..PostOptions::default() }).unwrap();
    let Some(Op::Rotate(home)) = p.ops.iter().rev().find(|op| matches!(op, Op::Rotate(_))).cloned() else { panic!() };
    let last = p.linearised.leaving(p.linearised.joints.len() - 1).rotary;
    assert_eq!(home[0], 0.0);
    assert!(
        (home[1] - last[1]).abs() <= 180.0 && home[1] % 360.0 == 0.0 && home[1].abs() >= 720.0,
        "{home:?} from {last:?}"
    );
    assert!(p.ops.iter().any(|op| matches!(op, Op::Comment(c) if c.contains("no unwinding rapid"))));
}

/// A limited axis goes home to 0 as the book says, even where it ends on a whole turn: C limited
/// to ±360 after one turn of the spiral ends at C360 and goes back to C0 (a rapid within its
/// range), with no "no unwinding rapid" comment.
#[test]
fn a_limited_axis_goes_home_to_zero() {
    let poses: Vec<Pose> = (0..=36)
        .map(|k| {
            let (t, f) = (30f64.to_radians(), (90.0 + 10.0 * k as f64).to_radians());
            Pose {
                tip: DVec3::new(40.0 * f.cos(), 40.0 * f.sin(), 0.0),
                axis: DVec3::new(t.sin() * f.cos(), t.sin() * f.sin(), t.cos()),
            }
        })
        .collect();
    let path = ToolPath { poses, tool: Tool { radius: 3.0, length: 25.0, end: ToolEnd::Ball } };
    let mut machine = Machine::preset("table-table-ac").unwrap();
    (machine.rotary[1].min, machine.rotary[1].max) = (Some(-360.0), Some(360.0));
    let p = plan(&path, &PostOptions { mode: Mode::Tcp, machine, ..PostOptions::default() }).unwrap();
    let last = p.linearised.leaving(p.linearised.joints.len() - 1).rotary;
    assert!((last[1].abs() - 360.0).abs() < 1e-6, "{last:?}");
    let Some(Op::Rotate(home)) = p.ops.iter().rev().find(|op| matches!(op, Op::Rotate(_))).cloned() else { panic!() };
    assert_eq!(home, [0.0, 0.0]);
    assert!(!p.ops.iter().any(|op| matches!(op, Op::Comment(c) if c.contains("no unwinding rapid"))));
}

/// What the bindings report of a program, in its units: the axis values of each pose (X, Y, Z
/// scaled, the rotary axes in degrees), each block's tip feed (its way over its time) and rotary
/// speeds — here of a program in inches, an inch a model unit.
#[test]
fn a_program_reports_its_axes_feeds_and_speeds_in_its_units() {
    let o = PostOptions { units: Units::Inch, feed: 100.0, clearance: 1.0, ..PostOptions::default() };
    let p = crate::post::gcode(&path(), &o).unwrap();
    let u = o.units.mm();
    assert_eq!(u, 25.4);
    let axes = p.axis_values(u);
    assert_eq!(axes.len(), 5 * p.joints.len());
    for (k, j) in p.joints.iter().enumerate() {
        assert_eq!(&axes[5 * k..5 * k + 5], &[j.xyz.x / u, j.xyz.y / u, j.xyz.z / u, j.rotary[0], j.rotary[1]]);
    }
    let feeds = p.block_feeds(u);
    assert_eq!(feeds.len(), p.motion.len());
    for (i, (f, b)) in feeds.iter().zip(&p.motion).enumerate() {
        let way = (p.poses[i + 1].tip - p.poses[i].tip).length() / u;
        assert!((f * b.minutes - way).abs() <= 1e-12 * way.max(1.0), "block {i}: {f} in/min for {} min", b.minutes);
    }
    let speeds = p.rotary_speeds();
    assert_eq!(speeds.len(), 2 * p.motion.len());
    assert!(speeds.iter().any(|&s| s > 0.0), "the A turns are in the speeds");
    assert_eq!(speeds[1], p.motion[0].speed(4));
}

/// A refined path's poses named in the input's: with 4 path poses per input pose (two steps of
/// refinement) path pose 9 is in input pose 2 (its line 30 of the file), and "between poses 9 and
/// 10" is between input poses 2 and 3; the next input pose after path pose 7 is 2, after 8 it
/// is 3, after 0 it is 1. Unrefined, a pose is its own number.
#[test]
fn a_refined_path_s_poses_are_named_in_the_input_s_numbering() {
    let numbering = Numbering { stride: 4, lines: vec![10, 20, 30, 40] };
    let refined = Namer(Some(&numbering));
    assert_eq!(refined.at(9), (2, Some(30)));
    assert_eq!([0, 7, 8, 9].map(|i| refined.next(i)), [1, 2, 3, 3]);
    let given = Namer(None);
    assert_eq!((given.at(9), given.next(9)), ((9, None), 10));
    // only "pose" and "next" are renamed; the deviation stands for every other argument
    let message = crate::msg!("linearisation-tolerance", pose = 9, next = 10, deviation = 0.5);
    let between = Error::Unreachable { pose: 9, line: None, message };
    let Error::Unreachable { pose, line, message } = refined.error(between) else { panic!("an unreachable pose") };
    assert_eq!((pose, line), (2, Some(30)));
    let number = |name: &str| message.args.iter().find(|(n, _)| *n == name).map(|(_, v)| v.clone());
    assert_eq!((number("pose"), number("next")), (Some(Arg::Number(2.0)), Some(Arg::Number(3.0))));
    assert_eq!(number("deviation"), Some(Arg::Number(0.5)));
}

/// What the plan says of its progress: 0.05 when it starts; after each round r of the
/// linearisation 0.8 − 0.75·2^−(r+1), halving what is left before 0.8; 0.85 once the blocks are
/// timed; then the sweep's share of the target done, from 0.85 to 0.95.
#[test]
fn the_plan_says_how_far_it_is() {
    let o = PostOptions { scale: 2.0, target: Some(vec![DVec3::new(3.0, 1.0, 2.0); 120]), ..PostOptions::default() };
    let mut said = Vec::new();
    plan_reporting(&path(), &o, o.dialect.controller(), &mut |f| said.push(f)).unwrap();
    assert_eq!(said[0], 0.05);
    let timed = said.iter().position(|&f| f == 0.85).unwrap();
    assert!(timed >= 2, "{said:?}");
    for (r, &f) in said[1..timed].iter().enumerate() {
        let want = 0.8 - 0.75 * 0.5f64.powi(r as i32 + 1);
        assert!((f - want).abs() < 1e-15, "round {r}: {f} against {want}");
    }
    let sweep = &said[timed + 1..];
    assert!(sweep.windows(2).all(|w| w[0] <= w[1]) && sweep.iter().all(|f| (0.85..=0.95).contains(f)), "{sweep:?}");
    assert_eq!((sweep[0], sweep[sweep.len() - 1]), (0.85, 0.95));
}

/// The blocks the program's sweep is measured over, one by one: the approach (the tool on its
/// axis from the point it comes from down to the first pose, no span along the path), each
/// block of the cut from the pose before to the next as the controller interpolates it (machine
/// axes here, from the axis values it leaves with — after an unwinding, the unwound ones), an
/// unwinding's way out along the tool axis and back at its pose, and the retract from the last
/// pose. The path turns three times around a wall on the fork head, so C unwinds once.
#[test]
fn the_program_is_swept_block_by_block() {
    let poses: Vec<Pose> = (0..=3 * 36)
        .map(|k| {
            let turn = (10.0 * k as f64).to_radians();
            let axis = DVec3::new(0.5 * turn.cos(), 0.5 * turn.sin(), 0.75f64.sqrt());
            Pose { tip: DVec3::new(0.0, 0.0, -0.1 * k as f64), axis }
        })
        .collect();
    let path = ToolPath { poses, tool: Tool { radius: 3.0, length: 25.0, end: ToolEnd::Ball } };
    let o = PostOptions { machine: Machine::preset("head-head-ac").unwrap(), ..PostOptions::default() };
    let p = plan(&path, &o).unwrap();
    let lin = &p.linearised;
    let n = lin.poses.len();
    let unwinds: Vec<usize> = (0..n).filter(|&i| lin.unwound[i].is_some()).collect();
    assert_eq!(unwinds.len(), 1, "{unwinds:?}");
    assert_eq!(p.sweep.len(), (n - 1) + 2 + unwinds.len());
    let (first, last) = (&p.sweep[0], &p.sweep[p.sweep.len() - 1]);
    assert_eq!((first.how, first.to, first.start, first.span), (Move::Straight, lin.poses[0], 0.0, 0.0));
    assert_eq!(first.from.axis, lin.poses[0].axis);
    assert_eq!((last.how, last.to, last.start, last.span), (Move::Straight, lin.poses[n - 1], (n - 1) as f64, 0.0));
    let mut k = 1;
    for i in 1..n {
        let b = &p.sweep[k];
        assert_eq!(
            (b.from, b.to, b.how, b.start, b.span),
            (lin.poses[i - 1], lin.poses[i], Move::Joints, (i - 1) as f64, 1.0)
        );
        assert_eq!(b.joints, (lin.leaving(i - 1), lin.joints[i]), "block {i}");
        k += 1;
        if unwinds.contains(&i) {
            let out = &p.sweep[k];
            assert_eq!(
                (out.how, out.to, out.start, out.span, out.joints),
                (Move::Straight, lin.poses[i], i as f64, 0.0, (lin.joints[i], lin.joints[i]))
            );
            let away = out.from.tip - lin.poses[i].tip;
            assert!(
                away.cross(lin.poses[i].axis).length() < 1e-9 && away.dot(lin.poses[i].axis) > 0.0,
                "out along the axis"
            );
            k += 1;
        }
    }
}

/// A job in inches is the job in millimetres: every length of the options given in inches
/// (25.4 mm each) — the scale, feeds, clearance, tolerance, safe height, gauge, shank, holder and
/// stock — makes the same plan in millimetres inside (the poses and axis values, the blocks'
/// times, the swept blocks and the target's deviation), and the same warnings.
#[test]
fn a_job_in_inches_is_the_job_in_millimetres() {
    let inch = 25.4;
    let mm = PostOptions {
        scale: 2.0,
        feed: 900.0,
        approach_feed: Some(300.0),
        clearance: 5.0,
        tolerance: 0.02,
        safe_height: Some(80.0),
        gauge: Some(60.0),
        shank: Some(4.0),
        holder: Some(Holder { radius: 12.0, length: 20.0 }),
        stock: Some([[-15.0, -15.0, -15.0], [40.0, 15.0, 10.0]]),
        target: Some((0..12).map(|k| DVec3::new(k as f64, 0.5, -0.2)).collect()),
        ..PostOptions::default()
    };
    let inches = PostOptions {
        units: Units::Inch,
        scale: mm.scale / inch,
        feed: mm.feed / inch,
        approach_feed: mm.approach_feed.map(|f| f / inch),
        clearance: mm.clearance / inch,
        tolerance: mm.tolerance / inch,
        safe_height: mm.safe_height.map(|h| h / inch),
        gauge: mm.gauge.map(|g| g / inch),
        shank: mm.shank.map(|r| r / inch),
        holder: mm.holder.map(|h| Holder { radius: h.radius / inch, length: h.length / inch }),
        stock: mm.stock.map(|s| s.map(|c| c.map(|x| x / inch))),
        ..mm.clone()
    };
    let (a, b) = (plan(&path(), &mm).unwrap(), plan(&path(), &inches).unwrap());
    let (la, lb) = (&a.linearised, &b.linearised);
    assert_eq!(la.poses.len(), lb.poses.len());
    for (p, q) in la.poses.iter().zip(&lb.poses) {
        assert!(near(p.tip, q.tip) && near(p.axis, q.axis), "{p:?} {q:?}");
    }
    for (j, k) in la.joints.iter().zip(&lb.joints) {
        assert!(
            near(j.xyz, k.xyz) && (j.rotary[0] - k.rotary[0]).abs() < 1e-9 && (j.rotary[1] - k.rotary[1]).abs() < 1e-9
        );
    }
    assert_eq!(a.motion.len(), b.motion.len());
    for (x, y) in a.motion.iter().zip(&b.motion) {
        assert!((x.minutes - y.minutes).abs() <= 1e-9 * x.minutes.max(1e-9), "{} {}", x.minutes, y.minutes);
    }
    assert_eq!(a.sweep.len(), b.sweep.len());
    for (x, y) in a.sweep.iter().zip(&b.sweep) {
        assert!(near(x.from.tip, y.from.tip) && near(x.to.tip, y.to.tip) && x.how == y.how);
    }
    let (da, db) = (a.deviation.as_ref().unwrap(), b.deviation.as_ref().unwrap());
    for (x, y) in da.points.iter().zip(&db.points) {
        assert!((x - y).abs() < 1e-9, "{x} {y}");
    }
    let reasons = |p: &Plan| p.warnings.iter().map(|w| w.message.reason).collect::<Vec<_>>();
    assert_eq!(reasons(&a), reasons(&b));
}
