//! The batch path (one law call per chunk, lane sums, serial path for
//! small work) against the scalar law and brute-force sums; populations of
//! plastic asperities remember each summit's maximum interference; the
//! honesty of standard errors and z-scores.

use super::tests::{population, E_STAR, R, SIGMA};
use super::*;
use crate::gw::{GwModel, RoughSurface};
use crate::heights::Exponential;
use crate::law::interpolated::InterpolatedLaw;
use crate::law::plastic::{build, AdhesivePlastic, MaxInterference, PlasticLoading};
use crate::law::{
    AsperityLaw, Branch, ContactState, Dmt, Hertz, Jkr, LawKernels, Maugis, RadiusScaling,
};
use crate::loading::{History, LoadingModel, LoadingProgram, Observables};
use crate::material::plastic::{Plasticity, Variant};
use std::sync::Arc;

fn laws() -> Vec<Arc<dyn LawKernels>> {
    let md = Arc::new(Maugis::new(R, E_STAR, 0.5, 0.3).unwrap());
    let plastic = build(Variant::KogutEtsion, R, E_STAR, Plasticity::gold()).unwrap();
    let loading: Arc<dyn PlasticLoading> = plastic.clone().as_loading();
    vec![
        Arc::new(Hertz::new(R, E_STAR).unwrap()),
        Arc::new(Jkr::new(R, E_STAR, 0.5).unwrap()),
        Arc::new(Dmt::new(R, E_STAR, 0.5).unwrap()),
        md.clone(),
        Arc::new(InterpolatedLaw::new(md, -3e-9, 2e-8, 1e-9).unwrap()),
        plastic.as_law(),
        Arc::new(AdhesivePlastic::new(loading, 0.5).unwrap()),
        Arc::new(
            crate::law::Shaped::new(crate::axisym::Profile::paraboloid(R).unwrap(), E_STAR, 0.5)
                .unwrap(),
        ),
        Arc::new(
            crate::law::shaped::ShapedMd::new(
                crate::axisym::Profile::cone(0.01).unwrap(),
                E_STAR,
                0.5,
                3e9,
            )
            .unwrap(),
        ),
    ]
}

/// Interferences: sorted (as in a population), then shuffled, with the
/// special values 0, -0, and the table edges' neighbourhood.
fn interferences() -> Vec<f64> {
    let mut v: Vec<f64> = (0..600)
        .map(|k| -4e-9 + 2.6e-8 * k as f64 / 599.0)
        .collect();
    v.extend([0.0, -0.0, 1e-300, -1e-300, -3e-9, 2e-8, 3e-8]);
    let mut w = v.clone();
    // A deterministic shuffle: the panel walk must also work unsorted.
    let n = w.len();
    for i in 0..n {
        w.swap(i, (i * 7919 + 13) % n);
    }
    v.extend(w);
    v
}

#[test]
fn batch_equals_scalar_bit_for_bit_for_every_law() {
    let d = interferences();
    let m: Vec<f64> = d
        .iter()
        .enumerate()
        .map(|(i, &x)| x + 1e-9 * (i % 5) as f64)
        .collect();
    for law in laws() {
        let (mut load, mut radius) = (vec![0.0; d.len()], vec![0.0; d.len()]);
        law.state_batch(&d, None, &mut load, &mut radius);
        let approach = d.iter().map(|&x| (x, law.state(x, Branch::Approach)));
        assert_same_bits(&load, &radius, approach, law.name());
        law.state_batch(&d, Some(&m), &mut load, &mut radius);
        let after = d
            .iter()
            .zip(&m)
            .map(|(&x, &mx)| (x, law.state_after(x, mx)));
        assert_same_bits(&load, &radius, after, law.name());
    }
}

/// `load[i]`, `radius[i]` are the `i`-th `states`' (at their interference
/// `x`, m), bit for bit.
fn assert_same_bits(
    load: &[f64],
    radius: &[f64],
    states: impl Iterator<Item = (f64, ContactState)>,
    name: &str,
) {
    for (i, (x, s)) in states.enumerate() {
        assert_eq!(load[i].to_bits(), s.load.to_bits(), "{name} {x:e}");
        assert_eq!(radius[i].to_bits(), s.radius.to_bits(), "{name} {x:e}");
    }
}

