//! Skipping pays and costs nothing: for three example scenes, the planned
//! run against an everything-on run (every output, the exact law,
//! quadrature everywhere, both legs, the full separation range), written
//! into `docs/performance.md` between `<!-- plan-report:start -->` and
//! `<!-- plan-report:end -->`.
//!
//! `cargo run --release --example plan_report`
//!
//! Both runs use the same separations (the planned start is imposed on the
//! everything-on run), so the outputs can be compared point by point:
//! difference = max |planned - everything-on| / max |everything-on| over
//! the curve, worst of load and area.

use asperity::loading::State;
use asperity::study::{Plan, PlanMode, Scene};
use std::fmt::Write as _;
use std::time::Instant;

fn median_seconds(plan: &Plan) -> f64 {
    let mut t: Vec<f64> = (0..7)
        .map(|_| {
            let t0 = Instant::now();
            std::hint::black_box(plan.run().unwrap());
            t0.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[3]
}

fn gap(a: &[State], b: &[State]) -> f64 {
    let worst = |f: &dyn Fn(&State) -> Option<f64>| {
        let scale = b.iter().filter_map(f).fold(0.0f64, |m, v| m.max(v.abs()));
        a.iter()
            .zip(b)
            .filter_map(|(x, y)| Some((f(x)? - f(y)?).abs() / scale))
            .fold(0.0, f64::max)
    };
    worst(&|s| s.load()).max(worst(&|s| s.area()))
}

fn main() {
    let mut md = String::from(
        "| scene | planned law, methods | planned ms | everything-on ms | speed-up | max difference | rtol |\n|---|---|---|---|---|---|---|\n",
    );
    for name in ["hertz-exponential.toml", "soft-jkr.toml", "mems-gold.toml"] {
        let path = format!("{}/examples/scenes/{name}", env!("CARGO_MANIFEST_DIR"));
        let mut scene = Scene::from_toml(&std::fs::read_to_string(path).unwrap()).unwrap();
        if scene.program.start_separation.is_none() {
            let p = Plan::new(&scene, PlanMode::Planned).unwrap();
            scene.program.start_separation = Some(p.start);
        }
        let planned = Plan::new(&scene, PlanMode::Planned).unwrap();
        let full = Plan::new(&scene, PlanMode::EverythingOn).unwrap();
        let (rp, rf) = (planned.run().unwrap(), full.run().unwrap());
        let d = gap(&rp.curve.approach, &rf.curve.approach)
            .max(gap(&rp.curve.retract, &rf.curve.retract));
        let (tp, tf) = (median_seconds(&planned), median_seconds(&full));
        let how: Vec<String> = planned
            .decisions
            .iter()
            .filter(|x| ["law", "load", "retraction", "law evaluation"].contains(&x.topic()))
            .map(|x| format!("{}: {}", x.topic(), x.choice()))
            .collect();
        let _ = writeln!(
            md,
            "| {name} | {} | {:.2} | {:.2} | {:.1}x | {d:.1e} | {:e} |",
            how.join("; "),
            tp * 1e3,
            tf * 1e3,
            tf / tp,
            scene.accuracy.rtol
        );
    }
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/performance.md");
    let doc = std::fs::read_to_string(path).unwrap_or_default();
    let (start, end) = ("<!-- plan-report:start -->", "<!-- plan-report:end -->");
    let section = format!(
        "{start}\n## Scenes: planned against everything-on\n\n\
         Regenerate: `cargo run --release --example plan_report` (median of 7 runs each; same \
         separations for both; difference = max |planned - everything-on| / max |everything-on| \
         over load and area on both legs). `tests/it/scenes.rs` asserts the same two facts: the \
         planned run is faster and agrees within the scene's rtol.\n\n{md}{end}"
    );
    let new = match (doc.find(start), doc.find(end)) {
        (Some(a), Some(b)) => format!("{}{section}{}", &doc[..a], &doc[b + end.len()..]),
        _ => format!("{}\n\n{section}\n", doc.trim_end()),
    };
    std::fs::write(path, new).unwrap();
    println!("{md}");
}
