//! Snapping a dragged handle, checked on the geometry the page computes with (Section 2): a
//! ruling's end snapped onto a neighbouring ruling makes the pair torsal — h = δ = 0 to 1e-12 —
//! from any camera; an end slid along its own ruling (the line mode) leaves the line the same.
//! Natively and, with the same bodies, in headless Chromium and Firefox under wasm-bindgen-test.

use glam::DVec3;
use ruledlab::tolerance::test::EXACT;
use ruledlab::{place, AnalyticSurface, Bounds, Constraint, RuledSurface, SmoothRuled, Target};
use ruledlab::{Ray, Segment};

#[cfg(target_family = "wasm")]
use wasm_bindgen_test::wasm_bindgen_test;
#[cfg(target_family = "wasm")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

/// The torsal-pair exercise's surface: the hyperboloid of Example 1, 8 rulings.
fn hyperboloid() -> RuledSurface {
    let s = AnalyticSurface::by_name("hyperboloid").unwrap();
    s.sample(8, s.ranges()).unwrap()
}

const BOX: Bounds = Bounds { min: DVec3::splat(-40.0), max: DVec3::splat(40.0) };

/// Reproducible numbers in [0, 1).
fn uniform(seed: &mut u64) -> f64 {
    *seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
    (*seed >> 11) as f64 / (1u64 << 53) as f64
}

#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn an_end_snapped_onto_the_neighbour_gives_delta_zero() {
    let surface = hyperboloid();
    let mut seed = 3;
    for i in 0..surface.len() {
        for j in [i.wrapping_sub(1), i + 1] {
            if j >= surface.len() {
                continue;
            }
            for end in 0..2 {
                let (own, other) = (surface.segment(i), surface.segment(j));
                let moved = if end == 0 { own.a } else { own.b };
                // the pointer over a point of the neighbour's line, from a camera anywhere
                let eye =
                    DVec3::new(uniform(&mut seed), uniform(&mut seed), uniform(&mut seed)) * 30.0 - DVec3::splat(15.0);
                let at = other.at(0.2 + 0.6 * uniform(&mut seed));
                let ray = Ray { origin: eye, direction: at - eye };
                let line = Target::Line { point: other.a, direction: other.b - other.a };
                let view = Constraint::View { normal: at - eye };
                let snapped = place(&ray, moved, &view, &[line], &BOX).snaps[0].expect("the line is under the pointer");
                let mut segments: Vec<Segment> = surface.segments().collect();
                segments[i] = if end == 0 { Segment::new(snapped, own.b) } else { Segment::new(own.a, snapped) };
                let inv = RuledSurface::new(segments).unwrap().invariants();
                let pair = i.min(j);
                assert!(
                    inv.distance[pair].abs() < EXACT,
                    "h = {:e} (ruling {i}, end {end}, onto {j})",
                    inv.distance[pair]
                );
                assert!(
                    inv.distribution[pair].abs() < EXACT,
                    "δ = {:e} (ruling {i}, end {end}, onto {j})",
                    inv.distribution[pair]
                );
            }
        }
    }
}

#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn an_end_slid_along_its_ruling_keeps_the_line() {
    let surface = hyperboloid();
    let mut seed = 5;
    let mut segments: Vec<Segment> = surface.segments().collect();
    for (i, s) in segments.iter_mut().enumerate() {
        let eye = DVec3::new(uniform(&mut seed), uniform(&mut seed), uniform(&mut seed)) * 30.0 - DVec3::splat(15.0);
        // the pointer beside the ruling, past its end: the end slides along the line only
        let at = s.at(1.3) + DVec3::splat(0.2);
        let along = Constraint::On(Target::Line { point: s.b, direction: s.b - s.a });
        let placed = place(&Ray { origin: eye, direction: at - eye }, s.b, &along, &[], &BOX);
        let b = placed.point.unwrap_or_else(|why| panic!("ruling {i}: {why:?}"));
        assert!(b.distance(s.b) > 0.1, "ruling {i}: the end moved");
        s.b = b;
    }
    let slid = RuledSurface::new(segments).unwrap();
    assert!(slid.max_angle_to(&surface).unwrap() < 1e-15);
    let (before, after) = (surface.invariants(), slid.invariants());
    for k in 0..before.distribution.len() {
        assert!((before.distribution[k] - after.distribution[k]).abs() < EXACT, "δ of pair {k} kept");
    }
}
