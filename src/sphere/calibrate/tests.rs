use super::*;
use crate::law::{AsperityLaw, Branch, Control};
use crate::sphere::SolverOptions;

fn problem() -> SphereProblem {
    SphereProblem::new(1.0, Shape::Paraboloid, SolverOptions::coarse()).unwrap()
}

/// The calibrated law reproduces the solver's critical points and has the
/// hysteresis of the S-curve: attached on retraction down to the jump-out,
/// detached on approach up to the jump-in.
#[test]
fn law_reproduces_the_solver_curve() {
    let c = Calibration::compute(&problem()).unwrap();
    assert!((c.lambda_equivalent - 1.157_011_634_850_799_3).abs() < 1e-15);
    let (r, e, w) = (2e-6, 3e10, 0.4);
    let law = c.law(r, e, w).unwrap();
    let s = crate::material::MaugisScales::new(r, e, w).unwrap();
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
    // zero below the far-field cut-off (rigid gap 100 z0), tiny just above
    let cut = law.cutoff_interference();
    assert_eq!(law.state(cut * 1.001, Branch::Approach).load, 0.0);
    let just = law.state(cut * 0.999, Branch::Approach).load;
    assert!(just < 0.0 && just > -3e-4 * s.load, "{just}");
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
    let laws: Vec<_> = contacts
        .iter()
        .map(|&(r, e, w)| {
            (
                c.law(r, e, w).unwrap(),
                crate::material::MaugisScales::new(r, e, w).unwrap(),
            )
        })
        .collect();
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
