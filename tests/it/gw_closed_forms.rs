//! GW integration with the real height distributions: the exponential
//! classic (load/area and load/count exactly constant) and adaptive
//! quadrature of the Hertz law reproducing the Gaussian closed forms.

use asperity::gw::{Accuracy, GwModel, Method, RoughSurface};
use asperity::heights::{Exponential, Gaussian};
use asperity::law::Hertz;
use asperity::loading::{History, LoadingModel, MethodUsed, Observables};
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
    let r0 = m
        .clone()
        .with_accuracy(acc)
        .state(0.0, History::Approach, &Observables::ALL)
        .unwrap();
    assert_eq!(r0.method, MethodUsed::ClosedForm);
    let q0 = r0.load().unwrap() / r0.area().unwrap();
    let c0 = r0.load().unwrap() / r0.count().unwrap();
    for h in [0.1, 0.3, 1.0, 2.5, 4.0, 10.0, 20.0, 100.0] {
        let r = m
            .clone()
            .with_accuracy(acc)
            .state(h * s.sigma, History::Approach, &Observables::ALL)
            .unwrap();
        let q = r.load().unwrap() / r.area().unwrap();
        let c = r.load().unwrap() / r.count().unwrap();
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
                .clone()
                .with_accuracy(acc.with_method(Method::ClosedForm))
                .state(d, History::Approach, &Observables::ALL)
                .unwrap();
            assert_eq!(exact.method, MethodUsed::ClosedForm);
            let quad = m
                .clone()
                .with_accuracy(acc.with_method(Method::Quadrature))
                .state(d, History::Approach, &Observables::ALL)
                .unwrap();
            assert_eq!(quad.method, MethodUsed::Quadrature);
            for (i, (a, b)) in [
                (exact.load(), quad.load()),
                (exact.area(), quad.area()),
                (exact.count(), quad.count()),
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
                    (a - b).abs() <= quad.totals.error(i).unwrap() + 1e-12 * a.abs(),
                    "estimate, tol {tol:e} h {h} output {i}"
                );
            }
        }
        println!("tol {tol:e}: worst relative deviation {worst:.2e}");
    }
}

/// GW's density-weighted quadrature (Method::Quadrature integrates the law
/// against `pdf`) agrees with each distribution's own `F_n` (closed form
/// or its separate quadrature): `P = N (4/3) E* R^(1/2) sigma^(3/2) F_3/2(h)`.
#[test]
fn quadrature_over_pdf_matches_moment_above_for_every_distribution() {
    use asperity::heights::{TruncatedGaussian, Weibull};
    let dists: Vec<Arc<dyn asperity::heights::HeightDistribution>> = vec![
        Arc::new(Gaussian::new()),
        Arc::new(Exponential::new()),
        Arc::new(Weibull::new(2.0).unwrap()),
        Arc::new(Weibull::new(0.8).unwrap()),
        Arc::new(TruncatedGaussian::new(3.0).unwrap()),
    ];
    for dist in dists {
        let (m, s) = hertz_model(dist.clone());
        let form = m.law().power_form().unwrap();
        let acc = Accuracy::new(1e-10)
            .unwrap()
            .with_method(Method::Quadrature);
        for h in [-1.0, 0.2, 1.5, 2.9] {
            let q = m
                .clone()
                .with_accuracy(acc)
                .state(h * s.sigma, History::Approach, &Observables::ALL)
                .unwrap();
            let load: f64 = form
                .load
                .iter()
                .map(|&(c, n)| c * s.sigma.powf(n) * dist.moment_above(n, h))
                .sum::<f64>()
                * s.summits();
            let count = s.summits() * dist.moment_above(0.0, h);
            if load == 0.0 {
                assert_eq!(q.load().unwrap(), 0.0, "{} h {h}", dist.name());
                continue;
            }
            let e = (q.load().unwrap() / load - 1.0).abs();
            assert!(
                e < 1e-9,
                "{} h {h}: {} vs {load} ({e:e})",
                dist.name(),
                q.load().unwrap()
            );
            let e = (q.count().unwrap() / count - 1.0).abs();
            assert!(e < 1e-9, "{} h {h}: count {e:e}", dist.name());
        }
    }
}

