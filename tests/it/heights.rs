//! Height distributions: F_n against mpmath (tests/data/heights_fn.json) and the
//! shared exponential reference, exact values, round trips, validation, and
//! property tests of F_n (positivity, monotonicity, F_n' = -n F_(n-1)).

use asperity::heights::{
    DistributionKind, DistributionParams, Empirical, Exponential, Gaussian, HeightDistribution,
    TruncatedGaussian, Weibull,
};
use asperity::named::Named;
use proptest::prelude::*;

use crate::common::{local, num, rel, shared};

#[test]
fn exponential_matches_mpmath_and_shared_reference() {
    let e = Exponential::new();
    let d = local("heights_fn.json");
    let mut worst = 0.0_f64;
    for row in d["exponential"].as_array().unwrap() {
        let (n, h) = (num(&row["n"]), num(&row["h"]));
        worst = worst.max(rel(e.moment_above(n, h), num(&row["F"])));
    }
    println!("exponential vs mpmath: max rel err {worst:.2e}");
    // Closed forms ~1e-15; the quadrature fallback (n = 0.3, 3 is integer) 1e-13.
    assert!(worst < 1e-12, "{worst:e}");
    if let Some(d) = shared("gw_exponential_Fn.json") {
        let mut worst = 0.0_f64;
        for (n, rows) in d["table"].as_object().unwrap() {
            let n: f64 = n.parse().unwrap();
            assert!(e.closed_form_moment(n));
            for row in rows.as_array().unwrap() {
                let h = row["h"].as_f64().unwrap();
                worst = worst.max(rel(e.moment_above(n, h), num(&row["F"])));
            }
        }
        println!("exponential vs shared gw_exponential_Fn.json: max rel err {worst:.2e}");
        assert!(worst < 1e-14, "{worst:e}");
    }
}

#[test]
fn weibull_matches_mpmath() {
    let d = local("heights_fn.json");
    let mut worst = 0.0_f64;
    for row in d["weibull"].as_array().unwrap() {
        let w = Weibull::new(num(&row["k"])).unwrap();
        assert!(rel(w.scale(), num(&row["lambda"])) < 1e-14);
        let (n, h) = (num(&row["n"]), num(&row["h"]));
        let exact = num(&row["F"]);
        let e = rel(w.moment_above(n, h), exact);
        assert!(e < 1e-11, "k {} n {n} h {h}: {e:e}", w.shape());
        worst = worst.max(e);
    }
    println!("weibull vs mpmath: max rel err {worst:.2e}");
}

#[test]
fn truncated_matches_mpmath() {
    let d = local("heights_fn.json");
    let mut worst = 0.0_f64;
    for row in d["truncated"].as_array().unwrap() {
        let t = TruncatedGaussian::new(num(&row["k"])).unwrap();
        let (n, h) = (num(&row["n"]), num(&row["h"]));
        let exact = num(&row["F"]);
        let e = rel(t.moment_above(n, h), exact);
        assert!(e < 1e-11, "k {} n {n} h {h}: {e:e}", t.truncation());
        worst = worst.max(e);
    }
    println!("truncated vs mpmath: max rel err {worst:.2e}");
}

#[test]
fn weibull_shape_one_is_the_exponential() {
    let w = Weibull::new(1.0).unwrap();
    let e = Exponential::new();
    assert!((w.scale() - 1.0).abs() < 1e-15);
    for h in [-2.0, -0.3, 0.0, 0.7, 3.0] {
        for n in [0.0, 1.0, 1.5, 2.5] {
            let (a, b) = (w.moment_above(n, h), e.moment_above(n, h));
            assert!(rel(a, b) < 1e-12, "n {n} h {h}: {a} {b}");
        }
        assert!(rel(w.pdf(h.abs()), e.pdf(h.abs())) < 1e-15);
    }
}

