//! Section 3 against exact answers: the hinge chain is an isometry, the conoidal model is
//! conoidal, the development behaves as the paper says, and the non-developability measure
//! is 0 for a cone, O(H²) for a tangent surface and convergent for a skew surface. Runs
//! natively and in headless Chromium.

use glam::{DVec2, DVec3};
use ruledlab::assert_near;
use ruledlab::tolerance::test::{EXACT, ORDER};
use ruledlab::{AnalyticSurface, Ranges, SmoothRuled};
use ruledlab::{Development, HingeChain};
use ruledlab::{RuledSurface, Segment};

#[cfg(target_family = "wasm")]
use wasm_bindgen_test::wasm_bindgen_test;
#[cfg(target_family = "wasm")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

/// A small deterministic generator (tests must be reproducible, also in wasm).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn sample(s: &AnalyticSurface, n: usize, u: (f64, f64)) -> RuledSurface {
    s.sample(n, Ranges { u, v: (-1.0, 1.0), closed: false }).unwrap()
}

/// Edge lengths of the polygon p_i = a_i + t_i (b_i − a_i).
fn polygon_lengths(s: &RuledSurface, t: &[f64]) -> Vec<f64> {
    let p: Vec<DVec3> = s.segments().zip(t).map(|(g, &t)| g.at(t)).collect();
    p.windows(2).map(|w| (w[1] - w[0]).length()).collect()
}

/// Every deformation preserves the lengths of random polygons to 1e-12 relative, and φ and
/// the signed h of every pair.
fn assert_isometric(s: &RuledSurface, image: &RuledSurface, rng: &mut Lcg) {
    for _ in 0..5 {
        let t: Vec<f64> = (0..s.len()).map(|_| 3.0 * rng.next() - 1.0).collect();
        for (l0, l1) in polygon_lengths(s, &t).iter().zip(polygon_lengths(image, &t)) {
            assert!((l0 - l1).abs() <= EXACT * l0, "length {l0} became {l1}");
        }
    }
    let (a, b) = (s.invariants(), image.invariants());
    for i in 0..s.len() - 1 {
        assert_near!(a.angle[i], b.angle[i], EXACT);
        assert_near!(a.distance[i], b.distance[i], EXACT);
    }
}

fn surfaces() -> Vec<RuledSurface> {
    let mut rng = Lcg(7);
    let random = RuledSurface::new(
        (0..30)
            .map(|_| {
                let a = DVec3::new(rng.next(), rng.next(), rng.next()) * 4.0;
                Segment::new(a, a + DVec3::new(rng.next() - 0.5, rng.next() - 0.5, rng.next() - 0.5))
            })
            .collect(),
    )
    .unwrap();
    vec![
        sample(&AnalyticSurface::ALL[0].clone(), 40, (0.0, 5.0)),
        sample(&AnalyticSurface::Quartic, 25, (-1.0, 1.0)),
        sample(&AnalyticSurface::ALL[3].clone(), 60, (0.0, 9.0)),
        random,
    ]
}

#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn hinge_bend_and_conoidal_are_isometries() {
    let mut rng = Lcg(1);
    for s in surfaces() {
        let chain = HingeChain::new(&s);
        let angles: Vec<f64> = (0..s.len() - 2).map(|_| 6.0 * rng.next() - 3.0).collect();
        assert_isometric(&s, &chain.deform(&angles).unwrap(), &mut rng);
        assert_isometric(&s, &chain.bend(0.37).unwrap(), &mut rng);
        assert_isometric(&s, &chain.conoidal(), &mut rng);
        // R_0 and R_1 stay where they are
        let c = chain.conoidal();
        for k in 0..4 {
            assert_near!(c.points()[k], s.points()[k], EXACT);
        }
    }
}

#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn conoidal_rulings_are_orthogonal_to_the_first_common_normal() {
    for s in surfaces() {
        let n01 = s.invariants().central_normal[0];
        let c = HingeChain::new(&s).conoidal();
        for line in c.lines() {
            assert!(line.dir.dot(n01).abs() <= EXACT, "e'·n = {:e}", line.dir.dot(n01));
        }
        // and all its common normals point the same way as n_{0,1}
        for n in c.invariants().central_normal {
            assert_near!(n, n01, 1e-11);
        }
    }
}

