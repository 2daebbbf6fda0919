//! the hysteresis energy follows the tolerance. JKR
//! asperities on Gaussian heights (Fuller & Tabor), against the mpmath
//! reference of tests/data/hysteresis_energy.py (30 digits; the energy
//! computed per asperity and then over heights, not over separation).
use asperity::gw::{Accuracy, GwModel, RoughSurface};
use asperity::heights::Gaussian;
use asperity::law::Jkr;
use asperity::loading::{hysteresis_energy_to, LoadingModel, LoadingProgram, Observables};
use std::f64::consts::PI;
use std::sync::Arc;

/// Units R = 1, K = 1 (E* = 3/4), pi w R = 1, N = 1: the interference unit
/// is 1, so sigma = k and energies are in N pi w R delta_unit.
fn model(k: f64, rtol: f64) -> GwModel {
    let (r, e, w) = (1.0, 0.75, 1.0 / PI);
    let surface = RoughSurface::new(1.0, r, k, 1.0).unwrap();
    GwModel::new(
        surface,
        Arc::new(Gaussian::new()),
        Arc::new(Jkr::new(r, e, w).unwrap()),
    )
    .unwrap()
    .with_accuracy(Accuracy::new(rtol).unwrap())
}

#[test]
fn hysteresis_energy_meets_the_tolerance() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/hysteresis_energy.json"
    ))
    .unwrap();
    let doc: serde_json::Value = serde_json::from_str(&text).unwrap();
    for case in doc["cases"].as_array().unwrap() {
        let k = case["k_sigma_over_maugis_delta"].as_f64().unwrap();
        let (h_min, h_start) = (
            case["h_min"].as_f64().unwrap(),
            case["h_start"].as_f64().unwrap(),
        );
        let want = case["energy_over_N_pi_w_R_delta"].as_f64().unwrap();
        let program = LoadingProgram::new(h_start * k, h_min * k, 200).unwrap();
        for rtol in [1e-6, 1e-9] {
            let m = model(k, rtol);
            let got = hysteresis_energy_to(&m, &program, rtol).unwrap();
            let rel = (got / want - 1.0).abs();
            // The states are accurate to rtol against int |integrand|,
            // which here is within a factor of a few of the energy.
            assert!(
                rel < 10.0 * rtol,
                "k {k} rtol {rtol}: {got} vs {want} ({rel:e})"
            );
            if rtol == 1e-9 {
                let trapezoid = m
                    .curve(&program, &Observables::LOAD)
                    .unwrap()
                    .hysteresis_energy()
                    .unwrap();
                eprintln!(
                    "k {k}: adaptive {rel:.1e}, trapezoid on 200 points {:.1e}",
                    (trapezoid / want - 1.0).abs()
                );
            }
        }
    }
}

#[test]
fn no_hysteresis_without_adhesion_and_bad_rtol_is_refused() {
    let s = RoughSurface::gold_microswitch();
    let hertz = asperity::law::Hertz::new(s.radius, 5e10).unwrap();
    let m = GwModel::new(s, Arc::new(Gaussian::new()), Arc::new(hertz)).unwrap();
    let program = LoadingProgram::new(4.0 * s.sigma, 0.0, 50).unwrap();
    assert_eq!(hysteresis_energy_to(&m, &program, 1e-8).unwrap(), 0.0);
    let e = hysteresis_energy_to(&m, &program, 0.0).unwrap_err();
    assert_eq!(e.field(), Some("rtol"));
}
