use super::*;

const LAMBDAS: [f64; 12] = [
    1e-3, 0.01, 0.1, 0.3, 0.6, 0.9, 0.95, 1.0, 2.0, 10.0, 100.0, 1e3,
];

#[test]
fn derivatives_match_finite_differences() {
    for l in LAMBDAS {
        let c = MaugisCurve::new(l).unwrap();
        for t in [1e-6f64, 1e-3, 0.1, 0.7, 1.2, 1.5] {
            let h = 1e-6 * t.min(FRAC_PI_2 - t);
            let dp = |t: f64| c.raw(Angle::from_t(t));
            let fd_d = (dp(t + h).interference - dp(t - h).interference) / (2.0 * h);
            let fd_p = (dp(t + h).load - dp(t - h).load) / (2.0 * h);
            let an_d = c.d_interference(Angle::from_t(t));
            let an_p = c.d_load(Angle::from_t(t));
            // Central differences: O(h^2) truncation plus eps |f| / h rounding.
            let r = dp(t);
            let tol_d = 1e-6 * an_d.abs() + 1e-9 * (1.0 + r.interference.abs()) / h * h.max(1e-3);
            let tol_p = 1e-6 * an_p.abs() + 1e-9 * (1.0 + r.load.abs()) / h * h.max(1e-3);
            assert!(
                (fd_d - an_d).abs() <= tol_d,
                "lam {l} t {t}: {fd_d} vs {an_d}"
            );
            assert!(
                (fd_p - an_p).abs() <= tol_p,
                "lam {l} t {t}: {fd_p} vs {an_p}"
            );
        }
    }
}

#[test]
fn contact_branch_joins_non_contact_branch_at_zero_radius() {
    for l in LAMBDAS {
        let c = MaugisCurve::new(l).unwrap();
        let j = c.junction_bar();
        let nc = c.non_contact_point(j.outer_radius_bar);
        // The non-contact form subtracts 2/(pi lambda): rounding of that size.
        let tol = 1e-14 * (1.0 + c.attach_bar().abs());
        assert!((nc.interference_bar - j.interference_bar).abs() < tol);
        assert!((nc.load_bar - j.load_bar).abs() < 1e-13 * (1.0 + j.load_bar.abs()));
        // m -> inf on the contact branch: A -> 0, C -> C0, gap continuous.
        for m in [1e6, 1e9, 1e12] {
            let p = c.point_at_m(m).unwrap();
            let tol = 1e-8 * (1e6 / m) * (1.0 + j.load_bar.abs());
            assert!(p.radius_bar < 10.0 * j.outer_radius_bar / m * 1.01, "{p:?}");
            assert!(
                (p.load_bar - j.load_bar).abs() < tol,
                "lam {l} m {m}: {p:?} vs {j:?}"
            );
            assert!((p.interference_bar - j.interference_bar).abs() < tol);
            assert!((p.outer_radius_bar / j.outer_radius_bar - 1.0).abs() < 1e-6);
        }
        assert_eq!(c.point_at_m(f64::INFINITY), Some(j));
        assert_eq!(c.point_at_m(1.0), None);
        assert_eq!(c.point_at_m(f64::NAN), None);
    }
}

#[test]
fn non_contact_branch_tends_to_rigid_derjaguin_attraction() {
    // Pbar_rigid = -2 - pi lambda Dbar for -2/(pi lambda) <= Dbar <= 0: the
    // elastic term b C of the exact branch is O(lambda^(1/2)) relative.
    let mut last = f64::INFINITY;
    for l in [1e-1, 1e-2, 1e-3, 1e-4] {
        let c = MaugisCurve::new(l).unwrap();
        let j = c.junction_bar();
        let mut worst: f64 = 0.0;
        for k in 1..=20 {
            let cc = j.outer_radius_bar * k as f64 / 20.0;
            let p = c.non_contact_point(cc);
            let rigid = -2.0 - PI * l * p.interference_bar;
            worst = worst.max((p.load_bar - rigid).abs());
        }
        assert!(worst < 3.0 * l.sqrt(), "lam {l}: {worst}");
        assert!(worst < last, "lam {l}: {worst} !< {last}");
        last = worst;
    }
}

