//! Example 6's programs read by a real controller's interpreter: LinuxCNC's `rs274` (Debian's
//! `linuxcnc-uspace`, installed by `scripts/setup.sh --browser`) runs the LinuxCNC output in
//! batch mode (`rs274 -g`): the paper's example on every preset machine in both modes, a twisted
//! blade whose path passes 0.008° from the pole, and a wall milled round three times (a limited
//! C unwinds). It must report no error, and the canonical moves it prints
//! (`STRAIGHT_FEED(x, y, z, a, b, c)`, 4 decimals), put through the machine's forward
//! kinematics, must give back the poses of the program — the refined path with the poses the
//! linearisation inserted, on the path's strips, and in the pole cone the written tool axis
//! within the reported angle of the path's with the ball's centre kept — to the precision of
//! the output. The LinuxCNC rules the post follows are read back from the same output, each
//! test naming its source. The runs go in parallel.
//!
//! Without `rs274` on PATH the test says so and passes, unless `RULEDLAB_REQUIRE_RS274` is set
//! (as `scripts/test.sh` does).
#![cfg(not(target_family = "wasm"))]

#[allow(dead_code)] // the ring and the targets are measured in sweep.rs
mod jobs;

use glam::DVec3;
use ruledlab::{Scheme, Variant};
use ruledlab_cam::{
    example_tool_path, forward_kinematics, gcode, tool_axis, Joints, Machine, Mode, PostOptions, Program,
};
use ruledlab_cam::{SpindleDirection, ToolEnd, ToolPath, Units, MACHINE_PRESETS};
use std::process::Command;
use std::thread::JoinHandle;

fn rs274() -> Option<String> {
    let found = std::env::var_os("PATH")?
        .to_str()?
        .split(':')
        .map(|d| format!("{d}/rs274"))
        .find(|p| std::path::Path::new(p).is_file());
    if found.is_none() && std::env::var_os("RULEDLAB_REQUIRE_RS274").is_some() {
        panic!("rs274 (Debian linuxcnc-uspace) is not installed: run scripts/setup.sh --browser");
    }
    found
}

/// The numbers of `NAME(…)` in a line of rs274's canonical output.
fn call(line: &str, name: &str) -> Option<Vec<f64>> {
    let rest = line.split_once(&format!("{name}("))?.1;
    let inner = rest.strip_suffix(')')?;
    Some(inner.split(',').map(|x| x.trim().parse().unwrap_or(f64::NAN)).collect())
}

/// rs274 reading `text` in a folder of its own (HOME there: rs274 maps its tool table at
/// $HOME/.tool.mmap, which runs side by side would share: a bus error), on a thread: what it
/// said and the canonical output.
fn run(rs274: &str, name: &str, text: &str) -> JoinHandle<(std::process::Output, String)> {
    let dir = std::env::temp_dir().join(format!("ruledlab-rs274-{}", std::process::id())).join(name);
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("program.ngc");
    std::fs::write(&file, text).unwrap();
    let rs274 = rs274.to_string();
    std::thread::spawn(move || {
        let out = file.with_extension("txt");
        let run = Command::new(&rs274)
            .current_dir(&dir)
            .env("HOME", &dir)
            .arg("-g")
            .arg(&file)
            .arg(&out)
            .output()
            .expect("rs274 runs");
        let canon = std::fs::read_to_string(&out).unwrap_or_default();
        let _ = std::fs::remove_dir_all(&dir);
        (run, canon)
    })
}

/// rs274 ran the program to its end without a word of error.
fn ran(name: &str, run: &std::process::Output, canon: &str) {
    let said = String::from_utf8_lossy(&run.stdout).to_string() + &String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{name}: rs274 failed: {said}");
    assert!(!said.to_lowercase().contains("error") && !said.contains("Unknown"), "{name}: {said}");
    assert!(canon.contains("PROGRAM_END()"), "{name}: the program did not run to its end");
}

