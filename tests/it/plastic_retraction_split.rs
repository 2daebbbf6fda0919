//! GW retraction over elastic-plastic summits splits its
//! quadrature at the summit whose elastic unloading curve has just lost
//! contact (`AsperityLaw::contact_loss_peaks`): the integrand's kink there
//! (load `~ x^(3/2)`, radius `~ x^(1/2)`) no longer has to be found by
//! bisection. The same law without the hook (a wrapper forwarding
//! everything else) gives the same totals to the tolerance with more
//! evaluations; the split is what brings the 1000-point plastic curve at
//! rtol 1e-8 (`benches/plastic.rs`) towards its 20 ms goal.
use asperity::gw::{Accuracy, GwModel, Method, RoughSurface};
use asperity::heights::{Gaussian, HeightDistribution};
use asperity::law::plastic::build;
use asperity::law::{
    AsperityLaw, Branch, ContactState, Control, Instability, LawKernels, PowerForm,
};
use asperity::loading::{History, LoadingModel, Observables};
use asperity::material::plastic::{Plasticity, Variant};
use std::sync::Arc;

/// `inner` without its contact-loss breakpoint.
#[derive(Debug)]
struct NoPeak(Arc<dyn AsperityLaw>);

impl AsperityLaw for NoPeak {
    fn name(&self) -> &'static str {
        self.0.name()
    }
    fn state(&self, delta: f64, branch: Branch) -> ContactState {
        self.0.state(delta, branch)
    }
    fn load(&self, delta: f64, branch: Branch) -> f64 {
        self.0.load(delta, branch)
    }
    fn state_after(&self, delta: f64, delta_max: f64) -> ContactState {
        self.0.state_after(delta, delta_max)
    }
    fn load_after(&self, delta: f64, delta_max: f64) -> f64 {
        self.0.load_after(delta, delta_max)
    }
    fn remembers_maximum(&self) -> bool {
        self.0.remembers_maximum()
    }
    fn history_breakpoints(&self) -> Vec<f64> {
        self.0.history_breakpoints()
    }
    fn attach_interference(&self) -> f64 {
        self.0.attach_interference()
    }
    fn detach_interference(&self) -> f64 {
        self.0.detach_interference()
    }
    fn cutoff_interference(&self) -> f64 {
        self.0.cutoff_interference()
    }
    fn max_interference(&self) -> f64 {
        self.0.max_interference()
    }
    fn breakpoints(&self, branch: Branch) -> Vec<f64> {
        self.0.breakpoints(branch)
    }
    fn pull_off(&self, control: Control) -> Option<Instability> {
        self.0.pull_off(control)
    }
    fn zero_load_radius(&self) -> Option<f64> {
        self.0.zero_load_radius()
    }
    fn power_form(&self) -> Option<PowerForm> {
        self.0.power_form()
    }
}

impl LawKernels for NoPeak {}

/// Contacts on retraction from `closest` at `d` (m), independently of the
/// quadrature: which summits still touch is read from `state_after` alone
/// on a grid of heights (step 1e-3), each change located by bisection to
/// full precision, and the count is `N` times the Gaussian probability of
/// the touching intervals (the touching set need not be a suffix: the
/// Kogut–Etsion unloading span jumps at its breakpoints).
fn count_reference(law: &dyn AsperityLaw, surface: RoughSurface, closest: f64, d: f64) -> f64 {
    let sigma = surface.sigma;
    let touching = |s: f64| {
        law.state_after(sigma * s - d, sigma * s - closest)
            .in_contact()
    };
    let edge = |mut lo: f64, mut hi: f64| {
        let at_lo = touching(lo);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if !(mid > lo && mid < hi) {
                break;
            }
            if touching(mid) == at_lo {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        hi
    };
    let g = Gaussian::new();
    let (start, end) = (closest / sigma, 38.0);
    assert!(!touching(start));
    let (mut s, mut inside, mut from, mut total) = (start, false, 0.0, 0.0);
    while s < end {
        let next = (s + 1e-3).min(end);
        if touching(next) != inside {
            let x = edge(s, next);
            if inside {
                total += g.tail(from) - g.tail(x);
            } else {
                from = x;
            }
            inside = !inside;
        }
        s = next;
    }
    if inside {
        total += g.tail(from);
    }
    surface.summits() * total
}

#[test]
fn retraction_splits_at_the_contact_loss_summit() {
    let surface = RoughSurface::gold_microswitch();
    let sigma = surface.sigma;
    let rtol = 1e-8;
    let acc = Accuracy::new(rtol).unwrap().with_method(Method::Quadrature);
    let closest = -3.0 * sigma;
    let back = History::Retract { closest };
    for v in Variant::ALL {
        let law = build(v, surface.radius, 4.796e10, Plasticity::gold())
            .unwrap()
            .as_law();
        let plain: Arc<dyn LawKernels> = Arc::new(NoPeak(law.clone()));
        let model = |l: Arc<dyn LawKernels>| {
            GwModel::new(surface, Arc::new(Gaussian::new()), l)
                .unwrap()
                .with_accuracy(acc)
        };
        let (split, whole) = (model(law), model(plain));
        let (mut n_split, mut n_whole) = (0, 0);
        let mut worst_whole: f64 = 0.0;
        for i in 0..=60 {
            let d = closest + 9.0 * sigma * i as f64 / 60.0;
            let a = split.state(d, back, &Observables::ALL).unwrap();
            let b = whole.state(d, back, &Observables::ALL).unwrap();
            n_split += a.evaluations;
            n_whole += b.evaluations;
            // Load and area are continuous (kinks only): both agree.
            for (x, y) in [(a.load(), b.load()), (a.area(), b.area())] {
                let (x, y) = (x.unwrap(), y.unwrap());
                assert!(
                    (x - y).abs() <= 4.0 * rtol * y.abs().max(1e-300),
                    "{v:?} d/sigma {}: {x:e} vs {y:e}",
                    d / sigma
                );
            }
            // The count jumps where summits lose contact: without the
            // split the quadrature misplaces the jump and still reports
            // convergence (6.7e-7 off at d = 0, even at rtol 1e-12).
            let want = count_reference(split.law(), surface, closest, d);
            let got = a.count().unwrap();
            assert!(
                // Absolute floor: the quadrature stops where the Gaussian
                // tail is 1e-300 (`SUPPORT_EPS`), so it omits up to N 1e-300.
                (got - want).abs() <= 10.0 * rtol * want + 2.0 * surface.summits() * 1e-300,
                "{v:?} d/sigma {}: count {got:e} vs {want:e}",
                d / sigma
            );
            worst_whole = worst_whole.max((b.count().unwrap() - want).abs() / want);
        }
        eprintln!(
            "{}: {n_split} evaluations with the split, {n_whole} without; count error without \
             the split {worst_whole:.1e}",
            v.name()
        );
        assert!(
            (n_split as f64) < 0.85 * n_whole as f64,
            "{v:?}: {n_split} vs {n_whole}"
        );
    }
}
