//! Property tests (native): the invariants of Section 2 are Euclidean invariants.
//! φ, h and δ do not change under proper rigid motions; footpoints, striction points and
//! normals move with them; a reflection flips the signs of h and δ; scaling by λ scales h
//! and δ by λ; reversing the order of the rulings, or the orientation of all of them,
//! leaves h unchanged.
#![cfg(not(target_family = "wasm"))]

use glam::{DAffine3, DQuat, DVec3};
use proptest::prelude::*;
use ruledlab::assert_near;
use ruledlab::tolerance::test::EXACT;
use ruledlab::Invariants;
use ruledlab::{Line, RuledSurface, Segment};

const TOL: f64 = 1e-9; // random surfaces include badly conditioned (nearly parallel) pairs

fn vec3() -> impl Strategy<Value = DVec3> {
    (-3.0..3.0f64, -3.0..3.0f64, -3.0..3.0f64).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

/// Random surfaces of 3–12 rulings whose consecutive directions are clearly not parallel.
fn surface() -> impl Strategy<Value = RuledSurface> {
    prop::collection::vec((vec3(), vec3()), 3..12).prop_filter_map("degenerate", |pairs| {
        let segments: Vec<Segment> = pairs.iter().map(|&(a, d)| Segment::new(a, a + d)).collect();
        let s = RuledSurface::new(segments).ok()?;
        let lines: Vec<Line> = s.lines().collect();
        let ok = lines.windows(2).all(|w| w[0].dir.cross(w[1].dir).length() > 0.05)
            && s.segments().all(|g| g.length() > 0.1);
        ok.then_some(s)
    })
}

fn motion() -> impl Strategy<Value = DAffine3> {
    (vec3(), vec3(), -3.0..3.0f64).prop_map(|(t, axis, angle)| {
        let axis = axis.try_normalize().unwrap_or(DVec3::X);
        DAffine3::from_rotation_translation(DQuat::from_axis_angle(axis, angle), t * 10.0)
    })
}

fn all_near(a: &[f64], b: &[f64], tol: f64) {
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(b) {
        assert_near!(*x, *y, tol);
    }
}

fn points_near(a: &[DVec3], b: &[DVec3], tol: f64) {
    for (x, y) in a.iter().zip(b) {
        assert_near!(*x, *y, tol);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn invariants_are_invariant_and_points_equivariant(s in surface(), m in motion()) {
        let moved = s.map_points(|p| m.transform_point3(p)).unwrap();
        let (a, b) = (s.invariants(), moved.invariants());
        all_near(&a.angle, &b.angle, TOL);
        all_near(&a.distance, &b.distance, TOL);
        all_near(&a.distribution, &b.distribution, TOL);
        all_near(&a.distribution_mean, &b.distribution_mean, TOL);
        let image = |v: &[DVec3]| v.iter().map(|&p| m.transform_point3(p)).collect::<Vec<_>>();
        points_near(&image(&a.footpoints), &b.footpoints, TOL);
        points_near(&image(&a.striction), &b.striction, TOL);
        points_near(&image(&a.perpendicular_midpoints), &b.perpendicular_midpoints, TOL);
        let turned: Vec<DVec3> = a.central_normal.iter().map(|&n| m.transform_vector3(n)).collect();
        points_near(&turned, &b.central_normal, TOL);
    }

    #[test]
    fn reflection_flips_signed_quantities(s in surface()) {
        let mirrored = s.map_points(|p| DVec3::new(p.x, p.y, -p.z)).unwrap();
        let (a, b) = (s.invariants(), mirrored.invariants());
        all_near(&a.angle, &b.angle, TOL);
        let neg = |v: &[f64]| v.iter().map(|x| -x).collect::<Vec<_>>();
        all_near(&neg(&a.distance), &b.distance, TOL);
        all_near(&neg(&a.distribution), &b.distribution, TOL);
    }

    #[test]
    fn scaling_scales_lengths(s in surface(), lambda in 0.01..100.0f64) {
        let scaled = s.map_points(|p| lambda * p).unwrap();
        let (a, b) = (s.invariants(), scaled.invariants());
        all_near(&a.angle, &b.angle, TOL);
        let times = |v: &[f64]| v.iter().map(|x| lambda * x).collect::<Vec<_>>();
        all_near(&times(&a.distance), &b.distance, TOL);
        all_near(&times(&a.distribution), &b.distribution, TOL);
    }

    #[test]
    fn reversal_keeps_h(s in surface()) {
        let n = s.len();
        let reversed = RuledSurface::new((0..n).rev().map(|i| s.segment(i)).collect()).unwrap();
        let flipped = RuledSurface::new(s.segments().map(|g| Segment::new(g.b, g.a)).collect()).unwrap();
        let a = s.invariants();
        let mut r = reversed.invariants().distance;
        r.reverse();
        all_near(&a.distance, &r, TOL);
        all_near(&a.distance, &flipped.invariants().distance, TOL);
    }

    /// The defining property of the footpoints: the segment f_{i,i+1} f_{i+1,i} is
    /// orthogonal to both rulings, lies on them, and has length |h|.
    #[test]
    fn footpoints_span_the_common_perpendicular(s in surface()) {
        let inv = s.invariants();
        let lines: Vec<Line> = s.lines().collect();
        for i in 0..lines.len() - 1 {
            let (f0, f1) = (inv.footpoints[2 * i], inv.footpoints[2 * i + 1]);
            let scale = 1.0 + f0.length() + f1.length();
            assert_near!(lines[i].distance_to(f0) / scale, 0.0, TOL);
            assert_near!(lines[i + 1].distance_to(f1) / scale, 0.0, TOL);
            assert_near!((f1 - f0).dot(lines[i].dir) / scale, 0.0, TOL);
            assert_near!((f1 - f0).dot(lines[i + 1].dir) / scale, 0.0, TOL);
            assert_near!((f1 - f0).dot(inv.central_normal[i]), inv.distance[i], TOL * scale);
        }
    }
}

/// `Invariants::of` agrees with a direct evaluation of the definitions via nalgebra-free
/// brute force: the closest points found by minimising over a fine grid.
#[test]
fn footpoints_minimise_the_distance() {
    let lines = [
        Line { point: DVec3::new(0.3, -1.0, 0.2), dir: DVec3::new(1.0, 0.4, -0.2).normalize() },
        Line { point: DVec3::new(-0.5, 0.7, 1.1), dir: DVec3::new(0.1, 1.0, 0.5).normalize() },
    ];
    let inv = Invariants::of(&lines);
    let (f0, f1) = (inv.footpoints[0], inv.footpoints[1]);
    let d = (f1 - f0).length();
    for t in [-0.01, 0.01] {
        for s in [-0.01, 0.01] {
            let p = f0 + t * lines[0].dir;
            let q = f1 + s * lines[1].dir;
            assert!((q - p).length() > d);
        }
    }
    assert_near!(d, inv.distance[0].abs(), EXACT);
}

mod schemes {
    //! Every subdivision scheme and every isometry commutes with rigid motions.
    use super::*;
    use ruledlab::{subdivide_congruence, CongruenceScheme, LineCongruence};
    use ruledlab::{subdivide_strip, Scheme, Variant};
    use ruledlab::{Development, HingeChain};

    fn same(a: &[DVec3], b: &[DVec3]) {
        assert_eq!(a.len(), b.len());
        for (p, q) in a.iter().zip(b) {
            assert_near!(*p, *q, TOL);
        }
    }

    fn schemes() -> Vec<Scheme> {
        vec![
            Scheme::Chaikin,
            Scheme::BSpline { degree: 3 },
            Scheme::Bezier,
            Scheme::FourPoint { w: 1.0 / 16.0 },
            Scheme::Variational { n: 5, variant: Variant::Coupled },
            Scheme::Variational { n: 5, variant: Variant::Averaged },
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        #[test]
        fn strip_schemes_commute_with_rigid_motions(s in surface(), m in motion()) {
            let moved = s.map_points(|p| m.transform_point3(p)).unwrap();
            for scheme in schemes() {
                let (Ok(a), Ok(b)) = (subdivide_strip(&s, scheme, false, 1), subdivide_strip(&moved, scheme, false, 1)) else { continue };
                let image: Vec<DVec3> = a.points().iter().map(|&p| m.transform_point3(p)).collect();
                same(&image, b.points());
            }
        }

        #[test]
        fn interpolatory_schemes_keep_old_rulings_bit_for_bit(s in surface()) {
            for scheme in [Scheme::FourPoint { w: 0.07 }, Scheme::Variational { n: 7, variant: Variant::Coupled }] {
                let Ok(r) = subdivide_strip(&s, scheme, false, 2) else { continue };
                for i in 0..s.len() {
                    prop_assert_eq!(r.segment(4 * i), s.segment(i));
                }
            }
        }

        #[test]
        fn isometries_commute_with_rigid_motions_and_keep_lengths(s in surface(), m in motion(), t in 0.0..1.0f64) {
            let moved = s.map_points(|p| m.transform_point3(p)).unwrap();
            let (a, b) = (HingeChain::new(&s).bend(t).unwrap(), HingeChain::new(&moved).bend(t).unwrap());
            let image: Vec<DVec3> = a.points().iter().map(|&p| m.transform_point3(p)).collect();
            same(&image, b.points());
            // lengths of the a-polygon and of each ruling are kept
            for i in 0..s.len() {
                assert_near!(a.segment(i).length(), s.segment(i).length(), EXACT);
                if i + 1 < s.len() {
                    assert_near!((a.segment(i + 1).a - a.segment(i).a).length(), (s.segment(i + 1).a - s.segment(i).a).length(), 1e-11);
                }
            }
            // the development and the measure are invariant
            let (d0, d1) = (Development::of(&s), Development::of(&moved));
            assert_near!(d0.non_developability(), d1.non_developability(), TOL);
            for (p, q) in d0.points.iter().zip(&d1.points) {
                assert_near!(*p, *q, TOL);
            }
        }

        #[test]
        fn congruence_schemes_commute_with_rigid_motions(grid in prop::collection::vec(vec3(), 9), m in motion()) {
            let p: Vec<DVec3> = (0..9).map(|k| DVec3::new((k / 3) as f64, (k % 3) as f64, 0.0) + 0.2 * grid[k]).collect();
            let q: Vec<DVec3> = p.iter().zip(&grid).map(|(a, g)| *a + DVec3::new(0.1 * g.x, 0.1 * g.y, 1.0)).collect();
            let c = LineCongruence::from_points(3, 3, &p, &q).unwrap();
            let moved = LineCongruence::from_points(3, 3, &p.iter().map(|&x| m.transform_point3(x)).collect::<Vec<_>>(), &q.iter().map(|&x| m.transform_point3(x)).collect::<Vec<_>>()).unwrap();
            for scheme in [CongruenceScheme::Butterfly { w: 1.0 / 16.0 }, CongruenceScheme::TwoStage { k: 4 }, CongruenceScheme::Coupled { k: 4 }] {
                let (a, b) = (subdivide_congruence(&c, scheme, 1).unwrap(), subdivide_congruence(&moved, scheme, 1).unwrap());
                same(&a.p().iter().map(|&x| m.transform_point3(x)).collect::<Vec<_>>(), &b.p());
                same(&a.q().iter().map(|&x| m.transform_point3(x)).collect::<Vec<_>>(), &b.q());
            }
        }

        #[test]
        fn focal_geometry_moves_with_rigid_motions(grid in prop::collection::vec(vec3(), 16), m in motion()) {
            use ruledlab::focal_grid;
            let p: Vec<DVec3> = (0..16).map(|k| DVec3::new((k / 4) as f64, (k % 4) as f64, 0.0) + 0.2 * grid[k]).collect();
            let q: Vec<DVec3> = p.iter().zip(&grid).map(|(a, g)| *a + DVec3::new(0.3 * g.x, 0.3 * g.y, 1.0 + 0.1 * g.z)).collect();
            let moved = |x: &[DVec3]| x.iter().map(|&x| m.transform_point3(x)).collect::<Vec<_>>();
            let (a, b) = (focal_grid(4, 4, &p, &q), focal_grid(4, 4, &moved(&p), &moved(&q)));
            // swapping p and q, too, keeps the focal points
            let r = focal_grid(4, 4, &q, &p);
            for ((f, g), h) in a.iter().zip(&b).zip(&r) {
                let close = f.parameters[1] - f.parameters[0] < 1e-6 * f.parameters[1].abs().max(1.0);
                if f.kind != g.kind && close {
                    continue; // nearly parabolic: rounding may decide the kind
                }
                prop_assert_eq!(f.kind, g.kind);
                prop_assert_eq!(f.middle.is_finite(), g.middle.is_finite());
                if f.middle.is_finite() && f.middle.length() < 1e6 {
                    assert_near!(m.transform_point3(f.middle), g.middle, 1e-7);
                    assert_near!(f.middle, h.middle, 1e-7);
                }
                if f.kind == ruledlab::FocalKind::Hyperbolic && f.parameters.iter().all(|t| t.abs() < 1e4) && !close {
                    for k in 0..2 {
                        assert_near!(m.transform_point3(f.points[k]), g.points[k], 1e-7);
                        assert_near!(f.parameters[k], g.parameters[k], 1e-7);
                        assert_near!(f.torsal[k], g.torsal[k], 1e-6);
                        assert_near!(f.points[k], h.points[1 - k], 1e-7);
                    }
                    assert_near!(f.normality, g.normality, 1e-7);
                }
            }
        }

        #[test]
        fn linear_complexes_move_with_rigid_motions(lines in prop::collection::vec((vec3(), vec3()), 3..20), m in motion()) {
            use ruledlab::fit_linear_complex;
            let segments: Vec<Segment> = lines.iter().filter(|(_, d)| d.length() > 0.1).map(|&(a, d)| Segment::new(a, a + d)).collect();
            prop_assume!(segments.len() >= 3);
            let moved: Vec<Segment> = segments.iter().map(|s| Segment::new(m.transform_point3(s.a), m.transform_point3(s.b))).collect();
            let (f, g) = (fit_linear_complex(&segments, None), fit_linear_complex(&moved, None));
            prop_assert_eq!(f.nullity, g.nullity);
            prop_assert_eq!(f.kind, g.kind);
            assert_near!(f.residual, g.residual, 1e-9);
            for k in 0..6 {
                assert_near!(f.spectrum[k], g.spectrum[k], 1e-9);
            }
            // a unique best complex: its axis moves along, its pitch stays
            if f.spectrum[1] - f.spectrum[0] > 1e-3 && f.pitch.is_finite() && f.pitch.abs() < 1e3 && f.axis_point.length() < 1e3 {
                assert_near!(f.pitch, g.pitch, 1e-7);
                let dir = m.transform_vector3(f.axis_direction);
                assert_near!(dir.cross(g.axis_direction), DVec3::ZERO, 1e-7);
                let on_axis = m.transform_point3(f.axis_point) - g.axis_point;
                assert_near!(on_axis.cross(g.axis_direction), DVec3::ZERO, 1e-6);
            }
        }
    }
}
