//! Greenwood–Williamson curves and the Maugis–Dugdale pull-off,
//! criterion: `cargo bench --bench gw -- --warm-up-time 1 --measurement-time 3`.
//!
//! - `gw_md_curve/1000+1000_rtol_1e-6`: the planner's Maugis–Dugdale curve
//!   (gold microswitch, `lambda = 1`): Chebyshev table of the exact law to
//!   1e-7 built inside the iteration, then 1000 approach + 1000 retraction
//!   states (load) from `6 sigma` to `0` by adaptive quadrature at rtol
//!   1e-6, states in parallel on the global rayon pool (both cores).
//!   Goal: <= 10 ms on 2 cores. `.../1_thread`: the same on one thread.
//! - `maugis_pull_off/only/LAMBDA`: `MaugisCurve::pull_off_only` (sparse
//!   scan, no table); `maugis_pull_off/full_curve/LAMBDA`:
//!   `MaugisCurve::new(lambda).pull_off_bar()` for comparison. Goal: <= 3 us.
use asperity::gw::{Accuracy, GwModel, RoughSurface};
use asperity::heights::Gaussian;
use asperity::law::interpolated::InterpolatedLaw;
use asperity::law::{AsperityLaw, Maugis, MaugisCurve};
use asperity::loading::{LoadingModel, LoadingProgram, Observables};
use asperity::material::{contact_modulus, Material};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;
use std::sync::Arc;

fn md_curve(c: &mut Criterion) {
    let mut group = c.benchmark_group("gw_md_curve");
    group.sample_size(20);
    let s = RoughSurface::gold_microswitch();
    let g = Material::gold();
    let exact: Arc<dyn AsperityLaw> =
        Arc::new(Maugis::new(s.radius, contact_modulus(&g, &g), 0.5, 1.0).unwrap());
    let program = LoadingProgram::new(6.0 * s.sigma, 0.0, 1000).unwrap();
    let acc = Accuracy::new(1e-6).unwrap();
    let run = || {
        let table = InterpolatedLaw::new(
            exact.clone(),
            exact.cutoff_interference(),
            40.0 * s.sigma,
            1e-7,
        )
        .unwrap();
        GwModel::new(s, Arc::new(Gaussian::new()), Arc::new(table))
            .unwrap()
            .with_accuracy(acc)
            .curve(&program, &Observables::LOAD)
            .unwrap()
    };
    group.bench_function("1000+1000_rtol_1e-6", |b| b.iter(|| black_box(run())));
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    group.bench_function("1000+1000_rtol_1e-6/1_thread", |b| {
        b.iter(|| one.install(|| black_box(run())))
    });
    group.finish();
}

fn md_pull_off(c: &mut Criterion) {
    let mut group = c.benchmark_group("maugis_pull_off");
    for lambda in [0.1, 1.0, 10.0] {
        group.bench_with_input(BenchmarkId::new("only", lambda), &lambda, |b, &l| {
            b.iter(|| black_box(MaugisCurve::pull_off_only(black_box(l)).unwrap()))
        });
        group.bench_with_input(BenchmarkId::new("full_curve", lambda), &lambda, |b, &l| {
            b.iter(|| black_box(MaugisCurve::new(black_box(l)).unwrap().pull_off_bar()))
        });
    }
    group.finish();
}

criterion_group!(benches, md_curve, md_pull_off);
criterion_main!(benches);
