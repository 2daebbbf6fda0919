//! Run time against error of the sphere solver (docs/performance.md, "Sphere
//! solver: speed and accuracy"): `cargo run --release --example sphere_speed`.
//! Errors are relative to the converged references of
//! tests/data/sphere_converged.json; times are the best of three runs of
//! `SphereProblem::facts` on one thread.
use asperity::sphere::{Shape, SolverOptions, SphereProblem};
use std::time::Instant;

fn main() {
    let refs: serde_json::Value =
        serde_json::from_str(include_str!("../../tests/data/sphere_converged.json")).unwrap();
    let reference = |mu: f64, key: &str| {
        refs["cases"]
            .as_array()
            .unwrap()
            .iter()
            .find(|c| c["mu"].as_f64() == Some(mu) && c["rho"].is_null())
            .and_then(|c| c[key].as_f64())
    };
    let err = |x: Option<f64>, r: Option<f64>| match (x, r) {
        (Some(x), Some(r)) => format!("{:.1e}", ((x - r) / r).abs()),
        _ => "–".into(),
    };
    println!("| mu | resolution | nodes | time (s) | pull-off error | jump-out load error | zero-load radius error |");
    println!("|---|---|---|---|---|---|---|");
    for mu in [0.5, 1.0, 10.0] {
        for res in [0.5, 1.0, 2.0, 4.0] {
            let o = {
                let mut o = SolverOptions::default();
                o.resolution = res;
                o
            };
            let p = SphereProblem::new(mu, Shape::Paraboloid, o).unwrap();
            let mut best = f64::INFINITY;
            let mut facts = None;
            for _ in 0..3 {
                let t = Instant::now();
                facts = Some(p.facts().unwrap());
                best = best.min(t.elapsed().as_secs_f64());
            }
            let f = facts.unwrap();
            println!(
                "| {mu} | {res} | {} | {best:.3} | {} | {} | {} |",
                f.nodes,
                err(
                    Some(f.pull_off.load_bar),
                    reference(mu, "pull_off_load_control")
                ),
                err(
                    f.jump_out.map(|j| j.load_bar),
                    reference(mu, "jump_out_load")
                ),
                err(
                    f.zero_load_radius_bar,
                    reference(mu, "contact_radius_zero_load")
                ),
            );
        }
    }
}
