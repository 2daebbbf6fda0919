//! The laws that call their retraction curves unimodal
//! (`LawKernels::retraction_minimum`) are checked on dense grids, and the
//! pull-off search that prunes separations with it finds exactly the
//! minimum of the full retraction curve (same bits), seed by seed.
//!
//! Unimodal: after `delta_max`, the load is non-increasing in the
//! interference below `delta_p` and non-decreasing above it, with
//! `f(delta_p)` its least value. On a grid of 4001 interferences from far
//! out of contact up to `delta_max`, every sample must obey both
//! monotonicities (to roundoff: 1e-12 of the largest load on the grid),
//! and no sample may fall below the stated minimum.

use asperity::heights::Gaussian;
use asperity::law::{Dmt, Hertz, Jkr, LawKernels, RetractionMinimum};
use asperity::loading::{LoadingModel, LoadingProgram, Observables};
use asperity::montecarlo::pull_off::{candidate_separations, realised_pull_off};
use asperity::montecarlo::{MonteCarlo, Population, PopulationSpec, RadiusSpec, SummitLaw};
use asperity::prelude::{build_plastic, AdhesivePlastic, Plasticity, Variant};
use asperity::sphere::{Shape, SolverOptions, SphereProblem};
use asperity::study::cache::CalibrationCache;
use std::sync::Arc;

const R: f64 = 1e-6;
const E_STAR: f64 = 4.8e10;
const W: f64 = 0.5;

fn adhesive_plastic(v: Variant) -> Arc<dyn LawKernels> {
    let law = build_plastic(v, R, E_STAR, Plasticity::gold()).unwrap();
    Arc::new(AdhesivePlastic::new(law.as_loading(), W).unwrap())
}

fn plastic(v: Variant) -> Arc<dyn LawKernels> {
    build_plastic(v, R, E_STAR, Plasticity::gold())
        .unwrap()
        .as_law()
}

/// Calibrated (full Lennard-Jones solver) laws, coarse tables: one
/// without hysteresis (mu = 0.5) and two with it.
fn calibrated() -> Vec<(String, Arc<dyn LawKernels>)> {
    let dir = std::env::temp_dir().join(format!("asperity-retr-min-{}", std::process::id()));
    let cache = CalibrationCache::new(&dir);
    [0.5, 1.0, 2.0]
        .iter()
        .map(|&mu| {
            let p = SphereProblem::new(mu, Shape::Paraboloid, SolverOptions::coarse()).unwrap();
            let law: Arc<dyn LawKernels> =
                Arc::new(cache.get_or_compute(&p).unwrap().law(R, E_STAR, W).unwrap());
            (format!("calibrated mu={mu}"), law)
        })
        .collect()
}

fn laws() -> Vec<(String, Arc<dyn LawKernels>)> {
    let mut v: Vec<(String, Arc<dyn LawKernels>)> = vec![
        ("hertz".into(), Arc::new(Hertz::new(R, E_STAR).unwrap())),
        ("jkr".into(), Arc::new(Jkr::new(R, E_STAR, W).unwrap())),
        ("dmt".into(), Arc::new(Dmt::new(R, E_STAR, W).unwrap())),
    ];
    for variant in [
        Variant::KogutEtsion,
        Variant::JacksonGreen,
        Variant::ChangEtsionBogy,
        Variant::ZhaoMaiettaChang,
    ] {
        v.push((format!("{variant:?}"), plastic(variant)));
        v.push((format!("{variant:?}+jkr"), adhesive_plastic(variant)));
    }
    v.extend(calibrated());
    v
}

#[test]
fn stated_minima_bound_dense_retraction_curves() {
    for (name, law) in laws() {
        // The interference scale: the JKR scale of the contact (~1 nm).
        let s = Jkr::new(R, E_STAR, W).unwrap().scales().interference;
        let mut answered = 0;
        for dm in [-0.5, 0.0, 0.3, 2.0, 20.0, 200.0, 2000.0] {
            let delta_max = dm * s;
            let Some(rm) = law.retraction_minimum(delta_max) else {
                continue;
            };
            answered += 1;
            let lo = -30.0 * s;
            let grid: Vec<f64> = (0..=4000)
                .map(|i| lo + (delta_max - lo) * i as f64 / 4000.0)
                .collect();
            let loads: Vec<f64> = grid
                .iter()
                .map(|&d| law.state_after(d, delta_max).load)
                .collect();
            let scale = loads.iter().fold(rm.load.abs(), |m, l| m.max(l.abs()));
            let tol = 1e-12 * scale;
            for (i, w) in grid.windows(2).enumerate() {
                let (a, b) = (loads[i], loads[i + 1]);
                if w[1] <= rm.interference {
                    assert!(
                        b <= a + tol,
                        "{name} dmax {dm}: rises below delta_p at {}",
                        w[0]
                    );
                }
                if w[0] >= rm.interference {
                    assert!(
                        b >= a - tol,
                        "{name} dmax {dm}: falls above delta_p at {}",
                        w[0]
                    );
                }
            }
            let least = loads.iter().copied().fold(f64::INFINITY, f64::min);
            assert!(
                least >= rm.load - tol,
                "{name} dmax {dm}: {least} < {}",
                rm.load
            );
            // Windows: the bound never exceeds the samples inside.
            for (i, j) in [(0, 4000), (100, 900), (2000, 2100), (3990, 4000)] {
                let b = rm.window_minimum(grid[i], loads[i], grid[j], loads[j]);
                let inside = loads[i..=j].iter().copied().fold(f64::INFINITY, f64::min);
                assert!(b <= inside + tol, "{name} dmax {dm}: window {i}..{j}");
            }
        }
        assert!(answered > 0, "{name} gives no retraction minimum");
    }
}

