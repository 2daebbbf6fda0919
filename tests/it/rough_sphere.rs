//! The Greenwood–Tripp rough sphere (Hertz summits, Gaussian heights, in
//! Greenwood–Tripp units) against an independent solver
//! (`tests/data/rough_sphere.py`: Gauss–Legendre panels, the ring-load
//! kernel, scipy; each reference converged to < 5e-9 between two layouts),
//! the rigid limit `mu -> 0` against mpmath, and the Hertz limit at heavy
//! load.

use asperity::roughsphere::units::{
    hertz_approach_gt, hertz_load_fraction_radius, hertz_pressure_gt, hertz_radius_gt,
    rigid_load_gt,
};
use asperity::roughsphere::{GreenwoodTripp, SolverOptions};
use serde_json::Value;

fn reference() -> Value {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/rough_sphere.json"
    ))
    .unwrap();
    serde_json::from_str(&text).unwrap()
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap()
}

/// Every case of mu in {1e-3, 0.1, 1, 10, 100} x d in {-1, 0, 0.5, 2} at the
/// default tolerance (1e-6 on the load): the load and central deflection
/// within 1e-6, the pressure at rho in {0, 0.25, ..., 1} within 1e-5
/// (relative), and the load's error estimate never below the actual error
/// (measured up to 0.4 of it).
#[test]
fn agrees_with_the_independent_solver() {
    let r = reference();
    assert!(num(&r["product_weights_vs_quad"]) < 1e-13);
    let cases = r["cases"].as_array().unwrap();
    assert_eq!(cases.len(), 20);
    for c in cases {
        let (mu, d) = (num(&c["mu"]), num(&c["d"]));
        assert!(
            num(&c["layout_difference"]) < 1e-8,
            "reference not converged: {c}"
        );
        let refs = c["pressure"].as_array().unwrap();
        let rhos: Vec<f64> = refs.iter().map(|p| num(&p["rho"])).collect();
        let s = GreenwoodTripp::new(mu).unwrap().state(d, &rhos).unwrap();
        assert!(s.converged, "mu {mu} d {d}");
        let load = num(&c["load"]);
        let err = (s.load.value - load).abs();
        assert!(
            err <= 1e-6 * load,
            "mu {mu} d {d}: load {} vs {load}",
            s.load.value
        );
        assert!(
            err <= s.load.error,
            "mu {mu} d {d}: error {err:e} above its estimate {:e}",
            s.load.error
        );
        let u0 = num(&c["central_deflection"]);
        let e = (s.central_deflection.value - u0).abs();
        assert!(
            e <= 1e-6 * u0,
            "mu {mu} d {d}: u(0) {} vs {u0}",
            s.central_deflection.value
        );
        for (q, p) in s.pressure.iter().zip(refs) {
            let pr = num(&p["p"]);
            let e = (q.p.value - pr).abs();
            assert!(
                e <= 1e-5 * pr,
                "mu {mu} d {d} rho {}: p {} vs {pr}",
                q.rho,
                q.p.value
            );
        }
    }
}

/// A tighter tolerance converges further on the same references (mesh
/// convergence to 1e-8).
#[test]
fn refinement_converges_to_the_reference() {
    let r = reference();
    let opts = SolverOptions {
        tolerance: 1e-8,
        ..Default::default()
    };
    for c in r["cases"].as_array().unwrap() {
        let (mu, d) = (num(&c["mu"]), num(&c["d"]));
        if !((mu == 1.0 && d == -1.0) || (mu == 100.0 && d == 2.0) || (mu == 0.1 && d == 0.5)) {
            continue;
        }
        let s = GreenwoodTripp::with_options(mu, opts)
            .unwrap()
            .state(d, &[0.5])
            .unwrap();
        let load = num(&c["load"]);
        assert!(
            (s.load.value - load).abs() <= 1e-8 * load,
            "mu {mu} d {d}: {} vs {load}",
            s.load.value
        );
        let p = num(&c["pressure"][2]["p"]);
        assert!(
            (s.pressure[0].p.value - p).abs() <= 1e-7 * p,
            "mu {mu} d {d}"
        );
    }
}

/// `mu -> 0`: no bulk deformation, `P* = pi mu F_5/2(d)/(5/2)` (mpmath at
/// 30 digits); at mu = 1e-10 the bulk's correction is ~1e-10 relative, so
/// the solver's load over mu meets the rigid value to 1e-9.
#[test]
fn rigid_limit_is_gw_without_bulk_deformation() {
    let r = reference();
    let opts = SolverOptions {
        tolerance: 1e-10,
        ..Default::default()
    };
    let mu = 1e-10;
    let gt = GreenwoodTripp::with_options(mu, opts).unwrap();
    for c in r["rigid_limit"].as_array().unwrap() {
        let d = num(&c["d"]);
        let exact = num(&c["load_over_mu"]);
        assert!(
            (rigid_load_gt(1.0, d) - exact).abs() <= 1e-13 * exact,
            "closed form at d {d}"
        );
        let s = gt.state(d, &[]).unwrap();
        let got = s.load.value / mu;
        assert!(
            (got - exact).abs() <= 1e-9 * exact,
            "d {d}: {got} vs {exact}"
        );
    }
}

/// Heavy load (mu = 10, d from 0 down to -4): the radius holding 95 % of
/// the load, the approach and the pressure profile tend to Hertz's at the
/// same load, monotonically.
#[test]
fn heavy_load_tends_to_hertz() {
    let gt = GreenwoodTripp::new(10.0).unwrap();
    let mut prev = (f64::INFINITY, f64::INFINITY, f64::INFINITY);
    for d in [0.0, -1.0, -2.0, -4.0] {
        let s = gt.state(d, &[]).unwrap();
        let p = s.load.value;
        let a95 = s.radius_95.unwrap().value;
        let radius = (a95 / (hertz_radius_gt(p) * hertz_load_fraction_radius(0.95)) - 1.0).abs();
        let approach = (s.approach.value / hertz_approach_gt(p) - 1.0).abs();
        let p0 = hertz_pressure_gt(p, 0.0);
        let shape = s
            .profile
            .iter()
            .map(|&(r, q)| (q - hertz_pressure_gt(p, r)).abs())
            .fold(0.0, f64::max)
            / p0;
        assert!(
            radius < prev.0 && shape < prev.2,
            "d {d}: {radius} {shape} after {prev:?}"
        );
        if d <= -1.0 {
            assert!(
                approach < prev.1,
                "d {d}: approach {approach} after {}",
                prev.1
            );
        }
        prev = (radius, approach, shape);
    }
    // measured at d = -4: 0.0029, 0.0011, 0.063
    assert!(
        prev.0 < 0.005 && prev.1 < 0.002 && prev.2 < 0.07,
        "{prev:?}"
    );
}