/// The moves rs274 made from the approach's end (the first pose) to the end of the cut, checked
/// against the program's poses: each through the machine's forward kinematics (machine mode) or
/// as the tip and the angles' axis (TCP), to the output's precision. An unwinding adds, after
/// its pose, the feed out along the axis and the feed back in to the same pose, its rotary
/// axes a whole number of turns on.
fn traces(name: &str, canon: &str, program: &Program, machine: &Machine, mode: Mode, length: f64) {
    let lines: Vec<&str> = canon.lines().collect();
    let cut = lines.iter().position(|l| l.contains("COMMENT(\"cut\")")).expect("a cut");
    let end = lines.iter().position(|l| l.contains("COMMENT(\"end of cut\")")).expect("its end");
    let first = lines[..cut].iter().rev().find_map(|l| call(l, "STRAIGHT_FEED")).expect("the approach");
    let moves: Vec<Vec<f64>> =
        std::iter::once(first).chain(lines[cut..end].iter().filter_map(|l| call(l, "STRAIGHT_FEED"))).collect();
    // what the program meant: each pose (and an unwound pose again after its feed out)
    let mut expected: Vec<Option<(usize, [f64; 2])>> = Vec::new();
    for i in 0..program.poses.len() {
        expected.push(Some((i, program.joints[i].rotary)));
        if let Some(after) = program.unwound[i] {
            expected.extend([None, Some((i, after))]);
        }
    }
    assert_eq!(moves.len(), expected.len(), "{name}");
    let letter = |k: usize| machine.rotary[k].name as usize;
    // the output's precision: 0.5e-4 mm per linear axis and 0.5e-4° per rotary axis, the angle's
    // error times the lever of the part or the head
    let angle = (0.5e-4f64).to_radians() * 2f64.sqrt();
    for (k, (mv, want)) in moves.iter().zip(&expected).enumerate() {
        let Some((i, rotary_meant)) = want else { continue };
        let pose = &program.poses[*i];
        assert_eq!(mv.len(), 6, "{name}: {mv:?}");
        let rotary = [mv[3 + letter(0)], mv[3 + letter(1)]];
        for r in 0..2 {
            assert!(
                (rotary[r] - rotary_meant[r]).abs() <= 0.5e-4 + 1e-9,
                "{name} move {k}: {rotary:?} vs {rotary_meant:?}"
            );
        }
        let xyz = DVec3::new(mv[0], mv[1], mv[2]);
        let (tip, axis) = match mode {
            Mode::Tcp => (xyz, tool_axis(machine, rotary)),
            Mode::Machine => {
                let p = forward_kinematics(machine, &Joints { xyz, rotary }, length);
                (p.tip, p.axis)
            }
        };
        let lever = match mode {
            Mode::Tcp => 0.0,
            Mode::Machine => {
                let pivots = machine.rotary.iter().map(|r| DVec3::from(r.pivot).length()).sum::<f64>();
                xyz.length() + pose.tip.length() + DVec3::from(machine.part_zero).length() + pivots + length
            }
        };
        let tip_tolerance = 0.5e-4 * 3f64.sqrt() + angle * lever;
        assert!((tip - pose.tip).length() <= tip_tolerance, "{name} move {k}: tip {tip} vs {}", pose.tip);
        assert!((axis - pose.axis).length() <= angle * 1.01, "{name} move {k}: axis {axis} vs {}", pose.axis);
    }
}

/// The program's poses are the refined path's (scaled), in order, with inserted poses on the
/// strips between them (the tip on the chord, the axis on the great-circle arc); in the pole
/// cone the tool axis is within the reported angle of the path's, and the ball's centre kept.
fn on_the_path(name: &str, program: &Program, path: &ToolPath, scale: f64) {
    let r = path.tool.radius * scale;
    let ball = path.tool.end == ToolEnd::Ball;
    let centre = |tip: DVec3, axis: DVec3| if ball { tip + r * axis } else { tip };
    let given: Vec<usize> = (0..program.poses.len()).filter(|&i| program.origin[i].fract() == 0.0).collect();
    assert_eq!(given.len(), path.poses.len(), "{name}");
    for (i, p) in program.poses.iter().enumerate() {
        let o = program.origin[i];
        let (k, s) = (o.floor() as usize, o.fract());
        let (a, b) = (&path.poses[k], &path.poses[(k + 1).min(path.poses.len() - 1)]);
        let tip = scale * (a.tip + s * (b.tip - a.tip));
        let adjusted = program.adjusted[i];
        if adjusted == 0.0 {
            assert!((p.tip - tip).length() < 1e-9, "{name} pose {i}: tip {} vs {tip}", p.tip);
        } else {
            // the ball's centre where the strip's pose would have it (its axis on the arc: the
            // inserted poses halve the arc, so at s it is the great circle's point at s)
            let theta = a.axis.angle_between(b.axis);
            let on_arc = if theta < 1e-12 {
                a.axis
            } else {
                (((1.0 - s) * theta).sin() * a.axis + (s * theta).sin() * b.axis) / theta.sin()
            };
            assert!((centre(p.tip, p.axis) - centre(tip, on_arc)).length() < 1e-6, "{name} pose {i}");
            assert!(adjusted < 1f64.to_radians(), "{name} pose {i}: {adjusted}");
        }
        // the axis in the plane of the arc's ends, between them (or turned by the cone)
        let n = a.axis.cross(b.axis);
        if n.length() > 1e-9 && adjusted == 0.0 {
            assert!(p.axis.dot(n.normalize()).abs() < 1e-9, "{name} pose {i}: off the arc's plane");
        }
    }
    assert!(program.linearisation.after.max() <= program.linearisation.tolerance);
}

