//! Placing a dragged handle against exact answers: each constraint and target, the torsal pair,
//! and every degenerate case (no NaN, nothing outside the box).

use super::*;
use crate::assert_near;
use crate::tolerance::test::{uniform, EXACT};

const BOX: Bounds = Bounds { min: DVec3::splat(-10.0), max: DVec3::splat(10.0) };

/// The ray from `eye` through `at`.
fn ray(eye: DVec3, at: DVec3) -> Ray {
    Ray { origin: eye, direction: at - eye }
}

#[test]
fn free_drag_in_the_view_plane() {
    // looking down from z = 5 at a handle at the origin; the pointer over (1, 2, 0)
    let eye = DVec3::new(0.0, 0.0, 5.0);
    let place =
        place(&ray(eye, DVec3::new(1.0, 2.0, 0.0)), DVec3::ZERO, &Constraint::View { normal: DVec3::Z }, &[], &BOX);
    assert_eq!(place.point, Ok(DVec3::new(1.0, 2.0, 0.0)));
    assert!(place.snaps.is_empty());
    // a pointer far out: the handle stops at the box
    let far = place_free(ray(eye, DVec3::new(400.0, -300.0, 0.0)));
    assert_eq!(far, Ok(DVec3::new(10.0, -10.0, 0.0)));
    // looking away from the plane (it is behind the eye): no place
    assert_eq!(place_free(Ray { origin: eye, direction: DVec3::Z }), Err(Held::Parallel));
}

fn place_free(r: Ray) -> Result<DVec3, Held> {
    place(&r, DVec3::ZERO, &Constraint::View { normal: DVec3::Z }, &[], &BOX).point
}

#[test]
fn a_free_handle_snaps_onto_points_lines_and_planes_exactly() {
    let eye = DVec3::new(0.3, -8.0, 2.0);
    let pointer = DVec3::new(1.0, 0.0, 1.0);
    let targets = [
        Target::Point(DVec3::new(1.0, 0.1, 1.02)),
        // a line through the pointer's point: the snap is that point, on the line to rounding
        Target::Line { point: DVec3::new(-1.0, 0.0, 0.0), direction: DVec3::new(2.0, 0.0, 1.0) },
        Target::Plane { point: DVec3::new(0.0, 0.0, 0.5), normal: DVec3::new(0.0, 0.0, 2.0) },
    ];
    let p = place(&ray(eye, pointer), DVec3::ZERO, &Constraint::View { normal: DVec3::Y }, &targets, &BOX);
    assert_near!(p.point.unwrap(), pointer, EXACT);
    assert_eq!(p.snaps[0], Some(DVec3::new(1.0, 0.1, 1.02)));
    assert_near!(p.snaps[1].unwrap(), pointer, EXACT);
    assert_near!(p.snaps[2].unwrap(), DVec3::new(1.0, 0.0, 0.5), EXACT);
}

/// The distance of two lines p + s·u and q + t·v, by the triple product.
fn line_gap(p: DVec3, u: DVec3, q: DVec3, v: DVec3) -> f64 {
    (q - p).dot(u.cross(v)).abs() / u.cross(v).length()
}

#[test]
fn a_rulings_end_snapped_onto_its_neighbour_makes_them_meet() {
    // two skew rulings of the hyperboloid of Example 1 (x² + y²/4 − z²/9 = 1): a_0 → b_0, a_1 → b_1
    let (a0, b0) = (DVec3::new(1.0, -2.0, -3.0), DVec3::new(1.0, 2.0, 3.0));
    let (a1, b1) = (DVec3::new(2f64.sqrt(), 0.0, -3.0), DVec3::new(0.0, 8f64.sqrt(), 3.0));
    assert!(line_gap(a0, b0 - a0, a1, b1 - a1) > 0.1, "skew before");
    let line = Target::Line { point: a1, direction: b1 - a1 };
    let mut seed = 7;
    let mut snapped = 0;
    for _ in 0..200 {
        // the pointer near the neighbour's line, seen from anywhere
        let eye = DVec3::new(uniform(&mut seed), uniform(&mut seed), uniform(&mut seed)) * 40.0 - DVec3::splat(20.0);
        let near = a1 + uniform(&mut seed) * (b1 - a1) + DVec3::splat(0.01 * uniform(&mut seed));
        let p = place(&ray(eye, near), a0, &Constraint::View { normal: near - eye }, &[line], &BOX);
        let Some(end) = p.snaps[0] else { continue };
        snapped += 1;
        // b_0 → the snapped end meets the neighbour: their distance is rounding
        let gap = line_gap(end, b0 - end, a1, b1 - a1);
        assert!(gap < 1e-14, "gap {gap:e} from {eye}");
    }
    assert!(snapped > 190, "{snapped} of 200 snapped");
}

