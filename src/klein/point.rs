//! A line as a point of P⁵: its normalised Plücker coordinates, the Klein form and the Klein
//! residual (the Klein quadric's background; docs/src/conventions.md, "The Klein quadric").
//!
//! An oriented line with unit direction d through p is L = (d, m), m = p × d: |d| = 1 and
//! d·m = 0. A 6-vector (d, m) with d ≠ 0 that is not of this form (a combination of lines, as
//! the line-space subdivision makes before projecting back) is a point of P⁵ off the quadric M.
//!
//! **Klein form.** Ω(L₁, L₂) = d₁·m₂ + d₂·m₁ (K1), the polar form of the quadric M: Ω(L, L) = 2 d·m.
//! The same form, with a linear complex C = (c, c̄) in place of L₁, is the complex's equation
//! c·m + c̄·d = 0 (C1 of `linear_complex.rs`).
//!
//! **Klein residual.** ρ(L) = Ω(L, L)/(2|d|²) = d·m/|d|² (K3): the residual of L scaled to |d| = 1,
//! a length; 0 exactly on M, to rounding for every line made by [`KleinPoint::of_line`].

use crate::line::{Line, Segment};
use glam::DVec3;

/// A point of P⁵ given by six coordinates (d, m); a line when |d| = 1 and d·m = 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KleinPoint {
    /// The direction part d (the line's unit direction).
    pub d: DVec3,
    /// The moment part m (p × d for a point p of the line).
    pub m: DVec3,
}

/// Ω(L₁, L₂) = d₁·m₂ + d₂·m₁ (K1), the Klein form (the polar form of the quadric M).
pub fn klein_form(a: &KleinPoint, b: &KleinPoint) -> f64 {
    a.d.dot(b.m) + b.d.dot(a.m)
}

impl KleinPoint {
    /// The six coordinates (d, m) as they are.
    pub fn new(d: DVec3, m: DVec3) -> Self {
        KleinPoint { d, m }
    }

    /// The normalised Plücker coordinates (d, p × d) of an oriented line (|d| = 1).
    pub fn of_line(line: &Line) -> Self {
        KleinPoint { d: line.dir, m: line.point.cross(line.dir) }
    }

    /// The line a → b as a point of M.
    pub fn of_segment(segment: &Segment) -> Self {
        Self::of_line(&segment.line())
    }

    /// (d₁, d₂, d₃, m₁, m₂, m₃).
    pub fn to_array(&self) -> [f64; 6] {
        let (d, m) = (self.d, self.m);
        [d.x, d.y, d.z, m.x, m.y, m.z]
    }

    /// The point of the six coordinates `c` (inverse of [`to_array`](Self::to_array)).
    pub fn from_array(c: [f64; 6]) -> Self {
        KleinPoint { d: DVec3::new(c[0], c[1], c[2]), m: DVec3::new(c[3], c[4], c[5]) }
    }

    /// ρ = Ω(L, L)/(2|d|²) = d·m/|d|² (K3): 0 on M; NaN when d = 0 (a point of P⁵ that is no
    /// line of Euclidean space's lines with a direction).
    pub fn residual(&self) -> f64 {
        self.d.dot(self.m) / self.d.length_squared()
    }

    /// The point scaled by `s` (the same point of P⁵ for s ≠ 0).
    pub fn scaled(&self, s: f64) -> Self {
        KleinPoint { d: s * self.d, m: s * self.m }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The x-axis and the line through (0, 1, 0) along z: skew at distance 1, at right angles;
    /// Ω = d₁·m₂ + d₂·m₁ = x·((0,1,0) × z) + 0 = x·x = 1.
    #[test]
    fn klein_form_of_two_skew_lines() {
        let a = KleinPoint::of_line(&Line { point: DVec3::ZERO, dir: DVec3::X });
        let b = KleinPoint::of_line(&Line { point: DVec3::Y, dir: DVec3::Z });
        assert_eq!(b.m, DVec3::X);
        assert_eq!(klein_form(&a, &b), 1.0);
        assert_eq!(klein_form(&b, &a), 1.0);
        // the same line, and lines meeting at (0, 1, 0): Ω = 0
        let c = KleinPoint::of_line(&Line { point: DVec3::Y, dir: DVec3::X });
        assert_eq!(klein_form(&b, &c), 0.0);
        assert_eq!(klein_form(&b, &b), 0.0);
    }

    #[test]
    fn residual_is_zero_on_lines_and_the_moment_part_off_them() {
        let l = KleinPoint::of_line(&Line { point: DVec3::new(1.0, 2.0, 3.0), dir: DVec3::new(0.0, 0.6, 0.8) });
        assert!(l.residual().abs() < 1e-15);
        assert_eq!(KleinPoint::from_array(l.to_array()), l);
        // (2x, 3x): d·m/|d|² = 6/4
        let off = KleinPoint::new(2.0 * DVec3::X, 3.0 * DVec3::X);
        assert_eq!(off.residual(), 1.5);
        assert_eq!(off.scaled(-2.0).residual(), 1.5);
        assert!(KleinPoint::new(DVec3::ZERO, DVec3::X).residual().is_nan());
    }
}
