//! Forward and inverse kinematics of a five-axis [`Machine`] (frames and conventions in
//! `machine.rs`): from the controller's axis values to the tool pose in the part frame and back.
//!
//! **Forward.** Write T_k(x) = c_k + R(u_k, θ_k)(x − c_k) for a rotary axis k at geometric angle
//! θ_k about the line through c_k along u_k. With the head axes H = H₁∘H₂ (pivots measured from
//! the spindle nose, moved by the tool length L: c′ = c + L·Z) and the table axes T = T₁∘T₂ (the
//! first of the chain outermost), the tool tip and axis in the machine frame are
//!   tip_M = (X, Y, Z) + H(0),   axis_M = R_H Z,
//! and in the part frame (`partZero` = z₀)
//!   tip = T⁻¹(tip_M) − z₀,   axis = R_Tᵀ axis_M.
//!
//! **Inverse, the orientation.** A part-frame axis a needs R_T a = R_H Z. Each machine type
//! turns this into R(u, φ) p = R(w, ψ) q with u ⊥ w (the two axes are distinct letters):
//! table–table R(u₂, θ₂) a = R(u₁, −θ₁) Z; head–table R(u_t, θ_t) a = R(u_h, θ_h) Z;
//! head–head R(u₁, −θ₁) a = R(u₂, θ₂) Z. The common vector is
//!   c = α u + β w ± γ (u × w),  α = u·p,  β = w·q,  γ = √(1 − α² − β²),
//! and φ (ψ) is the angle about u (w) from the part of p (q) normal to u (w) to that of c:
//! **two solutions per pose** (±γ), one where γ = 0. Where p ∥ u (|p × u| < 1e-9) φ is
//! undetermined: **the pole** (on the presets: the tool axis along the C axis). There the free
//! angle takes the values it has at the nearest poses off the pole (before and after; 0 when the
//! whole path is on the pole), and the choice below picks among them.
//!
//! **Choice and unwrapping.** Each solution gives controller values v = zero + direction·θ and,
//! for a limited axis, every v + 360°·n within its limits; a continuous axis (no limits) is
//! unwrapped to the value nearest the previous pose. Over the whole path a dynamic programme picks
//! the candidates that keep every axis within its limits and **move least** (the sum of
//! |Δv| over both axes and all blocks, the first pose measured from 0). A pose without a
//! candidate within limits, or whose machine position leaves the travel of X, Y or Z, is an
//! [`Error::Unreachable`] naming the pose and the axis.

use crate::machine::{turn, Machine};
use crate::tolerance::{MAX_AXIS_TURNS, POLE_SIN};
use crate::Pose;
use glam::{DMat3, DVec3};
use ruledlab::{Error, Result};

/// The axis values of one pose: machine X, Y, Z (mm) and the controller values of `rotary[0]`
/// and `rotary[1]` (degrees).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Joints {
    /// X, Y, Z.
    pub xyz: DVec3,
    /// The rotary axes, in the machine's order.
    pub rotary: [f64; 2],
}

fn head_pivot(m: &Machine, k: usize, tool_length: f64) -> DVec3 {
    DVec3::from(m.rotary[k].pivot) + tool_length * DVec3::Z
}

/// H(0): where the tool tip is, relative to (X, Y, Z), with the head axes at `rotary`.
pub fn head_offset(m: &Machine, rotary: [f64; 2], tool_length: f64) -> DVec3 {
    let mut x = DVec3::ZERO;
    for &k in m.head_axes().iter().rev() {
        x = turn(&m.rotary[k], rotary[k], x, head_pivot(m, k, tool_length));
    }
    x
}

/// R_H: the head's rotation.
pub fn head_rotation(m: &Machine, rotary: [f64; 2]) -> DMat3 {
    m.head_axes().iter().fold(DMat3::IDENTITY, |r, &k| r * m.rotary[k].rotation(rotary[k]))
}

