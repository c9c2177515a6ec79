//! Jobs a CAM engineer brings to the post, shared by the tests of the programs
//! (`controller.rs`, `dialects.rs`): a twisted blade edge that passes the fork head's pole, and a
//! wall milled round three times, a ring milled round 450° on a hyperboloid's flank (`sweep.rs`).

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

/// The hyperboloid of one sheet of waist radius 40 mm whose rulings lean 30° from the vertical
/// (tangent to the waist circle): the ruling at φ, p(φ, t) = (40 cos φ, 40 sin φ, 0) + t·d(φ),
/// d(φ) = cos 30°·Z + sin 30°·(−sin φ, cos φ, 0), and its outward unit normal there.
pub fn hyperboloid(phi: f64, t: f64) -> (DVec3, DVec3) {
    let (s, c) = phi.sin_cos();
    let beta = 30f64.to_radians();
    let d = beta.cos() * DVec3::Z + beta.sin() * DVec3::new(-s, c, 0.0);
    let p = DVec3::new(40.0 * c, 40.0 * s, 0.0) + t * d;
    // ∂p/∂φ = (−40 sin φ, 40 cos φ, 0) + t·d′(φ), d′ = sin 30°·(−cos φ, −sin φ, 0)
    let dp = DVec3::new(-40.0 * s, 40.0 * c, 0.0) + t * beta.sin() * DVec3::new(-c, -s, 0.0);
    let mut n = dp.cross(d).normalize();
    if n.dot(DVec3::new(c, s, 0.0)) < 0.0 {
        n = -n;
    }
    (p, n)
}

/// A ring milled round 450° on the flank of the hyperboloid: 151 poses 3° apart, a flat end of
/// radius 5 and length 30, its axis along the ruling and its tip the ruling's foot offset by the
/// radius along the normal there (the ruling-aligned baseline), and the target: 300 × 4 points
/// of the surface over the whole turn, a quarter to three quarters up the 20 mm flank.
pub fn ring() -> (ToolPath, Vec<DVec3>) {
    let poses = (0..=150)
        .map(|k| {
            let phi = (3.0 * k as f64).to_radians();
            let (p, n) = hyperboloid(phi, 0.0);
            let (q, _) = hyperboloid(phi, 1.0);
            Pose { tip: p + 5.0 * n, axis: (q - p).normalize() }
        })
        .collect();
    let height = 20.0 / 30f64.to_radians().cos();
    let targets = (0..300)
        .flat_map(|k| {
            let phi = (1.2 * k as f64 + 0.37).to_radians();
            (0..4).map(move |j| hyperboloid(phi, height * (0.25 + j as f64 / 6.0)).0)
        })
        .collect();
    (ToolPath { poses, tool: Tool::new(5.0, 30.0, ToolEnd::Flat).expect("a tool") }, targets)
}

/// The line the refined blade's ball touches: each ball centre moved by the radius across the
/// path (along the unit tangent × axis), 20 points a block, as the tool path interpolates it.
pub fn blade_target() -> Vec<DVec3> {
    let path = blade_refined();
    let r = path.tool.radius;
    let centres = path.cutting_centres();
    let mut out = Vec::new();
    for k in 0..centres.len() - 1 {
        let tangent = centres[k + 1] - centres[k];
        for j in 0..20 {
            let s = j as f64 / 20.0;
            let axis = path.poses[k].axis.lerp(path.poses[k + 1].axis, s).normalize();
            let side = tangent.cross(axis).normalize();
            out.push(centres[k].lerp(centres[k + 1], s) + r * side);
        }
    }
    out
}
