//! A random summit population against the Greenwood–Williamson integral.
//!
//! `cargo run --release --example montecarlo`
//!
//! Draws populations of growing size on GW's exponential height
//! distribution, sums Hertz and JKR summits exactly, and compares each total
//! with the statistical integral in units of its standard error; then shows
//! what GW cannot do (lognormal radii) and times a 1e6-summit program.
use asperity::gw::{Accuracy, GwModel, RoughSurface};
use asperity::heights::Exponential;
use asperity::law::{Hertz, Jkr, LawKernels, RadiusScaling};
use asperity::loading::{History, LoadingModel, LoadingProgram, Observables};
use asperity::montecarlo::*;
use std::sync::Arc;
use std::time::Instant;

fn main() -> asperity::Result<()> {
    let (r, sigma, e_star, w) = (1e-6, 5e-9, 4.8e10, 0.5);
    let acc = Accuracy::new(1e-10)?;
    let d = 0.5 * sigma;

    println!("Hertz and JKR summits, exponential heights, R = 1 um, sigma = 5 nm, d = 0.5 sigma");
    println!(
        "{:>9} {:>6} {:>14} {:>14} {:>10} {:>7}",
        "N", "law", "MC load (N)", "GW load (N)", "SE (N)", "z"
    );
    let laws: [(&str, Arc<dyn LawKernels>); 2] = [
        ("hertz", Arc::new(Hertz::new(r, e_star)?)),
        ("jkr", Arc::new(Jkr::new(r, e_star, w)?)),
    ];
    for n in [100usize, 10_000, 1_000_000] {
        let spec = PopulationSpec::new(n, sigma, RadiusSpec::Fixed(r), 2024)?;
        let pop = Arc::new(Population::sample(&spec, &Exponential::new())?);
        for (name, law) in &laws {
            let mc = MonteCarlo::new(
                pop.clone(),
                SummitLaw::scaled(law.clone(), r, RadiusScaling::MAUGIS)?,
            )?;
            let gw = GwModel::new(
                RoughSurface::new(n as f64, r, sigma, 1.0)?,
                Arc::new(Exponential::new()),
                law.clone(),
            )?;
            let history = History::Retract { closest: -sigma };
            let m = mc.state(d, history, &Observables::LOAD)?;
            let g = gw
                .clone()
                .with_accuracy(acc)
                .state(d, history, &Observables::LOAD)?;
            let (pm, pg, se) = (
                m.load().unwrap(),
                g.load().unwrap(),
                m.totals.error(0).unwrap(),
            );
            println!(
                "{n:>9} {name:>6} {pm:>14.6e} {pg:>14.6e} {se:>10.2e} {:>7.2}",
                (pm - pg) / se
            );
        }
    }

    // Lognormal radii (GW cannot): Hertz load grows by E[rho^(1/2)] = exp(s^2/8).
    let s = 0.5;
    let spec = PopulationSpec::new(
        1_000_000,
        sigma,
        RadiusSpec::LogNormal {
            median: r,
            log_std: s,
        },
        7,
    )?;
    let pop = Arc::new(Population::sample(&spec, &Exponential::new())?);
    let hertz = SummitLaw::scaled(laws[0].1.clone(), r, RadiusScaling::MAUGIS)?;
    let mc = MonteCarlo::new(pop, hertz)?;
    let m = mc.state(d, History::Approach, &Observables::ALL)?;
    let gw = GwModel::new(
        RoughSurface::new(1e6, r, sigma, 1.0)?,
        Arc::new(Exponential::new()),
        laws[0].1.clone(),
    )?;
    let g = gw
        .clone()
        .with_accuracy(acc)
        .state(d, History::Approach, &Observables::ALL)?;
    println!(
        "\nlognormal radii (log-std {s}): MC load {:.6e} +- {:.1e} N; GW(median R) x exp(s^2/8) = {:.6e} N",
        m.load().unwrap(),
        m.totals.error(0).unwrap(),
        g.load().unwrap() * (s * s / 8.0).exp()
    );

    // Timing: approach-retract programs of 1000 states (500 separations per
    // leg, from 6 sigma to -sigma): Hertz on 1e6 summits, soft sticky JKR
    // (E* = 1 GPa, strong hysteresis) on 1e5.
    let soft: Arc<dyn LawKernels> = Arc::new(Jkr::new(r, 1e9, w)?);
    let program = LoadingProgram::new(6.0 * sigma, -sigma, 500)?;
    for (name, law, n) in [
        ("hertz", laws[0].1.clone(), 1_000_000),
        ("soft jkr", soft, 100_000),
    ] {
        let spec = PopulationSpec::new(n, sigma, RadiusSpec::Fixed(r), 1)?;
        let t0 = Instant::now();
        let pop = Arc::new(Population::sample(&spec, &Exponential::new())?);
        let t_sample = t0.elapsed();
        let mc = MonteCarlo::new(pop, SummitLaw::scaled(law, r, RadiusScaling::MAUGIS)?)?;
        let t1 = Instant::now();
        let curve = mc.curve(&program, &Observables::ALL)?;
        let t_curve = t1.elapsed();
        let evals = curve.evaluations();
        println!(
            "\n{n} {name} summits: sampled in {:.3} s; 1000-state program in {:.3} s \
             ({evals} evaluations, {:.3e}/s on {} threads)",
            t_sample.as_secs_f64(),
            t_curve.as_secs_f64(),
            evals as f64 / t_curve.as_secs_f64(),
            rayon::current_num_threads()
        );
        if let Some(p) = curve.sampled_pull_off() {
            println!(
                "  pull-off {:.4e} N at {:.3} sigma; hysteresis energy {:.4e} J",
                p.load,
                p.separation / sigma,
                curve.hysteresis_energy().unwrap()
            );
        }
    }
    Ok(())
}
