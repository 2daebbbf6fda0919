//! src/electrical against independent mpmath values (tests/data/electrical.py),
//! Barber's identity, the Wexler limits and the exact many-spot solution.

use crate::common::gw_spots::GwSpots;
use crate::common::{local, num, rel, shared};
use asperity::electrical::greenwood_mean_field;
use asperity::electrical::heating::Heating;
use asperity::electrical::{Conductor, Interaction, SpotResistance, Spots, Spreading, C_SQ};
use asperity::heights::Gaussian;
use asperity::law::{Branch, LawKind};
use asperity::material::AsperityContact;
use proptest::prelude::*;
use serde_json::Value;
use std::sync::Arc;

/// Agreement asked by the issue for every resistance.
const TOL: f64 = 1e-9;

/// The spot models of the reference file, by its names.
fn models(r: &Value) -> Vec<(&'static str, SpotResistance)> {
    let (rho, l) = (num(&r["resistivity"]), num(&r["mean_free_path"]));
    let gold = Conductor::new(rho, Some(l)).unwrap();
    let copper = Conductor::new(num(&r["resistivity2"]), Some(num(&r["mean_free_path2"]))).unwrap();
    let film = num(&r["film_resistance"]);
    let one = |s| SpotResistance::new(s, gold, gold, 0.0).unwrap();
    let two = |s| SpotResistance::new(s, gold, copper, 0.0).unwrap();
    vec![
        ("maxwell", one(Spreading::Maxwell)),
        ("sharvin", one(Spreading::Sharvin)),
        ("wexler", one(Spreading::Wexler)),
        (
            "wexler_film",
            SpotResistance::new(Spreading::Wexler, gold, gold, film).unwrap(),
        ),
        ("maxwell_two_metals", two(Spreading::Maxwell)),
        ("sharvin_two_metals", two(Spreading::Sharvin)),
        ("wexler_two_metals", two(Spreading::Wexler)),
    ]
}

#[test]
fn single_spots_match_mpmath() {
    let r = local("electrical.json");
    let mut worst: f64 = 0.0;
    for row in r["single_spot"].as_array().unwrap() {
        let a = num(&row["radius_m"]);
        for (name, m) in models(&r) {
            let e = rel(m.resistance(a), num(&row[name]));
            assert!(e < TOL, "{name} a={a}: {e:e}");
            worst = worst.max(e);
        }
    }
    eprintln!("single spots: worst relative error {worst:e}");
}

#[test]
fn single_spots_match_the_shared_wexler_table() {
    let Some(t) = shared("contact_resistance.json") else {
        return;
    };
    let (rho, a) = (2.44e-8, 1e-7);
    for row in t["table"].as_array().unwrap() {
        let k = num(&row["K"]);
        let spot = SpotResistance::same_metal(Spreading::Wexler, rho, Some(k * a));
        let Ok(w) = spot else { continue }; // K = 0: no mean free path
        let ratio = w.resistance(a) / (rho / (2.0 * a));
        assert!(
            rel(ratio, num(&row["R_Wexler_over_R_Maxwell"])) < 1e-13,
            "K={k}"
        );
    }
}

#[test]
fn c_sq_matches_mpmath() {
    let r = local("electrical.json");
    assert!(rel(C_SQ, num(&r["c_sq"])) < 1e-15);
}

fn gw_surface(g: &Value) -> GwSpots {
    GwSpots::new(
        num(&g["count"]),
        num(&g["summit_radius_m"]),
        num(&g["sigma_m"]),
        num(&g["nominal_area_m2"]),
        Arc::new(Gaussian::new()),
    )
    .unwrap()
}

