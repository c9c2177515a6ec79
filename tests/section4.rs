//! Section 4 against exact answers and measured accuracy. Runs natively and in Chromium.

use ruledlab::RuledSurface;
use ruledlab::{max_distance, recut, subdivide_polygon, subdivide_strip, Scheme, Variant};
use ruledlab::{AnalyticSurface, Ranges, SmoothRuled};

#[cfg(target_family = "wasm")]
use wasm_bindgen_test::wasm_bindgen_test;
#[cfg(target_family = "wasm")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

const COUPLED: Scheme = Scheme::Variational { n: 12, variant: Variant::Coupled };
const FOUR_POINT: Scheme = Scheme::FourPoint { w: 1.0 / 16.0 };

fn sample(s: &AnalyticSurface, n: usize, u: (f64, f64)) -> RuledSurface {
    s.sample(n, Ranges { u, v: (-1.0, 1.0), closed: false }).unwrap()
}

/// Distances of the inserted rulings (odd indices): (max, interior without two per end).
fn errors(surface: &AnalyticSurface, u: (f64, f64), scheme: Scheme) -> (f64, f64) {
    let r = subdivide_strip(&sample(surface, 12, u), scheme, false, 1).unwrap();
    let which: Vec<usize> = (1..r.len()).step_by(2).collect();
    (
        max_distance(surface, &r, u.0, u.1, which.iter().copied()),
        max_distance(surface, &r, u.0, u.1, which[2..which.len() - 2].iter().copied()),
    )
}

/// Example 3 (Fig. 10): 12 rulings of the quartic surface, n = 12, one step: 11 rulings are
/// inserted, the 12 old ones kept bit for bit, and the result is far closer to the surface
/// than the midpoint rule.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn example_3_variational_step() {
    let q = AnalyticSurface::Quartic;
    let s = sample(&q, 12, (-1.0, 1.0));
    let r = subdivide_strip(&s, COUPLED, false, 1).unwrap();
    assert_eq!(r.len(), 23);
    for i in 0..12 {
        assert_eq!(r.segment(2 * i), s.segment(i));
    }
    let midpoint = errors(&q, (-1.0, 1.0), Scheme::BSpline { degree: 1 });
    let coupled = errors(&q, (-1.0, 1.0), COUPLED);
    assert!(coupled.0 < midpoint.0 / 10.0, "max: coupled {:e} vs midpoint {:e}", coupled.0, midpoint.0);
    assert!(coupled.1 < midpoint.1 / 30.0, "interior: coupled {:e} vs midpoint {:e}", coupled.1, midpoint.1);
}

/// The literal energy (umbrellas at new points only) is the midpoint rule.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn literal_variational_equals_the_midpoint_rule() {
    let s = sample(&AnalyticSurface::ALL[0], 15, (0.0, 3.0));
    let literal = subdivide_strip(&s, Scheme::Variational { n: 7, variant: Variant::Literal }, false, 2).unwrap();
    let midpoint = subdivide_strip(&s, Scheme::BSpline { degree: 1 }, false, 2).unwrap();
    for (p, q) in literal.points().iter().zip(midpoint.points()) {
        assert!((*p - *q).length() < 1e-12);
    }
}

/// The coupled scheme beats the midpoint rule on three surfaces, clearly in the interior;
/// the averaged variant is better still in the interior.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn variational_beats_the_midpoint_rule_on_curved_surfaces() {
    let cases = [
        (AnalyticSurface::Quartic, (-1.0, 1.0)),
        (AnalyticSurface::ALL[0].clone(), (0.0, 3.0)),
        (AnalyticSurface::ALL[3].clone(), (0.0, 6.0)),
    ];
    for (surface, u) in cases {
        let midpoint = errors(&surface, u, Scheme::BSpline { degree: 1 });
        let coupled = errors(&surface, u, COUPLED);
        let averaged = errors(&surface, u, Scheme::Variational { n: 12, variant: Variant::Averaged });
        assert!(coupled.0 < midpoint.0 / 2.0, "{}: {coupled:?} vs {midpoint:?}", surface.name());
        assert!(coupled.1 < midpoint.1 / 20.0, "{}: {coupled:?} vs {midpoint:?}", surface.name());
        assert!(averaged.1 < coupled.1, "{}: {averaged:?} vs {coupled:?}", surface.name());
    }
}

