//! Monte Carlo checks against exact expectations and the GW integral, on
//! GW's exponential heights (`phi(s) = e^-s`, `s >= 0`; the full
//! distributions are tested in `tests/`).
//!
//! Statistical bounds: a total is accepted within 5 standard errors of its
//! expectation. For a normal estimator a false failure has probability
//! 5.7e-7 per comparison, so the few hundred comparisons here fail by
//! accident with probability < 1e-4 (and the seeds are fixed, so a pass is
//! reproducible); the "wrong integral" tests show the bound has power.

use super::*;
use crate::error::Error;
use crate::gw::{Accuracy, GwModel, Method, RoughSurface};
use crate::heights::{Exponential, Gaussian};
use crate::law::RadiusScaling;
use crate::law::{AsperityLaw, Bradley, Branch, Hertz, Jkr, LawKernels, LawKind};
use crate::loading::{Curve, History, LoadingModel, LoadingProgram, Observables, State};
use crate::material::{Adhesion, AsperityContact};
use std::sync::Arc;

pub(super) const R: f64 = 1e-6;
pub(super) const SIGMA: f64 = 5e-9;
pub(super) const E_STAR: f64 = 4.8e10;

/// `n` summits of radius [`R`] with GW's exponential heights of scale
/// [`SIGMA`], drawn with `seed`.
pub(super) fn population(n: usize, seed: u64) -> Arc<Population> {
    let spec = PopulationSpec::new(n, SIGMA, RadiusSpec::Fixed(R), seed).unwrap();
    Arc::new(Population::sample(&spec, &Exponential::new()).unwrap())
}

fn hertz() -> SummitLaw {
    SummitLaw::scaled(
        Arc::new(Hertz::new(R, E_STAR).unwrap()),
        R,
        RadiusScaling::MAUGIS,
    )
    .unwrap()
}

/// Soft and sticky: strong hysteresis (as in the GW tests).
fn jkr() -> SummitLaw {
    SummitLaw::scaled(
        Arc::new(Jkr::new(R, 1e9, 0.5).unwrap()),
        R,
        RadiusScaling::MAUGIS,
    )
    .unwrap()
}

/// The GW model of `n` summits of the same surface (integrated by
/// quadrature in [`acc`], independent of the exponential's closed forms).
fn gw(n: usize, law: &SummitLaw) -> GwModel {
    let surface = RoughSurface::new(n as f64, R, SIGMA, 1.0).unwrap();
    GwModel::new(
        surface,
        Arc::new(Exponential::new()),
        Arc::from(law_arc(law)),
    )
    .unwrap()
}

fn law_arc(law: &SummitLaw) -> Box<dyn LawKernels> {
    // Rebuild by name: the tests only use Hertz and JKR at R.
    match law.law().name() {
        "hertz" => Box::new(Hertz::new(R, E_STAR).unwrap()),
        "jkr" => Box::new(Jkr::new(R, 1e9, 0.5).unwrap()),
        other => panic!("{other}"),
    }
}

fn acc() -> Accuracy {
    Accuracy::new(1e-10)
        .unwrap()
        .with_method(Method::Quadrature)
}

fn values(s: &State) -> [f64; 3] {
    [s.load().unwrap(), s.area().unwrap(), s.count().unwrap()]
}

fn gw_values(s: &State) -> [f64; 3] {
    [s.load().unwrap(), s.area().unwrap(), s.count().unwrap()]
}

// ---------------------------------------------------------------- sampling

#[test]
fn sample_is_sorted_reproducible_and_seed_dependent() {
    let a = population(10_000, 7);
    let b = population(10_000, 7);
    let c = population(10_000, 8);
    assert_eq!(a, b);
    assert_ne!(a.heights(), c.heights());
    assert!(a.heights().is_sorted());
    assert!(a.heights()[0] > 0.0);
    assert!(a.radii().is_none());
    assert_eq!(a.radius(17), R);
}

#[test]
fn sampled_heights_have_the_distribution() {
    // Exponential: mean 1, variance 1 (standardised). Kolmogorov–Smirnov
    // distance below 1.95/sqrt(N) (the 0.1% critical value).
    let n = 100_000;
    let p = population(n, 3);
    let s: Vec<f64> = p.heights().iter().map(|z| z / SIGMA).collect();
    let mean = s.iter().sum::<f64>() / n as f64;
    assert!((mean - 1.0).abs() < 5.0 / (n as f64).sqrt(), "{mean}");
    let mut ks: f64 = 0.0;
    for (i, &x) in s.iter().enumerate() {
        let f = 1.0 - (-x).exp();
        ks = ks
            .max((f - i as f64 / n as f64).abs())
            .max((f - (i + 1) as f64 / n as f64).abs());
    }
    assert!(ks < 1.95 / (n as f64).sqrt(), "KS {ks}");
    // The sample maximum of N exponentials is ln N + Gumbel: within
    // [ln N - 3, ln N + 10] with probability > 1 - 1e-4.
    let top = *s.last().unwrap();
    let ln_n = (n as f64).ln();
    assert!(top > ln_n - 3.0 && top < ln_n + 10.0, "{top}");
}

