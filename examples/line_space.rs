//! Line-space versus endpoint subdivision: error of the inserted rulings against the exact
//! ruling at the parameter midpoint (angle, and distance of the exact striction point from the
//! inserted line), for N = 12, 24, 48 rulings, with the observed order.
//! `cargo run --release --example line_space`
use ruledlab::subdivide_lines;
use ruledlab::RuledSurface;
use ruledlab::{subdivide_strip, Scheme};
use ruledlab::{AnalyticSurface, Ranges, SmoothRuled};

fn errors(surface: &AnalyticSurface, n: usize, u: (f64, f64), refined: &RuledSurface) -> (f64, f64) {
    let h = (u.1 - u.0) / (n - 1) as f64;
    let mut worst = (0.0f64, 0.0f64);
    for i in 0..n - 1 {
        let um = u.0 + (i as f64 + 0.5) * h;
        let exact = surface.line(um);
        let got = refined.segment(2 * i + 1).line();
        // atan2 form: accurate for tiny angles (acos bottoms out near 1e-8)
        worst.0 = worst.0.max(got.dir.cross(exact.dir).length().atan2(got.dir.dot(exact.dir).abs()));
        if let Some(s) = surface.striction(um) {
            worst.1 = worst.1.max(got.distance_to(s));
        }
    }
    worst
}

fn main() {
    let cases = [
        ("hyperboloid", AnalyticSurface::ALL[0].clone(), (0.0, 3.0)),
        ("quartic", AnalyticSurface::Quartic, (-1.0, 1.0)),
        ("helical", AnalyticSurface::ALL[3].clone(), (0.0, 6.0)),
    ];
    let w = Scheme::FourPoint { w: 1.0 / 16.0 };
    for (name, surface, u) in cases {
        println!("{name}: max angle / max distance of the exact striction point, four-point w = 1/16");
        let mut last: Option<[(f64, f64); 2]> = None;
        for n in [12usize, 24, 48] {
            let s = surface.sample(n, Ranges { u, v: (-1.0, 1.0), closed: false }).unwrap();
            let ends = errors(&surface, n, u, &subdivide_strip(&s, w, false, 1).unwrap());
            let lines = errors(&surface, n, u, &subdivide_lines(&s, w, false, 1, None).unwrap());
            let order = |a: f64, b: f64| (a / b).log2();
            let orders = last
                .map(|l| {
                    format!(
                        "  orders: endpoints {:.2}/{:.2}, lines {:.2}/{:.2}",
                        order(l[0].0, ends.0),
                        order(l[0].1, ends.1),
                        order(l[1].0, lines.0),
                        order(l[1].1, lines.1)
                    )
                })
                .unwrap_or_default();
            println!(
                "  N = {n:>3}: endpoints {:.2e} / {:.2e}   lines {:.2e} / {:.2e}{orders}",
                ends.0, ends.1, lines.0, lines.1
            );
            last = Some([ends, lines]);
        }
    }
}
