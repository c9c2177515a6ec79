//! What a dragged handle is snapped onto (beyond the paper): a point of the figure (another
//! handle, a footpoint, the apex of a cone), a line (a ruling, the neighbour's line, a tool axis,
//! the axis of a linear complex) or a plane — as a scene declares them, in the coordinates of
//! the scene's input.
//!
//! Bad targets are harmless: a line through two coincident points (a ruling of zero length) is
//! the point, a plane without a normal, or anything with a coordinate that is not finite or
//! beyond [`MAX_COORD`] (a target "at infinity"), is no target at all.

use crate::tolerance::{MAX_COORD, ZERO_LENGTH_REL};
use glam::DVec3;

/// A point, line or plane a dragged handle can be snapped onto.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Target {
    /// The point itself.
    Point(DVec3),
    /// The line point + t·direction (a ruling a_i → b_i: point a_i, direction b_i − a_i, so
    /// that a point found on it is a_i + t·(b_i − a_i), on it to rounding).
    Line {
        /// A point of the line.
        point: DVec3,
        /// Its direction, of any length (zero: the line is the point).
        direction: DVec3,
    },
    /// The plane through `point` orthogonal to `normal`.
    Plane {
        /// A point of the plane.
        point: DVec3,
        /// Its normal, of any length (zero: no plane).
        normal: DVec3,
    },
}

/// A target or a constraint made safe to compute with: directions and normals non-zero, every
/// coordinate finite and within [`MAX_COORD`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Shape {
    Point(DVec3),
    Line(DVec3, DVec3),
    Plane(DVec3, DVec3),
}

/// Whether every coordinate of `v` is finite and at most [`MAX_COORD`] in magnitude.
pub(super) fn sane(v: DVec3) -> bool {
    v.is_finite() && v.abs().max_element() <= MAX_COORD
}

/// Whether the direction `d` from `p` is too short to give a line (relative to where it is):
/// |d| ≤ ZERO_LENGTH_REL·|p| (at the origin only the zero vector; measuring against |p + d| as
/// well would change nothing, as |p + d| exceeds |p| by at most |d|).
pub(super) fn vanishes(p: DVec3, d: DVec3) -> bool {
    d.length() <= ZERO_LENGTH_REL * p.length()
}

impl Target {
    /// The target's shape, or `None` where it is none (see the module's documentation).
    pub(super) fn shape(&self) -> Option<Shape> {
        match *self {
            Target::Point(p) => sane(p).then_some(Shape::Point(p)),
            Target::Line { point, direction } => {
                if !sane(point) || !sane(direction) {
                    None
                } else if vanishes(point, direction) {
                    Some(Shape::Point(point))
                } else {
                    Some(Shape::Line(point, direction))
                }
            }
            Target::Plane { point, normal } => {
                (sane(point) && sane(normal) && normal != DVec3::ZERO).then_some(Shape::Plane(point, normal))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_direction_vanishes_relative_to_where_it_is() {
        // ZERO_LENGTH_REL (1e-12) of the larger of |p| and |p + d|
        let p = DVec3::new(3e6, 0.0, 4e6); // |p| = 5e6: directions up to 5e-6 vanish
        assert!(vanishes(p, DVec3::new(0.0, 4e-6, 0.0)));
        assert!(!vanishes(p, DVec3::new(0.0, 6e-6, 0.0)));
        // at the origin no direction vanishes but zero
        assert!(!vanishes(DVec3::ZERO, DVec3::new(0.0, 1e-100, 0.0)));
        assert!(vanishes(DVec3::ZERO, DVec3::ZERO));
        // a long direction from near the origin: its own length is the scale
        assert!(!vanishes(DVec3::new(1e-3, 0.0, 0.0), DVec3::new(0.0, 0.0, 2.0)));
    }

    #[test]
    fn degenerate_targets_are_points_or_nothing() {
        let p = DVec3::new(1.0, 2.0, 3.0);
        // a ruling of zero length is its point
        assert_eq!(Target::Line { point: p, direction: DVec3::ZERO }.shape(), Some(Shape::Point(p)));
        assert_eq!(Target::Line { point: p, direction: DVec3::splat(1e-16) }.shape(), Some(Shape::Point(p)));
        assert_eq!(Target::Line { point: p, direction: DVec3::X }.shape(), Some(Shape::Line(p, DVec3::X)));
        // at infinity, NaN, beyond the largest coordinate: no target
        assert_eq!(Target::Point(DVec3::new(f64::INFINITY, 0.0, 0.0)).shape(), None);
        assert_eq!(Target::Point(DVec3::new(0.0, f64::NAN, 0.0)).shape(), None);
        assert_eq!(Target::Point(DVec3::new(0.0, 0.0, 1e200)).shape(), None);
        assert_eq!(Target::Line { point: p, direction: DVec3::new(0.0, f64::INFINITY, 0.0) }.shape(), None);
        assert_eq!(Target::Plane { point: p, normal: DVec3::ZERO }.shape(), None);
        assert_eq!(Target::Plane { point: p, normal: DVec3::Z }.shape(), Some(Shape::Plane(p, DVec3::Z)));
    }
}