#[test]
fn summits_drawn_above_a_height_are_the_full_draws_highest() {
    // Cut inside the first sampling block, across blocks and below every
    // summit; fixed and lognormal radii: the kept heights and radii are
    // the full draw's highest, bit for bit, and the rest only counted.
    for radius in [RadiusSpec::Fixed(R), lognormal(R, 0.3)] {
        let spec = spec(10_000, SIGMA, radius).with_seed(5);
        let full = Population::sample(&spec, &Gaussian::new()).unwrap();
        for cut in [2.5, -0.3, -9.0] {
            let above = Population::sample_above(&spec, &Gaussian::new(), cut * SIGMA).unwrap();
            let kept = above.len();
            let want = full.heights().iter().filter(|&&z| z >= cut * SIGMA).count();
            assert_eq!(kept, want, "cut {cut}");
            assert_eq!(above.omitted(), 10_000 - kept);
            let tail = &full.heights()[10_000 - kept..];
            assert!(tail
                .iter()
                .zip(above.heights())
                .all(|(a, b)| a.to_bits() == b.to_bits()));
            if let Some(r) = full.radii() {
                assert_eq!(above.radii().unwrap(), &r[10_000 - kept..]);
            }
        }
        // Above every summit: the highest alone.
        let top = Population::sample_above(&spec, &Gaussian::new(), 100.0 * SIGMA).unwrap();
        assert_eq!(top.heights(), &full.heights()[9_999..]);
        // A NaN bound is refused, naming it; -inf keeps every summit.
        let e = Population::sample_above(&spec, &Gaussian::new(), f64::NAN).unwrap_err();
        assert_eq!(e.field(), Some("min_height"));
        let all = Population::sample_above(&spec, &Gaussian::new(), f64::NEG_INFINITY).unwrap();
        assert_eq!(all, full);
    }
}

#[test]
fn the_tail_of_a_billion_summits_is_drawn_at_the_tails_cost() {
    // N = 1e9 Gaussian summits above 5 sigma: the number kept is
    // Binomial(N, Q(5)), mean 286.65 (Q(5) = 2.8665157e-7), variance about
    // the same; over 40 seeds the mean count is within 4 standard errors,
    // and every kept summit is above the cut (the cut's margin aside).
    let q5 = 2.866_515_718_791_939e-7;
    let n = 1_000_000_000usize;
    let mut total = 0usize;
    for seed in 1..=40 {
        let spec = spec(n, SIGMA, RadiusSpec::Fixed(R)).with_seed(seed);
        let p = Population::sample_above(&spec, &Gaussian::new(), 5.0 * SIGMA).unwrap();
        assert_eq!(p.len() + p.omitted(), n);
        assert!(
            p.heights()[0] >= 5.0 * SIGMA * (1.0 - 1e-9),
            "{}",
            p.heights()[0]
        );
        total += p.len();
    }
    let mean = total as f64 / 40.0;
    let expect = n as f64 * q5;
    assert!(
        (mean - expect).abs() < 4.0 * (expect / 40.0).sqrt(),
        "{mean} vs {expect}"
    );
}

#[test]
fn lognormal_radii_have_their_moments() {
    let n = 100_000;
    let (median, log_std) = (2e-6, 0.4);
    let spec = PopulationSpec::new(n, SIGMA, RadiusSpec::LogNormal { median, log_std }, 1).unwrap();
    let p = Population::sample(&spec, &Exponential::new()).unwrap();
    let r = p.radii().unwrap();
    let logs: Vec<f64> = r.iter().map(|x| (x / median).ln()).collect();
    let m = logs.iter().sum::<f64>() / n as f64;
    let v = logs.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (n - 1) as f64;
    assert!(m.abs() < 5.0 * log_std / (n as f64).sqrt(), "{m}");
    // var of the sample variance of a normal: 2 s^4 / (N - 1).
    let sd_v = (2.0 / (n - 1) as f64).sqrt() * log_std * log_std;
    assert!((v - log_std * log_std).abs() < 5.0 * sd_v, "{v}");
    assert_eq!(p.reference_radius(), median);
    // log_std = 0 is the fixed radius.
    let spec0 = PopulationSpec::new(
        100,
        SIGMA,
        RadiusSpec::LogNormal {
            median,
            log_std: 0.0,
        },
        1,
    )
    .unwrap();
    assert!(Population::sample(&spec0, &Exponential::new())
        .unwrap()
        .radii()
        .is_none());
}

#[test]
fn populations_are_identical_for_one_and_two_threads() {
    let run = |threads: usize| {
        crate::test_threads::on_threads(threads, || {
            let spec = PopulationSpec::new(
                50_000,
                SIGMA,
                RadiusSpec::LogNormal {
                    median: R,
                    log_std: 0.3,
                },
                11,
            )
            .unwrap();
            let pop = Arc::new(Population::sample(&spec, &Exponential::new()).unwrap());
            let mc = MonteCarlo::new(pop.clone(), jkr()).unwrap();
            let prog = LoadingProgram::new(8.0 * SIGMA, -SIGMA, 30).unwrap();
            let path: Vec<f64> = (0..40).map(|k| SIGMA * (3.0 - 0.1 * k as f64)).collect();
            let seq = mc.sequence(&path, &Observables::ALL).unwrap();
            (pop, mc.curve(&prog, &Observables::ALL).unwrap(), seq)
        })
    };
    let (p1, c1, s1) = run(1);
    let (p2, c2, s2) = run(2);
    assert_eq!(p1, p2);
    assert_eq!(s1, s2);
    // Bitwise: compare the bit patterns, not just values.
    let bits = |c: &Curve| -> Vec<u64> {
        c.approach
            .iter()
            .chain(&c.retract)
            .flat_map(|s| {
                values(s)
                    .into_iter()
                    .chain((0..3).map(|i| s.totals.error(i).unwrap()))
                    .map(f64::to_bits)
            })
            .collect()
    };
    assert_eq!(bits(&c1), bits(&c2));
}

