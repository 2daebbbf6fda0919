//! the rough-surface pull-off is searched within the
//! loading program, not up to the interaction onset. The reference is the
//! model's own retraction curve on a fine grid of the program (a load the
//! flat never feels cannot be its pull-off).
use asperity::gw::{Accuracy, GwModel, RoughSurface};
use asperity::heights::Gaussian;
use asperity::law::Maugis;
use asperity::loading::{History, LoadingModel, Observables};
use std::sync::Arc;

fn model(lambda: f64) -> GwModel {
    let s = RoughSurface::gold_microswitch();
    let law = Maugis::new(s.radius, 1.0e11, 0.5, lambda).unwrap();
    GwModel::new(s, Arc::new(Gaussian::new()), Arc::new(law))
        .unwrap()
        .with_accuracy(Accuracy::new(1e-8).unwrap())
}

/// Retraction loads (N) on `n` separations of `[closest, start]`.
fn retraction_loads(m: &GwModel, closest: f64, start: f64, n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let d = closest + (start - closest) * i as f64 / (n - 1) as f64;
            let p = m
                .state(d, History::Retract { closest }, &Observables::LOAD)
                .unwrap()
                .load()
                .unwrap();
            (d, p)
        })
        .collect()
}

#[test]
fn no_tensile_load_inside_the_program_means_no_pull_off() {
    // lambda = 1e-3 (DMT-like): a deep, short program stays compressive.
    let m = model(1e-3);
    let sigma = m.surface().sigma;
    let (closest, start) = (-2.0 * sigma, -sigma);
    let loads = retraction_loads(&m, closest, start, 41);
    assert!(loads.iter().all(|&(_, p)| p > 0.0), "{loads:?}");
    // Up to the onset there is a tensile load (what the old search found).
    let anywhere = m.pull_off(closest, f64::INFINITY, 64).unwrap().unwrap();
    assert!(anywhere.load < 0.0 && anywhere.separation > start);
    assert_eq!(m.pull_off(closest, start, 64).unwrap(), None);
}

#[test]
fn the_pull_off_lies_in_the_program_and_is_its_most_tensile_load() {
    // lambda = 1e-3: tensile from h ~ 1.3, most tensile at the program's
    // end; lambda = 1: tensile only beyond h ~ 6, inside an 8-sigma program.
    for (lambda, top) in [(1e-3, 2.0), (1e-3, 8.0), (1.0, 8.0)] {
        let m = model(lambda);
        let sigma = m.surface().sigma;
        let (closest, start) = (0.0, top * sigma);
        let p = m.pull_off(closest, start, 64).unwrap().unwrap();
        assert!(p.separation >= closest && p.separation <= start, "{p:?}");
        let grid = retraction_loads(&m, closest, start, 201);
        let sampled = grid.iter().map(|&(_, p)| p).fold(f64::INFINITY, f64::min);
        // Refined minimum: at least as tensile as any grid sample (to the
        // quadrature tolerance).
        assert!(
            p.load <= sampled + 1e-7 * sampled.abs(),
            "{lambda}: {p:?} vs {sampled}"
        );
    }
    let m = model(1.0);
    assert!(m.pull_off(0.0, f64::NAN, 64).is_err());
    // lambda = 1, 2-sigma program: every retraction load is compressive.
    let sigma = m.surface().sigma;
    let grid = retraction_loads(&m, 0.0, 2.0 * sigma, 41);
    assert!(grid.iter().all(|&(_, p)| p > 0.0), "{grid:?}");
    assert_eq!(m.pull_off(0.0, 2.0 * sigma, 64).unwrap(), None);
}
