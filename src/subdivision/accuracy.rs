//! How far refined rulings are from the exact surface they were sampled from: the measure
//! behind the comparison of schemes in Section 4 (docs/src/guide/subdivision.md, `cargo run --example subdivision`).

use crate::ruled::RuledSurface;
use crate::ruled::SmoothRuled;

/// Largest distance from `surface` of the points a + t(b − a), t = 0, ⅛, …, 1, of the
/// rulings `which` of `refined`, which was refined from a sampling of `surface` over the
/// parameter interval `[u0, u1]`.
pub fn max_distance(
    surface: &(impl SmoothRuled + ?Sized),
    refined: &RuledSurface,
    u0: f64,
    u1: f64,
    which: impl Iterator<Item = usize>,
) -> f64 {
    let n = refined.len();
    let margin = (u1 - u0) / (n as f64 - 1.0) * 4.0;
    which
        .map(|i| {
            let s = refined.segment(i);
            // the ruling belongs near u_i = u0 + i/(n−1) (u1 − u0): search around it
            let ui = u0 + (u1 - u0) * i as f64 / (n as f64 - 1.0);
            (0..=8).map(|k| surface.distance_to(s.at(k as f64 / 8.0), ui - margin, ui + margin)).fold(0.0, f64::max)
        })
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::base::Jet;
    use crate::line::Segment;
    use crate::tolerance::DISTANCE_SCAN;
    use glam::DVec3;

    /// The plane z = 0 ruled by the lines a(u) = (u, 0, 0), d = (0, 1, 0): a point (x, y, z)
    /// is at √((x − u)² + z²) from the ruling u.
    struct Plane;

    impl SmoothRuled for Plane {
        fn name(&self) -> &str {
            "plane"
        }

        fn jet(&self, u: f64) -> Jet {
            Jet { a: DVec3::new(u, 0.0, 0.0), da: DVec3::X, d: DVec3::Y, dd: DVec3::ZERO }
        }
    }

    // 9 rulings over u ∈ [1, 9]: ruling i belongs at u_i = 1 + i, and is searched for in
    // u_i ± 4 (four steps of 1).
    const U: (f64, f64) = (1.0, 9.0);

    /// Ruling i is the segment from (u_i + shift_i, 0, 1) to (u_i + shift_i, 0, 2): its points
    /// at t = 0, ⅛, …, 1 are at heights 1 to 2 above the plane.
    fn rulings(shift: impl Fn(usize) -> f64) -> RuledSurface {
        let segment = |i: usize| {
            let x = U.0 + i as f64 + shift(i);
            Segment { a: DVec3::new(x, 0.0, 1.0), b: DVec3::new(x, 0.0, 2.0) }
        };
        RuledSurface::new((0..9).map(segment).collect()).unwrap()
    }

    #[test]
    fn a_ruling_inside_its_window_is_measured_at_its_farthest_point() {
        // 3.9 steps left or right of its own parameter: the nearest ruling is right below,
        // the farthest point (t = 1) is at height 2
        for sign in [1.0, -1.0] {
            let r = rulings(|i| if i % 2 == 0 { sign * 3.9 } else { -sign * 3.9 });
            for i in 0..9 {
                let d = max_distance(&Plane, &r, U.0, U.1, [i].into_iter());
                assert!((d - 2.0).abs() < 1e-12, "ruling {i}, shift {}: {d}", sign * 3.9);
            }
            assert!((max_distance(&Plane, &r, U.0, U.1, 0..9) - 2.0).abs() < 1e-12);
        }
    }

    #[test]
    fn a_ruling_beyond_its_window_is_measured_from_the_window() {
        // 6 steps away, 2 beyond the window's end u_i ± 4: distance_to's search ends one scan
        // step h = 8/DISTANCE_SCAN past the window, so the nearest ruling it sees is 2 − h away
        let h = 8.0 / DISTANCE_SCAN as f64;
        let expected = ((2.0 - h).powi(2) + 4.0).sqrt();
        for shift in [6.0, -6.0] {
            let r = rulings(|_| shift);
            for i in 0..9 {
                let d = max_distance(&Plane, &r, U.0, U.1, [i].into_iter());
                assert!((d - expected).abs() < 1e-9, "ruling {i}, shift {shift}: {d} ≠ {expected}");
            }
        }
    }

    #[test]
    fn only_the_chosen_rulings_count() {
        // ruling 4 alone is out of its window
        let r = rulings(|i| if i == 4 { 6.0 } else { 0.0 });
        assert!((max_distance(&Plane, &r, U.0, U.1, (0..9).filter(|&i| i != 4)) - 2.0).abs() < 1e-12);
        assert!(max_distance(&Plane, &r, U.0, U.1, 0..9) > 2.5);
        assert_eq!(max_distance(&Plane, &r, U.0, U.1, std::iter::empty()), 0.0);
    }
}