#[test]
fn a_line_constraint_keeps_the_handle_on_it() {
    // vertical through (−0.4, 0.9, 2.6) (a lifted cone ruling's end), the pointer anywhere
    let start = DVec3::new(-0.403, 0.912, 2.6);
    let vertical = Constraint::On(Target::Line { point: start, direction: DVec3::Z });
    let eye = DVec3::new(6.0, -5.0, 4.0);
    let targets = [
        Target::Plane { point: DVec3::new(0.0, 0.0, 2.2), normal: DVec3::Z },
        // a point on the vertical, a point off it
        Target::Point(DVec3::new(-0.403, 0.912, 1.0)),
        Target::Point(DVec3::new(-0.4, 0.912, 1.0)),
        // a line meeting the vertical at z = 2, a skew one, a parallel one, the vertical itself
        Target::Line { point: DVec3::new(1.0, 0.0, 2.0), direction: DVec3::new(-1.403, 0.912, 0.0) },
        Target::Line { point: DVec3::new(1.0, 0.0, 2.0), direction: DVec3::Y },
        Target::Line { point: DVec3::ZERO, direction: DVec3::Z },
        Target::Line { point: DVec3::new(-0.403, 0.912, 0.0), direction: DVec3::new(0.0, 0.0, -3.0) },
    ];
    let p = place(&ray(eye, DVec3::new(-0.403, 0.912, 2.0)), start, &vertical, &targets, &BOX);
    let free = p.point.unwrap();
    assert_near!(free, DVec3::new(-0.403, 0.912, 2.0), EXACT);
    assert_eq!(p.snaps[0], Some(DVec3::new(-0.403, 0.912, 2.2)), "exactly on the plane z = 2.2");
    assert_eq!(p.snaps[1], Some(DVec3::new(-0.403, 0.912, 1.0)));
    assert_eq!(p.snaps[2], None, "a point off the line");
    assert_near!(p.snaps[3].unwrap(), DVec3::new(-0.403, 0.912, 2.0), EXACT);
    assert_eq!(p.snaps[4], None, "skew lines do not meet");
    assert_eq!(p.snaps[5], None, "a parallel line");
    assert_eq!(p.snaps[6], Some(free), "the same line: the handle stays where the pointer has it");
    for s in p.snaps.iter().flatten() {
        assert_eq!((s.x, s.y), (start.x, start.y), "on the vertical");
    }
}

#[test]
fn a_plane_constraint_keeps_the_handle_in_it() {
    let plane = Constraint::On(Target::Plane { point: DVec3::ZERO, normal: DVec3::Z });
    let eye = DVec3::new(1.0, -6.0, 5.0);
    let targets = [
        Target::Line { point: DVec3::new(2.0, 1.0, 3.0), direction: DVec3::new(0.0, 1.0, -1.0) },
        Target::Plane { point: DVec3::new(0.5, 0.0, 0.0), normal: DVec3::X },
        Target::Plane { point: DVec3::new(0.0, 0.0, 1.0), normal: DVec3::Z },
        Target::Point(DVec3::new(3.0, 3.0, 0.0)),
        Target::Point(DVec3::new(3.0, 3.0, 0.1)),
        // a line in the plane: its point nearest the ray
        Target::Line { point: DVec3::new(0.0, 2.0, 0.0), direction: DVec3::X },
    ];
    let p = place(&ray(eye, DVec3::new(1.0, 2.0, 0.0)), DVec3::new(1.0, 1.0, 0.0), &plane, &targets, &BOX);
    assert_near!(p.point.unwrap(), DVec3::new(1.0, 2.0, 0.0), EXACT);
    assert_eq!(p.snaps[0], Some(DVec3::new(2.0, 4.0, 0.0)));
    assert_near!(p.snaps[1].unwrap(), DVec3::new(0.5, 2.0, 0.0), EXACT);
    assert_eq!(p.snaps[2], None, "a parallel plane");
    assert_eq!(p.snaps[3], Some(DVec3::new(3.0, 3.0, 0.0)));
    assert_eq!(p.snaps[4], None, "a point off the plane");
    assert_near!(p.snaps[5].unwrap(), DVec3::new(1.0, 2.0, 0.0), EXACT);
    // a drag far out stays in the plane, at the box
    let far = place(&ray(eye, DVec3::new(100.0, 2.0, 0.0)), DVec3::new(1.0, 1.0, 0.0), &plane, &[], &BOX);
    let far = far.point.unwrap();
    assert_eq!(far.z, 0.0);
    assert!(BOX.contains(far) && far.x >= 10.0 - EXACT);
}

