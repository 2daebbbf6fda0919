//! The stickiness criteria (Pastewka–Robbins with its validity,
//! Persson–Tosatti, the Tabor parameter at `R = 1/h''`, Müser's `mu_rho`)
//! on a periodic map and on a spectrum, against numpy
//! (`tests/data/stickiness.py`), and the one number of Adhesion 0.93's
//! challenge example that depends on no surface: `mu_rho = 0.31811`.
//!
//! Tolerances: the map's moments are sums of 65,536 terms in a different
//! order (and FFTs of different libraries for the energy): 1e-12 relative;
//! the spectrum's moments are closed forms both sides: 1e-12.

use asperity::bem::{Options, Problem};
use asperity::spectrum::{Normalisation, Spectrum};
use asperity::stickiness::{AdhesiveInteraction, Criteria, Roughness};
use asperity::surface::npy;
use serde_json::Value;
use std::process::Command;

fn reference() -> Value {
    serde_json::from_str(&std::fs::read_to_string("tests/data/stickiness.json").unwrap()).unwrap()
}

fn close(got: f64, want: &Value, tol: f64, what: &str) {
    let want = want.as_f64().unwrap();
    assert!(
        (got / want - 1.0).abs() < tol,
        "{what}: {got} against {want} ({:e})",
        got / want - 1.0
    );
}

fn check(r: &Roughness, c: &Criteria, want: &Value, tol: f64) {
    for (got, key) in [
        (r.slope_rms, "slope_rms"),
        (r.curvature_rms, "curvature_rms"),
        (r.full_contact_energy, "full_contact_energy"),
        (r.pixel_size, "pixel_size"),
        (c.pastewka_robbins, "pastewka_robbins"),
        (c.g0, "g0"),
        (c.range_over_g0, "range_over_g0"),
        (c.persson_tosatti, "persson_tosatti"),
        (c.tabor, "tabor"),
        (c.mu_rho, "mu_rho"),
    ] {
        close(got, &want[key], tol, key);
    }
    assert_eq!(
        c.pastewka_robbins_valid,
        want["range_over_g0"].as_f64().unwrap() < 0.1
    );
}

fn interaction(want: &Value) -> AdhesiveInteraction {
    AdhesiveInteraction {
        contact_modulus: want["E"].as_f64().unwrap(),
        energy: want["w"].as_f64().unwrap(),
        range: want["rho"].as_f64().unwrap(),
    }
}

#[test]
fn map_criteria_against_numpy() {
    let want = &reference()["map"];
    let m = npy::parse(&std::fs::read("examples/data/selfaffine-256.npy").unwrap()).unwrap();
    let opts = Options::default();
    let prob = Problem::new(&m, 3.90625e-7, 1e9, true, &opts).unwrap();
    let r = prob.roughness();
    let c = Criteria::new(&r, &interaction(want)).unwrap();
    check(&r, &c, want, 1e-12);
    assert!(c.pastewka_robbins_valid);
    // mu_rho above Müser's 0.5 on this grid: warned.
    assert!(c.warnings(true).iter().any(|w| w.contains("mu_rho")));
    assert!(c.warnings(false).is_empty());
}

#[test]
fn spectrum_criteria_against_closed_forms() {
    let want = &reference()["spectrum"];
    let s = Spectrum::self_affine(0.8, 1e5, 4e5, 4e8, Normalisation::HRms(1e-8)).unwrap();
    let r = Roughness::of_spectrum(&s, 1e9).unwrap();
    let c = Criteria::new(&r, &interaction(want)).unwrap();
    check(&r, &c, want, 1e-12);
    // rho/g0 = 1.35: outside Pastewka–Robbins' validity, and said so.
    assert!(!c.pastewka_robbins_valid);
    let w = c.warnings(false);
    assert!(w.len() == 1 && w[0].contains("rho/g0 < 0.1"), "{w:?}");
}

#[test]
fn challenge_example_mu_rho() {
    let want = &reference()["challenge"];
    let r = Roughness {
        slope_rms: 1.0,
        curvature_rms: 1.0,
        full_contact_energy: 1.0,
        pixel_size: want["pixel_size"].as_f64().unwrap(),
    };
    let c = Criteria::new(&r, &interaction(want)).unwrap();
    close(c.mu_rho, &want["mu_rho"], 1e-14, "mu_rho");
    // Adhesion 0.93's example prints 0.31811 (five digits).
    assert!((c.mu_rho - 0.31811).abs() < 5e-6, "{}", c.mu_rho);
}

#[test]
fn bad_interaction_is_named() {
    let r = Roughness {
        slope_rms: 0.1,
        curvature_rms: 1e5,
        full_contact_energy: 1.0,
        pixel_size: 1e-7,
    };
    for (e, w, rho, name) in [
        (0.0, 0.05, 1e-9, "contact_modulus"),
        (1e9, -1.0, 1e-9, "adhesion_energy"),
        (1e9, 0.05, f64::NAN, "adhesion_range"),
    ] {
        let i = AdhesiveInteraction {
            contact_modulus: e,
            energy: w,
            range: rho,
        };
        let err = Criteria::new(&r, &i).unwrap_err();
        assert_eq!(err.field(), Some(name), "{err}");
    }
}

#[test]
fn cli_prints_the_criteria() {
    let run = |args: &[&str]| {
        let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
            .args(args)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    let map = &reference()["map"];
    let bem = [
        "bem",
        "examples/data/selfaffine-256.npy",
        "--pixel-size",
        "3.90625e-7",
        "--estar",
        "1e9",
        "--periodic",
        "--gaps",
        "2e-7",
        "--adhesion-energy",
        "0.05",
        "--adhesion-range",
        "2e-9",
    ];
    let text = run(&bem);
    for needle in ["Pastewka-Robbins", "Persson-Tosatti", "Tabor", "mu_rho"] {
        assert!(text.contains(needle), "{needle}: {text}");
    }
    let mut j = bem.to_vec();
    j.push("--json");
    let v: Value = serde_json::from_str(run(&j).trim()).unwrap();
    let c = &v["adhesion_criteria"];
    for key in ["pastewka_robbins", "persson_tosatti", "tabor", "mu_rho"] {
        close(c[key].as_f64().unwrap(), &map[key], 1e-12, key);
    }
    assert_eq!(c["pastewka_robbins_valid"], Value::Bool(true));
    let spec = &reference()["spectrum"];
    let v: Value = serde_json::from_str(
        run(&[
            &crate::common::cli::PERSSON_SPECTRUM[..],
            &[
                "--pressures",
                "1e6",
                "--adhesion-energy",
                "0.05",
                "--adhesion-range",
                "2e-9",
                "--json",
            ],
        ]
        .concat())
        .trim(),
    )
    .unwrap();
    let c = &v["adhesion_criteria"];
    for key in ["pastewka_robbins", "persson_tosatti", "tabor", "mu_rho"] {
        close(c[key].as_f64().unwrap(), &spec[key], 1e-12, key);
    }
    assert_eq!(c["pastewka_robbins_valid"], Value::Bool(false));
    assert!(v["warnings"].to_string().contains("rho/g0 < 0.1"));
}
