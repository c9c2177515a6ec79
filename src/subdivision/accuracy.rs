//! How far refined rulings are from the exact surface they were sampled from: the measure
//! behind the comparison of schemes in Section 4 (README, `cargo run --example subdivision`).

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
