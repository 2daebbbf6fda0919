//! `asperity surface`: the JSON contract (keys exactly as the contract writes
//! them) against the numpy reference, flags, outputs, and bad files (exit
//! 2, one stderr line naming the file and the problem).

use crate::common::{local, num, rel};
use serde_json::Value;
use std::process::Command;

fn data(name: &str) -> String {
    format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .arg("surface")
        .args(args)
        .output()
        .expect("run asperity");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn json(args: &[&str]) -> Value {
    let (code, out, err) = run(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(out.trim()).expect("one JSON object")
}

fn keys(v: &Value) -> Vec<&str> {
    let mut k: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
    k.sort_unstable();
    k
}

#[test]
fn json_has_exactly_the_contract_keys() {
    let v = json(&[&data("surface_a.npy"), "--pixel-size", "1e-7", "--json"]);
    let mut top = vec![
        "rows",
        "cols",
        "rms_height_m",
        "m0",
        "m2",
        "m4",
        // slopes and curvature beside the moments.
        "rms_slope",
        "rms_gradient",
        "rms_curvature_per_m",
        "bandwidth_alpha",
        "summits",
        "gw_from_moments",
        "plasticity_index",
        // Where the map came from, and warnings about its units.
        "source",
        "warnings",
        // GW's and Persson's error against the exact solution of the map.
        "model_error",
    ];
    top.sort_unstable();
    assert_eq!(keys(&v), top);
    let mut s = vec![
        "count",
        "density_per_m2",
        "mean_curvature_per_m",
        "radius_m",
        "height_std_m",
        "mean_height_m",
    ];
    s.sort_unstable();
    assert_eq!(keys(&v["summits"]), s);
    assert_eq!(
        keys(&v["gw_from_moments"]),
        ["density_per_m2", "radius_m", "sigma_m"]
    );
    assert!(v["plasticity_index"].is_null());
}

fn assert_like_reference(v: &Value, r: &Value) {
    assert_eq!(v["rows"], r["rows"]);
    assert_eq!(v["cols"], r["cols"]);
    assert_eq!(v["summits"]["count"], r["summits"]["count"]);
    for k in ["rms_height_m", "m0", "m2", "m4", "bandwidth_alpha"] {
        assert!(rel(num(&v[k]), num(&r[k])) < 1e-12, "{k}");
    }
    for k in [
        "density_per_m2",
        "mean_curvature_per_m",
        "radius_m",
        "height_std_m",
    ] {
        let (a, b) = (num(&v["summits"][k]), num(&r["summits"][k]));
        assert!(rel(a, b) < 1e-12, "summits.{k}: {a} vs {b}");
    }
    let (a, b) = (
        num(&v["summits"]["mean_height_m"]),
        num(&r["summits"]["mean_height_m"]),
    );
    assert!(
        (a - b).abs() < 1e-12 * num(&r["rms_height_m"]),
        "mean_height_m"
    );
    for k in ["density_per_m2", "radius_m", "sigma_m"] {
        let (a, b) = (num(&v["gw_from_moments"][k]), num(&r["gw_from_moments"][k]));
        assert!(rel(a, b) < 1e-12, "gw_from_moments.{k}");
    }
}

#[test]
fn both_readers_and_both_modes_match_the_numpy_reference() {
    let refs = local("surface_ref.json");
    let a = &refs["maps"]["surface_a"];
    for file in ["surface_a.npy", "surface_a.txt"] {
        let v = json(&[&data(file), "--pixel-size", "1e-7", "--json"]);
        assert_like_reference(&v, &a["interior"]);
        let v = json(&[&data(file), "--pixel-size", "1e-7", "--periodic", "--json"]);
        assert_like_reference(&v, &a["periodic"]);
    }
    let b = &refs["maps"]["surface_b"];
    for file in ["surface_b.npy", "surface_b.csv"] {
        let args = [
            &data(file),
            "--pixel-size",
            "5e-8",
            "--scale",
            "1e-9",
            "--json",
        ];
        assert_like_reference(&json(&args), &b["interior"]);
    }
}

#[test]
fn plasticity_index_from_the_moment_based_gw_parameters() {
    let v = json(&[
        &data("surface_a.npy"),
        "--pixel-size",
        "1e-7",
        "--estar",
        "1e11",
        "--hardness",
        "2e9",
        "--json",
    ]);
    let g = &v["gw_from_moments"];
    let psi = 1e11 / 2e9 * (num(&g["sigma_m"]) / num(&g["radius_m"])).sqrt();
    assert!(rel(num(&v["plasticity_index"]), psi) < 1e-14, "{v}");
}

#[test]
fn out_writes_the_json_copy_and_both_charts() {
    let dir = std::env::temp_dir().join(format!("asperity-cli-surface-{}", std::process::id()));
    let d = dir.to_str().unwrap();
    let (code, out, err) = run(&[
        &data("surface_b.npy"),
        "--pixel-size",
        "5e-8",
        "--scale",
        "1e-9",
        "--json",
        "--out",
        d,
    ]);
    assert_eq!(code, 0, "{err}");
    let copy = std::fs::read_to_string(dir.join("surface.json")).unwrap();
    assert_eq!(copy.trim(), out.trim());
    for svg in ["summit_heights.svg", "summit_map.svg"] {
        let s = std::fs::read_to_string(dir.join(svg)).unwrap();
        assert!(s.starts_with("<svg") || s.contains("<svg"), "{svg}");
    }
    let h = std::fs::read_to_string(dir.join("summit_heights.svg")).unwrap();
    assert!(h.contains("Gaussian, GW parameters from moments"));
    std::fs::remove_dir_all(&dir).ok();
    // Without --json: a table.
    let (code, out, _) = run(&[
        &data("surface_a.csv").replace("a.csv", "a.txt"),
        "--pixel-size",
        "1e-7",
    ]);
    assert_eq!(code, 0);
    assert!(
        out.contains("bandwidth alpha") && out.contains("GW from moments"),
        "{out}"
    );
}

fn one_line_error(args: &[&str]) -> String {
    let (code, out, err) = run(args);
    assert_eq!(code, 2, "{args:?}: {out} {err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    err
}

#[test]
fn bad_files_exit_2_naming_the_file_and_the_problem() {
    for (file, problem) in [
        ("one_d.npy", "1-D array"),
        ("one_d.txt", "1-D profile"),
        ("ragged.txt", "ragged rows: line 2"),
        ("nan.npy", "NaN height at row 1, column 2"),
        ("nan.csv", "NaN height at row 1, column 1"),
        ("inf.npy", "infinite height at row 2, column 0"),
        ("inf.txt", "infinite height at row 2, column 2"),
        ("empty.npy", "empty"),
        ("empty.txt", "empty"),
        ("int64.npy", "unsupported dtype '<i8'"),
        ("fortran.npy", "Fortran"),
    ] {
        let path = data(&format!("surface_bad/{file}"));
        let err = one_line_error(&[&path, "--pixel-size", "1e-7", "--json"]);
        assert!(
            err.contains(&path) && err.contains(problem),
            "{file}: {err}"
        );
    }
    let missing = data("surface_bad/missing.npy");
    let err = one_line_error(&[&missing, "--pixel-size", "1e-7"]);
    assert!(
        err.contains("missing.npy") && err.contains("cannot read"),
        "{err}"
    );
    let err = one_line_error(&[&data("surface_ref.json"), "--pixel-size", "1e-7"]);
    assert!(err.contains("unknown extension 'json'"), "{err}");
}

#[test]
fn bad_flags_exit_2_naming_the_flag() {
    let f = data("surface_a.npy");
    // clap reads "-1e-7" as a flag: the `=` form passes it as a value.
    let err = one_line_error(&[&f, "--pixel-size=-1e-7"]);
    assert!(
        err.contains("--pixel-size = -1e-7 is out of range"),
        "{err}"
    );
    let err = one_line_error(&[&f, "--pixel-size", "-2"]);
    assert!(err.contains("--pixel-size"), "{err}");
    let err = one_line_error(&[&f, "--pixel-size", "1e-7", "--scale", "0"]);
    assert!(err.contains("--scale"), "{err}");
    let err = one_line_error(&[&f, "--pixel-size", "1e-7", "--estar", "1e11"]);
    assert!(err.contains("--hardness"), "{err}");
    let err = one_line_error(&[
        &f,
        "--pixel-size",
        "1e-7",
        "--estar",
        "1e11",
        "--hardness",
        "-2",
    ]);
    assert!(err.contains("--hardness"), "{err}");
    let err = one_line_error(&[&f]);
    assert!(err.contains("--pixel-size"), "{err}");
}

fn run_scene(scene: &str, out: &std::path::Path) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(["run", scene, "--json", "--out"])
        .arg(out)
        .output()
        .expect("run asperity");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn run_on_the_measured_topography_scene_reports_both_models() {
    let scene = format!(
        "{}/examples/scenes/measured-topography.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let dir = std::env::temp_dir().join(format!("asperity-measured-{}", std::process::id()));
    let (code, out, err) = run_scene(&scene, &dir);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(out.trim()).expect("one JSON object");
    let t = &v["topography"];
    assert_eq!(
        keys(t),
        [
            "bandwidth_alpha",
            "cols",
            "file",
            "gw_from_moments",
            "m0",
            "m2",
            "m4",
            "model",
            "other",
            "periodic",
            "pixel_size_m",
            "pixel_size_y_m",
            "rms_height_m",
            "rows",
            "summits"
        ]
    );
    assert_eq!(t["model"], "measured");
    assert_eq!(t["summits"]["count"], 525);
    assert_eq!(
        (t["rows"].as_u64(), t["cols"].as_u64()),
        (Some(160), Some(160))
    );
    let other = &t["other"];
    assert_eq!(other["model"], "moments");
    for k in ["max_load", "max_area", "max_count", "pull_off_load"] {
        assert!(other[k].is_number(), "{k}: {other}");
    }
    assert!(v["plan"].as_array().unwrap().iter().any(|d| d
        .as_str()
        .unwrap()
        .starts_with("topography: measured summits")));
    for f in ["summit_heights.svg", "summit_map.svg", "curve.csv"] {
        let text = std::fs::read_to_string(dir.join(f)).unwrap();
        assert!(!text.is_empty(), "{f}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn measured_scene_with_summit_statistics_exits_2_naming_the_key() {
    let src = format!(
        "{}/examples/scenes/measured-topography.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(src).unwrap().replacen(
        "pixel_size = 50e-9",
        "pixel_size = 50e-9\nsigma = 5e-9",
        1,
    );
    let dir = std::env::temp_dir().join(format!("asperity-measured-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("bad.toml");
    std::fs::write(&scene, text).unwrap();
    let (code, _, err) = run_scene(scene.to_str().unwrap(), &dir);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("surface.sigma"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
