//! CPU time of a non-adhesive solve at p = 0.01 E* (E* = 1 GPa) on a
//! periodic map, solve only (as Tamaas' timing in
//! `benches/peers/tamaas_bem.py`), run with `RAYON_NUM_THREADS=1` for one
//! thread:
//! `cargo run --release --example bem_rough_time -- REPS TOL [MAP.npy] [L]`
//! (default map `examples/data/selfaffine-256.npy`, side `L` = 100 um).
//! Prints one JSON line: the answer (area fraction, mean gap, iterations)
//! and the CPU time of every solve (all threads, `/proc/self/stat`, in
//! 10 ms ticks) with their median and their mean (the whole loop's CPU
//! over the solves: finer than one solve's ticks).
use asperity::bem::{Options, Problem};
use asperity::surface::npy;

fn cpu_s() -> f64 {
    asperity::study::cpu_time::process_cpu_seconds().unwrap_or(f64::NAN)
}

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let reps: usize = a.get(1).map_or(10, |s| s.parse().unwrap());
    let tol: f64 = a.get(2).map_or(1e-8, |s| s.parse().unwrap());
    let path = a
        .get(3)
        .map_or("examples/data/selfaffine-256.npy", String::as_str);
    let side: f64 = a.get(4).map_or(1e-4, |s| s.parse().unwrap());
    let map = npy::parse(&std::fs::read(path).unwrap()).unwrap();
    let dx = side / map.cols() as f64;
    let opts = Options {
        tolerance: tol,
        memory_limit: usize::MAX,
        ..Default::default()
    };
    let prob = Problem::new(&map, dx, 1e9, true, &opts).unwrap();
    let mut cpu = Vec::new();
    let mut last = None;
    let t0 = cpu_s();
    for _ in 0..reps.max(1) {
        let t = cpu_s();
        last = Some(prob.solve_pressure(1e7, &opts, None).unwrap());
        cpu.push(cpu_s() - t);
    }
    // The counter ticks every 10 ms: the mean over all solves resolves a
    // short solve better than any one of them.
    let mean = (cpu_s() - t0) / reps.max(1) as f64;
    let s = last.expect("reps >= 1");
    let mut sorted = cpu.clone();
    sorted.sort_by(f64::total_cmp);
    println!(
        "{{\"map\": \"{path}\", \"rows\": {}, \"tolerance\": {tol:e}, \"area_fraction\": {:.17e}, \
         \"mean_gap_m\": {:.17e}, \"iterations\": {}, \"cpu_s_median\": {:.6}, \"cpu_s_mean\": {:.6}, \"cpu_s\": {:?}}}",
        map.rows(),
        s.area_fraction(),
        s.mean_gap,
        s.iterations,
        sorted[sorted.len() / 2],
        mean,
        cpu
    );
}
