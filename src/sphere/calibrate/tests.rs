use super::*;
use crate::law::{AsperityLaw, Branch, Control};
use crate::sphere::SolverOptions;

fn problem() -> SphereProblem {
    SphereProblem::new(1.0, Shape::Paraboloid, SolverOptions::coarse()).unwrap()
}

/// The contact most tests put the calibrated law on: `R = 1 um`,
/// `E* = 50 GPa`, `w = 0.5 J/m^2`.
const CONTACT: (f64, f64, f64) = (1e-6, 5e10, 0.5);

/// `cal`'s law on the contact `(R, E*, w)` and its Maugis scales.
fn law_and_scales(
    cal: &Calibration,
    (r, e, w): (f64, f64, f64),
) -> (Tabulated, crate::material::MaugisScales) {
    let law = cal.law(r, e, w).unwrap();
    (law, crate::material::MaugisScales::new(r, e, w).unwrap())
}

/// The calibrated law reproduces the solver's critical points and has the
/// hysteresis of the S-curve: attached on retraction down to the jump-out,
/// detached on approach up to the jump-in.
#[test]
fn law_reproduces_the_solver_curve() {
    let c = Calibration::compute(&problem()).unwrap();
    assert!((c.lambda_equivalent - 1.157_011_634_850_799_3).abs() < 1e-15);
    let (law, s) = law_and_scales(&c, (2e-6, 3e10, 0.4));
    let pull = law.pull_off(Control::Load).unwrap();
    assert!((pull.load / s.load - c.facts.pull_off.load_bar).abs() < 1e-15);
    // the table's minimum on the attached branch is the refined pull-off
    let at = law.state(pull.interference, Branch::Retract);
    assert!(
        (at.load - pull.load).abs() < 2e-3 * pull.load.abs(),
        "{at:?} {pull:?}"
    );
    let (att, det) = (law.attach_interference(), law.detach_interference());
    assert!(det < att);
    let mid = 0.5 * (att + det);
    let on = law.state(mid, Branch::Retract);
    let off = law.state(mid, Branch::Approach);
    assert!(on.radius > 0.0 && on.load < off.load, "{on:?} {off:?}");
    // every branch monotone in load where it should be: far field attractive
    let far = law.state(-20.0 * s.interference, Branch::Approach);
    assert!(far.load < 0.0 && far.load > -0.1 * s.load, "{far:?}");
    let deep = law.state(5.0 * s.interference, Branch::Approach);
    assert!(deep.load > 0.0 && deep.radius > 0.0);
    assert_eq!(law.name(), "tabulated");
    // never cut; the program-start range at the rigid gap 100 z0
    assert_eq!(law.cutoff_interference(), f64::NEG_INFINITY);
    let range = law.interaction_range();
    let at_range = law.state(range, Branch::Approach).load / s.load;
    assert!(
        (at_range / (-8.0 / 3.0 / 1e4) - 1.0).abs() < 1e-3,
        "{at_range}"
    );
}

#[test]
fn small_mu_has_one_branch() {
    let p = SphereProblem::new(0.1, Shape::Paraboloid, SolverOptions::coarse()).unwrap();
    let c = Calibration::compute(&p).unwrap();
    assert!(c.table.attach_bar.is_none() && c.table.detach_bar.is_none());
    let law = c.law(1e-6, 5e10, 0.5).unwrap();
    assert_eq!(law.attach_interference(), f64::NEG_INFINITY);
    for d in [-3e-9, -1e-10, 0.0, 1e-9] {
        assert_eq!(
            law.state(d, Branch::Approach),
            law.state(d, Branch::Retract)
        );
    }
}

/// One table serves every R, E*, w: the law in Maugis units is the same.
#[test]
fn one_table_serves_every_contact() {
    let c = Calibration::compute(&problem()).unwrap();
    let contacts = [(1e-6, 5e10, 0.5), (3e-5, 1e9, 0.05), (2e-8, 2e11, 1.5)];
    let laws: Vec<_> = contacts.iter().map(|&k| law_and_scales(&c, k)).collect();
    for d in [-5.0, -0.95, -0.5, 0.0, 1.0, 3.0] {
        for branch in [Branch::Approach, Branch::Retract] {
            let v: Vec<(f64, f64)> = laws
                .iter()
                .map(|(l, s)| {
                    let st = l.state(d * s.interference, branch);
                    (st.load / s.load, st.radius / s.radius)
                })
                .collect();
            for x in &v[1..] {
                assert!(
                    (x.0 - v[0].0).abs() < 1e-12 && (x.1 - v[0].1).abs() < 1e-12,
                    "{d} {v:?}"
                );
            }
        }
    }
}