/// The quartic's boundary curves are quadratic in u, and the four-point scheme with
/// w = 1/16 reproduces cubics (ends included, by its cubic end rule): the refined strip
/// lies exactly on the surface, at every level of refinement.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn four_point_reproduces_the_quartic_exactly() {
    let q = AnalyticSurface::Quartic;
    let r = subdivide_strip(&sample(&q, 12, (-1.0, 1.0)), FOUR_POINT, false, 3).unwrap();
    assert_eq!(r.len(), 89);
    for (i, s) in r.segments().enumerate() {
        let u = -1.0 + 2.0 * i as f64 / 88.0;
        assert!((s.a - q.point(u, -1.0)).length() < 1e-13 && (s.b - q.point(u, 1.0)).length() < 1e-13, "ruling {i}");
    }
}

/// Repeated steps converge: the detail a step adds, |A_i − (a_i + a_{i+1})/2|, shrinks by
/// about 4 per step (at least 2 is asserted). (The distance to the sampled surface does not
/// shrink: an interpolatory scheme converges to its own limit, fixed by the coarse data.)
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn repeated_steps_converge() {
    let s = sample(&AnalyticSurface::ALL[0], 9, (0.0, 3.0));
    for scheme in [COUPLED, Scheme::Variational { n: 12, variant: Variant::Averaged }, FOUR_POINT] {
        let mut cur = s.clone();
        let mut last = f64::INFINITY;
        for step in 0..5 {
            let r = subdivide_strip(&cur, scheme, false, 1).unwrap();
            assert_eq!(r.len(), 2 * cur.len() - 1);
            let mut detail = 0.0f64;
            for i in 0..cur.len() - 1 {
                let (p, q, m) = (r.segment(2 * i), r.segment(2 * i + 2), r.segment(2 * i + 1));
                detail = detail.max((m.a - 0.5 * (p.a + q.a)).length()).max((m.b - 0.5 * (p.b + q.b)).length());
            }
            assert!(detail < 0.5 * last, "{scheme:?} step {step}: {detail:e} vs {last:e}");
            last = detail;
            cur = r;
        }
    }
}

/// Closed curve schemes on a sampled closed surface; Bézier and variational refuse closed.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn closed_strips() {
    let hyp = AnalyticSurface::ALL[0].clone();
    let s = hyp.sample(16, hyp.ranges()).unwrap();
    let r = subdivide_strip(&s, FOUR_POINT, true, 2).unwrap();
    assert_eq!(r.len(), 64);
    for i in 0..16 {
        assert_eq!(r.segment(4 * i), s.segment(i));
    }
    assert!(subdivide_strip(&s, Scheme::Bezier, true, 1).is_err());
    assert!(subdivide_strip(&s, COUPLED, true, 1).is_err());
    assert_eq!(subdivide_strip(&s, Scheme::Chaikin, true, 1).unwrap().len(), 32);
}

