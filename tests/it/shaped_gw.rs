//! Conical JKR summits (`law::Shaped`) on a Gaussian surface through the
//! Greenwood–Williamson integrator, against an independent mpmath
//! quadrature over heights of the cone's closed-form JKR branch
//! (tests/data/shaped_gw.py, 30 digits), at 1e-8 relative.

use crate::common::{local, num};
use asperity::axisym::Profile;
use asperity::gw::{Accuracy, GwModel, Method, RoughSurface};
use asperity::heights::Gaussian;
use asperity::law::Shaped;
use asperity::loading::{History, LoadingModel, Observables};
use std::sync::Arc;

#[test]
fn conical_summits_match_independent_quadrature_at_1e_8() {
    let doc = local("shaped_gw.json");
    let p = &doc["params"];
    let g = |k: &str| num(&p[k]);
    let sigma = g("sigma");
    let law = Shaped::new(Profile::cone(g("tan_angle")).unwrap(), g("estar"), g("w")).unwrap();
    // The summit radius is unused by a shaped law (no closed forms).
    let surface = RoughSurface::new(g("density"), 1e-6, sigma, g("nominal_area")).unwrap();
    let model = GwModel::new(surface, Arc::new(Gaussian::new()), Arc::new(law)).unwrap();
    let acc = Accuracy::new(1e-11)
        .unwrap()
        .with_method(Method::Quadrature);
    let mut worst: f64 = 0.0;
    for case in doc["cases"].as_array().unwrap() {
        let d = num(&case["h"]) * sigma;
        let history = match case["history"].as_str().unwrap() {
            "approach" => History::Approach,
            _ => History::Retract {
                closest: num(&case["closest_h"]) * sigma,
            },
        };
        let s = model
            .clone()
            .with_accuracy(acc)
            .state(d, history, &Observables::ALL)
            .unwrap();
        let want: Vec<f64> = case["totals"].as_array().unwrap().iter().map(num).collect();
        for (got, want) in [s.load(), s.area(), s.count()].into_iter().zip(want) {
            let e = (got.unwrap() / want - 1.0).abs();
            worst = worst.max(e);
            assert!(e < 1e-8, "{case}: got {got:?}, want {want}");
        }
    }
    println!("worst relative error against mpmath: {worst:.2e}");
}
