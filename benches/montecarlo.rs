//! Monte Carlo summation throughput (criterion):
//! `cargo bench --bench montecarlo -- --warm-up-time 1 --measurement-time 3`.
//!
//! - `mc_state/*`: one separation over a population of 1e6 summits, every
//!   summit within range (throughput = law evaluations per second).
//! - `mc_curve/*`: a 1e6-summit approach-retract program of 1000 states
//!   (500 separations per leg).
//! - `mc_sample/*`: drawing the population.
//! - `mc_state/{tabulated-md,kogut-etsion}/fixed/*`: exact Maugis–Dugdale
//!   (`lambda = 0.5`) tabulated automatically by `SummitLaw::from_kind`,
//!   and the Kogut–Etsion plastic law (gold), one radius.
//! - `mc_small/hertz/*`: Hertz, 1e3 .. 1e5 summits, one state (the serial
//!   path below `SERIAL_BELOW` evaluations); `mc_small/hertz_x8/*`: eight
//!   states per call (parallel once `8 n >= SERIAL_BELOW`).
//!
//! The numpy peer of `mc_state/*/fixed/approach` is
//! `benches/peers/montecarlo_numpy.py`.
use asperity::heights::Exponential;
use asperity::law::plastic::build;
use asperity::law::{Hertz, Jkr, LawKind, RadiusScaling};
use asperity::loading::{History, LoadingModel, LoadingProgram, Observables};
use asperity::material::plastic::{Plasticity, Variant};
use asperity::material::{Adhesion, AsperityContact};
use asperity::montecarlo::*;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use std::hint::black_box;
use std::sync::Arc;

const R: f64 = 1e-6;
const SIGMA: f64 = 5e-9;
const N: usize = 1_000_000;

fn laws() -> Vec<(&'static str, SummitLaw)> {
    vec![
        (
            "hertz",
            SummitLaw::scaled(
                Arc::new(Hertz::new(R, 4.8e10).unwrap()),
                R,
                RadiusScaling::MAUGIS,
            )
            .unwrap(),
        ),
        (
            "jkr",
            SummitLaw::scaled(
                Arc::new(Jkr::new(R, 4.8e10, 0.5).unwrap()),
                R,
                RadiusScaling::MAUGIS,
            )
            .unwrap(),
        ),
    ]
}

/// Laws for one radius only (no radius scaling used).
fn fixed_laws() -> Vec<(&'static str, SummitLaw)> {
    // z0 = 0.3 nm: lambda = 1.157 mu ~ 0.6 (transition regime).
    let contact = AsperityContact::new(R, 4.8e10, Adhesion::new(0.5, 3e-10).unwrap()).unwrap();
    vec![
        (
            "tabulated-md",
            SummitLaw::from_kind(LawKind::Maugis, &contact).unwrap(),
        ),
        (
            "kogut-etsion",
            SummitLaw::fixed(
                build(Variant::KogutEtsion, R, 4.8e10, Plasticity::gold())
                    .unwrap()
                    .as_law(),
                R,
            )
            .unwrap(),
        ),
    ]
}

fn populations() -> Vec<(&'static str, Arc<Population>)> {
    let fixed = PopulationSpec::new(N, SIGMA, RadiusSpec::Fixed(R), 1).unwrap();
    let logn = PopulationSpec::new(
        N,
        SIGMA,
        RadiusSpec::LogNormal {
            median: R,
            log_std: 0.3,
        },
        1,
    )
    .unwrap();
    vec![
        (
            "fixed",
            Arc::new(Population::sample(&fixed, &Exponential::new()).unwrap()),
        ),
        (
            "lognormal",
            Arc::new(Population::sample(&logn, &Exponential::new()).unwrap()),
        ),
    ]
}

