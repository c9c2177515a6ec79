#![allow(missing_docs)]
//! Criterion benchmark of Section 2's invariants for 10³ … 10⁶ rulings (native).
//! `cargo bench --bench invariants`; the wasm counterpart is `bench/wasm.mjs`.
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use ruledlab::examples::AnalyticSurface;
use std::hint::black_box;

fn invariants(c: &mut Criterion) {
    let mut group = c.benchmark_group("invariants");
    group.sample_size(10);
    for n in [1_000usize, 10_000, 100_000, 1_000_000] {
        let hyp = AnalyticSurface::ALL[0];
        let surface = hyp.sample(n, hyp.ranges()).expect("valid sample");
        group.throughput(Throughput::Elements(n as u64));
        group.bench_with_input(BenchmarkId::from_parameter(n), &surface, |b, s| {
            b.iter(|| black_box(s.invariants()))
        });
    }
    group.finish();
}

fn from_flat(c: &mut Criterion) {
    let mut group = c.benchmark_group("validate");
    group.sample_size(10);
    let hyp = AnalyticSurface::ALL[0];
    let flat = hyp.sample(1_000_000, hyp.ranges()).expect("valid sample").flat().to_vec();
    group.throughput(Throughput::Elements(1_000_000));
    group.bench_function("from_flat/1000000", |b| {
        b.iter(|| black_box(ruledlab::RuledSurface::from_flat(&flat).expect("valid")))
    });
    group.finish();
}

criterion_group!(benches, invariants, from_flat);
criterion_main!(benches);
