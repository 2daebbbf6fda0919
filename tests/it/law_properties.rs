//! Property tests over every single-asperity law: finite values,
//! continuity, monotonicity on the stable branches, hysteresis order and
//! the pull-off bounds, with Maugis–Dugdale over lambda in [1e-3, 1e3].
use asperity::law::{AsperityLaw, Branch, Control, LawInputs, LawKernels, LawKind, Maugis};
use asperity::material::MaugisScales;
use proptest::prelude::*;
use std::f64::consts::PI;

/// One contact: R (m), E* (Pa), w (J/m^2), z0 (m), lambda.
#[derive(Debug, Clone, Copy)]
struct Setup {
    r: f64,
    e: f64,
    w: f64,
    z0: f64,
    lambda: f64,
}

fn setup() -> impl Strategy<Value = Setup> {
    (
        -8.0..-2.0f64,
        6.0..12.0f64,
        -3.0..1.0f64,
        -10.0..-8.5f64,
        -3.0..3.0f64,
    )
        .prop_map(|(r, e, w, z0, l)| Setup {
            r: 10f64.powf(r),
            e: 10f64.powf(e),
            w: 10f64.powf(w),
            z0: 10f64.powf(z0),
            lambda: 10f64.powf(l),
        })
}

/// Every law kind ([`LawKind::ALL`]): a new kind is tested without editing
/// this file.
fn laws(s: Setup) -> Vec<Box<dyn LawKernels>> {
    let inputs = LawInputs {
        radius: s.r,
        contact_modulus: s.e,
        work_of_adhesion: s.w,
        range: s.z0,
        lambda: s.lambda,
    };
    LawKind::ALL
        .iter()
        .map(|k| k.build_from(&inputs).unwrap())
        .collect()
}

/// Interferences in Maugis units: +-1e-6 .. 1e6, both signs, and 0.
fn interferences(law: &dyn AsperityLaw, scale: f64) -> Vec<f64> {
    let mut v = vec![0.0];
    for k in -24..=24 {
        let x = 10f64.powf(k as f64 / 4.0);
        v.push(x);
        v.push(-x);
    }
    for d in [
        law.attach_interference(),
        law.detach_interference(),
        law.cutoff_interference(),
    ] {
        if d.is_finite() {
            v.push(d / scale);
            v.push(d / scale * (1.0 + 1e-9));
            v.push(d / scale * (1.0 - 1e-9));
        }
    }
    v.retain(|&x| x * scale < law.max_interference());
    v.sort_by(f64::total_cmp);
    v
}