#[test]
fn stable_point_inverts_the_curve() {
    for l in LAMBDAS {
        let c = MaugisCurve::new(l).unwrap();
        let fold = c.jump_out_bar();
        // Stable contact points: m from the fold / junction to deep contact.
        for m in [
            1.0 + 1e-12,
            1.0 + 1e-6,
            1.001,
            1.1,
            1.5,
            3.0,
            10.0,
            100.0,
            1e4,
        ] {
            let p = c.point_at_m(m).unwrap();
            let on_stable = p.interference_bar > fold.interference_bar
                && (c.non_contact_stable || p.radius_bar > fold.radius_bar);
            if !on_stable {
                continue;
            }
            let q = c.stable_point(p.interference_bar);
            let scale = 1.0 + p.load_bar.abs();
            // Near the fold the root is ill-conditioned (dDbar/dA -> 0).
            let slope = c.d_interference(Angle::from_t(((m - 1.0) * (m + 1.0)).sqrt().atan()));
            let tol =
                1e-12 + 1e-14 * (1.0 + p.interference_bar.abs()) / slope.abs().clamp(1e-6, 1.0);
            assert!(
                (q.load_bar - p.load_bar).abs() <= tol * scale,
                "lam {l} m {m}: {q:?} vs {p:?}"
            );
            assert!(
                (q.radius_bar - p.radius_bar).abs() <= tol * (1.0 + p.radius_bar),
                "lam {l} m {m}"
            );
        }
        // Non-contact stable states.
        if c.non_contact_stable {
            let j = c.junction_bar();
            for f in [0.01, 0.5, 0.99] {
                let cc = fold.outer_radius_bar + f * (j.outer_radius_bar - fold.outer_radius_bar);
                let p = c.non_contact_point(cc);
                let q = c.stable_point(p.interference_bar);
                assert!(
                    (q.load_bar - p.load_bar).abs() < 1e-9 * (1.0 + p.load_bar.abs()),
                    "{l} {f}"
                );
                assert_eq!(q.radius_bar, 0.0);
            }
        }
    }
}

#[test]
fn table_is_ascending_and_branch_has_one_fold() {
    for l in LAMBDAS {
        let c = MaugisCurve::new(l).unwrap();
        for w in c.nodes.windows(2) {
            assert!(w[1].d > w[0].d, "lam {l}: {:?}", w);
        }
        // The whole curve: Dbar decreases to the jump-out, then increases.
        let fold = c.jump_out_bar().interference_bar;
        assert!(fold < c.attach_bar());
        assert!(c.jump_in_bar().interference_bar - c.attach_bar() < 1e-12 * (1.0 + fold.abs()));
        let pull = c.pull_off_bar();
        assert!(pull.load_bar <= c.jump_out_bar().load_bar);
        assert!(pull.load_bar <= c.junction_bar().load_bar);
        assert!(c.zero_load_bar().load_bar.abs() < 1e-13);
    }
}

#[test]
fn instability_regimes_switch_at_their_critical_lambdas() {
    let below = MaugisCurve::new(LAMBDA_CONTINUOUS_DETACH * 0.99).unwrap();
    let above = MaugisCurve::new(LAMBDA_CONTINUOUS_DETACH * 1.01).unwrap();
    assert_eq!(below.jump_out_bar().radius_bar, 0.0);
    assert!(below.contact_loss_bar().is_some());
    assert!(above.jump_out_bar().radius_bar > 0.0);
    assert!(above.contact_loss_bar().is_none());
    // Continuous across lambda_c.
    let d = (below.jump_out_bar().interference_bar - above.jump_out_bar().interference_bar).abs();
    assert!(d < 0.01, "{d}");
    let lc = (9.0 * PI / (16.0 * (PI - 1.0))).cbrt();
    assert!((lc - LAMBDA_CONTINUOUS_DETACH).abs() < 1e-15);
    assert!(((9.0f64 / 32.0).cbrt() - LAMBDA_NON_CONTACT_JUMP_IN).abs() < 1e-15);
    let lo = MaugisCurve::new(LAMBDA_NON_CONTACT_JUMP_IN * 0.99).unwrap();
    let hi = MaugisCurve::new(LAMBDA_NON_CONTACT_JUMP_IN * 1.01).unwrap();
    assert_eq!(lo.jump_in_bar().radius_bar, 0.0);
    assert!(hi.jump_in_bar().radius_bar > 0.0);
}

