//! `LoadingModel::pull_off` with a far start: the issue reported a
//! plausible `start = 1e-2 m` giving -14.3 uN instead of -78.5 uN with no
//! warning. The search samples up to `min(start, interaction onset)` and
//! refines by golden section; for a law felt everywhere (Bradley's
//! Lennard-Jones tail: infinite onset) the samples are 156 um apart and the
//! refinement still finds the minimum. This guards that the pull-off does
//! not depend on how far the start is, for long- and short-range laws.
use asperity::gw::{GwModel, RoughSurface};
use asperity::heights::{Gaussian, HeightDistribution, TruncatedGaussian};
use asperity::law::LawKind;
use asperity::loading::LoadingModel;
use asperity::material::AsperityContact;
use std::sync::Arc;

#[test]
fn a_far_start_finds_the_same_pull_off() {
    let c = AsperityContact::gold_microswitch();
    // The gold switch surface: eta = 1e12 m^-2, R = 1 um, sigma = 5 nm,
    // 100 um x 100 um.
    let surface = RoughSurface::new(1e12, 1e-6, 5e-9, 1e-8).unwrap();
    // Bradley (rigid spheres: the Lennard-Jones tail, felt far out) needs
    // heights bounded above.
    let truncated: Arc<dyn HeightDistribution> = Arc::new(TruncatedGaussian::new(4.0).unwrap());
    for (kind, heights) in [
        (LawKind::Bradley, truncated),
        (
            LawKind::Maugis,
            Arc::new(Gaussian::new()) as Arc<dyn HeightDistribution>,
        ),
        (LawKind::Jkr, Arc::new(Gaussian::new())),
    ] {
        let law = Arc::from(kind.build(&c).unwrap());
        let m = GwModel::new(surface, heights, law).unwrap();
        let closest = 5e-9;
        // The reference: evenly sampled over 60 nm (12 sigma), where the
        // whole adhesive range lies, with 400 samples.
        let near = m.pull_off(closest, 65e-9, 400).unwrap().unwrap();
        for start in [1e-6, 1e-4, 1e-2] {
            let far = m.pull_off(closest, start, 64).unwrap().unwrap();
            // Both refined by golden section to the separation tolerance:
            // the loads agree to the model's tolerance.
            assert!(
                (far.load / near.load - 1.0).abs() < 1e-6,
                "{kind:?} start {start:e}: {:e} vs {:e} N",
                far.load,
                near.load
            );
        }
    }
}
