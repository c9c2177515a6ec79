//! Section 2 against exact answers. Every test here runs natively (`cargo test`) and, with
//! the same body, in headless Chromium under wasm-bindgen-test, so the core is shown to
//! compute the same numbers in wasm.

use glam::DVec3;
use ruledlab::assert_near;
use ruledlab::convergence_study;
use ruledlab::tolerance::test::{EXACT, ORDER};
use ruledlab::RuledSurface;
use ruledlab::{AnalyticSurface, Ranges, SmoothRuled};

#[cfg(target_family = "wasm")]
use wasm_bindgen_test::wasm_bindgen_test;
#[cfg(target_family = "wasm")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

fn sample(s: &AnalyticSurface, n: usize, u: (f64, f64)) -> RuledSurface {
    s.sample(n, Ranges { u, v: (-1.0, 1.0), closed: false }).unwrap()
}

fn params(n: usize, u: (f64, f64)) -> Vec<f64> {
    (0..n).map(|i| u.0 + (u.1 - u.0) * i as f64 / (n - 1) as f64).collect()
}

/// Helicoid: consecutive rulings are orthogonal to the axis, so the common perpendicular
/// is the axis itself: h = pH, φ = H, δ = p exactly, footpoints on the axis.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn helicoid_discrete_invariants_are_exact() {
    let p = 0.5;
    let s = sample(&AnalyticSurface::Helicoid { pitch: p }, 25, (0.0, 3.0));
    let u = params(25, (0.0, 3.0));
    let inv = s.invariants();
    let h = 3.0 / 24.0;
    for i in 0..24 {
        assert_near!(inv.angle[i], h, EXACT);
        assert_near!(inv.distance[i], p * h, EXACT);
        assert_near!(inv.distribution[i], p, EXACT);
        assert_near!(inv.footpoints[2 * i], DVec3::new(0.0, 0.0, p * u[i]), EXACT);
        assert_near!(inv.footpoints[2 * i + 1], DVec3::new(0.0, 0.0, p * u[i + 1]), EXACT);
        assert_near!(inv.central_normal[i], DVec3::Z, EXACT);
    }
}

/// Plücker's conoid: every ruling meets the z-axis orthogonally, so footpoints are the
/// points (0, 0, sin 2u_i), h_{i,i+1} = sin 2u_{i+1} − sin 2u_i and φ = H.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn pluecker_conoid_footpoints_are_on_the_axis() {
    let s = sample(&AnalyticSurface::PlueckerConoid, 31, (0.1, 1.4));
    let u = params(31, (0.1, 1.4));
    let inv = s.invariants();
    for i in 0..30 {
        let (z0, z1) = ((2.0 * u[i]).sin(), (2.0 * u[i + 1]).sin());
        assert_near!(inv.footpoints[2 * i], DVec3::new(0.0, 0.0, z0), EXACT);
        assert_near!(inv.footpoints[2 * i + 1], DVec3::new(0.0, 0.0, z1), EXACT);
        assert_near!(inv.angle[i], u[i + 1] - u[i], EXACT);
        assert_near!(inv.distance[i], z1 - z0, EXACT);
    }
}

/// Hyperbolic paraboloid z = xy: the rulings (u, 0, 0) + v(0, 1, u) have their common
/// perpendicular along x between (u_i, 0, 0) and (u_{i+1}, 0, 0), so h = H and
/// δ = H/(atan u_{i+1} − atan u_i), which tends to 1 + u².
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn hyperbolic_paraboloid_distribution_in_closed_form() {
    let s = sample(&AnalyticSurface::HyperbolicParaboloid, 21, (-1.0, 1.0));
    let u = params(21, (-1.0, 1.0));
    let inv = s.invariants();
    for i in 0..20 {
        let h = u[i + 1] - u[i];
        assert_near!(inv.distance[i], h, EXACT);
        assert_near!(inv.angle[i], u[i + 1].atan() - u[i].atan(), EXACT);
        assert_near!(inv.distribution[i], h / (u[i + 1].atan() - u[i].atan()), EXACT);
        assert_near!(inv.footpoints[2 * i], DVec3::new(u[i], 0.0, 0.0), EXACT);
        assert_near!(inv.footpoints[2 * i + 1], DVec3::new(u[i + 1], 0.0, 0.0), EXACT);
    }
}