// ---------------------------------------------------------------- summation

#[test]
fn sum_equals_brute_force_and_skips_out_of_range_summits() {
    let pop = population(30_000, 5);
    let mc = MonteCarlo::new(pop.clone(), jkr()).unwrap();
    let law = Jkr::new(R, 1e9, 0.5).unwrap();
    let closest = -0.5 * SIGMA;
    for d in [-0.5 * SIGMA, 0.3 * SIGMA, 2.0 * SIGMA, 6.0 * SIGMA] {
        for (history, brute) in [
            (
                History::Approach,
                Box::new(|z: f64| law.state(z - d, Branch::Approach)) as Box<dyn Fn(f64) -> _>,
            ),
            (
                History::Retract { closest },
                Box::new(|z: f64| law.state_after(z - d, z - closest)),
            ),
        ] {
            let s = mc.state(d, history, &Observables::ALL).unwrap();
            let (mut p, mut a, mut c, mut touched) = (0.0, 0.0, 0.0, 0usize);
            for &z in pop.heights() {
                let st = brute(z);
                p += st.load;
                a += st.area();
                c += f64::from(u8::from(st.in_contact()));
                if z - d >= law.cutoff_interference() {
                    touched += 1;
                }
            }
            let v = values(&s);
            assert!(
                (v[0] - p).abs() <= 1e-12 * p.abs().max(1e-30),
                "{d} {v:?} {p}"
            );
            assert!((v[1] - a).abs() <= 1e-12 * a.max(1e-30));
            assert_eq!(v[2], c);
            assert_eq!(s.evaluations, touched);
            if d > 3.0 * SIGMA {
                // JKR reaches 2 sigma below contact; the rest is skipped.
                assert!(touched < pop.len() / 10, "{touched}");
            }
        }
    }
}

#[test]
fn lognormal_radii_use_the_law_of_each_radius() {
    // The scaled reference law against a law built for every summit.
    let spec = PopulationSpec::new(
        3000,
        SIGMA,
        RadiusSpec::LogNormal {
            median: R,
            log_std: 0.5,
        },
        9,
    )
    .unwrap();
    let pop = Arc::new(Population::sample(&spec, &Exponential::new()).unwrap());
    let contact = AsperityContact::new(R, 1e9, Adhesion::new(0.5, 3e-10).unwrap()).unwrap();
    for kind in [LawKind::Hertz, LawKind::Dmt, LawKind::Jkr] {
        let mc =
            MonteCarlo::new(pop.clone(), SummitLaw::from_kind(kind, &contact).unwrap()).unwrap();
        let (d, closest) = (0.5 * SIGMA, -0.2 * SIGMA);
        let s = mc
            .state(d, History::Retract { closest }, &Observables::ALL)
            .unwrap();
        let (mut p, mut a) = (0.0, 0.0);
        for (i, &z) in pop.heights().iter().enumerate() {
            let c = AsperityContact::new(pop.radius(i), 1e9, contact.adhesion).unwrap();
            let law = kind.build(&c).unwrap();
            let st = law.state_after(z - d, z - closest);
            p += st.load;
            a += st.area();
        }
        let v = values(&s);
        // powf and cbrt round differently from the direct build: ~1e-13.
        assert!((v[0] - p).abs() <= 1e-11 * p.abs(), "{kind:?} {} {p}", v[0]);
        assert!((v[1] - a).abs() <= 1e-11 * a, "{kind:?} {} {a}", v[1]);
    }
}

#[test]
fn hertz_population_converges_to_gw_and_a_wrong_integral_is_detected() {
    // Several seeds at N = 1e5; separations from deep (every summit in
    // contact) to the tail. Each total within 5 SE of GW (quadrature to
    // 1e-10, negligible); a GW value 1% off is rejected in deep contact,
    // where the relative SE of the load is 0.12% (a 1% error is ~8 SE).
    let n = 100_000;
    let law = hertz();
    let model = gw(n, &law);
    for seed in 1..=4 {
        let mc = MonteCarlo::new(population(n, seed), law.clone()).unwrap();
        for h in [-3.0, 0.0, 1.0, 3.0] {
            let d = h * SIGMA;
            let s = mc.state(d, History::Approach, &Observables::ALL).unwrap();
            let g = model
                .clone()
                .with_accuracy(acc())
                .state(d, History::Approach, &Observables::ALL)
                .unwrap();
            let (v, e) = (values(&s), gw_values(&g));
            for k in 0..3 {
                // Every summit in contact: the count is exact (SE 0).
                let bound = 5.0 * s.totals.error(k).unwrap() + 1e-9 * e[k];
                assert!(
                    (v[k] - e[k]).abs() < bound,
                    "seed {seed} h {h} output {k}: {} vs {}, SE {}",
                    v[k],
                    e[k],
                    s.totals.error(k).unwrap()
                );
            }
            if h == -3.0 {
                let wrong = (v[0] - 1.01 * e[0]) / s.totals.error(0).unwrap();
                assert!(
                    wrong.abs() > 5.0,
                    "seed {seed}: 1% error not seen, z = {wrong}"
                );
                assert!(s.totals.error(0).unwrap() / v[0] < 2e-3);
            }
        }
    }
}

