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
    // the solution of b on the side of a: its tilt has a's sign
    let same = orientations(m, b.axis).into_iter().find(|o| o[k].is_some_and(|t| t.to_degrees() * t0 >= 0.0));
    // the limited axis that solution takes nearest its limits, or beyond (where the flip comes
    // early, the poses after it are the ones beyond): its value, the turn nearest the limits
    let blocked = same.and_then(|o| {
        (0..2)
            .filter_map(|j| {
                let r = &m.rotary[j];
                if r.min.is_none() && r.max.is_none() {
                    return None;
                }
                let v = r.value(o[j]?);
                let mid = 0.5 * (r.min.unwrap_or(v) + r.max.unwrap_or(v));
                let v = v - 360.0 * ((v - mid) / 360.0).round();
                let inside = (v - r.min.unwrap_or(f64::NEG_INFINITY)).min(r.max.unwrap_or(f64::INFINITY) - v);
                Some((inside, j, v))
            })
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .map(|(_, j, v)| (j, v))
    });
    let round = |x: f64| (x * 1e4).round() / 1e4;
    let Some((j, value)) = blocked else {
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
    let r = &m.rotary[j];
    crate::msg!(
        "flip-in-cut",
        pose = pose,
        next = pose + 1,
        tilt = m.rotary[k].name.letter(),
        from = round(from),
        to = round(to),
        angle = round(theta),
        axis = r.name.letter(),
        value = round(value),
        min = r.min.unwrap_or(f64::NEG_INFINITY),
        max = r.max.unwrap_or(f64::INFINITY)
    )
}
