//! Maugis–Dugdale for any profile (`axisym::AxisymMd`, Barthel's
//! cohesive-zone form): the paraboloid reproduces `law::Maugis` (Maugis
//! 1992, itself checked against mpmath in tests/it/maugis.rs) to 1e-10, and
//! the cone tends to JKR as the range shrinks and to the rigid (Derjaguin)
//! force `-pi w h0/tan^2 beta` as it grows.
use asperity::axisym::{AxisymJkr, AxisymMd, Profile};
use asperity::law::shaped::{ShapedMd, ShapedMdExact};
use asperity::law::{AsperityLaw, Branch, Control, Maugis};
use std::f64::consts::PI;

fn rel(x: f64, y: f64) -> f64 {
    ((x - y) / y).abs()
}

#[test]
fn the_paraboloid_reproduces_maugis_at_1e_10() {
    let (r, e, w) = (1e-6, 1e9, 0.05);
    let mut worst: f64 = 0.0;
    // Both sides of lambda_c = 0.938 (snap off the disc, then off contact).
    for lambda in [0.1, 0.5, 1.0, 3.0, 10.0] {
        let law = Maugis::new(r, e, w, lambda).unwrap();
        let sc = law.scales();
        let sigma = AxisymMd::stress_from_lambda(lambda, r, e, w);
        let md = AxisymMd::new(Profile::paraboloid(r).unwrap(), e, w, sigma).unwrap();
        // Points of the contact branch at given m = c/a.
        for m in [1.01, 1.1, 1.5, 3.0, 10.0] {
            let p = law.curve().point_at_m(m).unwrap();
            let a = p.radius_bar * sc.radius;
            let q = md.point(a);
            let load_scale = p.load_bar.abs().max(1.0) * sc.load;
            let errs = [
                rel(q.outer_radius, p.outer_radius_bar * sc.radius),
                (q.load - p.load_bar * sc.load).abs() / load_scale,
                (q.interference - p.interference_bar * sc.interference).abs()
                    / (p.interference_bar.abs().max(1.0) * sc.interference),
            ];
            for x in errs {
                worst = worst.max(x);
                assert!(x < 1e-10, "lambda {lambda} m {m}: {q:?} vs {p:?}");
            }
        }
        for (mine, control) in [
            (md.pull_off_load_control(), Control::Load),
            (md.jump_out_displacement_control(), Control::Displacement),
        ] {
            let theirs = law.pull_off(control).unwrap();
            let errs = [
                rel(mine.load, theirs.load),
                (mine.interference - theirs.interference).abs() / sc.interference,
                (mine.radius - theirs.radius).abs() / sc.radius,
            ];
            for x in errs {
                worst = worst.max(x);
                assert!(
                    x < 1e-10,
                    "lambda {lambda} {control:?}: {mine:?} vs {theirs:?}"
                );
            }
        }
        let z = law.zero_load_radius().unwrap();
        assert!(rel(md.zero_load().radius, z) < 1e-10, "{lambda}");
    }
    println!("worst relative error against law::Maugis: {worst:.2e}");
}

/// `lambda = sigma0/(E* tan beta)`: the cone's range `h0 = w/sigma0` over
/// its JKR elastic displacement `w/(E* tan beta)`, inverted.
fn cone(lambda: f64) -> AxisymMd {
    let (e, w, t) = (1e9, 0.05, 0.2);
    AxisymMd::new(Profile::cone(t).unwrap(), e, w, lambda * e * t).unwrap()
}