/// Lines rather than segments: re-cut symmetric to the striction points, then subdivide;
/// sliding the given endpoints along their lines does not change the result.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn recut_makes_the_result_independent_of_the_given_endpoints() {
    let hyp = AnalyticSurface::ALL[0].clone();
    let s = sample(&hyp, 10, (0.0, 2.0));
    let slid = RuledSurface::new(
        s.segments()
            .enumerate()
            .map(|(i, g)| {
                let d = g.b - g.a;
                ruledlab::Segment::new(g.a + (0.3 * i as f64 - 1.0) * d, g.b + (0.1 * i as f64) * d)
            })
            .collect(),
    )
    .unwrap();
    let r1 = subdivide_strip(&recut(&s, Some(1.0)).unwrap(), FOUR_POINT, false, 1).unwrap();
    let r2 = subdivide_strip(&recut(&slid, Some(1.0)).unwrap(), FOUR_POINT, false, 1).unwrap();
    for (p, q) in r1.points().iter().zip(r2.points()) {
        assert!((*p - *q).length() < 1e-12);
    }
}

/// Polygons: every scheme on open and closed input, with the documented sizes.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn polygon_sizes() {
    let p: Vec<glam::DVec3> = (0..7).map(|i| glam::DVec3::new(i as f64, (i as f64).sin(), 0.0)).collect();
    let cases = [
        (Scheme::Chaikin, false, 2, 22),
        (Scheme::Chaikin, true, 2, 28),
        (Scheme::BSpline { degree: 3 }, false, 1, 11),
        (Scheme::BSpline { degree: 3 }, true, 1, 14),
        (Scheme::Bezier, false, 2, 25),
        (FOUR_POINT, false, 3, 49),
        (FOUR_POINT, true, 1, 14),
    ];
    for (scheme, closed, steps, len) in cases {
        assert_eq!(subdivide_polygon(&p, scheme, closed, steps).unwrap().len(), len, "{scheme:?} closed={closed}");
    }
    assert!(subdivide_polygon(&p, COUPLED, false, 1).is_err());
}

/// The control polygon of the curves scene (www/scenes/curves.js): eight points in a zigzag.
const ZIGZAG: [f64; 24] = [
    0.0, 0.0, 0.0, 2.0, 3.0, 0.0, 4.0, 0.5, 0.0, 6.5, 3.5, 0.0, 8.0, -0.5, 0.0, 5.5, -3.0, 0.0, 3.0, -1.5, 0.0, 1.0,
    -3.2, 0.0,
];

/// Where the four-point scheme's polygons stop straightening out (the curves scene's readout,
/// its text and claims): the largest turning angle after 8 and 12 steps. On the closed zigzag
/// it still falls at w = 0.14 and 0.15, beyond the paper's ⅛, and up to 0.17; from 0.171 the
/// polygon still turns by more than 1 rad after 12 steps. Open, ruledlab's end rule (cubic
/// ghost points) gives out first: the angle falls up to w = 0.126 and not from 0.127.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn four_point_turning_angles_on_the_zigzag() {
    let p = ruledlab::points_from_flat(&ZIGZAG).unwrap();
    let at = |w: f64, closed: bool| {
        let a = ruledlab::turning_angles(&p, Scheme::FourPoint { w }, closed, 12).unwrap();
        (a[8], a[12])
    };
    for (w, closed, late) in [
        (1.0 / 13.0, true, (0.0554, 0.0058)),
        (0.14, true, (0.3934, 0.1883)),
        (0.15, true, (0.5568, 0.3174)),
        (0.17, true, (1.0406, 0.9962)),
        (0.171, true, (1.1421, 1.1555)),
        (0.2, true, (2.3762, 3.1005)),
        (0.126, false, (1.7422, 1.2213)),
        (0.127, false, (2.0878, 2.2778)),
    ] {
        let (a8, a12) = at(w, closed);
        assert!((a8 - late.0).abs() < 1e-4 && (a12 - late.1).abs() < 1e-4, "w = {w}, closed {closed}: {a8} → {a12}");
    }
    // w = 0: the polygon itself, its largest turn (2.088 rad) at every step
    let flat = ruledlab::turning_angles(&p, Scheme::FourPoint { w: 0.0 }, true, 12).unwrap();
    assert!(flat.iter().all(|a| (a - flat[0]).abs() < 1e-12) && (flat[0] - 2.0881).abs() < 1e-4);
}
