//! Example 6 (Figs. 16–18): refined tool paths, export and G-code round trip. Runs natively
//! and in Chromium.

use glam::DVec3;
use ruledlab::{Scheme, Variant};
use ruledlab_cam::{deviation, Quality};
use ruledlab_cam::{example_profile, example_tool_path, Pose, Tool, ToolEnd, ToolPath};
use ruledlab_cam::{forward_kinematics, gcode, inverse_kinematics, Machine, PostOptions};

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
/// the book's "Tool paths" and `cargo run --example milling`).
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

/// The post's program: its poses are the refined path's (scaled to mm) with inserted ones, its
/// axis values give them back through the forward kinematics, the safe moves stay above the cut.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn gcode_program_gives_back_the_path() {
    let path = example_tool_path(7).unwrap().refine(VARIATIONAL, 2).unwrap();
    let o = PostOptions { feed: 800.0, scale: 10.0, ..Default::default() };
    let program = gcode(&path, &o).unwrap();
    let text = &program.text;
    assert!(text.starts_with("(ruledlab tool path: "), "{text}");
    assert!(text.contains("G21 G90 G94") && text.trim_end().ends_with("M30"));
    assert!(text.contains("T1 M6\nG43 H1\nS10000 M3") && text.contains("G93 G1"));
    let length = 10.0 * path.tool.length;
    for (p, j) in program.poses.iter().zip(&program.joints) {
        let q = forward_kinematics(&o.machine, j, length);
        assert!((p.tip - q.tip).length() < 1e-9 && (p.axis - q.axis).length() < 1e-12);
    }
    assert_eq!(program.poses.len(), path.poses.len() + program.linearisation.inserted);
    // the first rapid after the retract is at the safe height, on the first pose's tool axis
    let safe = program.poses.iter().map(|p| p.tip.z).fold(f64::NEG_INFINITY, f64::max) + 30.0;
    assert!(text.contains(&format!("(safe height {safe:.4} mm above the part zero")), "{safe}");
}

/// A path whose axis turns twice around the vertical keeps C continuous (unwrapped); a vertical
/// axis (the pole) holds C.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn angle_wrap_and_pole() {
    let mut poses: Vec<Pose> = (0..=60)
        .map(|k| {
            let t = k as f64 / 60.0 * 4.0 * std::f64::consts::PI;
            Pose { tip: DVec3::new(t.cos(), t.sin(), 0.1 * t), axis: DVec3::new(0.6 * t.cos(), 0.6 * t.sin(), 0.8) }
        })
        .collect();
    poses.push(Pose { tip: DVec3::new(1.0, 0.0, 1.5), axis: DVec3::Z });
    let m = Machine::preset("table-table-ac").unwrap();
    let j = inverse_kinematics(&m, &poses, 20.0).unwrap();
    for w in j.windows(2) {
        assert!((w[1].rotary[1] - w[0].rotary[1]).abs() < 15.0, "C jumps {:?} → {:?}", w[0], w[1]);
    }
    assert!((j[60].rotary[1] - j[0].rotary[1]).abs() > 700.0, "two turns of C");
    assert_eq!(j[61].rotary[1], j[60].rotary[1], "C held at the pole");
    assert!(j[61].rotary[0].abs() < 1e-12);
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
    let bad = |o: PostOptions| gcode(&path, &o).unwrap_err().to_string();
    assert_eq!(
        bad(PostOptions { feed: 0.0, ..Default::default() }),
        "feed: must be a positive number of at most 1e7, got 0"
    );
    assert!(bad(PostOptions { scale: f64::NAN, ..Default::default() }).starts_with("scale: must be a positive"));
    assert!(bad(PostOptions { tolerance: 1e-6, ..Default::default() }).starts_with("tolerance: must be at least"));
    assert!(bad(PostOptions { work_offset: 7, ..Default::default() }).starts_with("workOffset: must be an integer"));
    assert!(
        bad(PostOptions { safe_height: Some(-5.0), ..Default::default() }).starts_with("safeHeight: must be at least")
    );
    assert!(bad(PostOptions { name: "a b".into(), ..Default::default() }).starts_with("name: must be 1 to 24"));
}
