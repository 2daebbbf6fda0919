use super::*;
use proptest::prelude::*;

#[derive(serde::Deserialize)]
struct RawRow {
    m1: String,
    k_comp: String,
    e_comp: String,
    m: String,
    k: Option<String>,
    e: String,
}

struct Row {
    m1: f64,
    k_comp: f64,
    e_comp: f64,
    m: f64,
    k: Option<f64>,
    e: f64,
}

#[derive(serde::Deserialize)]
struct Data {
    rows: Vec<RawRow>,
}

fn rows() -> Vec<Row> {
    let text = include_str!("../../../tests/data/elliptic.json");
    let p = |s: &str| s.parse::<f64>().unwrap();
    serde_json::from_str::<Data>(text)
        .unwrap()
        .rows
        .iter()
        .map(|r| Row {
            m1: p(&r.m1),
            k_comp: p(&r.k_comp),
            e_comp: p(&r.e_comp),
            m: p(&r.m),
            k: r.k.as_deref().map(p),
            e: p(&r.e),
        })
        .collect()
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// Against mpmath (330 digits): AGM and the log series are both good to a few
/// ulps; 2e-15 relative allows ~9 ulps of rounding in the sums.
#[test]
fn matches_mpmath_including_m_to_one() {
    let rows = rows();
    assert!(rows.len() > 60);
    let mut worst = 0.0f64;
    for r in &rows {
        let (k, e) = ellip_ke_comp(r.m1);
        worst = worst.max(rel(k, r.k_comp)).max(rel(e, r.e_comp));
        assert!(
            rel(k, r.k_comp) < 2e-15,
            "K m1={}: {k} vs {}",
            r.m1,
            r.k_comp
        );
        assert!(
            rel(e, r.e_comp) < 2e-15,
            "E m1={}: {e} vs {}",
            r.m1,
            r.e_comp
        );
        let (k2, e2) = ellip_ke(r.m);
        match r.k {
            Some(kr) => assert!(rel(k2, kr) < 2e-15, "K m={}: {k2} vs {kr}", r.m),
            None => assert_eq!(k2, f64::INFINITY),
        }
        assert!(rel(e2, r.e) < 2e-15, "E m={}", r.m);
    }
    // The log singularity: K(1 - 1e-300) = ln 4 + 150 ln 10 = 346.77...
    assert!(rel(ellip_k_comp(1e-300), 346.774_058_310_226_74) < 1e-15);
    eprintln!("worst relative error against mpmath: {worst:e}");
}

#[test]
fn special_values_and_bad_input() {
    use std::f64::consts::FRAC_PI_2;
    assert_eq!(ellip_k(0.0), FRAC_PI_2);
    assert_eq!(ellip_e(0.0), FRAC_PI_2);
    assert_eq!(ellip_k(1.0), f64::INFINITY);
    assert_eq!(ellip_e(1.0), 1.0);
    assert!(ellip_k(1.5).is_nan() && ellip_e(1.0 + 1e-15).is_nan());
    assert!(ellip_k(f64::NAN).is_nan() && ellip_e_comp(f64::NAN).is_nan());
    assert!(ellip_k_comp(-1e-300).is_nan());
}

/// The lanes give the scalar function's bits: both methods, the switch
/// between them, the ends and bad input.
#[test]
fn lanes_are_the_scalar_bits() {
    let mut m1s: Vec<f64> = rows().iter().map(|r| r.m1).collect();
    m1s.extend([
        0.0,
        0.1,
        0.1 - 1e-17,
        1.0,
        3.5,
        1e300,
        -1.0,
        f64::NAN,
        1e-300,
    ]);
    m1s.extend((0..400).map(|i| (i as f64 * 0.37).sin().abs() * 1.2));
    let mut compared = 0;
    for chunk in m1s.chunks(4).filter(|c| c.len() == 4) {
        let m1: [f64; 4] = chunk.try_into().unwrap();
        for (got, &m) in ellip_ke_comp_lanes(&m1).iter().zip(&m1) {
            let want = ellip_ke_comp(m);
            assert_eq!(got.0.to_bits(), want.0.to_bits(), "K at m1 = {m}");
            assert_eq!(got.1.to_bits(), want.1.to_bits(), "E at m1 = {m}");
            compared += 1;
        }
    }
    assert!(compared > 400, "{compared}");
}

/// The AGM stops once `c` is within rounding of `a`: at most 7 steps over
/// its range `m1` in [0.1, 1] (parameters whose `a` and `b` stay an ulp
/// apart ran to the 40-step cap when it asked `|c| <= 1e-17 a`), and with
/// the same bits as running on to that cap.
#[test]
fn agm_stops_at_rounding_with_the_bits_of_running_on() {
    let mut most = 0;
    for i in 0..=20_000 {
        let m1 = 0.1 + 0.9 * (i as f64 / 20_000.0);
        let (quick, steps) = agm_ke_steps(m1, AGM_DONE);
        // `c = 0` exactly, or the 40-step cap
        let (slow, _) = agm_ke_steps(m1, 0.0);
        assert_eq!(quick.0.to_bits(), slow.0.to_bits(), "K at m1 = {m1}");
        assert_eq!(quick.1.to_bits(), slow.1.to_bits(), "E at m1 = {m1}");
        most = most.max(steps);
    }
    assert!(most <= 7, "{most} steps");
}

proptest! {
    /// Legendre's relation `E K' + E' K - K K' = pi/2` (DLMF 19.7.1) couples the
    /// two branches of the implementation (m and m1 on opposite sides of 0.1).
    #[test]
    fn legendre_relation(m in 0.0f64..1.0) {
        let (k, e) = ellip_ke(m);
        let (kp, ep) = ellip_ke_comp(m);
        let lhs = e * kp + ep * k - k * kp;
        prop_assert!((lhs - std::f64::consts::FRAC_PI_2).abs() < 4e-15 * k * kp, "{lhs}");
    }

    /// The two methods agree where both converge fast (either side of the switch).
    #[test]
    fn series_and_agm_agree(q in 0.02f64..0.3) {
        let (k1, e1) = series_ke(q);
        let (k2, e2) = agm_ke(q);
        prop_assert!(rel(k1, k2) < 3e-15 && rel(e1, e2) < 3e-15);
    }
}
