//! Elastic-plastic asperities against the independent mpmath
//! evaluation in tests/data/plastic.py (40 digits; formulas from
//! docs/physics.md, written independently of the Rust code):
//! - each law's load and contact radius at 1e-12 relative, on both sides of
//!   every breakpoint; the unloading curve and the JKR pull-off after
//!   plastic loading likewise;
//! - GW totals over Gaussian heights through `GwModel` (adaptive quadrature
//!   at rtol 1e-10) against mpmath quadrature at 1e-8 relative, on approach
//!   and on retraction, across the breakpoints;
//! - limits: psi -> 0 is elastic GW exactly; fully plastic contact P = H A.
use asperity::gw::{Accuracy, GwModel, Method, RoughSurface};
use asperity::heights::Gaussian;
use asperity::law::plastic::{build, AdhesivePlastic, PlasticLaw};
use asperity::law::{Branch, Control, Hertz, LawKernels};
use asperity::loading::{History, LoadingModel, Observables};
use asperity::material::plastic::{Plasticity, Variant};
use asperity::named::Named;
use serde_json::Value;
use std::sync::Arc;

fn reference() -> Value {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/plastic.json"
    ))
    .unwrap();
    serde_json::from_str(&text).unwrap()
}

fn law_of(doc: &Value, set: &str, name: &str) -> Arc<dyn PlasticLaw> {
    let s = &doc["sets"][set];
    let f = |k: &str| s[k].as_f64().unwrap();
    let p = Plasticity::new(f("Y"), s["H"].as_f64(), f("nu")).unwrap();
    build(Variant::parse(name).unwrap(), f("R"), f("E"), p).unwrap()
}

fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / b.abs()
    }
}

#[test]
fn laws_match_mpmath_at_1e12() {
    let doc = reference();
    let mut worst: f64 = 0.0;
    for v in doc["laws"].as_array().unwrap() {
        let law = law_of(&doc, v["set"].as_str().unwrap(), v["law"].as_str().unwrap());
        let d = v["delta"].as_f64().unwrap();
        let s = law.state(d, Branch::Approach);
        let (ep, ea) = (
            rel(s.load, v["load"].as_f64().unwrap()),
            rel(s.radius, v["radius"].as_f64().unwrap()),
        );
        assert!(ep < 1e-12 && ea < 1e-12, "{v}: {s:?} ({ep:e}, {ea:e})");
        worst = worst.max(ep).max(ea);
    }
    eprintln!("laws: worst relative error {worst:e}");
}

#[test]
fn unloading_and_pull_off_match_mpmath_at_1e12() {
    let doc = reference();
    let mut worst: f64 = 0.0;
    for v in doc["unloading"].as_array().unwrap() {
        let law = law_of(&doc, v["set"].as_str().unwrap(), v["law"].as_str().unwrap());
        let (d, dm) = (
            v["delta"].as_f64().unwrap(),
            v["delta_max"].as_f64().unwrap(),
        );
        let s = law.state_after(d, dm);
        let (p, a) = (v["load"].as_f64().unwrap(), v["radius"].as_f64().unwrap());
        let (ep, ea) = (rel(s.load, p), rel(s.radius, a));
        assert!(ep < 1e-12 && ea < 1e-12, "{v}: {s:?}");
        worst = worst.max(ep).max(ea);
    }
    for v in doc["pull_off"].as_array().unwrap() {
        let law = law_of(&doc, v["set"].as_str().unwrap(), v["law"].as_str().unwrap());
        let adh = AdhesivePlastic::new(law.as_loading(), v["work"].as_f64().unwrap()).unwrap();
        let dm = v["delta_max"].as_f64().unwrap();
        let p = adh.pull_off_after(dm, Control::Load).load;
        let e = rel(p, v["pull_off"].as_f64().unwrap());
        assert!(e < 1e-12, "{v}: {p}");
        worst = worst.max(e);
    }
    eprintln!("unloading and pull-off: worst relative error {worst:e}");
}