#[test]
fn jkr_population_hysteresis_matches_gw_retraction() {
    let n = 100_000;
    let law = jkr();
    let model = gw(n, &law);
    let program = LoadingProgram::new(6.0 * SIGMA, -0.5 * SIGMA, 14).unwrap();
    let acc = Accuracy::new(1e-9).unwrap();
    for seed in [21, 22] {
        let mc = MonteCarlo::new(population(n, seed), law.clone()).unwrap();
        let c = mc.curve(&program, &Observables::ALL).unwrap();
        let g = model
            .clone()
            .with_accuracy(acc)
            .curve(&program, &Observables::ALL)
            .unwrap();
        let mut compared = 0;
        for (m, e) in c
            .approach
            .iter()
            .zip(&g.approach)
            .chain(c.retract.iter().zip(&g.retract))
        {
            // Only where the CLT applies: expected contacts >= 20.
            if e.count().unwrap() < 20.0 {
                continue;
            }
            let (v, w) = (values(m), gw_values(e));
            for k in 0..3 {
                let z = (v[k] - w[k]) / (m.totals.error(k).unwrap() + e.totals.error(k).unwrap());
                assert!(
                    z.abs() < 5.0,
                    "seed {seed} d {} output {k}: z = {z}",
                    m.separation
                );
            }
            compared += 1;
        }
        assert!(compared >= 16, "{compared}");
        // Hysteresis is real: retraction more tensile, energy lost > 0.
        let w_mc = c.hysteresis_energy().unwrap();
        let w_gw = g.hysteresis_energy().unwrap();
        assert!(w_mc > 0.0);
        assert!((w_mc / w_gw - 1.0).abs() < 0.05, "{w_mc} {w_gw}");
        assert!(c.sampled_pull_off().unwrap().load < 0.0);
    }
}

#[test]
fn lognormal_hertz_matches_the_radius_averaged_integral() {
    // Radii independent of heights: E[P] = E[(R/R0)^(1/2)] P_GW(R0),
    // E[A] = E[R/R0] A_GW(R0), with E[rho^q] = exp(q^2 s^2 / 2).
    let n = 100_000;
    let s = 0.5;
    let spec = PopulationSpec::new(
        n,
        SIGMA,
        RadiusSpec::LogNormal {
            median: R,
            log_std: s,
        },
        4,
    )
    .unwrap();
    let mc = MonteCarlo::new(
        Arc::new(Population::sample(&spec, &Exponential::new()).unwrap()),
        hertz(),
    )
    .unwrap();
    let model = gw(n, &hertz());
    for h in [-2.0, 0.5] {
        let st = mc
            .state(h * SIGMA, History::Approach, &Observables::ALL)
            .unwrap();
        let g = model
            .clone()
            .with_accuracy(acc())
            .state(h * SIGMA, History::Approach, &Observables::ALL)
            .unwrap();
        let expect = [
            g.load().unwrap() * (s * s / 8.0).exp(),
            g.area().unwrap() * (s * s / 2.0).exp(),
            g.count().unwrap(),
        ];
        let v = values(&st);
        for k in 0..3 {
            let bound = 5.0 * st.totals.error(k).unwrap() + 1e-9 * expect[k];
            assert!((v[k] - expect[k]).abs() < bound, "h {h} output {k}");
        }
        // Ignoring the radius spread would be detected in deep contact.
        if h < 0.0 {
            let z = (v[1] - g.area().unwrap()) / st.totals.error(1).unwrap();
            assert!(z.abs() > 5.0, "{z}");
        }
    }
}

#[test]
fn standard_error_matches_the_spread_over_seeds() {
    // 40 seeds of N = 2000: the spread of the totals matches the reported SE
    // (ratio of variances within the 99.99% chi-square band for 39 dof,
    // [0.39, 2.0]).
    let n = 2000;
    let d = 0.5 * SIGMA;
    let (mut sum, mut sq, mut se2) = (0.0, 0.0, 0.0);
    let seeds = 40;
    for seed in 0..seeds {
        let mc = MonteCarlo::new(population(n, 1000 + seed), hertz()).unwrap();
        let s = mc.state(d, History::Approach, &Observables::LOAD).unwrap();
        let p = s.load().unwrap();
        sum += p;
        sq += p * p;
        se2 += s.totals.error(0).unwrap().powi(2);
    }
    let k = seeds as f64;
    let var = (sq - sum * sum / k) / (k - 1.0);
    let ratio = var / (se2 / k);
    assert!(ratio > 0.39 && ratio < 2.0, "{ratio}");
}

#[test]
fn unrequested_outputs_are_none_and_single_summit_has_no_error() {
    let mc = MonteCarlo::new(population(10, 1), hertz()).unwrap();
    let s = mc
        .state(0.0, History::Approach, &Observables::LOAD)
        .unwrap();
    assert!(s.load().is_some() && s.area().is_none() && s.count().is_none());
    let one = Population::from_summits(vec![1e-9], Radii::Fixed(R)).unwrap();
    let mc = MonteCarlo::new(Arc::new(one), hertz()).unwrap();
    let s = mc.state(0.0, History::Approach, &Observables::ALL).unwrap();
    assert!(s.load().unwrap() > 0.0);
    // One summit: the standard error is undefined (None, not NaN).
    assert_eq!(s.totals.error(0), None);
}

