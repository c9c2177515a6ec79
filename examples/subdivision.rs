//! The comparison of Section 4's schemes: distance of refined rulings from the exact surface
//! for Example 3 (12 rulings of the quartic surface, n = 12) and two other surfaces.
//! `cargo run --release --example subdivision`
use ruledlab::{max_distance, subdivide_strip, Scheme, Variant};
use ruledlab::{AnalyticSurface, Ranges, SmoothRuled};

fn main() {
    let cases = [
        ("Example 3: quartic, u ∈ [−1, 1]", AnalyticSurface::Quartic, (-1.0, 1.0)),
        ("hyperboloid, u ∈ [0, 3]", AnalyticSurface::ALL[0].clone(), (0.0, 3.0)),
        ("helical surface, u ∈ [0, 6]", AnalyticSurface::ALL[3].clone(), (0.0, 6.0)),
    ];
    let schemes: [(&str, Scheme); 7] = [
        ("midpoint (bspline d=1)", Scheme::BSpline { degree: 1 }),
        ("Chaikin", Scheme::Chaikin),
        ("four-point w=1/16", Scheme::FourPoint { w: 1.0 / 16.0 }),
        ("four-point w=1/13", Scheme::FourPoint { w: 1.0 / 13.0 }),
        ("variational literal", Scheme::Variational { n: 12, variant: Variant::Literal }),
        ("variational coupled", Scheme::Variational { n: 12, variant: Variant::Coupled }),
        ("variational averaged", Scheme::Variational { n: 12, variant: Variant::Averaged }),
    ];
    for (title, surface, u) in cases {
        println!("{title}, N = 12, one step: distance of new rulings from the surface");
        println!("  {:<22} {:>10} {:>10}", "scheme", "max", "interior");
        let s = surface.sample(12, Ranges { u, v: (-1.0, 1.0), closed: false }).unwrap();
        for (name, scheme) in schemes {
            let r = subdivide_strip(&s, scheme, false, 1).unwrap();
            // interpolatory: the inserted rulings; approximating: every ruling (none is kept)
            let which: Vec<usize> =
                if scheme.is_interpolatory() { (1..r.len()).step_by(2).collect() } else { (0..r.len()).collect() };
            let d = max_distance(&surface, &r, u.0, u.1, which.iter().copied());
            // "interior": without the two rulings nearest each end
            let inner = max_distance(&surface, &r, u.0, u.1, which[2..which.len() - 2].iter().copied());
            println!("  {name:<22} {d:10.2e} {inner:10.2e}");
        }
    }
}