/// Cone: consecutive rulings meet in the apex: h = 0, δ = 0, every footpoint is the apex.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn cone_rulings_meet_in_the_apex() {
    let cone = AnalyticSurface::Cone;
    let s = cone.sample(40, cone.ranges()).unwrap();
    let apex = DVec3::new(0.5, -0.2, 1.0);
    let inv = s.invariants();
    assert!(inv.parallel.iter().all(|&p| !p));
    for i in 0..39 {
        assert_near!(inv.distance[i], 0.0, EXACT);
        assert_near!(inv.distribution[i], 0.0, 1e-11);
        assert_near!(inv.footpoints[2 * i], apex, 1e-11);
        assert_near!(inv.footpoints[2 * i + 1], apex, 1e-11);
    }
}

/// Cylinder: every pair is parallel; the distance is the chord, the rest is NaN and flagged.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn cylinder_pairs_are_flagged_parallel() {
    let cyl = AnalyticSurface::Cylinder;
    let s = cyl.sample(12, cyl.ranges()).unwrap();
    let inv = s.invariants();
    for i in 0..11 {
        assert!(inv.parallel[i]);
        assert_eq!(inv.angle[i], 0.0);
        let chord = (cyl.jet(0.0).a - cyl.jet(0.0).a).length() + (s.segment(i + 1).a - s.segment(i).a).length();
        assert_near!(inv.distance[i], chord, EXACT);
        assert!(inv.distribution[i].is_nan() && inv.footpoints[2 * i].is_nan());
    }
    assert!(inv.striction.iter().all(|m| m.is_nan()));
}

/// Tangent surface of a helix: consecutive tangents are skew by O(H³) at angle O(H), so
/// the discrete δ is O(H²) although the smooth δ is 0: halving H quarters it.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn helix_tangent_distribution_vanishes_at_second_order() {
    let t = AnalyticSurface::HelixTangent { radius: 1.0, pitch: 0.3 };
    let delta = |n: usize| {
        let inv = sample(&t, n, (0.0, 1.0)).invariants();
        inv.distribution.iter().fold(0.0f64, |m, d| m.max(d.abs()))
    };
    let (coarse, fine) = (delta(11), delta(21));
    assert!(coarse > 0.0 && coarse < 1e-2);
    assert_near!((coarse / fine).log2(), 2.0, ORDER);
}

/// Propositions 1 and 2 measured: footpoints, δ and central normals converge at first
/// order, the footpoint midpoint, averaged δ and Example 1's polygon at second order.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn measured_orders_match_propositions_1_and_2() {
    // Generic surfaces only: on the helicoid, the conoid, the hyperbolic paraboloid and the
    // cone the footpoints are exact, and screw symmetry makes a helical surface's δ even in H.
    let cases = [
        (AnalyticSurface::ALL[0].clone(), 0.7),
        (AnalyticSurface::ALL[0].clone(), 2.0),
        (AnalyticSurface::Quartic, 0.4),
        (AnalyticSurface::Quartic, -0.8),
    ];
    for (surface, u) in cases {
        let study = convergence_study(&surface, u, 0.1, 7).unwrap();
        for series in &study.series {
            // the last ratios are deep in the asymptotic regime
            let last = series.orders[series.orders.len() - 1];
            assert_near!(last, series.expected_order, ORDER);
            assert_near!(series.fitted_order, series.expected_order, 2.0 * ORDER);
        }
    }
}

/// The striction polygon of a sampled hyperboloid is within O(H²) of the exact curve, the
/// footpoints only within O(H): doubling N divides the errors at the same rulings by 4 and 2.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn striction_polygon_of_the_hyperboloid_is_second_order() {
    let hyp = AnalyticSurface::ALL[0].clone();
    // max errors over the rulings of the coarse model (index i of N = 41, 2i of N = 81)
    let errors = |n: usize, every: usize| {
        let u = params(n, (0.2, 2.2));
        let inv = sample(&hyp, n, (0.2, 2.2)).invariants();
        let (mut mid, mut foot) = (0.0f64, 0.0f64);
        for i in (every..n - 1).step_by(every) {
            let s = hyp.striction(u[i]).unwrap();
            mid = mid.max((inv.striction[i - 1] - s).length());
            foot = foot.max((inv.footpoints[2 * i] - s).length());
        }
        (mid, foot)
    };
    let (m1, f1) = errors(41, 1);
    let (m2, f2) = errors(81, 2);
    assert_near!((m1 / m2).log2(), 2.0, ORDER);
    assert_near!((f1 / f2).log2(), 1.0, ORDER);
}