/// A tabulated law's batch on dense sorted input (whole groups on one
/// panel: coefficients broadcast) and on groups that straddle panels, hold
/// a NaN or change branch (coefficients per lane), against the scalar law
/// bit for bit.
#[test]
fn tabulated_batch_on_one_panel_and_across_panels_equals_scalar() {
    let md = Arc::new(Maugis::new(R, E_STAR, 0.5, 0.3).unwrap());
    let law = InterpolatedLaw::new(md, -3e-9, 2e-8, 1e-9).unwrap();
    let mut d: Vec<f64> = (0..20_000)
        .map(|k| -2e-9 + 2e-8 * k as f64 / 19_999.0)
        .collect();
    d[5_000] = f64::NAN;
    // Maxima on both sides of the attach interference within a group.
    let m: Vec<f64> = d
        .iter()
        .enumerate()
        .map(|(i, &x)| {
            if i % 97 == 0 {
                -5e-9
            } else {
                x.max(0.0) + 1e-9
            }
        })
        .collect();
    let (mut load, mut radius) = (vec![0.0; d.len()], vec![0.0; d.len()]);
    for history in [None, Some(&m[..])] {
        law.state_batch(&d, history, &mut load, &mut radius);
        for (i, &x) in d.iter().enumerate() {
            let s = match history {
                None => law.state(x, Branch::Approach),
                Some(m) => law.state_after(x, m[i]),
            };
            assert!(
                load[i].to_bits() == s.load.to_bits() || (load[i].is_nan() && s.load.is_nan()),
                "{i} {x:e}"
            );
            assert!(
                radius[i].to_bits() == s.radius.to_bits()
                    || (radius[i].is_nan() && s.radius.is_nan()),
                "{i} {x:e}"
            );
        }
    }
}

/// A tabulated law sums its own states (`add_state_sums`: interferences
/// from the heights, groups on one panel and across panels, summits below
/// the table, a last group not full): the same bits as `state_batch` at
/// `(z - sep) s` followed by `StateSums::add` of each state, on approach
/// and on retraction; a change of one load by the table's tolerance
/// (1e-9 relative) shows in the sums.
#[test]
fn tabulated_state_sums_equal_the_batch_then_the_sums() {
    use crate::numeric::lanes::{StateSums, STATE_LANES};
    let md = Arc::new(Maugis::new(R, E_STAR, 0.5, 0.3).unwrap());
    let law = InterpolatedLaw::new(md, -3e-9, 2e-8, 1e-9).unwrap();
    let n = 10_003;
    let z: Vec<f64> = (0..n)
        .map(|k| -4e-9 + 2.4e-8 * k as f64 / (n - 1) as f64)
        .collect();
    let (sep, scale) = (1e-9, 0.9);
    let bits = |s: &StateSums| s.lanes.map(|l| l.map(f64::to_bits));
    for closest in [None, Some(-1e-8)] {
        let delta: Vec<f64> = z.iter().map(|&x| (x - sep) * scale).collect();
        let delta_max: Option<Vec<f64>> =
            closest.map(|c| z.iter().map(|&x| (x - c) * scale).collect());
        let (mut load, mut radius) = (vec![0.0; n], vec![0.0; n]);
        law.state_batch(&delta, delta_max.as_deref(), &mut load, &mut radius);
        let sum = |load: &[f64]| {
            let mut s = StateSums::default();
            for i in 0..n {
                s.add(i % STATE_LANES, load[i], radius[i]);
            }
            s
        };
        let want = sum(&load);
        let mut got = StateSums::default();
        assert!(law.add_state_sums(&z, sep, closest, scale, &mut got));
        assert_eq!(bits(&got), bits(&want), "{closest:?}");
        assert!(want.lanes[2].iter().sum::<f64>() > 0.0, "no contact");
        load[n / 2] *= 1.0 + 1e-9;
        assert_ne!(bits(&got), bits(&sum(&load)), "{closest:?}");
    }
    // A law that does not sum its own states adds nothing.
    let mut s = StateSums::default();
    assert!(!Hertz::new(R, E_STAR)
        .unwrap()
        .add_state_sums(&z, sep, None, scale, &mut s));
    assert_eq!(s, StateSums::default());
}

