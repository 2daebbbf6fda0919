//! Never silently wrong: each case here was an exit-0 result that
//! was wrong or meaningless without a word; now the value is right, or it
//! comes with a warning, or the input is refused (exit 2) naming the flag or
//! field and its range.
use crate::common::cli;
use cli::{bin, example, json, run, tmp};
use std::path::Path;

/// Every listed load is met to the scene's `rtol` (before: 2.48e-6,
/// 1.17e-5, 9.76e-5 N for soft-jkr, -4.07e-7 N for conical-summits' 1e-6 N,
/// 1.7 % off for dmt-stiff).
#[test]
fn listed_loads_are_met_to_rtol() {
    let dir = tmp("loads");
    for name in ["soft-jkr.toml", "conical-summits.toml", "dmt-stiff.toml"] {
        let text: String = example(name)
            .lines()
            .map(|l| {
                if l.starts_with("closest_separation") {
                    "loads = [1e-6, 1e-5, 1e-4]".to_string()
                } else {
                    l.to_string()
                }
            })
            .collect::<Vec<_>>()
            .join("\n");
        std::fs::write(dir.join(name), &text).unwrap();
        let (code, _, err) = run(&["run", name, "--out", "o", "--json"], &dir);
        assert_eq!(code, 0, "{name}: {err}");
        let s = json(&dir.join("o/summary.json"));
        let rtol = s["rtol"].as_f64().unwrap();
        let states = s["states"].as_array().unwrap();
        assert_eq!(states.len(), 3, "{name}");
        for (st, want) in states.iter().zip([1e-6, 1e-5, 1e-4]) {
            let got = st["load_N"].as_f64().unwrap();
            assert!(
                (got - want).abs() <= rtol * want,
                "{name}: asked {want:e} N, got {got:e} N (rtol {rtol:e})"
            );
        }
    }
}

/// A scene from an example with `edits` (`key = value` lines replacing the
/// line that starts with `key`, or appended to `[table]` when absent).
fn edited(name: &str, edits: &[(&str, &str)]) -> String {
    let mut lines: Vec<String> = example(name).lines().map(String::from).collect();
    for (key, line) in edits {
        if let Some(l) = lines.iter_mut().find(|l| l.starts_with(key)) {
            *l = line.to_string();
        } else {
            panic!("{name} has no line starting with {key}");
        }
    }
    lines.join("\n")
}

/// Holm's relation ends where the metal melts. `heating --voltage
/// 10` printed 31,991 K; now no temperature, `condition = molten` and a
/// warning; softening is warned about; the inverse stops at melting.
#[test]
fn no_temperature_above_melting_from_heating() {
    let dir = tmp("heating");
    let (code, out, err) = run(&["heating", "--voltage", "10", "--json"], &dir);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert!(v["max_temperature_K"].is_null(), "{v}");
    assert_eq!(v["condition"], "molten");
    assert!(v["warnings"][0]
        .as_str()
        .unwrap()
        .contains("melting voltage 0.4079 V"));
    let (code, out, _) = run(&["heating", "--voltage", "0.1", "--json"], &dir);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["condition"], "softened");
    assert!(v["warnings"][0].as_str().unwrap().contains("softens"));
    let (code, out, _) = run(&["heating", "--voltage", "0.05", "--json"], &dir);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["condition"], "solid");
    assert_eq!(v["warnings"].as_array().unwrap().len(), 0);
    // Text: no temperature, a warning on stderr.
    let (code, out, err) = run(&["heating", "--voltage", "10"], &dir);
    assert_eq!(code, 0);
    assert!(
        out.contains("the spot melts") && !out.contains("31991"),
        "{out}"
    );
    assert!(err.contains("warning:"), "{err}");
    // Another metal's limits (copper softens ~463 K, melts 1358 K).
    let (_, out, _) = run(
        &[
            "heating",
            "--voltage",
            "0.1",
            "--softening-temperature",
            "463",
            "--melting-temperature",
            "1358",
            "--json",
        ],
        &dir,
    );
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["condition"], "solid", "{v}");
    for (args, flag) in [
        (vec!["--max-temperature", "1e300"], "--max-temperature"),
        (vec!["--max-temperature", "2000"], "--max-temperature"),
        (
            vec!["--voltage", "0.1", "--melting-temperature", "300"],
            "--melting-temperature",
        ),
        (
            vec!["--voltage", "0.1", "--softening-temperature", "-1"],
            "--softening-temperature",
        ),
        (
            vec!["--voltage", "0.1", "--bulk-temperature", "1400"],
            "--bulk-temperature",
        ),
    ] {
        let mut a = vec!["heating"];
        a.extend(args);
        let (code, _, err) = run(&a, &dir);
        assert_eq!(code, 2, "{a:?}: {err}");
        assert!(err.contains(flag), "{a:?}: {err}");
    }
}

