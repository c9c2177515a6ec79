//! How a dragged handle may move (beyond the paper): in the plane through it that faces the
//! viewer (free: a snap may take it anywhere), along a line (its own ruling, the vertical, an
//! axis an exercise names), in a plane, or not at all — the drag modes of the page and the
//! constraints a scene or an exercise declares. The core projects the pointer's ray onto the
//! constraint, and a snap keeps it.

use super::target::{sane, vanishes, Shape};
use glam::DVec3;

/// Where a dragged handle may go.
#[derive(Debug, Clone, Copy, PartialEq)]
// Line and Plane are written as Target's are, but a line here cannot lose its direction: two enums
pub enum Constraint {
    /// Anywhere: the pointer moves it in the plane through where it started with this normal
    /// (the view's direction), and a snap may take it off that plane.
    View {
        /// The plane's normal.
        normal: DVec3,
    },
    /// On the line point + t·direction (it stays on it when snapped).
    Line {
        /// A point of the line.
        point: DVec3,
        /// Its direction, of any non-zero length.
        direction: DVec3,
    },
    /// In the plane through `point` orthogonal to `normal` (it stays in it when snapped).
    Plane {
        /// A point of the plane.
        point: DVec3,
        /// Its normal, of any non-zero length.
        normal: DVec3,
    },
    /// Held at this point.
    Fixed(DVec3),
}

/// A constraint made safe: `None` for anywhere, else its shape; `Err(())` when it cannot hold
/// (a line without a direction, a plane without a normal, a coordinate that is not finite).
pub(super) fn shape_of(constraint: &Constraint, start: DVec3) -> Result<Option<Shape>, ()> {
    match *constraint {
        Constraint::View { normal } => {
            if sane(normal) && normal != DVec3::ZERO && sane(start) {
                Ok(None)
            } else {
                Err(())
            }
        }
        Constraint::Line { point, direction } => {
            if sane(point) && sane(direction) && !vanishes(point, direction) {
                Ok(Some(Shape::Line(point, direction)))
            } else {
                Err(())
            }
        }
        Constraint::Plane { point, normal } => {
            if sane(point) && sane(normal) && normal != DVec3::ZERO {
                Ok(Some(Shape::Plane(point, normal)))
            } else {
                Err(())
            }
        }
        Constraint::Fixed(p) => {
            if sane(p) {
                Ok(Some(Shape::Point(p)))
            } else {
                Err(())
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_constraint_that_cannot_hold_is_refused() {
        let p = DVec3::new(1.0, 2.0, 3.0);
        assert_eq!(shape_of(&Constraint::View { normal: DVec3::Z }, p), Ok(None));
        assert_eq!(shape_of(&Constraint::View { normal: DVec3::ZERO }, p), Err(()));
        assert_eq!(
            shape_of(&Constraint::Line { point: p, direction: DVec3::Z }, p),
            Ok(Some(Shape::Line(p, DVec3::Z)))
        );
        assert_eq!(shape_of(&Constraint::Line { point: p, direction: DVec3::ZERO }, p), Err(()));
        assert_eq!(shape_of(&Constraint::Plane { point: p, normal: DVec3::ZERO }, p), Err(()));
        assert_eq!(shape_of(&Constraint::Plane { point: DVec3::splat(f64::NAN), normal: DVec3::Z }, p), Err(()));
        assert_eq!(shape_of(&Constraint::Fixed(DVec3::new(f64::INFINITY, 0.0, 0.0)), p), Err(()));
        assert_eq!(shape_of(&Constraint::Fixed(p), p), Ok(Some(Shape::Point(p))));
    }
}