// ---------------------------------------------------------------- bad input

#[test]
fn bad_population_specs_name_the_field() {
    let ok = RadiusSpec::Fixed(R);
    let cases: Vec<(PopulationSpec, &str)> = vec![
        (spec(0, SIGMA, ok), "summits"),
        (spec(MAX_SUMMITS + 1, SIGMA, ok), "summits"),
        (spec(10, f64::NAN, ok), "sigma"),
        (spec(10, 0.0, ok), "sigma"),
        (spec(10, -1e-9, ok), "sigma"),
        (spec(10, f64::INFINITY, ok), "sigma"),
        (spec(10, SIGMA, RadiusSpec::Fixed(0.0)), "radius"),
        (spec(10, SIGMA, RadiusSpec::Fixed(f64::NAN)), "radius"),
        (spec(10, SIGMA, lognormal(-1e-6, 0.1)), "radius_median"),
        (spec(10, SIGMA, lognormal(R, -0.1)), "radius_log_std"),
        (spec(10, SIGMA, lognormal(R, f64::NAN)), "radius_log_std"),
        (
            spec(10, SIGMA, lognormal(R, f64::INFINITY)),
            "radius_log_std",
        ),
    ];
    for (s, field) in cases {
        let e = PopulationSpec::new(s.summits, s.sigma, s.radius, s.seed).unwrap_err();
        assert_eq!(e.field(), Some(field), "{s:?}");
        // `sample` validates too (fields are public).
        assert_eq!(
            Population::sample(&s, &Exponential::new())
                .unwrap_err()
                .field(),
            Some(field)
        );
    }
    let huge = RoughSurface::new(1e12, R, SIGMA, 1e-2).unwrap();
    assert_eq!(
        PopulationSpec::from_surface(&huge, 0).unwrap_err().field(),
        Some("summits")
    );
    let tiny = RoughSurface::new(1.0, R, SIGMA, 0.1).unwrap();
    assert_eq!(
        PopulationSpec::from_surface(&tiny, 0).unwrap_err().field(),
        Some("summits")
    );
    let gold = PopulationSpec::from_surface(&RoughSurface::gold_microswitch(), 0).unwrap();
    assert_eq!(gold.summits, 10_000);
}

fn spec(summits: usize, sigma: f64, radius: RadiusSpec) -> PopulationSpec {
    PopulationSpec {
        summits,
        sigma,
        radius,
        seed: 0,
    }
}

impl PopulationSpec {
    fn with_seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }
}

fn lognormal(median: f64, log_std: f64) -> RadiusSpec {
    RadiusSpec::LogNormal { median, log_std }
}

#[test]
fn bad_summit_lists_name_the_field() {
    let e = Population::from_summits(vec![], Radii::Fixed(R)).unwrap_err();
    assert_eq!(e.field(), Some("heights"));
    let e = Population::from_summits(vec![0.0, f64::NAN], Radii::Fixed(R)).unwrap_err();
    assert_eq!(e.field(), Some("heights[1]"));
    let e = Population::from_summits(vec![0.0], Radii::Fixed(-R)).unwrap_err();
    assert_eq!(e.field(), Some("radius"));
    let e = Population::from_summits(vec![0.0, 1.0], Radii::PerSummit(vec![R])).unwrap_err();
    assert_eq!(e.field(), Some("radii"));
    let e = Population::from_summits(vec![0.0, 1.0], Radii::PerSummit(vec![R, f64::INFINITY]))
        .unwrap_err();
    assert_eq!(e.field(), Some("radii[1]"));
    // Given summits are sorted, radii kept with their heights.
    let p = Population::from_summits(vec![2.0, 1.0], Radii::PerSummit(vec![R, 2.0 * R])).unwrap();
    assert_eq!(p.heights(), &[1.0, 2.0]);
    assert_eq!(p.radii().unwrap(), &[2.0 * R, R]);
}

