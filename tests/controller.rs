//! Example 6's programs read by a real controller's interpreter: LinuxCNC's `rs274` (Debian's
//! `linuxcnc-uspace`, installed by `scripts/setup.sh --browser`) runs the LinuxCNC output of
//! every preset machine in both modes, in batch mode (`rs274 -g`). It must report no error, and
//! the canonical moves it prints (`STRAIGHT_FEED(x, y, z, a, b, c)`, 4 decimals), put through
//! the machine's forward kinematics, must give back the poses of the program — the refined path
//! with the poses the linearisation inserted, each of those on the path's strip — to the
//! precision of the output. The eight runs go in parallel.
//!
//! Without `rs274` on PATH the test says so and passes, unless `RULEDLAB_REQUIRE_RS274` is set
//! (as `scripts/test.sh` does).
#![cfg(not(target_family = "wasm"))]

use glam::DVec3;
use ruledlab::{example_tool_path, forward_kinematics, gcode, tool_axis, Joints, Machine, Mode, PostOptions};
use ruledlab::{Scheme, Variant, MACHINE_PRESETS};
use std::process::Command;

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

#[test]
fn rs274_runs_every_preset_in_both_modes_and_its_moves_give_back_the_path() {
    let Some(rs274) = rs274() else {
        eprintln!("skipped: rs274 (Debian linuxcnc-uspace) not found on PATH");
        return;
    };
    let path =
        example_tool_path(7).unwrap().refine(Scheme::Variational { n: 12, variant: Variant::Coupled }, 2).unwrap();
    let dir = std::env::temp_dir().join(format!("ruledlab-rs274-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let runs: Vec<_> = MACHINE_PRESETS
        .iter()
        .flat_map(|name| [(*name, Mode::Machine), (*name, Mode::Tcp)])
        .map(|(name, mode)| {
            let machine = Machine::preset(name).unwrap();
            let o = PostOptions { machine: machine.clone(), mode, scale: 10.0, feed: 1200.0, ..Default::default() };
            let program = gcode(&path, &o).unwrap_or_else(|e| panic!("{name} {mode:?}: {e}"));
            // a folder each, and HOME there: rs274 maps its tool table at $HOME/.tool.mmap, which
            // runs side by side would share (a bus error)
            let own = dir.join(format!("{name}-{mode:?}"));
            std::fs::create_dir_all(&own).unwrap();
            let file = own.join("program.ngc");
            std::fs::write(&file, &program.text).unwrap();
            let rs274 = rs274.clone();
            let handle = std::thread::spawn(move || {
                let out = file.with_extension("txt");
                let run = Command::new(&rs274)
                    .current_dir(file.parent().expect("a folder"))
                    .env("HOME", file.parent().expect("a folder"))
                    .arg("-g")
                    .arg(&file)
                    .arg(&out)
                    .output()
                    .expect("rs274 runs");
                (run, std::fs::read_to_string(&out).unwrap_or_default())
            });
            (name, mode, machine, program, handle)
        })
        .collect();
    for (name, mode, machine, program, handle) in runs {
        let (run, canon) = handle.join().unwrap();
        let said = String::from_utf8_lossy(&run.stdout).to_string() + &String::from_utf8_lossy(&run.stderr);
        assert!(run.status.success(), "{name} {mode:?}: rs274 failed: {said}");
        assert!(!said.to_lowercase().contains("error") && !said.contains("Unknown"), "{name} {mode:?}: {said}");
        assert!(canon.contains("PROGRAM_END()"), "{name} {mode:?}: the program did not run to its end");
        // the feed moves from the approach's end (the first pose) to the end of the cut
        let lines: Vec<&str> = canon.lines().collect();
        let cut = lines.iter().position(|l| l.contains("COMMENT(\"cut\")")).expect("a cut");
        let end = lines.iter().position(|l| l.contains("COMMENT(\"end of cut\")")).expect("its end");
        let first = lines[..cut].iter().rev().find_map(|l| call(l, "STRAIGHT_FEED")).expect("the approach");
        let moves: Vec<Vec<f64>> =
            std::iter::once(first).chain(lines[cut..end].iter().filter_map(|l| call(l, "STRAIGHT_FEED"))).collect();
        assert_eq!(moves.len(), program.poses.len(), "{name} {mode:?}");
        let letter = |k: usize| machine.rotary[k].name as usize;
        let length = path.tool.length * 10.0;
        // the output's precision: 0.5e-4 mm per linear axis and 0.5e-4° per rotary axis, the
        // angle's error times the lever of the part or the head
        let angle = (0.5e-4f64).to_radians() * 2f64.sqrt();
        for (k, (mv, pose)) in moves.iter().zip(&program.poses).enumerate() {
            assert_eq!(mv.len(), 6, "{name}: {mv:?}");
            let rotary = [mv[3 + letter(0)], mv[3 + letter(1)]];
            let xyz = DVec3::new(mv[0], mv[1], mv[2]);
            let (tip, axis) = match mode {
                Mode::Tcp => (xyz, tool_axis(&machine, rotary)),
                Mode::Machine => {
                    let p = forward_kinematics(&machine, &Joints { xyz, rotary }, length);
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
            assert!((tip - pose.tip).length() <= tip_tolerance, "{name} {mode:?} pose {k}: tip {tip} vs {}", pose.tip);
            assert!(
                (axis - pose.axis).length() <= angle * 1.01,
                "{name} {mode:?} pose {k}: axis {axis} vs {}",
                pose.axis
            );
        }
        // the program's poses are the refined path's, in order, with inserted poses between
        let given: Vec<usize> = (0..program.poses.len()).filter(|&i| program.origin[i].fract() == 0.0).collect();
        assert_eq!(given.len(), path.poses.len(), "{name} {mode:?}");
        for (g, p) in given.iter().zip(&path.poses) {
            assert!((program.poses[*g].tip - 10.0 * p.tip).length() < 1e-9);
            assert!((program.poses[*g].axis - p.axis).length() < 1e-12);
        }
        assert!(program.linearisation.after.max() <= program.linearisation.tolerance);
    }
    let _ = std::fs::remove_dir_all(&dir);
}
