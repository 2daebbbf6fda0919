//! `asperity rough-sphere` from outside: the contract's keys and order,
//! values against the independent solver of tests/data/rough_sphere.py,
//! charts with `--out`, exit 2 naming the argument.

use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(args)
        .output()
        .expect("run asperity");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn reference() -> serde_json::Value {
    let path = format!(
        "{}/tests/data/rough_sphere.json",
        env!("CARGO_MANIFEST_DIR")
    );
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The states come in the order given, each with exactly the contract's
/// keys, the pressure at the `--rho` values; the numbers match the
/// independent solver (load 1e-6, pressure 1e-5).
#[test]
fn contract_keys_order_and_values() {
    let (code, out, err) = run(&[
        "rough-sphere",
        "--mu",
        "10",
        "--d",
        "0.5,-1,2,0",
        "--rho",
        "0,0.5,1",
        "--json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
    let states = v["states"].as_array().unwrap();
    let r = reference();
    let cases = r["cases"].as_array().unwrap();
    let ds = [0.5, -1.0, 2.0, 0.0];
    assert_eq!(states.len(), 4);
    for (s, d) in states.iter().zip(ds) {
        let mut keys: Vec<&str> = s.as_object().unwrap().keys().map(|k| k.as_str()).collect();
        keys.sort();
        assert_eq!(keys, ["central_deflection", "d", "load", "pressure"]);
        assert_eq!(s["d"].as_f64().unwrap(), d);
        let c = cases
            .iter()
            .find(|c| c["mu"].as_f64() == Some(10.0) && c["d"].as_f64() == Some(d))
            .unwrap();
        let load = c["load"].as_f64().unwrap();
        assert!((s["load"].as_f64().unwrap() - load).abs() < 1e-6 * load);
        let u0 = c["central_deflection"].as_f64().unwrap();
        assert!((s["central_deflection"].as_f64().unwrap() - u0).abs() < 1e-6 * u0);
        let p = s["pressure"].as_array().unwrap();
        assert_eq!(p.len(), 3);
        for (q, rho) in p.iter().zip([0.0, 0.5, 1.0]) {
            let mut keys: Vec<&str> = q.as_object().unwrap().keys().map(|k| k.as_str()).collect();
            keys.sort();
            assert_eq!(keys, ["p", "rho"]);
            assert_eq!(q["rho"].as_f64().unwrap(), rho);
            let refp = c["pressure"]
                .as_array()
                .unwrap()
                .iter()
                .find(|x| x["rho"].as_f64() == Some(rho))
                .unwrap()["p"]
                .as_f64()
                .unwrap();
            assert!((q["p"].as_f64().unwrap() - refp).abs() < 1e-5 * refp);
        }
    }
    // without --rho: an empty pressure list
    let (code, out, _) = run(&["rough-sphere", "--mu", "1", "--d", "0", "--json"]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
    assert_eq!(v["states"][0]["pressure"].as_array().unwrap().len(), 0);
}

/// `--errors` adds each value's error estimate; `--out` writes the charts.
#[test]
fn errors_and_charts() {
    let dir = std::env::temp_dir().join(format!("asperity-rough-sphere-{}", std::process::id()));
    let dir_s = dir.to_str().unwrap();
    let (code, out, err) = run(&[
        "rough-sphere",
        "--mu",
        "1",
        "--d",
        "0,-1",
        "--rho",
        "0.5",
        "--json",
        "--errors",
        "--out",
        dir_s,
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
    let s = &v["states"][1];
    let (load, e) = (
        s["load"].as_f64().unwrap(),
        s["load_error"].as_f64().unwrap(),
    );
    assert!(e > 0.0 && e < 1e-6 * load);
    assert!(s["pressure"][0]["p_error"].as_f64().unwrap() >= 0.0);
    for f in ["pressure_0.svg", "pressure_1.svg", "load_approach.svg"] {
        let text = std::fs::read_to_string(dir.join(f)).unwrap();
        assert!(text.contains("<svg") && text.contains("Hertz"), "{f}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Bad input exits 2 with one line naming the argument.
#[test]
fn bad_input_names_the_argument() {
    let cases: [(&[&str], &str); 7] = [
        (&["--mu", "0", "--d", "0"], "--mu"),
        (&["--mu", "-1", "--d", "0"], "--mu"),
        (&["--mu", "nan", "--d", "0"], "--mu"),
        (&["--mu", "inf", "--d", "0"], "--mu"),
        (&["--mu", "1", "--d", "0,nan"], "--d"),
        (&["--mu", "1", "--d", "inf"], "--d"),
        (&["--mu", "1", "--d", "0", "--rho", "-0.5"], "--rho"),
    ];
    for (args, flag) in cases {
        let mut all = vec!["rough-sphere"];
        all.extend_from_slice(args);
        all.push("--json");
        let (code, out, err) = run(&all);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(out.is_empty(), "{args:?}");
        assert!(
            err.contains(flag) && err.lines().count() == 1,
            "{args:?}: {err}"
        );
    }
}