#[test]
fn bad_evaluation_input_names_the_field() {
    let mc = MonteCarlo::new(population(100, 1), hertz()).unwrap();
    for d in [f64::NAN, f64::INFINITY] {
        let e = mc
            .state(d, History::Approach, &Observables::ALL)
            .unwrap_err();
        assert_eq!(e.field(), Some("separation"));
    }
    let e = mc
        .state(0.0, History::Retract { closest: 1e-9 }, &Observables::ALL)
        .unwrap_err();
    assert_eq!(e.field(), Some("separation"));
    let e = mc
        .state(
            0.0,
            History::Retract { closest: f64::NAN },
            &Observables::ALL,
        )
        .unwrap_err();
    assert_eq!(e.field(), Some("closest_separation"));
    // A law without radius scaling cannot serve other radii.
    let fixed = SummitLaw::fixed(Arc::new(Hertz::new(R, E_STAR).unwrap()), R).unwrap();
    let spec = PopulationSpec::new(10, SIGMA, lognormal(R, 0.2), 0).unwrap();
    let varied = Arc::new(Population::sample(&spec, &Exponential::new()).unwrap());
    let e = MonteCarlo::new(varied, fixed.clone()).unwrap_err();
    assert!(matches!(e, Error::Invalid { .. }));
    assert_eq!(e.field(), Some("radius"));
    let other = SummitLaw::fixed(Arc::new(Hertz::new(2.0 * R, E_STAR).unwrap()), 2.0 * R).unwrap();
    assert_eq!(
        MonteCarlo::new(population(10, 0), other)
            .unwrap_err()
            .field(),
        Some("radius")
    );
    assert!(MonteCarlo::new(population(10, 0), fixed).is_ok());
    assert_eq!(
        SummitLaw::scaled(
            Arc::new(Hertz::new(R, E_STAR).unwrap()),
            0.0,
            RadiusScaling::MAUGIS
        )
        .unwrap_err()
        .field(),
        Some("reference_radius")
    );
    // Rigid Bradley: a summit past z0 has infinite load -> error, not inf.
    let b = SummitLaw::scaled(
        Arc::new(Bradley::new(R, 0.5, 3e-10).unwrap()),
        R,
        RadiusScaling::RIGID,
    )
    .unwrap();
    let mc = MonteCarlo::new(population(100, 1), b).unwrap();
    assert!(mc.state(1e-6, History::Approach, &Observables::ALL).is_ok());
    let e = mc
        .state(0.0, History::Approach, &Observables::ALL)
        .unwrap_err();
    assert_eq!(e.field(), Some("separation"));
}

// ---------------------------------------------------------------- sequences

/// `mc.sequence` down the program's separations and back up equals
/// `mc.curve` on the program, state for state (bit for bit); returns the
/// curve's approach leg.
fn assert_sequence_is_the_curve(mc: &MonteCarlo, program: &LoadingProgram) -> Vec<State> {
    let curve = mc.curve(program, &Observables::ALL).unwrap();
    let seps = program.separations();
    let path: Vec<f64> = seps.iter().rev().chain(seps.iter()).copied().collect();
    let seq = mc.sequence(&path, &Observables::ALL).unwrap();
    let expect: Vec<&State> = curve.approach.iter().rev().chain(&curve.retract).collect();
    assert_eq!(seq.len(), expect.len());
    for (a, b) in seq.iter().zip(expect) {
        assert_eq!(a, b);
    }
    curve.approach
}

#[test]
fn sequence_reproduces_the_curve_bit_for_bit() {
    let mc = MonteCarlo::new(population(20_000, 6), jkr()).unwrap();
    let program = LoadingProgram::new(5.0 * SIGMA, -0.5 * SIGMA, 25).unwrap();
    assert_sequence_is_the_curve(&mc, &program);
}

/// Hertz at its own radius is summed in one fused pass
/// (`Accumulator::add_root_monomials`); the sequence path sums
/// `law.state` summit by summit through the chunk buffers: the same bits,
/// also with a last lane group that is not full (20,003 summits).
#[test]
fn fused_hertz_sums_equal_the_summit_by_summit_path() {
    for n in [20_000, 20_003, 5] {
        let mc = MonteCarlo::new(population(n, 7), hertz()).unwrap();
        let program = LoadingProgram::new(5.0 * SIGMA, -1.5 * SIGMA, 25).unwrap();
        let approach = assert_sequence_is_the_curve(&mc, &program);
        assert!(
            approach.iter().any(|s| s.load().unwrap() > 0.0),
            "{n} summits"
        );
    }
}

/// Brute force with the threshold rule, summit by summit: with `a_i`,
/// `b_i` its attach and detach interferences, the set of attached heights
/// after separations `d_1..d_t` is `z >= z*(t)`, `z*(t) = min(max(z*(t-1),
/// d_t + b_i), d_t + a_i)`, `z*(0) = +inf` (derived independently of the
/// flag update in `sequence`).
fn brute_sequence(
    pop: &Population,
    kind: LawKind,
    contact: &AsperityContact,
    path: &[f64],
) -> Vec<[f64; 3]> {
    let laws: Vec<Box<dyn LawKernels>> = (0..pop.len())
        .map(|i| {
            let c = AsperityContact::new(pop.radius(i), contact.contact_modulus, contact.adhesion)
                .unwrap();
            kind.build(&c).unwrap()
        })
        .collect();
    let mut thresholds = vec![f64::INFINITY; pop.len()];
    path.iter()
        .map(|&d| {
            let mut v = [0.0; 3];
            for (i, &z) in pop.heights().iter().enumerate() {
                let law = &laws[i];
                let (a, b) = (law.attach_interference(), law.detach_interference());
                thresholds[i] = thresholds[i].max(d + b).min(d + a);
                let branch = if z >= thresholds[i] {
                    Branch::Retract
                } else {
                    Branch::Approach
                };
                let st = law.state(z - d, branch);
                v[0] += st.load;
                v[1] += st.area();
                v[2] += f64::from(u8::from(st.in_contact()));
            }
            v
        })
        .collect()
}

