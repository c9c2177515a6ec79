//! Criterion benchmark of Section 5: one butterfly step on 100² … 1000² grids of lines and
//! the coupled variational solve on growing grids (native). `cargo bench --bench congruence`
#![allow(missing_docs)]
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use ruledlab::{subdivide_congruence, CongruenceScheme};
use ruledlab::{AnalyticCongruence, SmoothCongruence};
use std::hint::black_box;

mod sizes;
use sizes::sizes;

fn congruence(c: &mut Criterion) {
    let ex = AnalyticCongruence::Example5;
    let mut group = c.benchmark_group("butterfly");
    group.sample_size(10);
    for &n in sizes(&[100usize, 300, 1000]) {
        let grid = ex.grid(n, n).expect("valid grid");
        group.throughput(Throughput::Elements((n * n) as u64));
        group.bench_with_input(BenchmarkId::from_parameter(n), &grid, |b, g| {
            b.iter(|| {
                black_box(subdivide_congruence(g, CongruenceScheme::Butterfly { w: 1.0 / 16.0 }, 1).expect("refines"))
            })
        });
    }
    group.finish();
    let mut group = c.benchmark_group("coupled");
    group.sample_size(10);
    for &n in sizes(&[33usize, 65, 129, 257]) {
        let grid = ex.grid(n, n).expect("valid grid");
        group.throughput(Throughput::Elements((n * n) as u64));
        group.bench_with_input(BenchmarkId::from_parameter(n), &grid, |b, g| {
            b.iter(|| black_box(subdivide_congruence(g, CongruenceScheme::Coupled { k: 6 }, 1).expect("refines")))
        });
    }
    group.finish();
}

criterion_group!(benches, congruence);
criterion_main!(benches);
