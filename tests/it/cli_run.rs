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

/// `--plan` runs nothing expensive and writes nothing: a measured map is
/// not read (here it does not even exist), an uncached calibration is not
/// computed (its cache directory stays absent).
#[test]
fn plan_reads_no_map_and_computes_no_calibration() {
    let dir = tmp("plan-lazy");
    let topo = std::fs::read_to_string(scene_path("measured-topography.toml")).unwrap();
    let (old, _) = topo
        .lines()
        .find_map(|l| l.trim().strip_prefix("topography = ").map(|v| (l, v)))
        .unwrap();
    let scene = dir.join("map.toml");
    std::fs::write(&scene, topo.replacen(old, "topography = \"absent.npy\"", 1)).unwrap();
    let (code, out, err) = asperity(&["run", scene.to_str().unwrap(), "--plan"], &dir);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("absent.npy is read and characterised when the run starts"),
        "{out}"
    );
    // The run itself reads it, and says which file is missing (exit 2).
    let (code, _, err) = asperity(&["run", scene.to_str().unwrap()], &dir);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("surface.topography") && err.contains("absent.npy"),
        "{err}"
    );

    let cache = dir.join("cache");
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(["run", &scene_path("calibrated-gold.toml"), "--plan"])
        .env("ASPERITY_CACHE", &cache)
        .current_dir(&dir)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{text}");
    assert!(text.contains("is not cached"), "{text}");
    assert!(!cache.exists(), "the preview wrote the cache");
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