#[test]
fn gw_parallel_spots_and_greenwood_mean_field_match_mpmath() {
    let r = local("electrical.json");
    let g = &r["gw_gaussian_hertz"];
    let gw = gw_surface(g);
    let mut worst: f64 = 0.0;
    for row in g["rows"].as_array().unwrap() {
        let h = num(&row["h"]);
        for (name, m) in models(&r) {
            let want = &row[name];
            let sums = gw.hertz_sums(&m, h);
            let none = gw.hertz_resistance(&m, Interaction::None, h);
            let green = gw.hertz_resistance(&m, Interaction::Greenwood, h);
            let term = greenwood_mean_field(m.mutual_resistivity(), gw.side(), &sums);
            let checks = [
                (sums.contacts, num(&row["contacts"])),
                (sums.conductance, num(&want["conductance_S"])),
                (sums.conductance_sq, num(&want["conductance_sq_S2"])),
                (none.resistance, num(&want["parallel_ohm"])),
                // Below ~1 contact 1 - sum G^2/(sum G)^2 < 0: clamped to 0.
                (term, num(&want["greenwood_term_ohm"]).max(0.0)),
            ];
            for (k, (got, exp)) in checks.into_iter().enumerate() {
                let e = rel(got, exp);
                assert!(e < TOL, "{name} h={h} check {k}: {got} vs {exp} ({e:e})");
                worst = worst.max(e);
            }
            if sums.contacts >= 2.0 {
                let e = rel(green.resistance, num(&want["greenwood_total_ohm"]));
                assert!(e < TOL, "{name} h={h} total: {e:e}");
                assert_eq!(green.interaction, Some(term));
            } else {
                assert!(green.interaction_skipped, "{name} h={h}");
                assert_eq!(green.resistance, none.resistance);
            }
        }
    }
    eprintln!("GW sums: worst relative error {worst:e}");
}

fn spots_of(set: &Value) -> Spots {
    let pts = set["spots"].as_array().unwrap();
    let col = |k: usize| pts.iter().map(|p| num(&p[k])).collect::<Vec<_>>();
    Spots::new(col(0), col(1), col(2)).unwrap()
}

#[test]
fn explicit_spots_match_mpmath() {
    let r = local("electrical.json");
    let mut worst: f64 = 0.0;
    for set in r["explicit_spots"].as_array().unwrap() {
        let spots = spots_of(set);
        for (name, m) in models(&r) {
            let Some(want) = set.get(name) else { continue };
            let got = [
                spots.parallel(&m),
                spots.greenwood(&m),
                spots.exact(&m).unwrap(),
            ];
            for (g, key) in got
                .into_iter()
                .zip(["parallel_ohm", "greenwood_ohm", "exact_ohm"])
            {
                let e = rel(g, num(&want[key]));
                assert!(e < TOL, "{name} {key}: {e:e}");
                worst = worst.max(e);
            }
            // Thomson's principle: Greenwood's trial currents cannot beat
            // the equal-potential currents.
            assert!(got[2] <= got[1] * (1.0 + 1e-14), "{name}");
            assert!(got[0] < got[2], "{name}");
        }
    }
    eprintln!("explicit spots: worst relative error {worst:e}");
}

/// `n x n` jittered grid of spacing `s`, radii in `[0.5, 1.5] a0`.
fn grid(n: usize, s: f64, a0: f64) -> Spots {
    let (mut x, mut y, mut a) = (vec![], vec![], vec![]);
    for i in 0..n * n {
        let u = ((i * 7919) % 97) as f64 / 97.0;
        let v = ((i * 104729) % 89) as f64 / 89.0;
        x.push(((i % n) as f64 + 0.2 * u) * s);
        y.push(((i / n) as f64 + 0.2 * v) * s);
        a.push(a0 * (0.5 + ((i * 31) % 11) as f64 / 10.0));
    }
    Spots::new(x, y, a).unwrap()
}

#[test]
fn exact_solution_approaches_greenwood_as_spots_separate() {
    let m = SpotResistance::same_metal(Spreading::Maxwell, 2.44e-8, None).unwrap();
    let mut last = f64::INFINITY;
    for ratio in [10.0, 100.0, 1000.0, 10000.0] {
        let spots = grid(6, ratio * 1e-6, 1e-6);
        let (gw, ex) = (spots.greenwood(&m), spots.exact(&m).unwrap());
        let d = (gw - ex) / ex;
        eprintln!("spacing/radius {ratio}: (Greenwood - exact)/exact = {d:e}");
        assert!(d >= -1e-14, "{ratio}: {d:e}");
        // The difference is second order in the mutual/self ratio ~ a/s.
        assert!(d < 0.05 * last, "{ratio}: {d:e} after {last:e}");
        last = d;
    }
    assert!(last < 1e-7, "{last:e}");
}

#[test]
fn two_spots_have_the_two_by_two_result() {
    // Equal spots at distance s: R = rho/(4a) + rho/(2 pi s) (both exact and
    // Greenwood); far apart -> rho/(4a) (two Holm spots in parallel).
    let rho = 2.44e-8;
    let m = SpotResistance::same_metal(Spreading::Maxwell, rho, None).unwrap();
    for s in [3e-6, 1e-5, 1e-3] {
        let sp = Spots::new(vec![0.0, s], vec![0.0, 0.0], vec![1e-6, 1e-6]).unwrap();
        let want = rho / 4e-6 + rho / (2.0 * std::f64::consts::PI * s);
        assert!(rel(sp.exact(&m).unwrap(), want) < 1e-13);
        assert!(rel(sp.greenwood(&m), want) < 1e-13);
    }
}

