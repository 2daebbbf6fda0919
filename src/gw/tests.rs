//! Machinery checks on GW's exponential heights, whose `F_n` is exact
//! (`Gamma(n+1) e^-h`, h >= 0); the full distributions, and the
//! exponential's constant load/area/count ratios, are tested in `tests/`
//! (`gw_closed_forms.rs`).

use super::*;
use crate::heights::Exponential;
use crate::law::{Hertz, Jkr, LawKernels};
use crate::loading::{History, LoadingModel, LoadingProgram, MethodUsed, Observables};
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

/// Hertz and Kogut–Etsion summits of the gold surface `s` (laws smooth in
/// the root of their interference), and load, area and count with
/// [`AreaAgain`] (no closed form).
pub(crate) fn root_smooth_laws(
    s: &RoughSurface,
) -> (Arc<dyn LawKernels>, Arc<dyn LawKernels>, Observables) {
    use crate::law::plastic::build;
    use crate::material::plastic::{Plasticity, Variant};
    let hertz: Arc<dyn LawKernels> = Arc::new(Hertz::new(s.radius, 4.8e10).unwrap());
    let ke = build(Variant::KogutEtsion, s.radius, 4.796e10, Plasticity::gold())
        .unwrap()
        .as_law();
    let extra = Observables::ALL
        .with(crate::loading::Observable::Custom(Arc::new(AreaAgain)))
        .unwrap();
    (hertz, ke, extra)
}

/// Every total of `st` within `tol` of the reference `r` and within its
/// own error estimate (plus 1e-13 of the reference, the reference's own
/// error).
pub(crate) fn assert_within_tolerance_and_estimate(
    st: &crate::loading::State,
    r: &crate::loading::State,
    tol: f64,
    law: &str,
) {
    let d = st.separation;
    for k in 0..crate::loading::SLOTS {
        let (Some(a), Some(b)) = (st.totals.get(k), r.totals.get(k)) else {
            continue;
        };
        let e = st.totals.error(k).unwrap();
        assert!(
            (a - b).abs() <= tol * b.abs() && (a - b).abs() <= e + 1e-13 * b.abs(),
            "{law} tol {tol} d {d:e} slot {k}: {a} vs {b} (estimate {e:e})"
        );
    }
}

/// A per-asperity observable that forces quadrature (`pi a^2` again).
#[derive(Debug)]
struct AreaAgain;

impl crate::loading::PerAsperity for AreaAgain {
    fn name(&self) -> &str {
        "area_again"
    }
    fn value(&self, s: &crate::law::ContactState) -> f64 {
        s.area()
    }
}

/// The root rule (`Method::Auto` with an extra observable, Hertz smooth in
/// `sqrt(delta)`): on Gaussian and exponential heights, across and below
/// the bulk, every total within its tolerance of the closed forms, with
/// error estimates that cover the deviation; fewer evaluations at looser
/// tolerances no more than at tighter ones.
#[test]
fn root_rule_meets_the_tolerance_against_closed_forms() {
    use crate::heights::{Gaussian, HeightDistribution};
    use crate::loading::Observable;
    let s = RoughSurface::gold_microswitch();
    let hertz: Arc<dyn LawKernels> = Arc::new(Hertz::new(s.radius, 4.8e10).unwrap());
    let extra = Observables::ALL
        .with(Observable::Custom(Arc::new(AreaAgain)))
        .unwrap();
    let dists: [Arc<dyn HeightDistribution>; 2] =
        [Arc::new(Gaussian::new()), Arc::new(Exponential::new())];
    for dist in dists {
        let m = GwModel::new(s, dist.clone(), hertz.clone()).unwrap();
        let mut last = 0;
        for tol in [1e-3, 1e-6, 1e-8, 1e-11] {
            let acc = Accuracy::new(tol).unwrap();
            let mut evaluations = 0;
            for h in [-3.0, -0.7, 0.0, 0.5, 2.0, 6.0] {
                let d = h * s.sigma;
                let m = m.clone().with_accuracy(acc);
                let exact = m.state(d, History::Approach, &Observables::ALL).unwrap();
                assert_eq!(exact.method, MethodUsed::ClosedForm);
                let root = m.state(d, History::Approach, &extra).unwrap();
                assert_eq!(root.method, MethodUsed::Quadrature);
                evaluations += root.evaluations;
                let pairs = [
                    (root.load(), exact.load(), root.totals.error(0)),
                    (root.area(), exact.area(), root.totals.error(1)),
                    (root.count(), exact.count(), root.totals.error(2)),
                    (root.totals.get(3), exact.area(), root.totals.error(3)),
                ];
                for (a, b, e) in pairs {
                    let (a, b, e) = (a.unwrap(), b.unwrap(), e.unwrap());
                    let dev = (a - b).abs();
                    assert!(
                        dev <= tol * b.abs() + 1e-13 * b.abs(),
                        "{} tol {tol} h {h}: {a} vs {b}",
                        dist.name()
                    );
                    assert!(dev <= e + 1e-13 * b.abs(), "estimate {e} < {dev}");
                }
            }
            assert!(evaluations >= last, "{}: {evaluations}", dist.name());
            last = evaluations;
        }
    }
}

/// The fixed rules in the root serve a curve in batches: every state of
/// `states` is bit for bit the state computed alone, the batch and single
/// paths agree on method and evaluations, looser tolerances cost fewer
/// evaluations, and the Kogut–Etsion curve (pieces at its three jumps)
/// stays within the tolerance of the tightest adaptive curve.
#[test]
fn fixed_root_rules_in_batches_are_the_single_states() {
    use crate::heights::Gaussian;
    let s = RoughSurface::gold_microswitch();
    let (hertz, ke, extra) = root_smooth_laws(&s);
    let steps: Vec<(f64, History)> = (0..75)
        .map(|i| ((-3.0 + 0.1 * i as f64) * s.sigma, History::Approach))
        .collect();
    for (law, obs) in [(hertz, &extra), (ke, &Observables::ALL)] {
        let m = GwModel::new(s, Arc::new(Gaussian::new()), law).unwrap();
        let reference = m
            .clone()
            .with_accuracy(Accuracy::new(1e-12).unwrap())
            .states(&steps, obs)
            .unwrap();
        let mut last = usize::MAX;
        for tol in [1e-6, 1e-3] {
            let m = m.clone().with_accuracy(Accuracy::new(tol).unwrap());
            let batch = m.states(&steps, obs).unwrap();
            let mut evaluations = 0;
            for ((st, &(d, h)), r) in batch.iter().zip(&steps).zip(&reference) {
                let one = m.state(d, h, obs).unwrap();
                assert_eq!(st, &one, "{} tol {tol} d {d:e}", m.law().name());
                assert_eq!(st.method, MethodUsed::Quadrature);
                evaluations += st.evaluations;
                assert_within_tolerance_and_estimate(st, r, tol, m.law().name());
            }
            assert!(evaluations < last, "{}: {evaluations}", m.law().name());
            last = evaluations;
        }
    }
}