#[test]
fn the_cone_tends_to_jkr_as_the_range_shrinks() {
    let (e, w, t) = (1e9, 0.05, 0.2);
    let jkr = AxisymJkr::new(Profile::cone(t).unwrap(), e, w).unwrap();
    let (pj, qj) = (
        jkr.pull_off_load_control(),
        jkr.jump_out_displacement_control(),
    );
    let mut last = (f64::INFINITY, f64::INFINITY);
    for lambda in [10.0, 100.0, 1000.0] {
        let md = cone(lambda);
        let (p, q) = (
            md.pull_off_load_control(),
            md.jump_out_displacement_control(),
        );
        let d = (
            rel(p.load, pj.load).max(rel(p.radius, pj.radius)),
            rel(q.load, qj.load)
                .max(rel(q.radius, qj.radius))
                .max(rel(q.interference, qj.interference)),
        );
        println!(
            "cone lambda {lambda}: pull-off {:.2e}, jump-out {:.2e}",
            d.0, d.1
        );
        // Second order in 1/lambda (measured 8.4e-4, 8.4e-6, 8.5e-8 and
        // 1.0e-2, 1.0e-4, 1.0e-6): 100-fold per decade.
        assert!(
            d.0 < 0.02 * last.0 && d.1 < 0.02 * last.1,
            "{lambda}: {d:?}"
        );
        assert!(d.0 < 1e-1 / (lambda * lambda) && d.1 < 2.0 / (lambda * lambda));
        last = d;
    }
}

#[test]
fn the_cone_tends_to_the_rigid_derjaguin_force_as_the_range_grows() {
    let (w, t) = (0.05, 0.2);
    let mut last = f64::INFINITY;
    for lambda in [1e-1, 1e-2, 1e-3] {
        let md = cone(lambda);
        let rigid = -PI * w * md.range() / (t * t);
        let d = rel(md.pull_off_load_control().load, rigid);
        println!("cone lambda {lambda}: pull-off / rigid - 1 = {d:.2e}");
        // First order in lambda (measured 0.37, 3.5e-2, 3.5e-3).
        assert!(d < 0.15 * last && d < 4.0 * lambda, "{lambda}: {d}");
        last = d;
    }
}

/// The law on `AsperityLaw`: a paraboloid `ShapedMd` (tables of the exact
/// general-profile solve) follows `law::Maugis` on both branches, with
/// Maugis' history (free on approach until `-h0`, attached on retraction
/// down to the snap), on both sides of `lambda_c`.
#[test]
fn the_shaped_md_law_is_maugis_for_a_paraboloid() {
    let (r, e, w) = (1e-6, 1e9, 0.05);
    for lambda in [0.3, 2.0] {
        let law = Maugis::new(r, e, w, lambda).unwrap();
        let sigma = AxisymMd::stress_from_lambda(lambda, r, e, w);
        let s = ShapedMd::new(Profile::paraboloid(r).unwrap(), e, w, sigma).unwrap();
        let ps = law.pull_off(Control::Load).unwrap().load.abs();
        assert!(rel(s.attach_interference(), law.attach_interference()) < 1e-12);
        assert!(rel(s.detach_interference(), law.detach_interference()) < 1e-10);
        let (lo, hi) = (
            law.detach_interference(),
            30.0 * law.detach_interference().abs(),
        );
        let mut worst: f64 = 0.0;
        for i in 0..=300 {
            let d = lo - 0.01 * lo.abs() + (hi - lo) * (i as f64 / 300.0).powi(2);
            for b in [Branch::Approach, Branch::Retract] {
                let (x, y) = (s.state(d, b), law.state(d, b));
                let e = (x.load - y.load).abs() / (y.load.abs() + ps);
                worst = worst.max(e);
                assert!(e < 1e-9, "lambda {lambda} {d} {b:?}: {x:?} {y:?}");
                assert!(
                    (x.radius - y.radius).abs() <= 1e-8 * y.radius.max(1e-9),
                    "{d}"
                );
            }
        }
        println!("lambda {lambda}: worst load error vs Maugis {worst:.2e}");
    }
}