proptest! {
    #![proptest_config(crate::common::proptest_config(48))]

    #[test]
    fn finite_and_ordered(s in setup()) {
        let sc = MaugisScales::new(s.r, s.e, s.w).unwrap();
        for law in laws(s) {
            for d in interferences(law.as_ref(), sc.interference) {
                let delta = d * sc.interference;
                let a = law.state(delta, Branch::Approach);
                let r = law.state(delta, Branch::Retract);
                for st in [a, r] {
                    prop_assert!(st.load.is_finite() && st.radius.is_finite(),
                        "{} at {d}: {st:?}", law.name());
                    prop_assert!(st.radius >= 0.0);
                }
                // Retraction is never less adhesive than approach.
                prop_assert!(r.load <= a.load + 1e-12 * sc.load * (1.0 + a.load.abs() / sc.load),
                    "{} at {d}: retract {} approach {}", law.name(), r.load, a.load);
                // Below the cutoff the load is exactly zero on every branch.
                if delta < law.cutoff_interference() {
                    prop_assert_eq!(a.load, 0.0);
                    prop_assert_eq!(r.load, 0.0);
                }
            }
        }
    }

    #[test]
    fn continuous_and_monotone_on_stable_branches(s in setup()) {
        let sc = MaugisScales::new(s.r, s.e, s.w).unwrap();
        for law in laws(s) {
            let name = law.name();
            // Load-controlled pull-off splits the stable branch: load falls
            // towards it, then rises (Hertz: rises everywhere).
            let d_pull = law.pull_off(Control::Load).map_or(f64::NEG_INFINITY, |p| p.interference);
            for branch in [Branch::Approach, Branch::Retract] {
                let bps = law.breakpoints(branch);
                let lo = match branch {
                    Branch::Approach => law.attach_interference(),
                    Branch::Retract => law.detach_interference(),
                }
                .max(-50.0 * sc.interference);
                let hi = (50.0 * sc.interference).min(0.999 * law.max_interference());
                let n = 400;
                let mut prev: Option<(f64, f64)> = None;
                for k in 0..=n {
                    let delta = lo + (hi - lo) * (k as f64 + 0.5) / (n as f64 + 1.0);
                    let p = law.load(delta, branch);
                    if let Some((d0, p0)) = prev {
                        let crosses = bps.iter().any(|&b| b > d0 && b <= delta);
                        let tol = 1e-11 * sc.load * (1.0 + p.abs() / sc.load);
                        if !crosses {
                            if d0 >= d_pull {
                                prop_assert!(p >= p0 - tol, "{name} {branch:?}: rises after pull-off at {delta}: {p0} -> {p}");
                            } else if delta <= d_pull {
                                prop_assert!(p <= p0 + tol, "{name} {branch:?}: falls before pull-off at {delta}: {p0} -> {p}");
                            }
                            // Continuity: a jump does not shrink with the step;
                            // a continuous load (even sqrt-like at a fold) does.
                            let h = 1e-6 * (hi - lo);
                            let j1 = (law.load(delta + h, branch) - p).abs();
                            let j2 = (law.load(delta + h / 100.0, branch) - p).abs();
                            let crosses_h = bps.iter().any(|&b| b > delta && b <= delta + h);
                            prop_assert!(crosses_h || j2 <= 0.5 * j1 + tol,
                                "{name} {branch:?}: jump at {delta}: {j1} {j2}");
                        }
                    }
                    prev = Some((delta, p));
                }
            }
        }
    }

    #[test]
    fn maugis_pull_off_is_between_jkr_and_dmt_and_monotone(l1 in -3.0..3.0f64, dl in 0.001..1.0f64) {
        let (a, b) = (10f64.powf(l1), 10f64.powf((l1 + dl).min(3.0)));
        let w = 0.1;
        let r = 1e-6;
        let pa = Maugis::new(r, 1e10, w, a).unwrap().pull_off(Control::Load).unwrap().load / (PI * w * r);
        let pb = Maugis::new(r, 1e10, w, b).unwrap().pull_off(Control::Load).unwrap().load / (PI * w * r);
        prop_assert!(-pa >= 1.5 && -pa <= 2.0, "lambda {a}: {pa}");
        prop_assert!(-pb >= 1.5 && -pb <= 2.0, "lambda {b}: {pb}");
        // Magnitude decreases with lambda (DMT -> JKR).
        prop_assert!(-pa >= -pb - 1e-13, "lambda {a} -> {b}: {pa} vs {pb}");
    }
}

#[test]
fn other_laws_pull_off_in_units_of_pi_w_r() {
    let s = Setup {
        r: 1e-6,
        e: 5e10,
        w: 0.5,
        z0: 3e-10,
        lambda: 1.0,
    };
    let unit = PI * s.w * s.r;
    let want = [Some(0.0), Some(-2.0), Some(-2.0), Some(-1.5)];
    for (law, w) in laws(s).iter().zip(want) {
        let got = law.pull_off(Control::Load).map(|p| p.load / unit);
        match (got, w) {
            (Some(g), Some(w)) => assert!((g - w).abs() < 1e-12, "{}", law.name()),
            (None, None) => {}
            other => panic!("{}: {other:?}", law.name()),
        }
    }
}
