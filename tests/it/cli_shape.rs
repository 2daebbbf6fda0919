//! `asperity shape`: the JSON contract (keys exactly as the contract writes
//! them), closed forms through the binary, warnings and exit codes.
use std::f64::consts::PI;
use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .arg("shape")
        .args(args)
        .output()
        .expect("run asperity");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn json(args: &[&str]) -> (serde_json::Value, String) {
    let (code, out, err) = run(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    (
        serde_json::from_str(out.trim()).expect("one JSON object"),
        err,
    )
}

fn num(v: &serde_json::Value, key: &str) -> f64 {
    v[key].as_f64().unwrap_or_else(|| panic!("{key} in {v}"))
}

fn keys(v: &serde_json::Value) -> Vec<String> {
    let mut k: Vec<String> = v.as_object().unwrap().keys().cloned().collect();
    k.sort();
    k
}

#[test]
fn every_profile_prints_the_contract_keys() {
    let common = ["--estar", "1e9", "--w", "0.05", "--json"];
    let cases: [&[&str]; 5] = [
        &["--profile", "paraboloid", "--radius", "1e-6"],
        &["--profile", "sphere", "--radius", "1e-6"],
        &["--profile", "cone", "--tan-angle", "0.2"],
        &["--profile", "flat", "--radius", "1e-6"],
        &[
            "--profile",
            "power",
            "--exponent",
            "1.5",
            "--coefficient",
            "316",
        ],
    ];
    for c in cases {
        let args: Vec<&str> = c.iter().chain(common.iter()).copied().collect();
        let (v, _) = json(&args);
        let mut top = vec![
            "jump_out_displacement_control",
            "pull_off_load_control",
            "warnings",
        ];
        top.sort();
        assert_eq!(keys(&v), top, "{c:?}: no curve without --radii");
        for k in ["pull_off_load_control", "jump_out_displacement_control"] {
            assert_eq!(
                keys(&v[k]),
                ["interference_m", "load_N", "radius_m"],
                "{c:?}"
            );
            assert!(num(&v[k], "load_N") < 0.0, "tensile: {v}");
        }
        assert!(v["warnings"].as_array().unwrap().is_empty());
    }
}

#[test]
fn curve_points_and_closed_forms() {
    let (e, w, r) = (1e9f64, 0.05f64, 1e-6f64);
    let (v, _) = json(&[
        "--profile",
        "paraboloid",
        "--radius",
        "1e-6",
        "--estar",
        "1e9",
        "--w",
        "0.05",
        "--radii",
        "2e-8,5e-8,1e-7",
        "--json",
    ]);
    // JKR: -(3/2) pi w R under load control, -(5/6) pi w R under displacement control.
    let p = num(&v["pull_off_load_control"], "load_N");
    assert!((p / (-1.5 * PI * w * r) - 1.0).abs() < 1e-14);
    let q = num(&v["jump_out_displacement_control"], "load_N");
    assert!((q / (-5.0 / 6.0 * PI * w * r) - 1.0).abs() < 1e-14);
    let curve = v["curve"].as_array().unwrap();
    assert_eq!(curve.len(), 3);
    for (pt, a) in curve.iter().zip([2e-8, 5e-8, 1e-7]) {
        assert_eq!(keys(pt), ["interference_m", "load_N", "radius_m"]);
        assert_eq!(num(pt, "radius_m"), a);
        let f = 4.0 * e * a * a * a / (3.0 * r) - (8.0 * PI * e * w * a * a * a).sqrt();
        let d = a * a / r - (2.0 * PI * w * a / e).sqrt();
        assert!((num(pt, "load_N") - f).abs() < 1e-14 * f.abs().max(1e-9));
        assert!((num(pt, "interference_m") - d).abs() < 1e-14 * d.abs().max(1e-10));
    }
    // Flat punch: both controls give Kendall's pull-off.
    let (v, _) = json(&[
        "--profile",
        "flat",
        "--radius",
        "2e-6",
        "--estar",
        "1e9",
        "--w",
        "0.05",
        "--json",
    ]);
    let kendall = -(8.0 * PI * e * w * 8e-18f64).sqrt();
    for k in ["pull_off_load_control", "jump_out_displacement_control"] {
        assert!((num(&v[k], "load_N") / kendall - 1.0).abs() < 1e-14);
        assert_eq!(num(&v[k], "radius_m"), 2e-6);
    }
    // Cone: a = 18 w/(pi E* t^2) under load control.
    let (v, _) = json(&[
        "--profile",
        "cone",
        "--tan-angle",
        "0.2",
        "--estar",
        "1e9",
        "--w",
        "0.05",
        "--json",
    ]);
    let a = num(&v["pull_off_load_control"], "radius_m");
    assert!((a / (18.0 * w / (PI * e * 0.04)) - 1.0).abs() < 1e-14);
}

#[test]
fn the_large_sphere_warns_on_stderr_and_in_json() {
    let (v, err) = json(&[
        "--profile",
        "sphere",
        "--radius",
        "1e-8",
        "--estar",
        "1e8",
        "--w",
        "0.5",
        "--radii",
        "1e-9,5e-9",
        "--json",
    ]);
    let warnings = v["warnings"].as_array().unwrap();
    // Pull-off (a/R = 0.78), jump-out (0.51) and the 5e-9 point; not 1e-9.
    assert_eq!(warnings.len(), 3, "{v}");
    assert!(warnings.iter().all(|w| w.as_str().unwrap().contains("0.3")));
    assert_eq!(
        err.lines().filter(|l| l.starts_with("warning:")).count(),
        3,
        "{err}"
    );
    // Without --json the table prints and the warnings still go to stderr.
    let (code, out, err) = run(&[
        "--profile",
        "sphere",
        "--radius",
        "1e-8",
        "--estar",
        "1e8",
        "--w",
        "0.5",
    ]);
    assert_eq!(code, 0);
    assert!(out.contains("pull-off, load control"));
    assert!(err.contains("warning:"));
}

#[test]
fn bad_input_exits_2_with_one_line_naming_the_argument() {
    let cases: [(&[&str], &str); 9] = [
        (
            &[
                "--profile",
                "cone",
                "--tan-angle",
                "0.2",
                "--estar",
                "0",
                "--w",
                "0.1",
            ],
            "--estar",
        ),
        (
            &[
                "--profile",
                "cone",
                "--tan-angle",
                "0.2",
                "--estar",
                "-1e9",
                "--w",
                "0.1",
            ],
            "--estar",
        ),
        (
            &[
                "--profile",
                "cone",
                "--tan-angle",
                "0.2",
                "--estar",
                "1e9",
                "--w",
                "-0.1",
            ],
            "--w",
        ),
        (
            &[
                "--profile",
                "cone",
                "--tan-angle",
                "0",
                "--estar",
                "1e9",
                "--w",
                "0.1",
            ],
            "--tan-angle",
        ),
        (
            &[
                "--profile",
                "cone",
                "--tan-angle",
                "-0.3",
                "--estar",
                "1e9",
                "--w",
                "0.1",
            ],
            "--tan-angle",
        ),
        (
            &[
                "--profile",
                "power",
                "--exponent",
                "0",
                "--coefficient",
                "1",
                "--estar",
                "1e9",
                "--w",
                "0.1",
            ],
            "--exponent",
        ),
        (
            &[
                "--profile",
                "power",
                "--exponent",
                "-2",
                "--coefficient",
                "1",
                "--estar",
                "1e9",
                "--w",
                "0.1",
            ],
            "--exponent",
        ),
        (
            &[
                "--profile",
                "sphere",
                "--radius",
                "1e-6",
                "--estar",
                "1e9",
                "--w",
                "0.1",
                "--radii",
                "1e-7,2e-6",
            ],
            "--radii",
        ),
        (
            &[
                "--profile",
                "blob",
                "--radius",
                "1e-6",
                "--estar",
                "1e9",
                "--w",
                "0.1",
            ],
            "--profile",
        ),
    ];
    for (args, name) in cases {
        let (code, out, err) = run(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(out.is_empty());
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        assert!(err.contains(name), "{args:?}: {err}");
    }
    // A missing profile parameter names it.
    let (code, _, err) = run(&["--profile", "sphere", "--estar", "1e9", "--w", "0.1"]);
    assert_eq!(code, 2);
    assert!(err.contains("--radius"), "{err}");
    // w = 0 is Sneddon's contact: nothing pulls off.
    let (v, _) = json(&[
        "--profile",
        "cone",
        "--tan-angle",
        "0.2",
        "--estar",
        "1e9",
        "--w",
        "0",
        "--json",
    ]);
    assert_eq!(num(&v["pull_off_load_control"], "load_N"), 0.0);
}

/// `--stress`: Maugis–Dugdale for the profile, same keys; the paraboloid
/// gives `law::Maugis` (Maugis 1992) through the binary.
#[test]
fn stress_switches_to_maugis_dugdale() {
    use asperity::axisym::AxisymMd;
    use asperity::law::{AsperityLaw, Control, Maugis};
    let (r, e, w) = (1e-6, 1e9, 0.05);
    for lambda in [0.5, 2.0] {
        let sigma = AxisymMd::stress_from_lambda(lambda, r, e, w).to_string();
        let (v, _) = json(&[
            "--profile",
            "paraboloid",
            "--radius",
            "1e-6",
            "--estar",
            "1e9",
            "--w",
            "0.05",
            "--stress",
            &sigma,
            "--json",
        ]);
        let law = Maugis::new(r, e, w, lambda).unwrap();
        for (k, c) in [
            ("pull_off_load_control", Control::Load),
            ("jump_out_displacement_control", Control::Displacement),
        ] {
            assert_eq!(keys(&v[k]), ["interference_m", "load_N", "radius_m"]);
            let want = law.pull_off(c).unwrap().load;
            // The decimal sigma0 round-trips: 1e-10 holds.
            assert!(
                (num(&v[k], "load_N") / want - 1.0).abs() < 1e-10,
                "{lambda} {k}: {v}"
            );
        }
    }
    // The flat punch has no Maugis-Dugdale form; the stress must be > 0.
    for (args, name) in [
        (
            ["--profile", "flat", "--radius", "1e-6", "--stress", "1e7"],
            "--profile",
        ),
        (
            ["--profile", "cone", "--tan-angle", "0.2", "--stress", "-1"],
            "--stress",
        ),
    ] {
        let all: Vec<&str> = args
            .iter()
            .chain(["--estar", "1e9", "--w", "0.05"].iter())
            .copied()
            .collect();
        let (code, _, err) = run(&all);
        assert_eq!(code, 2, "{all:?}");
        assert!(err.contains(name), "{err}");
    }
}