/// Every preset in both modes on the paper's example (10 mm a unit), on the blade and on the
/// wall (millimetres): rs274 runs all of them, and their moves trace the refined path.
#[test]
fn rs274_runs_every_job_on_every_preset_in_both_modes_and_its_moves_give_back_the_path() {
    let Some(rs274) = rs274() else {
        eprintln!("skipped: rs274 (Debian linuxcnc-uspace) not found on PATH");
        return;
    };
    let example =
        example_tool_path(7).unwrap().refine(Scheme::Variational { n: 12, variant: Variant::Coupled }, 2).unwrap();
    let jobs = [("example", example, 10.0), ("blade", jobs::blade_refined(), 1.0), ("wall", jobs::wall(), 1.0)];
    let mut runs = Vec::new();
    for (job, path, scale) in &jobs {
        for name in MACHINE_PRESETS {
            for mode in [Mode::Machine, Mode::Tcp] {
                let machine = Machine::preset(name).unwrap();
                let o =
                    PostOptions { machine: machine.clone(), mode, scale: *scale, feed: 1200.0, ..Default::default() };
                let label = format!("{job} {name} {mode:?}");
                let program = gcode(path, &o).unwrap_or_else(|e| panic!("{label}: {e}"));
                let handle = run(&rs274, &label.replace(' ', "-"), &program.text);
                runs.push((label, path, *scale, mode, machine, program, handle));
            }
        }
    }
    let mut pole = 0;
    let mut unwinds = 0;
    for (label, path, scale, mode, machine, program, handle) in runs {
        let (out, canon) = handle.join().unwrap();
        ran(&label, &out, &canon);
        traces(&label, &canon, &program, &machine, mode, path.tool.length * scale);
        on_the_path(&label, &program, path, scale);
        pole += program.adjusted.iter().filter(|&&a| a > 0.0).count();
        unwinds += program.unwound.iter().filter(|u| u.is_some()).count();
        // no block turns a rotary axis by more than 10° (the pole's 80° swing in one block is
        // gone), and no program ends with a rapid of more than half a turn of a continuous axis
        for w in program.joints.windows(2) {
            for k in 0..2 {
                assert!((w[1].rotary[k] - w[0].rotary[k]).abs() < 10.0 || label.starts_with("wall"), "{label}: {w:?}");
            }
        }
        let last = canon.lines().rev().find_map(|l| call(l, "STRAIGHT_TRAVERSE")).expect("a last rapid");
        let before = canon.lines().rev().filter_map(|l| call(l, "STRAIGHT_TRAVERSE")).nth(1).expect("one before");
        // (a limited axis goes home to 0 as documented: a rapid within its range, less than a turn)
        for k in 3..6 {
            let limited = machine
                .rotary
                .iter()
                .find(|r| r.name.letter() == ["A", "B", "C"][k - 3])
                .is_some_and(|r| r.min.is_some() || r.max.is_some());
            if limited {
                assert!(last[k] == 0.0 && (last[k] - before[k]).abs() < 360.0, "{label}: {before:?} → {last:?}");
            } else {
                assert!((last[k] - before[k]).abs() <= 180.0, "{label}: {before:?} → {last:?}");
            }
        }
    }
    assert!(pole > 0, "the blade passes the pole");
    assert!(unwinds > 0, "the fork head unwinds on the wall");
}

/// One program of the blade on the fork head in TCP mode, with the options given.
fn blade_program(o: PostOptions) -> Program {
    gcode(&jobs::blade_refined(), &PostOptions { machine: Machine::preset("head-head-ac").unwrap(), feed: 1200.0, ..o })
        .unwrap()
}

