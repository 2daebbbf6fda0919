//! `asperity punch` and `asperity punch-fit` from outside: the contract's keys, values
//! against tests/data/punch.json (mpmath), exit codes and one-line errors naming the flag.

use std::io::Write;
use std::process::Command;

/// `tests/data/NAME` (made by its mpmath script), parsed.
fn local(name: &str) -> serde_json::Value {
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// A JSON number or a string holding one.
fn num(v: &serde_json::Value) -> f64 {
    match v {
        serde_json::Value::String(s) => s.parse().unwrap(),
        other => other.as_f64().unwrap(),
    }
}

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

fn json(args: &[&str]) -> serde_json::Value {
    let (code, out, err) = run(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(out.trim()).expect("one JSON object")
}

const FIG3: [&str; 11] = [
    "punch",
    "--estar",
    "1",
    "--w",
    "0.007957747154594767",
    "--radius",
    "1",
    "--amplitude",
    "0.1",
    "--wavelength",
    "0.03",
];

fn keys(v: &serde_json::Value) -> Vec<String> {
    let mut k: Vec<String> = v.as_object().unwrap().keys().cloned().collect();
    k.sort();
    k
}

#[test]
fn punch_prints_the_contract_keys_and_mpmath_values() {
    let d = local("punch.json");
    let c = &d["evolution"]["fig3"];
    let rows = c["rows"].as_array().unwrap();
    let depths: Vec<String> = rows
        .iter()
        .map(|r| r["h"].as_str().unwrap().to_string())
        .collect();
    let depths = depths.join(",");
    let cycle = format!(
        "{}:{}",
        c["h_min"].as_str().unwrap(),
        c["h_max"].as_str().unwrap()
    );
    let mut args = FIG3.to_vec();
    args.extend([
        "--radii",
        "0.1,0.3,0.45",
        "--depths",
        &depths,
        "--cycle",
        &cycle,
        "--json",
    ]);
    let v = json(&args);
    assert_eq!(
        keys(&v),
        [
            "curve",
            "energy_loss_per_cycle_J",
            "envelope_loading",
            "envelope_unloading",
            "loading",
            "unloading"
        ]
    );
    for k in ["curve", "envelope_loading", "envelope_unloading"] {
        let rows = v[k].as_array().unwrap();
        assert_eq!(rows.len(), 3);
        assert_eq!(keys(&rows[0]), ["depth_m", "load_N", "radius_m"]);
    }
    for k in ["loading", "unloading"] {
        let r = v[k].as_array().unwrap();
        assert_eq!(r.len(), rows.len());
        assert_eq!(keys(&r[0]), ["depth_m", "load_N", "radius_m"]);
    }
    // Loading in increasing depth, unloading from the deepest down; both match mpmath.
    let lo = v["loading"].as_array().unwrap();
    let un = v["unloading"].as_array().unwrap();
    for (i, row) in rows.iter().enumerate() {
        let h = num(&row["h"]);
        assert_eq!(num(&lo[i]["depth_m"]), h);
        assert!((num(&lo[i]["radius_m"]) - num(&row["a_loading"])).abs() < 1e-12);
        let u = &un[rows.len() - 1 - i];
        assert_eq!(num(&u["depth_m"]), h);
        assert!((num(&u["radius_m"]) - num(&row["a_unloading"])).abs() < 1e-12);
    }
    assert_eq!(lo.last().unwrap()["radius_m"], un[0]["radius_m"]);
    let loss = num(&v["energy_loss_per_cycle_J"]);
    let want = num(&c["loss"]);
    assert!(((loss - want) / want).abs() < 1e-6, "{loss} vs {want}");
    // Negative depths: detached on loading, still in contact on unloading.
    assert_eq!(num(&lo[0]["radius_m"]), 0.0);
    assert_eq!(num(&lo[0]["load_N"]), 0.0);
    assert!(num(&un[rows.len() - 1]["radius_m"]) > 0.0);
}

#[test]
fn punch_curve_matches_mpmath_and_cycle_is_optional() {
    let d = local("punch.json");
    let c = &d["curves"]["fig8_l0.1"];
    let rows = c["rows"].as_array().unwrap();
    let radii: Vec<&str> = rows.iter().map(|r| r["a"].as_str().unwrap()).collect();
    let radii = radii.join(",");
    let v = json(&[
        "punch",
        "--estar",
        "1",
        "--w",
        c["w"].as_str().unwrap(),
        "--radius",
        "1",
        "--amplitude",
        "0.14",
        "--wavelength",
        "0.1",
        "--radii",
        &radii,
        "--depths",
        "-0.01,0.2",
        "--json",
    ]);
    assert!(v.get("energy_loss_per_cycle_J").is_none());
    for (row, got) in rows.iter().zip(v["curve"].as_array().unwrap()) {
        assert_eq!(num(&got["radius_m"]), num(&row["a"]));
        assert!((num(&got["depth_m"]) - num(&row["h"])).abs() < 1e-13);
        assert!((num(&got["load_N"]) - num(&row["P"])).abs() < 1e-13);
    }
    // Defaults: radii and depths chosen by the program.
    let mut args = FIG3.to_vec();
    args.push("--json");
    let v = json(&args);
    assert!(v["curve"].as_array().unwrap().len() > 100);
    assert!(v["loading"].as_array().unwrap().len() > 50);
    // Without --json: a table.
    let (code, out, _) = run(&FIG3);
    assert_eq!(code, 0);
    assert!(out.contains("radius_m") && out.contains("unloading"));
}

fn one_line_error(args: &[&str], flag: &str, code: i32) {
    let (c, out, err) = run(args);
    assert_eq!(c, code, "{args:?}: {err}");
    assert!(out.is_empty(), "{out}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(err.contains(flag), "{args:?}: {err} should name {flag}");
}

#[test]
fn punch_bad_input_exits_2_naming_the_flag() {
    for (i, flag) in [
        (2, "--estar"),
        (4, "--w"),
        (6, "--radius"),
        (8, "--amplitude"),
        (10, "--wavelength"),
    ] {
        for bad in ["0", "-1", "NaN"] {
            let mut args = FIG3.to_vec();
            args[i] = bad;
            one_line_error(&args, flag, 2);
        }
    }
    // A wavelength not smaller than the punch radius.
    let mut args = FIG3.to_vec();
    args[10] = "1";
    one_line_error(&args, "--wavelength", 2);
    for (flag, bad) in [
        ("--cycle", "0.1:-0.1"),
        ("--cycle", "x"),
        ("--depths", "0,a"),
        ("--radii", "-1"),
    ] {
        let mut args = FIG3.to_vec();
        args.extend([flag, bad]);
        one_line_error(&args, flag, 2);
    }
    let mut args = FIG3.to_vec();
    args.extend(["--cycle", "-0.05:0.1", "--depths", "-0.2,-0.1", "--json"]);
    assert_eq!(run(&args).0, 0, "negative depths and HMIN are fine");
}

fn csv(name: &str, body: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("asperity-punch-fit-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::File::create(&path)
        .unwrap()
        .write_all(body.as_bytes())
        .unwrap();
    path
}

/// Envelope points of the paper's gelatin values (eq. 4.9), E* 17.08 kPa, w 80.4 mJ/m^2,
/// A sqrt(l) 1.1e-4 m^1/2, R 0.25 m.
fn gelatin_csv(phases: &[&str]) -> String {
    let (e, w, eps, r) = (17.08e3f64, 80.4e-3f64, 1.1e-4f64, 0.25f64);
    let mut s = String::from("phase,radius_m,load_N\n");
    for i in 0..20 {
        let a = 0.008 + 0.018 * i as f64 / 19.0;
        let pm = 4.0 * e * a.powi(3) / (3.0 * r)
            - (8.0 * std::f64::consts::PI * w * e * a.powi(3)).sqrt();
        let d = 2.0 * std::f64::consts::PI * e * eps * a.powf(1.5);
        for ph in phases {
            let p = if *ph == "loading" { pm + d } else { pm - d };
            s.push_str(&format!("{ph},{a:e},{p:e}\n"));
        }
    }
    s
}

#[test]
fn punch_fit_recovers_the_gelatin_values() {
    let path = csv("both.csv", &gelatin_csv(&["loading", "unloading"]));
    let p = path.to_str().unwrap();
    let v = json(&["punch-fit", p, "--radius", "0.25", "--json"]);
    for (k, want) in [
        ("estar_Pa", 17.08e3),
        ("w_J_per_m2", 80.4e-3),
        ("amplitude_sqrt_wavelength_m_half", 1.1e-4),
    ] {
        let got = num(&v[k]);
        assert!(((got - want) / want).abs() < 1e-6, "{k}: {got}");
        let se = &v[format!("{k}_stderr").as_str()];
        assert!(num(se) >= 0.0 && num(se) < 1e-6 * want, "{k}_stderr {se}");
    }
    let (code, out, _) = run(&["punch-fit", p, "--radius", "0.25"]);
    assert_eq!(code, 0);
    assert!(out.contains("E*"));
}

#[test]
fn punch_fit_bad_input() {
    let one = csv("one.csv", &gelatin_csv(&["loading"]));
    one_line_error(
        &[
            "punch-fit",
            one.to_str().unwrap(),
            "--radius",
            "0.25",
            "--json",
        ],
        "DATA.csv",
        2,
    );
    let few = csv(
        "few.csv",
        "phase,radius_m,load_N\nloading,0.01,0.1\nunloading,0.02,0.2\n",
    );
    one_line_error(
        &[
            "punch-fit",
            few.to_str().unwrap(),
            "--radius",
            "0.25",
            "--json",
        ],
        "DATA.csv",
        2,
    );
    let header = csv("header.csv", "phase,a,P\nloading,0.01,0.1\n");
    one_line_error(
        &["punch-fit", header.to_str().unwrap(), "--radius", "0.25"],
        "DATA.csv",
        2,
    );
    let phase = csv("phase.csv", "phase,radius_m,load_N\nup,0.01,0.1\n");
    one_line_error(
        &["punch-fit", phase.to_str().unwrap(), "--radius", "0.25"],
        "DATA.csv",
        2,
    );
    let both = csv("ok.csv", &gelatin_csv(&["loading", "unloading"]));
    for bad in ["0", "-0.25", "NaN"] {
        one_line_error(
            &["punch-fit", both.to_str().unwrap(), "--radius", bad],
            "--radius",
            2,
        );
    }
    // A file that cannot be read is bad input naming it (found by the CLI
    // fuzz; it was exit 1).
    one_line_error(
        &["punch-fit", "/nonexistent/data.csv", "--radius", "0.25"],
        "/nonexistent/data.csv",
        2,
    );
}

/// `--svg` draws the cycle's chart, and asks for the cycle it spans.
#[test]
fn svg_draws_the_cycle_and_needs_one() {
    let dir = std::env::temp_dir().join(format!("asperity-cli-punch-svg-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("punch.svg");
    let base = [
        "punch",
        "--estar",
        "1",
        "--w",
        "0.008",
        "--radius",
        "1",
        "--amplitude",
        "0.1",
        "--wavelength",
        "0.03",
    ];
    let mut with_cycle = base.to_vec();
    with_cycle.extend(["--cycle=-0.1:0.1", "--svg", svg.to_str().unwrap()]);
    let (code, _, err) = run(&with_cycle);
    assert_eq!(code, 0, "{err}");
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(
        text.starts_with("<svg") && text.contains("<polyline"),
        "{text:.200}"
    );
    let mut without = base.to_vec();
    without.extend(["--svg", svg.to_str().unwrap()]);
    let (code, _, err) = run(&without);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--svg") && err.contains("--cycle"), "{err}");
}
