//! GW's pull-off on a measured map against the adhesive boundary elements,
//! as `asperity run --json` reports it (`model_error.pull_off_map`): the
//! exact pull-off against the same retraction through the library's public
//! boundary-element API (and a finer one), the difference and its warning,
//! the budget that skips a map too large, and `accuracy.model_error =
//! false`.

use crate::common::cli::{example, tmp};
use asperity::bem::{Options, Problem, Solution};
use asperity::surface::{npy, HeightMap};
use serde_json::Value;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// `example` with the map path made absolute, run with `--json`.
fn run_scene(text: &str, dir: &Path) -> Value {
    let data = root().join("examples/data");
    let text = text.replace("../data/", &format!("{}/", data.display()));
    crate::common::cli::run_scene_json(dir, "scene", &text)
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// The example scene on the periodic 32 x 32 map of
/// `tests/data/pull_off_map32.py` (RMS 5 nm, 50 nm pixels, JKR, w = 0.5
/// J/m^2, z0 = 0.3 nm).
fn periodic_scene() -> (String, HeightMap) {
    let file = root().join("tests/data/pull_off_map32.npy");
    let map: HeightMap = npy::parse(&std::fs::read(&file).unwrap()).unwrap();
    let text = example("measured-topography.toml")
        .replace("../data/measured-topography.npy", file.to_str().unwrap())
        .replace("compare = true", "compare = false")
        .replace("# periodic = false", "periodic = true");
    (text, map)
}

/// The exact pull-off is the most tensile state of the same retraction
/// made through `asperity::bem` (the start at the run's largest load, the
/// run's steps, each warm-started from the previous state) to 1e-12; steps
/// four times finer pull off at 0.78 of that tension on this map, whose
/// range is under-resolved (0.18 of a pixel's height change): the step
/// dependence the docs state. The difference is `(GW - exact)/|exact|` to
/// 1e-12, in `model_error.pull_off` too, and is beyond 10 % here (+98 %:
/// JKR summits against the whole map deforming with a finite-range
/// interaction, beyond 90 % against the finer steps too): the warning
/// names it.
#[test]
fn exact_pull_off_is_the_library_retraction_and_warns() {
    let d = tmp("pull_off_map");
    let (text, map) = periodic_scene();
    let v = run_scene(&text, &d);
    let m = &v["model_error"];
    let p = &m["pull_off_map"];
    let (gw, exact) = (num(&p["gw_N"]), num(&p["exact_N"]));
    assert_eq!(gw, num(&v["pull_off_load_N"]), "{p}");
    let relative = num(&p["relative"]);
    assert!(
        ((gw - exact) / exact.abs() - relative).abs() <= 1e-12,
        "{p}"
    );
    assert_eq!(num(&m["pull_off"]), relative);
    assert_eq!(num(&m["reference_pull_off_N"]), exact);
    assert_eq!(num(&p["tolerance"]), 1e-8);
    let differences = p["differences"].as_str().unwrap();
    for what in [
        "interaction law",
        "JKR",
        "summit independence",
        "grid resolution",
    ] {
        assert!(differences.contains(what), "{what}: {differences}");
    }
    assert!(p["reference"]
        .as_str()
        .unwrap()
        .starts_with("the adhesive boundary elements"));

    // The independent retraction.
    let (w, rho) = (num(&p["work_of_adhesion_J_m2"]), num(&p["range_m"]));
    assert_eq!(w, 0.5);
    assert!((rho - 0.9743 * 0.3e-9).abs() < 1e-4 * rho, "{rho}");
    let options = Options {
        tolerance: 1e-8,
        ..Options::default()
    };
    let estar = num(&v["contact_modulus_Pa"]);
    let problem = Problem::new(&map, 50e-9, estar, true, &options)
        .unwrap()
        .with_adhesion(w, rho)
        .unwrap();
    let a_n = 32.0 * 32.0 * 50e-9 * 50e-9;
    let start = problem
        .solve_pressure(num(&v["max_load_N"]) / a_n, &options, None)
        .unwrap();
    // The run's own steps (its sweep without the refinement), and steps
    // four times finer, each sequence warm-started from the start.
    let retraction = |step: f64| {
        let (u0, end) = (
            start.mean_gap,
            num(&p["gap_m"]) + 2.0 * num(&p["gap_step_m"]),
        );
        let mut warm: Solution = start.clone();
        let mut least = f64::INFINITY;
        let (mut k, mut failed, mut solved) = (1.0, 0, 0);
        while u0 + k * step <= end {
            // The under-resolved interaction leaves a few states at the
            // iteration cap: skipped, the next warm-started from the last
            // converged one.
            match problem.solve_gap(u0 + k * step, &options, Some(&warm)) {
                Ok(s) => {
                    least = least.min(s.mean_pressure * a_n);
                    warm = s;
                    solved += 1;
                }
                Err(_) => failed += 1,
            }
            k += 1.0;
        }
        (least, solved, failed)
    };
    let step = num(&p["gap_step_m"]);
    let same = retraction(step);
    let fine = retraction(step / 4.0);
    println!("exact {exact:e} N, same steps {same:?}, four times finer {fine:?}, GW {gw:e} N");
    let (same, fine) = (same.0, fine.0);
    // The run's pull-off is its sweep's most tensile state (the golden
    // section can only make it more tensile; here it does not).
    assert!(
        exact <= same && (exact - same).abs() <= 1e-12 * same.abs(),
        "{exact} {same}"
    );
    // On this under-resolved map the retraction's branch depends on its
    // step: four times finer steps pull off at 0.78 of the run's tension
    // (measured); the bound 0.7-1 holds that, and GW's difference stays
    // far beyond 10 % against either.
    let ratio = fine / exact;
    assert!(ratio > 0.7 && ratio < 1.0, "{ratio}");
    assert!((gw - fine) / fine.abs() > 0.9, "{gw} {fine}");
    assert!(relative.abs() > 0.1, "{p}");
    let warnings = v["warnings"].to_string();
    assert!(
        warnings.contains("GW's pull-off on this map differs")
            && warnings.contains("model_error.pull_off"),
        "{warnings}"
    );
}

/// The shipped example (160 x 160, not periodic: mirrored to 320 x 320)
/// is beyond the 2 s budget: not measured, with the estimate; switched off
/// it says so; without adhesion there is no pull-off to compare.
#[test]
fn a_map_too_large_or_switched_off_says_so() {
    let d = tmp("pull_off_large");
    let v = run_scene(&example("measured-topography.toml"), &d);
    let p = &v["model_error"]["pull_off_map"];
    let reference = p["reference"].as_str().unwrap();
    assert!(
        reference.contains("160 x 160 map (mirrored to twice its size)")
            && reference.contains("estimated"),
        "{reference}"
    );
    // 41 solves of 300 iterations at 100 ns on 320^2 pixels.
    assert!((num(&p["estimate_s"]) - 41.0 * 300.0 * 100e-9 * 320.0 * 320.0).abs() < 1e-9);
    assert!(p["exact_N"].is_null() && v["model_error"]["pull_off"].is_null());

    let d = tmp("pull_off_off");
    let (text, _) = periodic_scene();
    let v = run_scene(&(text + "\n[accuracy]\nmodel_error = false\n"), &d);
    let p = &v["model_error"]["pull_off_map"];
    assert!(
        p["reference"]
            .as_str()
            .unwrap()
            .contains("accuracy.model_error = false"),
        "{p}"
    );
    assert!(p["exact_N"].is_null());

    let d = tmp("pull_off_dry");
    let (text, _) = periodic_scene();
    let text = text
        .replace("w = 0.5", "w = 0.0")
        .replace("kind = \"jkr\"", "kind = \"hertz\"");
    let v = run_scene(&text, &d);
    assert!(v["model_error"].get("pull_off_map").is_none(), "{v}");
}
