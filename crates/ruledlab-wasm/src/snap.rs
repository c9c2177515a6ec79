//! Snapping and constraints of a dragged handle for JavaScript (beyond the paper):
//! `snapPoint(query)`, where the core puts a handle the reader drags — on its constraint, and
//! exactly onto each target the page found near the pointer (the core's `snap`).

use glam::DVec3;
use ruledlab::tolerance::MAX_SNAP_TARGETS;
use ruledlab::{Bounds, Constraint, Held, Ray, Target};
use ruledlab_js::args::{fail, required, to_js};
use serde::{Deserialize, Serialize};
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

const F: &str = "snapPoint";

/// Where the reader drags a handle, in the coordinates of the scene's input.
#[derive(Deserialize, Tsify)]
#[serde(deny_unknown_fields)]
struct SnapQuery {
    /// The pointer's ray, from the eye through the pointer.
    ray: SnapRay,
    /// Where the handle was when the drag began.
    start: [f64; 3],
    /// How the handle may move.
    constraint: SnapConstraint,
    /// What it may be snapped onto (the page's candidates near the pointer), at most 4096.
    #[serde(default)]
    targets: Vec<SnapTarget>,
    /// The box the handle stays in.
    bounds: SnapBounds,
}

/// A ray: from `origin` along `direction` (not zero; its length does not matter).
#[derive(Deserialize, Tsify)]
#[serde(deny_unknown_fields)]
struct SnapRay {
    origin: [f64; 3],
    direction: [f64; 3],
}

/// A box: its least and greatest corners.
#[derive(Deserialize, Tsify)]
#[serde(deny_unknown_fields)]
struct SnapBounds {
    min: [f64; 3],
    max: [f64; 3],
}

/// How a dragged handle may move: `view`, in the plane through its start with this normal (a
/// snap may take it anywhere); `line`, on the line point + t·direction; `plane`, in the plane
/// through `point` orthogonal to `normal`; `fixed`, held at `point`.
#[derive(Deserialize, Tsify)]
#[serde(tag = "kind", rename_all = "lowercase", deny_unknown_fields)]
enum SnapConstraint {
    View { normal: [f64; 3] },
    Line { point: [f64; 3], direction: [f64; 3] },
    Plane { point: [f64; 3], normal: [f64; 3] },
    Fixed { point: [f64; 3] },
}

/// A point, the line point + t·direction (a ruling a → b: point a, direction b − a), or the
/// plane through `point` orthogonal to `normal`.
#[derive(Deserialize, Tsify)]
#[serde(tag = "kind", rename_all = "lowercase", deny_unknown_fields)]
enum SnapTarget {
    Point { point: [f64; 3] },
    Line { point: [f64; 3], direction: [f64; 3] },
    Plane { point: [f64; 3], normal: [f64; 3] },
}

/// Where the drag puts the handle.
#[derive(Serialize, Tsify)]
struct Snapped {
    /// The handle on its constraint without snapping, inside the box; absent when there is no
    /// such place (then `held` says why).
    #[tsify(optional)]
    point: Option<[f64; 3]>,
    /// Why there is no place: "degenerate" (the constraint cannot hold: no direction, no normal,
    /// a coordinate not finite), "parallel" (the pointer's ray runs along the line or parallel
    /// to the plane: turn the view), "outside" (the line or plane misses the box).
    #[tsify(optional, type = "\"degenerate\" | \"parallel\" | \"outside\"")]
    held: Option<&'static str>,
    /// For each target, in order: the handle snapped onto it (on the constraint, inside the
    /// box), exactly; undefined where the target is none or does not meet the constraint.
    #[tsify(type = "Array<[number, number, number] | undefined>")]
    snaps: Vec<Option<[f64; 3]>>,
}

/// Where a drag puts a handle (see `SnapQuery`): on its constraint, cut to the box, and exactly
/// onto each target — a point target is the point, a line target the point of the line nearest
/// the pointer's ray (a ruling's end snapped onto its neighbour makes the pair torsal: h = δ = 0
/// to rounding), a plane target the handle's shadow on it. Degenerate targets (a ruling of zero
/// length, a target at infinity) give a point or none, never NaN.
#[wasm_bindgen(js_name = snapPoint, unchecked_return_type = "Snapped")]
pub fn snap_point(#[wasm_bindgen(unchecked_param_type = "SnapQuery")] query: JsValue) -> Result<JsValue, JsValue> {
    let q: SnapQuery = required(F, "query", query, &[])?;
    if q.targets.len() > MAX_SNAP_TARGETS {
        return Err(fail(F, ruledlab::Error::TooMany { what: "targets", got: q.targets.len(), max: MAX_SNAP_TARGETS }));
    }
    let v = DVec3::from_array;
    let constraint = match q.constraint {
        SnapConstraint::View { normal } => Constraint::View { normal: v(normal) },
        SnapConstraint::Line { point, direction } => {
            Constraint::On(Target::Line { point: v(point), direction: v(direction) })
        }
        SnapConstraint::Plane { point, normal } => Constraint::On(Target::Plane { point: v(point), normal: v(normal) }),
        SnapConstraint::Fixed { point } => Constraint::On(Target::Point(v(point))),
    };
    let targets: Vec<Target> = q
        .targets
        .into_iter()
        .map(|t| match t {
            SnapTarget::Point { point } => Target::Point(v(point)),
            SnapTarget::Line { point, direction } => Target::Line { point: v(point), direction: v(direction) },
            SnapTarget::Plane { point, normal } => Target::Plane { point: v(point), normal: v(normal) },
        })
        .collect();
    let placed = ruledlab::place(
        &Ray { origin: v(q.ray.origin), direction: v(q.ray.direction) },
        v(q.start),
        &constraint,
        &targets,
        &Bounds { min: v(q.bounds.min), max: v(q.bounds.max) },
    );
    let (point, held) = match placed.point {
        Ok(p) => (Some(p.to_array()), None),
        Err(why) => (
            None,
            Some(match why {
                Held::Degenerate => "degenerate",
                Held::Parallel => "parallel",
                Held::Outside => "outside",
            }),
        ),
    };
    to_js(F, &Snapped { point, held, snaps: placed.snaps.into_iter().map(|s| s.map(|p| p.to_array())).collect() })
}
