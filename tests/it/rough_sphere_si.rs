//! The rough sphere in SI units on any Greenwood–Williamson surface: the
//! dimensionless solver's numbers through the SI layer, the remote
//! separation, the rigid-bulk limit of adhesive summits on approach and
//! retraction against an independent quadrature of the model's own local
//! states, hysteresis and pull-off, and the bump's resistance against the
//! closed form of the rigid limit.

use asperity::electrical::{Interaction, SpotResistance, Spreading};
use asperity::gw::{GwModel, RoughSurface};
use asperity::heights::{Gaussian, HeightDistribution};
use asperity::law::plastic::KogutEtsion;
use asperity::law::{Hertz, Jkr, LawKernels};
use asperity::loading::{hysteresis_energy_to, History, LoadingModel, LoadingProgram, Observables};
use asperity::material::plastic::Plasticity;
use asperity::numeric::quadrature::{integrate, QuadOptions};
use asperity::roughsphere::units::greenwood_tripp_mu;
use asperity::roughsphere::{
    BumpElectrics, GreenwoodTripp, RoughSphere, SolverOptions, SphereProfile, SphereQuery,
};
use std::f64::consts::PI;
use std::sync::Arc;

/// A gold switch bump: R = 5 um on summits of 1 um, 1 per um^2.
const R: f64 = 5e-6;
const BETA: f64 = 1e-6;
const ETA: f64 = 1e12;
const ESTAR: f64 = 44e9;

fn surface(sigma: f64) -> RoughSurface {
    RoughSurface::new(ETA, BETA, sigma, 1e-8).unwrap()
}

fn model(law: Arc<dyn LawKernels>, sigma: f64) -> GwModel {
    GwModel::new(surface(sigma), Arc::new(Gaussian::new()), law).unwrap()
}

fn sphere(law: Arc<dyn LawKernels>, sigma: f64, estar_bulk: f64) -> RoughSphere {
    RoughSphere::new(
        model(law, sigma),
        R,
        estar_bulk,
        SphereProfile::Paraboloid,
        SolverOptions::default(),
    )
    .unwrap()
}

/// Hertz summits on Gaussian heights in SI give Greenwood–Tripp's numbers
/// times the units, and the remote separation search lands on the state
/// whose `d - w(0)` is the asked separation.
#[test]
fn si_layer_matches_greenwood_tripp() {
    let sigma = 5e-9;
    let s = sphere(Arc::new(Hertz::new(BETA, ESTAR).unwrap()), sigma, ESTAR);
    let mu = greenwood_tripp_mu(ETA, sigma, R, BETA);
    assert!((s.mu() - mu).abs() < 1e-15 * mu);
    let u = s.units();
    let gt = GreenwoodTripp::new(mu)
        .unwrap()
        .state(-1.0, &[0.7])
        .unwrap();
    let q = SphereQuery {
        radii: vec![0.7 * u.length()],
        ..Default::default()
    };
    let st = s.sphere_state_central(-sigma, &q).unwrap();
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
    assert!(rel(st.load.value, gt.load.value * u.load()) < 1e-9);
    assert!(
        rel(
            st.central_deflection.value,
            gt.central_deflection.value * sigma
        ) < 1e-9
    );
    assert!(
        rel(
            st.pressure[0].pressure.value,
            gt.pressure[0].p.value * u.pressure()
        ) < 1e-9
    );
    assert!(st.converged && st.warnings.is_empty(), "{:?}", st.warnings);
    // remote separation: the approach of distant points
    let sep = st.separation;
    assert!(rel(sep, -sigma - st.central_deflection.value) < 1e-12);
    let back = s.sphere_state(sep, History::Approach, &q).unwrap();
    assert!(
        (back.central_separation + sigma).abs() < 1e-9 * sigma,
        "{}",
        back.central_separation
    );
    // the LoadingModel view gives the same load
    let lm = s.state(sep, History::Approach, &Observables::LOAD).unwrap();
    assert!(rel(lm.load().unwrap(), st.load.value) < 1e-9);
}

