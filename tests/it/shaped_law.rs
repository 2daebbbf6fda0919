//! `law::Shaped` over the parameter box: the tables agree with the exact
//! solve, the branches obey the history rules, and the law's facts are the
//! profile's JKR instabilities.
use asperity::axisym::Profile;
use asperity::law::shaped::ShapedExact;
use asperity::law::{AsperityLaw, Branch, Control, Shaped};
use proptest::prelude::*;

fn profile(kind: u8, p: f64, n: f64) -> Profile {
    match kind {
        0 => Profile::cone(p).unwrap(),
        1 => Profile::power(p, n).unwrap(),
        2 => Profile::sphere(p * 1e-6).unwrap(),
        _ => Profile::flat(p * 1e-6).unwrap(),
    }
}

proptest! {
    #![proptest_config(crate::common::proptest_config(24))]
    #[test]
    fn tables_match_the_exact_law(
        kind in 0u8..4, p in 0.05f64..2.0, n in 0.8f64..4.0, le in 8.0f64..11.0,
        lw in -2.0f64..0.0, x in 0.0f64..1.0,
    ) {
        let (e, w) = (10f64.powf(le), 10f64.powf(lw));
        let prof = profile(kind, p, n);
        let fast = Shaped::new(prof.clone(), e, w).unwrap();
        // Cost bound: every corner of this box builds in < 8000 exact
        // evaluations (< 20 ms); a sphere table that ran into the noise near
        // a = R once took 17 CPU-minutes.
        prop_assert!(fast.table().build_evaluations() < 20_000, "{}", fast.table().build_evaluations());
        let exact = ShapedExact::new(prof, e, w).unwrap();
        let scale = exact.pull_off(Control::Load).unwrap().load.abs();
        let dc = exact.detach_interference();
        prop_assert!(dc < 0.0);
        prop_assert_eq!(fast.pull_off(Control::Displacement), exact.pull_off(Control::Displacement));
        // From the jump-out to 30 times its depth.
        let d = dc + 31.0 * dc.abs() * x * x;
        for b in [Branch::Approach, Branch::Retract] {
            let (f, g) = (fast.state(d, b), exact.state(d, b));
            prop_assert!((f.load - g.load).abs() <= 1e-9 * (g.load.abs() + scale), "{:?} {:?}", f, g);
            prop_assert!((f.radius - g.radius).abs() <= 1e-8 * g.radius.max(1e-12));
        }
        // History: free on approach below 0, attached on retraction down to dc.
        prop_assert_eq!(fast.state(0.5 * dc, Branch::Approach).load, 0.0);
        prop_assert!(fast.state(0.5 * dc, Branch::Retract).load < 0.0);
        prop_assert_eq!(fast.state_after(0.5 * dc, -1e-30).load, 0.0);
        prop_assert!(fast.state_after(0.5 * dc, 0.0).radius > 0.0);
        prop_assert_eq!(fast.state(1.0001 * dc, Branch::Retract).load, 0.0);
        // The most tensile attached load is the load-controlled pull-off.
        let po = fast.pull_off(Control::Load).unwrap();
        prop_assert!(fast.state(d, Branch::Retract).load >= po.load * (1.0 + 1e-9));
    }
}

/// The case that once ran for 17 CPU-minutes: a sphere whose JKR contact
/// reaches a/R = 0.67 at pull-off (w/(E* R) = 0.2). The tables stop at
/// 0.95 R, where the load still has its digits.
#[test]
fn a_strongly_adhering_sphere_builds_in_bounded_cost() {
    let (r, e, w) = (5e-8, 1e8, 1.0);
    let fast = Shaped::new(Profile::sphere(r).unwrap(), e, w).unwrap();
    assert!(fast.table().build_evaluations() < 20_000);
    let exact = ShapedExact::new(Profile::sphere(r).unwrap(), e, w).unwrap();
    let dc = exact.detach_interference();
    let scale = exact.pull_off(Control::Load).unwrap().load.abs();
    for i in 0..20 {
        let d = dc + 2.0 * dc.abs() * i as f64 / 19.0;
        let (f, g) = (
            fast.state(d, Branch::Retract),
            exact.state(d, Branch::Retract),
        );
        assert!(
            (f.load - g.load).abs() <= 1e-9 * (g.load.abs() + scale),
            "{d}"
        );
    }
}

#[test]
fn a_table_law_builds_and_matches_its_exact_solve() {
    // A rounded cone sqrt(r^2 + rho^2) - rho, rho = 50 nm, 41 nodes.
    let rho: f64 = 5e-8;
    let r: Vec<f64> = (0..41).map(|i| i as f64 * 10.0 * rho / 40.0).collect();
    let f = r.iter().map(|x| (x * x + rho * rho).sqrt() - rho).collect();
    let prof = Profile::tabulated(r, f).unwrap();
    let fast = Shaped::new(prof.clone(), 1e8, 1.0).unwrap();
    let exact = ShapedExact::new(prof, 1e8, 1.0).unwrap();
    let dc = exact.detach_interference();
    let scale = exact.pull_off(Control::Load).unwrap().load.abs();
    for i in 0..50 {
        let d = dc + 20.0 * dc.abs() * (i as f64 / 49.0).powi(2);
        let (f, g) = (
            fast.state(d, Branch::Retract),
            exact.state(d, Branch::Retract),
        );
        // TABLE_TOLERANCE = 1e-9 plus the interpolant's own error estimate margin.
        assert!(
            (f.load - g.load).abs() <= 1e-8 * (g.load.abs() + scale),
            "{d}: {f:?} {g:?}"
        );
    }
}
