//! CPU nanoseconds per pixel of `Topography::characterise` on a rayon pool
//! of `RAYON_NUM_THREADS` threads (set it to 1 for the one-core figure):
//! `RAYON_NUM_THREADS=1 cargo run --release --example surface_ns_per_pixel [repeats] [side] [npy-out]`
//! (defaults: 10 repeats, a 4096 x 4096 map).
//!
//! The map is the bench's (`benches/surface.rs`): a synthetic Gaussian
//! surface, correlation length 4 px, rms 1 nm, pixel 0.1 um, seed 1, made
//! before the clock starts. Process CPU time (every thread's run time
//! from `/proc/self/task/*/schedstat`, Linux, in ns) around the repeated
//! calls, so other processes' load does not count; the median of the
//! per-call figures is printed. With a third argument the map is written
//! there as `.npy` (what `benches/peers/surface_numpy.py` reads). Prints
//! one JSON object: the timing and the answer (plane, moments, summit
//! count, the sum of the summits' flat indices `row * side + col` and
//! their statistics) for the numpy peer to check.
use asperity::surface::synthetic::GaussianSurface;
use asperity::surface::{npy, Topography};
use std::hint::black_box;

/// Run time of every thread of this process (ns), from schedstat.
fn cpu_ns() -> u64 {
    let mut total = 0;
    if let Ok(tasks) = std::fs::read_dir("/proc/self/task") {
        for t in tasks.flatten() {
            let s = std::fs::read_to_string(t.path().join("schedstat")).unwrap_or_default();
            total += s
                .split_whitespace()
                .next()
                .and_then(|x| x.parse::<u64>().ok())
                .unwrap_or(0);
        }
    }
    total
}

fn main() {
    let arg = |i: usize| std::env::args().nth(i);
    let repeats: usize = arg(1).and_then(|a| a.parse().ok()).unwrap_or(10);
    let side: usize = arg(2).and_then(|a| a.parse().ok()).unwrap_or(4096);
    let dx = 1e-7;
    let map = GaussianSurface::new(side, side, 4.0, 1e-9, dx, 1)
        .expect("valid synthetic surface")
        .generate();
    if let Some(path) = arg(3) {
        std::fs::write(&path, npy::to_bytes(&map)).expect("writable npy path");
    }
    let topo = Topography::new(map, dx).expect("valid topography");
    let threads = rayon::current_num_threads();
    // One untimed call: the pool and the page tables are warm.
    let c = topo.characterise(false).expect("rough map");
    let mut per_call = Vec::with_capacity(repeats);
    for _ in 0..repeats {
        let t0 = cpu_ns();
        black_box(topo.characterise(false).expect("rough map").stats.count);
        per_call.push((cpu_ns() - t0) as f64);
    }
    per_call.sort_by(f64::total_cmp);
    let median = per_call[repeats / 2];
    let pixels = (side * side) as f64;
    println!(
        "{{\"side\": {side}, \"threads\": {threads}, \"repeats\": {repeats}, \
         \"cpu_ms_median\": {:.3}, \"cpu_ms_min\": {:.3}, \"ns_per_pixel\": {:.3}, \
         \"c0\": {:e}, \"slope_x\": {:e}, \"slope_y\": {:e}, \
         \"m0\": {:e}, \"m2\": {:e}, \"m4\": {:e}, \"summits\": {}, \"summit_index_sum\": {}, \
         \"mean_curvature\": {:e}, \"mean_height\": {:e}, \"height_std\": {:e}}}",
        median * 1e-6,
        per_call[0] * 1e-6,
        median / pixels,
        c.plane.c0,
        c.plane.slope_x,
        c.plane.slope_y,
        c.moments.m0,
        c.moments.m2,
        c.moments.m4,
        c.stats.count,
        c.summits
            .iter()
            .map(|s| s.row * side + s.col)
            .sum::<usize>(),
        c.stats.mean_curvature_per_m.unwrap_or(f64::NAN),
        c.stats.mean_height_m.unwrap_or(f64::NAN),
        c.stats.height_std_m.unwrap_or(f64::NAN),
    );
}
