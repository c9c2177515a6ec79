//! Example 6 (Figs. 16–18): refined tool paths, export and G-code round trip. Runs natively
//! and in Chromium.

use glam::DVec3;
use ruledlab::{deviation, Quality};
use ruledlab::{example_profile, example_tool_path, Pose, Tool, ToolEnd, ToolPath};
use ruledlab::{gcode, machine_coordinates, parse_gcode, GcodeOptions};
use ruledlab::{Scheme, Variant};

#[cfg(target_family = "wasm")]
use wasm_bindgen_test::wasm_bindgen_test;
#[cfg(target_family = "wasm")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

const VARIATIONAL: Scheme = Scheme::Variational { n: 12, variant: Variant::Coupled };

/// The refined path passes through the given poses (tips bit for bit, axes to rounding) and
/// every axis is a unit vector.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn refined_path_interpolates_the_given_poses() {
    let path = example_tool_path(7).unwrap();
    let r = path.refine(VARIATIONAL, 2).unwrap();
    assert_eq!(r.poses.len(), 25);
    for (i, p) in path.poses.iter().enumerate() {
        assert_eq!(r.poses[4 * i].tip, p.tip);
        assert!((r.poses[4 * i].axis - p.axis).length() < 1e-15);
    }
    for p in &r.poses {
        assert!((p.axis.length() - 1.0).abs() < 1e-15);
    }
}

/// Refinement brings the machined surface closer to the target profile and makes the
/// orientation smoother; the variational scheme does best on this path (measured:
/// README and `cargo run --example milling`).
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn refinement_improves_the_profile_and_the_orientation() {
    let path = example_tool_path(7).unwrap();
    let target = example_profile(600);
    let worst = |p: &ToolPath| deviation(p, &target).iter().fold(0.0f64, |m, d| m.max(d.abs()));
    let coarse = worst(&path);
    let linear = path.refine(Scheme::BSpline { degree: 1 }, 3).unwrap();
    let four = path.refine(Scheme::FourPoint { w: 1.0 / 16.0 }, 3).unwrap();
    let fair = path.refine(VARIATIONAL, 3).unwrap();
    assert!(worst(&fair) < coarse / 3.0, "{} vs {coarse}", worst(&fair));
    assert!(worst(&fair) < worst(&four) && worst(&four) < worst(&linear));
    let (ql, qf) = (Quality::of(&linear), Quality::of(&fair));
    assert!(qf.max_second_difference() < ql.max_second_difference() / 3.0);
    assert!(qf.max_angle_step() < 0.05);
}

/// G-code round trip: parsing the G1 moves and inverting the kinematics gives back every pose
/// (6 decimals in mm and degrees: tips within 2e-6, axes within 1e-7).
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn gcode_round_trip() {
    let path = example_tool_path(7).unwrap().refine(VARIATIONAL, 2).unwrap();
    let o = GcodeOptions { feed: 800.0, scale: 10.0, clearance: 5.0 };
    let text = gcode(&path, o).unwrap();
    assert!(text.starts_with("(ruledlab tool path, 25 poses)"));
    assert!(text.contains("G21 G90 G94") && text.trim_end().ends_with("M30"));
    let back = parse_gcode(&text, o.scale).unwrap();
    assert_eq!(back.len(), path.poses.len());
    for (p, q) in path.poses.iter().zip(&back) {
        assert!((p.tip - q.tip).length() < 2e-6, "{} vs {}", p.tip, q.tip);
        assert!((p.axis - q.axis).length() < 1e-7);
    }
    // the safe moves are above every cutting move
    let z: Vec<f64> = machine_coordinates(&path, o.scale).iter().map(|m| m[2]).collect();
    let safe: f64 = text.lines().find(|l| l.starts_with("G0 Z")).unwrap()[4..].parse().unwrap();
    assert!(z.iter().all(|&v| v + 4.99 < safe));
}

/// A path whose axis turns twice around the vertical keeps C continuous (unwrapped) and
/// survives the round trip; a vertical axis (the pole) holds C.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn angle_wrap_and_pole() {
    let tool = Tool::new(0.2, 2.0, ToolEnd::Flat).unwrap();
    let mut poses: Vec<Pose> = (0..=60)
        .map(|k| {
            let t = k as f64 / 60.0 * 4.0 * std::f64::consts::PI;
            Pose { tip: DVec3::new(t.cos(), t.sin(), 0.1 * t), axis: DVec3::new(0.6 * t.cos(), 0.6 * t.sin(), 0.8) }
        })
        .collect();
    poses.push(Pose { tip: DVec3::new(1.0, 0.0, 1.5), axis: DVec3::Z });
    let path = ToolPath { poses, tool };
    let m = machine_coordinates(&path, 1.0);
    for w in m.windows(2) {
        assert!((w[1][4] - w[0][4]).abs() < 15.0, "C jumps {} → {}", w[0][4], w[1][4]);
    }
    assert_eq!(m[61][4], m[60][4], "C held at the pole");
    assert_eq!(m[61][3], 0.0);
    let back = parse_gcode(&gcode(&path, GcodeOptions::default()).unwrap(), 1.0).unwrap();
    for (p, q) in path.poses.iter().zip(&back) {
        assert!((p.tip - q.tip).length() < 2e-6 && (p.axis - q.axis).length() < 1e-7);
    }
}

/// Bad tools and options are rejected.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn rejects_bad_tools_and_options() {
    assert!(Tool::new(0.0, 1.0, ToolEnd::Ball).is_err());
    assert!(Tool::new(-1.0, 1.0, ToolEnd::Ball).is_err());
    assert!(Tool::new(f64::NAN, 1.0, ToolEnd::Ball).is_err());
    assert!(Tool::new(0.1, f64::INFINITY, ToolEnd::Ball).is_err());
    let path = example_tool_path(3).unwrap();
    assert!(gcode(&path, GcodeOptions { feed: 0.0, ..Default::default() }).is_err());
    assert!(gcode(&path, GcodeOptions { scale: f64::NAN, ..Default::default() }).is_err());
}
