//! The hard elastic–perfectly-plastic case (RMS gradient 0.08, `H = 0.1 E*`,
//! periodic 128^2) against ContactMechanics 1.8.3's plastic system on the
//! same map (`tests/data/bem_plastic_cm.py`, its output
//! `tests/data/bem_plastic_cm.json` stored as provenance).

use asperity::bem::{Options, Problem};
use asperity::surface::npy;
use serde_json::Value;

fn data(name: &str) -> String {
    format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// Every load up to `P = H` converges to 1e-8 within 500 applications of
/// `K`; where ContactMechanics converged, the same contact pixels (its
/// `jac > 0`, asperity's `p > 0`) and the same plastic pixels (its force
/// truncated to exactly `H dx^2`, asperity's `p = H`): fractions to 1e-6,
/// i.e. the same count on 16384 pixels.
#[test]
fn the_hard_case_against_contactmechanics() {
    let text = std::fs::read_to_string(data("bem_plastic_cm.json")).unwrap();
    let r: Value = serde_json::from_str(&text).unwrap();
    let map = npy::parse(&std::fs::read(data("bem_plastic_cm_map128.npy")).unwrap()).unwrap();
    let f = |k: &str| r[k].as_f64().unwrap();
    let (dx, e, h) = (f("pixel_size_m"), f("contact_modulus_Pa"), f("hardness_Pa"));
    let opts = Options {
        tolerance: 1e-8,
        max_iterations: 500,
        ..Options::default()
    };
    let prob = Problem::new(&map, dx, e, true, &opts)
        .unwrap()
        .with_hardness(h)
        .unwrap();
    let mut compared = 0;
    for load in r["loads"].as_array().unwrap() {
        let p = load["pressure_over_estar"].as_f64().unwrap() * e;
        let s = prob
            .solve_pressure(p, &opts, None)
            .unwrap_or_else(|err| panic!("P = {p:e}: {err}"));
        assert!(s.residual < 1e-8 && s.iterations <= 500, "P = {p:e}");
        if load["converged"] != Value::Bool(true) {
            continue;
        }
        compared += 1;
        let get = |k: &str| load[k].as_f64().unwrap();
        assert!(
            (s.area_fraction() - get("area_fraction")).abs() < 1e-6,
            "P = {p:e}: A/A0 {} vs ContactMechanics {}",
            s.area_fraction(),
            get("area_fraction")
        );
        assert!(
            (s.plastic_fraction() - get("plastic_fraction_at_hardness")).abs() < 1e-6,
            "P = {p:e}: A_pl/A0 {} vs ContactMechanics {}",
            s.plastic_fraction(),
            get("plastic_fraction_at_hardness")
        );
    }
    assert!(compared >= 3, "{compared}");
}
