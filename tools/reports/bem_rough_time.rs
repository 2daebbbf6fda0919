//! CPU time of the 256^2 self-affine solve at p = 0.01 E* (the map of
//! `examples/data/selfaffine-256.npy`), solve only (as Tamaas' timing), one
//! thread: `RAYON_NUM_THREADS=1 cargo run --release --example bem_rough_time -- 20 1e-8`.
use asperity::bem::{Options, Problem};
use asperity::surface::npy;

fn cpu_s() -> f64 {
    let s = std::fs::read_to_string("/proc/self/stat").unwrap_or_default();
    let f: Vec<&str> = s
        .rsplit(')')
        .next()
        .unwrap_or("")
        .split_whitespace()
        .collect();
    let t = |i: usize| {
        f.get(i)
            .and_then(|v| v.parse::<f64>().ok())
            .unwrap_or(f64::NAN)
    };
    (t(11) + t(12)) / 100.0
}

fn main() {
    let map = npy::parse(&std::fs::read("examples/data/selfaffine-256.npy").unwrap()).unwrap();
    let dx = 1e-4 / 256.0;
    let reps: usize = std::env::args().nth(1).map_or(10, |s| s.parse().unwrap());
    let tol: f64 = std::env::args().nth(2).map_or(1e-8, |s| s.parse().unwrap());
    let opts = Options {
        tolerance: tol,
        ..Default::default()
    };
    let prob = Problem::new(&map, dx, 1e9, true, &opts).unwrap();
    let t = cpu_s();
    let mut last = None;
    for _ in 0..reps {
        last = Some(prob.solve_pressure(1e7, &opts, None).unwrap());
    }
    let cpu = (cpu_s() - t) / reps as f64;
    let s = last.expect("reps >= 1");
    println!(
        "tol {tol:e}: A/A0 {:.10} mean gap {:.12e} m, {} iterations, {cpu:.4} s CPU per solve",
        s.area_fraction(),
        s.mean_gap,
        s.iterations
    );
}
