//! Cost of one shaped-asperity law evaluation (criterion), against today's
//! JKR: `cargo bench --bench shaped -- --warm-up-time 1 --measurement-time 3`.
use asperity::axisym::{AxisymMd, Profile};
use asperity::law::shaped::{ShapedExact, ShapedMd, ShapedMdExact};
use asperity::law::{AsperityLaw, Branch, Jkr, Shaped};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;

/// A rounded cone `sqrt(r^2 + rho^2) - rho` (rho = 50 nm), 41 nodes to 500 nm.
fn table() -> Profile {
    let rho: f64 = 5e-8;
    let r: Vec<f64> = (0..41).map(|i| i as f64 * 10.0 * rho / 40.0).collect();
    let f = r.iter().map(|x| (x * x + rho * rho).sqrt() - rho).collect();
    Profile::tabulated(r, f).unwrap()
}

fn laws() -> Vec<(&'static str, Box<dyn AsperityLaw>)> {
    let (e, w) = (1e9, 0.05);
    vec![
        ("jkr (today)", Box::new(Jkr::new(1e-6, e, w).unwrap())),
        (
            "paraboloid",
            Box::new(Shaped::new(Profile::paraboloid(1e-6).unwrap(), e, w).unwrap()),
        ),
        (
            "sphere",
            Box::new(Shaped::new(Profile::sphere(1e-6).unwrap(), e, w).unwrap()),
        ),
        (
            "cone",
            Box::new(Shaped::new(Profile::cone(0.2).unwrap(), e, w).unwrap()),
        ),
        (
            "flat",
            Box::new(Shaped::new(Profile::flat(1e-6).unwrap(), e, w).unwrap()),
        ),
        (
            "power_1.5",
            Box::new(Shaped::new(Profile::power(316.0, 1.5).unwrap(), e, w).unwrap()),
        ),
        (
            "tabulated",
            Box::new(Shaped::new(table(), 1e8, 1.0).unwrap()),
        ),
        (
            "md_paraboloid_lambda_1",
            Box::new(
                ShapedMd::new(
                    Profile::paraboloid(1e-6).unwrap(),
                    e,
                    w,
                    AxisymMd::stress_from_lambda(1.0, 1e-6, e, w),
                )
                .unwrap(),
            ),
        ),
        (
            "md_cone",
            Box::new(ShapedMd::new(Profile::cone(0.2).unwrap(), e, w, 3.0 * e * 0.2).unwrap()),
        ),
        (
            "md_cone_exact_untabulated",
            Box::new(ShapedMdExact::new(Profile::cone(0.2).unwrap(), e, w, 3.0 * e * 0.2).unwrap()),
        ),
        (
            "cone_exact_untabulated",
            Box::new(ShapedExact::new(Profile::cone(0.2).unwrap(), e, w).unwrap()),
        ),
    ]
}

fn bench_shaped(c: &mut Criterion) {
    let mut group = c.benchmark_group("shaped_state");
    for (name, law) in laws() {
        let d0 = law.detach_interference();
        // 64 interferences from the jump-out to 20 times its depth, cycled.
        let deltas: Vec<f64> = (0..64)
            .map(|i| d0 + 21.0 * d0.abs() * (i as f64 / 63.0).powi(2))
            .collect();
        group.bench_with_input(BenchmarkId::from_parameter(name), &deltas, |b, ds| {
            let mut i = 0usize;
            b.iter(|| {
                i = (i + 1) & 63;
                black_box(law.state(black_box(ds[i]), Branch::Retract))
            })
        });
    }
    group.finish();
}

fn bench_build(c: &mut Criterion) {
    let mut group = c.benchmark_group("shaped_build");
    group.sample_size(10);
    group.bench_function("cone", |b| {
        b.iter(|| black_box(Shaped::new(Profile::cone(0.2).unwrap(), 1e9, 0.05).unwrap()))
    });
    group.bench_function("md_cone", |b| {
        b.iter(|| black_box(ShapedMd::new(Profile::cone(0.2).unwrap(), 1e9, 0.05, 6e8).unwrap()))
    });
    group.finish();
}

criterion_group!(benches, bench_shaped, bench_build);
criterion_main!(benches);