#[test]
fn a_fixed_handle_stays_and_snaps_nowhere() {
    let at = DVec3::new(1.0, 2.0, 3.0);
    let p = place(
        &ray(DVec3::splat(9.0), DVec3::ZERO),
        at,
        &Constraint::On(Target::Point(at)),
        &[Target::Point(DVec3::ZERO)],
        &BOX,
    );
    assert_eq!(p, Placement { point: Ok(at), snaps: vec![None] });
    let outside =
        place(&ray(DVec3::splat(9.0), DVec3::ZERO), at, &Constraint::On(Target::Point(DVec3::splat(20.0))), &[], &BOX);
    assert_eq!(outside.point, Err(Held::Outside));
}

#[test]
fn constraints_that_cannot_hold_say_why() {
    let r = ray(DVec3::new(0.0, -9.0, 0.0), DVec3::ZERO);
    let at = DVec3::ZERO;
    let p = |c: Constraint| place(&r, at, &c, &[Target::Point(DVec3::ZERO)], &BOX);
    // the ray runs along the line, parallel to the plane: turn the view
    assert_eq!(p(Constraint::On(Target::Line { point: at, direction: DVec3::Y })).point, Err(Held::Parallel));
    assert_eq!(p(Constraint::On(Target::Plane { point: at, normal: DVec3::Z })).point, Err(Held::Parallel));
    // a line or plane that misses the box
    assert_eq!(
        p(Constraint::On(Target::Line { point: DVec3::new(0.0, 0.0, 50.0), direction: DVec3::X })).point,
        Err(Held::Outside)
    );
    let high = Constraint::On(Target::Plane { point: DVec3::new(0.0, 0.0, 50.0), normal: DVec3::Z });
    assert_eq!(
        place(&ray(DVec3::new(0.0, -9.0, 60.0), DVec3::new(0.0, 500.0, 50.0)), at, &high, &[], &BOX).point,
        Err(Held::Outside)
    );
    // a line without a direction, a plane without a normal, a NaN: degenerate, nothing snaps
    for c in [
        Constraint::On(Target::Line { point: at, direction: DVec3::ZERO }),
        Constraint::On(Target::Plane { point: at, normal: DVec3::ZERO }),
        Constraint::View { normal: DVec3::splat(f64::NAN) },
    ] {
        assert_eq!(p(c), Placement { point: Err(Held::Degenerate), snaps: vec![None] });
    }
    // a ray that is not one, a box that is not one
    let bad = Ray { origin: DVec3::ZERO, direction: DVec3::ZERO };
    let view = Constraint::View { normal: DVec3::Y };
    assert_eq!(place(&bad, at, &view, &[Target::Point(at)], &BOX).point, Err(Held::Degenerate));
    assert_eq!(place(&bad, at, &view, &[Target::Point(at)], &BOX).snaps, vec![None]);
    let inverted = Bounds { min: DVec3::ONE, max: DVec3::ZERO };
    assert_eq!(place(&r, at, &view, &[], &inverted).point, Err(Held::Degenerate));
}

