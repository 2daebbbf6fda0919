//! Helpers shared by the modules of the integration-test binary
//! (`tests/it/main.rs`): reference values read from mpmath tables, the
//! proptest configuration, and (`cli`) running the built program.

use proptest::test_runner::{Config as ProptestConfig, FileFailurePersistence};
use serde_json::Value;

/// Running the built `asperity` in a temporary directory.
pub mod cli;

/// `tests/data/NAME`, parsed as JSON.
pub fn local(name: &str) -> Value {
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// `tests/data/reference/NAME` (the project's copy of the shared reference
/// values, provenance in its README), parsed as JSON. Always present: the
/// `Option` only keeps the callers' shape.
pub fn shared(name: &str) -> Option<Value> {
    let path = format!("{}/tests/data/reference/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    Some(serde_json::from_str(&text).unwrap())
}

/// A JSON number, or a string holding one (high-precision mpmath digits).
pub fn num(v: &Value) -> f64 {
    match v {
        Value::String(s) => s.parse().unwrap(),
        other => other.as_f64().unwrap(),
    }
}

/// Relative error `|(a - b)/b|`, exactly 0 when `a == b` (so equal zeros or
/// infinities count as exact).
pub fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        ((a - b) / b).abs()
    }
}

/// The converged sphere-solver case of `tests/data/sphere_converged.json`
/// at Tabor parameter `mu` and size ratio `rho` (`None`: paraboloid); panics
/// naming the case when it is missing.
pub fn sphere_converged(mu: f64, rho: Option<f64>) -> Value {
    let v = local("sphere_converged.json");
    v["cases"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["mu"].as_f64() == Some(mu) && c["rho"].as_f64() == rho)
        .unwrap_or_else(|| panic!("no reference for mu {mu}, rho {rho:?}"))
        .clone()
}

/// A second, independent GW integrator of contact-resistance sums.
pub mod gw_spots;

/// The proptest configuration of these tests: `cases` cases, the failures
/// persisted beside the module's source as `<module>.proptest-regressions`
/// (`tests/it/heights.proptest-regressions`), where they were kept before
/// the tests became one binary. Proptest's default would now look for
/// `tests/proptest-regressions/<module>.txt`, since `tests/it/` holds a
/// `main.rs`. `PROPTEST_DISABLE_FAILURE_PERSISTENCE` still turns it off.
pub fn proptest_config(cases: u32) -> ProptestConfig {
    let mut config = ProptestConfig::with_cases(cases);
    if config.failure_persistence.is_some() {
        config.failure_persistence = Some(Box::new(FileFailurePersistence::WithSource(
            "proptest-regressions",
        )));
    }
    config
}

/// The body rows of the Markdown table whose header row starts with
/// `header`, each split into trimmed cells (the outer pipes dropped).
pub fn markdown_table(md: &str, header: &str) -> Vec<Vec<String>> {
    let at = md
        .find(header)
        .unwrap_or_else(|| panic!("no table with header {header:?}"));
    let rows: Vec<Vec<String>> = md[at..]
        .lines()
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .map(|l| {
            l.trim()
                .trim_matches('|')
                .split('|')
                .map(|c| c.trim().to_string())
                .collect()
        })
        .collect();
    assert!(!rows.is_empty(), "the table {header:?} has no rows");
    rows
}
