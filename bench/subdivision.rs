//! Criterion benchmark: one subdivision step of a ruled strip of 10³ … 10⁶ rulings for each
//! scheme (native). `cargo bench --bench subdivision`; the wasm counterpart is `bench/wasm.mjs`.
#![allow(missing_docs)]
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use ruledlab::{subdivide_strip, Scheme, Variant};
use ruledlab::{AnalyticSurface, Ranges, SmoothRuled};
use std::hint::black_box;

mod sizes;
use sizes::sizes;

fn schemes(c: &mut Criterion) {
    let hyp = AnalyticSurface::ALL[0].clone();
    let schemes = [
        ("chaikin", Scheme::Chaikin),
        ("bspline3", Scheme::BSpline { degree: 3 }),
        ("four-point", Scheme::FourPoint { w: 1.0 / 16.0 }),
        ("variational", Scheme::Variational { n: 12, variant: Variant::Coupled }),
        ("bezier", Scheme::Bezier),
    ];
    for (name, scheme) in schemes {
        let mut group = c.benchmark_group(format!("subdivide/{name}"));
        group.sample_size(10);
        let all: &[usize] = if scheme == Scheme::Bezier { &[1_000] } else { &[1_000, 10_000, 100_000, 1_000_000] };
        for &n in sizes(all) {
            let s = hyp.sample(n, Ranges { u: (0.0, 100.0), v: (-1.0, 1.0), closed: false }).expect("valid sample");
            group.throughput(Throughput::Elements(n as u64));
            group.bench_with_input(BenchmarkId::from_parameter(n), &s, |b, s| {
                b.iter(|| black_box(subdivide_strip(s, scheme, false, 1).expect("subdivides")))
            });
        }
        group.finish();
    }
}

criterion_group!(benches, schemes);
criterion_main!(benches);
