//! The Klein quadric (beyond the paper; docs/src/conventions.md, "The Klein quadric"): the Klein
//! form of consecutive rulings is −h sin φ (K7) on every surface of the catalogue, unchanged by
//! rigid motions, and every line ruledlab makes — sampled, subdivided in line space step after
//! step — is a point of M to within [`KLEIN_RESIDUAL`].

#![cfg(not(target_family = "wasm"))]

use glam::{DAffine3, DQuat, DVec3};
use proptest::prelude::*;
use ruledlab::tolerance::test::KLEIN_RESIDUAL;
use ruledlab::{
    klein_form, line_space_departure, subdivide_lines, AnalyticCongruence, AnalyticSurface, KleinNet, KleinPoint,
    KleinPolygon, Line, RuledSurface, Scheme, Segment, SmoothCongruence, SmoothRuled,
};

/// Ω(L_i, L_{i+1}) = −h_{i,i+1} sin φ_{i,i+1} on every built-in surface, to rounding of the
/// rulings' size; the cone's steps are torsal (Ω = 0).
#[test]
fn omega_is_minus_h_sin_phi_on_the_catalogue() {
    for name in [
        "hyperboloid",
        "quartic",
        "helicoid",
        "helical",
        "helical-orthogonal",
        "pluecker-conoid",
        "hyperbolic-paraboloid",
        "cone",
        "cylinder",
        "helix-tangent",
    ] {
        let s = AnalyticSurface::by_name(name).unwrap();
        let surface = s.sample(50, s.ranges()).unwrap();
        let inv = surface.invariants();
        let k = KleinPolygon::of(&surface, false);
        let scale = surface.points().iter().fold(1.0f64, |m, p| m.max(p.length()));
        let mut worst = 0.0f64;
        for i in 0..k.omega.len() {
            let want = if inv.parallel[i] { 0.0 } else { -inv.distance[i] * inv.angle[i].sin() };
            worst = worst.max((k.omega[i] - want).abs());
        }
        eprintln!("{name}: |Ω + h sin φ| ≤ {worst:.1e}, residual ≤ {:.1e}", k.max_residual);
        assert!(worst < 1e-14 * scale, "{name}: |Ω + h sin φ| up to {worst:e}");
        assert!(k.max_residual <= KLEIN_RESIDUAL, "{name}: residual {:e}", k.max_residual);
        if name == "cone" || name == "cylinder" {
            assert!(k.torsal.iter().all(|&t| t), "{name}: {:?}", k.omega);
        }
    }
}

/// On a smooth surface sampled at step H, Ω = −δ φ² + O(φ⁴): Ω/φ² tends to −δ (the hyperboloid).
#[test]
fn omega_over_phi_squared_tends_to_minus_delta() {
    let s = AnalyticSurface::by_name("hyperboloid").unwrap();
    for n in [100, 400] {
        let surface = s.sample(n, s.ranges()).unwrap();
        let inv = surface.invariants();
        let k = KleinPolygon::of(&surface, false);
        for i in (0..n - 1).step_by(7) {
            let ratio = -k.omega[i] / (inv.angle[i] * inv.angle[i]);
            assert!(
                (ratio - inv.distribution[i]).abs() < 1e-3 * (400.0 / n as f64).powi(2),
                "{n} {i}: {ratio} vs {}",
                inv.distribution[i]
            );
        }
    }
}

/// A congruence's grid as a net on M: Ω on each edge is −h sin φ of the edge's two lines, as
/// Section 2 computes h and φ for the rulings of the grid's rows and columns read as surfaces.
#[test]
fn omega_on_a_congruence_net_is_minus_h_sin_phi_of_its_rows_and_columns() {
    for c in AnalyticCongruence::ALL {
        let grid = c.grid(7, 5).unwrap();
        let net = KleinNet::of(&grid);
        assert_eq!(net.edges.len(), 7 * 4 + 5 * 6);
        assert!(net.max_residual <= KLEIN_RESIDUAL);
        let mut k = 0;
        let rows = (0..7).map(|i| grid.row(i).unwrap());
        let cols = (0..5).map(|j| grid.column(j).unwrap());
        for surface in rows.chain(cols) {
            let inv = surface.invariants();
            for step in 0..surface.len() - 1 {
                let want = -inv.distance[step] * inv.angle[step].sin();
                let scale = surface.segments().map(|s| s.a.length().max(s.b.length())).fold(1.0, f64::max);
                assert!((net.omega[k] - want).abs() <= 1e-14 * scale, "{c:?} edge {k}: {} vs {want}", net.omega[k]);
                k += 1;
            }
        }
        assert_eq!(k, net.edges.len());
    }
}