#[test]
fn gaussian_quadrature_fallback_matches_closed_forms() {
    // Other n go through quadrature; check the same machinery on closed n
    // via n + 1e-300 (not a closed order, same value to rounding).
    let g = Gaussian::new();
    for n in [0.5, 1.0, 1.5, 2.0, 2.5] {
        for h in [-6.0, -1.0, 0.0, 0.7, 4.0, 12.0, 30.0] {
            let exact = g.moment_above(n, h);
            let quad = g.moment_above(n * (1.0 + f64::EPSILON), h);
            assert!(rel(quad, exact) < 1e-12, "n {n} h {h}: {quad} {exact}");
        }
    }
    // F_3 = 2 F_1 - h F_2.
    for h in [-2.0, 0.0, 1.0, 3.0] {
        let f3 = 2.0 * g.moment_above(1.0, h) - h * g.moment_above(2.0, h);
        assert!(rel(g.moment_above(3.0, h), f3) < 1e-12, "h {h}");
    }
}

#[test]
fn empirical_is_the_exact_sample_average() {
    let z = [
        3.1e-9, -1.0e-9, 0.2e-9, 5.5e-9, 2.0e-9, 2.0e-9, -4.25e-9, 0.0,
    ];
    let e = Empirical::new(&z).unwrap();
    let n = z.len() as f64;
    let mean = z.iter().sum::<f64>() / n;
    let std = (z.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n).sqrt();
    assert!(rel(e.std_m(), std) < 1e-14);
    let s: Vec<f64> = z.iter().map(|x| (x - mean) / std).collect();
    for h in [-3.0, -1.0, -0.2, 0.0, 0.4, 0.9, 1.5, 1.7, 3.0] {
        for order in [0.0, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0] {
            let direct: f64 = s
                .iter()
                .filter(|&&x| x > h)
                .map(|&x| (x - h).powf(order))
                .sum::<f64>()
                / n;
            let got = e.moment_above(order, h);
            assert!(
                (got - direct).abs() <= 1e-14 * direct.abs().max(1e-300),
                "n {order} h {h}: {got} {direct}"
            );
        }
    }
    // A point exactly at h does not count (s > h).
    let top = e.standardised()[7];
    assert_eq!(e.moment_above(0.0, top), 0.0);
    assert_eq!(e.tail(top - 1e-12), 1.0 / n);
    // KDE density integrates to ~1.
    let (lo, hi) = e.numerical_support(1e-16);
    let steps = 20000;
    let dx = (hi - lo) / steps as f64;
    let mass: f64 = (0..steps)
        .map(|i| e.pdf(lo + (i as f64 + 0.5) * dx) * dx)
        .sum();
    assert!((mass - 1.0).abs() < 1e-6, "{mass}");
}

#[test]
fn empirical_accurate_when_points_cluster_above_h() {
    // Many points just above h: the O(log N) form must not cancel.
    let z: Vec<f64> = (0..2000)
        .map(|i| 1.0 + 1e-6 * f64::from(i % 7) + f64::from(i / 1000))
        .collect();
    let e = Empirical::new(&z).unwrap();
    let s = e.standardised().to_vec();
    let h = s[999] - 1e-9;
    for order in [1.0, 2.0, 3.0] {
        let direct: f64 = s
            .iter()
            .filter(|&&x| x > h)
            .map(|&x| (x - h).powf(order))
            .sum::<f64>()
            / s.len() as f64;
        assert!(rel(e.moment_above(order, h), direct) < 1e-12, "n {order}");
    }
}

