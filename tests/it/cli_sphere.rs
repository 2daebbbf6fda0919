//! `asperity sphere`: JSON keys, CSV curve, exit code 2 on bad input.
use std::process::Command;

fn run(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_asperity"))
        .arg("sphere")
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn json_has_the_documented_keys() {
    let out = run(&["--mu", "1", "--resolution", "0.5", "--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let pull = v["pull_off_load_control"].as_f64().unwrap();
    assert!(pull < -1.6 && pull > -1.75, "{pull}");
    let jl = v["jump_out_load"].as_f64().unwrap();
    assert!(jl > pull && jl < -0.8);
    let jd = v["jump_out_interference"].as_f64().unwrap();
    assert!(jd < -0.9 && jd > -1.1, "{jd}");
    let a0 = v["contact_radius_zero_load"].as_f64().unwrap();
    assert!(a0 > 1.6 && a0 < 1.85, "{a0}");
}

#[test]
fn small_mu_has_no_jump_and_table_prints() {
    let out = run(&["--mu", "0.05", "--json"]);
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(v["jump_out_load"].is_null());
    let out = run(&["--mu", "0.5", "--rho", "100"]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("pull-off, load control") && text.contains("rho = 100"),
        "{text}"
    );
}

#[test]
fn curve_csv_has_a_header_and_rows() {
    let dir = std::env::temp_dir().join(format!("asperity-cli-sphere-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("curve.csv");
    let out = run(&[
        "--mu",
        "1",
        "--resolution",
        "0.5",
        "--curve",
        path.to_str().unwrap(),
    ]);
    assert!(out.status.success());
    let text = std::fs::read_to_string(&path).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    assert!(header.starts_with("central_gap,approach,load_bar,interference_bar"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert!(rows.len() > 50);
    assert!(rows.iter().all(|r| r.len() == 8));
    // central gap decreases along the curve; the load ends compressive
    assert!(rows.windows(2).all(|w| w[1][0] < w[0][0]));
    assert!(rows.last().unwrap()[2] >= 2.0);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_input_exits_2_naming_the_argument() {
    for (args, name) in [
        (vec!["--mu", "0"], "--mu"),
        (vec!["--mu", "-1"], "--mu"),
        (vec!["--mu", "NaN"], "--mu"),
        (vec!["--mu", "1", "--rho", "5"], "--rho"),
        (vec!["--mu", "1", "--rho", "nan"], "--rho"),
        (vec!["--mu", "abc"], "--mu"),
        (vec!["--mu", "101"], "--mu"),
        (vec!["--mu", "20", "--rho", "1000"], "--rho"),
    ] {
        let out = run(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains(name), "{args:?}: {err}");
    }
}

/// absurd or too-coarse resolutions exit 2 naming `--resolution`
/// at once (1e6 once tried to allocate 16 PB); expensive ones (mu = 10 at
/// resolution 4 once ran for minutes; since solver version 4 it takes ~20 s,
/// resolution 16 would take ~30 min) are refused with the estimate and the
/// bound.
#[test]
fn costly_or_too_coarse_resolutions_are_refused_with_the_estimate() {
    let t = std::time::Instant::now();
    for args in [
        vec!["--mu", "1", "--resolution", "1e6"],
        vec!["--mu", "1", "--resolution", "100"],
        vec!["--mu", "1", "--resolution", "0.05"],
        vec!["--mu", "1", "--resolution", "0.2"],
        vec!["--mu", "10", "--resolution", "16"],
        vec!["--mu", "10", "--resolution", "30"],
    ] {
        let out = run(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains("--resolution"), "{args:?}: {err}");
    }
    let out = run(&["--mu", "10", "--resolution", "16"]);
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains("estimated") && err.contains("nodes") && err.contains("120 s"),
        "{err}"
    );
    assert!(t.elapsed().as_secs_f64() < 5.0);
}