/// `int_d^inf p(h) dh` (m Pa) of the model's local pressure on approach, or
/// on retraction after the closest separation `closest` (m) of the sphere's
/// apex: a radius where the gap is `h` came as close as `h - d + closest`.
fn rigid_integral(m: &GwModel, d: f64, closest: Option<f64>, sigma: f64) -> f64 {
    let per_area = 1.0 / m.surface().nominal_area;
    let f = |h: f64| {
        let history = match closest {
            None => History::Approach,
            Some(c) => History::Retract { closest: h - d + c },
        };
        m.state(h, history, &Observables::LOAD)
            .unwrap()
            .load()
            .unwrap()
            * per_area
    };
    let top = sigma * Gaussian::new().numerical_support(1e-18).1;
    // split where the retraction's attached summits end
    let mut opts = QuadOptions::relative(1e-10);
    opts.max_intervals = 2000;
    let q = integrate(f, d, top + 2.0 * sigma, &opts);
    assert!(q.converged);
    q.value
}

/// A rigid bulk (E* 1e6 times the summits'): the sphere's load is
/// `2 pi R int_d^inf p(h) dh` on approach and on retraction, JKR summits
/// included, against the quadrature of the model's own local states (no
/// mesh, no Newton, no extrapolation).
#[test]
fn rigid_bulk_limit_of_adhesive_summits() {
    let sigma = 1e-9;
    let jkr: Arc<dyn LawKernels> = Arc::new(Jkr::new(BETA, ESTAR, 0.5).unwrap());
    let s = sphere(jkr.clone(), sigma, 1e6 * ESTAR);
    let m = model(jkr, sigma).with_accuracy(asperity::gw::Accuracy::new(1e-11).unwrap());
    let closest = -0.5 * sigma;
    let q = SphereQuery::default();
    let a = s.sphere_state_central(closest, &q).unwrap();
    let exact = 2.0 * PI * R * rigid_integral(&m, closest, None, sigma);
    // bulk deformation ~1e-6 of the asperities' (E* ratio)
    assert!(
        (a.load.value - exact).abs() < 1e-5 * exact.abs(),
        "{} vs {exact}",
        a.load.value
    );
    let d = 0.8 * sigma;
    let r = s
        .sphere_state(
            d,
            History::Retract {
                closest: a.separation,
            },
            &q,
        )
        .unwrap();
    let exact_r = 2.0 * PI * R * rigid_integral(&m, r.central_separation, Some(closest), sigma);
    let approach_here = 2.0 * PI * R * rigid_integral(&m, r.central_separation, None, sigma);
    assert!(
        exact_r < approach_here,
        "retraction holds on: {exact_r} vs {approach_here}"
    );
    assert!(
        (r.load.value - exact_r).abs() < 1e-5 * exact_r.abs(),
        "{} vs {exact_r}",
        r.load.value
    );
}

/// Elastic-plastic summits (Kogut–Etsion, yield 0.3 GPa) with history: in
/// the rigid-bulk limit the retraction load after flattening, against the
/// same independent quadrature; it falls below the approach load.
#[test]
fn rigid_bulk_limit_of_plastic_summits() {
    let sigma = 5e-9;
    let plastic = Plasticity::new(3e8, None, 0.42).unwrap();
    let law: Arc<dyn LawKernels> = Arc::new(KogutEtsion::new(BETA, ESTAR, plastic).unwrap());
    assert!(law.remembers_maximum());
    let s = sphere(law.clone(), sigma, 1e6 * ESTAR);
    let m = model(law, sigma).with_accuracy(asperity::gw::Accuracy::new(1e-11).unwrap());
    let closest = -sigma;
    let q = SphereQuery::default();
    let a = s.sphere_state_central(closest, &q).unwrap();
    let exact = 2.0 * PI * R * rigid_integral(&m, closest, None, sigma);
    assert!(
        (a.load.value - exact).abs() < 1e-5 * exact,
        "{} vs {exact}",
        a.load.value
    );
    let r = s
        .sphere_state(
            -0.5 * sigma,
            History::Retract {
                closest: a.separation,
            },
            &q,
        )
        .unwrap();
    let exact_r = 2.0 * PI * R * rigid_integral(&m, r.central_separation, Some(closest), sigma);
    let approach_here = 2.0 * PI * R * rigid_integral(&m, r.central_separation, None, sigma);
    assert!(exact_r < approach_here);
    assert!(
        (r.load.value - exact_r).abs() < 1e-5 * exact_r.abs(),
        "{} vs {exact_r}",
        r.load.value
    );
}

