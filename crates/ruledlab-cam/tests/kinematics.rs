//! Property tests (native) of the kinematics of the G-code post (`kinematics.rs`): inverse then
//! forward kinematics is the identity on random reachable poses of every preset machine; on the
//! pole the free axis holds its neighbour's value; a pose beyond the limits is an error naming it.
#![cfg(not(target_family = "wasm"))]

use glam::DVec3;
use proptest::prelude::*;
use ruledlab_cam::{at_pole, forward_kinematics, inverse_kinematics, Joints, Machine, Pose, MACHINE_PRESETS};

/// Random axis values within the machine's limits (a continuous axis within ±180°), and a
/// random tip of the part: the pose they give is reachable by construction.
fn reachable(m: &Machine, u: [f64; 2], tip: DVec3) -> Pose {
    let rotary = [0, 1].map(|k| {
        let r = &m.rotary[k];
        let (lo, hi) = (r.min.unwrap_or(-180.0), r.max.unwrap_or(180.0));
        lo + u[k] * (hi - lo)
    });
    // the tip where the part is: place it through the inverse of the position map
    let probe = forward_kinematics(m, &Joints { xyz: DVec3::ZERO, rotary }, 40.0);
    Pose { tip, axis: probe.axis }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn inverse_then_forward_is_the_identity(
        preset in 0usize..4,
        u in proptest::collection::vec((0.001..0.999f64, 0.001..0.999f64), 2..6),
        tips in proptest::collection::vec((-60.0..60.0f64, -60.0..60.0f64, -20.0..40.0f64), 6),
    ) {
        let m = Machine::preset(MACHINE_PRESETS[preset]).unwrap();
        let poses: Vec<Pose> =
            u.iter().zip(&tips).map(|(&(a, b), &(x, y, z))| reachable(&m, [a, b], DVec3::new(x, y, z))).collect();
        let joints = inverse_kinematics(&m, &poses, 40.0).unwrap();
        for (p, j) in poses.iter().zip(&joints) {
            let q = forward_kinematics(&m, j, 40.0);
            prop_assert!((q.tip - p.tip).length() < 1e-9, "{}: tip {} vs {}", m.name, q.tip, p.tip);
            prop_assert!((q.axis - p.axis).length() < 1e-12, "{}: axis {} vs {}", m.name, q.axis, p.axis);
            for k in 0..2 {
                prop_assert!(m.rotary[k].allows(j.rotary[k]), "{}: {} = {}", m.name, m.rotary[k].name.letter(), j.rotary[k]);
            }
        }
    }

    #[test]
    fn the_pole_holds_the_free_axis(preset in 0usize..4, a in 0.05..0.95f64, c in -3.0..3.0f64) {
        // on every preset the pole is the tool axis along Z, where C is free
        let m = Machine::preset(MACHINE_PRESETS[preset]).unwrap();
        let off = Pose { tip: DVec3::ZERO, axis: DVec3::new(a * c.cos(), a * c.sin(), 1.0).normalize() };
        let pole = Pose { tip: DVec3::X, axis: DVec3::Z };
        prop_assert!(at_pole(&m, DVec3::Z) && !at_pole(&m, off.axis));
        let j = inverse_kinematics(&m, &[off, pole, off], 40.0).unwrap();
        let c_axis = (0..2).find(|&k| m.rotary[k].name.letter() == "C").unwrap();
        prop_assert_eq!(j[1].rotary[c_axis], j[0].rotary[c_axis]);
        prop_assert!((forward_kinematics(&m, &j[1], 40.0).axis - DVec3::Z).length() < 1e-12);
    }

    #[test]
    fn beyond_the_limits_is_an_error_naming_the_pose(tilt in 121.0..179.0f64, turn in -3.0..3.0f64) {
        // table-table-ac: A from -30° to 120°, so an axis tilted more than 120° from Z
        let m = Machine::preset("table-table-ac").unwrap();
        let t = tilt.to_radians();
        let axis = DVec3::new(t.sin() * turn.cos(), t.sin() * turn.sin(), t.cos());
        let ok = Pose { tip: DVec3::ZERO, axis: DVec3::new(0.1, 0.2, 1.0).normalize() };
        let e = inverse_kinematics(&m, &[ok, ok, Pose { tip: DVec3::ZERO, axis }], 40.0).unwrap_err();
        prop_assert_eq!(e.code(), "unreachable");
        prop_assert!(e.to_string().starts_with("pose 2 cannot be reached: A would be"), "{}", e);
        let near = Pose { tip: DVec3::ZERO, axis: DVec3::new((tilt - 2.0).min(119.0).to_radians().sin(), 0.0, (tilt - 2.0).min(119.0).to_radians().cos()) };
        prop_assert!(inverse_kinematics(&m, &[ok, near], 40.0).is_ok());
    }
}