/// The laws that say they are reversible (Monte Carlo then skips their
/// maximum interferences on retraction) retract along their approach bit
/// for bit; no hysteretic law says so.
#[test]
fn reversible_laws_retract_along_their_approach() {
    let mut all = laws();
    all.push(Arc::new(crate::law::Bradley::new(R, 0.5, 3e-10).unwrap()));
    let mut seen = Vec::new();
    for law in all {
        if !law.reversible() {
            continue;
        }
        seen.push(law.name());
        for &x in &interferences() {
            for m in [x, x + 1e-9, -1e-8, 1e-7] {
                let (a, b) = (law.state_after(x, m), law.state(x, Branch::Approach));
                assert_eq!(a.load.to_bits(), b.load.to_bits(), "{} {x:e}", law.name());
                assert_eq!(a.radius.to_bits(), b.radius.to_bits(), "{}", law.name());
            }
        }
    }
    assert_eq!(seen, ["hertz", "dmt", "bradley"]);
}

/// Sequential brute force (one accumulator, summit order) against the
/// lane sums: the orders differ, so the totals agree to rounding; for n
/// terms of one sign both are within `n eps sum|x|` of the exact sum.
#[test]
fn lane_sums_match_a_sequential_sum_and_serial_equals_parallel() {
    let pop = population(40_000, 3);
    for law in laws().into_iter().take(5) {
        let mc = MonteCarlo::new(pop.clone(), SummitLaw::fixed(law.clone(), R).unwrap()).unwrap();
        let closest = -0.5 * SIGMA;
        let steps = [
            (0.5 * SIGMA, History::Approach),
            (0.5 * SIGMA, History::Retract { closest }),
        ];
        for &(d, h) in &steps {
            // One step of < SERIAL_BELOW evaluations: the serial path.
            let s = mc.state(d, h, &Observables::ALL).unwrap();
            assert!(s.evaluations < SERIAL_BELOW);
            let (mut p, mut pa, mut c) = (0.0, 0.0, 0.0);
            let (mut sp, mut sa) = (0.0f64, 0.0f64);
            for &z in pop.heights() {
                let st = match h {
                    History::Approach => law.state(z - d, Branch::Approach),
                    History::Retract { closest } => law.state_after(z - d, z - closest),
                };
                p += st.load;
                pa += st.area();
                sp += st.load.abs();
                sa += st.area();
                c += f64::from(u8::from(st.in_contact()));
            }
            let n = pop.len() as f64;
            let tol = |s: f64| 2.0 * n * f64::EPSILON * s;
            assert!(
                (s.load().unwrap() - p).abs() <= tol(sp),
                "{} {d}",
                law.name()
            );
            assert!(
                (s.area().unwrap() - pa).abs() <= tol(sa),
                "{} {d}",
                law.name()
            );
            assert_eq!(s.count().unwrap(), c);
            // The same steps many times over: > SERIAL_BELOW, parallel.
            let many = vec![(d, h); 8];
            let par = mc.states(&many, &Observables::ALL).unwrap();
            assert!(par.iter().map(|s| s.evaluations).sum::<usize>() >= SERIAL_BELOW);
            for q in &par {
                assert_eq!(q, &s, "{} serial vs parallel", law.name());
            }
        }
    }
}

/// Per summit `MaxInterference::step` on a sequential sum: the reference
/// for a plastic population's path.
/// Returns load, area, count and the sum of `|load|` per step.
fn brute_plastic(pop: &Population, law: &dyn AsperityLaw, path: &[f64]) -> Vec<[f64; 4]> {
    let mut mem = vec![MaxInterference::default(); pop.len()];
    path.iter()
        .map(|&d| {
            let mut v = [0.0; 4];
            for (z, m) in pop.heights().iter().zip(&mut mem) {
                let st = m.step(law, z - d);
                v[0] += st.load;
                v[3] += st.load.abs();
                v[1] += st.area();
                v[2] += f64::from(u8::from(st.in_contact()));
            }
            v
        })
        .collect()
}