/// scenes outside GW's validity range or with impossible results
/// are refused naming the field (exit 2), or run with warnings in the text
/// summary, on stderr and in summary.json `"warnings"`.
#[test]
fn scenes_outside_the_model_are_refused_or_warned() {
    let dir = tmp("validity");
    let good = std::fs::read_to_string(scene_path("mems-gold.toml")).unwrap();
    let refused = [
        ("sigma = 5e-9 ", "sigma = 1e-3 ", "surface.sigma"),
        ("sigma = 5e-9 ", "sigma = 1e300 ", "surface.sigma"),
        ("e1 = 79e9", "e1 = 1e-300", "materials.e1"),
        (
            "closest_separation = 5e-9",
            "closest_separation = -1e-6",
            "program.closest_separation",
        ),
        ("points = 200", "points = 1000000000", "program.points"),
        (
            "nominal_area = 1e-8",
            "nominal_area = 1e-8\nheights = [1e-9, 2e-9]",
            "surface.heights",
        ),
        (
            "nominal_area = 1e-8",
            "nominal_area = 1e-8\nweibull_shape = 2.0",
            "surface.weibull_shape",
        ),
    ];
    for (old, new, field) in refused {
        std::fs::write(dir.join("bad.toml"), good.replacen(old, new, 1)).unwrap();
        let (code, out, err) = asperity(&["run", "bad.toml"], &dir);
        assert_eq!(code, 2, "{field}: {out} {err}");
        assert!(
            err.starts_with(&format!("error: {field}")),
            "{field}: {err}"
        );
    }
    // Large populations are refused with the estimate and the bound.
    for (extra, field) in [
        ("summits = 1000000000", "montecarlo.summits"),
        ("", "surface.nominal_area"),
    ] {
        let text = good.replacen(
            "nominal_area = 1e-8",
            "nominal_area = 1e2",
            extra.is_empty() as usize,
        ) + &format!("\n[montecarlo]\n{extra}\n");
        std::fs::write(dir.join("bad.toml"), text).unwrap();
        let (code, _, err) = asperity(&["run", "bad.toml"], &dir);
        assert_eq!(code, 2, "{err}");
        assert!(err.contains(field) && err.contains("GB"), "{err}");
    }
    // The reference scene is inside GW's validity: the only warning is the
    // pull-off of one switch against the integral's.
    let (code, out, err) = asperity(&["run", &scene_path("mems-gold.toml"), "--json"], &dir);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let warnings = v["warnings"].as_array().unwrap();
    assert!(
        warnings
            .iter()
            .all(|w| w.as_str().unwrap().starts_with("pull-off:")),
        "{warnings:?}"
    );
    // `auto` takes the full-solver law there (no analytic law is within
    // rtol); a scene that asks for Maugis-Dugdale gets one summit's error
    // and the surface-level one, which is far larger.
    assert_eq!(v["law"], "calibrated");
    let (_, text, _) = asperity(&["run", &scene_path("max-load.toml")], &dir);
    assert!(
        text.contains("differs from the full Lennard-Jones solution by 4.")
            && text.contains("on this surface: pull-off +98."),
        "{text}"
    );
    // Outside the model but possible: exit 0 with warnings.
    for (old, new, needle) in [
        ("sigma = 5e-9 ", "sigma = 1e-7 ", "A_r/A_n"),
        (
            "# start_separation = 40e-9",
            "start_separation = 1.0",
            "resolution",
        ),
    ] {
        std::fs::write(dir.join("warn.toml"), good.replacen(old, new, 1)).unwrap();
        let (code, out, err) = asperity(&["run", "warn.toml", "--json"], &dir);
        assert_eq!(code, 0, "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        let w = v["warnings"].as_array().unwrap();
        assert!(
            w.iter().any(|s| s.as_str().unwrap().contains(needle)),
            "{needle}: {w:?}"
        );
        assert!(err.contains("warning:"), "{err}");
        assert!(v["hysteresis_energy"].as_f64().unwrap() >= 0.0);
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Monte Carlo outputs say what each number is; no standard
/// errors where fewer than 20 summits are in contact; no NaN cells.
#[test]
fn montecarlo_outputs_are_honest() {
    let dir = tmp("mc-honest");
    let gold = std::fs::read_to_string(scene_path("montecarlo-gold.toml")).unwrap();
    let (code, out, err) = asperity(
        &["run", &scene_path("montecarlo-gold.toml"), "--out", "o"],
        &dir,
    );
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("minimum of the mean load"), "{out}");
    assert!(out.contains("seeds: mean"), "{out}");
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("o/summary.json")).unwrap())
            .unwrap();
    let m = &v["montecarlo"];
    // The pull-off populations: this one and 99 other seeds.
    assert_eq!(m["pull_off_other_seeds"].as_array().unwrap().len(), 99);
    assert!(m["pull_off_seed_std"].as_f64().unwrap() > 0.0);
    let csv = std::fs::read_to_string(dir.join("o/montecarlo.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let (se, contacts) = (
        header.iter().position(|h| *h == "load_se_N").unwrap(),
        header.iter().position(|h| *h == "contacts").unwrap(),
    );
    let mut blank = 0;
    for line in csv.lines().skip(1) {
        let cells: Vec<&str> = line.split(',').collect();
        if cells[contacts].parse::<f64>().unwrap() < 20.0 {
            assert_eq!(cells[se], "", "{line}");
            assert!(line.contains("fewer than 20"), "{line}");
            blank += 1;
        } else {
            assert!(!cells[se].is_empty(), "{line}");
        }
    }
    assert!(blank > 0);
    // One summit: no NaN anywhere.
    let one = gold.replacen("# summits = 10000", "summits = 1", 1);
    assert_ne!(one, gold);
    std::fs::write(dir.join("one.toml"), one).unwrap();
    let (code, _, err) = asperity(&["run", "one.toml", "--out", "p"], &dir);
    assert_eq!(code, 0, "{err}");
    for f in ["montecarlo.csv", "summary.json", "curve.csv"] {
        let t = std::fs::read_to_string(dir.join("p").join(f)).unwrap();
        assert!(!t.to_lowercase().contains("nan"), "{f}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// The resolution warning counts points, not intervals: a program whose
/// every point lies where summits are in range has `points` of them (10
/// is enough: no warning), and one with too few says so by
/// `program.points` instead of claiming that some lie out of range.
#[test]
fn resolution_warning_counts_points_in_range() {
    let dir = tmp("resolution-count");
    let dmt = std::fs::read_to_string(scene_path("dmt-stiff.toml")).unwrap();
    for (points, expect) in [(10, None), (5, Some("5 points per leg (program.points)"))] {
        let scene = dmt.replacen("points = 100", &format!("points = {points}"), 1);
        std::fs::write(dir.join("p.toml"), scene).unwrap();
        let (code, out, err) = asperity(&["run", "p.toml", "--json"], &dir);
        assert_eq!(code, 0, "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        let res: Vec<&str> = v["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .filter_map(|w| w.as_str())
            .filter(|w| w.starts_with("resolution"))
            .collect();
        match expect {
            None => assert!(res.is_empty(), "{points}: {res:?}"),
            Some(needle) => assert!(
                res.len() == 1 && res[0].contains(needle) && !res[0].contains("only"),
                "{points}: {res:?}"
            ),
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}
