//! Snapping and constraints of a dragged handle (beyond the paper: how the page's reader puts a
//! point exactly where the geometry of Sections 2–5 asks for it).
//!
//! A reader drags a handle of a scene's input (a ruling's end, a control point, a line of a
//! congruence, a tool pose). The page casts the pointer's ray and finds, on screen, the targets
//! near the pointer; this module decides where the handle goes, exactly:
//!
//! - **the constraint** ([`Constraint`]): the plane through the handle facing the viewer (free),
//!   a line (the handle's own ruling, the vertical, an axis an exercise names), a plane, or held
//!   in place — the pointer's ray is projected onto it, and the result cut to the edit box;
//! - **the targets** ([`Target`]): for each, the point of the constraint on it nearest the ray
//!   (or `None` where the two do not meet) — a point target is the point, a line target the
//!   point of the line nearest the ray, a plane target the handle's shadow on it.
//!
//! A handle snapped onto a line is on that line to rounding: a ruling's end a_i put on the line
//! R_{i+1} = a_{i+1} + t·(b_{i+1} − a_{i+1}) makes the two rulings meet, so their distance
//! h_{i,i+1} and distribution parameter δ_{i,i+1} = h/φ (Section 2, (1)–(3)) are 0 to rounding —
//! a torsal pair. No answer is NaN or outside the box: degenerate targets (a ruling of zero
//! length, two coincident lines, a target at infinity) give a point or none, and a constraint
//! that cannot hold says why ([`Held`]).

mod constraint;
mod meet;
mod target;

pub use constraint::Constraint;
pub use meet::{closest_on_lines, line_through_plane, planes_meet, shadow_on_line, shadow_on_plane};
pub use target::Target;

use crate::tolerance::{MAX_SNAP_TARGETS, SNAP_ON};
use constraint::shape_of;
use glam::DVec3;
use meet::{line_distance, plane_distance};
use target::{sane, Shape};

/// The pointer's ray: from the eye through the pointer, in the input's coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ray {
    /// The eye.
    pub origin: DVec3,
    /// Towards the pointer (not zero; its length does not matter).
    pub direction: DVec3,
}

/// The box a handle stays in (the page's edit box: the scene's bounds scaled about their centre).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    /// The least corner.
    pub min: DVec3,
    /// The greatest corner.
    pub max: DVec3,
}

impl Bounds {
    /// Whether `p` is inside (the faces included).
    pub fn contains(&self, p: DVec3) -> bool {
        p.cmpge(self.min).all() && p.cmple(self.max).all()
    }

    /// The parameters t of the line p + t·u inside the box, or `None` where it misses it.
    fn span(&self, p: DVec3, u: DVec3) -> Option<(f64, f64)> {
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        for k in 0..3 {
            if u[k] == 0.0 {
                if p[k] < self.min[k] || p[k] > self.max[k] {
                    return None;
                }
                continue;
            }
            let (a, b) = ((self.min[k] - p[k]) / u[k], (self.max[k] - p[k]) / u[k]);
            lo = lo.max(a.min(b));
            hi = hi.min(a.max(b));
        }
        (lo <= hi).then_some((lo, hi))
    }

    /// Whether the box is a box: finite corners in order.
    fn sane(&self) -> bool {
        sane(self.min) && sane(self.max) && self.min.cmple(self.max).all()
    }
}

/// Why a constraint gives the handle no place.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Held {
    /// It cannot hold at all: a line without a direction, a plane without a normal, a
    /// coordinate that is not finite (or the ray or the box is such).
    Degenerate,
    /// The pointer's ray runs along the line or parallel to the plane: turn the view.
    Parallel,
    /// The line or plane misses the box (or the held point is outside it).
    Outside,
}

/// Where a drag puts a handle: its place under the constraint, and the place each target gives.
#[derive(Debug, Clone, PartialEq)]
pub struct Placement {
    /// The handle's place without snapping (inside the box), or why there is none.
    pub point: Result<DVec3, Held>,
    /// For each target given, in order: the handle snapped onto it (on the constraint and inside
    /// the box), or `None` where the target is none or does not meet the constraint there.
    pub snaps: Vec<Option<DVec3>>,
}

/// Where a drag puts a handle that was at `start` when it began: under `constraint`, the
/// pointer's `ray` projected onto it and cut to `bounds`, and for each of `targets` (at most
/// [`MAX_SNAP_TARGETS`]; more are left out) the handle snapped onto it. See the module's
/// documentation.
pub fn place(ray: &Ray, start: DVec3, constraint: &Constraint, targets: &[Target], bounds: &Bounds) -> Placement {
    let targets = &targets[..targets.len().min(MAX_SNAP_TARGETS)];
    let none = |why| Placement { point: Err(why), snaps: vec![None; targets.len()] };
    let shape = match shape_of(constraint, start) {
        Ok(shape) if bounds.sane() => shape,
        _ => return none(Held::Degenerate),
    };
    let ray_ok = sane(ray.origin) && sane(ray.direction) && ray.direction != DVec3::ZERO;
    let point = if !ray_ok && !matches!(shape, Some(Shape::Point(_))) {
        Err(Held::Degenerate)
    } else {
        free_point(ray, start, constraint, shape, bounds)
    };
    // what counts as on a line or plane: a share of the box's size (rounding of a scene's numbers)
    let tol = SNAP_ON * (bounds.max - bounds.min).length().max(1.0);
    let snaps = targets
        .iter()
        .map(|target| {
            let t = target.shape()?;
            if !ray_ok {
                return None;
            }
            let p = meet(shape, t, ray, point.ok(), tol)?;
            (sane(p) && bounds.contains(p)).then_some(p)
        })
        .collect();
    Placement { point, snaps }
}