#[test]
fn plastic_populations_remember_each_summits_maximum() {
    let pop = population(20_000, 9);
    let plastic = build(Variant::KogutEtsion, R, E_STAR, Plasticity::gold()).unwrap();
    let loading = plastic.clone().as_loading();
    let adhesive: Arc<dyn LawKernels> = Arc::new(AdhesivePlastic::new(loading, 0.5).unwrap());
    let program = LoadingProgram::new(4.0 * SIGMA, -0.5 * SIGMA, 20).unwrap();
    let seps = program.separations();
    // Two full cycles.
    let cycle: Vec<f64> = seps.iter().rev().chain(seps.iter()).copied().collect();
    let path: Vec<f64> = cycle.iter().chain(&cycle).copied().collect();
    let k = seps.len();
    for (law, is_adhesive) in [(plastic.as_law(), false), (adhesive, true)] {
        assert!(law.remembers_maximum());
        let mc = MonteCarlo::new(pop.clone(), SummitLaw::fixed(law.clone(), R).unwrap()).unwrap();
        let seq = mc.sequence(&path, &Observables::ALL).unwrap();
        // The first cycle is the approach-retract curve, bit for bit.
        let curve = mc.curve(&program, &Observables::ALL).unwrap();
        let first: Vec<_> = curve.approach.iter().rev().chain(&curve.retract).collect();
        for (a, b) in seq[..2 * k].iter().zip(first) {
            assert_eq!(a, b, "{}", law.name());
        }
        // Against the per-summit reference.
        for (j, (s, e)) in seq
            .iter()
            .zip(brute_plastic(&pop, law.as_ref(), &path))
            .enumerate()
        {
            // Different summation orders: within 2 n eps sum|P|.
            let tol = 2.0 * pop.len() as f64 * f64::EPSILON * e[3];
            assert!(
                (s.load().unwrap() - e[0]).abs() <= tol,
                "{} step {j}",
                law.name()
            );
            assert_eq!(s.count().unwrap(), e[2], "{} step {j}", law.name());
        }
        // The second approach retraces the unloading (elastic shakedown),
        // not the virgin curve: lower loads wherever summits were flattened.
        let (a1, a2) = (&seq[..k], &seq[2 * k..3 * k]);
        let lower = a1
            .iter()
            .zip(a2)
            .filter(|(x, y)| y.load().unwrap() < x.load().unwrap())
            .count();
        assert!(lower > k / 2, "{}: {lower} of {k}", law.name());
        if !is_adhesive {
            for (x, y) in a1.iter().zip(a2) {
                assert!(y.load().unwrap() <= x.load().unwrap() * (1.0 + 1e-12) + 1e-30);
            }
        }
        // The deepest point and the second retraction repeat the first.
        assert_eq!(seq[k - 1], seq[3 * k - 1]);
        assert_eq!(&seq[k..2 * k], &seq[3 * k..]);
    }
}

#[test]
fn one_summit_has_no_standard_error_and_empty_samples_no_z() {
    let hertz = SummitLaw::scaled(
        Arc::new(Hertz::new(R, E_STAR).unwrap()),
        R,
        RadiusScaling::MAUGIS,
    )
    .unwrap();
    let one = Population::from_summits(vec![1e-9], Radii::Fixed(R)).unwrap();
    let mc = MonteCarlo::new(Arc::new(one), hertz.clone()).unwrap();
    let s = mc.state(0.0, History::Approach, &Observables::ALL).unwrap();
    assert!(s.load().unwrap() > 0.0);
    for i in 0..3 {
        assert_eq!(s.totals.error(i), None, "slot {i}");
    }
    // No summit in range: every standard error is 0; the integral is tiny
    // but not 0. No z-score, rather than ~1e6.
    let n = 10_000;
    let mc = MonteCarlo::new(population(n, 4), hertz).unwrap();
    let model = GwModel::new(
        RoughSurface::new(n as f64, R, SIGMA, 1.0).unwrap(),
        Arc::new(Exponential::new()),
        Arc::new(Hertz::new(R, E_STAR).unwrap()),
    )
    .unwrap();
    let d = mc.top_height() + 0.01 * SIGMA;
    let s = mc.state(d, History::Approach, &Observables::ALL).unwrap();
    let g = model
        .state(d, History::Approach, &Observables::ALL)
        .unwrap();
    assert_eq!(s.evaluations, 0);
    assert!(g.load().unwrap() > 0.0);
    assert_eq!(s.deviation_from(&g)[..3], [None; 3]);
    // Summits in range: a z-score.
    let d = 3.0 * SIGMA;
    let s = mc.state(d, History::Approach, &Observables::ALL).unwrap();
    let g = model
        .state(d, History::Approach, &Observables::ALL)
        .unwrap();
    assert!(s.deviation_from(&g)[0].unwrap().abs() < 5.0);
}
