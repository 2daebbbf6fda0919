//! The study layer's warnings are typed (`asperity::study::Warning`, a
//! code per kind) and worded at the edge: an example scene that warns at
//! plan and run time gives the same sentences as when the warnings were
//! strings (`tests/data/warnings/README.md`), in the same order, with
//! their codes beside them in `summary.json`, the text report and on
//! stderr.

use asperity::study::{text_report, Plan, PlanMode, Scene, Summary};
use std::process::Command;

const SCENE: &str = "rf-mems-switch-humid";

fn expected() -> Vec<String> {
    let root = env!("CARGO_MANIFEST_DIR");
    let text = std::fs::read_to_string(format!("{root}/tests/data/warnings/{SCENE}.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w.as_str().unwrap().to_string())
        .collect()
}

#[test]
fn an_example_scene_warns_with_codes_and_the_same_sentences() {
    let root = env!("CARGO_MANIFEST_DIR");
    let path = format!("{root}/examples/scenes/{SCENE}.toml");
    let scene = Scene::from_toml(&std::fs::read_to_string(&path).unwrap()).unwrap();
    let plan = Plan::new(&scene, PlanMode::Planned).unwrap();
    let results = plan.run().unwrap();
    let want = expected();
    // typed: the plan's warning first, then the run's
    let codes = [
        "meniscus-rigid",
        "pull-off-population-disagrees",
        "greenwood-interaction-skipped",
    ];
    let typed: Vec<&str> = plan
        .warnings
        .iter()
        .chain(&results.warnings)
        .map(|w| w.code())
        .collect();
    assert_eq!(typed, codes);
    // worded at the edge: summary.json
    let summary = Summary::new(&plan, &results);
    let json: serde_json::Value = serde_json::from_str(&summary.to_json()).unwrap();
    let words: Vec<&str> = json["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w.as_str().unwrap())
        .collect();
    assert_eq!(words, want);
    let json_codes: Vec<&str> = json["warning_codes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_str().unwrap())
        .collect();
    assert_eq!(json_codes, codes);
    // the text report lists the same sentences
    let report = text_report(&plan, &summary, &[]);
    for w in &want {
        assert!(report.contains(&format!("    {w}\n")), "{w}\n{report}");
    }
}

#[test]
fn the_command_line_prints_the_same_sentences_on_stderr() {
    let root = env!("CARGO_MANIFEST_DIR");
    let dir = std::env::temp_dir().join(format!("asperity-warnings-{}", std::process::id()));
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args([
            "run",
            &format!("{root}/examples/scenes/{SCENE}.toml"),
            "--json",
            "--out",
        ])
        .arg(&dir)
        .output()
        .unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert!(out.status.success());
    let stderr = String::from_utf8(out.stderr).unwrap();
    let printed: Vec<&str> = stderr
        .lines()
        .filter_map(|l| l.strip_prefix("warning: "))
        .collect();
    assert_eq!(printed, expected());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(
        v["warning_codes"].as_array().map(Vec::len),
        Some(printed.len())
    );
}
