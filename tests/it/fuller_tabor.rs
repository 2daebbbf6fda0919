//! Fuller & Tabor (1975): JKR asperities on Gaussian heights, approached to
//! the mean summit height and retracted; the rough surface's pull-off,
//! normalised by `N pi w R`, against an independent scipy computation
//! (tests/data/fuller_tabor.py: numpy polynomial roots for the JKR radius,
//! QUADPACK, bounded Brent; about 9 significant digits).
use asperity::gw::dimensionless::fuller_tabor_parameter;
use asperity::gw::{Accuracy, GwModel, RoughSurface};
use asperity::heights::Gaussian;
use asperity::law::Jkr;
use asperity::loading::LoadingModel;
use std::f64::consts::PI;
use std::sync::Arc;

/// Pull-off / (N pi w R) at Fuller-Tabor parameter `theta`, in units where
/// R = 1, K = 1 (E* = 3/4), pi w R = 1 and N = 1.
fn pull_off(theta: f64) -> f64 {
    let (r, e, w): (f64, f64, f64) = (1.0, 0.75, 1.0 / PI);
    let sigma = (theta * r.sqrt() * w / e).powf(2.0 / 3.0);
    assert!((fuller_tabor_parameter(e, sigma, r, w) / theta - 1.0).abs() < 1e-14);
    let surface = RoughSurface::new(1.0, r, sigma, 1.0).unwrap();
    let model = GwModel::new(
        surface,
        Arc::new(Gaussian::new()),
        Arc::new(Jkr::new(r, e, w).unwrap()),
    )
    .unwrap();
    let acc = Accuracy::new(1e-11).unwrap();
    model
        .clone()
        .with_accuracy(acc)
        .pull_off(0.0, f64::INFINITY, 200)
        .unwrap()
        .unwrap()
        .load
        / (PI * w * r)
}

#[test]
fn pull_off_matches_the_independent_reference_and_falls_with_theta() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/fuller_tabor.json"
    ))
    .unwrap();
    let doc: serde_json::Value = serde_json::from_str(&text).unwrap();
    let mut last = f64::NEG_INFINITY;
    for v in doc["values"].as_array().unwrap() {
        let theta = v["theta"].as_f64().unwrap();
        let want = v["pull_off_over_N_pi_w_R"].as_f64().unwrap();
        let got = pull_off(theta);
        eprintln!(
            "theta {theta}: {got} vs {want} ({:.1e} relative)",
            (got / want - 1.0).abs()
        );
        // The reference carries ~9 digits; the minimum of a smooth curve is
        // located to rtol * sigma in separation, so its value to ~1e-12.
        assert!(
            (got - want).abs() <= 1e-9 * want.abs(),
            "theta {theta}: {got} vs {want}"
        );
        // Less adhesive (closer to zero) as theta grows.
        assert!(got > last, "theta {theta}: {got} after {last}");
        last = got;
    }
}
