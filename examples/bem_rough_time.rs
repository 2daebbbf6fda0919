//! Times one 256^2 rough periodic solve at p = 0.01 E* (used with perf).
use asperity::bem::{Options, Problem};
use asperity::spectrum::{synthesis::random_phase_map, Normalisation, Spectrum};
fn main() {
    let n = 256;
    let dx = 1e-4 / n as f64;
    let q0 = 2.0 * std::f64::consts::PI / 1e-4;
    let spec = Spectrum::self_affine(
        0.8,
        4.0 * q0,
        4.0 * q0,
        64.0 * q0,
        Normalisation::SlopeRms(0.1),
    )
    .unwrap();
    let map = random_phase_map(&spec, n, n, dx, 1).unwrap();
    let opts = Options {
        tolerance: 1e-8,
        ..Default::default()
    };
    let reps: usize = std::env::args().nth(1).map_or(5, |s| s.parse().unwrap());
    let t = std::time::Instant::now();
    for _ in 0..reps {
        let prob = Problem::new(&map, dx, 1e9, true, &opts).unwrap();
        let s = prob.solve_pressure(1e7, &opts, None).unwrap();
        assert!(s.area_fraction() > 0.0);
    }
    println!(
        "{:.4} s per solve (wall)",
        t.elapsed().as_secs_f64() / reps as f64
    );
}
