//! Discrete Minding isometries: the hinge chain of Section 3, and the isometric conoidal
//! model of Example 2 (Figs. 4–5).
//!
//! Two consecutive rulings R_i, R_{i+1} with their common perpendicular N_{i,i+1} form a
//! rigid body S_{i,i+1}; the ruling R_i is a hinge between S_{i−1,i} and S_{i,i+1}. Turning
//! the hinges by angles θ_1 … θ_{N−2} (body S_{0,1} stays put) moves every point of R_i with
//! its bodies and preserves the length of every polygon p_i ∈ R_i.
//!
//! **Hinge angles.** At hinge R_i, τ_i is the signed angle about e_i from n_{i−1,i} to
//! n_{i,i+1}: an intrinsic quantity of the discrete surface. A deformation composes
//! rotations about the original hinges (see [`HingeChain::deform`]), so a chain of 10⁵
//! rulings keeps every body rigid to ~1e-15 and does not drift (measured in the tests).
//!
//! **Conoidal model** (Example 2): θ_i = −τ_i turns each body until n_{i,i+1} points the
//! same way as n_{0,1} (docs/src/conventions.md, Section 3); then every ruling is orthogonal to n_{0,1}. The bending
//! parameter t ∈ [0, 1] uses θ_i = −t τ_i: t = 0 is the input, t = 1 the conoidal model.
//!
//! **Parallel pairs** have no unique common perpendicular. Two parallel rulings span a plane,
//! as two intersecting rulings do, and the body then takes that plane's unit normal
//! e_i × (the perpendicular from R_i towards R_{i+1}), turned to agree with the previous body's
//! (for coincident rulings the previous body's perpendicular itself), so the chain and the
//! conoidal model stay defined and a parallel pair adds no height, as a meeting pair does: a
//! sampled cylinder bends into one plane, with its rulings at the chord distances, and its
//! non-developability is 0 (docs/src/conventions.md, Section 3).

use crate::error::{Error, Result};
use crate::line::Line;
use crate::ruled::RuledSurface;
use crate::tolerance::{PARALLEL_SIN, ZERO_LENGTH_REL};
use glam::{DQuat, DVec3};

/// A discrete ruled surface as a hinge chain, ready to be deformed isometrically.
#[derive(Debug, Clone, PartialEq)]
pub struct HingeChain {
    surface: RuledSurface,
    /// The hinges R_1 … R_{N−2} as lines.
    hinges: Vec<Line>,
    /// τ_i for the hinges R_1 … R_{N−2}.
    tau: Vec<f64>,
    /// n_{0,1} (or the first body's perpendicular when R_0 ∥ R_1).
    first_normal: DVec3,
}

/// The unit perpendicular of the body on `r0`, `r1` (see the module docs).
fn body_normal(r0: &Line, r1: &Line, previous: Option<DVec3>) -> DVec3 {
    let c = r0.dir.cross(r1.dir);
    let sin = c.length();
    if sin >= PARALLEL_SIN {
        return c / sin;
    }
    let d = r1.point - r0.point;
    let perp = d.reject_from_normalized(r0.dir);
    let scale = r0.point.length().max(r1.point.length()).max(d.length());
    if perp.length() > ZERO_LENGTH_REL * scale {
        // the normal of the plane of the two rulings: the pair lies at one height, as a
        // meeting pair does (either sign is a normal; the previous body's picks the smaller turn)
        let normal = r0.dir.cross(perp).normalize();
        return match previous {
            Some(p) if p.dot(normal) < 0.0 => -normal,
            _ => normal,
        };
    }
    previous
        .map(|p| p.reject_from_normalized(r0.dir))
        .and_then(DVec3::try_normalize)
        .unwrap_or_else(|| r0.dir.any_orthonormal_vector())
}

/// Signed angle about unit `axis` from `from` to `to`, both made orthogonal to the axis.
fn signed_angle(from: DVec3, to: DVec3, axis: DVec3) -> f64 {
    let (from, to) = (from.reject_from_normalized(axis), to.reject_from_normalized(axis));
    from.cross(to).dot(axis).atan2(from.dot(to))
}

