//! Results do not change under refactoring: every example scene's
//! `curve.csv` (and the Monte Carlo table) against the stored golden output
//! (tests/data/golden/README.md), to 1e-12 of each column's largest value
//! (the curves are deterministic for any thread count; what a refactoring
//! may change is the order of a few floating-point sums).

use asperity::study::{curve_csv, montecarlo_csv, Plan, PlanMode, Scene};

fn table(text: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let mut lines = text.lines();
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(String::from).collect())
        .collect();
    (header, rows)
}

fn assert_same(name: &str, got: &str, want: &str) {
    let (gh, gr) = table(got);
    let (wh, wr) = table(want);
    assert_eq!(gh, wh, "{name}: columns");
    assert_eq!(gr.len(), wr.len(), "{name}: rows");
    for j in 0..wh.len() {
        let num = |r: &Vec<String>| r[j].parse::<f64>().ok();
        let scale = wr.iter().filter_map(num).map(f64::abs).fold(0.0, f64::max);
        for (g, w) in gr.iter().zip(&wr) {
            match (num(g), num(w)) {
                (Some(a), Some(b)) => assert!(
                    (a - b).abs() <= 1e-12 * scale,
                    "{name} {}: {a} vs {b}",
                    wh[j]
                ),
                _ => assert_eq!(g[j], w[j], "{name} {}", wh[j]),
            }
        }
    }
}

#[test]
fn example_scenes_reproduce_their_golden_curves() {
    for name in [
        "calibrated-gold",
        "dmt-stiff",
        "hertz-exponential",
        "max-load",
        "measured-heights",
        "mems-gold",
        "montecarlo-gold",
        "rf-mems-switch-humid",
        "soft-jkr",
    ] {
        let root = env!("CARGO_MANIFEST_DIR");
        let text = std::fs::read_to_string(format!("{root}/examples/scenes/{name}.toml")).unwrap();
        let scene = Scene::from_toml(&text).unwrap();
        let plan = Plan::new(&scene, PlanMode::Planned).unwrap();
        let results = plan.run().unwrap();
        let want =
            std::fs::read_to_string(format!("{root}/tests/data/golden/{name}.curve.csv")).unwrap();
        assert_same(name, &curve_csv(&results, &plan), &want);
        if let Some(mc) = montecarlo_csv(&results, &plan) {
            let want =
                std::fs::read_to_string(format!("{root}/tests/data/golden/{name}.montecarlo.csv"))
                    .unwrap();
            assert_same(name, &mc, &want);
        }
    }
}