fn gold_model(law: Arc<dyn LawKernels>) -> GwModel {
    // One summit per unit area and unit area: totals per summit.
    let surface = RoughSurface::new(1.0, 1e-6, 5e-9, 1.0).unwrap();
    GwModel::new(surface, Arc::new(Gaussian::new()), law).unwrap()
}

#[test]
fn gw_sums_match_mpmath_quadrature_at_1e8() {
    let doc = reference();
    let acc = Accuracy::new(1e-10)
        .unwrap()
        .with_method(Method::Quadrature);
    let mut worst: f64 = 0.0;
    for v in doc["gw"].as_array().unwrap() {
        let law = law_of(&doc, "gold", v["law"].as_str().unwrap());
        let model = gold_model(law.as_law());
        let d = v["separation"].as_f64().unwrap();
        let history = match v["closest"].as_f64() {
            Some(c) => History::Retract { closest: c },
            None => History::Approach,
        };
        let st = model
            .clone()
            .with_accuracy(acc)
            .state(d, history, &Observables::ALL)
            .unwrap();
        for (got, key) in [
            (st.load(), "load"),
            (st.area(), "area"),
            (st.count(), "count"),
        ] {
            let e = rel(got.unwrap(), v[key].as_f64().unwrap());
            assert!(e < 1e-8, "{v} {key}: {got:?} ({e:e})");
            worst = worst.max(e);
        }
    }
    eprintln!("GW: worst relative error {worst:e}");
}

#[test]
fn vanishing_plasticity_index_recovers_elastic_gw_exactly() {
    // H -> huge: omega_c far beyond every summit within the support.
    let p = Plasticity::new(1e15, None, 0.42).unwrap();
    let acc = Accuracy::new(1e-10)
        .unwrap()
        .with_method(Method::Quadrature);
    let hertz = gold_model(Arc::new(Hertz::new(1e-6, 4.796e10).unwrap()));
    for v in Variant::ALL {
        let model = gold_model(build(v, 1e-6, 4.796e10, p).unwrap().as_law());
        for h in [-2.0, 0.0, 1.5] {
            for history in [
                History::Approach,
                History::Retract {
                    closest: -3.0 * 5e-9,
                },
            ] {
                let a = model
                    .clone()
                    .with_accuracy(acc)
                    .state(h * 5e-9, history, &Observables::ALL)
                    .unwrap();
                let b = hertz
                    .clone()
                    .with_accuracy(acc)
                    .state(h * 5e-9, history, &Observables::ALL)
                    .unwrap();
                assert_eq!(
                    (a.load(), a.area(), a.count()),
                    (b.load(), b.area(), b.count()),
                    "{v:?}"
                );
            }
        }
    }
}

#[test]
fn fully_plastic_surface_carries_hardness_times_real_area() {
    // Tiny omega_c (soft, yields at once): every contact beyond 110 omega_c
    // except a sliver; KE and ZMC give P = H A there exactly.
    let p = Plasticity::new(2e6, None, 0.42).unwrap();
    let acc = Accuracy::new(1e-10)
        .unwrap()
        .with_method(Method::Quadrature);
    for v in [Variant::KogutEtsion, Variant::ZhaoMaiettaChang] {
        let law = build(v, 1e-6, 4.796e10, p).unwrap();
        let wc = law.critical_interference();
        assert!(110.0 * wc < 1e-3 * 5e-9, "{wc}");
        let model = gold_model(law.as_law());
        let st = model
            .clone()
            .with_accuracy(acc)
            .state(0.0, History::Approach, &Observables::ALL)
            .unwrap();
        let ratio = st.load().unwrap() / (p.hardness() * st.area().unwrap());
        // The elastic and elastic-plastic sliver (delta < 110 omega_c) holds a
        // fraction ~(110 omega_c/sigma)^2 of the area.
        assert!((ratio - 1.0).abs() < 1e-6, "{v:?}: {ratio}");
        eprintln!("{v:?}: P/(H A) - 1 = {:e}", ratio - 1.0);
    }
}
