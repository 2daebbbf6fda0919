//! Machinery checks on GW's exponential heights, whose `F_n` is exact
//! (`Gamma(n+1) e^-h`, h >= 0); the full distributions, and the
//! exponential's constant load/area/count ratios, are tested in `tests/`
//! (`gw_closed_forms.rs`).

use super::*;
use crate::heights::Exponential;
use crate::law::{AsperityLaw, Hertz, Jkr};
use crate::loading::{History, LoadingModel, LoadingProgram, MethodUsed, Observables};
use std::sync::Arc;

fn model(law: Arc<dyn AsperityLaw>) -> GwModel {
    GwModel::new(
        RoughSurface::gold_microswitch(),
        Arc::new(Exponential::new()),
        law,
    )
    .unwrap()
}

#[test]
fn quadrature_reproduces_closed_form_for_hertz() {
    let s = RoughSurface::gold_microswitch();
    let m = model(Arc::new(Hertz::new(s.radius, 4.8e10).unwrap()));
    for tol in [1e-3, 1e-6, 1e-10] {
        let acc = Accuracy::new(tol).unwrap();
        for h in [0.0, 0.5, 2.0, 6.0] {
            let d = h * s.sigma;
            let exact = m
                .clone()
                .with_accuracy(acc)
                .state(d, History::Approach, &Observables::ALL)
                .unwrap();
            assert_eq!(exact.method, MethodUsed::ClosedForm);
            let quad = m
                .clone()
                .with_accuracy(acc.with_method(Method::Quadrature))
                .state(d, History::Approach, &Observables::ALL)
                .unwrap();
            for (a, b) in [
                (exact.load(), quad.load()),
                (exact.area(), quad.area()),
                (exact.count(), quad.count()),
            ] {
                let (a, b) = (a.unwrap(), b.unwrap());
                assert!(
                    (a - b).abs() <= tol * a.abs(),
                    "tol {tol} h {h}: {a} vs {b}"
                );
            }
        }
    }
}

#[test]
fn jkr_retraction_is_more_tensile_than_approach() {
    let s = RoughSurface::gold_microswitch();
    // Soft, sticky: strong hysteresis.
    let m = model(Arc::new(Jkr::new(s.radius, 1e9, 0.5).unwrap()));
    let acc = Accuracy::new(1e-8).unwrap();
    let program = LoadingProgram::new(8.0 * s.sigma, 0.5 * s.sigma, 40).unwrap();
    let c = m
        .clone()
        .with_accuracy(acc)
        .curve(&program, &Observables::ALL)
        .unwrap();
    for (a, r) in c.approach.iter().zip(&c.retract) {
        assert!(
            r.load().unwrap()
                <= a.load().unwrap() + a.totals.error(0).unwrap() + r.totals.error(0).unwrap(),
            "{a:?} {r:?}"
        );
    }
    assert!(c.hysteresis_energy().unwrap() > 0.0);
    let pull = m
        .clone()
        .with_accuracy(acc)
        .pull_off(0.5 * s.sigma, 8.0 * s.sigma, 60)
        .unwrap()
        .unwrap();
    assert!(pull.load < 0.0);
    assert!(pull.load <= c.sampled_pull_off().unwrap().load + 1e-12);
}

#[test]
fn bad_inputs_are_rejected() {
    let s = RoughSurface::gold_microswitch();
    let m = model(Arc::new(Hertz::new(s.radius, 4.8e10).unwrap()));
    let acc = Accuracy::new(1e-6).unwrap();
    assert!(m
        .clone()
        .with_accuracy(acc)
        .state(f64::NAN, History::Approach, &Observables::ALL)
        .is_err());
    let e = m
        .clone()
        .with_accuracy(acc)
        .state(0.0, History::Retract { closest: 1e-9 }, &Observables::ALL)
        .unwrap_err();
    assert_eq!(e.field(), Some("separation"));
    assert_eq!(Accuracy::new(0.5).unwrap_err().field(), Some("rel_tol"));
    assert_eq!(Accuracy::new(1e-16).unwrap_err().field(), Some("rel_tol"));
    let bradley = crate::law::Bradley::new(s.radius, 0.5, 3e-10).unwrap();
    let e = GwModel::new(s, Arc::new(Exponential::new()), Arc::new(bradley)).unwrap_err();
    assert_eq!(e.field(), Some("law"));
}

#[test]
fn unrequested_outputs_are_none() {
    let s = RoughSurface::gold_microswitch();
    let m = model(Arc::new(Jkr::new(s.radius, 1e9, 0.5).unwrap()));
    let acc = Accuracy::new(1e-6).unwrap();
    let st = m
        .clone()
        .with_accuracy(acc)
        .state(s.sigma, History::Approach, &Observables::LOAD)
        .unwrap();
    assert!(st.load().is_some() && st.area().is_none() && st.count().is_none());
}

#[test]
fn fixed_rule_converges_as_panels_grow() {
    let s = RoughSurface::gold_microswitch();
    let m = model(Arc::new(Hertz::new(s.radius, 4.8e10).unwrap()));
    let acc = Accuracy::new(1e-12).unwrap();
    let d = 0.7 * s.sigma;
    let exact = m
        .clone()
        .with_accuracy(acc)
        .state(d, History::Approach, &Observables::LOAD)
        .unwrap()
        .load()
        .unwrap();
    let mut last = f64::INFINITY;
    for panels in [1, 2, 8, 32] {
        let st = m
            .clone()
            .with_accuracy(acc.with_method(Method::Fixed { panels }))
            .state(d, History::Approach, &Observables::LOAD)
            .unwrap();
        assert_eq!(st.method, MethodUsed::Fixed);
        let err = (st.load().unwrap() - exact).abs() / exact;
        assert!(
            err < last || err < 1e-14,
            "panels {panels}: {err} after {last}"
        );
        last = err;
    }
    assert!(last < 1e-10, "{last}");
}