#[test]
fn best_fit_lambda_beats_the_matched_dugdale_stress() {
    let c = Calibration::compute(&problem()).unwrap();
    let (lambda, err) = c.best_fit_lambda(4.0).unwrap();
    // The error at the fitted lambda is no worse than at 1.1570 mu, or at
    // twice or half the fitted value.
    let at = |l: f64| {
        let md = crate::law::MaugisCurve::new(l).unwrap();
        c.table
            .attached
            .interference_bar
            .iter()
            .zip(&c.table.attached.load_bar)
            .filter(|(_, &p)| p <= 4.0)
            .map(|(&d, &p)| {
                (md.state_bar(d, crate::law::Branch::Retract).1 - p).abs() / (1.0 + p.abs())
            })
            .fold(0.0, f64::max)
    };
    assert!((at(lambda) - err).abs() < 1e-12);
    for other in [c.lambda_equivalent, 2.0 * lambda, 0.5 * lambda] {
        assert!(
            err <= at(other),
            "lambda {lambda} ({err}) vs {other} ({})",
            at(other)
        );
    }
    assert!(
        lambda > 0.1 * c.mu && lambda < 10.0 * c.mu,
        "{lambda} at mu {}",
        c.mu
    );
    assert_eq!(
        c.best_fit_lambda(-10.0).unwrap_err().field(),
        Some("max_load_bar")
    );
}

/// Default resolution with a wider arc step (points are still converged to
/// Newton accuracy; only their spacing changes): the options of the
/// reference tests below.
fn reference_options() -> SolverOptions {
    SolverOptions {
        arc_step: 0.1,
        ..SolverOptions::default()
    }
}

/// Linear interpolation of the solver's load (and radius) at `Dbar` on a
/// traced branch ascending in interference.
fn solver_at(curve: &[crate::sphere::SpherePoint], d: f64) -> (f64, f64) {
    let w = curve
        .windows(2)
        .find(|w| w[0].interference_bar <= d && d <= w[1].interference_bar)
        .unwrap_or_else(|| panic!("{d} not traced"));
    let t = (d - w[0].interference_bar) / (w[1].interference_bar - w[0].interference_bar);
    (
        w[0].load_bar + t * (w[1].load_bar - w[0].load_bar),
        w[0].radius_bar + t * (w[1].radius_bar - w[0].radius_bar),
    )
}

/// out of contact, beyond the table's first point
/// (rigid gap ~6 z0), the law follows the solver traced from 60 z0, whose
/// elastic enhancement over Bradley decays (mu = 1: 1.5 %, 0.53 %, 0.32 %,
/// 0.16 % at H = 6, 10, 20, 50). Tolerance 0.5 %: the solver's own
/// far-field floor at default resolution is 0.1-0.35 % at H = 10-60 (its
/// ratio to Bradley at resolution 2, far_gap 1000 is 1.0016 flat there,
/// mu = 1.59), against the 1.2-1.4 % of a constant enhancement at H >= 20.
#[test]
fn far_field_follows_the_solver_out_to_50_z0() {
    let mu = 1.0;
    let opt = reference_options();
    let cal =
        Calibration::compute(&SphereProblem::new(mu, Shape::Paraboloid, opt).unwrap()).unwrap();
    let far = SphereProblem::new(
        mu,
        Shape::Paraboloid,
        SolverOptions {
            start_gap: 60.0,
            max_load_bar: 0.1,
            ..opt
        },
    )
    .unwrap()
    .trace()
    .unwrap();
    let far: Vec<_> = far.into_iter().filter(|p| p.radius_bar == 0.0).collect();
    let (law, sc) = law_and_scales(&cal, CONTACT);
    let s = mu * super::super::trace::MAUGIS_INTERFERENCE;
    for gap in [5.0, 10.0, 20.0, 50.0] {
        let d = (1.0 - gap) / s;
        let (want, _) = solver_at(&far, d);
        let got = law.state(d * sc.interference, Branch::Approach).load / sc.load;
        assert!(
            (got / want - 1.0).abs() < 5e-3,
            "H = {gap}: law {got}, solver {want}"
        );
    }
    // Far out the law is Bradley's rigid law (enhancement < 1e-4 at 50 z0).
    let d = (1.0 - 50.0) / s;
    let got = law.state(d * sc.interference, Branch::Approach).load / sc.load;
    let h: f64 = 50.0;
    let bradley = -(8.0 / 3.0) * (h.powi(-2) - 0.25 * h.powi(-8));
    assert!((got / bradley - 1.0).abs() < 1e-4, "{got} {bradley}");
}

