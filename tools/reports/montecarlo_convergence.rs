//! Convergence of Monte Carlo totals to the GW integral against population
//! size (the table in docs/performance.md, "Monte Carlo populations").
//!
//! `cargo run --release --example montecarlo_convergence`
//!
//! Hertz summits (R = 1 um, E* = 48 GPa) on exponential heights
//! (sigma = 5 nm) at d = 0.5 sigma, and JKR summits (E* = 1 GPa,
//! w = 0.5 J/m^2) on retraction from d = -0.5 sigma to d = 0.5 sigma;
//! for each N, `seeds` populations. Columns: mean relative error over
//! seeds, RMS relative error, mean reported relative SE, RMS error x
//! sqrt(N) (constant when the error falls like N^-1/2), and the RMS of the
//! z-scores (about 1 when the reported SE is right).
use asperity::gw::{Accuracy, GwModel, Method, RoughSurface};
use asperity::heights::Exponential;
use asperity::law::{Hertz, Jkr, LawKernels, RadiusScaling};
use asperity::loading::{History, LoadingModel, Observables};
use asperity::montecarlo::*;
use std::sync::Arc;

fn main() -> asperity::Result<()> {
    let (r, sigma) = (1e-6, 5e-9);
    let acc = Accuracy::new(1e-10)?.with_method(Method::Quadrature);
    let d = 0.5 * sigma;
    let cases: [(&str, Arc<dyn LawKernels>, History); 2] = [
        ("hertz", Arc::new(Hertz::new(r, 4.8e10)?), History::Approach),
        (
            "jkr",
            Arc::new(Jkr::new(r, 1e9, 0.5)?),
            History::Retract {
                closest: -0.5 * sigma,
            },
        ),
    ];
    println!("| law | N | seeds | mean rel. error | RMS rel. error | mean rel. SE | RMS x sqrt(N) | RMS z |");
    println!("|---|---|---|---|---|---|---|---|");
    for (name, law, history) in &cases {
        for (n, seeds) in [
            (100usize, 200u64),
            (1_000, 200),
            (10_000, 100),
            (100_000, 40),
            (1_000_000, 20),
        ] {
            let gw = GwModel::new(
                RoughSurface::new(n as f64, r, sigma, 1.0)?,
                Arc::new(Exponential::new()),
                law.clone(),
            )?;
            let expect = gw
                .clone()
                .with_accuracy(acc)
                .state(d, *history, &Observables::LOAD)?
                .load()
                .unwrap();
            let (mut m, mut sq, mut se, mut z2) = (0.0, 0.0, 0.0, 0.0);
            for seed in 0..seeds {
                let spec = PopulationSpec::new(n, sigma, RadiusSpec::Fixed(r), seed)?;
                let pop = Arc::new(Population::sample(&spec, &Exponential::new())?);
                let mc = MonteCarlo::new(
                    pop,
                    SummitLaw::scaled(law.clone(), r, RadiusScaling::MAUGIS)?,
                )?;
                let s = mc.state(d, *history, &Observables::LOAD)?;
                let e = s.load().unwrap() / expect - 1.0;
                m += e;
                sq += e * e;
                se += s.totals.error(0).unwrap() / expect.abs();
                let z = (s.load().unwrap() - expect) / s.totals.error(0).unwrap();
                z2 += z * z;
            }
            let k = seeds as f64;
            let rms = (sq / k).sqrt();
            println!(
                "| {name} | {n} | {seeds} | {:+.2e} | {:.2e} | {:.2e} | {:.3} | {:.2} |",
                m / k,
                rms,
                se / k,
                rms * (n as f64).sqrt(),
                (z2 / k).sqrt()
            );
        }
    }
    Ok(())
}