impl HingeChain {
    /// The chain of `surface` (O(N)).
    pub fn new(surface: &RuledSurface) -> Self {
        let lines: Vec<Line> = surface.lines().collect();
        let mut normals: Vec<DVec3> = Vec::with_capacity(lines.len() - 1);
        for w in lines.windows(2) {
            let previous = normals.last().copied();
            normals.push(body_normal(&w[0], &w[1], previous));
        }
        let tau = (1..lines.len() - 1).map(|i| signed_angle(normals[i - 1], normals[i], lines[i].dir)).collect();
        HingeChain {
            surface: surface.clone(),
            hinges: lines[1..lines.len() - 1].to_vec(),
            tau,
            first_normal: normals[0],
        }
    }

    /// τ_i, the hinge angles of the input (N − 2 values, for R_1 … R_{N−2}).
    pub fn hinge_angles(&self) -> &[f64] {
        &self.tau
    }

    /// n_{0,1}, the direction all common perpendiculars share in the conoidal model.
    pub fn first_normal(&self) -> DVec3 {
        self.first_normal
    }

    /// The surface with hinge R_k turned by θ_k (`angles[k − 1]`, k = 1 … N − 2).
    pub fn deform(&self, angles: &[f64]) -> Result<RuledSurface> {
        if angles.len() != self.tau.len() {
            return Err(Error::parameter(
                "angles",
                format!(
                    "need one angle per interior ruling: {} for {} rulings, got {}",
                    self.tau.len(),
                    self.surface.len(),
                    angles.len()
                ),
            ));
        }
        if let Some(k) = angles.iter().position(|a| !a.is_finite()) {
            return Err(Error::parameter("angles", format!("angle {k} is {}, must be finite", angles[k])));
        }
        Ok(self.rebuild(|k| angles[k]))
    }

    /// The isometric conoidal model (Example 2): every n_{i,i+1} turned onto n_{0,1}.
    pub fn conoidal(&self) -> RuledSurface {
        self.rebuild(|k| -self.tau[k])
    }

    /// The bending R(t) from the input (t = 0) to the conoidal model (t = 1): θ_k = −t τ_k.
    pub fn bend(&self, t: f64) -> Result<RuledSurface> {
        if !(t.is_finite() && (0.0..=1.0).contains(&t)) {
            return Err(Error::parameter("t", format!("must be a number in [0, 1], got {t}")));
        }
        Ok(self.rebuild(|k| -t * self.tau[k]))
    }

    /// Body S_{i,i+1} moves by M_i = M_{i−1} ∘ Rot(R_i, θ_i), M_0 = id, and ruling R_j by
    /// M_{j−1}. Each factor is a rotation about an *original* hinge, whose rounding error is
    /// proportional to its angle (zero for θ = 0). The product is formed in two levels,
    /// within blocks of about √N hinges and across blocks, so rounding in the products
    /// does not build up along the chain either (measured on 10⁵ rulings in the tests).
    fn rebuild(&self, theta: impl Fn(usize) -> f64) -> RuledSurface {
        let n = self.surface.len();
        let block = (n as f64).sqrt().ceil() as usize;
        let (mut block_start, mut local) = (Rigid::IDENTITY, Rigid::IDENTITY);
        let mut points = Vec::with_capacity(2 * n);
        let src = self.surface.points();
        points.extend_from_slice(&src[..4]);
        for (k, hinge) in self.hinges.iter().enumerate() {
            if k > 0 && k % block == 0 {
                block_start = block_start.then(&local);
                local = Rigid::IDENTITY;
            }
            local = local.then(&Rigid::rotation_about(hinge, theta(k)));
            let m = block_start.then(&local);
            let j = k + 2; // the ruling that moves with body S_{k+1,k+2}
            points.extend([m.apply(src[2 * j]), m.apply(src[2 * j + 1])]);
        }
        RuledSurface::from_trusted_points(points)
    }
}

/// A rigid motion x ↦ q x + t.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Rigid {
    q: DQuat,
    t: DVec3,
}

impl Rigid {
    const IDENTITY: Rigid = Rigid { q: DQuat::IDENTITY, t: DVec3::ZERO };

