//! One operation of the benchmarks, repeated, for counting instructions with valgrind (the
//! robust measure on a shared machine; `scripts/count.sh` runs it and prints instructions per
//! ruling): `cargo run --release --example count -- <operation> <rulings> <repeats>`.
//! Operations: invariants (the f64x2 kernel, into reused arrays), invariants-fresh (into new
//! arrays), invariants-scalar (the scalar path, `Invariants::compute_from`), four-point, chaikin,
//! bspline3 (one strip step). bench/wasm.mjs runs it beside each wasm measurement.
//! It prints the median time of one repeat (ms), for a quick look; criterion (`cargo bench`) is
//! the measurement.
use ruledlab::{subdivide_strip, AnalyticSurface, Invariants, Ranges, Scheme, SmoothRuled};
use std::hint::black_box;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (op, n, reps) = match &args[1..] {
        [op, n, reps] => (op.as_str(), n.parse().expect("rulings"), reps.parse().expect("repeats")),
        _ => panic!("usage: count <operation> <rulings> <repeats>"),
    };
    let hyp = AnalyticSurface::by_name("hyperboloid").expect("in the catalogue");
    let s = hyp.sample(n, Ranges { u: (0.0, 100.0), v: (-1.0, 1.0), closed: false }).expect("valid");
    let mut out = Invariants::default();
    let mut times = Vec::new();
    for _ in 0..reps {
        let t0 = std::time::Instant::now();
        match op {
            "invariants" => s.invariants_into(&mut out, false),
            "invariants-fresh" => drop(black_box(s.invariants())),
            "invariants-scalar" => out.compute_from(s.lines()),
            "four-point" => drop(black_box(subdivide_strip(&s, Scheme::FourPoint { w: 1.0 / 16.0 }, false, 1))),
            "chaikin" => drop(black_box(subdivide_strip(&s, Scheme::Chaikin, false, 1))),
            "bspline3" => drop(black_box(subdivide_strip(&s, Scheme::BSpline { degree: 3 }, false, 1))),
            _ => panic!("unknown operation {op}"),
        }
        black_box(&out);
        times.push(t0.elapsed().as_secs_f64() * 1e3);
    }
    times.sort_by(f64::total_cmp);
    if let Some(median) = times.get(times.len() / 2) {
        eprintln!("{op}, {n} rulings: {median:.4} ms (median of {reps})");
    }
}
