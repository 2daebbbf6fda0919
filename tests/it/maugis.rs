//! Exact Maugis–Dugdale against independent references and its limits.
use asperity::law::maugis::MaugisCurve;
use asperity::law::{jkr, AsperityLaw, Branch, Control, Maugis};
use serde_json::Value;

fn reference() -> Value {
    let text = include_str!(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/maugis_pull_off.json"
    ));
    serde_json::from_str(text).expect("maugis_pull_off.json")
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// mpmath (40 digits, parametrised by A, tests/data/maugis_pull_off.py)
/// against the Rust solution (parametrised by the angle t): 1e-9 relative.
#[test]
fn matches_mpmath_reference_to_1e9() {
    let data = reference();
    let values = data["values"].as_array().unwrap();
    assert!(values.len() >= 7);
    let mut worst: f64 = 0.0;
    for v in values {
        let l = v["lambda"].as_f64().unwrap();
        let c = MaugisCurve::new(l).unwrap();
        let pull = c.pull_off_bar();
        let r = &v["pull_off"];
        for (got, want) in [
            (pull.load_bar, r["load"].as_f64().unwrap()),
            (pull.radius_bar, r["radius"].as_f64().unwrap()),
            (pull.interference_bar, r["interference"].as_f64().unwrap()),
            (
                c.zero_load_bar().radius_bar,
                v["zero_load_radius"].as_f64().unwrap(),
            ),
        ] {
            worst = worst.max(rel(got, want));
            assert!(rel(got, want) < 1e-9, "lambda {l}: {got} vs {want}");
        }
        let j = &v["jump_out"];
        let out = c.jump_out_bar();
        let in_contact = j["branch"] == "contact";
        assert_eq!(out.radius_bar > 0.0, in_contact, "lambda {l}");
        for (got, want) in [
            (out.load_bar, j["load"].as_f64().unwrap()),
            (out.interference_bar, j["interference"].as_f64().unwrap()),
        ] {
            worst = worst.max(rel(got, want));
            assert!(rel(got, want) < 1e-9, "lambda {l}: {got} vs {want}");
        }
        if in_contact {
            let want = j["radius"].as_f64().unwrap();
            // The fold radius is a root of dDbar/dA = 0: sqrt(eps)-limited
            // in the reference's numerical derivative, not in ours.
            assert!(rel(out.radius_bar, want) < 1e-7, "lambda {l}");
        }
    }
    eprintln!("worst relative error against mpmath: {worst:e}");
}

/// physics.md's checked values, to their printed digits.
#[test]
fn matches_checked_values_of_physics_md() {
    for (l, p) in [
        (0.1, -1.9506),
        (0.5, -1.7182),
        (1.0, -1.6007),
        (2.0, -1.5346),
        (5.0, -1.5063),
        (10.0, -1.5016),
    ] {
        let got = MaugisCurve::new(l).unwrap().pull_off_bar().load_bar;
        assert!((got - p).abs() <= 0.5e-4, "lambda {l}: {got} vs {p}");
    }
}

/// lambda -> 0: DMT (-2, zero-load radius 2^(1/3)); the error shrinks
/// monotonically as lambda decreases.
#[test]
fn tends_to_dmt_monotonically() {
    let mut last = (f64::INFINITY, f64::INFINITY);
    for l in [1.0, 0.3, 0.1, 0.03, 0.01, 3e-3, 1e-3] {
        let c = MaugisCurve::new(l).unwrap();
        let e_pull = (c.pull_off_bar().load_bar + 2.0).abs();
        let e_a0 = (c.zero_load_bar().radius_bar - 2f64.cbrt()).abs();
        assert!(e_pull < last.0 && e_a0 < last.1, "lambda {l}");
        last = (e_pull, e_a0);
    }
    assert!(last.0 < 1e-4 && last.1 < 1e-2, "{last:?}");
}

/// lambda -> inf: JKR (-3/2; jump-out -5/6 at -(3/4)(4/3)^(2/3);
/// zero-load radius 6^(1/3)); every error shrinks monotonically.
#[test]
fn tends_to_jkr_monotonically() {
    let mut last = [f64::INFINITY; 4];
    for l in [2.0, 5.0, 10.0, 30.0, 100.0, 300.0, 1e3] {
        let c = MaugisCurve::new(l).unwrap();
        let out = c.jump_out_bar();
        let e = [
            (c.pull_off_bar().load_bar - jkr::PULL_OFF_LOAD).abs(),
            (out.load_bar - jkr::JUMP_OUT_LOAD).abs(),
            (out.interference_bar - jkr::JUMP_OUT_INTERFERENCE).abs(),
            (c.zero_load_bar().radius_bar - jkr::ZERO_LOAD_RADIUS).abs(),
        ];
        for k in 0..4 {
            assert!(
                e[k] < last[k],
                "lambda {l}, quantity {k}: {} !< {}",
                e[k],
                last[k]
            );
        }
        last = e;
    }
    assert!(last.iter().all(|&e| e < 1e-4), "{last:?}");
}

/// Approach and retract loops of the dimensional law.
#[test]
fn hysteresis_loop_is_consistent() {
    for l in [0.05, 0.5, 0.8, 1.0, 3.0, 50.0] {
        let law = Maugis::new(1e-6, 5e10, 0.5, l).unwrap();
        let s = law.scales().interference;
        let (att, det) = (law.attach_interference(), law.detach_interference());
        assert!(det < att);
        // Free on approach just below the attach point, attached just above.
        assert_eq!(law.load(att - 1e-9 * s, Branch::Approach), 0.0);
        assert!(law.load(att + 1e-9 * s, Branch::Approach) < 0.0);
        // Attached on retraction down to the detach point, free below.
        assert!(law.load(det + 1e-9 * s, Branch::Retract) < 0.0);
        assert_eq!(law.load(det - 1e-9 * s, Branch::Retract), 0.0);
        let p = law.pull_off(Control::Displacement).unwrap();
        assert!((p.interference - det).abs() < 1e-15 * s);
        // state_after: retract branch once the attach point was reached.
        let mid = 0.5 * (att + det);
        assert_eq!(
            law.state_after(mid, att - 1e-3 * s),
            law.state(mid, Branch::Approach)
        );
        assert_eq!(
            law.state_after(mid, att + 1e-3 * s),
            law.state(mid, Branch::Retract)
        );
    }
}
