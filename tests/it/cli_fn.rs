//! `asperity fn`: JSON contract, table output, exit code 2 on bad input.

use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .arg("fn")
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn json_has_full_precision_values() {
    let (code, out, _) = run(&[
        "--dist",
        "gaussian",
        "--n",
        "1.5",
        "--h",
        "-1,0,2.5,37",
        "--json",
    ]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["dist"], "gaussian");
    assert_eq!(v["n"], 1.5);
    let values = v["values"].as_array().unwrap();
    assert_eq!(values.len(), 4);
    assert_eq!(values[1]["h"], 0.0);
    // F_3/2(0) = 2^(1/4) Gamma(5/4)/sqrt(2 pi) (mpmath: 0.4300199936622596...).
    let f0 = values[1]["F"].as_f64().unwrap();
    assert!((f0 / 0.430_019_993_662_259_6 - 1.0).abs() < 1e-15, "{f0}");
    let f37 = values[3]["F"].as_f64().unwrap();
    assert!(f37 > 0.0 && f37 < 1e-300);
}

#[test]
fn exponential_json_and_table() {
    let (code, out, _) = run(&["--dist", "exponential", "--n", "1", "--h", "0, 2", "--json"]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let f = v["values"][1]["F"].as_f64().unwrap();
    assert!((f / (-2f64).exp() - 1.0).abs() < 1e-15);
    let (code, out, _) = run(&["--dist", "exponential", "--n", "0.3", "--h=-1,1"]);
    assert_eq!(code, 0);
    assert!(
        out.contains("quadrature") && out.lines().count() == 4,
        "{out}"
    );
}

#[test]
fn bad_input_exits_2_naming_the_argument() {
    for (args, name) in [
        (vec!["--dist", "weibull", "--n", "1", "--h", "1"], "--dist"),
        (vec!["--dist", "gaussian", "--n", "-1", "--h", "1"], "--n"),
        (vec!["--dist", "gaussian", "--n", "NaN", "--h", "1"], "--n"),
        (vec!["--dist", "gaussian", "--n", "inf", "--h", "1"], "--n"),
        (vec!["--dist", "gaussian", "--n", "one", "--h", "1"], "--n"),
        (vec!["--dist", "gaussian", "--n", "1", "--h", ""], "--h"),
        (vec!["--dist", "gaussian", "--n", "1", "--h", "1,,2"], "--h"),
        (vec!["--dist", "gaussian", "--n", "1", "--h", "1,x"], "--h"),
        (vec!["--dist", "gaussian", "--n", "1", "--h", "nan"], "--h"),
        (vec!["--dist", "gaussian", "--n", "1"], "--h"),
    ] {
        let (code, out, err) = run(&args);
        assert_eq!(code, 2, "{args:?}");
        assert!(out.is_empty(), "{args:?}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(name), "{args:?}: {err}");
    }
}
