//! Every vectorised pass gives the same bits at every SIMD width: whole
//! runs with `ASPERITY_SIMD=scalar`, `avx2` and the CPU's widest set
//! (`numeric::simd`), compared number for number (timings aside). The
//! scenes cover the Monte Carlo sums (Hertz-type and JKR batches, lane
//! sums), the calibrated law's far-field pass and its populations, the
//! plastic summits' prepared shapes, the GW quadrature's root rules and
//! the contact resistance's conductance batch.

use std::process::Command;

fn run(scene: &str, simd: Option<&str>) -> serde_json::Value {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_asperity"));
    cmd.args(["run", scene, "--json"]);
    match simd {
        Some(s) => cmd.env("ASPERITY_SIMD", s),
        None => cmd.env_remove("ASPERITY_SIMD"),
    };
    let out = cmd.output().expect("asperity runs");
    assert!(
        out.status.success(),
        "{scene} {simd:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    // The run says which set it used: the variable took effect.
    let used = v["simd"].as_str().expect("simd").to_string();
    match simd {
        Some("scalar") => assert_eq!(used, "scalar"),
        Some("avx2") => assert!(used == "avx2" || used == "scalar", "{used}"),
        _ => assert!(
            ["avx512", "avx2", "scalar"].contains(&used.as_str()),
            "{used}"
        ),
    }
    strip_timings(&mut v);
    v
}

/// Wall-clock fields differ from run to run, and the instruction set by
/// design.
fn strip_timings(v: &mut serde_json::Value) {
    match v {
        serde_json::Value::Object(m) => {
            m.remove("seconds");
            m.remove("simd");
            m.values_mut().for_each(strip_timings);
        }
        serde_json::Value::Array(a) => a.iter_mut().for_each(strip_timings),
        _ => {}
    }
}

#[test]
fn every_simd_width_gives_the_same_bits() {
    for scene in [
        "examples/scenes/montecarlo-gold.toml",
        "examples/scenes/mems-gold.toml",
        "examples/scenes/gold-rf-mems-plastic.toml",
        "examples/scenes/rf-mems-switch.toml",
        "examples/scenes/soft-jkr.toml",
    ] {
        let widest = run(scene, None);
        for simd in ["avx2", "scalar"] {
            // serde_json keeps f64 exactly (float_roundtrip): equality is
            // equality of bits.
            assert!(
                run(scene, Some(simd)) == widest,
                "{scene}: {simd} differs from the widest set"
            );
        }
    }
}

/// A value the variable does not know is not silently dropped: the run
/// says which set it used instead, in a warning.
#[test]
fn an_unknown_simd_request_is_named_in_a_warning() {
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(["run", "examples/scenes/hertz-exponential.toml", "--json"])
        .env("ASPERITY_SIMD", "sse9")
        .output()
        .expect("asperity runs");
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let warnings = v["warnings"].as_array().expect("warnings");
    assert!(
        warnings.iter().any(|w| w
            .as_str()
            .is_some_and(|w| w.contains("ASPERITY_SIMD=sse9 not followed"))),
        "{warnings:?}"
    );
}