#[test]
fn general_sequences_match_the_threshold_rule_for_every_radius() {
    // Partial retraction, re-approach, deeper approach, full retraction.
    let legs = [
        (4.0, -0.5),
        (-0.5, 1.0),
        (1.0, 0.2),
        (0.2, 2.5),
        (2.5, -1.0),
        (-1.0, 5.0),
    ];
    let mut path = Vec::new();
    for (from, to) in legs {
        for k in 0..12 {
            path.push(SIGMA * (from + (to - from) * k as f64 / 11.0));
        }
    }
    let contact = AsperityContact::new(R, 1e9, Adhesion::new(0.5, 3e-10).unwrap()).unwrap();
    for radius in [RadiusSpec::Fixed(R), lognormal(R, 0.4)] {
        let spec = PopulationSpec::new(3000, SIGMA, radius, 12).unwrap();
        let pop = Arc::new(Population::sample(&spec, &Exponential::new()).unwrap());
        let mc = MonteCarlo::new(
            pop.clone(),
            SummitLaw::from_kind(LawKind::Jkr, &contact).unwrap(),
        )
        .unwrap();
        let seq = mc.sequence(&path, &Observables::ALL).unwrap();
        let brute = brute_sequence(&pop, LawKind::Jkr, &contact, &path);
        let mut differs_from_approach = 0;
        for (k, (s, e)) in seq.iter().zip(&brute).enumerate() {
            let v = values(s);
            assert!(
                (v[0] - e[0]).abs() <= 1e-11 * e[0].abs().max(1e-15),
                "{radius:?} step {k}: {v:?} {e:?}"
            );
            assert!((v[1] - e[1]).abs() <= 1e-11 * e[1].max(1e-30));
            assert_eq!(v[2], e[2], "{radius:?} step {k}");
            let fresh = mc
                .state(path[k], History::Approach, &Observables::LOAD)
                .unwrap();
            if fresh.load().unwrap() != v[0] {
                differs_from_approach += 1;
            }
        }
        // The history matters on most steps (the test has teeth).
        assert!(
            differs_from_approach > path.len() / 2,
            "{differs_from_approach}"
        );
    }
    assert_eq!(
        MonteCarlo::new(population(10, 0), jkr())
            .unwrap()
            .sequence(&[0.0, f64::NAN], &Observables::ALL)
            .unwrap_err()
            .field(),
        Some("separations[1]")
    );
}

#[test]
fn scaled_states_multiply_totals_and_errors() {
    let mc = MonteCarlo::new(population(1000, 2), hertz()).unwrap();
    let s = mc
        .state(0.2 * SIGMA, History::Approach, &Observables::ALL)
        .unwrap();
    let t = s.scaled(10.0);
    assert_eq!(t.load().unwrap(), 10.0 * s.load().unwrap());
    assert_eq!(t.count().unwrap(), 10.0 * s.count().unwrap());
    assert_eq!(
        t.totals.error(1).unwrap(),
        10.0 * s.totals.error(1).unwrap()
    );
    assert_eq!(t.separation, s.separation);
    assert_eq!(t.evaluations, s.evaluations);
}

// ---------------------------------------------------------------- properties

mod properties {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        /// Any size (block boundaries included), scale and seed: heights
        /// finite, non-negative for the exponential, ascending, scaled by
        /// sigma, and reproducible.
        #[test]
        fn samples_are_sorted_finite_and_reproducible(
            n in 1usize..20_000,
            log_sigma in -12.0f64..-3.0,
            seed in any::<u64>(),
        ) {
            let sigma = 10f64.powf(log_sigma);
            let spec = PopulationSpec::new(n, sigma, RadiusSpec::Fixed(R), seed).unwrap();
            let p = Population::sample(&spec, &Exponential::new()).unwrap();
            prop_assert_eq!(p.len(), n);
            prop_assert!(p.heights().is_sorted());
            prop_assert!(p.heights().iter().all(|z| z.is_finite() && *z >= 0.0));
            // The largest of n exponentials is below ln(n) + 60 (tail e^-60).
            prop_assert!(*p.heights().last().unwrap() / sigma < (n as f64).ln() + 60.0);
            prop_assert_eq!(&p, &Population::sample(&spec, &Exponential::new()).unwrap());
        }

        /// The radius scaling is exact for Hertz, DMT and JKR over six
        /// decades of radius ratio: the rescaled reference law equals the
        /// law built at that radius, on both branches.
        #[test]
        fn radius_scaling_matches_a_law_built_for_the_radius(
            log_rho in -3.0f64..3.0,
            delta_bar in -1.0f64..20.0,
            which in 0usize..3,
        ) {
            let kind = [LawKind::Hertz, LawKind::Dmt, LawKind::Jkr][which];
            let contact = AsperityContact::new(R, 1e9, Adhesion::new(0.5, 3e-10).unwrap()).unwrap();
            let family = SummitLaw::from_kind(kind, &contact).unwrap();
            let rho = 10f64.powf(log_rho);
            let f = family.factors_for(rho * R).unwrap();
            let other = AsperityContact::new(rho * R, 1e9, contact.adhesion).unwrap();
            let direct = kind.build(&other).unwrap();
            // Interferences in the summit's own Maugis scale.
            let scale = other.scales().unwrap().interference;
            let delta = delta_bar * scale;
            for branch in [Branch::Approach, Branch::Retract] {
                let a = family.law().state(delta * f[0], branch);
                let b = direct.state(delta, branch);
                let (pa, pb) = (a.load * f[1], b.load);
                let (ra, rb) = (a.radius * f[2], b.radius);
                let ps = other.scales().unwrap().load;
                let rs = other.scales().unwrap().radius;
                prop_assert!((pa - pb).abs() <= 1e-9 * ps.max(pb.abs()), "{kind:?} {pa} {pb}");
                prop_assert!((ra - rb).abs() <= 1e-9 * rs.max(rb), "{kind:?} {ra} {rb}");
            }
        }