    /// Rotation by `angle` about `line`: x ↦ p + q (x − p), with the translation
    /// (I − q) p = −sin θ (e × p) − 2 sin²(θ/2) e × (e × p) free of cancellation.
    fn rotation_about(line: &Line, angle: f64) -> Rigid {
        if angle == 0.0 {
            return Rigid::IDENTITY;
        }
        let (e, p) = (line.dir, line.point);
        let (s, c) = (angle / 2.0).sin_cos();
        let ep = e.cross(p);
        let t = -(2.0 * s * c) * ep - (2.0 * s * s) * e.cross(ep);
        Rigid { q: DQuat::from_xyzw(s * e.x, s * e.y, s * e.z, c), t }
    }

    /// self ∘ other.
    fn then(&self, other: &Rigid) -> Rigid {
        Rigid { q: (self.q * other.q).normalize(), t: self.t + self.q * other.t }
    }

    fn apply(&self, x: DVec3) -> DVec3 {
        self.q * x + self.t
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;
    use crate::tolerance::test::EXACT;
    use std::f64::consts::FRAC_PI_2;

    fn staircase() -> RuledSurface {
        // rulings along x, y, −x, … at heights 0, 1, 2, …: a discrete right helicoid
        RuledSurface::from_flat(&[
            0.0, 0.0, 0.0, 1.0, 0.0, 0.0, //
            0.0, 0.0, 1.0, 0.0, 1.0, 1.0, //
            0.0, 0.0, 2.0, -1.0, 0.0, 2.0, //
            0.0, 0.0, 3.0, 0.0, -1.0, 3.0,
        ])
        .unwrap()
    }

    #[test]
    fn zero_angles_reproduce_the_input() {
        let s = staircase();
        let chain = HingeChain::new(&s);
        assert_eq!(chain.hinge_angles(), &[0.0, 0.0]);
        let back = chain.deform(&[0.0, 0.0]).unwrap();
        for (p, q) in s.points().iter().zip(back.points()) {
            assert_near!(*p, *q, EXACT);
        }
    }

    #[test]
    fn a_quarter_turn_about_the_second_ruling_moves_only_what_follows() {
        let s = staircase();
        let turned = HingeChain::new(&s).deform(&[FRAC_PI_2, 0.0]).unwrap();
        // R_0 and R_1 fixed; R_2 turned about R_1 (the line x = 0, z = 1 along y):
        // its point (0, 0, 2) goes to (±1, 0, 1), direction −x to ±z.
        assert_near!(turned.segment(1).a, DVec3::new(0.0, 0.0, 1.0), EXACT);
        let a2 = turned.segment(2).a;
        assert_near!(a2.y, 0.0, EXACT);
        assert_near!(a2.z, 1.0, EXACT);
        assert_near!(a2.x.abs(), 1.0, EXACT);
        assert_near!(turned.segment(2).line().dir.z.abs(), 1.0, EXACT);
    }

    #[test]
    fn rejects_wrong_angle_counts_and_bad_t() {
        let chain = HingeChain::new(&staircase());
        assert!(chain.deform(&[0.0]).unwrap_err().to_string().contains("2 for 4 rulings, got 1"));
        assert!(chain.deform(&[0.0, f64::NAN]).is_err());
        for t in [-0.1, 1.5, f64::NAN, f64::INFINITY] {
            assert!(chain.bend(t).is_err());
        }
    }

    #[test]
    fn parallel_rulings_take_the_normal_of_their_plane_or_the_previous_perpendicular() {
        let line = |p: [f64; 3]| Line { point: DVec3::from(p), dir: DVec3::X };
        // skew: the unit common perpendicular e₀ × e₁
        let skew = Line { point: DVec3::ZERO, dir: DVec3::Y };
        assert_eq!(body_normal(&line([0.0, 0.0, 0.0]), &skew, None), DVec3::Z);
        // parallel, 2 apart in the plane z = 0: that plane's normal, e₀ × (0, −1, 0) = −z on its
        // own, turned to agree with the previous body's
        let (r0, r1) = (line([5.0, 3.0, 0.0]), line([0.0, 1.0, 0.0]));
        assert_eq!(body_normal(&r0, &r1, None), -DVec3::Z);
        assert_eq!(body_normal(&r0, &r1, Some(DVec3::new(0.0, 0.3, 1.0))), DVec3::Z);
        assert_eq!(body_normal(&r0, &r1, Some(-DVec3::Z)), -DVec3::Z);
        // antiparallel: the same plane
        let back = Line { point: DVec3::new(0.0, 1.0, 0.0), dir: -DVec3::X };
        assert_eq!(body_normal(&r0, &back, None), -DVec3::Z);
        // within 1e-12 of their size of each other (1e-10 at 1000), or the same line: the
        // previous body's perpendicular, made orthogonal to them
        let near = (line([1e3, 0.0, 0.0]), line([1e3, 1e-10, 0.0]));
        assert_eq!(body_normal(&near.0, &near.1, Some(DVec3::new(1.0, 0.0, 1.0))), DVec3::Z);
        assert_eq!(body_normal(&near.0, &near.0, Some(DVec3::Z)), DVec3::Z);
        let any = body_normal(&near.0, &near.0, None);
        assert!((any.length() - 1.0).abs() < 1e-15 && any.dot(DVec3::X) == 0.0);
    }

    #[test]
    fn a_long_chain_moves_as_the_rotations_composed_one_by_one() {
        // 10 rulings of a helicoid: the blocks of ⌈√10⌉ = 4 hinges are composed across blocks too
        let n = 10;
        let flat: Vec<f64> = (0..n)
            .flat_map(|k| {
                let (s, c) = (k as f64 * std::f64::consts::PI / 5.0).sin_cos();
                [0.0, 0.0, 0.5 * k as f64, c, s, 0.5 * k as f64]
            })
            .collect();
        let surface = RuledSurface::from_flat(&flat).unwrap();
        let chain = HingeChain::new(&surface);
        let angles: Vec<f64> = (0..n - 2).map(|k| 0.1 * (k + 1) as f64).collect();
        let moved = chain.deform(&angles).unwrap();
        // the reference: M_k = M_{k−1} ∘ Rot(R_k, θ_k) as affine maps, ruling j moved by M_{j−1}
        let mut m = glam::DAffine3::IDENTITY;
        for j in 0..n {
            if j >= 2 {
                let hinge = surface.segment(j - 1).line();
                let rot = glam::DAffine3::from_translation(hinge.point)
                    * glam::DAffine3::from_axis_angle(hinge.dir, angles[j - 2])
                    * glam::DAffine3::from_translation(-hinge.point);
                m *= rot;
            }
            let (want, got) = (surface.segment(j), moved.segment(j));
            assert_near!(m.transform_point3(want.a), got.a, 1e-14);
            assert_near!(m.transform_point3(want.b), got.b, 1e-14);
        }
        // bending: t = 0 is the input, t = 1 the conoidal model
        assert_eq!(chain.bend(0.0).unwrap(), surface);
        assert_eq!(chain.bend(1.0).unwrap(), chain.conoidal());
    }

    #[test]
    fn bending_turns_each_body_back_by_its_angle_times_t() {
        // rulings turning unevenly and climbing unevenly: the bodies' normals turn about the hinges
        let flat = [
            0.0, 0.0, 0.0, 1.0, 0.0, 0.0, //
            0.1, 0.2, 1.0, 0.3, 1.0, 1.4, //
            -0.2, 0.1, 2.1, -1.0, 0.5, 1.7, //
            0.3, -0.1, 2.9, 0.2, -1.1, 3.6, //
            0.0, 0.4, 4.2, 1.1, 0.9, 4.0, //
            0.2, 0.0, 5.0, 0.4, 1.2, 5.8,
        ];
        let surface = RuledSurface::from_flat(&flat).unwrap();
        let chain = HingeChain::new(&surface);
        assert!(chain.hinge_angles().iter().filter(|t| t.abs() > 0.5).count() >= 3, "{:?}", chain.hinge_angles());
        let minus: Vec<f64> = chain.hinge_angles().iter().map(|t| -0.5 * t).collect();
        assert_eq!(chain.bend(0.5).unwrap(), chain.deform(&minus).unwrap());
        assert_eq!(chain.bend(1.0).unwrap(), chain.conoidal());
        // the conoidal model's bodies all have the first body's normal: its hinge angles vanish
        let flat_again = HingeChain::new(&chain.conoidal());
        assert!(flat_again.hinge_angles().iter().all(|t| t.abs() < 1e-12), "{:?}", flat_again.hinge_angles());
    }
}