/// R_T: the table's rotation (a part-frame vector v appears as R_T v in the machine).
pub fn table_rotation(m: &Machine, rotary: [f64; 2]) -> DMat3 {
    m.table_axes().iter().fold(DMat3::IDENTITY, |r, &k| r * m.rotary[k].rotation(rotary[k]))
}

/// T(x): a point of the table (machine frame at zero) where the table axes put it.
fn table_map(m: &Machine, rotary: [f64; 2], x: DVec3) -> DVec3 {
    m.table_axes().iter().rev().fold(x, |x, &k| turn(&m.rotary[k], rotary[k], x, DVec3::from(m.rotary[k].pivot)))
}

/// T⁻¹(y).
fn table_unmap(m: &Machine, rotary: [f64; 2], y: DVec3) -> DVec3 {
    m.table_axes().iter().fold(y, |y, &k| {
        let c = DVec3::from(m.rotary[k].pivot);
        c + m.rotary[k].rotation(rotary[k]).transpose() * (y - c)
    })
}

/// The tool axis in the part frame for the rotary values: R_Tᵀ R_H Z.
pub fn tool_axis(m: &Machine, rotary: [f64; 2]) -> DVec3 {
    table_rotation(m, rotary).transpose() * (head_rotation(m, rotary) * DVec3::Z)
}

/// Forward kinematics: the pose (part frame, mm) of the axis values `j` for a tool of length
/// `tool_length` (mm).
pub fn forward_kinematics(m: &Machine, j: &Joints, tool_length: f64) -> Pose {
    let tip_m = j.xyz + head_offset(m, j.rotary, tool_length);
    Pose { tip: table_unmap(m, j.rotary, tip_m) - DVec3::from(m.part_zero), axis: tool_axis(m, j.rotary) }
}

/// The machine position X, Y, Z that puts the tip at `tip` (part frame, mm) with the rotary axes
/// at `rotary`: T(tip + z₀) − H(0).
pub fn machine_position(m: &Machine, tip: DVec3, rotary: [f64; 2], tool_length: f64) -> DVec3 {
    table_map(m, rotary, tip + DVec3::from(m.part_zero)) - head_offset(m, rotary, tool_length)
}

/// A solution of the orientation: the geometric angles (radians) of `rotary[0]`, `rotary[1]`;
/// `None` for the angle the pole leaves free.
pub type Orientation = [Option<f64>; 2];

/// The angle about unit `u` from the part of `from` normal to u to that of `to`; `None` when
/// `from` lies along u.
fn angle_about(u: DVec3, from: DVec3, to: DVec3) -> Option<f64> {
    let f = from - from.dot(u) * u;
    let t = to - to.dot(u) * u;
    if from.cross(u).length() < POLE_SIN {
        return None;
    }
    Some(u.dot(f.cross(t)).atan2(f.dot(t)))
}

/// How a machine's orientation equation R(u, φ) p = R(w, ψ) q reads (module documentation):
/// p is the part-frame tool axis and q is Z on every machine type; φ is the geometric angle of
/// `rotary[iu]` times `su`, ψ that of `rotary[iw]` times `sw`. The pole is p ∥ u: φ free there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// The axis whose angle the pole leaves free, its direction and sign.
    pub iu: usize,
    /// Its direction.
    pub u: DVec3,
    /// φ = su · θ[iu].
    pub su: f64,
    /// The other axis, its direction and sign.
    pub iw: usize,
    /// Its direction.
    pub w: DVec3,
    /// ψ = sw · θ[iw].
    pub sw: f64,
}

/// The machine's [`Frame`]; `None` for a machine with no rotary axis on the table or the head
/// that can turn the tool axis (never for a valid description with two axes).
pub fn frame(m: &Machine) -> Option<Frame> {
    let (table, head) = (m.table_axes(), m.head_axes());
    let dir = |k: usize| m.rotary[k].name.direction();
    let ((iu, su), (iw, sw)) = match (table.as_slice(), head.as_slice()) {
        ([o, i], []) => ((*i, 1.0), (*o, -1.0)),
        ([t], [h]) => ((*t, 1.0), (*h, 1.0)),
        (_, [o, i]) => ((*o, -1.0), (*i, 1.0)),
        _ => return None,
    };
    Some(Frame { iu, u: dir(iu), su, iw, w: dir(iw), sw })
}

