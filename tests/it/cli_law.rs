//! `asperity law`: JSON output of every law and one-line errors (exit 2).
use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .arg("law")
        .args(args)
        .output()
        .expect("run asperity");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn json(args: &[&str]) -> serde_json::Value {
    let (code, out, err) = run(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(out.trim()).expect("one JSON object")
}

fn num(v: &serde_json::Value, key: &str) -> f64 {
    v[key].as_f64().unwrap_or_else(|| panic!("{key} in {v}"))
}

#[test]
fn jkr_gives_its_closed_forms() {
    let v = json(&["--law", "jkr", "--json"]);
    assert_eq!(v["law"], "jkr");
    assert!((num(&v, "pull_off_load_control") + 1.5).abs() < 1e-14);
    assert!((num(&v, "jump_out_load") + 5.0 / 6.0).abs() < 1e-14);
    let dc = -0.75 * (4.0f64 / 3.0).powf(2.0 / 3.0);
    assert!((num(&v, "jump_out_interference") - dc).abs() < 1e-14);
    assert!((num(&v, "contact_radius_zero_load") - 6f64.cbrt()).abs() < 1e-14);
}

#[test]
fn maugis_matches_checked_pull_off_values() {
    // physics.md: lambda 0.1 -> -1.9506, 1 -> -1.6007, 10 -> -1.5016.
    for (l, p) in [("0.1", -1.9506), ("1", -1.6007), ("10", -1.5016)] {
        let v = json(&["--law", "maugis", "--lambda", l, "--json"]);
        assert_eq!(v["law"], "maugis");
        assert_eq!(num(&v, "lambda"), l.parse::<f64>().unwrap());
        assert!((num(&v, "pull_off_load_control") - p).abs() < 5e-5, "{v}");
        // Something always snaps in the Dugdale model.
        assert!(num(&v, "jump_out_load") < 0.0);
        assert!(num(&v, "jump_out_interference") < 0.0);
        let a0 = num(&v, "contact_radius_zero_load");
        assert!(a0 > 2f64.cbrt() && a0 < 6f64.cbrt(), "{v}");
    }
    // Default lambda = 1.
    let v = json(&["--law", "maugis", "--json"]);
    assert!((num(&v, "pull_off_load_control") + 1.6007).abs() < 5e-5);
}

#[test]
fn cos_shares_maugis_pull_off_and_zero_load_radius() {
    for l in ["0.3", "3"] {
        let c = json(&["--law", "cos", "--lambda", l, "--json"]);
        let m = json(&["--law", "maugis", "--lambda", l, "--json"]);
        assert_eq!(c["law"], "cos");
        for k in ["pull_off_load_control", "contact_radius_zero_load"] {
            assert!((num(&c, k) - num(&m, k)).abs() < 1e-14, "{k}");
        }
        assert!(num(&c, "jump_out_load") < 0.0);
    }
}

#[test]
fn every_law_prints_a_table_without_json() {
    for law in ["hertz", "bradley", "dmt", "jkr", "maugis", "cos"] {
        let (code, out, err) = run(&["--law", law]);
        assert_eq!(code, 0, "{law}: {err}");
        assert!(out.contains("pull-off, load control"), "{out}");
    }
}

#[test]
fn bad_input_exits_2_with_one_line_naming_the_argument() {
    for (args, needle) in [
        (vec!["--law", "maugis", "--lambda", "0"], "--lambda"),
        (vec!["--law", "maugis", "--lambda", "-2"], "--lambda"),
        (vec!["--law", "maugis", "--lambda", "NaN"], "--lambda"),
        (vec!["--law", "cos", "--lambda", "inf"], "--lambda"),
        // Beyond the accepted [1e-6, 1e6]: the library names `lambda`.
        (vec!["--law", "maugis", "--lambda", "1e7"], "lambda"),
        (vec!["--law", "maugis", "--lambda", "abc"], "--lambda"),
        (vec!["--law", "mdx"], "law"),
        (vec!["--lambda", "1"], "--law"),
    ] {
        let (code, out, err) = run(&args);
        assert_eq!(code, 2, "{args:?}: {out} {err}");
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
        assert!(out.is_empty());
    }
}