fn segment() -> impl Strategy<Value = Segment> {
    let c = -3.0..3.0f64;
    (c.clone(), c.clone(), c.clone(), c.clone(), c.clone(), c)
        .prop_filter("a segment of length", |(a, b, c, d, e, f)| {
            (DVec3::new(*a, *b, *c) - DVec3::new(*d, *e, *f)).length() > 0.1
        })
        .prop_map(|(a, b, c, d, e, f)| Segment::new(DVec3::new(a, b, c), DVec3::new(d, e, f)))
}

proptest! {
    /// Ω of two normalised lines is a motion invariant: −h sin φ is.
    #[test]
    fn omega_is_invariant_under_rigid_motions(
        s in segment(), t in segment(),
        axis in (-1.0..1.0f64, -1.0..1.0f64, 0.1..1.0f64), angle in -3.0..3.0f64,
        shift in (-5.0..5.0f64, -5.0..5.0f64, -5.0..5.0f64),
    ) {
        let motion = DAffine3::from_rotation_translation(
            DQuat::from_axis_angle(DVec3::new(axis.0, axis.1, axis.2).normalize(), angle),
            DVec3::new(shift.0, shift.1, shift.2),
        );
        let moved = |g: &Segment| Segment::new(motion.transform_point3(g.a), motion.transform_point3(g.b));
        let (a, b) = (KleinPoint::of_segment(&s), KleinPoint::of_segment(&t));
        let (ma, mb) = (KleinPoint::of_segment(&moved(&s)), KleinPoint::of_segment(&moved(&t)));
        prop_assert!((klein_form(&a, &b) - klein_form(&ma, &mb)).abs() < 1e-12);
        prop_assert!(ma.residual().abs() <= KLEIN_RESIDUAL && mb.residual().abs() <= KLEIN_RESIDUAL);
    }

    /// Every line of the line-space subdivision is a point of M after every step (and of the
    /// re-cut segments the page draws), however far the combinations before N left it.
    #[test]
    fn line_space_subdivision_stays_on_m(
        segments in prop::collection::vec(segment(), 4..12), steps in 1usize..5, scheme in 0usize..3,
    ) {
        let surface = RuledSurface::new(segments).unwrap();
        let scheme = [Scheme::Chaikin, Scheme::BSpline { degree: 3 }, Scheme::FourPoint { w: 0.0625 }][scheme];
        if let Ok(d) = line_space_departure(&surface, scheme, false, steps) {
            for after in &d.after {
                prop_assert!(*after <= KLEIN_RESIDUAL, "{after:e}");
            }
            let refined = subdivide_lines(&surface, scheme, false, steps, None).unwrap();
            prop_assert!(KleinPolygon::of(&refined, false).max_residual <= KLEIN_RESIDUAL);
        }
    }
}

/// The lines of a pencil are a line of P⁵ on M: Ω = 0 for every pair, and the line-space
/// combinations of pencil lines stay on M before N.
#[test]
fn a_pencil_is_a_line_on_m() {
    let o = DVec3::new(1.0, -2.0, 0.5);
    let lines: Vec<Segment> = (0..6)
        .map(|i| Segment::new(o, o + Line { point: o, dir: DVec3::new(1.0, 0.2 * i as f64, 0.0).normalize() }.dir))
        .collect();
    let surface = RuledSurface::new(lines).unwrap();
    let d = line_space_departure(&surface, Scheme::Chaikin, false, 3).unwrap();
    assert!(d.before.iter().all(|r| *r < 1e-15), "{:?}", d.before);
}
