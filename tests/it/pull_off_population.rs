//! The pull-off of one switch over populations of its summits, and
//! stiction as a probability, through `asperity run --json` (the JSON keys
//! exactly as the contract writes them).
//!
//! A switch of `N = eta A_n` summits is one realisation: population `k`
//! is exactly the population `[montecarlo] seed = s + k` draws, so the
//! statistics are checked against the Monte Carlo mode run seed by seed.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("asperity-popul-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The default gold surface with JKR summits (cheap), 60 points per leg.
fn scene(extra: &str) -> String {
    let base = std::fs::read_to_string(format!(
        "{}/examples/scenes/mems-gold.toml",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap();
    base.replacen("kind = \"auto\"", "kind = \"jkr\"", 1)
        .replacen("points = 200", "points = 60", 1)
        + extra
}

fn run(text: &str, d: &Path) -> (i32, Value, String) {
    let path = d.join("scene.toml");
    std::fs::write(&path, text).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(["run", path.to_str().unwrap(), "--json", "--out"])
        .arg(d.join("out"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    let v = serde_json::from_slice(&o.stdout).unwrap_or(Value::Null);
    (o.status.code().unwrap_or(-1), v, err)
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// numpy's default percentile (type 7).
fn quantile(sorted: &[f64], q: f64) -> f64 {
    let h = (sorted.len() - 1) as f64 * q;
    let lo = h.floor() as usize;
    let hi = (lo + 1).min(sorted.len() - 1);
    sorted[lo] + (h - lo as f64) * (sorted[hi] - sorted[lo])
}

#[test]
fn populations_are_the_montecarlo_populations_seed_by_seed() {
    let d = dir("seeds");
    let (code, v, err) = run(&scene("\n[montecarlo]\nseed = 3\nseeds = 6\n"), &d);
    assert_eq!(code, 0, "{err}");
    let p = &v["pull_off_population"];
    for key in [
        "seeds", "summits", "mean_N", "median_N", "std_N", "p05_N", "p95_N", "carriers",
    ] {
        assert!(p.get(key).is_some(), "{key} missing: {p}");
    }
    assert_eq!(p["seeds"], 6);
    assert_eq!(p["summits"], 10000);
    // The Monte Carlo mode, seed by seed: its own pull-off (no tensile
    // load reads as 0: the switch opens without pulling).
    let mut values = Vec::new();
    for k in 0..6 {
        let (code, w, err) = run(&scene(&format!("\n[montecarlo]\nseed = {}\n", 3 + k)), &d);
        assert_eq!(code, 0, "{err}");
        values.push(w["montecarlo"]["pull_off_load"].as_f64().unwrap_or(0.0));
    }
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let std = (values.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
    let mut sorted = values.clone();
    sorted.sort_by(f64::total_cmp);
    // The same numbers: equal to the last bit the JSON carries.
    assert_eq!(num(&p["mean_N"]), mean);
    assert_eq!(num(&p["std_N"]), std);
    assert_eq!(num(&p["median_N"]), quantile(&sorted, 0.5));
    assert_eq!(num(&p["p05_N"]), quantile(&sorted, 0.05));
    assert_eq!(num(&p["p95_N"]), quantile(&sorted, 0.95));
    assert!((num(&p["mean_se_N"]) - std / n.sqrt()).abs() <= 1e-15 * std);
    // Six populations hold the 5 % quantile between their minimum and
    // maximum with probability 1 - 0.95^6 - 0.05^6 = 26.5 %: no 95 %
    // interval, said in a note and a warning.
    for key in ["p05_interval_N", "p95_interval_N", "p05_interval_coverage"] {
        assert!(p[key].is_null(), "{key}: {p}");
    }
    let note = p["interval_note"].as_str().unwrap();
    assert!(
        note.contains("of 6 populations") && note.contains("26.5 %"),
        "{note}"
    );
    assert!(
        v["warnings"]
            .to_string()
            .contains("6 populations are too few"),
        "{}",
        v["warnings"]
    );
    // A few summits carry the integral's pull-off, and one switch pulls
    // off much harder than the integral says: the summary warns.
    assert!(num(&p["carriers"]) < 100.0, "{p}");
    assert!(
        mean < 3.0 * num(&v["pull_off_load"]),
        "{mean} vs {}",
        v["pull_off_load"]
    );
    let warnings = v["warnings"].to_string();
    assert!(
        warnings.contains("one switch of 10000 summits"),
        "{warnings}"
    );
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn stiction_is_a_probability_over_the_populations() {
    let d = dir("stiction");
    let switch = "\n[switch]\nspring_constant = 10.0\ntravel = 1e-6\n";
    let (code, v, err) = run(&scene(&format!("{switch}\n[montecarlo]\nseeds = 40\n")), &d);
    assert_eq!(code, 0, "{err}");
    let s = &v["stiction"];
    let p = &v["pull_off_population"];
    for key in ["pull_off_N", "restoring_force_N", "margin_N", "sticks"] {
        assert!(s.get(key).is_some(), "{key} missing: {s}");
    }
    assert_eq!(s["pull_off_basis"], "population");
    assert_eq!(num(&s["confidence"]), 0.95);
    // The margin uses the 5 % most tensile pull-off.
    assert_eq!(num(&s["pull_off_N"]), num(&p["p05_N"]).min(0.0));
    let prob = num(&s["sticks_probability"]);
    assert!((0.0..=1.0).contains(&prob), "{prob}");
    assert_eq!(
        s["sticks"].as_bool().unwrap(),
        num(&s["margin_N"]) < 0.0,
        "{s}"
    );
    // Another confidence: the median.
    let (code, v, err) = run(
        &scene(&format!(
            "{}confidence = 0.5\n\n[montecarlo]\nseeds = 40\n",
            switch
        )),
        &d,
    );
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        num(&v["stiction"]["pull_off_N"]),
        num(&v["pull_off_population"]["median_N"]).min(0.0)
    );
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn bad_population_keys_exit_2_naming_the_field() {
    let d = dir("bad");
    for (extra, field) in [
        ("\n[montecarlo]\nseeds = 0\n", "montecarlo.seeds"),
        (
            "\n[switch]\nspring_constant = 10.0\ntravel = 1e-6\nconfidence = 1.5\n",
            "switch.confidence",
        ),
    ] {
        let (code, _, err) = run(&scene(extra), &d);
        assert_eq!(code, 2, "{extra}: {err}");
        assert!(err.contains(field), "{err}");
    }
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn many_carriers_within_the_tolerance_skip_the_populations_and_say_why() {
    // A soft, dense contact: hundreds of summits carry the pull-off, and at
    // rtol = 0.1 one switch's scatter ~1/sqrt(carriers) is inside it.
    let d = dir("skip");
    let base = std::fs::read_to_string(format!(
        "{}/examples/scenes/soft-jkr.toml",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap();
    let text = base.replace("rtol = 1e-2", "rtol = 0.1");
    assert!(text.contains("rtol = 0.1"));
    let (code, v, err) = run(&text, &d);
    assert_eq!(code, 0, "{err}");
    let p = &v["pull_off_population"];
    assert!(num(&p["carriers"]) > 100.0, "{p}");
    assert_eq!(p["seeds"], 0, "{p}");
    assert!(p["mean_N"].is_null());
    assert!(p["note"].as_str().unwrap().contains("skipped"), "{p}");
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn switched_off_populations_leave_the_integral_as_the_basis() {
    let d = dir("off");
    let text = scene("\n[switch]\nspring_constant = 10.0\ntravel = 1e-6\n").replacen(
        "[outputs]",
        "[outputs]\npull_off_population = false",
        1,
    );
    assert!(text.contains("pull_off_population = false"));
    let (code, v, err) = run(&text, &d);
    assert_eq!(code, 0, "{err}");
    assert!(
        v["pull_off_population"].is_null(),
        "{}",
        v["pull_off_population"]
    );
    let s = &v["stiction"];
    assert_eq!(s["pull_off_basis"], "integral");
    assert_eq!(num(&s["pull_off_N"]), num(&v["pull_off_load"]));
    // The plan says why there is no distribution.
    assert!(
        v["plan"]
            .to_string()
            .contains("outputs.pull_off_population = false"),
        "{}",
        v["plan"]
    );
    std::fs::remove_dir_all(&d).ok();
}

/// Populations that would cost more than the run's budget (an estimated
/// `POPULATION_CPU_BUDGET` = 0.5 s of CPU) are cut to what it affords,
/// never below 20, and the summary says so, naming the key that sets them:
/// a million JKR summits (160,000 within the flat's reach each) afford
/// about 25.
#[test]
fn populations_beyond_the_cost_budget_are_cut_and_said() {
    let d = dir("budget");
    let text = scene("").replacen("nominal_area = 1e-8", "nominal_area = 1e-6", 1);
    let (code, v, err) = run(&text, &d);
    assert_eq!(code, 0, "{err}");
    let p = &v["pull_off_population"];
    assert_eq!(p["summits"], 1_000_000, "{p}");
    // (The estimate counts law evaluations, not time: the same on any
    // machine.)
    let seeds = p["seeds"].as_u64().unwrap();
    assert!((20..100).contains(&seeds), "{p}");
    let note = p["note"].as_str().unwrap_or_default();
    assert!(
        note.contains(&format!("{seeds} of the 100 populations asked for drawn"))
            && note.contains("montecarlo.seeds"),
        "{note}"
    );
    assert!(num(&p["mean_se_N"]) > 0.0);
    std::fs::remove_dir_all(&d).ok();
}
