//! Cost of one closed-form Gaussian `F_n(h)` value (criterion), at h in the
//! bulk, the Chebyshev region, the asymptotic tail and below zero:
//! `cargo bench --bench heights -- --warm-up-time 1 --measurement-time 3`.
use asperity::heights::{Exponential, Gaussian, HeightDistribution};
use asperity::special::normal;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;

fn bench_gaussian_fn(c: &mut Criterion) {
    let g = Gaussian::new();
    let mut group = c.benchmark_group("gaussian_fn");
    for n in [0.0, 0.5, 1.0, 1.5, 2.0, 2.5] {
        for h in [-7.0, -12.0, 0.3, 3.7, 11.5, 15.0, 36.0] {
            group.bench_with_input(
                BenchmarkId::new(format!("n={n}"), format!("h={h}")),
                &h,
                |b, &h| b.iter(|| black_box(g.moment_above(black_box(n), black_box(h)))),
            );
        }
    }
    group.finish();
    let mut group = c.benchmark_group("normal");
    for h in [-3.0, 0.3, 5.0, 20.0] {
        group.bench_with_input(BenchmarkId::new("tail", format!("h={h}")), &h, |b, &h| {
            b.iter(|| black_box(normal::tail(black_box(h))))
        });
    }
    group.bench_function("quantile p=1e-200", |b| {
        b.iter(|| black_box(normal::quantile(black_box(1e-200))))
    });
    group.finish();
    let e = Exponential::new();
    let mut group = c.benchmark_group("exponential_fn");
    for (n, h) in [(1.5, 2.0), (1.5, -2.0), (2.5, -2.0)] {
        group.bench_with_input(
            BenchmarkId::new(format!("n={n}"), format!("h={h}")),
            &h,
            |b, &h| b.iter(|| black_box(e.moment_above(black_box(n), black_box(h)))),
        );
    }
    group.finish();
}

criterion_group!(benches, bench_gaussian_fn);
criterion_main!(benches);