/// A cone's tables against its exact solve, and the history rules.
#[test]
fn a_conical_shaped_md_law_matches_its_exact_solve() {
    let (e, w, t) = (1e9, 0.05, 0.2);
    let prof = Profile::cone(t).unwrap();
    let s = ShapedMd::new(prof.clone(), e, w, 3.0 * e * t).unwrap();
    let x = ShapedMdExact::new(prof, e, w, 3.0 * e * t).unwrap();
    let dc = x.detach_interference();
    let ps = x.pull_off(Control::Load).unwrap().load.abs();
    for i in 0..=50 {
        let d = dc + 20.0 * dc.abs() * (i as f64 / 50.0).powi(2);
        let (f, g) = (s.state(d, Branch::Retract), x.state(d, Branch::Retract));
        assert!((f.load - g.load).abs() <= 1e-9 * (g.load.abs() + ps), "{d}");
        assert!(f.load >= x.pull_off(Control::Load).unwrap().load * (1.0 + 1e-9));
    }
    let h0 = x.contact().range();
    assert_eq!(s.state(-1.001 * h0, Branch::Approach).load, 0.0);
    assert!(s.state(-0.999 * h0, Branch::Approach).load < 0.0);
    assert!(s.state(-1.001 * h0, Branch::Retract).load < 0.0);
    assert_eq!(s.state(1.001 * dc, Branch::Retract).load, 0.0);
}

proptest::proptest! {
    // Cost bound: each case builds one AxisymMd (two 160-point scans, each
    // point one zone solve of ~50 adaptive quadratures: ~10-30 ms) and
    // solves 3 states; no tables are built. The range h0 is tied to the
    // profile's own JKR jump-out so every case has its instabilities inside
    // the scan, and the sphere keeps w/(E* R) = 1e-4 and a <= 0.4 R (its zone must end
    // before the equator).
    #![proptest_config(crate::common::proptest_config(24))]
    /// Over profiles and ranges: the load-controlled pull-off is at least as
    /// tensile as the snap and as every stable state; the stable branch
    /// inverts `delta(a)`; the zone lies outside the contact; the paraboloid's
    /// pull-off lies between JKR (1.5 pi w R) and DMT (2 pi w R).
    #[test]
    fn md_instabilities_and_branch(
        kind in 0u8..4, n in 1.2f64..3.0, le in 8.0f64..11.0, lw in -2.0f64..0.0,
        lmu in -1.0f64..1.0, frac in 0.0f64..1.0,
    ) {
        let (e, w) = (10f64.powf(le), 10f64.powf(lw));
        let r = 1e3 * w / e; // w/(E* R) = 1e-3
        let prof = match kind {
            0 => Profile::paraboloid(r).unwrap(),
            1 => Profile::cone(0.2).unwrap(),
            2 => Profile::power(1e-6f64.powf(1.0 - n), n).unwrap(),
            _ => Profile::sphere(10.0 * r).unwrap(),
        };
        let jkr = AxisymJkr::new(prof.clone(), e, w).unwrap();
        let h0 = 10f64.powf(lmu) * jkr.jump_out_displacement_control().interference.abs();
        let md = AxisymMd::new(prof, e, w, w / h0).unwrap();
        let (p, q) = (md.pull_off_load_control(), md.jump_out_displacement_control());
        proptest::prop_assert!(p.load <= q.load * (1.0 - 1e-12) || p == q, "{:?} {:?}", p, q);
        proptest::prop_assert!(q.interference <= -h0 * (1.0 - 1e-12));
        let a = (p.radius.max(q.radius).max(1e-3 * md.zero_load().radius) * (1.0 + 5.0 * frac))
            .min(0.4 * md.profile().max_radius());
        let pt = md.point(a);
        proptest::prop_assert!(pt.outer_radius > a && pt.load >= p.load);
        let back = md.stable_point(pt.interference).unwrap();
        proptest::prop_assert!((back.radius / a - 1.0).abs() < 1e-8, "{} {}", a, back.radius);
        proptest::prop_assert!(md.stable_point(q.interference - 1e-6 * q.interference.abs()).is_none());
        if kind == 0 {
            let x = -p.load / (PI * w * r);
            proptest::prop_assert!((1.5 * (1.0 - 1e-9)..=2.0).contains(&x), "{}", x);
        }
    }
}