#[test]
fn non_contact_snap_matches_closed_form() {
    for l in [1e-3, 0.1, 0.5, 0.9] {
        let c = MaugisCurve::new(l).unwrap();
        let j = c.jump_out_bar();
        let p = -32.0 * l * l * l / (9.0 * PI);
        let d = -2.0 / (PI * l) - 32.0 * l * l / (9.0 * PI * PI);
        assert!((j.load_bar / p - 1.0).abs() < 1e-14, "{l}");
        assert!((j.interference_bar / d - 1.0).abs() < 1e-14, "{l}");
    }
}

#[test]
fn bad_lambda_is_rejected_naming_the_field() {
    for l in [
        0.0,
        -1.0,
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        1e-7,
        1e7,
    ] {
        let e = MaugisCurve::new(l).unwrap_err();
        assert_eq!(e.field(), Some("lambda"), "{l}");
        let e = Maugis::new(1e-6, 1e10, 0.1, l).unwrap_err();
        assert_eq!(e.field(), Some("lambda"), "{l}");
    }
    assert_eq!(
        Maugis::new(-1.0, 1e10, 0.1, 1.0).unwrap_err().field(),
        Some("radius")
    );
    assert_eq!(
        Maugis::new(1e-6, 1e10, 0.0, 1.0).unwrap_err().field(),
        Some("work_of_adhesion")
    );
}

#[test]
fn dimensional_law_uses_the_scales() {
    let law = Maugis::new(1e-6, 5e10, 0.5, 1.0).unwrap();
    let s = law.scales();
    let c = law.curve();
    let pull = law.pull_off(Control::Load).unwrap();
    assert!((pull.load / (c.pull_off_bar().load_bar * s.load) - 1.0).abs() < 1e-15);
    for d in [-1.0, -0.5, 0.0, 0.7, 3.0] {
        let st = law.state(d * s.interference, Branch::Retract);
        let (a, p) = c.state_bar(d, Branch::Retract);
        assert!((st.load - p * s.load).abs() <= 1e-14 * s.load * (1.0 + p.abs()));
        assert!((st.radius - a * s.radius).abs() <= 1e-14 * s.radius * (1.0 + a));
    }
    assert_eq!(law.state(f64::NAN, Branch::Approach), ContactState::FREE);
    assert!(law.cutoff_interference() < law.attach_interference());
    let bp = law.breakpoints(Branch::Approach);
    assert!(bp.windows(2).all(|w| w[0] < w[1]));
}

