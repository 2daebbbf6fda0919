//! Profiling target: one Maugis–Dugdale (lambda = 1) GW curve at rtol 1e-6,
//! the way the planner computes it (Chebyshev table to 1e-7 + adaptive
//! quadrature), repeated. `perf record cargo run --release --example md_curve_profile`.
//!
//! Prints wall and process CPU time per curve on the global rayon pool and
//! on one thread, and the law evaluations per state (mean, each leg).
use asperity::gw::{Accuracy, GwModel, RoughSurface};
use asperity::heights::Gaussian;
use asperity::law::interpolated::InterpolatedLaw;
use asperity::law::{AsperityLaw, Maugis};
use asperity::loading::{Curve, LoadingModel, LoadingProgram, Observables};
use asperity::material::{contact_modulus, Material};
use std::sync::Arc;

/// Process CPU time (s), all threads, from `/proc/self/stat` (Linux).
fn cpu_seconds() -> f64 {
    asperity::study::cpu_time::process_cpu_seconds().unwrap_or(f64::NAN)
}

fn main() {
    let s = RoughSurface::gold_microswitch();
    let g = Material::gold();
    let exact: Arc<dyn AsperityLaw> =
        Arc::new(Maugis::new(s.radius, contact_modulus(&g, &g), 0.5, 1.0).unwrap());
    let program = LoadingProgram::new(6.0 * s.sigma, 0.0, 1000).unwrap();
    let acc = Accuracy::new(1e-6).unwrap();
    let reps: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(40);
    let run = || -> Curve {
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
    let curve = run();
    let mean = |v: &[asperity::loading::State]| {
        v.iter().map(|s| s.evaluations as f64).sum::<f64>() / v.len() as f64
    };
    println!(
        "law evaluations per state: approach {:.1}, retraction {:.1}",
        mean(&curve.approach),
        mean(&curve.retract)
    );
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    for (name, pool) in [("global pool", None), ("1 thread", Some(&one))] {
        let (t0, c0) = (std::time::Instant::now(), cpu_seconds());
        for _ in 0..reps {
            match pool {
                None => std::hint::black_box(run()),
                Some(p) => p.install(|| std::hint::black_box(run())),
            };
        }
        println!(
            "{name}: {:.2} ms wall, {:.2} ms CPU per curve",
            t0.elapsed().as_secs_f64() * 1e3 / reps as f64,
            (cpu_seconds() - c0) * 1e3 / reps as f64
        );
    }
}
