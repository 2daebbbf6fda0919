//! the quadrature path keeps relative accuracy in the far
//! Gaussian tail (it used to drop summits whose tail probability is below
//! 1e-300: 62 % wrong at h = 37, exactly 0 beyond). Hertz asperities on
//! Gaussian heights integrated by quadrature against the mpmath `F_n` of
//! tests/data/gaussian_fn.json (tests/data/gaussian_fn.py, 50 digits):
//! load `N (4/3) E* R^(1/2) sigma^(3/2) F_3/2(h)`, area `N pi R sigma
//! F_1(h)`, count `N F_0(h)`; units with N = R = sigma = 1, E* = 3/4.
use asperity::gw::{Accuracy, GwModel, Method, RoughSurface};
use asperity::heights::Gaussian;
use asperity::law::Hertz;
use asperity::loading::{History, LoadingModel, Observables};
use std::f64::consts::PI;
use std::sync::Arc;

#[test]
fn quadrature_keeps_relative_accuracy_to_the_end_of_the_tail() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/gaussian_fn.json"
    ))
    .unwrap();
    let doc: serde_json::Value = serde_json::from_str(&text).unwrap();
    let reference = |n: &str, h: f64| -> f64 {
        let row = doc["F"][n]
            .as_array()
            .unwrap()
            .iter()
            .find(|r| r["h"].as_f64().unwrap() == h)
            .unwrap();
        row["F"].as_str().unwrap().parse().unwrap()
    };
    let surface = RoughSurface::new(1.0, 1.0, 1.0, 1.0).unwrap();
    let rtol = 1e-10;
    let m = GwModel::new(
        surface,
        Arc::new(Gaussian::new()),
        Arc::new(Hertz::new(1.0, 0.75).unwrap()),
    )
    .unwrap()
    .with_accuracy(Accuracy::new(rtol).unwrap().with_method(Method::Quadrature));
    for h in [30.0, 35.5, 36.0, 36.5, 37.0, 37.25, 37.5, 38.0] {
        let st = m.state(h, History::Approach, &Observables::ALL).unwrap();
        for (got, want, what) in [
            (st.load().unwrap(), reference("1.5", h), "load"),
            (st.area().unwrap(), PI * reference("1", h), "area"),
            (st.count().unwrap(), reference("0", h), "count"),
        ] {
            // rtol (plus the 7e-14 of factoring the density out, and the
            // granularity of subnormals below 2.2e-308).
            let tol = 10.0 * rtol * want + 1e-321;
            assert!(
                (got - want).abs() <= tol,
                "h {h} {what}: {got:e} vs {want:e}"
            );
        }
    }
}
