//! Struve H0, H1 against mpmath (tests/data/struve.json, struveh at 50 digits,
//! made by tests/data/struve.py) and the shared reference
//! tests/data/reference/kesari_lew.json (a second script; read if present).

use asperity::special::struve::{struve_h0, struve_h0_h1, struve_h1};

use crate::common::{local, num, rel, shared};

/// The promise: `|err| <= 1e-14 max(|H|, 1e-3)` for 0 < x <= 1e6 (relative
/// 1e-14 wherever |H| > 1e-3, absolute 1e-17 near the zeros of H0).
#[test]
fn h0_h1_match_mpmath_to_1e14() {
    let d = local("struve.json");
    let (mut w0, mut w1) = (0.0_f64, 0.0_f64);
    let rows = d["rows"].as_array().unwrap();
    assert!(rows.len() > 1300);
    for row in rows {
        let x = num(&row["x"]);
        let (e0, e1) = (num(&row["h0"]), num(&row["h1"]));
        let (g0, g1) = (struve_h0(x), struve_h1(x));
        assert_eq!(struve_h0_h1(x), (g0, g1), "x {x}");
        let s0 = (g0 - e0).abs() / e0.abs().max(1e-3);
        let s1 = (g1 - e1).abs() / e1.abs().max(1e-3);
        assert!(s0 <= 1e-14, "H0({x}) = {g0}, mpmath {e0}: {s0:.2e}");
        assert!(s1 <= 1e-14, "H1({x}) = {g1}, mpmath {e1}: {s1:.2e}");
        w0 = w0.max(s0);
        w1 = w1.max(s1);
    }
    println!("worst scaled error: H0 {w0:.2e}, H1 {w1:.2e}");
}

#[test]
fn h0_h1_match_the_shared_reference() {
    let Some(d) = shared("kesari_lew.json") else {
        return;
    };
    for row in d["computed"]["struve_reference"].as_array().unwrap() {
        let x = num(&row["x"]);
        let (e0, e1) = (num(&row["H0"]), num(&row["H1"]));
        // Every reference value there exceeds 2e-5 in size: relative 1e-14.
        assert!(rel(struve_h0(x), e0) <= 1e-14, "x {x}");
        assert!(rel(struve_h1(x), e1) <= 1e-14, "x {x}");
    }
}
