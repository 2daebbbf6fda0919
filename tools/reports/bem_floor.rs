//! The cost of one boundary-element iteration against its FFT floor, and a
//! whole non-adhesive solve, on a synthetic self-affine `N x N` periodic map
//! (H = 0.8, wavevectors 4 to N/4 x 2 pi/L, RMS gradient 0.1, L = 100 um,
//! E* = 1 GPa, seed 1).
//!
//! `RAYON_NUM_THREADS=1 cargo run --release --example bem_floor -- floor N REPS`
//! prints the median CPU and wall time (s) over REPS of:
//! - `rows`: a forward and an inverse `realfft` of every row (N transforms of
//!   length N on contiguous rows, the input copied once per row as the 2-D
//!   transform does);
//! - `lines`: the same plus the N/2 + 1 complex column transforms of length N,
//!   run on contiguous lines (the 2-D transform's own 1-D transforms with no
//!   transpose: its flop count at contiguous speed);
//! - `conv`: one convolution `HalfSpace::displacement` (a forward and an inverse
//!   2-D real transform, the kernel product, the copies);
//! - `iter`: one Polonsky–Keer iteration (two convolutions and the element
//!   passes), from solves stopped at 10 and 20 iterations (the difference / 10).
//!
//! `... -- solve N` solves at p = 0.01 E* g once and prints iterations, CPU
//! and wall time (peak memory: run it under `/usr/bin/time -v`).
use asperity::bem::operator::HalfSpace;
use asperity::bem::{Options, Problem};
use asperity::spectrum::synthesis::random_phase_map;
use asperity::spectrum::{Normalisation, Spectrum};
use asperity::surface::HeightMap;
use realfft::num_complex::Complex;
use realfft::RealFftPlanner;
use rustfft::FftPlanner;
use std::f64::consts::PI;
use std::time::Instant;

/// CPU time (s) of every thread of the process, from the nanosecond
/// counters of `/proc/self/task/*/schedstat`.
fn cpu_s() -> f64 {
    asperity::study::cpu_time::process_cpu_seconds().unwrap_or(f64::NAN)
}

/// Median (CPU, wall) seconds of `reps` calls of `f`.
fn median<F: FnMut()>(reps: usize, mut f: F) -> (f64, f64) {
    let (mut c, mut w) = (Vec::new(), Vec::new());
    for _ in 0..reps {
        let (c0, w0) = (cpu_s(), Instant::now());
        f();
        c.push(cpu_s() - c0);
        w.push(w0.elapsed().as_secs_f64());
    }
    c.sort_by(f64::total_cmp);
    w.sort_by(f64::total_cmp);
    (c[reps / 2], w[reps / 2])
}

const L: f64 = 1e-4;
const ESTAR: f64 = 1e9;

fn map(n: usize) -> HeightMap {
    let q0 = 2.0 * PI / L;
    let s = Spectrum::self_affine(
        0.8,
        4.0 * q0,
        4.0 * q0,
        (n / 4) as f64 * q0,
        Normalisation::SlopeRms(0.1),
    )
    .unwrap();
    random_phase_map(&s, n, n, L / n as f64, 1).unwrap()
}

fn floor(n: usize, reps: usize) {
    let mut rp = RealFftPlanner::<f64>::new();
    let (r2c, c2r) = (rp.plan_fft_forward(n), rp.plan_fft_inverse(n));
    let mut cp = FftPlanner::<f64>::new();
    let (cf, ci) = (cp.plan_fft_forward(n), cp.plan_fft_inverse(n));
    let nh = n / 2 + 1;
    let x: Vec<f64> = (0..n * n).map(|k| ((k * 7919) % 97) as f64).collect();
    let mut y = vec![0.0; n * n];
    let mut spec = vec![Complex::new(0.0, 0.0); n * nh];
    let mut inp = r2c.make_input_vec();
    let mut rs = r2c.make_scratch_vec();
    let mut is = c2r.make_scratch_vec();
    let mut cs = vec![Complex::new(0.0, 0.0); cf.get_inplace_scratch_len()];
    let mut rows = |spec: &mut [Complex<f64>], y: &mut [f64], fwd: bool| {
        for ((xr, yr), s) in x.chunks(n).zip(y.chunks_mut(n)).zip(spec.chunks_mut(nh)) {
            if fwd {
                inp.copy_from_slice(xr);
                r2c.process_with_scratch(&mut inp, s, &mut rs).unwrap();
            } else {
                c2r.process_with_scratch(s, yr, &mut is).unwrap();
            }
        }
    };
    let (c, w) = median(reps, || {
        rows(&mut spec, &mut y, true);
        spec.iter_mut().for_each(|v| v.im = 0.0);
        rows(&mut spec, &mut y, false);
    });
    println!("{n} rows  cpu {c:.4} wall {w:.4}");
    let (c, w) = median(reps, || {
        rows(&mut spec, &mut y, true);
        // Each of the nh columns as a contiguous line of length n (the
        // spectrum holds n nh values: nh lines of n).
        cf.process_with_scratch(&mut spec, &mut cs);
        ci.process_with_scratch(&mut spec, &mut cs);
        spec.iter_mut().for_each(|v| v.im = 0.0);
        rows(&mut spec, &mut y, false);
    });
    println!("{n} lines cpu {c:.4} wall {w:.4}");
    let hs = HalfSpace::new(n, n, L / n as f64, ESTAR, true);
    let (c, w) = median(reps, || hs.displacement(&x, &mut y));
    println!("{n} conv  cpu {c:.4} wall {w:.4}");
    let m = map(n);
    let opts = |k| Options {
        tolerance: 1e-300,
        max_iterations: k,
        allow_unconverged: true,
        memory_limit: usize::MAX,
    };
    let prob = Problem::new(&m, L / n as f64, ESTAR, true, &opts(1)).unwrap();
    let p = 0.01 * ESTAR * prob.roughness().slope_rms;
    let (c10, w10) = median(reps, || {
        prob.solve_pressure(p, &opts(10), None).unwrap();
    });
    let (c20, w20) = median(reps, || {
        prob.solve_pressure(p, &opts(20), None).unwrap();
    });
    println!(
        "{n} iter  cpu {:.4} wall {:.4}",
        (c20 - c10) / 10.0,
        (w20 - w10) / 10.0
    );
}

fn solve(n: usize) {
    let (c0, w0) = (cpu_s(), Instant::now());
    let m = map(n);
    let opts = Options {
        tolerance: 1e-8,
        memory_limit: usize::MAX,
        ..Default::default()
    };
    let prob = Problem::new(&m, L / n as f64, ESTAR, true, &opts).unwrap();
    drop(m);
    let g = prob.roughness().slope_rms;
    let (c1, w1) = (cpu_s(), Instant::now());
    let s = prob.solve_pressure(0.01 * ESTAR * g, &opts, None).unwrap();
    println!(
        "{n}^2 p = 0.01 E* g (g = {g:.4}): A/A0 {:.6} mean gap {:.6e} m, {} iterations, \
         residual {:.2e}; solve CPU {:.2} s wall {:.2} s; setup CPU {:.2} s wall {:.2} s",
        s.area_fraction(),
        s.mean_gap,
        s.iterations,
        s.residual,
        cpu_s() - c1,
        w1.elapsed().as_secs_f64(),
        c1 - c0,
        (w1 - w0).as_secs_f64()
    );
}

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let n: usize = a.get(2).map_or(1024, |s| s.parse().unwrap());
    match a.get(1).map(String::as_str) {
        Some("solve") => solve(n),
        _ => floor(n, a.get(3).map_or(5, |s| s.parse().unwrap())),
    }
}