/// Measured heights: the closed form is the exact sum over the summits,
/// `P = (eta A_n / N) sum_i (4/3) E* R^(1/2) (z_i - mean - d)_+^(3/2)`.
#[test]
fn empirical_heights_give_the_exact_sum_over_summits() {
    use asperity::heights::Empirical;
    let z: Vec<f64> = (0..500)
        .map(|i| 5e-9 * ((f64::from(i) * 0.618_034).fract() - 0.5) * 3.0)
        .collect();
    let e = Empirical::new(&z).unwrap();
    let base = RoughSurface::gold_microswitch();
    let s = RoughSurface::new(base.density, base.radius, e.std_m(), base.nominal_area).unwrap();
    let e_star = 4.8e10;
    let law = Arc::new(Hertz::new(s.radius, e_star).unwrap());
    let m = GwModel::new(s, Arc::new(e.clone()), law).unwrap();
    let acc = Accuracy::new(1e-12).unwrap();
    for d in [-6e-9, -1e-9, 0.0, 2e-9, 4e-9] {
        let st = m
            .clone()
            .with_accuracy(acc)
            .state(d, History::Approach, &Observables::ALL)
            .unwrap();
        assert_eq!(st.method, MethodUsed::ClosedForm);
        let mut load = 0.0;
        let mut count = 0.0;
        for &zi in &z {
            let delta = zi - e.mean_m() - d;
            if delta > 0.0 {
                load += 4.0 / 3.0 * e_star * s.radius.sqrt() * delta.powf(1.5);
                count += 1.0;
            }
        }
        let scale = s.summits() / z.len() as f64;
        let (load, count) = (load * scale, count * scale);
        assert!(
            (st.load().unwrap() / load - 1.0).abs() < 1e-12,
            "d {d}: {} {load}",
            st.load().unwrap()
        );
        assert!((st.count().unwrap() / count - 1.0).abs() < 1e-12, "d {d}");
    }
}

#[test]
fn measured_heights_are_summed_exactly_for_any_law() {
    use asperity::heights::Empirical;
    use asperity::law::{AsperityLaw, Branch, Jkr};
    use asperity::loading::LoadingProgram;
    let heights_m: Vec<f64> = (0..40)
        .map(|i| 1e-9 * ((i * 37 % 40) as f64 - 17.3) / 4.0)
        .collect();
    let emp = Empirical::new(&heights_m).unwrap();
    let (mean, sd) = (emp.mean_m(), emp.std_m());
    let surface = RoughSurface::new(1e12, 1e-6, sd, 1e-8).unwrap();
    let jkr = Jkr::new(1e-6, 4.8e10, 0.5).unwrap();
    let model = GwModel::new(surface, Arc::new(emp), Arc::new(jkr)).unwrap();
    let acc = Accuracy::new(1e-8).unwrap();
    let n_total = surface.summits();
    let closest = -0.5 * sd;
    for d in [closest, 0.0, 0.7 * sd, 1.5 * sd] {
        for history in [History::Approach, History::Retract { closest }] {
            let st = model
                .clone()
                .with_accuracy(acc)
                .state(d, history, &Observables::ALL)
                .unwrap();
            assert_eq!(st.method, MethodUsed::SampleSum);
            // Brute force over the measured heights (from their mean).
            let (mut p, mut a, mut c) = (0.0, 0.0, 0.0);
            for &z in &heights_m {
                let delta = (z - mean) - d;
                let s = match history {
                    History::Approach => jkr.state(delta, Branch::Approach),
                    History::Retract { closest } => jkr.state_after(delta, (z - mean) - closest),
                };
                p += s.load;
                a += s.area();
                c += f64::from(u8::from(s.in_contact()));
            }
            let k = n_total / heights_m.len() as f64;
            let close = |x: f64, y: f64| (x - y).abs() <= 1e-12 * y.abs().max(1e-30);
            assert!(
                close(st.load().unwrap(), k * p),
                "{d}: {:?} vs {}",
                st.load(),
                k * p
            );
            assert!(close(st.area().unwrap(), k * a));
            assert_eq!(st.count().unwrap(), k * c);
        }
    }
    // The whole program runs on the same exact sums.
    let program = LoadingProgram::new(3.0 * sd, closest, 20).unwrap();
    let curve = model
        .clone()
        .with_accuracy(acc)
        .curve(&program, &Observables::LOAD)
        .unwrap();
    assert!(curve.hysteresis_energy().unwrap() > 0.0);
}
