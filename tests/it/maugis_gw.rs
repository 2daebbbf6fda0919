//! Maugis–Dugdale asperities in the Greenwood–Williamson integrator
//! (Morrow et al. 2003): the law's breakpoints let adaptive quadrature
//! converge on both branches, retraction is more tensile than approach, and
//! large lambda reproduces JKR asperities (Fuller–Tabor).
use asperity::gw::{Accuracy, GwModel, RoughSurface};
use asperity::heights::Exponential;
use asperity::law::{AsperityLaw, Jkr, LawKernels, Maugis};
use asperity::loading::{LoadingModel, LoadingProgram, Observables};
use std::sync::Arc;

fn model(law: Arc<dyn LawKernels>) -> GwModel {
    GwModel::new(
        RoughSurface::gold_microswitch(),
        Arc::new(Exponential::new()),
        law,
    )
    .unwrap()
}

#[test]
fn md_asperities_integrate_with_hysteresis() {
    let s = RoughSurface::gold_microswitch();
    let acc = Accuracy::new(1e-8).unwrap();
    // lambda below and above the continuous-detach threshold 0.938.
    for lambda in [0.2, 3.0] {
        let law = Arc::new(Maugis::new(s.radius, 1e9, 0.5, lambda).unwrap());
        // Start beyond the Dugdale range w/sigma0 (35 nm at lambda = 0.2):
        // every asperity must begin detached.
        let start = 6.0 * s.sigma - 1.5 * law.attach_interference();
        let program = LoadingProgram::new(start, 0.5 * s.sigma, 48).unwrap();
        let m = model(law);
        let c = m
            .clone()
            .with_accuracy(acc)
            .curve(&program, &Observables::ALL)
            .unwrap();
        for (a, r) in c.approach.iter().zip(&c.retract) {
            let (la, lr) = (a.load().unwrap(), r.load().unwrap());
            assert!(la.is_finite() && lr.is_finite());
            assert!(
                lr <= la + a.totals.error(0).unwrap() + r.totals.error(0).unwrap(),
                "lambda {lambda}: {a:?} {r:?}"
            );
        }
        let w = c.hysteresis_energy().unwrap();
        let gap: f64 = c
            .approach
            .iter()
            .zip(&c.retract)
            .map(|(a, r)| a.load().unwrap() - r.load().unwrap())
            .fold(0.0, f64::max);
        eprintln!("lambda {lambda}: hysteresis {w:e} J, largest load gap {gap:e} N");
        assert!(w > 0.0 && gap > 0.0, "lambda {lambda}: {w} {gap}");
    }
}

#[test]
fn large_lambda_reproduces_jkr_asperities() {
    let s = RoughSurface::gold_microswitch();
    let acc = Accuracy::new(1e-9).unwrap();
    let program = LoadingProgram::new(6.0 * s.sigma, 0.5 * s.sigma, 12).unwrap();
    let jkr = model(Arc::new(Jkr::new(s.radius, 1e9, 0.5).unwrap()));
    let cj = jkr
        .clone()
        .with_accuracy(acc)
        .curve(&program, &Observables::LOAD)
        .unwrap();
    let scale = cj
        .approach
        .iter()
        .chain(&cj.retract)
        .map(|x| x.load().unwrap().abs())
        .fold(0.0, f64::max);
    // MD attaches at -w/sigma0 = -2/(pi lambda) interference scales, JKR at
    // 0; asperities in that window give an O(1/lambda) difference, which
    // must shrink tenfold with lambda.
    let mut last = f64::INFINITY;
    for lambda in [10.0, 100.0, 1e3] {
        let md = model(Arc::new(Maugis::new(s.radius, 1e9, 0.5, lambda).unwrap()));
        let cm = md
            .clone()
            .with_accuracy(acc)
            .curve(&program, &Observables::LOAD)
            .unwrap();
        let worst = cm
            .approach
            .iter()
            .chain(&cm.retract)
            .zip(cj.approach.iter().chain(&cj.retract))
            .map(|(a, b)| (a.load().unwrap() - b.load().unwrap()).abs() / scale)
            .fold(0.0, f64::max);
        eprintln!("lambda {lambda}: worst |MD - JKR| / max |P| = {worst:e}");
        assert!(worst < 0.5 * last, "lambda {lambda}: {worst} vs {last}");
        last = worst;
    }
    assert!(last < 2e-3, "{last}");
}