#[test]
fn quantile_round_trips() {
    let dists: Vec<Box<dyn HeightDistribution>> = vec![
        Box::new(Gaussian::new()),
        Box::new(Exponential::new()),
        Box::new(Weibull::new(0.7).unwrap()),
        Box::new(Weibull::new(2.5).unwrap()),
        Box::new(TruncatedGaussian::new(3.0).unwrap()),
        Box::new(TruncatedGaussian::new(0.5).unwrap()),
    ];
    for d in &dists {
        for p in [1e-300, 1e-30, 1e-8, 0.01, 0.3, 0.5, 0.8, 0.999, 1.0 - 1e-12] {
            let s = d.quantile(p);
            assert!(s.is_finite(), "{} p {p}", d.name());
            // Upper tail at the quantile is 1 - p: compare in the smaller tail.
            let upper = d.tail(s);
            if p < 0.5 {
                let lower = 1.0 - upper;
                // 1 - tail has absolute error ~1e-16: a relative check
                // only where that resolves p (the far lower tail of the
                // Gaussian is checked by symmetry below).
                if p >= 1e-3 {
                    assert!(rel(lower, p) < 1e-12, "{} p {p}: {lower}", d.name());
                } else {
                    assert!((lower - p).abs() < 1e-15, "{} p {p}: {lower}", d.name());
                }
            } else {
                // Resolution of s itself: one ulp moves the tail by ~ulp * pdf
                // (matters next to a bounded support end).
                let res = 2.0 * s.abs() * f64::EPSILON * d.pdf(s);
                assert!(
                    (upper - (1.0 - p)).abs() <= 1e-12 * (1.0 - p) + res,
                    "{} p {p}: {upper}",
                    d.name()
                );
            }
        }
        assert!(d.quantile(f64::NAN).is_nan());
        assert!(d.quantile(-0.1).is_nan());
        assert!(d.quantile(1.5).is_nan());
    }
    // The upper quantile: P(S > s) = q to 1e-12 relative, down to q =
    // 1e-300 (where 1 - q is 1 and the quantile of it is lost).
    for d in &dists {
        for q in [
            1e-300, 1e-100, 1e-30, 1e-12, 1e-5, 0.01, 0.3, 0.5, 0.7, 0.99,
        ] {
            let s = d.quantile_upper(q);
            assert!(s.is_finite(), "{} q {q}", d.name());
            let res = 2.0 * s.abs() * f64::EPSILON * d.pdf(s);
            let upper = d.tail(s);
            if q <= 0.5 {
                assert!(
                    (upper - q).abs() <= 1e-12 * q + res,
                    "{} q {q}: {upper}",
                    d.name()
                );
            } else {
                let lower = 1.0 - upper;
                assert!(
                    (lower - (1.0 - q)).abs() <= 1e-12 * (1.0 - q) + res + 1e-16,
                    "{} q {q}: {upper}",
                    d.name()
                );
            }
        }
        assert!(d.quantile_upper(f64::NAN).is_nan());
        assert!(d.quantile_upper(-0.1).is_nan());
        assert!(d.quantile_upper(1.5).is_nan());
    }
    // Gaussian lower tail to 1e-300: exact symmetric check.
    let g = Gaussian::new();
    for p in [1e-300, 1e-100, 1e-20] {
        assert!(rel(g.tail(-g.quantile(p)), p) < 1e-13, "p {p}");
    }
}

#[test]
fn support_and_numerical_support() {
    let g = Gaussian::new();
    let (lo, hi) = g.numerical_support(1e-300);
    assert!(rel(g.tail(hi), 1e-300) < 1e-12 && lo == -hi);
    let e = Exponential::new();
    assert!(rel(e.tail(e.numerical_support(1e-20).1), 1e-20) < 1e-14);
    let w = Weibull::new(2.0).unwrap();
    assert!(rel(w.tail(w.numerical_support(1e-20).1), 1e-20) < 1e-13);
    let t = TruncatedGaussian::new(2.0).unwrap();
    assert_eq!(t.numerical_support(1e-300), (-2.0, 2.0));
    assert_eq!(t.support(), (-2.0, 2.0));
    for d in [&g as &dyn HeightDistribution, &e, &w, &t] {
        let (a, b) = d.numerical_support(f64::NAN);
        assert!(a.is_finite() && b.is_finite() && b > a, "{}", d.name());
    }
}

