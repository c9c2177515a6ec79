//! A flip of the rotary axes inside a cut: between two blocks the axes jump from one solution
//! of the orientation to the other (`kinematics.rs`: two per tool axis, ±γ) where the tool axis
//! does not pass the pole — the tilt swings from one side to the other while the tool turns
//! little, and the tool leaves the path on the way (on Sinumerik `ORIVECT` the controller's own
//! axes make the same jump). The post refuses it, naming the axis whose limit forces it.
//!
//! **The test.** On a machine whose tilting axis w is normal to the spindle's Z (every preset:
//! β = w·Z = 0 in the orientation's equation) the tilt ψ of a solution is ± the tool axis's
//! angle ρ from the pole, its sign the solution's. ρ changes by at most the angle θ the tool axis
//! turns, so within one solution |Δψ| = |Δρ| ≤ θ; from one solution to the other |Δψ| = ρ₀ + ρ₁,
//! which is θ only where the arc passes through the pole (ρ₀ + ρ₁ − θ ≤ 2δ for an arc passing δ
//! from it). A block is a flip where |Δψ| > θ + 2·(pole cone) + [`FLIP_MARGIN`]: the pole cone's
//! poses keep the free axis and may tilt through the pole.

use crate::kinematics::{frame, orientations, Joints};
use crate::machine::Machine;
use crate::tolerance::FLIP_MARGIN;
use crate::Pose;
use ruledlab::{Error, Message};

/// The flip of the block from pose `a` (axis values `ja`) to `b` (`jb`), if it is one (module
/// documentation; `cone` the pole cone's half-angle, radians), as the error naming poses `pose`
/// and `pose + 1`: the tilting axis's swing and the limit of the axis the other solution would
/// leave.
pub fn flip(
    m: &Machine,
    cone: f64,
    (a, b): (&Pose, &Pose),
    (ja, jb): (&Joints, &Joints),
    pose: usize,
) -> Option<Error> {
    let f = frame(m)?;
    if f.w.z.abs() > 1e-9 {
        return None;
    }
    let k = f.iw;
    let r = &m.rotary[k];
    let tilt = |v: f64| (v - r.zero) / r.direction;
    let (t0, t1) = (tilt(ja.rotary[k]), tilt(jb.rotary[k]));
    let theta = a.axis.angle_between(b.axis).to_degrees();
    if (t1 - t0).abs() <= theta + 2.0 * cone.to_degrees() + FLIP_MARGIN {
        return None;
    }
    let message = message(m, b, t0, (k, ja.rotary[k], jb.rotary[k]), theta, pose);
    Some(Error::Unreachable { pose, line: None, message })
}

/// The message: the tilting axis's swing, and the axis (with its limits) that keeps the solution
/// of pose `pose` (tilt `t0`, degrees) from going on to `b`.
fn message(m: &Machine, b: &Pose, t0: f64, (k, from, to): (usize, f64, f64), theta: f64, pose: usize) -> Message {
    // the solution of b on the side of a: its tilt has the sign of a's, taken within half a turn
    // of 0 (a tilting axis limited on one side may stand a turn away: −342.64° is +17.36°)
    let t0 = t0 - 360.0 * (t0 / 360.0).round();
    let same = orientations(m, b.axis).into_iter().find(|o| o[k].is_some_and(|t| t.to_degrees() * t0 >= 0.0));
    // the axis limited on both sides that solution takes nearest its limits, or beyond (where the
    // flip comes early, the poses after it are the ones beyond): its value, the turn nearest the
    // limits. An axis limited on one side only blocks nothing: a turn of it is within (solve.rs).
    let blocked = same.and_then(|o| {
        (0..2)
            .filter_map(|j| {
                let r = &m.rotary[j];
                let (Some(lo), Some(hi)) = (r.min, r.max) else { return None };
                let v = r.value(o[j]?);
                let v = v - 360.0 * ((v - 0.5 * (lo + hi)) / 360.0).round();
                Some(((v - lo).min(hi - v), j, v, (lo, hi)))
            })
            .min_by(|a, b| a.0.total_cmp(&b.0))
    });
    let round = |x: f64| (x * 1e4).round() / 1e4;
    let Some((_, j, value, (min, max))) = blocked else {
        return crate::msg!(
            "flip-in-cut-free",
            pose = pose,
            next = pose + 1,
            tilt = m.rotary[k].name.letter(),
            from = round(from),
            to = round(to),
            angle = round(theta)
        );
    };
    crate::msg!(
        "flip-in-cut",
        pose = pose,
        next = pose + 1,
        tilt = m.rotary[k].name.letter(),
        from = round(from),
        to = round(to),
        angle = round(theta),
        axis = m.rotary[j].name.letter(),
        value = round(value),
        min = min,
        max = max
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    /// The block from B = 10° to B = −10° (a swing of 20°) on the table-table B/C preset with
    /// both axes continuous, its tool axes turning by 17°: a flip where 20° > 17° + 2·cone +
    /// FLIP_MARGIN.
    fn swing(cone_degrees: f64) -> Option<Error> {
        let mut m = Machine::preset("table-table-bc").unwrap();
        let k = m.rotary.iter().position(|r| r.name.letter() == "B").unwrap();
        (m.rotary[k].min, m.rotary[k].max) = (None, None);
        let pose = |degrees: f64| Pose {
            tip: DVec3::ZERO,
            axis: DVec3::new(0.0, degrees.to_radians().sin(), degrees.to_radians().cos()),
        };
        let (a, b) = (pose(0.0), pose(17.0));
        let joints = |tilt: f64| {
            let mut rotary = [0.0; 2];
            rotary[k] = tilt;
            Joints { xyz: DVec3::ZERO, rotary }
        };
        flip(&m, cone_degrees.to_radians(), (&a, &b), (&joints(10.0), &joints(-10.0)), 3)
    }

    #[test]
    fn a_swing_beyond_the_turn_and_twice_the_pole_cone_is_a_flip() {
        // 17 + 2·1.2 + 0.01 = 19.41 < 20: a flip, between poses 3 and 4
        let e = swing(1.2).expect("a flip");
        let Error::Unreachable { pose, message, .. } = &e else { panic!("{e}") };
        assert_eq!((*pose, message.reason), (3, "flip-in-cut-free"), "{e}");
        // 17 + 2·2 + 0.01 = 21.01 ≥ 20: the pole cone lets the tilt swing through the pole
        assert!(swing(2.0).is_none());
        // the margin: 17 + 2·1.4955 + 0.01 = 20.001: no flip; 17 + 2·1.4945 + 0.01 = 19.999: a flip
        assert!(swing(1.4955).is_none());
        assert!(swing(1.4945).is_some());
    }
}
