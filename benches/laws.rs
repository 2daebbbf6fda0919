//! Cost of one law evaluation (criterion): `cargo bench --bench laws`.
use asperity::prelude::*;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;

fn bench_laws(c: &mut Criterion) {
    let contact = AsperityContact::gold_microswitch();
    let mut group = c.benchmark_group("law_state");
    for kind in LawKind::ALL {
        let law = kind.build(&contact).unwrap();
        let d0 = law.detach_interference().max(-1e-9);
        // 64 interferences spread over the attached branch, cycled.
        let deltas: Vec<f64> = (0..64).map(|i| d0 + 1e-9 * i as f64 / 16.0).collect();
        for branch in [Branch::Approach, Branch::Retract] {
            group.bench_with_input(
                BenchmarkId::new(kind.name(), format!("{branch:?}")),
                &deltas,
                |b, ds| {
                    let mut i = 0usize;
                    b.iter(|| {
                        i = (i + 1) & 63;
                        black_box(law.state(black_box(ds[i]), branch))
                    })
                },
            );
        }
    }
    group.finish();
}

/// Maugis–Dugdale across lambda: 64 interferences over the stable branch,
/// from the jump-out to 20 interference scales (non-contact, fold, deep).
fn bench_maugis_lambda(c: &mut Criterion) {
    let mut group = c.benchmark_group("maugis_state");
    for lambda in [1e-3, 0.3, 1.0, 10.0, 1e3] {
        let law = asperity::law::Maugis::new(1e-6, 5e10, 0.5, lambda).unwrap();
        let s = law.scales().interference;
        let d0 = law.detach_interference();
        let deltas: Vec<f64> = (0..64)
            .map(|i| d0 + (20.0 * s - d0) * (i as f64 / 63.0).powi(2))
            .collect();
        group.bench_with_input(BenchmarkId::from_parameter(lambda), &deltas, |b, ds| {
            let mut i = 0usize;
            b.iter(|| {
                i = (i + 1) & 63;
                black_box(law.state(black_box(ds[i]), Branch::Retract))
            })
        });
    }
    group.bench_function("build_lambda_1", |b| {
        b.iter(|| black_box(asperity::law::MaugisCurve::new(black_box(1.0)).unwrap()))
    });
    group.finish();
}

criterion_group!(benches, bench_laws, bench_maugis_lambda);
criterion_main!(benches);