#[test]
fn wexler_over_gw_tends_to_maxwell_and_sharvin() {
    let gw = GwSpots::new(1e4, 1e-6, 5e-9, 1e-8, Arc::new(Gaussian::new())).unwrap();
    let rho = 2.44e-8;
    let maxwell = SpotResistance::same_metal(Spreading::Maxwell, rho, None).unwrap();
    for h in [-1.0, 1.0, 3.0] {
        // Spots here are ~10-100 nm: l = 1e-14 m is K < 1e-5.
        let w = SpotResistance::same_metal(Spreading::Wexler, rho, Some(1e-14)).unwrap();
        let e = rel(
            gw.hertz_sums(&w, h).conductance,
            gw.hertz_sums(&maxwell, h).conductance,
        );
        assert!(e < 1e-5, "h={h}: {e:e}");
        // l = 1 mm: K > 1e4.
        let w = SpotResistance::same_metal(Spreading::Wexler, rho, Some(1e-3)).unwrap();
        let s = SpotResistance::same_metal(Spreading::Sharvin, rho, Some(1e-3)).unwrap();
        let e = rel(
            gw.hertz_sums(&w, h).conductance,
            gw.hertz_sums(&s, h).conductance,
        );
        assert!(e < 1e-3, "h={h}: {e:e}");
    }
}

#[test]
fn any_law_gives_spots_hertz_as_closed_form_jkr_larger() {
    let contact = AsperityContact::gold_microswitch();
    let r = contact.radius;
    let gw = GwSpots::new(1e4, r, 5e-9, 1e-8, Arc::new(Gaussian::new())).unwrap();
    let m = SpotResistance::same_metal(Spreading::Maxwell, 2.44e-8, None).unwrap();
    let hertz = LawKind::Hertz.build(&contact).unwrap();
    let jkr = LawKind::Jkr.build(&contact).unwrap();
    for h in [-1.0, 0.5, 2.0] {
        let closed = gw.hertz_sums(&m, h);
        let law = gw.law_sums(hertz.as_ref(), Branch::Approach, &m, h);
        assert!(rel(law.conductance, closed.conductance) < 1e-8, "h={h}");
        assert!(
            rel(law.conductance_sq, closed.conductance_sq) < 1e-8,
            "h={h}"
        );
        assert!(rel(law.contacts, closed.contacts) < 1e-8, "h={h}");
        // Adhesion enlarges every spot.
        let j = gw.law_sums(jkr.as_ref(), Branch::Retract, &m, h);
        assert!(j.conductance > closed.conductance, "h={h}");
    }
}

#[test]
fn heating_matches_mpmath() {
    let r = local("electrical.json");
    let t = &r["heating"];
    assert!(rel(asperity::electrical::heating::LORENZ, num(&t["lorenz"])) < 1e-15);
    for row in t["rows"].as_array().unwrap() {
        let h = Heating::new(num(&row["bulk_K"])).unwrap();
        let got = h.max_temperature(num(&row["voltage_V"])).unwrap();
        assert!(rel(got, num(&row["max_temperature_K"])) < 1e-14, "{row}");
    }
}

/// `-dP/dd` of the Hertz GW load by a 4th-order central difference in h.
fn stiffness(gw: &GwSpots, e_star: f64, m: &SpotResistance, sigma: f64, h: f64) -> f64 {
    let p = |x: f64| gw.hertz_state(e_star, m, Interaction::None, x * sigma).load;
    let dh = 1e-3;
    let d = (p(h - 2.0 * dh) - 8.0 * p(h - dh) + 8.0 * p(h + dh) - p(h + 2.0 * dh)) / (12.0 * dh);
    -d / sigma
}

