//! CPU seconds of `asperity fn` on many points, in-process (the reference
//! of `python/benchmarks/bench_fn.py`, which times `asperity.fn` from
//! Python on the same points):
//! `cargo run --release --example fn_time [points] [dist] [n] [repeats]`
//! (defaults 1e6 points of h evenly from -3 to 8, gaussian, n = 1.5, 7
//! repeats). Prints one JSON line with the best CPU time of the repeats
//! (process CPU time from `/proc/self/stat`, so other processes' load does
//! not count; the call is `asperity::commands::fn_::values`, what the
//! Python function calls).
use asperity::commands::fn_;
use std::hint::black_box;

/// utime + stime of this process (s), from /proc/self/stat.
fn cpu_seconds() -> f64 {
    asperity::study::cpu_time::process_cpu_seconds().unwrap_or(f64::NAN)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let points: usize = args
        .get(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1_000_000);
    let dist = fn_::dist_named(args.get(2).map_or("gaussian", String::as_str))
        .expect("gaussian or exponential");
    let n: f64 = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(1.5);
    let repeats: usize = args.get(4).and_then(|s| s.parse().ok()).unwrap_or(7);
    let h: Vec<f64> = (0..points)
        .map(|i| -3.0 + 11.0 * i as f64 / (points.max(2) - 1) as f64)
        .collect();
    let mut best = f64::INFINITY;
    for _ in 0..repeats {
        let t0 = cpu_seconds();
        let wall = std::time::Instant::now();
        let v = fn_::values(dist, n, black_box(&h)).expect("valid arguments");
        black_box(&v);
        let cpu = cpu_seconds() - t0;
        // /proc ticks are 10 ms: below ~0.2 s use the wall clock as well.
        let t = if cpu < 0.2 {
            wall.elapsed().as_secs_f64()
        } else {
            cpu
        };
        best = best.min(t);
    }
    println!(
        "{{\"points\": {points}, \"dist\": \"{}\", \"n\": {n}, \"seconds\": {best:e}, \"ns_per_point\": {:.3}}}",
        asperity::named::Named::name(dist),
        best / points as f64 * 1e9
    );
}
