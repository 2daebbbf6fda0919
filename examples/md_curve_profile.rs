//! Profiling target: one Maugis–Dugdale (lambda = 1) GW curve at rtol 1e-6,
//! the way the planner computes it (Chebyshev table to 1e-7 + adaptive
//! quadrature), repeated. `perf record cargo run --release --example md_curve_profile`.
use asperity::gw::{Accuracy, GwModel, RoughSurface};
use asperity::heights::Gaussian;
use asperity::law::interpolated::InterpolatedLaw;
use asperity::law::{AsperityLaw, Maugis};
use asperity::loading::{LoadingModel, LoadingProgram, Observables};
use asperity::material::{contact_modulus, Material};
use std::sync::Arc;

fn main() {
    let s = RoughSurface::gold_microswitch();
    let g = Material::gold();
    let exact: Arc<dyn AsperityLaw> =
        Arc::new(Maugis::new(s.radius, contact_modulus(&g, &g), 0.5, 1.0).unwrap());
    let program = LoadingProgram::new(6.0 * s.sigma, 0.0, 1000).unwrap();
    let acc = Accuracy::new(1e-6).unwrap();
    let t0 = std::time::Instant::now();
    let reps = 20;
    let mut build = 0.0;
    for _ in 0..reps {
        let tb = std::time::Instant::now();
        let table = InterpolatedLaw::new(
            exact.clone(),
            exact.cutoff_interference(),
            40.0 * s.sigma,
            1e-7,
        )
        .unwrap();
        build += tb.elapsed().as_secs_f64();
        let m = GwModel::new(s, Arc::new(Gaussian::new()), Arc::new(table)).unwrap();
        std::hint::black_box(
            m.clone()
                .with_accuracy(acc)
                .curve(&program, &Observables::LOAD)
                .unwrap(),
        );
    }
    println!(
        "{:.2} ms per curve, of which {:.2} ms building the table",
        t0.elapsed().as_secs_f64() * 1e3 / reps as f64,
        build * 1e3 / reps as f64
    );
}
