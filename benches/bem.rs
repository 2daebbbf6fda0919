//! Boundary elements on the 256^2 self-affine map at p = 0.01 E*
//! (`examples/data/selfaffine-256.npy`; Tamaas solves the same map in
//! `benches/peers/tamaas_bem.py`), one FFT convolution, and Persson's mean
//! gap on an analytic spectrum.
//!
//! `cargo bench --bench bem -- --warm-up-time 1 --measurement-time 5`

use asperity::bem::{Options, Problem};
use asperity::persson::Persson;
use asperity::spectrum::{Normalisation, Spectrum};
use asperity::surface::npy;
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

fn bem(c: &mut Criterion) {
    let bytes =
        std::fs::read("examples/data/selfaffine-256.npy").expect("run from the repository root");
    let map = npy::parse(&bytes).unwrap();
    let dx = 1e-4 / 256.0;
    let mut g = c.benchmark_group("bem_256");
    g.sample_size(10);
    for tol in [1e-6, 1e-8] {
        let opts = Options {
            tolerance: tol,
            ..Default::default()
        };
        let prob = Problem::new(&map, dx, 1e9, true, &opts).unwrap();
        g.bench_function(format!("load_control_tol_{tol:e}"), |b| {
            b.iter(|| {
                black_box(
                    prob.solve_pressure(1e7, &opts, None)
                        .unwrap()
                        .contact_pixels,
                )
            })
        });
    }
    let opts = Options::default();
    let prob = Problem::new(&map, dx, 1e9, true, &opts).unwrap();
    let adh = Problem::new(&map, dx, 1e9, true, &opts)
        .unwrap()
        .with_adhesion(0.02, 2.0 * dx)
        .unwrap();
    let gap = prob.h_rms();
    g.bench_function("adhesive_gap_control_tol_1e-10", |b| {
        b.iter(|| black_box(adh.solve_gap(gap, &opts, None).unwrap().contact_pixels))
    });
    g.bench_function("problem_setup", |b| {
        b.iter(|| black_box(Problem::new(&map, dx, 1e9, true, &opts).unwrap().h_rms()))
    });
    g.finish();
}

fn persson(c: &mut Criterion) {
    let s = Spectrum::self_affine(0.8, 1e5, 4e5, 4e8, Normalisation::HRms(1e-8)).unwrap();
    let m1 = Persson::new(s.clone(), 1e9, 1.0).unwrap();
    let m2 = Persson::new(s, 1e9, 0.42).unwrap();
    let mut g = c.benchmark_group("persson");
    g.bench_function("mean_gap_gamma_1", |b| {
        b.iter(|| black_box(m1.state(black_box(1e5)).unwrap().mean_gap))
    });
    g.bench_function("mean_gap_gamma_0.42", |b| {
        b.iter(|| black_box(m2.state(black_box(1e5)).unwrap().mean_gap))
    });
    g.finish();
}

criterion_group!(benches, bem, persson);
criterion_main!(benches);
