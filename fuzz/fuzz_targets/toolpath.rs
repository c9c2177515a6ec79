//! Tool paths: construction, refinement, quality, deviation and every export, the G-code post
//! on every preset machine, dialect and mode (an error, never a panic), and the tool poses read
//! back from the CSV and JSON.
#![no_main]
use libfuzzer_sys::fuzz_target;
use ruledlab_cam::{gcode, read_tool_poses, tool_path_csv, tool_path_json, Dialect, Machine, Mode, PostOptions, MACHINE_PRESETS};
use ruledlab_cam::{deviation, Quality};
use ruledlab_cam::{Tool, ToolEnd, ToolPath};
use ruledlab::Scheme;
use ruledlab::RuledSurface;

#[path = "common.rs"]
mod common;

fuzz_target!(|data: &[u8]| {
    let values = common::numbers(data);
    if values.len() < 15 {
        return;
    }
    let Ok(tool) = Tool::new(values[0], values[1], if values[2] > 0.0 { ToolEnd::Ball } else { ToolEnd::Flat }) else {
        return;
    };
    let n = (values.len() - 3) / 6 * 6;
    let Ok(axes) = RuledSurface::from_flat(&values[3..3 + n.min(6 * 32)]) else { return };
    let path = ToolPath::from_surface(&axes, tool);
    let Ok(r) = path.refine(Scheme::FourPoint { w: 1.0 / 16.0 }, 1) else { return };
    let _ = Quality::of(&r);
    let _ = deviation(&r, &[glam::DVec3::ZERO, glam::DVec3::ONE]);
    let (c, j) = (tool_path_csv(&r), tool_path_json(&r));
    let number = |t: &str| t.parse::<f64>().unwrap_or(f64::NAN);
    let _ = (read_tool_poses(&c, false, &number), read_tool_poses(&j, true, &number));
    let pick = |k: usize, n: usize| (values[k].abs() * 7.0) as usize % n;
    let o = PostOptions {
        feed: values[0].abs() + 1.0,
        machine: Machine::preset(MACHINE_PRESETS[pick(3, 4)]).unwrap_or_else(|| PostOptions::default().machine),
        dialect: [Dialect::LinuxCnc, Dialect::Heidenhain, Dialect::Sinumerik][pick(4, 3)],
        mode: [Mode::Tcp, Mode::Machine][pick(5, 2)],
        tolerance: 0.01 + values[6].abs().min(10.0),
        ..Default::default()
    };
    if let Ok(p) = gcode(&r, &o) {
        assert_eq!(p.poses.len(), r.poses.len() + p.linearisation.inserted);
    }
});