/// Laws that state a concave tail (`LawKernels::concave_tail`): below it
/// the load is concave in the interference on a dense grid from 1,000
/// interference scales out to the stated interference, on approach and on
/// retraction after any maximum (second differences at most roundoff);
/// the calibrated laws state one.
#[test]
fn stated_concave_tails_are_concave() {
    let s = Jkr::new(R, E_STAR, W).unwrap().scales().interference;
    let mut answered = 0;
    for (name, law) in laws() {
        let Some(top) = law.concave_tail() else {
            assert!(!name.starts_with("calibrated"), "{name} states no tail");
            continue;
        };
        answered += 1;
        // Geometric in the gap below the tail's top (the far field decays
        // like gap^-2): spacing fine where the load changes fast.
        let grid: Vec<f64> = (0..=4000)
            .map(|i| top - 1000.0 * s * (1e-6f64).powf(i as f64 / 4000.0))
            .collect();
        for dm in [f64::NEG_INFINITY, top, 0.0, 20.0 * s, 2000.0 * s] {
            let load = |d: f64| {
                if dm == f64::NEG_INFINITY {
                    law.state(d, asperity::law::Branch::Approach).load
                } else {
                    law.state_after(d, dm.max(d)).load
                }
            };
            let loads: Vec<f64> = grid.iter().map(|&d| load(d)).collect();
            let scale = loads.iter().fold(0.0f64, |m, l| m.max(l.abs()));
            for k in 1..grid.len() - 1 {
                let (x0, x1, x2) = (grid[k - 1], grid[k], grid[k + 1]);
                // The chord from x0 to x2 at x1 lies below the load.
                let t = (x1 - x0) / (x2 - x0);
                let chord = (1.0 - t) * loads[k - 1] + t * loads[k + 1];
                assert!(
                    loads[k] >= chord - 1e-12 * scale,
                    "{name} after {dm}: not concave at {x1}: {} < {chord}",
                    loads[k]
                );
            }
        }
    }
    assert!(answered >= 3, "{answered}");
}

#[test]
fn monotone_marker_bounds_by_the_lower_end() {
    let m = RetractionMinimum::MONOTONE;
    assert_eq!(m.window_minimum(-1.0, 0.0, 2.0, 5.0), 0.0);
    let p = RetractionMinimum {
        interference: 1.0,
        load: -3.0,
    };
    assert_eq!(p.window_minimum(0.0, -1.0, 2.0, 4.0), -3.0);
    assert_eq!(p.window_minimum(1.5, -2.0, 2.0, 4.0), -2.0);
    assert_eq!(p.window_minimum(-1.0, 0.0, 0.5, -1.0), -1.0);
}

/// The pruned pull-off is the full curve's least load, bit for bit, for
/// every law and 6 seeds; and it does skip separations.
#[test]
fn pruned_pull_off_equals_the_full_curve_minimum() {
    let program = LoadingProgram::new(25e-9, -5e-9, 200).unwrap();
    let mut pruned = 0usize;
    let mut total = 0usize;
    for (name, law) in laws() {
        let summit = SummitLaw::fixed(law.clone(), R).unwrap();
        for seed in 1..=6 {
            let spec = PopulationSpec::new(2000, 5e-9, RadiusSpec::Fixed(R), seed).unwrap();
            let pop = Population::sample(&spec, &Gaussian::new()).unwrap();
            let mc = MonteCarlo::new(Arc::new(pop), summit.clone()).unwrap();
            let curve = mc.curve(&program, &Observables::LOAD).unwrap();
            let want = curve
                .retract
                .iter()
                .filter_map(|s| s.load())
                .fold(0.0f64, f64::min);
            let got = realised_pull_off(&mc, &program, 1.0).unwrap();
            assert_eq!(
                got.to_bits(),
                want.to_bits(),
                "{name} seed {seed}: {got} vs {want}"
            );
            total += program.points;
            pruned += program.points - candidate_separations(&mc, &program).len();
        }
    }
    // Most separations are ruled out without being summed.
    assert!(pruned * 2 > total, "{pruned} of {total} pruned");
}