/// Adhesive summits on a deformable bump: a tensile pull-off on retraction
/// and energy lost per cycle.
#[test]
fn adhesive_bump_has_pull_off_and_hysteresis() {
    let sigma = 1e-9;
    let s = sphere(Arc::new(Jkr::new(BETA, ESTAR, 0.5).unwrap()), sigma, ESTAR);
    let closest = -sigma;
    let pull = s.pull_off(closest, f64::INFINITY, 12).unwrap().unwrap();
    assert!(pull.load < 0.0 && pull.separation > closest, "{pull:?}");
    let program = LoadingProgram::new(3.0 * sigma, closest, 8).unwrap();
    let w = hysteresis_energy_to(&s, &program, 1e-3).unwrap();
    assert!(w > 0.0, "{w}");
}

/// The bump's parallel spot conductance in the rigid limit:
/// `G = 2 pi R int_d^inf g(h) dh` with Maxwell spots on Hertz summits,
/// `g = (2/rho) eta sqrt(beta sigma) F_1/2(h/sigma)`, so
/// `G = 2 pi R sigma (2/rho) eta sqrt(beta sigma) F_3/2(d/sigma)/(3/2)`;
/// the count `2 pi R sigma eta F_1`; the interaction term is positive (a
/// dense surface, 50 summits per um^2, so that there are tens of spots).
#[test]
fn bump_resistance_in_the_rigid_limit() {
    let sigma = 5e-9;
    let eta = 5e13;
    let m = GwModel::new(
        RoughSurface::new(eta, BETA, sigma, 1e-8).unwrap(),
        Arc::new(Gaussian::new()),
        Arc::new(Hertz::new(BETA, ESTAR).unwrap()),
    )
    .unwrap();
    let s = RoughSphere::new(
        m,
        R,
        1e6 * ESTAR,
        SphereProfile::Paraboloid,
        SolverOptions::default(),
    )
    .unwrap();
    let rho = 2.2e-8;
    let q = SphereQuery {
        area_and_count: true,
        electrics: Some(BumpElectrics {
            spot: SpotResistance::same_metal(Spreading::Maxwell, rho, None).unwrap(),
            interaction: Interaction::Greenwood,
        }),
        ..Default::default()
    };
    let d = -2.0 * sigma;
    let st = s.sphere_state_central(d, &q).unwrap();
    let f32 = Gaussian::new().moment_above(1.5, d / sigma);
    let g = 2.0 * PI * R * sigma * (2.0 / rho) * eta * (BETA * sigma).sqrt() * f32 / 1.5;
    let res = st.resistance.unwrap();
    assert!(
        (1.0 / res.parallel - g).abs() < 1e-5 * g,
        "{} vs {g}",
        1.0 / res.parallel
    );
    let contacts = st.contacts.unwrap().value;
    let f1 = Gaussian::new().moment_above(1.0, d / sigma);
    let n = 2.0 * PI * R * sigma * eta * f1;
    assert!((contacts - n).abs() < 1e-5 * n, "{contacts} vs {n}");
    assert!(n > 10.0, "{n}");
    assert!(res.interaction.unwrap() > 0.0 && res.resistance.value > res.parallel);
}
