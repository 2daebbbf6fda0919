//! CPU time and values of the two GW curves of the curve benchmark against their
//! numpy peers (`benches/peers/gw_curves_numpy.py` runs this and compares):
//! `cargo run --release --example gw_peer_curves -- CASE RTOL [REPEATS]`,
//! `CASE` one of `resistance`, `kogut-etsion`.
//!
//! - `resistance`: the curve of `benches/electrical.rs` (`curve`): 10^4
//!   Hertz summits (R = 1 um, E* = 48 GPa) on Gaussian heights (sigma =
//!   5 nm) in (100 um)^2, gold Wexler spots with Greenwood's mean-field
//!   term; 1000 approach separations from -sigma to 4 sigma; load, count,
//!   `sum G`, `sum G^2` and the resistance.
//! - `kogut-etsion`: the gold surface (psi = 3.03) with Kogut–Etsion
//!   summits, the 1000 approach separations of
//!   `LoadingProgram::new(6 sigma, -3 sigma, 1000)`; load, area, count.
//!
//! Both at `Accuracy::new(RTOL)` (the engine's choice of method), on a
//! 1-thread rayon pool. Prints one JSON object: process CPU seconds per
//! curve (`/proc/self/stat`, utime + stime, over `REPEATS` curves), the
//! evaluations per curve, and every state's values.
use asperity::electrical::{Interaction, ResistanceObservables, SpotResistance, Spreading};
use asperity::gw::{Accuracy, GwModel, RoughSurface};
use asperity::heights::Gaussian;
use asperity::law::plastic::build;
use asperity::law::Hertz;
use asperity::loading::{History, LoadingModel, LoadingProgram, Observables, State};
use asperity::material::plastic::{Plasticity, Variant};
use std::hint::black_box;
use std::sync::Arc;

/// utime + stime of this process (s), from /proc/self/stat.
fn cpu_seconds() -> f64 {
    asperity::study::cpu_time::process_cpu_seconds().unwrap_or(f64::NAN)
}

fn list(v: impl Iterator<Item = f64>) -> String {
    let items: Vec<String> = v.map(|x| format!("{x:.17e}")).collect();
    format!("[{}]", items.join(","))
}

fn timed<F: Fn() -> Vec<State>>(repeats: usize, f: F) -> (f64, Vec<State>) {
    let first = f();
    let t0 = cpu_seconds();
    for _ in 0..repeats {
        black_box(f());
    }
    ((cpu_seconds() - t0) / repeats as f64, first)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let case = args.get(1).map_or("resistance", |s| s.as_str()).to_string();
    let rtol: f64 = args.get(2).and_then(|a| a.parse().ok()).unwrap_or(1e-6);
    let repeats: usize = args.get(3).and_then(|a| a.parse().ok()).unwrap_or(50);
    rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build_global()
        .unwrap();
    let acc = Accuracy::new(rtol).unwrap();
    match case.as_str() {
        "resistance" => {
            let surface = RoughSurface::new(1e12, 1e-6, 5e-9, 1e-8).unwrap();
            let model = GwModel::new(
                surface,
                Arc::new(Gaussian::new()),
                Arc::new(Hertz::new(1e-6, 48e9).unwrap()),
            )
            .unwrap()
            .with_accuracy(acc);
            let spot =
                SpotResistance::same_metal(Spreading::Wexler, 2.44e-8, Some(3.46e-8)).unwrap();
            let res = ResistanceObservables::new(spot, Interaction::Greenwood, 1e-4);
            let outputs = res.add_to(Observables::LOAD).unwrap();
            let steps: Vec<(f64, History)> = (0..1000)
                .map(|i| ((-1.0 + 5.0 * i as f64 / 999.0) * 5e-9, History::Approach))
                .collect();
            let (cpu, states) = timed(repeats, || model.states(&steps, &outputs).unwrap());
            let g = |s: &State, k: usize| s.totals.get(3 + k).unwrap();
            let r = |s: &State| res.resistance(&outputs, &s.totals).unwrap().resistance;
            println!(
                "{{\"case\":\"{case}\",\"rtol\":{rtol:e},\"cpu_s\":{cpu:e},\"evaluations\":{},\
                 \"d\":{},\"load\":{},\"count\":{},\"g\":{},\"g2\":{},\"resistance\":{}}}",
                states.iter().map(|s| s.evaluations).sum::<usize>(),
                list(steps.iter().map(|s| s.0)),
                list(states.iter().map(|s| s.load().unwrap())),
                list(states.iter().map(|s| s.count().unwrap())),
                list(states.iter().map(|s| g(s, 0))),
                list(states.iter().map(|s| g(s, 1))),
                list(states.iter().map(r)),
            );
        }
        "kogut-etsion" => {
            let surface = RoughSurface::gold_microswitch();
            let law = build(
                Variant::KogutEtsion,
                surface.radius,
                4.796e10,
                Plasticity::gold(),
            )
            .unwrap();
            let model = GwModel::new(surface, Arc::new(Gaussian::new()), law.as_law())
                .unwrap()
                .with_accuracy(acc);
            let sigma = surface.sigma;
            let program = LoadingProgram::new(6.0 * sigma, -3.0 * sigma, 1000).unwrap();
            let steps: Vec<(f64, History)> = program
                .separations()
                .into_iter()
                .map(|d| (d, History::Approach))
                .collect();
            let (cpu, states) = timed(repeats, || model.states(&steps, &Observables::ALL).unwrap());
            println!(
                "{{\"case\":\"{case}\",\"rtol\":{rtol:e},\"cpu_s\":{cpu:e},\"evaluations\":{},\
                 \"d\":{},\"load\":{},\"area\":{},\"count\":{}}}",
                states.iter().map(|s| s.evaluations).sum::<usize>(),
                list(steps.iter().map(|s| s.0)),
                list(states.iter().map(|s| s.load().unwrap())),
                list(states.iter().map(|s| s.area().unwrap())),
                list(states.iter().map(|s| s.count().unwrap())),
            );
        }
        other => {
            eprintln!("unknown case {other}: resistance or kogut-etsion");
            std::process::exit(2);
        }
    }
}
