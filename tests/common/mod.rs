//! Reference-value helpers shared by the integration tests that read
//! mpmath tables (`mod common;`).

use serde_json::Value;

/// `tests/data/NAME`, parsed as JSON.
pub fn local(name: &str) -> Value {
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// `/work/shared/reference/NAME`, parsed as JSON; `None` when the shared
/// reference is not present (those checks are optional).
pub fn shared(name: &str) -> Option<Value> {
    let text = std::fs::read_to_string(format!("/work/shared/reference/{name}")).ok()?;
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
