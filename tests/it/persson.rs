//! Persson's theory and GW on an analytic spectrum against the mpmath
//! references of `tests/data/persson.py` (30 digits, tanh-sinh quadrature,
//! independent code).
//!
//! Tolerances: Persson's area and mean gap to 1e-9 relative (the
//! Gauss–Kronrod tolerance is 1e-12; erf and E1 are good to ~1e-15). GW's
//! area and gap to 1e-12 (closed-form `F_n` to ~1e-15, the separation
//! found to a few ulps). Moments to 1e-13 (closed forms on both sides).

use asperity::gw::GwOnMoments;
use asperity::persson::Persson;
use asperity::spectrum::{Normalisation, Spectrum};
use serde_json::Value;

fn num(v: &Value) -> f64 {
    match v {
        Value::String(s) => s.parse().unwrap(),
        _ => v.as_f64().unwrap(),
    }
}

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

#[test]
fn persson_and_gw_match_mpmath() {
    let text = std::fs::read_to_string("tests/data/persson.json").unwrap();
    let data: Value = serde_json::from_str(&text).unwrap();
    let mut worst = [0.0f64; 4];
    for c in data["cases"].as_array().unwrap() {
        let norm = if c["h_rms"].is_null() {
            Normalisation::SlopeRms(num(&c["slope_rms"]))
        } else {
            Normalisation::HRms(num(&c["h_rms"]))
        };
        let s = Spectrum::self_affine(
            num(&c["hurst"]),
            num(&c["q_long"]),
            num(&c["q_roll"]),
            num(&c["q_short"]),
            norm,
        )
        .unwrap();
        for (k, v) in [("m0", s.m0()), ("m2", s.m2()), ("m4", s.m4())] {
            assert!(rel(v, num(&c[k])) < 1e-13, "{k}: {v} vs {}", c[k]);
        }
        let e = num(&c["estar"]);
        let model = Persson::new(s.clone(), e, num(&c["gamma"])).unwrap();
        let u0 = model.mean_gap_slope();
        assert!(rel(u0, num(&c["mean_gap_slope"])) < 1e-9, "u0 {u0}");
        let uf = model.full_contact_energy();
        assert!(
            rel(uf, num(&c["full_contact_energy"])) < 1e-13,
            "U_full {uf}"
        );
        let gw = GwOnMoments::new(&s.moments().unwrap(), e, 1.0).unwrap();
        for st in c["states"].as_array().unwrap() {
            let p = num(&st["pressure"]);
            let ps = model.state(p).unwrap();
            let errs = [
                rel(ps.area_fraction, num(&st["area_fraction"])),
                rel(ps.mean_gap, num(&st["mean_gap"])),
            ];
            let g = gw.state(p).unwrap();
            let gerrs = [
                rel(g.area_fraction, num(&st["gw_area_fraction"])),
                rel(g.mean_gap, num(&st["gw_mean_gap"])),
            ];
            assert!(
                errs[0] < 1e-9 && errs[1] < 1e-9,
                "Persson at p = {p}: {errs:?}"
            );
            assert!(ps.mean_gap_error < 1e-9 * ps.mean_gap);
            assert!(
                gerrs[0] < 1e-12 && gerrs[1] < 1e-12,
                "GW at p = {p}: {gerrs:?}"
            );
            for (w, v) in worst.iter_mut().zip(errs.iter().chain(&gerrs)) {
                *w = w.max(*v);
            }
        }
    }
    eprintln!("worst relative errors: Persson area, gap; GW area, gap = {worst:?}");
}

#[test]
fn bad_inputs_name_their_parameter() {
    let s = Spectrum::self_affine(0.8, 1e5, 1e5, 1e8, Normalisation::HRms(1e-9)).unwrap();
    let m = Persson::new(s.clone(), 1e9, 1.0).unwrap();
    assert_eq!(m.state(-1.0).unwrap_err().field(), Some("pressure"));
    assert_eq!(m.state(f64::NAN).unwrap_err().field(), Some("pressure"));
    assert_eq!(
        Persson::new(s.clone(), 0.0, 1.0).unwrap_err().field(),
        Some("contact_modulus")
    );
    assert_eq!(
        Spectrum::self_affine(0.8, 1e5, 1e5, 1e4, Normalisation::HRms(1e-9))
            .unwrap_err()
            .field(),
        Some("q_short")
    );
    assert_eq!(
        Spectrum::self_affine(0.8, 1e5, 1e5, 1e8, Normalisation::SlopeRms(0.0))
            .unwrap_err()
            .field(),
        Some("slope_rms")
    );
    assert_eq!(
        m.persson_tosatti_number(-1.0).unwrap_err().field(),
        Some("adhesion_energy")
    );
}
