#![allow(missing_docs)]
//! Criterion benchmark of Section 2's invariants for 10³ … 10⁶ rulings (native).
//! `cargo bench --bench invariants`; the wasm counterpart is `bench/wasm.mjs`.
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use ruledlab::{AnalyticSurface, SmoothRuled};
use std::hint::black_box;

mod sizes;
use sizes::sizes;

/// n rulings of Example 1's hyperboloid.
fn hyperboloid(n: usize) -> ruledlab::RuledSurface {
    let hyp = AnalyticSurface::ALL[0].clone();
    hyp.sample(n, hyp.ranges()).expect("valid sample")
}

fn invariants(c: &mut Criterion) {
    let mut group = c.benchmark_group("invariants");
    group.sample_size(10);
    for &n in sizes(&[1_000usize, 10_000, 100_000, 1_000_000]) {
        let surface = hyperboloid(n);
        group.throughput(Throughput::Elements(n as u64));
        group.bench_with_input(BenchmarkId::from_parameter(n), &surface, |b, s| b.iter(|| black_box(s.invariants())));
    }
    group.finish();
}

/// Into arrays that are reused, as the wasm API's `invariantsInPlace` does (no fresh memory).
fn invariants_into(c: &mut Criterion) {
    let mut group = c.benchmark_group("invariants_into");
    group.sample_size(10);
    for &n in sizes(&[1_000usize, 10_000, 100_000, 1_000_000]) {
        let surface = hyperboloid(n);
        let mut out = surface.invariants();
        group.throughput(Throughput::Elements(n as u64));
        group.bench_function(BenchmarkId::from_parameter(n), |b| {
            b.iter(|| {
                surface.invariants_into(&mut out, false);
                black_box(out.angle.len())
            })
        });
    }
    group.finish();
}

fn from_flat(c: &mut Criterion) {
    let mut group = c.benchmark_group("validate");
    group.sample_size(10);
    let n = *sizes(&[1_000usize, 1_000_000]).last().expect("a size");
    let flat = hyperboloid(n).flat().to_vec();
    group.throughput(Throughput::Elements(n as u64));
    group.bench_function(format!("from_flat/{n}"), |b| {
        b.iter(|| black_box(ruledlab::RuledSurface::from_flat(&flat).expect("valid")))
    });
    group.finish();
}

criterion_group!(benches, invariants, invariants_into, from_flat);
criterion_main!(benches);