#[test]
fn moment_above_rejects_bad_orders_without_panicking() {
    let emp = Empirical::new(&[1.0, 2.0, 4.0]).unwrap();
    let dists: Vec<&dyn HeightDistribution> = vec![&Gaussian, &Exponential, &emp];
    let w = Weibull::new(1.7).unwrap();
    let t = TruncatedGaussian::new(1.2).unwrap();
    for d in dists.into_iter().chain([&w as &dyn HeightDistribution, &t]) {
        assert!(d.moment_above(-1.0, 0.0).is_nan(), "{}", d.name());
        assert!(d.moment_above(f64::NAN, 0.0).is_nan(), "{}", d.name());
        assert!(d.moment_above(1.0, f64::NAN).is_nan(), "{}", d.name());
        assert_eq!(d.moment_above(1.5, f64::INFINITY), 0.0, "{}", d.name());
        assert!(
            !d.moment_above(1.5, f64::NEG_INFINITY).is_nan(),
            "{}",
            d.name()
        );
        assert!(
            d.pdf(f64::NAN).is_nan() && d.tail(f64::NAN).is_nan(),
            "{}",
            d.name()
        );
        assert_eq!(d.tail(f64::INFINITY), 0.0, "{}", d.name());
        assert_eq!(d.tail(f64::NEG_INFINITY), 1.0, "{}", d.name());
    }
}

#[test]
fn constructors_validate() {
    for k in [0.0, -1.0, f64::NAN, f64::INFINITY, 0.05, 1000.0] {
        let e = Weibull::new(k).unwrap_err();
        assert_eq!(e.field(), Some("weibull_shape"), "{k}");
    }
    // 1e-300 gave negative areas and an exit-1 negative hysteresis energy.
    for k in [0.0, -1.0, f64::NAN, f64::INFINITY, 1e-300, 0.009] {
        assert_eq!(
            TruncatedGaussian::new(k).unwrap_err().field(),
            Some("truncation")
        );
    }
    assert_eq!(Empirical::new(&[]).unwrap_err().field(), Some("heights"));
    assert_eq!(Empirical::new(&[1.0]).unwrap_err().field(), Some("heights"));
    assert_eq!(
        Empirical::new(&[2.0, 2.0, 2.0]).unwrap_err().field(),
        Some("heights")
    );
    assert_eq!(
        Empirical::new(&[1.0, f64::NAN]).unwrap_err().field(),
        Some("heights[1]")
    );
    assert_eq!(
        Empirical::new(&[1.0, 2.0, f64::NEG_INFINITY])
            .unwrap_err()
            .field(),
        Some("heights[2]")
    );
}

#[test]
fn kinds_build_and_name_their_own_parameters() {
    let by_name = |name: &str, p: &DistributionParams| DistributionKind::parse(name)?.build(p);
    let none = DistributionParams::default();
    for (name, field) in [
        ("weibull", "weibull_shape"),
        ("truncated-gaussian", "truncation"),
        ("empirical", "heights"),
    ] {
        assert_eq!(by_name(name, &none).unwrap_err().field(), Some(field));
    }
    let bad = |p: DistributionParams| p;
    let e = by_name(
        "weibull",
        &bad({
            let mut p = DistributionParams::default();
            p.weibull_shape = Some(-1.0);
            p
        }),
    );
    assert_eq!(e.unwrap_err().field(), Some("weibull_shape"));
    let e = by_name(
        "truncated-gaussian",
        &bad({
            let mut p = DistributionParams::default();
            p.truncation = Some(f64::NAN);
            p
        }),
    );
    assert_eq!(e.unwrap_err().field(), Some("truncation"));
    let e = by_name(
        "empirical",
        &bad({
            let mut p = DistributionParams::default();
            p.heights = Some(vec![1.0, f64::INFINITY]);
            p
        }),
    );
    assert_eq!(e.unwrap_err().field(), Some("heights[1]"));
    let e = by_name("lorentz", &none).unwrap_err();
    assert_eq!(e.field(), Some("distribution"));
    assert!(e.to_string().contains("truncated-gaussian"));
}