/// the table reaches 100 pi w R and the law there is
/// the solver's: load and contact radius at Pbar ~ 5, 20, 50, 95 against an
/// independent trace (arc step 0.5: other points) within 0.2 % (PCHIP
/// between points 0.1 apart plus the reference's linear interpolation
/// between points 0.5 apart on a curve of curvature ~A^-1: < 1e-3).
/// Before, the table stopped at 2 and the Hertz continuation put radii
/// 4-5 % low at Pbar ~ 100.
#[test]
fn table_reaches_100_pi_w_r() {
    let mu = 1.0;
    let opt = reference_options();
    let cal =
        Calibration::compute(&SphereProblem::new(mu, Shape::Paraboloid, opt).unwrap()).unwrap();
    let last = *cal.table.attached.load_bar.last().unwrap();
    assert!(last >= TABLE_MIN_LOAD_BAR, "{last}");
    let reference = SphereProblem::new(
        mu,
        Shape::Paraboloid,
        SolverOptions {
            arc_step: 0.5,
            max_load_bar: 110.0,
            ..opt
        },
    )
    .unwrap()
    .trace()
    .unwrap();
    let attached: Vec<_> = reference
        .iter()
        .filter(|p| p.load_bar > 1.0 && p.radius_bar > 0.0)
        .copied()
        .collect();
    let (law, sc) = law_and_scales(&cal, CONTACT);
    for want_load in [5.0, 20.0, 50.0, 95.0] {
        let p = attached.iter().find(|p| p.load_bar >= want_load).unwrap();
        let d = p.interference_bar;
        let (load, radius) = solver_at(&attached, d);
        let st = law.state(d * sc.interference, Branch::Retract);
        let (gl, ga) = (st.load / sc.load, st.radius / sc.radius);
        assert!((gl / load - 1.0).abs() < 2e-3, "P {gl} vs {load} at {d}");
        assert!(
            (ga / radius - 1.0).abs() < 2e-3,
            "A {ga} vs {radius} at {d}"
        );
    }
}

/// the far field is never cut (the old cut at a rigid
/// gap of 100 z0 dropped ~1.3 % of a rough surface's pull-off once sigma
/// exceeds ~100 z0): at 200 and 1e4 z0 the load is Bradley's, to 1e-6.
#[test]
fn far_field_is_not_cut() {
    let cal = Calibration::compute(&problem()).unwrap();
    let (law, sc) = law_and_scales(&cal, CONTACT);
    assert_eq!(law.cutoff_interference(), f64::NEG_INFINITY);
    let s = cal.table.far_field_scale;
    for h in [200.0f64, 1e4] {
        let d = (1.0 - h) / s;
        let got = law.state(d * sc.interference, Branch::Retract).load / sc.load;
        let bradley = -(8.0 / 3.0) * (h.powi(-2) - 0.25 * h.powi(-8));
        assert!(
            (got / bradley - 1.0).abs() < 1e-6,
            "H = {h}: {got} {bradley}"
        );
    }
}

/// one interference origin. The solver's approach is
/// 0 at a rigid gap z0, where the continuum laws' surfaces touch (the
/// Lennard-Jones traction changes sign at z0 as the continuum contact
/// pressure does at zero gap), so in contact the calibrated law carries
/// Maugis–Dugdale's load at the same interference: within 5 % of
/// `pi w R + |P|` at Dbar = 2, 4 (mu = 1, lambda = 1.157; the measured
/// MD error of data/law_errors.json at mu = 1 is 2-8 %, 2-5 % at these
/// loads). Measured from the geometric touching of the force-law planes
/// (shifted by z0 = 1/s = 0.56 in Dbar) it would be off by more than 15 %
/// at each.
#[test]
fn calibrated_law_shares_the_continuum_origin() {
    let cal = Calibration::compute(&problem()).unwrap();
    let md = crate::law::MaugisCurve::new(cal.lambda_equivalent).unwrap();
    let (law, sc) = law_and_scales(&cal, CONTACT);
    let shift = 1.0 / cal.table.far_field_scale;
    for d in [2.0, 4.0] {
        let p = law.state(d * sc.interference, Branch::Retract).load / sc.load;
        let same = md.state_bar(d, Branch::Retract).1;
        let shifted = md.state_bar(d - shift, Branch::Retract).1;
        let err = |x: f64| (x - p).abs() / (1.0 + p.abs());
        assert!(err(same) < 0.05, "Dbar {d}: {p} vs MD {same}");
        assert!(err(shifted) > 0.15, "Dbar {d}: {p} vs shifted MD {shifted}");
    }
}