/// The handle's place under the constraint without snapping, inside the box.
fn free_point(
    ray: &Ray,
    start: DVec3,
    constraint: &Constraint,
    shape: Option<Shape>,
    bounds: &Bounds,
) -> Result<DVec3, Held> {
    let inside = |p: DVec3| if bounds.contains(p) { p } else { p.clamp(bounds.min, bounds.max) };
    match shape {
        // the plane through the start facing the viewer, in front of the eye
        None => {
            let Constraint::View { normal } = *constraint else { unreachable!("only View has no shape") };
            let t = line_through_plane(ray.origin, ray.direction, start, normal).ok_or(Held::Parallel)?;
            if t.is_nan() || t <= 0.0 {
                return Err(Held::Parallel);
            }
            let p = ray.origin + t * ray.direction;
            if sane(p) {
                Ok(inside(p))
            } else {
                Err(Held::Parallel)
            }
        }
        Some(Shape::Point(p)) => bounds.contains(p).then_some(p).ok_or(Held::Outside),
        // the line's point nearest the ray, its parameter cut to the part inside the box
        Some(Shape::Line(p, u)) => {
            let (lo, hi) = bounds.span(p, u).ok_or(Held::Outside)?;
            let (t, _) = closest_on_lines(p, u, ray.origin, ray.direction).ok_or(Held::Parallel)?;
            Ok(inside(p + t.clamp(lo, hi) * u))
        }
        // where the ray meets the plane; outside the box, the segment from the start's shadow
        // towards it, cut at the box (a convex box: the cut stays in the plane)
        Some(Shape::Plane(c, n)) => {
            let t = line_through_plane(ray.origin, ray.direction, c, n).ok_or(Held::Parallel)?;
            let x = ray.origin + t * ray.direction;
            if !sane(x) {
                return Err(Held::Parallel);
            }
            if bounds.contains(x) {
                return Ok(x);
            }
            let anchor = shadow_on_plane(start, c, n);
            if !bounds.contains(anchor) {
                return Err(Held::Outside);
            }
            let (_, hi) = bounds.span(anchor, x - anchor).ok_or(Held::Outside)?;
            Ok(inside(anchor + hi.clamp(0.0, 1.0) * (x - anchor)))
        }
    }
}

/// The handle under `constraint` (`None`: free) snapped onto `target`, or `None` where they do
/// not meet; `free` is the handle's place without snapping, `tol` what counts as on.
fn meet(constraint: Option<Shape>, target: Shape, ray: &Ray, free: Option<DVec3>, tol: f64) -> Option<DVec3> {
    let nearest_ray = |q: DVec3, v: DVec3| -> Option<DVec3> {
        match closest_on_lines(q, v, ray.origin, ray.direction) {
            Some((s, _)) => Some(q + s * v),
            // a line along the ray is a point on screen: the handle's shadow on it
            None => free.and_then(|f| shadow_on_line(f, q, v)).map(|s| q + s * v),
        }
    };
    match (constraint, target) {
        (None, Shape::Point(q)) => Some(q),
        (None, Shape::Line(q, v)) => nearest_ray(q, v),
        (None, Shape::Plane(c, n)) => free.map(|f| shadow_on_plane(f, c, n)),
        // held in place: nothing to snap
        (Some(Shape::Point(_)), _) => None,
        (Some(Shape::Line(p, u)), Shape::Point(q)) => {
            (line_distance(q, p, u) <= tol).then(|| shadow_on_line(q, p, u).map(|s| p + s * u))?
        }
        (Some(Shape::Line(p, u)), Shape::Line(q, v)) => match closest_on_lines(p, u, q, v) {
            Some((s, t)) => ((p + s * u).distance(q + t * v) <= tol).then_some(p + s * u),
            // parallel: the same line (the handle stays where the pointer has it) or none
            None => (line_distance(q, p, u) <= tol).then_some(free?),
        },
        (Some(Shape::Line(p, u)), Shape::Plane(c, n)) => match line_through_plane(p, u, c, n) {
            Some(t) => Some(p + t * u),
            None => (plane_distance(p, c, n) <= tol).then_some(free?),
        },
        (Some(Shape::Plane(c, n)), Shape::Point(q)) => {
            (plane_distance(q, c, n) <= tol).then(|| shadow_on_plane(q, c, n))
        }
        (Some(Shape::Plane(c, n)), Shape::Line(q, v)) => match line_through_plane(q, v, c, n) {
            Some(t) => Some(q + t * v),
            None => (plane_distance(q, c, n) <= tol).then(|| nearest_ray(q, v))?,
        },
        (Some(Shape::Plane(c, n)), Shape::Plane(c2, n2)) => match planes_meet(c, n, c2, n2, free?) {
            Some((x, _)) => Some(x),
            None => (plane_distance(c2, c, n) <= tol).then_some(free?),
        },
    }
}

#[cfg(test)]
mod tests;