/// The angle (radians) of the part-frame unit axis `a` from the machine's pole (the nearer of
/// ±u, where the angle of `rotary[iu]` is free); π/2 on a machine without a frame.
pub fn pole_angle(m: &Machine, a: DVec3) -> f64 {
    frame(m).map_or(std::f64::consts::FRAC_PI_2, |f| a.cross(f.u).length().atan2(a.dot(f.u).abs()))
}

/// With the angle of the free axis fixed at `theta` (geometric, radians), the angle of the
/// other axis that brings the tool axis nearest to `a`: ψ turns Z about w towards R(u, φ) a.
/// `None` where that leaves it free too.
pub fn nearest_tilt(m: &Machine, a: DVec3, theta: f64) -> Option<f64> {
    let f = frame(m)?;
    let target = DMat3::from_axis_angle(f.u, f.su * theta) * a;
    angle_about(f.w, DVec3::Z, target).map(|psi| f.sw * psi)
}

/// Both solutions (one where they coincide) of the orientation for the part-frame unit axis `a`;
/// empty when no setting of the two axes gives it.
pub fn orientations(m: &Machine, a: DVec3) -> Vec<Orientation> {
    let Some(Frame { iu, u, su, iw, w, sw }) = frame(m) else { return Vec::new() };
    let (p, q) = (a, DVec3::Z);
    let (alpha, beta) = (u.dot(p), w.dot(q));
    // γ² = 1 − α² − β² = |u × p|² − β² (p a unit vector; likewise with w, q): near the pole α²
    // is within rounding of 1 and 1 − α² would keep only a few digits of γ, the cross product
    // all of them; it is taken for the larger of |α|, |β|, the one whose square may be near 1
    let (s, small) = if alpha.abs() >= beta.abs() { (u.cross(p).length(), beta) } else { (w.cross(q).length(), alpha) };
    let g2 = (s - small.abs()) * (s + small.abs());
    if g2 < -1e-12 {
        return Vec::new();
    }
    let gamma = g2.max(0.0).sqrt();
    let n = u.cross(w);
    let signs: &[f64] = if gamma < 1e-12 { &[1.0] } else { &[1.0, -1.0] };
    signs
        .iter()
        .map(|&s| {
            let c = alpha * u + beta * w + s * gamma * n;
            let mut o: Orientation = [None, None];
            o[iu] = angle_about(u, p, c).map(|phi| su * phi);
            o[iw] = angle_about(w, q, c).map(|psi| sw * psi);
            o
        })
        .collect()
}

/// A candidate value of one axis: fixed (a limited axis, unwrapped within its limits) or
/// known modulo 360° (a continuous axis, unwrapped later towards its neighbour).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Value {
    Fixed(f64),
    Turn(f64),
}

pub(crate) fn wrap(d: f64) -> f64 {
    d - 360.0 * (d / 360.0).round()
}

pub(crate) fn step(a: Value, b: Value) -> f64 {
    match (a, b) {
        (Value::Fixed(x), Value::Fixed(y)) => (y - x).abs(),
        (Value::Fixed(x) | Value::Turn(x), Value::Fixed(y) | Value::Turn(y)) => wrap(y - x).abs(),
    }
}

pub(crate) fn from_zero(v: Value) -> f64 {
    match v {
        Value::Fixed(x) => x.abs(),
        Value::Turn(x) => wrap(x).abs(),
    }
}

