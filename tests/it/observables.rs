//! The loading vocabulary is open: a new per-asperity observable defined in
//! one place (here, the contact perimeter `2 pi a`) gets its
//! Greenwood–Williamson integral and its Monte Carlo sum from the same code
//! that totals load, area and count.

use asperity::gw::{Accuracy, GwModel, RoughSurface};
use asperity::heights::{Gaussian, HeightDistribution};
use asperity::law::{ContactState, Hertz, LawKernels};
use asperity::loading::{
    History, LoadingModel, LoadingProgram, Observable, Observables, PerAsperity,
};
use asperity::montecarlo::{MonteCarlo, Population, PopulationSpec, RadiusSpec, SummitLaw};
use std::f64::consts::PI;
use std::sync::Arc;

/// The toy observable: contact perimeter `2 pi a` (m).
#[derive(Debug)]
struct Perimeter;

impl PerAsperity for Perimeter {
    fn name(&self) -> &str {
        "perimeter_m"
    }
    fn value(&self, s: &ContactState) -> f64 {
        2.0 * PI * s.radius
    }
}

fn setup() -> (RoughSurface, Arc<dyn LawKernels>, Observables, Observable) {
    let surface = RoughSurface::new(1e12, 1e-6, 5e-9, 1e-8).unwrap();
    let law: Arc<dyn LawKernels> = Arc::new(Hertz::new(surface.radius, 5e10).unwrap());
    let perimeter = Observable::Custom(Arc::new(Perimeter));
    let obs = Observables::ALL.with(perimeter.clone()).unwrap();
    (surface, law, obs, perimeter)
}

#[test]
fn toy_observable_integrates_over_heights() {
    let (surface, law, obs, perimeter) = setup();
    let model = GwModel::new(surface, Arc::new(Gaussian::new()), law)
        .unwrap()
        .with_accuracy(Accuracy::new(1e-10).unwrap());
    let slot = obs.slot(&perimeter).unwrap();
    for h in [-1.0, 0.0, 1.5, 3.0] {
        let d = h * surface.sigma;
        let s = model.state(d, History::Approach, &obs).unwrap();
        // Hertz: a = sqrt(R delta), so the total is
        // eta A_n 2 pi sqrt(R sigma) F_1/2(h) (GW 1966 with n = 1/2).
        let exact = surface.summits()
            * 2.0
            * PI
            * (surface.radius * surface.sigma).sqrt()
            * Gaussian::new().moment_above(0.5, h);
        let got = s.totals.get(slot).unwrap();
        assert!(
            (got - exact).abs() <= 1e-9 * exact,
            "h = {h}: {got} vs {exact}"
        );
        // The standard totals agree with their closed forms (the extra
        // observable sends the state through quadrature).
        let plain = model
            .state(d, History::Approach, &Observables::ALL)
            .unwrap();
        for (a, b) in [(s.load(), plain.load()), (s.count(), plain.count())] {
            let (a, b) = (a.unwrap(), b.unwrap());
            assert!((a - b).abs() <= 1e-9 * b, "{a} vs {b}");
        }
    }
}

#[test]
fn toy_observable_sums_over_a_population() {
    let (surface, law, obs, perimeter) = setup();
    let spec =
        PopulationSpec::new(20_000, surface.sigma, RadiusSpec::Fixed(surface.radius), 7).unwrap();
    let pop = Arc::new(Population::sample(&spec, &Gaussian::new()).unwrap());
    let mc = MonteCarlo::new(
        pop.clone(),
        SummitLaw::fixed(law.clone(), surface.radius).unwrap(),
    )
    .unwrap();
    let slot = obs.slot(&perimeter).unwrap();
    let program = LoadingProgram::new(3.0 * surface.sigma, 0.0, 5).unwrap();
    let curve = mc.curve(&program, &obs).unwrap();
    for s in curve.approach.iter().chain(&curve.retract) {
        // Direct sum over the summits.
        let direct: f64 = pop
            .heights()
            .iter()
            .map(|&z| {
                2.0 * PI
                    * law
                        .state(z - s.separation, asperity::law::Branch::Approach)
                        .radius
            })
            .sum();
        let got = s.totals.get(slot).unwrap();
        assert!(
            (got - direct).abs() <= 1e-12 * direct.max(1e-300),
            "{got} vs {direct}"
        );
        // And it estimates the integral within its standard error.
        let gw = GwModel::new(surface, Arc::new(Gaussian::new()), law.clone()).unwrap();
        let expected = gw.state(s.separation, History::Approach, &obs).unwrap();
        let scale = surface.summits() / pop.len() as f64;
        let z = (got * scale - expected.totals.get(slot).unwrap())
            / (s.totals.error(slot).unwrap() * scale);
        assert!(z.abs() < 5.0, "z = {z}");
    }
}
