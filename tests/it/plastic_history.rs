//! Loading history of elastic-plastic asperities on rough surfaces:
//! a second loading cycle differs from the first, the pull-off grows with
//! the closest approach (maximum load), Monte Carlo populations with varying
//! radii use the `(1, 2, 1)` radius scaling exactly, and the regime
//! diagnostics.
use asperity::gw::{Accuracy, GwModel, Method, RoughSurface};
use asperity::heights::{Gaussian, HeightDistribution};
use asperity::law::plastic::{
    build, contact_fractions, elastic_law_warning, AdhesivePlastic, MaxInterference, PlasticLaw,
};
use asperity::law::{Jkr, LawKernels, RadiusScaling};
use asperity::loading::{History, LoadingModel, Observables};
use asperity::material::plastic::{plasticity_index, Plasticity, Variant};
use asperity::montecarlo::{MonteCarlo, Population, Radii, SummitLaw};
use std::sync::Arc;

const R: f64 = 1e-6;
const E: f64 = 4.796e10;
const SIGMA: f64 = 5e-9;

fn model(law: Arc<dyn LawKernels>) -> GwModel {
    let surface = RoughSurface::new(1e12, R, SIGMA, 1e-8).unwrap();
    GwModel::new(surface, Arc::new(Gaussian::new()), law).unwrap()
}

fn ke() -> Arc<dyn PlasticLaw> {
    build(Variant::KogutEtsion, R, E, Plasticity::gold()).unwrap()
}

#[test]
fn second_loading_cycle_differs_from_the_first() {
    let acc = Accuracy::new(1e-9).unwrap().with_method(Method::Quadrature);
    for v in Variant::ALL {
        let m = model(build(v, R, E, Plasticity::gold()).unwrap().as_law());
        let closest = -1.5 * SIGMA;
        let first = m
            .clone()
            .with_accuracy(acc)
            .state(0.0, History::Approach, &Observables::ALL)
            .unwrap();
        // Reloading below the closest approach retraces the unloading curve.
        let second = m
            .clone()
            .with_accuracy(acc)
            .state(0.0, History::Retract { closest }, &Observables::ALL)
            .unwrap();
        let (l1, l2) = (first.load().unwrap(), second.load().unwrap());
        let (a1, a2) = (first.area().unwrap(), second.area().unwrap());
        eprintln!(
            "{v:?}: second/first load {:.4}, area {:.4}",
            l2 / l1,
            a2 / a1
        );
        assert!(l2 < 0.9 * l1, "{v:?}: {l2} vs {l1}");
        // At the closest approach the two meet.
        let at = m
            .clone()
            .with_accuracy(acc)
            .state(closest, History::Approach, &Observables::LOAD)
            .unwrap();
        let back = m
            .clone()
            .with_accuracy(acc)
            .state(closest, History::Retract { closest }, &Observables::LOAD)
            .unwrap();
        assert!((at.load().unwrap() / back.load().unwrap() - 1.0).abs() < 1e-8);
    }
}

#[test]
fn rough_surface_pull_off_grows_with_the_closest_approach() {
    let acc = Accuracy::new(1e-8).unwrap();
    let law = Arc::new(AdhesivePlastic::new(ke().as_loading(), 0.5).unwrap());
    let m = model(law);
    let mut last = 0.0;
    for hc in [1.0, 0.0, -1.0, -2.0] {
        let p = m
            .clone()
            .with_accuracy(acc)
            .pull_off(hc * SIGMA, f64::INFINITY, 120)
            .unwrap()
            .unwrap()
            .load;
        eprintln!("closest {hc} sigma: pull-off {p:e} N");
        assert!(p < last, "closest {hc}: {p} vs {last}");
        last = p;
    }
    // Without plasticity (huge H) the wrapper is JKR: Fuller-Tabor exactly.
    let stiff = Plasticity::new(1e15, None, 0.42).unwrap();
    let elastic = build(Variant::KogutEtsion, R, E, stiff).unwrap();
    let a = model(Arc::new(
        AdhesivePlastic::new(elastic.as_loading(), 0.5).unwrap(),
    ));
    let b = model(Arc::new(Jkr::new(R, E, 0.5).unwrap()));
    let acc = acc.with_method(Method::Quadrature);
    for h in [-1.0, 0.5] {
        let back = History::Retract { closest: -SIGMA };
        let x = a
            .clone()
            .with_accuracy(acc)
            .state(h * SIGMA, back, &Observables::ALL)
            .unwrap();
        let y = b
            .clone()
            .with_accuracy(acc)
            .state(h * SIGMA, back, &Observables::ALL)
            .unwrap();
        assert!(
            (x.load().unwrap() / y.load().unwrap() - 1.0).abs() < 1e-9,
            "{x:?} {y:?}"
        );
    }
}