/// The unwrapped values of geometric angle `theta` on axis `k`: within the limits, or one value
/// modulo 360° for a continuous axis.
pub(crate) fn values(m: &Machine, k: usize, theta: f64) -> Vec<Value> {
    let r = &m.rotary[k];
    let v = r.value(theta);
    if r.min.is_none() && r.max.is_none() {
        return vec![Value::Turn(wrap(v))];
    }
    // with a maximum alone, the MAX_AXIS_TURNS turns below it (the nearest one included)
    let lo = r.min.unwrap_or_else(|| r.max.unwrap_or(v) - 360.0 * MAX_AXIS_TURNS as f64);
    let first = v + 360.0 * ((lo - v) / 360.0).ceil();
    (0..MAX_AXIS_TURNS).map(|n| first + 360.0 * n as f64).filter(|&x| r.allows(x)).map(Value::Fixed).collect()
}

/// The nearest value to the limits an unreachable angle had, for the message: (axis, value).
pub(crate) fn nearest_violation(m: &Machine, solutions: &[[f64; 2]]) -> (usize, f64) {
    let mut best = (0, f64::NAN, f64::INFINITY);
    for s in solutions {
        for k in 0..2 {
            let r = &m.rotary[k];
            if !values(m, k, s[k]).is_empty() {
                continue;
            }
            let v = r.value(s[k]);
            let v = v - 360.0 * (v / 360.0).round();
            let miss = r.min.map_or(0.0, |lo| (lo - v).max(0.0)) + r.max.map_or(0.0, |hi| (v - hi).max(0.0));
            if miss < best.2 {
                best = (k, v, miss);
            }
        }
    }
    (best.0, best.1)
}

pub(crate) fn limit(x: Option<f64>, default: f64) -> f64 {
    x.unwrap_or(default)
}

/// An axis value beyond its limits `lo`..`hi` as an error states it: to the program's 4
/// decimals, unless rounding would bring it within the limits (then as it is).
pub fn beyond(v: f64, lo: f64, hi: f64) -> f64 {
    let r = (v * 1e4).round() / 1e4;
    if (lo..=hi).contains(&r) {
        v
    } else {
        r
    }
}

/// An error naming the pose and the linear axis when `xyz` leaves the machine's travel.
pub fn check_travel(m: &Machine, pose: usize, xyz: DVec3) -> Result<()> {
    for (k, [lo, hi]) in m.travel.iter().enumerate() {
        let v = xyz[k];
        if !(*lo - 1e-9..=*hi + 1e-9).contains(&v) {
            return Err(Error::Unreachable {
                pose,
                line: None,
                message: crate::msg!(
                    "pose-unreachable",
                    pose = pose,
                    axis = ["X", "Y", "Z"][k],
                    value = beyond(v, *lo, *hi),
                    min = *lo,
                    max = *hi
                ),
            });
        }
    }
    Ok(())
}

