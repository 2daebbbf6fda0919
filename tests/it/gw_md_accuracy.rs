//! the fast path of the Maugis–Dugdale curve (Chebyshev
//! table to 1e-7, load-only integrand evaluated a panel at a time,
//! `LawKernels::load_near_batch`) meets its tolerance. The curve of
//! `benches/gw.rs` (gold microswitch, lambda = 1, `6 sigma` to `0`, both
//! legs) at rtol 1e-6 against the same model at rtol 1e-11: every state's
//! load, area and count within `rtol` of the integral of the magnitude of
//! its integrand (the scale the tolerance is measured against, computed
//! here as a fourth observable `|P|`), and within its own reported error
//! estimate up to the reference's tolerance.
use asperity::gw::{Accuracy, GwModel, RoughSurface};
use asperity::heights::Gaussian;
use asperity::law::interpolated::InterpolatedLaw;
use asperity::law::{ContactState, LawKernels, Maugis};
use asperity::loading::{
    Curve, LoadingModel, LoadingProgram, Observable, Observables, PerAsperity, State,
};
use asperity::material::{contact_modulus, Material};
use std::sync::Arc;

/// `|P|` per asperity: its total is the load's scale `int |P| phi`.
#[derive(Debug)]
struct LoadMagnitude;

impl PerAsperity for LoadMagnitude {
    fn name(&self) -> &str {
        "load_magnitude_N"
    }

    fn value(&self, state: &ContactState) -> f64 {
        state.load.abs()
    }
}

fn model() -> GwModel {
    let s = RoughSurface::gold_microswitch();
    let g = Material::gold();
    let exact: Arc<dyn LawKernels> =
        Arc::new(Maugis::new(s.radius, contact_modulus(&g, &g), 0.5, 1.0).unwrap());
    let table = InterpolatedLaw::new(
        exact.clone(),
        exact.cutoff_interference(),
        40.0 * s.sigma,
        1e-7,
    )
    .unwrap();
    GwModel::new(s, Arc::new(Gaussian::new()), Arc::new(table)).unwrap()
}

fn curve(rtol: f64, obs: &Observables) -> Curve {
    let s = RoughSurface::gold_microswitch();
    let program = LoadingProgram::new(6.0 * s.sigma, 0.0, 250).unwrap();
    model()
        .with_accuracy(Accuracy::new(rtol).unwrap())
        .curve(&program, obs)
        .unwrap()
}

fn states(c: &Curve) -> impl Iterator<Item = (&'static str, &State)> {
    c.approach
        .iter()
        .map(|s| ("approach", s))
        .chain(c.retract.iter().map(|s| ("retract", s)))
}

#[test]
fn md_curve_at_rtol_1e6_is_within_rtol_of_the_rtol_1e11_curve() {
    const RTOL: f64 = 1e-6;
    const REF_RTOL: f64 = 1e-11;
    let full = Observables::ALL
        .with(Observable::Custom(Arc::new(LoadMagnitude)))
        .unwrap();
    let reference = curve(REF_RTOL, &full);
    let magnitude_slot = full
        .slot(&Observable::Custom(Arc::new(LoadMagnitude)))
        .map_or(3, |k| k);
    // The planner's fast path (load only) and every observable.
    for obs in [Observables::LOAD, Observables::ALL] {
        let fast = curve(RTOL, &obs);
        let mut worst = [0.0f64; 3];
        for ((leg, got), (_, want)) in states(&fast).zip(states(&reference)) {
            assert_eq!(got.separation, want.separation);
            // Scales: int |P| phi for the load; area and count integrands
            // are >= 0, so their own totals.
            let scale = [
                want.totals.get(magnitude_slot).unwrap(),
                want.area().unwrap(),
                want.count().unwrap(),
            ];
            for k in 0..3 {
                let Some(v) = got.totals.get(k) else {
                    continue;
                };
                let err = (v - want.totals.get(k).unwrap()).abs();
                let estimate = got.totals.error(k).unwrap();
                assert!(
                    err <= RTOL * scale[k],
                    "{leg} d = {:e} m, slot {k}: {v:e} off by {err:e} > rtol * {:e}",
                    got.separation,
                    scale[k]
                );
                // The estimate is honest, up to the reference's own error.
                assert!(
                    err <= estimate + 10.0 * REF_RTOL * scale[k],
                    "{leg} d = {:e} m, slot {k}: error {err:e} above its estimate {estimate:e}",
                    got.separation
                );
                if scale[k] > 0.0 {
                    worst[k] = worst[k].max(err / (RTOL * scale[k]));
                }
            }
        }
        // Both legs were compared; the load is always computed. Measured:
        // the worst load error is about 1e-3 of the tolerance.
        eprintln!(
            "worst error / (rtol scale), load, area, count: {:.2e} {:.2e} {:.2e}",
            worst[0], worst[1], worst[2]
        );
        assert!(worst[0] > 0.0 && worst[0] <= 1.0, "{worst:?}");
    }
}