#[test]
fn monte_carlo_radius_scaling_is_exact_for_plastic_laws() {
    // 2000 summits, heights and radii spread; the scaled law against laws
    // built per summit radius, summed by hand, on approach and retraction.
    let n = 2000;
    let heights: Vec<f64> = (0..n)
        .map(|i| SIGMA * Gaussian::new().quantile((i as f64 + 0.5) / n as f64))
        .collect();
    let radii: Vec<f64> = (0..n)
        .map(|i| R * (0.5 + 1.5 * ((i * 7919) % n) as f64 / n as f64))
        .collect();
    let pop = Arc::new(Population::from_summits(heights, Radii::PerSummit(radii)).unwrap());
    let scaling = RadiusScaling {
        interference: 1.0,
        load: 2.0,
        contact_radius: 1.0,
    };
    for v in Variant::ALL {
        let r_ref = pop.reference_radius();
        let law = build(v, r_ref, E, Plasticity::gold()).unwrap();
        let mc = MonteCarlo::new(
            pop.clone(),
            SummitLaw::scaled(law.as_law(), r_ref, scaling).unwrap(),
        )
        .unwrap();
        let (d, closest) = (0.5 * SIGMA, -SIGMA);
        for history in [History::Approach, History::Retract { closest }] {
            let st = mc.state(d, history, &Observables::ALL).unwrap();
            let (mut load, mut area) = (0.0, 0.0);
            for i in 0..pop.len() {
                let l = build(v, pop.radius(i), E, Plasticity::gold()).unwrap();
                let z = pop.heights()[i];
                let s = match history {
                    History::Approach => l.state(z - d, asperity::law::Branch::Approach),
                    History::Retract { closest } => l.state_after(z - d, z - closest),
                };
                load += s.load;
                area += s.area();
            }
            let (el, ea) = (
                st.load().unwrap() / load - 1.0,
                st.area().unwrap() / area - 1.0,
            );
            assert!(
                el.abs() < 1e-12 && ea.abs() < 1e-12,
                "{v:?} {history:?}: {el:e} {ea:e}"
            );
        }
    }
}

#[test]
fn per_asperity_memory_gives_cycles() {
    let law = ke();
    let wc = law.critical_interference();
    let mut m = MaxInterference::default();
    let path = [12.0, 20.0, 12.0, 20.0, 40.0, 12.0];
    let loads: Vec<f64> = path
        .iter()
        .map(|w| m.step(law.as_ref(), w * wc).load)
        .collect();
    assert!(loads[2] < loads[0], "{loads:?}");
    assert_eq!(loads[3], loads[1]);
    assert!(loads[2] > 0.0 && loads[5] < loads[2], "{loads:?}");
}

#[test]
fn diagnostics_fractions_and_warning() {
    let p = Plasticity::gold();
    let psi = plasticity_index(E, p.hardness(), SIGMA, R).unwrap();
    assert!((psi - 3.03).abs() < 0.01);
    assert!(elastic_law_warning("hertz", psi)
        .unwrap()
        .to_string()
        .contains("psi = 3.028"));
    assert!(elastic_law_warning("hertz", 0.8).is_none());
    let law = ke();
    let g = Gaussian::new();
    let f = contact_fractions(&law.regime_limits(), SIGMA, 0.0, &g);
    assert!((f.elastic + f.elastic_plastic + f.fully_plastic - 1.0).abs() < 1e-14);
    assert!((f.contacts_per_summit - 0.5).abs() < 1e-15);
    // omega_c ~ 0.106 sigma: the elastic fraction is P(0 < s < 0.106)/0.5.
    let wc = law.critical_interference();
    let expect = (0.5 - g.tail(wc / SIGMA)) / 0.5;
    assert!((f.elastic - expect).abs() < 1e-15);
    assert!(f.elastic < 0.1 && f.elastic_plastic > 0.8, "{f:?}");
    // Far apart: no contact, all zero.
    let none = contact_fractions(&law.regime_limits(), SIGMA, 50.0 * SIGMA, &g);
    assert_eq!(
        none.elastic + none.elastic_plastic + none.fully_plastic,
        0.0
    );
}
