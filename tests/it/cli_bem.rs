//! `asperity persson` and `asperity bem`: the JSON contracts (keys exactly
//! as specified), outputs, and bad input (exit 2 naming the argument).

use serde_json::Value;
use std::process::Command;

fn root(p: &str) -> String {
    format!("{}/{p}", env!("CARGO_MANIFEST_DIR"))
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

fn json(args: &[&str]) -> Value {
    let (code, out, err) = run(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(out.trim()).expect("one JSON object")
}

fn has_keys(v: &Value, keys: &[&str]) {
    for k in keys {
        assert!(v.get(k).is_some(), "missing {k} in {v}");
    }
}

const PERSSON: [&str; 15] = {
    let s = crate::common::cli::PERSSON_SPECTRUM;
    [
        s[0],
        s[1],
        s[2],
        s[3],
        s[4],
        s[5],
        s[6],
        s[7],
        s[8],
        s[9],
        s[10],
        s[11],
        s[12],
        "--pressures",
        "1e4,1e6",
    ]
};

#[test]
fn persson_contract() {
    let mut args = PERSSON.to_vec();
    args.push("--json");
    let v = json(&args);
    has_keys(
        &v,
        &[
            "states",
            "h_rms_m",
            "slope_rms",
            "m0",
            "m2",
            "m4",
            "mean_gap_slope_m",
            "full_contact_energy_J_per_m2",
            "gamma",
        ],
    );
    let states = v["states"].as_array().unwrap();
    assert_eq!(states.len(), 2);
    for s in states {
        has_keys(
            s,
            &[
                "pressure_Pa",
                "area_fraction",
                "mean_gap_m",
                "gw_area_fraction",
                "gw_mean_gap_m",
            ],
        );
    }
    // A/A0 = erf(sqrt 2 p/(E* g)) ~ sqrt(8/pi) p/(E* g) at light load.
    let g = v["slope_rms"].as_f64().unwrap();
    let a = states[0]["area_fraction"].as_f64().unwrap();
    let lin = (8.0 / std::f64::consts::PI).sqrt() * 1e4 / (1e9 * g);
    assert!((a / lin - 1.0).abs() < 1e-5, "{a} {lin}");
    assert_eq!(v["gamma"].as_f64(), Some(1.0));
    assert!((v["h_rms_m"].as_f64().unwrap() / 1e-8 - 1.0).abs() < 1e-12);
    let mut args = PERSSON.to_vec();
    args.extend(["--gamma", "0.42", "--adhesion-energy", "0.05", "--json"]);
    let w = json(&args);
    assert_eq!(w["gamma"].as_f64(), Some(0.42));
    assert!(w["persson_tosatti_number"].as_f64().unwrap() > 0.0);
}

#[test]
fn bem_contract_on_a_periodic_map_with_outputs() {
    let dir = std::env::temp_dir().join(format!("asperity-bem-{}", std::process::id()));
    let map = root("examples/data/selfaffine-256.npy");
    let out = dir.display().to_string();
    let v = json(&[
        "bem",
        &map,
        "--pixel-size",
        "3.90625e-7",
        "--estar",
        "1e9",
        "--pressures",
        "1e6,1e7",
        "--periodic",
        "--resistivity",
        "2.2e-8",
        "--out",
        &out,
        "--json",
    ]);
    has_keys(&v, &["states", "gw", "persson"]);
    let states = v["states"].as_array().unwrap();
    assert_eq!(states.len(), 2);
    for s in states {
        has_keys(
            s,
            &[
                "pressure_Pa",
                "mean_gap_m",
                "area_fraction",
                "clusters",
                "iterations",
                "residual",
            ],
        );
        assert!(s["residual"].as_f64().unwrap() < 1e-10);
    }
    // The converged reference (tests/data/bem_reference.json) at 1e7 Pa.
    assert!((states[1]["area_fraction"].as_f64().unwrap() - 0.2179412841796875).abs() < 1e-6);
    for list in ["gw", "persson"] {
        let l = v[list].as_array().unwrap();
        assert_eq!(l.len(), 2);
        for (m, s) in l.iter().zip(states) {
            has_keys(m, &["pressure_Pa", "area_fraction", "mean_gap_m"]);
            assert_eq!(m["pressure_Pa"], s["pressure_Pa"]);
            assert!(m["area_fraction"].as_f64().unwrap() > 0.0);
        }
    }
    for f in [
        "bem.json",
        "contact_0.npy",
        "pressure_1.npy",
        "gap_1.npy",
        "area_vs_pressure.svg",
        "gap_vs_pressure.svg",
    ] {
        assert!(dir.join(f).exists(), "{f}");
    }
    // Gap control gives the pressure back.
    let gap = states[1]["mean_gap_m"].as_f64().unwrap().to_string();
    let g = json(&[
        "bem",
        &map,
        "--pixel-size",
        "3.90625e-7",
        "--estar",
        "1e9",
        "--gaps",
        &gap,
        "--periodic",
        "--json",
    ]);
    assert!((g["states"][0]["pressure_Pa"].as_f64().unwrap() / 1e7 - 1.0).abs() < 1e-6);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bem_padded_map() {
    let v = json(&[
        "bem",
        &root("tests/data/surface_a.npy"),
        "--pixel-size",
        "1e-7",
        "--estar",
        "1e11",
        "--pressures",
        "1e8",
        "--json",
    ]);
    let s = &v["states"][0];
    assert!((s["pressure_Pa"].as_f64().unwrap() / 1e8 - 1.0).abs() < 1e-12);
    assert!(s["area_fraction"].as_f64().unwrap() > 0.0 && s["clusters"].as_u64().unwrap() >= 1);
}

#[test]
fn bad_input_exits_2_naming_the_argument() {
    let map = root("examples/data/selfaffine-256.npy");
    let bad = |args: &[&str], needle: &str| {
        let (code, _, err) = run(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    };
    let base = |m: &str, extra: &[&str]| -> Vec<String> {
        let mut v: Vec<String> = [
            "bem",
            m,
            "--pixel-size",
            "1e-7",
            "--estar",
            "1e9",
            "--pressures",
            "1e6",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect();
        v.extend(extra.iter().map(|s| s.to_string()));
        v
    };
    let call = |v: Vec<String>, needle: &str| {
        let r: Vec<&str> = v.iter().map(String::as_str).collect();
        bad(&r, needle);
    };
    call(
        base(&root("tests/data/surface_bad/one_d.npy"), &[]),
        "one_d.npy",
    );
    call(
        base(&root("tests/data/surface_bad/nan.npy"), &[]),
        "nan.npy",
    );
    bad(
        &[
            "bem",
            &map,
            "--pixel-size",
            "1e-7",
            "--estar",
            "0",
            "--pressures",
            "1e6",
        ],
        "--estar",
    );
    bad(
        &[
            "bem",
            &map,
            "--pixel-size",
            "-1",
            "--estar",
            "1e9",
            "--pressures",
            "1e6",
        ],
        "--pixel-size",
    );
    bad(
        &[
            "bem",
            &map,
            "--pixel-size",
            "1e-7",
            "--estar",
            "1e9",
            "--pressures",
            "1e6,-2",
        ],
        "--pressures",
    );
    bad(
        &[
            "bem",
            &map,
            "--pixel-size",
            "1e-7",
            "--estar",
            "1e9",
            "--gaps",
            "0",
        ],
        "--gaps",
    );
    call(base(&map, &["--memory-limit-mib", "1"]), "MiB");
    call(
        base(
            &map,
            &["--adhesion-energy", "0.1", "--adhesion-range", "1e-9"],
        ),
        "--periodic",
    );
    let mut p = PERSSON.to_vec();
    p[12] = "-1e9";
    bad(&p, "--estar");
    let mut p = PERSSON.to_vec();
    p[14] = "0,1e6";
    bad(&p, "--pressures");
}