/// The bounds between coarse separations (`MonteCarlo::retraction_bounds`,
/// `RetractionBounds::lower_at`, the chord of the concave tail included)
/// are below the exact load at every program separation in between, for
/// every law, and the window bound below each of them.
#[test]
fn window_bounds_are_below_every_load_inside() {
    let program = LoadingProgram::new(25e-9, -5e-9, 200).unwrap();
    let all = program.separations();
    let coarse: Vec<usize> = (0..all.len()).step_by(10).chain([all.len() - 1]).collect();
    let at: Vec<f64> = coarse.iter().map(|&i| all[i]).collect();
    let mut chords = 0;
    for (name, law) in laws() {
        let summit = SummitLaw::fixed(law.clone(), R).unwrap();
        let spec = PopulationSpec::new(2000, 5e-9, RadiusSpec::Fixed(R), 3).unwrap();
        let pop = Population::sample(&spec, &Gaussian::new()).unwrap();
        let mc = MonteCarlo::new(Arc::new(pop), summit).unwrap();
        let Some(b) = mc.retraction_bounds(&at, program.closest) else {
            continue;
        };
        let loads = asperity::montecarlo::pull_off::retraction_loads(&mc, &program, 1.0).unwrap();
        let slack = 1e-9 * b.magnitude;
        for j in 0..coarse.len() - 1 {
            chords += usize::from(b.chord[j] != (0.0, 0.0));
            for i in coarse[j]..=coarse[j + 1] {
                let t = (all[i] - at[j]) / (at[j + 1] - at[j]);
                let exact = loads[i].1;
                assert!(
                    b.lower_at(j, t) <= exact + slack,
                    "{name} window {j} at {i}: {} > {exact}",
                    b.lower_at(j, t)
                );
                assert!(b.lower[j] <= b.lower_at(j, t) + slack, "{name} window {j}");
            }
        }
    }
    // The calibrated laws' far field is bounded by chords.
    assert!(chords > 0);
}

/// The per-summit history prepared once for many separations
/// (`prepare_after`, a plastic summit's unloading shape) gives every law's
/// states and retraction minima bit for bit as without it: interferences
/// below, at and above the peak, peaks out of contact, NaN.
#[test]
fn prepared_histories_give_the_same_bits() {
    let s = Jkr::new(R, E_STAR, W).unwrap().scales().interference;
    let peaks: Vec<f64> = [-0.5, 0.0, 0.3, 2.0, 20.0, 200.0, 2000.0, f64::NAN]
        .iter()
        .map(|x| x * s)
        .collect();
    for (name, law) in laws() {
        let mut delta = Vec::new();
        let mut delta_max = Vec::new();
        for &m in &peaks {
            for i in 0..=300 {
                delta.push((-40.0 + 2100.0 * i as f64 / 300.0) * s);
                delta_max.push(m);
            }
            delta.push(f64::NAN);
            delta_max.push(m);
        }
        let n = delta.len();
        let mut words = vec![[0.0; 4]; n];
        law.prepare_after(&delta_max, &mut words);
        let (mut l0, mut r0, mut l1, mut r1) =
            (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        law.state_batch(&delta, Some(&delta_max), &mut l0, &mut r0);
        law.state_batch_prepared(&delta, &delta_max, &words, &mut l1, &mut r1);
        let mut l2 = vec![0.0; n];
        let mut cursor = asperity::law::LawCursor::default();
        law.load_near_batch(&delta, Some(&delta_max), &mut l2, &mut cursor);
        // On approach both batches are the scalar law's `state`.
        let (mut l3, mut r3, mut l4) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        law.state_batch(&delta, None, &mut l3, &mut r3);
        law.load_near_batch(&delta, None, &mut l4, &mut cursor);
        for i in 0..n {
            let st = law.state(delta[i], asperity::law::Branch::Approach);
            assert_eq!(
                (l3[i].to_bits(), r3[i].to_bits(), l4[i].to_bits()),
                (st.load.to_bits(), st.radius.to_bits(), st.load.to_bits()),
                "{name} approach: delta {:e}",
                delta[i]
            );
        }
        for i in 0..n {
            // The scalar law is the reference of both batches.
            let st = law.state_after(delta[i], delta_max[i]);
            let want = (st.load.to_bits(), st.radius.to_bits());
            for (which, got) in [
                ("state_batch", (l0[i].to_bits(), r0[i].to_bits())),
                ("state_batch_prepared", (l1[i].to_bits(), r1[i].to_bits())),
                ("load_near_batch", (l2[i].to_bits(), want.1)),
            ] {
                assert_eq!(
                    got, want,
                    "{name} {which}: delta {:e}, delta_max {:e}",
                    delta[i], delta_max[i]
                );
            }
            let (a, b) = (
                law.retraction_minimum(delta_max[i]),
                law.retraction_minimum_prepared(delta_max[i], &words[i]),
            );
            assert_eq!(
                a.map(|m| (m.load.to_bits(), m.interference.to_bits())),
                b.map(|m| (m.load.to_bits(), m.interference.to_bits())),
                "{name}: retraction minimum after {:e}",
                delta_max[i]
            );
        }
        if law.prepares_history() {
            println!("{name}: prepared history checked on {n} states");
        }
    }
}
