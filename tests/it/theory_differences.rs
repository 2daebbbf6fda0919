//! The theories beside the exact solution as the user reads them: `asperity
//! bem`'s difference columns and warnings, and `asperity persson`'s
//! measured, sourced model error.

use crate::common::cli::{run, tmp};
use serde_json::Value;

fn map() -> String {
    format!(
        "{}/examples/data/measured-topography.npy",
        env!("CARGO_MANIFEST_DIR")
    )
}

/// The text table's difference columns are the JSON's
/// `relative_differences` in per cent to one decimal (the same numbers),
/// and every theory beyond 10 % at some state is warned about.
#[test]
fn bem_table_shows_the_differences_and_warns_beyond_ten_percent() {
    let d = tmp("bem");
    let m = map();
    let args = [
        "bem",
        m.as_str(),
        "--pixel-size",
        "50e-9",
        "--estar",
        "4.796e10",
        "--pressures",
        "5e6,1.5e7,4.5e7",
    ];
    let (code, text, err) = run(&args, &d);
    assert_eq!(code, 0, "{err}");
    let mut with_json = args.to_vec();
    with_json.push("--json");
    let (code, json, err) = run(&with_json, &d);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&json).unwrap();
    let header = text.lines().nth(1).unwrap();
    assert!(
        header.contains("dA/A") && header.contains("du/u"),
        "{header}"
    );
    let rows: Vec<&str> = text.lines().skip(2).take(3).collect();
    let mut beyond = false;
    for (k, row) in rows.iter().enumerate() {
        let diff = &v["relative_differences"][k];
        for key in ["gw_area", "gw_mean_gap", "persson_area", "persson_mean_gap"] {
            let x = diff[key].as_f64().unwrap();
            beyond |= key == "gw_area" && x.abs() > 0.1;
            let shown = format!("{:+.1}%", 100.0 * x);
            assert!(row.contains(&shown), "{key} {shown} not in {row}");
        }
    }
    // GW's area is 25-30 % below the exact one on this map at these loads:
    // not above the old 0.1 area-fraction trigger, warned all the same.
    assert!(beyond, "{v}");
    let warnings = v["warnings"].to_string();
    assert!(
        warnings.contains("GW's area fraction differs from the exact one by more than 10 %"),
        "{warnings}"
    );
    assert!(!warnings.contains("light-load"), "{warnings}");
    let model_error = v["model_error"].as_str().unwrap();
    assert!(
        model_error.contains("Measured here against it")
            && model_error.contains("GW's area fraction"),
        "{model_error}"
    );
}

/// At p = 0.03 E* on the shipped 256^2 self-affine map GW's mean gap is
/// negative (-2.1e-8 m against the exact +2.2e-8 m): flagged on its own.
#[test]
fn bem_flags_negative_gw_gaps() {
    let d = tmp("negative");
    let m = format!(
        "{}/examples/data/selfaffine-256.npy",
        env!("CARGO_MANIFEST_DIR")
    );
    let (code, json, err) = run(
        &[
            "bem",
            m.as_str(),
            "--pixel-size",
            "3.90625e-7",
            "--estar",
            "1e9",
            "--periodic",
            "--pressures",
            "3e7",
            "--json",
        ],
        &d,
    );
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&json).unwrap();
    assert!(v["gw"][0]["mean_gap_m"].as_f64().unwrap() < 0.0, "{v}");
    assert!(
        v["warnings"].to_string().contains("GW's mean gap at p = "),
        "{}",
        v["warnings"]
    );
}

/// `asperity persson` states Persson's error as measured (which maps,
/// which loads, which numbers), not as a quoted range, and shows GW
/// against Persson in a column.
#[test]
fn persson_states_the_measured_error_with_its_source() {
    let d = tmp("persson");
    let args = [
        "persson",
        "--hurst",
        "0.8",
        "--q-long",
        "1e6",
        "--q-roll",
        "4e6",
        "--q-short",
        "1e9",
        "--slope-rms",
        "0.1",
        "--estar",
        "1e9",
        "--pressures",
        "1e6,1e7",
    ];
    let (code, text, err) = run(&args, &d);
    assert_eq!(code, 0, "{err}");
    assert!(text.contains("GW/P A"), "{text}");
    let mut with_json = args.to_vec();
    with_json.push("--json");
    let (code, json, err) = run(&with_json, &d);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&json).unwrap();
    let s = v["model_error"].as_str().unwrap();
    for part in [
        "measured against exact elastic boundary-element solutions",
        "examples/data/selfaffine-256.npy",
        "p/E* = 0.001, 0.003 and 0.01",
        "Persson's area (gamma = 1) was 24-37 % below the exact one",
    ] {
        assert!(s.contains(part), "{part} not in {s}");
    }
    assert!(!s.contains("10-25 %"), "{s}");
    let st = &v["states"][0];
    let ratio = st["gw_area_fraction"].as_f64().unwrap() / st["area_fraction"].as_f64().unwrap();
    assert!((st["gw_vs_persson_area"].as_f64().unwrap() - (ratio - 1.0)).abs() < 1e-12);
    // GW is 59 % below Persson: both cannot be within 10 % of the truth.
    assert!(
        v["warnings"]
            .to_string()
            .contains("at least one of them is more than 10 %"),
        "{}",
        v["warnings"]
    );
}

/// `asperity surface` measures GW (on the map's moments) and Persson
/// against the exact solution of the map at p/E* = 1e-3, 3e-3, 1e-2: the
/// same numbers as `asperity bem` at those pressures (one comparison), and
/// the text report shows them.
#[test]
fn surface_reports_the_model_error_of_its_map() {
    let d = tmp("surface");
    let m = map();
    let (code, json, err) = run(
        &["surface", m.as_str(), "--pixel-size", "50e-9", "--json"],
        &d,
    );
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&json).unwrap();
    let me = &v["model_error"];
    assert!(
        me["reference"]
            .as_str()
            .unwrap()
            .starts_with("exact elastic half-space"),
        "{me}"
    );
    let (code, json, err) = run(
        &[
            "bem",
            m.as_str(),
            "--pixel-size",
            "50e-9",
            "--estar",
            "1e9",
            "--pressures",
            "1e6,3e6,1e7",
            "--json",
        ],
        &d,
    );
    assert_eq!(code, 0, "{err}");
    let b: Value = serde_json::from_str(&json).unwrap();
    for k in 0..3 {
        let want = b["relative_differences"][k]["gw_area"].as_f64().unwrap();
        let got = me["area"][k].as_f64().unwrap();
        assert!((got - want).abs() <= 1e-12, "state {k}: {got} vs {want}");
        assert_eq!(
            me["exact_area_fraction"][k],
            b["states"][k]["area_fraction"]
        );
    }
    assert!(
        v["warnings"].to_string().contains("model_error.area"),
        "{}",
        v["warnings"]
    );
    let (code, text, err) = run(&["surface", m.as_str(), "--pixel-size", "50e-9"], &d);
    assert_eq!(code, 0, "{err}");
    assert!(
        text.contains("p/E* = 1e-3") && text.contains("GW area"),
        "{text}"
    );
}