/// In scenes: `film_resistance = 1e-6` gave 7.55e9 K with no word;
/// now the summary's temperature is null and a warning names the current.
#[test]
fn no_temperature_above_melting_in_scenes() {
    let dir = tmp("heating-scene");
    let text = edited(
        "rf-mems-switch.toml",
        &[("film_resistance", "film_resistance = 1e-6")],
    );
    std::fs::write(dir.join("rf.toml"), text).unwrap();
    let (code, _, err) = run(&["run", "rf.toml", "--out", "o"], &dir);
    assert_eq!(code, 0, "{err}");
    let s = json(&dir.join("o/summary.json"));
    assert!(s["heating"]["contact_voltage_V"].as_f64().unwrap() > 1.0);
    assert!(
        s["heating"]["max_temperature_K"].is_null(),
        "{}",
        s["heating"]
    );
    let warned = s["warnings"].as_array().unwrap().iter().any(|w| {
        w.as_str().unwrap().contains("electrical.current") && w.as_str().unwrap().contains("melts")
    });
    assert!(warned, "{}", s["warnings"]);
    // Every temperature written is below melting.
    let csv = std::fs::read_to_string(dir.join("o/curve.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let k = header
        .iter()
        .position(|h| *h == "max_temperature_K")
        .unwrap();
    for line in csv.lines().skip(1) {
        if let Ok(t) = line.split(',').nth(k).unwrap().parse::<f64>() {
            assert!(t < 1337.33, "{line}");
        }
    }
    // The example itself stays quiet (its spots stay near 293 K).
    let (code, _, _) = run(
        &[
            "run",
            &format!(
                "{}/examples/scenes/rf-mems-switch.toml",
                env!("CARGO_MANIFEST_DIR")
            ),
            "--out",
            "o2",
        ],
        &dir,
    );
    assert_eq!(code, 0);
    let s = json(&dir.join("o2/summary.json"));
    assert!(s["heating"]["max_temperature_K"].as_f64().unwrap() < 300.0);
    assert!(!s["warnings"].to_string().contains("electrical.current"));
    // A metal's limits are scene keys, checked against each other.
    for (line, field) in [
        (
            "current = 0.1\nmelting_temperature = 300",
            "electrical.melting_temperature",
        ),
        (
            "current = 0.1\nsoftening_temperature = 0",
            "electrical.softening_temperature",
        ),
        (
            "current = 0.1\nbulk_temperature = 2000",
            "electrical.bulk_temperature",
        ),
        (
            "melting_temperature = 1300",
            "electrical.melting_temperature",
        ),
    ] {
        let text = edited("rf-mems-switch.toml", &[("current", line)]);
        std::fs::write(dir.join("bad.toml"), text).unwrap();
        let (code, _, err) = run(&["run", "bad.toml", "--out", "o3"], &dir);
        assert_eq!(code, 2, "{line}: {err}");
        assert!(err.contains(field), "{line}: {err}");
    }
}

/// Two spots of 1 um whose centres are 0.1 um apart gave 0.0449
/// Ohm at exit 0 (3.7 times one spot); now exit 2 naming the pair.
#[test]
fn overlapping_spots_are_refused_naming_the_pair() {
    let dir = tmp("spots");
    std::fs::write(
        dir.join("ov.csv"),
        "x_m,y_m,radius_m\n0,0,1e-6\n1e-7,0,1e-6\n",
    )
    .unwrap();
    let (code, _, err) = run(&["spots", "ov.csv", "--resistivity", "2.44e-8"], &dir);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("spots 0 and 1 (0-based) overlap"), "{err}");
    // Touching spots are separate.
    std::fs::write(
        dir.join("touch.csv"),
        "x_m,y_m,radius_m\n0,0,1e-6\n2e-6,0,1e-6\n",
    )
    .unwrap();
    let (code, _, err) = run(&["spots", "touch.csv", "--resistivity", "2.44e-8"], &dir);
    assert_eq!(code, 0, "{err}");
}

fn write_map(dir: &Path, name: &str, f: impl Fn(usize, usize) -> f64) {
    let text: Vec<String> = (0..32)
        .map(|i| {
            (0..32)
                .map(|j| format!("{:e}", f(i, j)))
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect();
    std::fs::write(dir.join(name), text.join("\n") + "\n").unwrap();
}

/// A map whose relief is roundoff (a tilted plane: 9.9e-22 m rms
/// after the plane fit) was characterised; now refused as flat. And:
/// `--pixel-size 1e-300` and heights x 1e300 gave nulls at exit 0.
#[test]
fn flat_maps_and_absurd_scales_are_refused() {
    let dir = tmp("surface");
    write_map(&dir, "tilt.txt", |i, j| {
        5e-6 + i as f64 * 1e-9 + j as f64 * 2e-9
    });
    write_map(&dir, "rough.txt", |i, j| {
        1e-9 * (((i * 7 + j * 13) % 5) as f64 - 2.0)
    });
    let (code, _, err) = run(&["surface", "tilt.txt", "--pixel-size", "1e-7"], &dir);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("tilt.txt") && err.contains("roundoff"),
        "{err}"
    );
    for (args, flag) in [
        (vec!["--pixel-size", "1e-300"], "--pixel-size"),
        (vec!["--pixel-size", "1e9"], "--pixel-size"),
        (vec!["--pixel-size", "1e-7", "--scale", "1e300"], "--scale"),
    ] {
        let mut a = vec!["surface", "rough.txt", "--json"];
        a.extend(args);
        let (code, out, err) = run(&a, &dir);
        assert_eq!(code, 2, "{a:?}: {out} {err}");
        assert!(err.contains(flag), "{a:?}: {err}");
    }
    let (code, out, err) = run(
        &["surface", "rough.txt", "--pixel-size", "1e-7", "--json"],
        &dir,
    );
    assert_eq!(code, 0, "{err}");
    assert!(
        !out.contains("null") || !out.contains("\"m4\":null"),
        "{out}"
    );
}

/// Nulls at exit 0 (`F: null`, `load_N: null`) are now exit 2
/// naming the argument and its range or the overflow.
#[test]
fn overflowing_arguments_exit_2_naming_them() {
    let dir = tmp("nulls");
    for (args, flag) in [
        (
            vec!["fn", "--dist", "gaussian", "--n", "1e3", "--h", "0,1"],
            "--n",
        ),
        (
            vec!["fn", "--dist", "gaussian", "--n", "2", "--h", "-1e300"],
            "--h",
        ),
        (
            vec!["fn", "--dist", "exponential", "--n", "2", "--h", "-1e300"],
            "--h",
        ),
        (
            vec![
                "shape",
                "--profile",
                "paraboloid",
                "--radius",
                "1e-6",
                "--estar",
                "1e9",
                "--w",
                "0.1",
                "--radii",
                "1e300",
            ],
            "--radii",
        ),
        (
            vec![
                "punch",
                "--estar",
                "1e9",
                "--w",
                "0.1",
                "--radius",
                "1e-3",
                "--amplitude",
                "0.1",
                "--wavelength",
                "1e-5",
                "--radii",
                "1e300",
            ],
            "--radii",
        ),
        (
            vec!["heating", "--max-temperature", "1e300"],
            "--max-temperature",
        ),
    ] {
        let mut a = args.clone();
        a.push("--json");
        let (code, out, err) = run(&a, &dir);
        assert_eq!(code, 2, "{a:?}: {out} {err}");
        assert!(err.contains(flag), "{a:?}: {err}");
        assert!(!out.contains("null"), "{a:?}: {out}");
    }
    // In range, finite numbers.
    let (code, out, err) = run(
        &[
            "fn", "--dist", "gaussian", "--n", "100", "--h", "-5,0,5", "--json",
        ],
        &dir,
    );
    assert_eq!(code, 0, "{err}");
    assert!(!out.contains("null"), "{out}");
}

/// `shape --w 1e-300` gave a positive pull-off (4.7e-306 N: the
/// adhesive term underflowed); now -3/2 pi w R to the subnormal range.
#[test]
fn a_tiny_work_of_adhesion_keeps_a_tensile_pull_off() {
    let dir = tmp("tiny-w");
    for w in [1e-200, 1e-280] {
        let ws = format!("{w:e}");
        let (code, out, err) = run(
            &[
                "shape",
                "--profile",
                "paraboloid",
                "--radius",
                "1e-6",
                "--estar",
                "1e9",
                "--w",
                &ws,
                "--json",
            ],
            &dir,
        );
        assert_eq!(code, 0, "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        let p = v["pull_off_load_control"]["load_N"].as_f64().unwrap();
        let want = -1.5 * std::f64::consts::PI * w * 1e-6;
        assert!((p / want - 1.0).abs() < 1e-9, "w {w}: {p} vs {want}");
    }
}

/// The rms slope and curvature users compare with other tools,
/// with the surface's rms gradient beside the profile slope.
#[test]
fn surface_prints_rms_slope_gradient_and_curvature() {
    let dir = tmp("slopes");
    write_map(&dir, "rough.txt", |i, j| {
        1e-9 * (((i * 7 + j * 13) % 5) as f64 - 2.0)
    });
    let (code, out, err) = run(
        &["surface", "rough.txt", "--pixel-size", "1e-7", "--json"],
        &dir,
    );
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let f = |k: &str| v[k].as_f64().unwrap();
    assert!((f("rms_slope") - f("m2").sqrt()).abs() <= 1e-15 * f("rms_slope"));
    assert!((f("rms_gradient") - (2.0 * f("m2")).sqrt()).abs() <= 1e-15 * f("rms_gradient"));
    assert!((f("rms_curvature_per_m") - f("m4").sqrt()).abs() <= 1e-15 * f("rms_curvature_per_m"));
    let (_, text, _) = run(&["surface", "rough.txt", "--pixel-size", "1e-7"], &dir);
    assert!(
        text.contains("rms slope (profile)") && text.contains("rms curvature"),
        "{text}"
    );
}

/// `--shard-from-env` reads the Slurm array variables; a stepped
/// array is refused before any point runs (exit 2 naming the flag).
#[test]
fn shard_from_env_refuses_stepped_arrays() {
    let dir = tmp("slurm");
    let scene = format!(
        "{}/examples/scenes/soft-jkr.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let o = bin()
        .args([
            "sweep",
            &scene,
            "--vary",
            "surface.sigma=1e-7:2e-7:4",
            "--shard-from-env",
            "--out",
            "s",
        ])
        .env("SLURM_ARRAY_TASK_ID", "2")
        .env("SLURM_ARRAY_TASK_MIN", "0")
        .env("SLURM_ARRAY_TASK_MAX", "14")
        .env("SLURM_ARRAY_TASK_COUNT", "8")
        .env("SLURM_ARRAY_TASK_STEP", "2")
        .current_dir(&dir)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("--shard-from-env"), "{err}");
    assert!(!dir.join("s/results.csv").exists());
}

/// A misspelt or fractional-integer `--vary` path ran every point,
/// then exited 1; now exit 2 naming the path before the first point.
#[test]
fn vary_paths_are_checked_before_the_first_point() {
    let dir = tmp("vary");
    let scene = format!(
        "{}/examples/scenes/montecarlo-gold.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    for (vary, want) in [
        ("surface.sigm=1e-9:2e-9:3", "surface.sigm"),
        ("montecarlo.summits=1:100:3", "montecarlo.summits"),
    ] {
        let out = format!("s-{}", want.replace('.', "-"));
        let (code, _, err) = run(&["sweep", &scene, "--vary", vary, "--out", &out], &dir);
        assert_eq!(code, 2, "{vary}: {err}");
        assert!(err.contains(want), "{vary}: {err}");
        let rows = std::fs::read_to_string(dir.join(&out).join("results.csv")).unwrap_or_default();
        assert!(rows.lines().count() <= 1, "{vary}: points ran: {rows}");
    }
}
