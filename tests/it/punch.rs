//! The wavy punch's exact curve, evolution and energy loss against the independent mpmath
//! computation tests/data/punch.json (tests/data/punch.py: P by Sneddon's integral with
//! mp.quad, folds and roots by mpmath's solver, loss by tanh-sinh quadrature; 30 digits) and
//! the shared reference tests/data/reference/kesari_lew.json.

use asperity::punch::{Evolution, WavyPunch};
use proptest::prelude::*;
use serde_json::Value;
use std::f64::consts::PI;

use crate::common::{local, num, rel, shared};

fn punch_of(c: &Value) -> WavyPunch {
    let f = |k: &str| num(&c[k]);
    WavyPunch::new(
        f("estar"),
        f("w"),
        f("radius"),
        f("amplitude"),
        f("wavelength"),
    )
    .unwrap()
}

/// Acceptance: exact P(a), h(a) at 1e-12 against mpmath. The scale of each quantity is its
/// largest term (`a^2/R` for h, `E* a^3/R` or the adhesive term for P), since both pass
/// through zero; measured worst: about 1e-15.
#[test]
fn exact_curve_matches_mpmath_to_1e12() {
    let d = local("punch.json");
    let mut worst = 0.0_f64;
    for (name, c) in d["curves"].as_object().unwrap() {
        let p = punch_of(c);
        for row in c["rows"].as_array().unwrap() {
            let a = num(&row["a"]);
            let s = p.state(a);
            let (h, load) = (num(&row["h"]), num(&row["P"]));
            let h_scale = a * a / p.radius() + (2.0 * PI * p.w() * a / p.estar()).sqrt();
            let p_scale =
                p.smooth_load(a).abs() + (8.0 * PI * p.w() * p.estar() * a.powi(3)).sqrt();
            let (eh, ep) = (
                (s.depth - h).abs() / h_scale,
                (s.load - load).abs() / p_scale,
            );
            assert!(eh < 1e-12, "{name} a {a}: h {} vs {h}: {eh:.1e}", s.depth);
            assert!(ep < 1e-12, "{name} a {a}: P {} vs {load}: {ep:.1e}", s.load);
            assert_eq!(p.depth(a), s.depth);
            worst = worst.max(eh).max(ep);
        }
    }
    println!("worst scaled error of h(a), P(a): {worst:.2e}");
}

#[test]
fn exact_curve_matches_the_shared_reference() {
    let Some(d) = shared("kesari_lew.json") else {
        return;
    };
    let c = &d["computed"];
    for (l, rows) in c["exact_sinusoidal_punch_curves"].as_object().unwrap() {
        let p = WavyPunch::new(1.0, 0.05 / (2.0 * PI), 1.0, 0.14, l.parse().unwrap()).unwrap();
        for row in rows.as_array().unwrap() {
            let a = num(&row["a_over_R"]);
            let s = p.state(a);
            // The reference keeps 15 significant digits.
            assert!(
                (s.depth - num(&row["h_over_R"])).abs() < 1e-14,
                "l {l} a {a}"
            );
            assert!(
                (s.load - num(&row["P_over_EstarR2"])).abs() < 1e-14,
                "l {l} a {a}"
            );
        }
    }
}

/// Loading and unloading radii at given depths, and the loss per cycle at 1e-6 relative
/// (measured: ~1e-12).
#[test]
fn evolution_and_energy_loss_match_mpmath() {
    let d = local("punch.json");
    for (name, c) in d["evolution"].as_object().unwrap() {
        let p = punch_of(c);
        let (h_min, h_max) = (num(&c["h_min"]), num(&c["h_max"]));
        let ev = Evolution::new(&p, h_max).unwrap();
        for row in c["rows"].as_array().unwrap() {
            let h = num(&row["h"]);
            let (al, au) = (num(&row["a_loading"]), num(&row["a_unloading"]));
            let (l, u) = (ev.loading(h), ev.unloading(h));
            assert!(
                (l.radius - al).abs() <= 1e-12 * p.radius(),
                "{name} h {h}: {} vs {al}",
                l.radius
            );
            assert!(
                (u.radius - au).abs() <= 1e-12 * p.radius(),
                "{name} h {h}: {} vs {au}",
                u.radius
            );
            assert_eq!(l.depth, h);
        }
        let loss = ev.energy_loss(h_min);
        let want = num(&c["loss"]);
        let rel = rel(loss, want);
        println!("{name}: loss {loss:.15e} vs mpmath {want:.15e}: rel {rel:.1e}");
        assert!(rel < 1e-6, "{name}: {loss} vs {want}");
    }
}

fn arb_punch() -> impl Strategy<Value = WavyPunch> {
    // The whole box of the paper's figures and beyond: 2 pi w/(E* R) in [0.005, 0.5],
    // A in [0.01, 0.3], l/R in [0.005, 0.5].
    (0.005f64..0.5, 0.01f64..0.3, 0.005f64..0.5).prop_map(|(wb, a, l)| {
        WavyPunch::new(2.0e3, wb * 2.0e3 * 0.1 / (2.0 * PI), 0.1, a, l * 0.1).unwrap()
    })
}

proptest! {
    #![proptest_config(crate::common::proptest_config(48))]

    /// Invariants over the parameter box: every path state is a stable equilibrium at its
    /// depth; radii grow with depth; unloading keeps at least the loading radius; the
    /// energy lost is positive.
    #[test]
    fn paths_are_stable_monotone_and_dissipative(p in arb_punch(), frac in 0.2f64..1.0) {
        let h_max = frac * 0.3 * p.radius() * 0.1;
        let ev = Evolution::new(&p, h_max).unwrap();
        let h_lo = ev.detach().unwrap().depth * 1.5;
        let mut last = (0.0, 0.0);
        for i in 0..=60 {
            let h = h_lo + (h_max - h_lo) * i as f64 / 60.0;
            let (l, u) = (ev.loading(h), ev.unloading(h));
            for s in [l, u] {
                if s.radius > 0.0 {
                    prop_assert!(p.depth_slope(s.radius) > -1e-9 * p.depth_slope(s.radius).abs().max(1.0));
                    prop_assert!((p.depth(s.radius) - h).abs() <= 1e-12 * p.radius());
                }
            }
            prop_assert!(l.radius >= last.0 && u.radius >= last.1);
            prop_assert!(u.radius >= l.radius);
            last = (l.radius, u.radius);
        }
        let loss = ev.energy_loss(h_lo);
        prop_assert!(loss > 0.0, "loss {loss}");
    }

    /// Envelopes bound the exact curve up to O(l) terms (eq. 3.18): with the A l shift of h
    /// and a margin of 2 A l + the O(l^(3/2)) remainder.
    #[test]
    fn envelopes_bound_the_exact_curve(p in arb_punch(), t in 0.05f64..1.0) {
        use asperity::punch::Envelope;
        let a = t * p.radius();
        let s = p.state(a);
        let (up, lo) = (p.envelope(a, Envelope::Loading), p.envelope(a, Envelope::Unloading));
        let l = p.wavelength();
        let slack_h = 2.0 * p.amplitude() * l + p.amplitude() * l * (l / a).sqrt() * 2.0;
        let slack_p = 2.0 * p.estar() * p.amplitude() * l * a * (l / a).sqrt() * 2.0;
        prop_assert!(s.depth <= up.depth + slack_h && s.depth >= lo.depth - slack_h);
        prop_assert!(s.load <= up.load + slack_p && s.load >= lo.load - slack_p);
    }
}