#[test]
fn degenerate_targets_give_a_point_or_none_never_nan() {
    let eye = DVec3::new(0.0, -9.0, 1.0);
    let view = Constraint::View { normal: DVec3::Y };
    let targets = [
        // a ruling of zero length: its point
        Target::Line { point: DVec3::new(1.0, 0.0, 1.0), direction: DVec3::ZERO },
        // at infinity, NaN, beyond the box
        Target::Point(DVec3::new(f64::INFINITY, 0.0, 0.0)),
        Target::Line { point: DVec3::splat(f64::NAN), direction: DVec3::X },
        Target::Point(DVec3::new(50.0, 0.0, 0.0)),
        Target::Plane { point: DVec3::ZERO, normal: DVec3::ZERO },
        // a line along the ray (a point on screen): the handle's shadow on it
        Target::Line { point: DVec3::new(0.0, 3.0, 1.0), direction: DVec3::new(0.0, 1.0, 0.0) },
    ];
    let p = place(&ray(eye, DVec3::new(0.0, 0.0, 1.0)), DVec3::ZERO, &view, &targets, &BOX);
    assert_eq!(p.snaps[0], Some(DVec3::new(1.0, 0.0, 1.0)));
    assert_eq!(&p.snaps[1..5], &[None, None, None, None]);
    assert_near!(p.snaps[5].unwrap(), DVec3::new(0.0, 0.0, 1.0), EXACT);
    // two coincident lines as constraint and target: the handle's own place
    let line = Constraint::On(Target::Line { point: DVec3::ZERO, direction: DVec3::X });
    let same = Target::Line { point: DVec3::new(3.0, 0.0, 0.0), direction: DVec3::new(-2.0, 0.0, 0.0) };
    let q = place(&ray(eye, DVec3::new(2.0, 0.0, 0.0)), DVec3::ZERO, &line, &[same], &BOX);
    assert_eq!(q.snaps[0], Some(q.point.unwrap()));
    assert_near!(q.point.unwrap(), DVec3::new(2.0, 0.0, 0.0), EXACT);
}

#[test]
fn whatever_the_input_no_nan_and_nothing_outside_the_box() {
    let mut seed = 11;
    let mut r = |scale: f64| {
        let v = DVec3::new(uniform(&mut seed), uniform(&mut seed), uniform(&mut seed)) * 2.0 - DVec3::ONE;
        v * scale
    };
    let odd = [0.0, 1e-300, 1e300, f64::NAN, f64::INFINITY];
    for k in 0..3000 {
        let mut pick = |s: f64| if k % 7 == 0 { DVec3::splat(odd[k % odd.len()]) } else { r(s) };
        let start = pick(5.0);
        let ray = Ray { origin: pick(30.0), direction: pick(1.0) };
        let constraint = match k % 4 {
            0 => Constraint::View { normal: pick(1.0) },
            1 => Constraint::On(Target::Line { point: pick(12.0), direction: pick(1.0) }),
            2 => Constraint::On(Target::Plane { point: pick(12.0), normal: pick(1.0) }),
            _ => Constraint::On(Target::Point(pick(12.0))),
        };
        let targets = [
            Target::Point(pick(12.0)),
            Target::Line { point: pick(12.0), direction: pick(1.0) },
            Target::Plane { point: pick(12.0), normal: pick(1.0) },
            Target::Line { point: start, direction: DVec3::ZERO },
        ];
        let p = place(&ray, start, &constraint, &targets, &BOX);
        for q in p.point.iter().chain(p.snaps.iter().flatten()) {
            assert!(q.is_finite() && BOX.contains(*q), "{q} from {ray:?} {constraint:?}");
        }
    }
}