proptest! {
    #![proptest_config(crate::common::proptest_config(200))]

    /// Barber (2003): for Hertz summits and independent Maxwell spots
    /// (same metal) G = (dP/dd)/(E* rho), over the whole parameter box; the
    /// stiffness comes from the load's F_3/2 by finite differences, the
    /// conductance from F_1/2.
    #[test]
    fn barber_identity(
        log_n in 0.0f64..8.0,
        log_r in -7.0f64..-4.0,
        log_s in -10.0f64..-6.0,
        log_e in 9.0f64..11.6,
        log_rho in -9.0f64..-6.0,
        h in -3.0f64..6.0,
    ) {
        let (n, r, s, e, rho) = (10f64.powf(log_n), 10f64.powf(log_r), 10f64.powf(log_s),
                                 10f64.powf(log_e), 10f64.powf(log_rho));
        let gw = GwSpots::new(n, r, s, 1e-8, Arc::new(Gaussian::new())).unwrap();
        let m = SpotResistance::same_metal(Spreading::Maxwell, rho, None).unwrap();
        let g = gw.hertz_sums(&m, h).conductance;
        let k = stiffness(&gw, e, &m, s, h);
        prop_assert!(rel(g, k / (e * rho)) < 1e-7, "G {g} vs {}", k / (e * rho));
    }

    /// One spot of any model: the explicit-spot resistances all equal the
    /// spot's own resistance (Holm's single spot).
    #[test]
    fn one_spot_is_its_own_resistance(
        log_a in -9.0f64..-3.0,
        log_l in -9.0f64..-6.0,
        model in 0usize..3,
    ) {
        let s = [Spreading::Maxwell, Spreading::Sharvin, Spreading::Wexler][model];
        let m = SpotResistance::same_metal(s, 2.44e-8, Some(10f64.powf(log_l))).unwrap();
        let a = 10f64.powf(log_a);
        let sp = Spots::new(vec![0.0], vec![0.0], vec![a]).unwrap();
        let want = m.resistance(a);
        prop_assert!(rel(sp.parallel(&m), want) < 1e-15);
        prop_assert!(rel(sp.greenwood(&m), want) < 1e-15);
        prop_assert!(rel(sp.exact(&m).unwrap(), want) < 1e-15);
    }

    /// Wexler lies between its limits: max(Sharvin, Gamma_inf Maxwell)
    /// <= R_W <= Sharvin + Maxwell, for every radius and mean free path.
    #[test]
    fn wexler_is_bounded_by_its_limits(log_a in -10.0f64..-3.0, log_l in -10.0f64..-5.0) {
        let (a, l, rho) = (10f64.powf(log_a), 10f64.powf(log_l), 2.44e-8);
        let w = asperity::electrical::spot::wexler(rho, l, a);
        let m = asperity::electrical::spot::maxwell(rho, a);
        let s = asperity::electrical::spot::sharvin(rho, l, a);
        prop_assert!(w <= (m + s) * (1.0 + 1e-15));
        prop_assert!(w >= s.max(0.83 / 1.33 * m) * (1.0 - 1e-15));
    }
}

fn oracle_surface() -> GwSpots {
    GwSpots::new(1e4, 1e-6, 1e-8, 1e-8, Arc::new(Gaussian::new())).unwrap()
}

#[test]
fn oracle_closed_forms_match_its_quadrature() {
    let gw = oracle_surface();
    let rho = 2.44e-8;
    let maxwell = SpotResistance::same_metal(Spreading::Maxwell, rho, None).unwrap();
    let sharvin = SpotResistance::same_metal(Spreading::Sharvin, rho, Some(3.46e-8)).unwrap();
    for spot in [maxwell, sharvin] {
        for h in [-1.0, 0.0, 1.5, 4.0] {
            let closed = gw.hertz_sums(&spot, h);
            let [g, g2] = gw.integrate(h, |t| spot.spot_conductance((1e-6 * 1e-8 * t).sqrt()));
            let quad = (1e4 * g, 1e4 * g2);
            assert!((closed.conductance / quad.0 - 1.0).abs() < 1e-10, "{h}");
            assert!((closed.conductance_sq / quad.1 - 1.0).abs() < 1e-10, "{h}");
        }
    }
}

#[test]
fn interaction_is_skipped_below_two_contacts() {
    let gw = oracle_surface();
    let spot = SpotResistance::same_metal(Spreading::Maxwell, 2.44e-8, None).unwrap();
    let far = gw.hertz_resistance(&spot, Interaction::Greenwood, 4.5);
    assert!(far.contacts < 2.0);
    assert!(far.interaction_skipped && far.interaction.is_none());
    assert_eq!(far.resistance, far.parallel);
    let near = gw.hertz_resistance(&spot, Interaction::Greenwood, 1.0);
    assert!(!near.interaction_skipped);
    assert!(near.interaction.unwrap() > 0.0);
    assert!(near.resistance > near.parallel);
}