/// Whether the part-frame axis `a` is at the pole of `m` (an angle left free).
pub fn at_pole(m: &Machine, a: DVec3) -> bool {
    orientations(m, a).iter().any(|o| o[0].is_none() || o[1].is_none())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An error's axis value: the program's 4 decimals, more where they would hide the violation.
    #[test]
    fn a_value_beyond_its_limits_is_stated_to_four_decimals() {
        assert_eq!(beyond(167.99958945184727, -120.0, 120.0), 167.9996);
        assert_eq!(beyond(-120.00000004, -120.0, 120.0), -120.00000004);
        assert_eq!(beyond(f64::INFINITY, 0.0, 1.0), f64::INFINITY);
    }
    use crate::machine::MACHINE_PRESETS;
    use crate::solve::inverse_kinematics;

    fn pose(tip: [f64; 3], axis: [f64; 3]) -> Pose {
        Pose { tip: DVec3::from(tip), axis: DVec3::from(axis).normalize() }
    }

    #[test]
    fn both_solutions_give_the_axis() {
        for name in MACHINE_PRESETS {
            let m = Machine::preset(name).unwrap();
            for a in [[0.3, -0.5, 0.8], [-0.6, 0.2, 0.5], [0.0, 0.4, 0.9]] {
                let a = DVec3::from(a).normalize();
                let sols = orientations(&m, a);
                assert_eq!(sols.len(), 2, "{name}");
                for s in sols {
                    let v = [m.rotary[0].value(s[0].unwrap()), m.rotary[1].value(s[1].unwrap())];
                    assert!((tool_axis(&m, v) - a).length() < 1e-12, "{name}: {a}");
                }
            }
        }
    }

    #[test]
    fn inverse_then_forward_is_the_identity() {
        for name in MACHINE_PRESETS {
            let m = Machine::preset(name).unwrap();
            let poses = [pose([1.0, 2.0, 3.0], [0.2, 0.1, 1.0]), pose([4.0, -2.0, 1.0], [-0.3, 0.4, 0.9])];
            let j = inverse_kinematics(&m, &poses, 40.0).unwrap();
            for (p, j) in poses.iter().zip(&j) {
                let q = forward_kinematics(&m, j, 40.0);
                assert!((q.tip - p.tip).length() < 1e-9 && (q.axis - p.axis).length() < 1e-12, "{name}");
            }
        }
    }

    #[test]
    fn the_old_table_table_convention_holds() {
        // A = atan2(√(i² + j²), k), C = atan2(i, j) for the trunnion without offsets
        let mut m = Machine::preset("table-table-ac").unwrap();
        m.rotary[0].pivot = [0.0; 3];
        m.part_zero = [0.0; 3];
        let a = DVec3::new(0.3, -0.5, 0.8).normalize();
        let j = inverse_kinematics(&m, &[Pose { tip: DVec3::new(1.0, 2.0, 3.0), axis: a }], 10.0).unwrap()[0];
        assert!((j.rotary[0] - a.x.hypot(a.y).atan2(a.z).to_degrees()).abs() < 1e-9);
        assert!((j.rotary[1] - a.x.atan2(a.y).to_degrees()).abs() < 1e-9);
        let r = DMat3::from_rotation_x(j.rotary[0].to_radians()) * DMat3::from_rotation_z(j.rotary[1].to_radians());
        assert!((j.xyz - r * DVec3::new(1.0, 2.0, 3.0)).length() < 1e-12);
    }

    #[test]
    fn the_pole_takes_the_neighbours_angle() {
        let m = Machine::preset("table-table-ac").unwrap();
        let poses = [pose([0.0; 3], [0.5, 0.5, 0.7]), pose([1.0, 0.0, 0.0], [0.0, 0.0, 1.0])];
        let j = inverse_kinematics(&m, &poses, 10.0).unwrap();
        assert_eq!(j[1].rotary[1], j[0].rotary[1]);
        assert!(j[1].rotary[0].abs() < 1e-12);
        assert!(at_pole(&m, DVec3::Z) && !at_pole(&m, DVec3::X));
    }

    #[test]
    fn a_pose_beyond_the_limits_is_named() {
        let m = Machine::preset("table-table-ac").unwrap();
        // the axis pointing down into the part: A would be 180°
        let poses = [pose([0.0; 3], [0.0, 0.3, 1.0]), pose([0.0; 3], [0.0, 0.1, -1.0])];
        let e = inverse_kinematics(&m, &poses, 10.0).unwrap_err();
        assert_eq!(e.code(), "unreachable");
        assert!(e.to_string().starts_with("pose 1 cannot be reached"), "{e}");
    }

    /// Tilts of 10⁻³ … 10⁻⁹ rad from the pole: the orientation is as accurate as anywhere else.
    /// (1 − α² − β² lost all but a few digits of γ² ~ tilt² there: at a tilt of 4·10⁻⁸ rad the
    /// axis came back 5.8·10⁻¹⁰ off; the property test found 4·10⁻¹¹ at a tilt of 2·10⁻⁶ rad.)
    #[test]
    fn axes_near_the_pole_come_back_exactly() {
        for name in MACHINE_PRESETS {
            let m = Machine::preset(name).unwrap();
            for tilt in [1e-3f64, 1e-5, 4e-8, 2e-9] {
                for turn in [0.3f64, 2.0, -2.5] {
                    let a = DVec3::new(tilt.sin() * turn.cos(), tilt.sin() * turn.sin(), tilt.cos());
                    let sols = orientations(&m, a);
                    assert!(!sols.is_empty(), "{name}: tilt {tilt}");
                    for s in sols {
                        let v = [m.rotary[0].value(s[0].unwrap()), m.rotary[1].value(s[1].unwrap())];
                        let err = (tool_axis(&m, v) - a).length();
                        assert!(err < 1e-15, "{name}: tilt {tilt}, turn {turn}: {err:e}");
                    }
                }
            }
        }
    }

    #[test]
    fn angles_wrap_into_a_turn_and_steps_wrap_on_continuous_axes() {
        assert_eq!([wrap(370.0), wrap(-190.0), wrap(725.0), wrap(0.0), wrap(-90.0)], [10.0, 170.0, 5.0, 0.0, -90.0]);
        // a limited axis cannot go the short way round; a continuous one can
        assert_eq!(step(Value::Fixed(10.0), Value::Fixed(350.0)), 340.0);
        assert_eq!(step(Value::Turn(10.0), Value::Fixed(350.0)), 20.0);
        assert_eq!(step(Value::Fixed(-170.0), Value::Turn(170.0)), 20.0);
        assert_eq!(step(Value::Turn(30.0), Value::Turn(-45.0)), 75.0);
    }

    /// The head turns the tip about its pivot c′ = pivot + L·Z: at 180° the tip goes to
    /// c′ − R c′ = 2 c′ for a pivot on the spindle's axis, whichever way the axis counts.
    #[test]
    fn the_head_turns_the_tip_about_its_pivot() {
        // head-table-bc: B's pivot 150 mm above the nose, a 40 mm tool: c′ = (0, 0, 190)
        let m = Machine::preset("head-table-bc").unwrap();
        assert_eq!(head_offset(&m, [0.0, 0.0], 40.0), DVec3::ZERO);
        assert!((head_offset(&m, [180.0, 0.0], 40.0) - DVec3::new(0.0, 0.0, 380.0)).length() < 1e-12);
        let quarter = head_offset(&m, [90.0, 0.0], 40.0);
        assert!(
            (quarter.x.abs() - 190.0).abs() < 1e-12 && quarter.y.abs() < 1e-12 && (quarter.z - 190.0).abs() < 1e-12
        );
        // head-head-ac: A's pivot 120 mm up; C (pivot on the spindle's axis) does not move it
        let m = Machine::preset("head-head-ac").unwrap();
        for c in [0.0, 90.0, -135.0] {
            assert!((head_offset(&m, [c, 180.0], 40.0) - DVec3::new(0.0, 0.0, 320.0)).length() < 1e-12, "C = {c}");
        }
    }

    /// Near the pole two solutions closer than 10⁻¹² are one; elsewhere the two differ.
    #[test]
    fn one_solution_at_the_pole_two_elsewhere() {
        let m = Machine::preset("table-table-ac").unwrap();
        for tilt in [0.0f64, 1e-13] {
            assert_eq!(orientations(&m, DVec3::new(tilt.sin(), 0.0, tilt.cos())).len(), 1, "tilt {tilt}");
        }
        let sols = orientations(&m, DVec3::new(0.3, -0.5, 0.8).normalize());
        assert_eq!(sols.len(), 2);
        assert!(
            (sols[0][0].unwrap() + sols[1][0].unwrap()).abs() < 1e-12 && sols[0][0].unwrap().abs() > 0.1,
            "{sols:?}"
        );
    }

    /// A machine whose head turns about Z (C) over a table tilting about X (A): its axes reach
    /// only tool axes normal to X, each with C free; X itself is out of reach.
    #[test]
    fn a_head_turning_about_z_over_a_tilting_table() {
        let mut m = Machine::preset("head-table-bc").unwrap();
        m.rotary[0].name = crate::machine::AxisName::C;
        m.rotary[1].name = crate::machine::AxisName::A;
        m.validate().unwrap();
        assert!(orientations(&m, DVec3::X).is_empty());
        for t in [0.4f64, -1.1, 2.0] {
            let a = DVec3::new(0.0, t.sin(), t.cos());
            let sols = orientations(&m, a);
            assert_eq!(sols.len(), 1, "{t}");
            let [c, tilt] = sols[0];
            assert!(c.is_none());
            let v = [0.0, m.rotary[1].value(tilt.unwrap())];
            assert!((tool_axis(&m, v) - a).length() < 1e-15, "{t}: {}", tool_axis(&m, v));
        }
    }

    /// An axis tilted by `tilt`° from Z towards the direction `turn`° about Z.
    fn tilted(tilt: f64, turn: f64) -> [f64; 3] {
        let (t, f) = (tilt.to_radians(), turn.to_radians());
        [t.sin() * f.cos(), t.sin() * f.sin(), t.cos()]
    }

    /// What is out of reach is named: the orientation's axis nearest its limits (A would be
    /// ±130°, 10° and 100° beyond), or the linear axis that leaves its travel.
    #[test]
    fn unreachable_poses_are_named_with_the_axis_and_its_limits() {
        let m = Machine::preset("table-table-ac").unwrap();
        let e = inverse_kinematics(&m, &[pose([0.0; 3], tilted(130.0, 90.0))], 40.0).unwrap_err();
        assert_eq!(e.to_string(), "pose 0 cannot be reached: A would be 130, outside its limits -30 to 120");
        let far = [pose([0.0; 3], [0.0, 0.0, 1.0]), pose([900.0, 0.0, 0.0], [0.0, 0.0, 1.0])];
        let e = inverse_kinematics(&m, &far, 40.0).unwrap_err();
        assert_eq!(e.to_string(), "pose 1 cannot be reached: X would be 910, outside its limits -500 to 500");
        // the travel's ends are inside it
        for x in [-500.0, 500.0] {
            assert!(check_travel(&m, 0, DVec3::new(x, 400.0, -400.0)).is_ok(), "{x}");
        }
        assert!(check_travel(&m, 0, DVec3::new(500.001, 0.0, 0.0)).is_err());
        assert!(check_travel(&m, 0, DVec3::new(0.0, 0.0, -400.001)).is_err());
        // limits the other way round: now −130 is the nearer (10° below −120; 130 is 100° above 30)
        let mut flipped = m.clone();
        (flipped.rotary[0].min, flipped.rotary[0].max) = (Some(-120.0), Some(30.0));
        let e = inverse_kinematics(&flipped, &[pose([0.0; 3], tilted(130.0, 90.0))], 40.0).unwrap_err();
        assert_eq!(e.to_string(), "pose 0 cannot be reached: A would be -130, outside its limits -120 to 30");
        // a controller value of 360 at the zero position: the value named is within a turn of 0
        let mut turned = m.clone();
        turned.rotary[0].zero = 360.0;
        let e = inverse_kinematics(&turned, &[pose([0.0; 3], tilted(130.0, 90.0))], 40.0).unwrap_err();
        assert_eq!(e.to_string(), "pose 0 cannot be reached: A would be 130, outside its limits -30 to 120");
    }

    /// The values an angle may take: a limited axis every turn within its limits, a
    /// continuous one the angle wrapped into (−180°, 180°], a one-sided one MAX_AXIS_TURNS turns
    /// up from its limit.
    #[test]
    fn the_values_of_an_angle_on_each_kind_of_axis() {
        let fixed = |vs: Vec<Value>| -> Vec<f64> {
            vs.iter().map(|v| if let Value::Fixed(x) = v { (x * 1e9).round() / 1e9 } else { f64::NAN }).collect()
        };
        let m = Machine::preset("head-head-ac").unwrap();
        assert_eq!(fixed(values(&m, 0, 10f64.to_radians())), [-350.0, 10.0]);
        assert_eq!(fixed(values(&m, 1, 100f64.to_radians())), [100.0]);
        assert!(values(&m, 1, 115f64.to_radians()).is_empty());
        let t = Machine::preset("table-table-ac").unwrap();
        assert!(matches!(values(&t, 1, 370f64.to_radians())[..], [Value::Turn(x)] if (x - 10.0).abs() < 1e-9));
        let mut one_sided = t.clone();
        one_sided.rotary[0].max = None;
        let up = fixed(values(&one_sided, 0, 10f64.to_radians()));
        assert_eq!(up, (0..MAX_AXIS_TURNS).map(|n| 10.0 + 360.0 * n as f64).collect::<Vec<_>>());
        // a maximum alone: the turns below it, down from the nearest (it was MAX_AXIS_TURNS turns
        // below the value itself, which left out the value, 10, and every turn up to it)
        one_sided.rotary[0] = crate::machine::RotaryAxis { min: None, max: Some(20.0), ..t.rotary[0] };
        let down = fixed(values(&one_sided, 0, 10f64.to_radians()));
        assert_eq!(down, (0..MAX_AXIS_TURNS).rev().map(|n| 10.0 - 360.0 * n as f64).collect::<Vec<_>>());
        let j = inverse_kinematics(&one_sided, &[pose([0.0; 3], tilted(10.0, 90.0))], 40.0).unwrap()[0];
        assert!((j.rotary[0].abs() - 10.0).abs() < 1e-9, "{j:?}");
    }

    /// The first pose takes the solution nearest zero; a continuous C follows the path round
    /// and round without jumping back; a pose at the pole takes its free C from its neighbour.
    #[test]
    fn the_axes_move_least() {
        let m = Machine::preset("table-table-ac").unwrap();
        for turn in [30.0, 120.0, -150.0] {
            let j = inverse_kinematics(&m, &[pose([0.0; 3], tilted(20.0, turn))], 40.0).unwrap()[0];
            assert!(j.rotary[1].abs() <= 90.0 + 1e-9 && (j.rotary[0].abs() - 20.0).abs() < 1e-9, "{turn}: {j:?}");
        }
        let round: Vec<Pose> = (0..=72).map(|k| pose([0.0; 3], tilted(20.0, 10.0 * k as f64))).collect();
        let j = inverse_kinematics(&m, &round, 40.0).unwrap();
        for w in j.windows(2) {
            let d = w[1].rotary[1] - w[0].rotary[1];
            assert!((d.abs() - 10.0).abs() < 1e-9 && (w[1].rotary[0] - w[0].rotary[0]).abs() < 1e-9, "{w:?}");
        }
        assert!((j[72].rotary[1] - j[0].rotary[1]).abs() > 719.0);
        let pole_first =
            inverse_kinematics(&m, &[pose([0.0; 3], [0.0, 0.0, 1.0]), pose([0.0; 3], tilted(20.0, 50.0))], 40.0)
                .unwrap();
        assert!((pole_first[0].rotary[1] - pole_first[1].rotary[1]).abs() < 1e-9, "{pole_first:?}");
        // a pose repeated costs no motion whichever solution: the one nearer zero stays chosen
        for turn in [50.0, 140.0, -120.0, -20.0] {
            let twice = [pose([0.0; 3], tilted(20.0, turn)), pose([1.0, 0.0, 0.0], tilted(20.0, turn))];
            let j = inverse_kinematics(&m, &twice, 40.0).unwrap();
            assert!(j.iter().all(|j| j.rotary[1].abs() <= 90.0 + 1e-9), "{turn}: {j:?}");
        }
        // and of the neighbour's two solutions, the one nearer zero (the pole's A = 0 does not
        // make every C as good)
        for turn in [50.0, 140.0, -120.0, -20.0] {
            let j =
                inverse_kinematics(&m, &[pose([0.0; 3], [0.0, 0.0, 1.0]), pose([0.0; 3], tilted(20.0, turn))], 40.0)
                    .unwrap();
            assert!(j[1].rotary[1].abs() <= 90.0 + 1e-9, "{turn}: {j:?}");
        }
    }
}