/// LinuxCNC's rules, read back from rs274's canonical output:
/// - `G64 P… Q0`: path blending within the chordal tolerance, the naive CAM detector off (the
///   LinuxCNC G-code reference, "G64 Path Blending": "Set Q to zero to disable the Naive CAM
///   Detector") — rs274 says `SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, 0.005000)` and
///   `SET_NAIVECAM_TOLERANCE(0.0000)`;
/// - the kinematics switched to the tool-centre point with `M68 E3 Q1` and `M66 E0 L0`, back with
///   `M68 E3 Q0` (LinuxCNC's "Switchable Kinematics" chapter, "G-/M-code commands": analog
///   output 3 wired to `motion.switchkins-type`, M66 forcing the interpreter and motion into
///   step) — `SET_AUX_OUTPUT_VALUE(3,1.000000)` before the cut's first move, `(3,0.000000)`
///   after its last; no such switch in machine mode;
/// - `M4` turns the spindle counter-clockwise (`START_SPINDLE_COUNTERCLOCKWISE`), `G20` sets
///   inches (`USE_LENGTH_UNITS(CANON_UNITS_INCHES)`; LinuxCNC's G-code reference, G20/G21).
#[test]
fn linuxcnc_tolerance_kinematics_switch_spindle_and_units_as_rs274_reads_them() {
    let Some(rs274) = rs274() else {
        eprintln!("skipped: rs274 (Debian linuxcnc-uspace) not found on PATH");
        return;
    };
    let tcp = blade_program(PostOptions {
        mode: Mode::Tcp,
        tolerance: 0.005,
        direction: SpindleDirection::CounterClockwise,
        ..Default::default()
    });
    let machine = blade_program(PostOptions { mode: Mode::Machine, ..Default::default() });
    let inch = blade_program(PostOptions {
        mode: Mode::Tcp,
        units: Units::Inch,
        scale: 1.0 / 25.4,
        feed: 50.0,
        clearance: 0.2,
        ..Default::default()
    });
    let handles = [("tcp", &tcp), ("machine", &machine), ("inch", &inch)].map(|(n, p)| (n, run(&rs274, n, &p.text)));
    let canon: Vec<(&str, String)> = handles
        .into_iter()
        .map(|(n, h)| {
            let (out, canon) = h.join().unwrap();
            ran(n, &out, &canon);
            (n, canon)
        })
        .collect();
    let (t, m, i) = (&canon[0].1, &canon[1].1, &canon[2].1);
    assert!(
        t.contains("SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, 0.005000)")
            && t.contains("SET_NAIVECAM_TOLERANCE(0.0000)"),
        "{t}"
    );
    assert!(t.contains("START_SPINDLE_COUNTERCLOCKWISE(") && !t.contains("START_SPINDLE_CLOCKWISE("));
    let at = |text: &str, what: &str| text.lines().position(|l| l.contains(what));
    let (on, off) = (
        at(t, "SET_AUX_OUTPUT_VALUE(3,1.000000)").expect("on"),
        at(t, "SET_AUX_OUTPUT_VALUE(3,0.000000)").expect("off"),
    );
    let (cut, end) = (at(t, "COMMENT(\"cut\")").unwrap(), at(t, "COMMENT(\"end of cut\")").unwrap());
    assert!(on < cut && end < off, "the tool-centre point is on for the whole cut");
    assert!(!m.contains("SET_AUX_OUTPUT_VALUE(3,") && m.contains("START_SPINDLE_CLOCKWISE("));
    assert!(i.contains("USE_LENGTH_UNITS(CANON_UNITS_INCHES)"), "{i}");
    // the header says the kinematics and the INI lines the machine needs
    for (name, kins) in
        [("table-table-ac", Some("xyzac-trt-kins")), ("table-table-bc", Some("xyzbc-trt-kins")), ("head-head-ac", None)]
    {
        let o =
            PostOptions { machine: Machine::preset(name).unwrap(), mode: Mode::Tcp, scale: 10.0, ..Default::default() };
        // the header's comments as one text (long ones wrap onto lines of their own)
        let text = gcode(&example_tool_path(5).unwrap(), &o).unwrap().text.replace(")\n(  ", " ");
        match kins {
            Some(k) => assert!(
                text.contains(&format!("[KINS] KINEMATICS = {k} sparm=identityfirst"))
                    && text.contains("motion.switchkins-type"),
                "{name}"
            ),
            None => assert!(
                text.contains("no kinematics module of LinuxCNC 2.9 is this machine's tool-centre point"),
                "{name}"
            ),
        }
    }
}
