//! `asperity run` and the default run: outputs on disk, JSON summary, plans,
//! and bad scenes exiting 2 with a message naming the field.
use std::path::{Path, PathBuf};
use std::process::Command;

fn asperity(args: &[&str], dir: &Path) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("run asperity");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("asperity-cli-run-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn scene_path(name: &str) -> String {
    format!("{}/examples/scenes/{name}", env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn default_run_writes_its_outputs_and_prints_tables() {
    let dir = tmp("default");
    let (code, out, err) = asperity(&[], &dir);
    assert_eq!(code, 0, "{err}");
    for needle in [
        "maugis",
        "pull-off",
        "separation [nm]",
        "asperity-out/summary.json",
    ] {
        assert!(out.contains(needle), "{needle} missing from:\n{out}");
    }
    for f in [
        "curve.csv",
        "summary.json",
        "load_separation.svg",
        "area_load.svg",
        "count_load.svg",
    ] {
        assert!(dir.join("asperity-out").join(f).exists(), "{f}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn json_summary_matches_the_csv() {
    let dir = tmp("json");
    let (code, out, err) = asperity(
        &["run", &scene_path("soft-jkr.toml"), "--out", "o", "--json"],
        &dir,
    );
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["law"], "jkr");
    let csv = std::fs::read_to_string(dir.join("o/curve.csv")).unwrap();
    let max_load = csv
        .lines()
        .skip(1)
        .filter(|l| l.starts_with("approach"))
        .map(|l| l.split(',').nth(2).unwrap().parse::<f64>().unwrap())
        .fold(f64::NEG_INFINITY, f64::max);
    assert_eq!(v["max_load"].as_f64().unwrap(), max_load);
    assert!(v["pull_off_load"].as_f64().unwrap() < 0.0);
    assert_eq!(csv.lines().count(), 1 + 2 * 120);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn plan_is_printed_without_running() {
    let dir = tmp("plan");
    let (code, out, err) = asperity(
        &["run", &scene_path("hertz-exponential.toml"), "--plan"],
        &dir,
    );
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("closed form") && out.contains("skipped"),
        "{out}"
    );
    assert!(!dir.join("asperity-out").exists());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_scenes_exit_2_naming_the_field() {
    let dir = tmp("bad");
    let good = std::fs::read_to_string(scene_path("mems-gold.toml")).unwrap();
    let cases = [
        ("sigma = 5e-9", "", "surface.sigma"),
        ("sigma = 5e-9", "sigma = -5e-9", "surface.sigma"),
        ("sigma = 5e-9", "sigma = nan", "surface.sigma"),
        ("kind = \"auto\"", "kind = \"hertzz\"", "law.kind"),
        ("w = 0.5", "w = 0.5\nwork = 1.0", "adhesion.work"),
        ("e1 = 79e9", "e1 = inf", "materials.e1"),
        ("nu2 = 0.42", "nu2 = 0.5", "materials.nu2"),
    ];
    for (old, new, field) in cases {
        let text = good.replacen(old, new, 1);
        assert_ne!(text, good);
        std::fs::write(dir.join("bad.toml"), text).unwrap();
        let (code, out, err) = asperity(&["run", "bad.toml"], &dir);
        assert_eq!(code, 2, "{field}: {out} {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(field), "{field}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
    let (code, _, err) = asperity(&["run", "missing.toml"], &dir);
    assert_eq!(code, 2);
    assert!(err.contains("missing.toml"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn map_writes_svg_and_csv_and_checks_tolerance() {
    let dir = tmp("map");
    let (code, _, err) = asperity(&["map", "--tolerance", "0.05", "--out", "m"], &dir);
    assert_eq!(code, 0, "{err}");
    let csv = std::fs::read_to_string(dir.join("m/map.csv")).unwrap();
    assert!(csv.starts_with("mu,load_bar,hertz,bradley,dmt,jkr,maugis"));
    assert!(dir.join("m/map.svg").exists());
    for bad in ["0", "-1", "nan", "1"] {
        let (code, _, err) = asperity(&["map", "--tolerance", bad], &dir);
        assert_eq!(code, 2, "{bad}: {err}");
        assert!(err.contains("--tolerance"), "{err}");
    }
    std::fs::remove_dir_all(&dir).ok();
}