fn bench_state(c: &mut Criterion) {
    let mut group = c.benchmark_group("mc_state");
    group.throughput(Throughput::Elements(N as u64));
    for (pname, pop) in populations() {
        for (lname, law) in laws() {
            let mc = MonteCarlo::new(pop.clone(), law).unwrap();
            // d = -sigma: every summit in contact.
            let d = -SIGMA;
            for (hname, history) in [
                ("approach", History::Approach),
                ("retract", History::Retract { closest: 2.0 * d }),
            ] {
                assert_eq!(
                    mc.state(d, history, &Observables::ALL).unwrap().evaluations,
                    N
                );
                group.bench_function(BenchmarkId::new(format!("{lname}/{pname}"), hname), |b| {
                    b.iter(|| {
                        black_box(mc.state(black_box(d), history, &Observables::ALL).unwrap())
                    })
                });
            }
        }
    }
    let pop = populations().remove(0).1;
    for (lname, law) in fixed_laws() {
        let mc = MonteCarlo::new(pop.clone(), law).unwrap();
        let d = -SIGMA;
        for (hname, history) in [
            ("approach", History::Approach),
            ("retract", History::Retract { closest: 2.0 * d }),
        ] {
            group.bench_function(BenchmarkId::new(format!("{lname}/fixed"), hname), |b| {
                b.iter(|| black_box(mc.state(black_box(d), history, &Observables::ALL).unwrap()))
            });
        }
    }
    group.finish();
}

fn bench_small(c: &mut Criterion) {
    let mut group = c.benchmark_group("mc_small");
    let law = laws().remove(0).1;
    for n in [1_000usize, 10_000, 30_000, 100_000] {
        let spec = PopulationSpec::new(n, SIGMA, RadiusSpec::Fixed(R), 1).unwrap();
        let pop = Arc::new(Population::sample(&spec, &Exponential::new()).unwrap());
        let mc = MonteCarlo::new(pop, law.clone()).unwrap();
        group.throughput(Throughput::Elements(n as u64));
        group.bench_function(BenchmarkId::new("hertz", n), |b| {
            b.iter(|| {
                black_box(
                    mc.state(black_box(-SIGMA), History::Approach, &Observables::ALL)
                        .unwrap(),
                )
            })
        });
        // Eight states in one call: 8 n evaluations, parallel from n = 8192
        // (per-element throughput comparable with the serial single state).
        let steps = [(-SIGMA, History::Approach); 8];
        group.throughput(Throughput::Elements(8 * n as u64));
        group.bench_function(BenchmarkId::new("hertz_x8", n), |b| {
            b.iter(|| black_box(mc.states(black_box(&steps), &Observables::ALL).unwrap()))
        });
    }
    group.finish();
}

fn bench_curve(c: &mut Criterion) {
    let mut group = c.benchmark_group("mc_curve");
    group.sample_size(10);
    let pop = populations().remove(0).1;
    // Approach from 6 sigma to -sigma and back, 500 separations per leg.
    let program = LoadingProgram::new(6.0 * SIGMA, -SIGMA, 500).unwrap();
    for (lname, law) in laws() {
        let mc = MonteCarlo::new(pop.clone(), law).unwrap();
        let evals = mc.curve(&program, &Observables::ALL).unwrap().evaluations();
        group.throughput(Throughput::Elements(evals as u64));
        group.bench_function(BenchmarkId::new(lname, "1000_states"), |b| {
            b.iter(|| black_box(mc.curve(&program, &Observables::ALL).unwrap()))
        });
    }
    group.finish();
}

fn bench_sample(c: &mut Criterion) {
    let mut group = c.benchmark_group("mc_sample");
    group.sample_size(10);
    group.throughput(Throughput::Elements(N as u64));
    for (name, radius) in [
        ("fixed", RadiusSpec::Fixed(R)),
        (
            "lognormal",
            RadiusSpec::LogNormal {
                median: R,
                log_std: 0.3,
            },
        ),
    ] {
        let spec = PopulationSpec::new(N, SIGMA, radius, 1).unwrap();
        group.bench_function(name, |b| {
            b.iter(|| black_box(Population::sample(&spec, &Exponential::new()).unwrap()))
        });
    }
    group.finish();
}

criterion_group!(benches, bench_state, bench_small, bench_curve, bench_sample);
criterion_main!(benches);
