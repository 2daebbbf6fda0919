//! Persson's distribution of interfacial separations
//! (`Persson::gap_statistics`) against the mpmath reference of
//! `tests/data/persson_gaps.py` (20 digits, tanh-sinh quadrature nested
//! over the wavevector, `-dA/dq` by numerical differentiation, independent
//! code), and its own limits.
//!
//! Tolerances: 1e-8 relative. The crate integrates the outer wavevector
//! integral to 1e-10 and each inner mean gap to 1e-12; the nested error
//! adds at most a few 1e-10; mpmath's 20 digits are not the limit.

use asperity::capillary::{Meniscus, Regime};
use asperity::persson::Persson;
use asperity::spectrum::{Normalisation, Spectrum};
use serde_json::Value;
use std::process::Command;

fn num(v: &Value) -> f64 {
    match v {
        Value::String(s) => s.parse().unwrap(),
        _ => v.as_f64().unwrap(),
    }
}

fn model(r: &Value, gamma: f64) -> Persson {
    let s = Spectrum::self_affine(
        num(&r["hurst"]),
        num(&r["q_long"]),
        num(&r["q_roll"]),
        num(&r["q_short"]),
        Normalisation::HRms(num(&r["h_rms"])),
    )
    .unwrap();
    Persson::new(s, num(&r["estar"]), gamma).unwrap()
}

#[test]
fn gap_distribution_matches_mpmath() {
    let r: Value =
        serde_json::from_str(&std::fs::read_to_string("tests/data/persson_gaps.json").unwrap())
            .unwrap();
    let m = model(&r, num(&r["gamma"]));
    for c in r["cases"].as_array().unwrap() {
        let (p, h) = (num(&c["pressure"]), num(&c["height"]));
        let s = m.gap_statistics(p, h).unwrap();
        for (k, got) in [
            ("contact_fraction", s.contact_fraction),
            ("fraction_below", s.fraction_below),
            ("mean_gap", s.mean_gap),
            ("rms_gap", s.rms_gap),
        ] {
            let want = num(&c[k]);
            assert!(
                (got / want - 1.0).abs() < 1e-8,
                "{k} at p = {p:e}, H = {h:e}: {got} against {want}"
            );
        }
        // The distribution integrates to 1 (mpmath's own check too).
        assert!((num(&c["normalisation"]) - 1.0).abs() < 1e-15);
        assert!(s.error < 1e-9, "{}", s.error);
    }
}

/// `asperity persson --relative-humidity`: each state's wetted fraction is
/// the library's `P(u < h_m)`, the attraction `Delta p` times it, the ratio
/// `h_m/u_rms` and its regime; bad liquid input exits 2 naming the flag.
#[test]
fn persson_cli_with_humidity() {
    let r: Value =
        serde_json::from_str(&std::fs::read_to_string("tests/data/persson_gaps.json").unwrap())
            .unwrap();
    let run = |extra: &[&str]| {
        let mut a = vec![
            "persson",
            "--hurst",
            "0.8",
            "--q-long",
            "1e6",
            "--q-roll",
            "4e6",
            "--q-short",
            "1e8",
            "--h-rms",
            "1e-8",
            "--estar",
            "1e9",
            "--pressures",
            "1e5,1e6,1e7",
        ];
        a.extend_from_slice(extra);
        Command::new(env!("CARGO_BIN_EXE_asperity"))
            .args(&a)
            .output()
            .unwrap()
    };
    let o = run(&["--relative-humidity", "0.9", "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: Value = serde_json::from_str(String::from_utf8_lossy(&o.stdout).trim()).unwrap();
    let cap = &v["capillary"];
    let m = Meniscus::water(0.9).unwrap().unwrap();
    let hm = m.height();
    assert_eq!(cap["meniscus_height_m"].as_f64().unwrap(), hm);
    let model = model(&r, 1.0);
    let mut regimes = Vec::new();
    for s in cap["states"].as_array().unwrap() {
        let f = |k: &str| s[k].as_f64().unwrap();
        let g = model.gap_statistics(f("pressure_Pa"), hm).unwrap();
        assert_eq!(f("wetted_fraction"), g.fraction_below);
        assert_eq!(f("rms_gap_m"), g.rms_gap);
        assert_eq!(
            f("flooded_pressure_Pa"),
            m.laplace_pressure() * g.fraction_below
        );
        assert_eq!(f("ratio"), hm / g.rms_gap);
        let regime: Regime = match s["regime"].as_str().unwrap() {
            "per-summit" => Regime::PerSummit,
            "transition" => Regime::Transition,
            _ => Regime::Flooded,
        };
        assert_eq!(regime, Regime::of_ratio(hm / g.rms_gap));
        // The real contact is wet, and more besides.
        assert!(g.contact_fraction < g.fraction_below && g.fraction_below < 1.0);
        if regime == Regime::Transition {
            let ps = f("per_summit_pressure_Pa");
            assert_eq!(f("model_error"), ps / f("flooded_pressure_Pa") - 1.0);
        } else {
            assert!(s["model_error"].is_null());
        }
        regimes.push(regime);
    }
    // 1e5 and 1e6 Pa in the transition (ratios 0.26, 0.56), 1e7 flooded
    // (1.65), warned as such.
    assert_eq!(
        regimes,
        [Regime::Transition, Regime::Transition, Regime::Flooded]
    );
    let warnings = v["warnings"].to_string();
    assert!(
        warnings.contains("capillary state 2: flooded"),
        "{warnings}"
    );
    // Dry: no capillary key.
    let o = run(&["--json"]);
    let v: Value = serde_json::from_str(String::from_utf8_lossy(&o.stdout).trim()).unwrap();
    assert!(v.get("capillary").is_none());
    for (flags, name) in [
        (&["--relative-humidity", "1.5"][..], "--relative-humidity"),
        (
            &["--relative-humidity", "0.5", "--contact-angle-1", "200"][..],
            "--contact-angle-1",
        ),
        (
            &["--relative-humidity", "0.5", "--surface-tension", "-1"][..],
            "--surface-tension",
        ),
        (&["--temperature", "300"][..], "--relative-humidity"),
    ] {
        let o = run(flags);
        assert_eq!(o.status.code(), Some(2), "{flags:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains(name), "{flags:?}: {err}");
    }
}
