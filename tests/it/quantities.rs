//! A quantity added in one place reaches every writer: a toy observable
//! (the contact perimeter `2 pi a` summed over the summits) added to a plan
//! gets its `curve.csv` column, its key in the listed states, its headline
//! number in `summary.json` and the text report, and its column in a
//! sweep's `results.csv`, with no edit to any writer. Its values equal the
//! GW integral of the same observable computed straight from the library.

use asperity::gw::GwModel;
use asperity::law::ContactState;
use asperity::loading::{History, LoadingModel, Observable, Observables, PerAsperity};
use asperity::study::sweep::{run_sweep, Design, SweepOptions, SweepSpec, Vary};
use asperity::study::{
    curve_csv, text_report, Plan, PlanMode, Quantity, Scene, Summary, DEFAULT_SCENE,
};
use std::sync::Arc;

#[derive(Debug)]
struct Perimeter;

impl PerAsperity for Perimeter {
    fn name(&self) -> &str {
        "perimeter_m"
    }
    fn value(&self, s: &ContactState) -> f64 {
        2.0 * std::f64::consts::PI * s.radius
    }
}

fn perimeter() -> (Observable, Quantity) {
    let o = Observable::Custom(Arc::new(Perimeter));
    (o.clone(), Quantity::total("perimeter", "m", o))
}

fn scene() -> Scene {
    let text = DEFAULT_SCENE
        .replacen("points = 200", "points = 20", 1)
        .replacen("closest_separation = 5e-9", "separations = [8e-9, 5e-9]", 1);
    Scene::from_toml(&text).unwrap()
}

fn column(csv: &str, name: &str) -> Vec<String> {
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let k = header.iter().position(|h| *h == name).unwrap_or_else(|| {
        panic!("no column {name} in {header:?}");
    });
    lines
        .map(|l| l.split(',').nth(k).unwrap().to_string())
        .collect()
}

#[test]
fn a_toy_quantity_reaches_every_writer() {
    let (observable, q) = perimeter();
    let plan = Plan::new(&scene(), PlanMode::Planned)
        .unwrap()
        .with_quantity(q)
        .unwrap();
    let results = plan.run().unwrap();

    // The same integral straight from the library, at the closest approach.
    let closest = results.curve.program.closest;
    let model = GwModel::new(
        plan.surface,
        plan.distribution.clone(),
        plan.law.law.clone(),
    )
    .unwrap()
    .with_accuracy(plan.accuracy);
    let outputs = Observables::standard(true, false, false)
        .with(observable.clone())
        .unwrap();
    let direct = model
        .state(closest, History::Approach, &outputs)
        .unwrap()
        .totals
        .get(outputs.slot(&observable).unwrap())
        .unwrap();
    assert!(direct > 0.0);
    let close = |x: f64| (x - direct).abs() <= 1e-5 * direct;

    // curve.csv: a column, in program order (the closest approach is the
    // last approach row).
    let csv = curve_csv(&results, &plan);
    let cells = column(&csv, "perimeter_m");
    let n = results.curve.approach.len();
    let at_closest: f64 = cells[n - 1].parse().unwrap();
    assert!(close(at_closest), "{at_closest} vs {direct}");

    // summary.json: the headline number and the listed states' key.
    let summary = Summary::new(&plan, &results);
    let json: serde_json::Value = serde_json::from_str(&summary.to_json()).unwrap();
    assert!(close(json["perimeter_m"].as_f64().unwrap()), "{json}");
    let states = json["states"].as_array().unwrap();
    assert_eq!(states.len(), 2);
    assert!(states
        .iter()
        .all(|s| s["perimeter_m"].as_f64().unwrap() > 0.0));
    assert!(close(states[1]["perimeter_m"].as_f64().unwrap()));

    // The text report has a line for it.
    let text = text_report(&plan, &summary, &[]);
    assert!(text.contains("perimeter"), "{text}");
}

#[test]
fn a_toy_quantity_gets_a_sweep_column() {
    let (_, q) = perimeter();
    let dir = std::env::temp_dir().join(format!("asperity-quantity-sweep-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let spec = SweepSpec {
        vary: vec![Vary {
            path: "surface.sigma".into(),
            from: 4e-9,
            to: 6e-9,
            n: 2,
        }],
        design: Design::Grid,
        log: false,
        seed: 1,
    };
    let mut options = SweepOptions::default();
    options.quantities = vec![q];
    run_sweep(&scene(), &spec, &dir, &options, &|_, _| {}).unwrap();
    let csv = std::fs::read_to_string(dir.join("results.csv")).unwrap();
    let cells = column(&csv, "perimeter_m");
    assert_eq!(cells.len(), 2, "{csv}");
    for c in cells {
        assert!(c.parse::<f64>().unwrap() > 0.0, "{csv}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
