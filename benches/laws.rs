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

criterion_group!(benches, bench_laws);
criterion_main!(benches);
