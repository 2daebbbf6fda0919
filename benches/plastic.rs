//! Elastic-plastic asperities, criterion:
//! `cargo bench --bench plastic -- --warm-up-time 1 --measurement-time 3`.
//!
//! - `plastic_gw_curve/*`: a 1000-point GW curve (approach and retraction
//!   over `LoadingProgram::new(6 sigma, -3 sigma, 1000)`, load, area and
//!   count) of the gold surface (psi = 3.03) with each plastic law, adaptive
//!   quadrature at rtol 1e-8 (2000 states); `1000_points_approach`: the
//!   1000 approach states alone. Target: <= 20 ms.
//! - `plastic_law/*`: one `state` (loading) and one `state_after`
//!   (unloading) through `dyn AsperityLaw`, interferences cycled over
//!   0.1 .. 300 critical interferences; Hertz for comparison.
//! - `plastic_mc/*`: one Monte Carlo state over 1e5 summits with lognormal
//!   radii, Hertz against each plastic law (radius scaling `(1, 2, 1)`).
use asperity::gw::{Accuracy, GwModel, Method, RoughSurface};
use asperity::heights::{Exponential, Gaussian};
use asperity::law::plastic::{build, PlasticLaw};
use asperity::law::{AsperityLaw, Branch, Hertz, RadiusScaling};
use asperity::loading::{History, LoadingModel, LoadingProgram, Observables};
use asperity::material::plastic::{Plasticity, Variant};
use asperity::montecarlo::*;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use std::hint::black_box;
use std::sync::Arc;

const R: f64 = 1e-6;
const E: f64 = 4.796e10;
const SIGMA: f64 = 5e-9;

fn law(v: Variant) -> Arc<dyn PlasticLaw> {
    build(v, R, E, Plasticity::gold()).unwrap()
}

fn gw_curve(c: &mut Criterion) {
    let mut group = c.benchmark_group("plastic_gw_curve");
    group.sample_size(10);
    let surface = RoughSurface::gold_microswitch();
    let program = LoadingProgram::new(6.0 * SIGMA, -3.0 * SIGMA, 1000).unwrap();
    let acc = Accuracy::new(1e-8).unwrap().with_method(Method::Quadrature);
    for v in Variant::ALL {
        let model = GwModel::new(surface, Arc::new(Gaussian::new()), law(v).as_law()).unwrap();
        group.bench_function(BenchmarkId::new(v.name(), "1000_points"), |b| {
            b.iter(|| {
                black_box(
                    model
                        .clone()
                        .with_accuracy(acc)
                        .curve(&program, &Observables::ALL)
                        .unwrap(),
                )
            })
        });
        let seps = program.separations();
        group.bench_function(BenchmarkId::new(v.name(), "1000_points_approach"), |b| {
            b.iter(|| {
                for &d in &seps {
                    black_box(
                        model
                            .clone()
                            .with_accuracy(acc)
                            .state(d, History::Approach, &Observables::ALL)
                            .unwrap(),
                    );
                }
            })
        });
    }
    group.finish();
}

fn per_law(c: &mut Criterion) {
    let mut group = c.benchmark_group("plastic_law");
    let mut laws: Vec<(&str, Arc<dyn AsperityLaw>, f64)> = vec![(
        "hertz",
        Arc::new(Hertz::new(R, E).unwrap()),
        law(Variant::KogutEtsion).critical_interference(),
    )];
    for v in Variant::ALL {
        let l = law(v);
        let wc = l.critical_interference();
        laws.push((v.name(), l.as_law(), wc));
    }
    for (name, l, wc) in laws {
        let deltas: Vec<f64> = (0..64)
            .map(|i| wc * 10f64.powf(-1.0 + 3.5 * i as f64 / 63.0))
            .collect();
        group.throughput(Throughput::Elements(deltas.len() as u64));
        group.bench_function(BenchmarkId::new("state", name), |b| {
            b.iter(|| {
                let mut s = 0.0;
                for &d in &deltas {
                    s += l.state(black_box(d), Branch::Approach).load;
                }
                s
            })
        });
        group.bench_function(BenchmarkId::new("state_after", name), |b| {
            b.iter(|| {
                let mut s = 0.0;
                for &d in &deltas {
                    s += l.state_after(black_box(0.7 * d), d).load;
                }
                s
            })
        });
    }
    group.finish();
}

fn monte_carlo(c: &mut Criterion) {
    let mut group = c.benchmark_group("plastic_mc");
    group.sample_size(10);
    let n = 100_000;
    let spec = PopulationSpec::new(
        n,
        SIGMA,
        RadiusSpec::LogNormal {
            median: R,
            log_std: 0.3,
        },
        1,
    )
    .unwrap();
    let pop = Arc::new(Population::sample(&spec, &Exponential::new()).unwrap());
    let r_ref = pop.reference_radius();
    let plastic = RadiusScaling {
        interference: 1.0,
        load: 2.0,
        contact_radius: 1.0,
    };
    let mut laws = vec![(
        "hertz",
        SummitLaw::scaled(
            Arc::new(Hertz::new(r_ref, E).unwrap()),
            r_ref,
            RadiusScaling::MAUGIS,
        )
        .unwrap(),
    )];
    for v in Variant::ALL {
        let l = build(v, r_ref, E, Plasticity::gold()).unwrap();
        laws.push((
            v.name(),
            SummitLaw::scaled(l.as_law(), r_ref, plastic).unwrap(),
        ));
    }
    // Below the lowest summit: every summit in contact.
    let d = pop.heights()[0] - SIGMA;
    group.throughput(Throughput::Elements(n as u64));
    for (name, sl) in laws {
        let mc = MonteCarlo::new(pop.clone(), sl).unwrap();
        group.bench_function(BenchmarkId::new("approach", name), |b| {
            b.iter(|| black_box(mc.state(d, History::Approach, &Observables::ALL).unwrap()))
        });
        group.bench_function(BenchmarkId::new("retract", name), |b| {
            let back = History::Retract { closest: d - SIGMA };
            b.iter(|| black_box(mc.state(d, back, &Observables::ALL).unwrap()))
        });
    }
    group.finish();
}

criterion_group!(benches, gw_curve, per_law, monte_carlo);
criterion_main!(benches);
