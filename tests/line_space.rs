//! Subdivision in line space: the result depends on the lines only and commutes with rigid
//! motions; it converges at fourth order like the endpoint scheme. Native and in Chromium.

use glam::{DAffine3, DQuat, DVec3};
use ruledlab::LineCongruence;
use ruledlab::Scheme;
use ruledlab::{butterfly_lines, subdivide_lines};
use ruledlab::{AnalyticCongruence, AnalyticSurface, Ranges, SmoothCongruence, SmoothRuled};
use ruledlab::{RuledSurface, Segment};

#[cfg(target_family = "wasm")]
use wasm_bindgen_test::wasm_bindgen_test;
#[cfg(target_family = "wasm")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

const FOUR_POINT: Scheme = Scheme::FourPoint { w: 1.0 / 16.0 };

fn hyperboloid(n: usize) -> RuledSurface {
    AnalyticSurface::ALL[0].clone().sample(n, Ranges { u: (0.0, 3.0), v: (-1.0, 1.0), closed: false }).unwrap()
}

/// Slides both endpoints of every ruling along its line (by different amounts), and reverses
/// every third ruling after the first: the lines stay the same.
fn slide(s: &RuledSurface) -> RuledSurface {
    RuledSurface::new(
        s.segments()
            .enumerate()
            .map(|(i, g)| {
                let d = g.b - g.a;
                let (a, b) = (g.a + (0.37 * i as f64 - 1.1) * d, g.b + (0.5 + 0.13 * i as f64) * d);
                if i > 0 && i % 3 == 0 {
                    Segment::new(b, a)
                } else {
                    Segment::new(a, b)
                }
            })
            .collect(),
    )
    .unwrap()
}

fn assert_same(a: &[DVec3], b: &[DVec3], tol: f64) {
    assert_eq!(a.len(), b.len());
    for (p, q) in a.iter().zip(b) {
        assert!((*p - *q).length() < tol, "{p} vs {q}");
    }
}

fn motion() -> DAffine3 {
    DAffine3::from_rotation_translation(
        DQuat::from_axis_angle(DVec3::new(1.0, -2.0, 0.5).normalize(), 2.1),
        DVec3::new(3.0, -7.0, 11.0),
    )
}

#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn sliding_endpoints_changes_no_output() {
    let s = hyperboloid(10);
    for scheme in [FOUR_POINT, Scheme::Chaikin, Scheme::BSpline { degree: 3 }] {
        let a = subdivide_lines(&s, scheme, false, 2, Some(1.0)).unwrap();
        let b = subdivide_lines(&slide(&s), scheme, false, 2, Some(1.0)).unwrap();
        assert_same(a.points(), b.points(), 1e-12);
    }
}

#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn commutes_with_rigid_motions() {
    let m = motion();
    let s = hyperboloid(10);
    let moved_first =
        subdivide_lines(&s.map_points(|p| m.transform_point3(p)).unwrap(), FOUR_POINT, false, 2, Some(1.0)).unwrap();
    let moved_after: Vec<DVec3> = subdivide_lines(&s, FOUR_POINT, false, 2, Some(1.0))
        .unwrap()
        .points()
        .iter()
        .map(|&p| m.transform_point3(p))
        .collect();
    assert_same(moved_first.points(), &moved_after, 1e-11);
}

/// Interpolatory in line space: the old lines come back (as lines) at even indices.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn four_point_keeps_the_old_lines() {
    let s = hyperboloid(8);
    let r = subdivide_lines(&s, FOUR_POINT, false, 1, None).unwrap();
    for (i, g) in s.segments().enumerate() {
        let (old, new) = (g.line(), r.segment(2 * i).line());
        assert!(new.dir.cross(old.dir).length() < 1e-14 && old.distance_to(new.point) < 1e-13);
    }
}

/// Fourth order on a skew surface, like the endpoint scheme (measured against the exact
/// ruling at the parameter midpoint).
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn converges_at_fourth_order() {
    let hyp = AnalyticSurface::ALL[0].clone();
    let error = |n: usize| {
        let r = subdivide_lines(&hyperboloid(n), FOUR_POINT, false, 1, None).unwrap();
        let h = 3.0 / (n - 1) as f64;
        (0..n - 1)
            .map(|i| {
                let um = (i as f64 + 0.5) * h;
                r.segment(2 * i + 1).line().distance_to(hyp.striction(um).unwrap())
            })
            .fold(0.0, f64::max)
    };
    let order = (error(24) / error(48)).log2();
    assert!((3.7..4.6).contains(&order), "order {order}");
}

#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn butterfly_on_lines_is_endpoint_free_and_equivariant() {
    let c = AnalyticCongruence::Sphere.grid(5, 5).unwrap();
    let slid = {
        let (p, q) = (c.p(), c.q());
        let (p2, q2): (Vec<DVec3>, Vec<DVec3>) = p
            .iter()
            .zip(&q)
            .enumerate()
            .map(|(k, (a, b))| (*a + (0.2 * k as f64 - 1.0) * (*b - *a), *b + 0.3 * (*b - *a)))
            .unzip();
        LineCongruence::from_points(5, 5, &p2, &q2).unwrap()
    };
    let a = butterfly_lines(&c, 1.0 / 16.0, 1, Some(1.0)).unwrap();
    let b = butterfly_lines(&slid, 1.0 / 16.0, 1, Some(1.0)).unwrap();
    assert_same(&a.p(), &b.p(), 1e-12);
    assert_same(&a.q(), &b.q(), 1e-12);
    let m = motion();
    let moved = LineCongruence::from_points(
        5,
        5,
        &c.p().iter().map(|&x| m.transform_point3(x)).collect::<Vec<_>>(),
        &c.q().iter().map(|&x| m.transform_point3(x)).collect::<Vec<_>>(),
    )
    .unwrap();
    let r = butterfly_lines(&moved, 1.0 / 16.0, 1, Some(1.0)).unwrap();
    assert_same(&r.p(), &a.p().iter().map(|&x| m.transform_point3(x)).collect::<Vec<_>>(), 1e-11);
    assert!(butterfly_lines(&c, 0.5, 1, None).is_err());
}