#[test]
fn a_line_meets_the_box_between_its_exits_the_faces_included() {
    // a box off the origin, of unequal sides
    let b = Bounds { min: DVec3::new(1.0, 2.0, 3.0), max: DVec3::new(2.0, 4.0, 7.0) };
    let centre = DVec3::new(1.5, 3.0, 5.0);
    // along x: half a side each way; a longer or reversed direction scales the parameters
    assert_eq!(b.span(centre, DVec3::X), Some((-0.5, 0.5)));
    assert_eq!(b.span(centre, DVec3::new(4.0, 0.0, 0.0)), Some((-0.125, 0.125)));
    assert_eq!(b.span(centre, DVec3::new(0.0, -2.0, 0.0)), Some((-0.5, 0.5)));
    // oblique: the nearer exit of each side wins
    assert_eq!(b.span(centre, DVec3::new(1.0, 1.0, 1.0)), Some((-0.5, 0.5)));
    assert_eq!(b.span(DVec3::new(1.0, 2.0, 3.0), DVec3::new(0.5, 4.0, 1.0)), Some((0.0, 0.5)));
    // on a face, along it: inside; just off it: outside
    assert_eq!(b.span(DVec3::new(1.5, 4.0, 5.0), DVec3::X), Some((-0.5, 0.5)));
    assert_eq!(b.span(DVec3::new(1.5, 2.0, 5.0), DVec3::Z), Some((-2.0, 2.0)));
    assert_eq!(b.span(DVec3::new(1.5, 4.0 + 1e-12, 5.0), DVec3::X), None);
    assert_eq!(b.span(DVec3::new(1.5, 2.0 - 1e-12, 5.0), DVec3::X), None);
    // a line that passes the box
    assert_eq!(b.span(DVec3::new(0.0, 0.0, 5.0), DVec3::new(1.0, -1.0, 0.0)), None);
    // a line dragged out of the box stops at its exit, on the line
    let line = Constraint::On(Target::Line { point: centre, direction: DVec3::new(1.0, 0.5, 0.25) });
    let eye = DVec3::new(1.5, -20.0, 5.0);
    let out = place(&ray(eye, DVec3::new(40.0, 3.0, 5.0)), centre, &line, &[], &b).point.unwrap();
    assert_near!(out, DVec3::new(2.0, 3.25, 5.125), EXACT);
    let back = place(&ray(eye, DVec3::new(-40.0, 3.0, 5.0)), centre, &line, &[], &b).point.unwrap();
    assert_near!(back, DVec3::new(1.0, 2.75, 4.875), EXACT);
    // a plane dragged out: from the start's shadow towards the pointer's point, cut at the box
    let plane = Constraint::On(Target::Plane { point: centre, normal: DVec3::Z });
    let above = DVec3::new(1.5, 3.0, 30.0);
    let cut = place(&ray(above, DVec3::new(5.5, 9.0, 5.0)), centre, &plane, &[], &b).point.unwrap();
    // (the shadow (1.5, 3, 5), the point (5.5, 9, 5): x leaves first, at an eighth of the way)
    assert_near!(cut, DVec3::new(2.0, 3.75, 5.0), EXACT);
}

#[test]
fn what_counts_as_on_a_line_is_a_share_of_the_boxs_size() {
    // the box ±10 is 20√3 across: on means within 1e-9 of that, 3.46e-8
    let vertical = Constraint::On(Target::Line { point: DVec3::ZERO, direction: DVec3::Z });
    let eye = DVec3::new(6.0, -5.0, 4.0);
    let near = Target::Point(DVec3::new(2e-8, 0.0, 1.0));
    let off = Target::Point(DVec3::new(5e-8, 0.0, 1.0));
    let p = place(&ray(eye, DVec3::new(0.0, 0.0, 2.0)), DVec3::ZERO, &vertical, &[near, off], &BOX);
    assert_eq!(p.snaps, [Some(DVec3::new(0.0, 0.0, 1.0)), None]);
    // in a box a thousand times larger, both are on
    let large = Bounds { min: DVec3::splat(-1e4), max: DVec3::splat(1e4) };
    let p = place(&ray(eye, DVec3::new(0.0, 0.0, 2.0)), DVec3::ZERO, &vertical, &[near, off], &large);
    assert_eq!(p.snaps, [Some(DVec3::new(0.0, 0.0, 1.0)), Some(DVec3::new(0.0, 0.0, 1.0))]);
}

#[test]
fn a_line_along_a_plane_snaps_onto_it_only_when_it_lies_in_it() {
    let line = Constraint::On(Target::Line { point: DVec3::new(0.0, 1.0, 1.0), direction: DVec3::X });
    let targets = [
        Target::Plane { point: DVec3::new(5.0, -3.0, 1.0), normal: DVec3::Z },
        Target::Plane { point: DVec3::new(5.0, -3.0, 1.5), normal: DVec3::Z },
    ];
    let eye = DVec3::new(2.0, -6.0, 4.0);
    let p = place(&ray(eye, DVec3::new(2.0, 1.0, 1.0)), DVec3::new(0.0, 1.0, 1.0), &line, &targets, &BOX);
    let free = p.point.unwrap();
    assert_near!(free, DVec3::new(2.0, 1.0, 1.0), EXACT);
    assert_eq!(p.snaps, [Some(free), None], "in the plane: where the pointer has it; beside it: none");
}
