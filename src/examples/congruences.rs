//! The line congruences of Examples 4 and 5 (Section 5, Figs. 13 and 15), in closed form:
//! a line L(u, v) through p(u, v) on the director surface d₁ with direction d(u, v); the
//! segment runs to q = p + d (the paper gives no length; ERRATA.md 9).
//!
//! - `sphere` (Fig. 13 left): d₁ the unit sphere p = (cos v cos u, cos v sin u, sin v),
//!   d = normal + 0.3 (sin 2v, cos 3u, uv): a generalised offset, not a normal congruence.
//! - `hyperbolic-paraboloid` (Fig. 13 right): d₁: z = xy, p = (u, v, uv),
//!   d = (−v, −u, 1) + 0.3 (cos 2v, sin u, 0).
//! - `example5` (Fig. 15): d₁ = (u, v, ½ sin(2u + 1.5v)), d = (u, v, sin u + 1.3 cos v),
//!   an 8 × 7 grid on [−1.1, 1.1]², K = 6.

use crate::congruence::LineCongruence;
use crate::error::{Error, Result};
use glam::DVec3;

/// The congruences of the paper's examples.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AnalyticCongruence {
    /// Lines on a part of the unit sphere (Example 4, Fig. 13 left).
    Sphere,
    /// Lines on the hyperbolic paraboloid z = xy (Example 4, Fig. 13 right).
    HyperbolicParaboloid,
    /// Example 5 (Fig. 15).
    Example5,
}

impl AnalyticCongruence {
    /// Every congruence.
    pub const ALL: [AnalyticCongruence; 3] = [Self::Sphere, Self::HyperbolicParaboloid, Self::Example5];

    /// Machine name.
    pub fn name(&self) -> &'static str {
        match self {
            Self::Sphere => "sphere",
            Self::HyperbolicParaboloid => "hyperbolic-paraboloid",
            Self::Example5 => "example5",
        }
    }

    /// Human title.
    pub fn title(&self) -> &'static str {
        match self {
            Self::Sphere => "Lines on a sphere (Example 4, Fig. 13 left)",
            Self::HyperbolicParaboloid => "Lines on a hyperbolic paraboloid (Example 4, Fig. 13 right)",
            Self::Example5 => "Example 5: d₁ = (u, v, ½ sin(2u + 1.5v)) (Fig. 15)",
        }
    }

    /// The congruence of that name.
    pub fn by_name(name: &str) -> Result<Self> {
        Self::ALL.into_iter().find(|c| c.name() == name).ok_or_else(|| {
            Error::parameter("name", format!("unknown congruence \"{name}\"; known: sphere, hyperbolic-paraboloid, example5"))
        })
    }

    /// The parameter square of the paper's figure and its grid size.
    pub fn domain(&self) -> ((f64, f64), (f64, f64), usize, usize) {
        match self {
            Self::Sphere => ((-0.8, 0.8), (-0.6, 0.6), 6, 6),
            Self::HyperbolicParaboloid => ((-1.0, 1.0), (-1.0, 1.0), 6, 6),
            Self::Example5 => ((-1.1, 1.1), (-1.1, 1.1), 8, 7),
        }
    }

    /// p(u, v) on d₁ and the line direction d(u, v).
    pub fn line(&self, u: f64, v: f64) -> (DVec3, DVec3) {
        match self {
            Self::Sphere => {
                let p = DVec3::new(v.cos() * u.cos(), v.cos() * u.sin(), v.sin());
                (p, p + 0.3 * DVec3::new((2.0 * v).sin(), (3.0 * u).cos(), u * v))
            }
            Self::HyperbolicParaboloid => {
                (DVec3::new(u, v, u * v), DVec3::new(-v, -u, 1.0) + 0.3 * DVec3::new((2.0 * v).cos(), u.sin(), 0.0))
            }
            Self::Example5 => (DVec3::new(u, v, 0.5 * (2.0 * u + 1.5 * v).sin()), DVec3::new(u, v, u.sin() + 1.3 * v.cos())),
        }
    }

    /// The rows × cols grid of lines p → p + d at equally spaced (u_i, v_j) of the domain.
    pub fn grid(&self, rows: usize, cols: usize) -> Result<LineCongruence> {
        crate::congruence::grid::check_shape(rows, cols)?;
        let ((u0, u1), (v0, v1), _, _) = self.domain();
        let (p, q): (Vec<DVec3>, Vec<DVec3>) = (0..rows * cols)
            .map(|k| {
                let u = u0 + (u1 - u0) * (k / cols) as f64 / (rows - 1) as f64;
                let v = v0 + (v1 - v0) * (k % cols) as f64 / (cols - 1) as f64;
                let (p, d) = self.line(u, v);
                (p, p + d)
            })
            .unzip();
        LineCongruence::from_points(rows, cols, &p, &q)
    }

    /// Errors of a refined grid (from [`AnalyticCongruence::grid`]) against the exact lines at
    /// the same parameters, over its new lines: (largest distance |P − p|, largest angle
    /// between P → Q and d, in radians).
    pub fn errors(&self, refined: &LineCongruence) -> (f64, f64) {
        let ((u0, u1), (v0, v1), _, _) = self.domain();
        let (rows, cols) = (refined.rows(), refined.cols());
        let mut worst = (0.0f64, 0.0f64);
        for i in 0..rows {
            for j in 0..cols {
                if i % 2 == 0 && j % 2 == 0 {
                    continue;
                }
                let u = u0 + (u1 - u0) * i as f64 / (rows - 1) as f64;
                let v = v0 + (v1 - v0) * j as f64 / (cols - 1) as f64;
                let (p, d) = self.line(u, v);
                let s = refined.line(i, j);
                worst.0 = worst.0.max((s.a - p).length());
                worst.1 = worst.1.max(s.vector().angle_between(d));
            }
        }
        worst
    }
}
