//! How a dragged handle may move (beyond the paper): in the plane through it that faces the
//! viewer (free: a snap may take it anywhere), along a line (its own ruling, the vertical, an
//! axis an exercise names), in a plane, or not at all — the drag modes of the page and the
//! constraints a scene or an exercise declares. The core projects the pointer's ray onto the
//! constraint, and a snap keeps it.

use super::target::{sane, vanishes, Shape, Target};
use glam::DVec3;

/// Where a dragged handle may go.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Constraint {
    /// Anywhere: the pointer moves it in the plane through where it started with this normal
    /// (the view's direction), and a snap may take it off that plane.
    View {
        /// The plane's normal.
        normal: DVec3,
    },
    /// On a target, where a snap keeps it too: held at a point, on a line, in a plane. Unlike a
    /// snap's target, a line here must have a direction (one that vanishes where it is, see
    /// [`Target`], cannot hold) and a plane a normal.
    On(Target),
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
        // a target's line without a direction is its point: a constraint's cannot hold
        Constraint::On(Target::Line { point, direction }) if vanishes(point, direction) => Err(()),
        Constraint::On(target) => target.shape().map(Some).ok_or(()),
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
        let on = |t: Target| shape_of(&Constraint::On(t), p);
        assert_eq!(on(Target::Line { point: p, direction: DVec3::Z }), Ok(Some(Shape::Line(p, DVec3::Z))));
        assert_eq!(on(Target::Line { point: p, direction: DVec3::ZERO }), Err(()));
        assert_eq!(on(Target::Line { point: p, direction: DVec3::splat(1e-16) }), Err(()));
        assert_eq!(on(Target::Line { point: p, direction: DVec3::new(f64::NAN, 1.0, 0.0) }), Err(()));
        assert_eq!(on(Target::Plane { point: p, normal: DVec3::Z }), Ok(Some(Shape::Plane(p, DVec3::Z))));
        assert_eq!(on(Target::Plane { point: p, normal: DVec3::ZERO }), Err(()));
        assert_eq!(on(Target::Plane { point: DVec3::splat(f64::NAN), normal: DVec3::Z }), Err(()));
        assert_eq!(on(Target::Point(DVec3::new(f64::INFINITY, 0.0, 0.0))), Err(()));
        assert_eq!(on(Target::Point(p)), Ok(Some(Shape::Point(p))));
    }
}