fn all_dists() -> Vec<Box<dyn HeightDistribution>> {
    vec![
        Box::new(Gaussian::new()),
        Box::new(Exponential::new()),
        Box::new(Weibull::new(0.6).unwrap()),
        Box::new(Weibull::new(3.0).unwrap()),
        Box::new(TruncatedGaussian::new(2.0).unwrap()),
        Box::new(
            Empirical::new(
                &(0..50)
                    .map(|i| f64::from(i * i % 17) * 1e-9)
                    .collect::<Vec<_>>(),
            )
            .unwrap(),
        ),
    ]
}

proptest! {
    #![proptest_config(crate::common::proptest_config(64))]

    /// F_n >= 0 and non-increasing in h (strictly where positive, for n > 0).
    #[test]
    fn fn_positive_and_decreasing(h in -6.0f64..8.0, dh in 1e-3f64..2.0, ni in 0usize..6) {
        let n = [0.0, 0.5, 1.0, 1.5, 2.0, 2.5][ni];
        for d in all_dists() {
            let a = d.moment_above(n, h);
            let b = d.moment_above(n, h + dh);
            prop_assert!(a >= 0.0 && b >= 0.0, "{} n {} h {}", d.name(), n, h);
            prop_assert!(b <= a * (1.0 + 1e-12), "{} n {} h {}: {} {}", d.name(), n, h, a, b);
        }
    }

    /// F_n'(h) = -n F_(n-1)(h), checked by central differences (smooth
    /// distributions; n >= 1 so F_(n-1) is continuous).
    #[test]
    fn derivative_identity(h in -5.0f64..7.0, ni in 0usize..4) {
        let n = [1.0, 1.5, 2.0, 2.5][ni];
        let dists: Vec<Box<dyn HeightDistribution>> = vec![
            Box::new(Gaussian::new()),
            Box::new(Exponential::new()),
            Box::new(Weibull::new(2.0).unwrap()),
            Box::new(TruncatedGaussian::new(3.0).unwrap()),
        ];
        for d in dists {
            let (lo, hi) = d.support();
            // Central differences (step 1e-4) need distance from a support end,
            // where F_n ~ (k - h)^(n+1) has large higher derivatives.
            if h - 0.1 <= lo || h + 0.1 >= hi { continue; }
            let step = 1e-4;
            let fd = (d.moment_above(n, h + step) - d.moment_above(n, h - step)) / (2.0 * step);
            let exact = -n * d.moment_above(n - 1.0, h);
            prop_assert!((fd - exact).abs() <= 1e-6 * exact.abs() + 1e-12,
                "{} n {} h {}: {} {}", d.name(), n, h, fd, exact);
        }
    }

    /// F_0 = tail and tail is a probability.
    #[test]
    fn f0_is_the_tail(s in -40.0f64..40.0) {
        for d in all_dists() {
            let t = d.tail(s);
            prop_assert!((0.0..=1.0).contains(&t));
            prop_assert!((d.moment_above(0.0, s) - t).abs() <= 1e-15 * t.max(1e-300) + 1e-300,
                "{} s {}", d.name(), s);
        }
    }

    /// Gaussian symmetry: F_1(h) - F_1(-h) = -h, F_2(h) + F_2(-h) = 1 + h^2.
    #[test]
    fn gaussian_polynomial_identities(h in -8.0f64..8.0) {
        let g = Gaussian::new();
        let d1 = g.moment_above(1.0, h) - g.moment_above(1.0, -h);
        prop_assert!((d1 + h).abs() <= 1e-14 * (1.0 + h.abs()));
        let s2 = g.moment_above(2.0, h) + g.moment_above(2.0, -h);
        prop_assert!((s2 - 1.0 - h * h).abs() <= 1e-14 * (1.0 + h * h));
    }
}
