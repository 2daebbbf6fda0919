//! GW integration with the real height distributions: the exponential
//! classic (load/area and load/count exactly constant) and adaptive
//! quadrature of the Hertz law reproducing the Gaussian closed forms.

use asperity::gw::{Accuracy, GwModel, History, Method, MethodUsed, Outputs, RoughSurface};
use asperity::heights::{Exponential, Gaussian};
use asperity::law::Hertz;
use std::sync::Arc;

fn hertz_model(dist: Arc<dyn asperity::heights::HeightDistribution>) -> (GwModel, RoughSurface) {
    let s = RoughSurface::gold_microswitch();
    let law = Arc::new(Hertz::new(s.radius, 4.8e10).unwrap());
    (GwModel::new(s, dist, law).unwrap(), s)
}

/// GW 1966: with phi(s) = e^-s, F_n(h) = Gamma(n+1) e^-h for h >= 0, so the
/// ratios of load, area and count do not depend on the separation. Closed
/// forms make them constant to rounding.
#[test]
fn exponential_hertz_ratios_are_constant() {
    let (m, s) = hertz_model(Arc::new(Exponential::new()));
    let acc = Accuracy::new(1e-12).unwrap();
    let r0 = m.state(0.0, History::Approach, Outputs::ALL, &acc).unwrap();
    assert_eq!(r0.method, MethodUsed::ClosedForm);
    let q0 = r0.load.unwrap() / r0.area.unwrap();
    let c0 = r0.load.unwrap() / r0.count.unwrap();
    for h in [0.1, 0.3, 1.0, 2.5, 4.0, 10.0, 20.0, 100.0] {
        let r = m
            .state(h * s.sigma, History::Approach, Outputs::ALL, &acc)
            .unwrap();
        let q = r.load.unwrap() / r.area.unwrap();
        let c = r.load.unwrap() / r.count.unwrap();
        assert!((q / q0 - 1.0).abs() < 1e-12, "h {h}: {q} {q0}");
        assert!((c / c0 - 1.0).abs() < 1e-12, "h {h}: {c} {c0}");
    }
    // And the ratios are the GW values: P/A = (4/3) E* sigma^(1/2) Gamma(5/2) / (pi R^(1/2)).
    let e_star = 4.8e10;
    let expected = 4.0 / 3.0 * e_star * s.sigma.sqrt() * 0.75 * std::f64::consts::PI.sqrt()
        / (std::f64::consts::PI * s.radius.sqrt());
    assert!((q0 / expected - 1.0).abs() < 1e-13, "{q0} {expected}");
}

/// Adaptive quadrature of the Hertz law over Gaussian heights agrees with the
/// closed forms to the requested tolerance, h in [-3, 6], every tolerance.
#[test]
fn gaussian_hertz_quadrature_meets_each_tolerance() {
    let (m, s) = hertz_model(Arc::new(Gaussian::new()));
    let hs: Vec<f64> = (0..=18).map(|i| -3.0 + 0.5 * f64::from(i)).collect();
    for tol in [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10] {
        let acc = Accuracy::new(tol).unwrap();
        let mut worst = 0.0_f64;
        for &h in &hs {
            let d = h * s.sigma;
            let exact = m
                .state(
                    d,
                    History::Approach,
                    Outputs::ALL,
                    &acc.with_method(Method::ClosedForm),
                )
                .unwrap();
            assert_eq!(exact.method, MethodUsed::ClosedForm);
            let quad = m
                .state(
                    d,
                    History::Approach,
                    Outputs::ALL,
                    &acc.with_method(Method::Quadrature),
                )
                .unwrap();
            assert_eq!(quad.method, MethodUsed::Quadrature);
            for (i, (a, b)) in [
                (exact.load, quad.load),
                (exact.area, quad.area),
                (exact.count, quad.count),
            ]
            .into_iter()
            .enumerate()
            {
                let (a, b) = (a.unwrap(), b.unwrap());
                let e = (a - b).abs() / a.abs();
                worst = worst.max(e);
                assert!(
                    e <= tol,
                    "tol {tol:e} h {h} output {i}: closed {a} quad {b} rel {e:e}"
                );
                // The reported error estimate covers the true error.
                assert!(
                    (a - b).abs() <= quad.error[i] + 1e-12 * a.abs(),
                    "estimate, tol {tol:e} h {h} output {i}"
                );
            }
        }
        println!("tol {tol:e}: worst relative deviation {worst:.2e}");
    }
}