/// The footpoints sit at the same place on their rulings before and after: the striction
/// polygon maps to the striction polygon.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn striction_polygon_maps_to_striction_polygon() {
    for s in surfaces() {
        let c = HingeChain::new(&s).conoidal();
        let (a, b) = (s.invariants(), c.invariants());
        let along = |surf: &RuledSurface, i: usize, p: DVec3| (p - surf.segment(i).a).dot(surf.segment(i).line().dir);
        for i in 1..s.len() - 1 {
            let scale = 1.0 + a.striction[i - 1].length();
            assert_near!(along(&s, i, a.striction[i - 1]) / scale, along(&c, i, b.striction[i - 1]) / scale, EXACT);
            assert_near!(along(&s, i, a.footpoints[2 * i]) / scale, along(&c, i, b.footpoints[2 * i]) / scale, EXACT);
        }
    }
}

/// In the development the two footpoints of a pair coincide and lie on both projected
/// rulings, so the projected rulings envelop the image of the striction polygon.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn development_footpoints_coincide_and_lie_on_both_rulings() {
    for s in surfaces() {
        let dev = Development::of(&s);
        let inv = dev.conoidal.invariants();
        let n = dev.conoidal.segment(0).line().dir.cross(dev.conoidal.segment(1).line().dir).normalize();
        let x = dev.conoidal.segment(0).line().dir;
        let (o, y) = (dev.conoidal.segment(0).a, n.cross(x));
        let project = |p: DVec3| DVec2::new((p - o).dot(x), (p - o).dot(y));
        let dist_to_line = |q: DVec2, i: usize| {
            let (a, b) = (dev.points[2 * i], dev.points[2 * i + 1]);
            (q - a).perp_dot((b - a).normalize()).abs()
        };
        for i in 0..s.len() - 1 {
            let (f0, f1) = (project(inv.footpoints[2 * i]), project(inv.footpoints[2 * i + 1]));
            let scale = 1.0 + f0.length();
            assert!((f0 - f1).length() <= EXACT * scale);
            assert!(dist_to_line(f0, i) <= EXACT * scale && dist_to_line(f0, i + 1) <= EXACT * scale);
        }
        // the development is isometric on every ruling
        for i in 0..s.len() {
            assert_near!((dev.points[2 * i + 1] - dev.points[2 * i]).length(), s.segment(i).length(), EXACT);
        }
    }
}

/// A cone develops into a planar fan: measure 0, all rulings through one point, with the
/// original angles between consecutive rulings.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn cone_develops_to_a_planar_fan() {
    let cone = AnalyticSurface::Cone;
    let s = cone.sample(30, Ranges { u: (0.0, 5.0), v: (0.2, 1.2), closed: false }).unwrap();
    let dev = Development::of(&s);
    assert!(dev.non_developability() <= EXACT, "measure {:e}", dev.non_developability());
    let apex = dev.points[0] - 0.2 / 1.0 * (dev.points[1] - dev.points[0]); // a = apex + 0.2 d, b = apex + 1.2 d
    let angles = s.invariants().angle;
    for i in 0..30 {
        let (a, b) = (dev.points[2 * i], dev.points[2 * i + 1]);
        assert!((apex - a).perp_dot((b - a).normalize()).abs() <= 1e-11, "ruling {i} misses the apex");
        if let Some(&angle) = angles.get(i) {
            let (d0, d1) = (b - a, dev.points[2 * i + 3] - dev.points[2 * i + 2]);
            assert_near!(d0.angle_to(d1), angle, 1e-11);
        }
    }
}

/// The tangent surface of a helix is developable, but consecutive sampled tangents are skew
/// by O(H³): the measure falls as O(H²).
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn tangent_surface_measure_falls_at_second_order() {
    let t = AnalyticSurface::HelixTangent { radius: 1.0, pitch: 0.3 };
    let m = |n: usize| Development::of(&sample(&t, n, (0.0, 3.0))).non_developability();
    let (m1, m2, m3) = (m(31), m(61), m(121));
    assert!(m1 > 0.0 && m1 < 1e-2);
    assert_near!((m1 / m2).log2(), 2.0, ORDER);
    assert_near!((m2 / m3).log2(), 2.0, ORDER);
}

/// A skew surface has a positive measure that converges as N grows (at second order).
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn skew_surface_measure_converges() {
    let hyp = AnalyticSurface::ALL[0].clone();
    let m: Vec<f64> =
        [21, 41, 81, 161].iter().map(|&n| Development::of(&sample(&hyp, n, (0.0, 2.0))).non_developability()).collect();
    assert!(m[3] > 0.5, "a hyperboloid strip is far from developable: {}", m[3]);
    let order = ((m[1] - m[0]) / (m[2] - m[1])).abs().log2();
    let order2 = ((m[2] - m[1]) / (m[3] - m[2])).abs().log2();
    assert_near!(order, 2.0, 2.0 * ORDER);
    assert_near!(order2, 2.0, ORDER);
}

