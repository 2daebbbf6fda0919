//! Boundary elements on the 256^2 self-affine map at p = 0.01 E*
//! (`examples/data/selfaffine-256.npy`; Tamaas solves the same map in
//! `benches/peers/tamaas_bem.py`), one FFT convolution, and Persson's mean
//! gap on an analytic spectrum.
//!
//! `bem_floor`: at 1024^2 and 4096^2 on a synthetic self-affine map, the
//! floor (a forward and an inverse `realfft` of every row, contiguous rows,
//! the same process), one convolution of the half-space
//! (`HalfSpace::displacement`) and solves capped at 10 and 20 iterations
//! (their difference / 10 is one iteration).
//!
//! `cargo bench --bench bem -- --warm-up-time 1 --measurement-time 5`

use asperity::bem::operator::HalfSpace;
use asperity::bem::{Options, Problem};
use asperity::persson::Persson;
use asperity::spectrum::synthesis::random_phase_map;
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

fn floor(c: &mut Criterion) {
    use realfft::RealFftPlanner;
    let mut g = c.benchmark_group("bem_floor");
    g.sample_size(10);
    for n in [1024, 4096] {
        let mut rp = RealFftPlanner::<f64>::new();
        let (r2c, c2r) = (rp.plan_fft_forward(n), rp.plan_fft_inverse(n));
        let x: Vec<f64> = (0..n * n).map(|k| ((k * 7919) % 97) as f64).collect();
        let mut y = vec![0.0; n * n];
        let mut spec = vec![realfft::num_complex::Complex::new(0.0, 0.0); n * (n / 2 + 1)];
        let (mut inp, mut rs, mut is) = (
            r2c.make_input_vec(),
            r2c.make_scratch_vec(),
            c2r.make_scratch_vec(),
        );
        g.bench_function(format!("realfft_rows_forward_inverse_{n}"), |b| {
            b.iter(|| {
                for (xr, s) in x.chunks(n).zip(spec.chunks_mut(n / 2 + 1)) {
                    inp.copy_from_slice(xr);
                    r2c.process_with_scratch(&mut inp, s, &mut rs).unwrap();
                }
                for (yr, s) in y.chunks_mut(n).zip(spec.chunks_mut(n / 2 + 1)) {
                    s[0].im = 0.0;
                    s[n / 2].im = 0.0;
                    c2r.process_with_scratch(s, yr, &mut is).unwrap();
                }
                black_box(y[1])
            })
        });
        let dx = 1e-4 / n as f64;
        let hs = HalfSpace::new(n, n, dx, 1e9, true);
        g.bench_function(format!("convolution_{n}"), |b| {
            b.iter(|| {
                hs.displacement(&x, &mut y);
                black_box(y[1])
            })
        });
        let q0 = 2.0 * std::f64::consts::PI / 1e-4;
        let spectrum = Spectrum::self_affine(
            0.8,
            4.0 * q0,
            4.0 * q0,
            (n / 4) as f64 * q0,
            Normalisation::SlopeRms(0.1),
        )
        .unwrap();
        let map = random_phase_map(&spectrum, n, n, dx, 1).unwrap();
        let opts = |k| Options {
            tolerance: 1e-300,
            max_iterations: k,
            allow_unconverged: true,
            memory_limit: usize::MAX,
        };
        let prob = Problem::new(&map, dx, 1e9, true, &opts(1)).unwrap();
        for k in [10, 20] {
            g.bench_function(format!("solve_{k}_iterations_{n}"), |b| {
                b.iter(|| black_box(prob.solve_pressure(1e6, &opts(k), None).unwrap().residual))
            });
        }
    }
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

criterion_group!(benches, bem, floor, persson);
criterion_main!(benches);