/// The stability analysis of the module doc rests on the whole curve
/// (non-contact from C = 0, then contact from the junction to deep contact)
/// having exactly one local minimum of Dbar and one of Pbar. Checked on a
/// dense sampling for 25 lambdas over [1e-3, 1e3].
#[test]
fn whole_curve_has_one_minimum_of_interference_and_of_load() {
    for k in 0..25 {
        let l = 10f64.powf(-3.0 + 6.0 * k as f64 / 24.0);
        let c = MaugisCurve::new(l).unwrap();
        let c0 = c.junction_bar().outer_radius_bar;
        // Non-contact: dense around the fold C = b, then up to C0.
        let mut cs: Vec<f64> = (0..=100).map(|i| 2.0 * c.b * i as f64 / 100.0).collect();
        cs.extend((0..=400).map(|i| c0 * i as f64 / 400.0));
        cs.retain(|&x| x <= c0);
        cs.sort_by(f64::total_cmp);
        let mut pts: Vec<MaugisPoint> = cs.iter().map(|&x| c.non_contact_point(x)).collect();
        for i in 1..=2000 {
            let y = 1e-9 * (FRAC_PI_4 / 1e-9f64).powf(i as f64 / 2000.0);
            pts.push(c.point(Angle::from_y(y)));
        }
        for i in 1..=2000 {
            let t = FRAC_PI_4 * (1e-8 / FRAC_PI_4).powf(i as f64 / 2000.0);
            pts.push(c.point(Angle::from_t(t)));
        }
        for (what, v) in [
            (
                "Dbar",
                pts.iter().map(|p| p.interference_bar).collect::<Vec<_>>(),
            ),
            ("Pbar", pts.iter().map(|p| p.load_bar).collect::<Vec<_>>()),
        ] {
            // Sign changes of the increments, ignoring rounding-level ones.
            let scale = v.iter().fold(0.0f64, |m, x| m.max(x.abs().min(1e3)));
            let incs: Vec<f64> = v
                .windows(2)
                .map(|w| w[1] - w[0])
                .filter(|d| d.abs() > 1e-12 * scale)
                .collect();
            let turns = incs
                .windows(2)
                .filter(|w| w[0].signum() != w[1].signum())
                .count();
            assert_eq!(turns, 1, "lambda {l}: {what} turns {turns} times");
            assert!(
                incs[0] < 0.0 && *incs.last().unwrap() > 0.0,
                "lambda {l}: {what}"
            );
        }
        // Both minima agree with the precomputed instabilities.
        let dmin = pts
            .iter()
            .map(|p| p.interference_bar)
            .fold(f64::INFINITY, f64::min);
        let pmin = pts.iter().map(|p| p.load_bar).fold(f64::INFINITY, f64::min);
        assert!(
            c.jump_out_bar().interference_bar <= dmin + 1e-12 * (1.0 + dmin.abs()),
            "lambda {l}"
        );
        assert!(
            dmin - c.jump_out_bar().interference_bar < 1e-3 * (1.0 + dmin.abs()),
            "lambda {l}"
        );
        assert!(c.pull_off_bar().load_bar <= pmin + 1e-13, "lambda {l}");
        // The samples are ~1% apart in angle: O(1e-3) above the minimum.
        assert!(
            pmin - c.pull_off_bar().load_bar < 3e-3,
            "lambda {l}: {pmin} vs {:?}",
            c.pull_off_bar()
        );
        assert!(
            c.pull_off_bar().radius_bar > 0.0,
            "lambda {l}: pull-off in contact"
        );
    }
}

#[test]
fn accepted_range_ends_are_dmt_and_jkr() {
    let lo = MaugisCurve::new(LAMBDA_MIN).unwrap();
    // Pull-off -2 + O(lambda^1.5): 1.7e-9 at 1e-6.
    assert!(
        (lo.pull_off_bar().load_bar + 2.0).abs() < 3e-9,
        "{:?}",
        lo.pull_off_bar()
    );
    assert!(lo.pull_off_bar().load_bar > -2.0);
    assert!((lo.zero_load_bar().radius_bar - 2f64.cbrt()).abs() < 1e-5);
    let hi = MaugisCurve::new(LAMBDA_MAX).unwrap();
    assert!((hi.pull_off_bar().load_bar + 1.5).abs() < 1e-10);
    assert!((hi.jump_out_bar().load_bar + 5.0 / 6.0).abs() < 1e-8);
    assert!((hi.zero_load_bar().radius_bar - 6f64.cbrt()).abs() < 1e-8);
    for c in [&lo, &hi] {
        for d in [-1e7, -10.0, -1.0, 0.0, 1.0, 1e3, 1e12] {
            let (a, p) = c.state_bar(d, Branch::Retract);
            assert!(a.is_finite() && p.is_finite());
        }
    }
}

#[test]
fn pull_off_only_is_the_full_curves_pull_off_bit_for_bit() {
    // 601 lambdas log-spaced over the whole allowed range [1e-6, 1e6].
    for i in 0..=600 {
        let l = LAMBDA_MIN * (LAMBDA_MAX / LAMBDA_MIN).powf(i as f64 / 600.0);
        let l = l.clamp(LAMBDA_MIN, LAMBDA_MAX);
        let full = MaugisCurve::new(l).unwrap().pull_off_bar();
        let fast = MaugisCurve::pull_off_only(l).unwrap();
        if l >= 1e-5 {
            assert_eq!(full, fast, "lambda {l}");
        } else {
            // Below 1e-5 the load is flat to rounding near its minimum
            // (the DMT limit), so the sampled minimum is a rounding tie:
            // the load agrees to a few ulp, the location is immaterial.
            assert!(
                (fast.load_bar - full.load_bar).abs() <= 1e-14 * full.load_bar.abs(),
                "lambda {l}: {full:?} {fast:?}"
            );
        }
    }
    let e = MaugisCurve::pull_off_only(0.0).unwrap_err();
    assert_eq!(e.field(), Some("lambda"));
}
