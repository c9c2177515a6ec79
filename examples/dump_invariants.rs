//! Prints, as JSON, the invariants of Example 3's quartic surface sampled with 50 rulings,
//! computed natively. The Node tests compare the wasm build's numbers against it.
use ruledlab::Invariants;
use ruledlab::{AnalyticSurface, SmoothRuled};

fn main() {
    let q = AnalyticSurface::Quartic;
    let inv = q.sample(50, q.ranges()).expect("valid sample").invariants();
    let list = |v: &[f64]| v.iter().map(|x| format!("{x:e}")).collect::<Vec<_>>().join(",");
    println!(
        "{{\"angle\":[{}],\"distance\":[{}],\"distribution\":[{}],\"footpoints\":[{}],\"centralNormal\":[{}],\"striction\":[{}],\"distributionMean\":[{}],\"perpendicularMidpoints\":[{}]}}",
        list(&inv.angle),
        list(&inv.distance),
        list(&inv.distribution),
        list(Invariants::flat(&inv.footpoints)),
        list(Invariants::flat(&inv.central_normal)),
        list(Invariants::flat(&inv.striction)),
        list(&inv.distribution_mean),
        list(Invariants::flat(&inv.perpendicular_midpoints)),
    );
}