/// 10⁵ rulings: turning every hinge by a random θ and then the image's hinges by −θ comes
/// back to the input, and the conoidal model keeps every ruling orthogonal to n_{0,1}, both
/// to 1e-12 of the model's size: no drift along the chain.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn long_chains_do_not_drift() {
    let hyp = AnalyticSurface::ALL[0].clone();
    let s = hyp.sample(100_000, Ranges { u: (0.0, 400.0), v: (-1.0, 1.0), closed: false }).unwrap();
    let size = s.points().iter().fold(0.0f64, |m, p| m.max(p.length()));
    let chain = HingeChain::new(&s);
    let mut rng = Lcg(3);
    let theta: Vec<f64> = (0..s.len() - 2).map(|_| 0.2 * rng.next() - 0.1).collect();
    let there = chain.deform(&theta).unwrap();
    let back_angles: Vec<f64> = theta.iter().map(|t| -t).collect();
    let back = HingeChain::new(&there).deform(&back_angles).unwrap();
    let drift = s.points().iter().zip(back.points()).map(|(p, q)| (*p - *q).length()).fold(0.0, f64::max);
    let n01 = chain.first_normal();
    let worst = chain.conoidal().lines().map(|l| l.dir.dot(n01).abs()).fold(0.0, f64::max);
    println!("N = 10⁵: round-trip drift {:.1e} of size {size:.2}, conoidal |e'·n01| ≤ {worst:.1e}", drift);
    assert!(drift <= EXACT * size, "drift {drift:e}");
    assert!(worst <= EXACT, "orthogonality {worst:e}");
}

/// Fig. 5: the conoidal image of a ruled helical surface. Its rulings are tangent to a
/// cylinder about the screw axis of radius ρ → (e·ṡ)/|e′| = r + p tan β; they meet the axis
/// orthogonally only when the striction curve is orthogonal to the rulings (e·ṡ = 0).
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn helical_surface_conoidal_image_touches_a_cylinder() {
    let (r, p) = (1.0f64, 0.4f64);
    for (beta, rho) in [(std::f64::consts::FRAC_PI_4, r + p), ((-r / p).atan(), 0.0)] {
        let surface = AnalyticSurface::HelicalRuled { radius: r, pitch: p, slope: beta };
        let radius = |n: usize| {
            let dev = Development::of(&sample(&surface, n, (0.0, 6.0)));
            let inv = dev.conoidal.invariants();
            // by screw symmetry every footpoint image lies on one circle about the axis
            let q: Vec<DVec2> = (0..3)
                .map(|i| {
                    let f = inv.footpoints[2 * (i + 5)];
                    dev.points[0] + project(&dev, f)
                })
                .collect();
            let c = circumcenter(q[0], q[1], q[2]);
            let d: Vec<f64> = (0..n)
                .map(|i| {
                    let (a, b) = (dev.points[2 * i], dev.points[2 * i + 1]);
                    (c - a).perp_dot((b - a).normalize()).abs()
                })
                .collect();
            let spread = d.iter().fold(0.0f64, |m, x| m.max((x - d[0]).abs()));
            assert!(spread < 1e-9, "not all rulings touch one circle: spread {spread:e}");
            d[0]
        };
        let (coarse, fine) = (radius(121), radius(241));
        assert!((fine - rho).abs() < (coarse - rho).abs() || (fine - rho).abs() < 1e-12);
        assert_near!(fine, rho, 1e-3);
    }
}

fn project(dev: &Development, p: DVec3) -> DVec2 {
    let s0 = dev.conoidal.segment(0);
    let x = s0.line().dir;
    let y = dev.conoidal.segment(0).line().dir.cross(dev.conoidal.segment(1).line().dir).normalize().cross(x);
    DVec2::new((p - s0.a).dot(x), (p - s0.a).dot(y)) - dev.points[0]
}

fn circumcenter(a: DVec2, b: DVec2, c: DVec2) -> DVec2 {
    let (b, c) = (b - a, c - a);
    let d = 2.0 * b.perp_dot(c);
    a + DVec2::new(
        c.y * b.length_squared() - b.y * c.length_squared(),
        b.x * c.length_squared() - c.x * b.length_squared(),
    ) / d
}
