//! Jobs a CAM engineer brings to the post, shared by the tests of the programs
//! (`controller.rs`, `dialects.rs`): a twisted blade edge that passes the fork head's pole, and a
//! wall milled round three times.

use glam::DVec3;
use ruledlab::{Scheme, Variant};
use ruledlab_cam::{Pose, Tool, ToolEnd, ToolPath};

/// An axis tilted `tilt`° from Z towards the direction `turn`° about Z.
pub fn tilted(tilt: f64, turn: f64) -> DVec3 {
    let (t, f) = (tilt.to_radians(), turn.to_radians());
    DVec3::new(t.sin() * f.cos(), t.sin() * f.sin(), t.cos())
}

/// 15 poses (millimetres) along a twisted 70 mm blade edge, the tool tilted 0–40° from the
/// vertical: poses 3 and 4 are 2° off on nearly opposite sides (azimuths 100° and 279.542°),
/// so the great circle between them passes 0.008° from the vertical — the pole of every preset
/// machine — and pose 6 stands 0.3° from it. A ball end of radius 3 and length 30.
pub fn blade() -> ToolPath {
    let tilts = [12.0, 8.0, 5.0, 2.0, 2.0, 5.0, 0.3, 6.0, 12.0, 18.0, 24.0, 29.0, 33.0, 37.0, 40.0];
    let turns =
        [90.0, 95.0, 100.0, 100.0, 279.542, 280.0, 290.0, 300.0, 305.0, 310.0, 315.0, 320.0, 322.0, 325.0, 330.0];
    let poses = (0..15)
        .map(|k| {
            let x = 5.0 * k as f64;
            let tip = DVec3::new(x, 4.0 * (x / 25.0).sin(), 10.0 + 3.0 * (x / 20.0).cos());
            Pose { tip, axis: tilted(tilts[k], turns[k]) }
        })
        .collect();
    ToolPath { poses, tool: Tool::new(3.0, 30.0, ToolEnd::Ball).expect("a tool") }
}

/// The blade refined by two steps of the variational scheme (57 poses).
pub fn blade_refined() -> ToolPath {
    blade().refine(Scheme::Variational { n: 12, variant: Variant::Coupled }, 2).expect("refined")
}

/// A round wall of radius 30 mm milled round three times, 10° a pose and 0.5 mm down a turn:
/// the tool tilted 20° outwards, so its azimuth — and a C axis — turns three times (1080°).
/// A ball end of radius 2 and length 25.
pub fn wall() -> ToolPath {
    let poses = (0..=108)
        .map(|k| {
            let turn = 10.0 * k as f64;
            let f = turn.to_radians();
            let tip = DVec3::new(30.0 * f.cos(), 30.0 * f.sin(), -0.5 * k as f64 / 36.0);
            Pose { tip, axis: tilted(20.0, turn) }
        })
        .collect();
    ToolPath { poses, tool: Tool::new(2.0, 25.0, ToolEnd::Ball).expect("a tool") }
}