        /// Hertz totals fall as the flat retreats; the count never exceeds N;
        /// retraction after any closer approach equals approach (no hysteresis).
        #[test]
        fn hertz_totals_are_monotone_and_history_free(
            seed in any::<u64>(),
            h1 in -2.0f64..6.0,
            dh in 0.0f64..3.0,
        ) {
            let mc = MonteCarlo::new(population(2000, seed), hertz()).unwrap();
            let (d1, d2) = (h1 * SIGMA, (h1 + dh) * SIGMA);
            let s1 = mc.state(d1, History::Approach, &Observables::ALL).unwrap();
            let s2 = mc.state(d2, History::Approach, &Observables::ALL).unwrap();
            let (v1, v2) = (values(&s1), values(&s2));
            for k in 0..3 {
                prop_assert!(v2[k] <= v1[k]);
            }
            prop_assert!(v1[2] <= 2000.0);
            let back = mc.state(d2, History::Retract { closest: d1 }, &Observables::ALL).unwrap();
            prop_assert_eq!(values(&back), v2);
        }

        /// JKR: retraction is never less tensile than approach, summit by
        /// summit, hence in total (exact, no statistics).
        #[test]
        fn jkr_retraction_is_at_most_the_approach_load(
            seed in any::<u64>(),
            hc in -1.0f64..2.0,
            dh in 0.0f64..4.0,
        ) {
            let mc = MonteCarlo::new(population(2000, seed), jkr()).unwrap();
            let (closest, d) = (hc * SIGMA, (hc + dh) * SIGMA);
            let a = mc.state(d, History::Approach, &Observables::LOAD).unwrap().load().unwrap();
            let r = mc.state(d, History::Retract { closest }, &Observables::LOAD).unwrap().load().unwrap();
            prop_assert!(r <= a + 1e-12 * a.abs(), "{r} {a}");
        }
    }
}

#[test]
fn heights_do_not_depend_on_the_radius_spec_or_sigma() {
    let a = Population::sample(
        &spec(5000, SIGMA, RadiusSpec::Fixed(R)).with_seed(3),
        &Exponential::new(),
    )
    .unwrap();
    let b = Population::sample(
        &spec(5000, 2.0 * SIGMA, lognormal(R, 0.4)).with_seed(3),
        &Exponential::new(),
    )
    .unwrap();
    let c = Population::sample(
        &spec(5000, SIGMA, lognormal(R, 0.8)).with_seed(3),
        &Exponential::new(),
    )
    .unwrap();
    for i in 0..5000 {
        assert_eq!(2.0 * a.heights()[i], b.heights()[i]);
        // Same normal deviates: ln(R/median) doubles with the spread.
        let (lb, lc) = ((b.radius(i) / R).ln(), (c.radius(i) / R).ln());
        assert!((2.0 * lb - lc).abs() < 1e-12, "{lb} {lc}");
    }
    assert_eq!(a.heights(), c.heights());
}

#[test]
fn separation_for_load_reaches_the_target() {
    let mc = MonteCarlo::new(population(5000, 8), hertz()).unwrap();
    let full = mc
        .state(-SIGMA, History::Approach, &Observables::LOAD)
        .unwrap()
        .load()
        .unwrap();
    for target in [1e-3 * full, 0.5 * full, 3.0 * full] {
        let d = mc.separation_at_load(target, mc.top_height()).unwrap();
        let at = |d: f64| {
            mc.state(d, History::Approach, &Observables::LOAD)
                .unwrap()
                .load()
                .unwrap()
        };
        assert!(at(d) >= target);
        // Just beyond it the load is below the target.
        let step = 1e-9 * SIGMA;
        assert!(at(d + step) < target, "{} {}", at(d + step), target);
    }
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert_eq!(
            mc.separation_at_load(bad, mc.top_height())
                .unwrap_err()
                .field(),
            Some("max_load")
        );
    }
}

#[test]
fn deviation_from_gw_is_the_z_score() {
    let n = 20_000;
    let mc = MonteCarlo::new(population(n, 31), hertz()).unwrap();
    let model = gw(n, &hertz());
    let s = mc
        .state(0.4 * SIGMA, History::Approach, &Observables::LOAD)
        .unwrap();
    let g = model
        .clone()
        .with_accuracy(acc())
        .state(0.4 * SIGMA, History::Approach, &Observables::ALL)
        .unwrap();
    let z = s.deviation_from(&g);
    let expect = (s.load().unwrap() - g.load().unwrap())
        / s.totals.error(0).unwrap().hypot(g.totals.error(0).unwrap());
    assert_eq!(z[0], Some(expect));
    assert!(expect.abs() < 5.0);
    assert_eq!(z[1], None);
    // Deep contact: every summit touches, the count has no error.
    let s = mc
        .state(-SIGMA, History::Approach, &Observables::ALL)
        .unwrap();
    let g = model
        .clone()
        .with_accuracy(acc())
        .state(-SIGMA, History::Approach, &Observables::ALL)
        .unwrap();
    assert_eq!(s.totals.error(2).unwrap(), 0.0);
    assert!(s.deviation_from(&g)[0].is_some());
}
