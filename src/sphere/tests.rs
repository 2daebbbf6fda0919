//! Solver tests on coarse meshes (fast); the converged tables are in
//! docs/performance.md (`## Full sphere solver`).
use super::*;

fn paraboloid(mu: f64, o: SolverOptions) -> SphereFacts {
    SphereProblem::new(mu, Shape::Paraboloid, o)
        .unwrap()
        .facts()
        .unwrap()
}

/// mu -> 0 is the rigid Bradley sphere: pull-off `-2 pi w R` (within 1%;
/// the elastic correction at mu = 0.01 is ~5e-4).
#[test]
fn small_mu_gives_bradley() {
    let f = paraboloid(0.01, SolverOptions::default());
    let p = f.pull_off.load_bar;
    assert!((p + 2.0).abs() < 0.01 * 2.0, "{p}");
    assert!(f.jump_out.is_none() && f.jump_in.is_none());
}

/// Large mu tends to JKR (-1.5): monotone in mu, within 2% at mu = 5; jump-out
/// load and interference approach JKR's -5/6 and -0.9086.
#[test]
fn large_mu_tends_to_jkr() {
    let mut last = -2.0;
    for mu in [0.3, 1.0, 2.0, 5.0] {
        let p = paraboloid(mu, SolverOptions::coarse()).pull_off.load_bar;
        assert!(p > last && p < -1.5, "mu {mu}: {p} after {last}");
        last = p;
    }
    assert!((last + 1.5).abs() < 0.03, "{last}");
    let f = paraboloid(5.0, SolverOptions::coarse());
    let jo = f.jump_out.unwrap();
    assert!((jo.interference_bar - crate::law::jkr::JUMP_OUT_INTERFERENCE).abs() < 0.03);
    assert!((jo.load_bar - crate::law::jkr::JUMP_OUT_LOAD).abs() < 0.06);
    let a0 = f.zero_load_radius_bar.unwrap();
    assert!(
        (a0 - crate::law::jkr::ZERO_LOAD_RADIUS).abs() < 0.03,
        "{a0}"
    );
}

/// The S-curve at mu = 1: jump-in (local max of the approach) at a larger
/// central gap and interference than the jump-out (local min); the jump-out
/// load is above the load-controlled pull-off; approach and load are smooth
/// in H(0) with the analytic tangents matching finite differences.
#[test]
fn s_curve_at_mu_one() {
    let o = SolverOptions::coarse();
    let p = SphereProblem::new(1.0, Shape::Paraboloid, o).unwrap();
    let f = p.facts().unwrap();
    let (ji, jo) = (f.jump_in.unwrap(), f.jump_out.unwrap());
    assert!(ji.central_gap > jo.central_gap);
    assert!(ji.interference_bar > jo.interference_bar);
    assert!(jo.load_bar > f.pull_off.load_bar);
    assert!(ji.radius_bar == 0.0 && jo.radius_bar > 0.0);
    let curve = p.trace().unwrap();
    assert!(curve.len() > 30);
    assert!(curve.last().unwrap().load_bar >= o.max_load_bar);
    // unstable part exists: approach decreases while H(0) decreases
    assert!(curve.iter().any(|q| q.d_approach > 0.0));
    let mut checked = 0;
    for w in curve.windows(3) {
        let dh = w[2].central_gap - w[0].central_gap;
        // a mesh rebuilt in between shows as a jump of the arc speed
        // |d(P, alpha)/dH0| from one half-step to the next
        let speed = |a: &SpherePoint, b: &SpherePoint| {
            (b.arc - a.arc) / (b.central_gap - a.central_gap).abs()
        };
        let jump = speed(&w[1], &w[2]) / speed(&w[0], &w[1]);
        if dh.abs() > 1e-3
            || !(0.8..1.25).contains(&jump)
            || w[0].radius_bar.min(w[2].radius_bar) == 0.0 && w[1].radius_bar > 0.0
        {
            continue; // coarse steps or a remesh in between
        }
        let fd = (w[2].load_bar - w[0].load_bar) / dh;
        assert!(
            (fd - w[1].d_load).abs() < 0.05 * (1.0 + fd.abs()),
            "{fd} {}",
            w[1].d_load
        );
        checked += 1;
    }
    assert!(checked >= 10, "{checked}");
}

/// Pull-off changes by < 1e-3 between the coarse and default meshes at mu = 1.
#[test]
fn mesh_convergence_at_mu_one() {
    let coarse = paraboloid(1.0, SolverOptions::coarse()).pull_off.load_bar;
    let fine = paraboloid(1.0, SolverOptions::default()).pull_off.load_bar;
    assert!(((coarse - fine) / fine).abs() < 2e-3, "{coarse} {fine}");
}

/// A finite sphere (rho = R/z0) pulls off with less force than the paraboloid
/// and approaches it as rho grows (Greenwood 2009, fig. 6).
#[test]
fn true_sphere_below_paraboloid() {
    let o = SolverOptions::coarse();
    let para = paraboloid(1.0, o).pull_off.load_bar;
    let mut last = 0.0;
    for rho in [10.0, 100.0, 1e4] {
        let p = SphereProblem::new(1.0, Shape::Sphere { rho }, o)
            .unwrap()
            .pull_off()
            .unwrap()
            .load_bar;
        assert!(p < last && p > para, "rho {rho}: {p}");
        last = p;
    }
    assert!(((last - para) / para).abs() < 1e-3, "{last} {para}");
}

/// Rigid limit of the true sphere: integrating the Derjaguin force out to
/// `r = R` at contact gives `F = (2/rho)[(rho+1) (S0(1) - S0(1+rho)) -
/// (S1(1) - S1(1+rho))]`, `S0(h) = h^-8/3 - 4h^-2/3`, `S1(h) = (8/3)(h^-7/7 - 1/h)`
/// (-1.7671 at rho = 10, against -2 for the paraboloid).
#[test]
fn rigid_true_sphere_limit() {
    let rho: f64 = 10.0;
    let s0 = |h: f64| h.powi(-8) / 3.0 - 4.0 / (3.0 * h * h);
    let s1 = |h: f64| (8.0 / 3.0) * (h.powi(-7) / 7.0 - 1.0 / h);
    let exact = (2.0 / rho) * ((rho + 1.0) * (s0(1.0) - s0(1.0 + rho)) - (s1(1.0) - s1(1.0 + rho)));
    let p = SphereProblem::new(0.01, Shape::Sphere { rho }, SolverOptions::default())
        .unwrap()
        .pull_off()
        .unwrap()
        .load_bar;
    assert!(((p - exact) / exact).abs() < 2e-3, "{p} vs {exact}");
}

#[test]
fn profiles_show_contact_and_tension() {
    let p = SphereProblem::new(2.0, Shape::Paraboloid, SolverOptions::coarse()).unwrap();
    let prof = p.profile(0.99).unwrap();
    assert_eq!(prof.radius.len(), prof.gap.len());
    assert!((prof.gap[0] - 0.99).abs() < 1e-12);
    // compressive at the centre, tensile somewhere, maximum tension ~1.0264 mu
    assert!(prof.pressure[0] > 0.0);
    let min = prof.pressure.iter().cloned().fold(f64::INFINITY, f64::min);
    assert!(
        (-1.0264 * 2.0 * (1.0 + 1e-9)..-0.9 * 1.0264 * 2.0).contains(&min),
        "{min}"
    );
    assert!(prof.point.radius > 0.0);
    assert!(p.profile(0.1).is_err() && p.profile(f64::NAN).is_err());
}

#[test]
fn bad_inputs_name_the_field() {
    let o = SolverOptions::default();
    for (mu, shape, field) in [
        (0.0, Shape::Paraboloid, "mu"),
        (-1.0, Shape::Paraboloid, "mu"),
        (f64::NAN, Shape::Paraboloid, "mu"),
        (f64::INFINITY, Shape::Paraboloid, "mu"),
        (1e3, Shape::Paraboloid, "mu"),
        (100.5, Shape::Paraboloid, "mu"),
        (1.0, Shape::Sphere { rho: 9.0 }, "rho"),
        (20.0, Shape::Sphere { rho: 1999.0 }, "rho"),
        (1.0, Shape::Sphere { rho: f64::NAN }, "rho"),
        (1.0, Shape::Sphere { rho: -10.0 }, "rho"),
    ] {
        let e = SphereProblem::new(mu, shape, o).unwrap_err();
        assert_eq!(e.field(), Some(field), "{mu} {shape:?}");
    }
    for (opt, field) in [
        (
            SolverOptions {
                resolution: 0.0,
                ..o
            },
            "resolution",
        ),
        (
            SolverOptions {
                resolution: f64::NAN,
                ..o
            },
            "resolution",
        ),
        (SolverOptions { far_gap: 1.0, ..o }, "far_gap"),
        (
            SolverOptions {
                start_gap: 1.0,
                ..o
            },
            "start_gap",
        ),
        (
            SolverOptions {
                arc_step: -1.0,
                ..o
            },
            "arc_step",
        ),
        (SolverOptions { min_gap: 2.0, ..o }, "min_gap"),
        (
            SolverOptions {
                tolerance: 0.0,
                ..o
            },
            "tolerance",
        ),
        (
            SolverOptions {
                max_newton_iterations: 0,
                ..o
            },
            "max_newton_iterations",
        ),
    ] {
        let e = SphereProblem::new(1.0, Shape::Paraboloid, opt).unwrap_err();
        assert_eq!(e.field(), Some(field));
    }
}

/// Newton that cannot converge (one iteration from the rigid guess at a
/// central gap where the elastic sphere has deformed) is reported as
/// `NoConvergence`, promptly.
#[test]
fn failure_is_an_error_not_a_hang() {
    let o = SolverOptions {
        start_gap: 1.31,
        max_newton_iterations: 1,
        ..SolverOptions::coarse()
    };
    let t = std::time::Instant::now();
    let e = SphereProblem::new(1.0, Shape::Paraboloid, o)
        .unwrap()
        .facts()
        .unwrap_err();
    assert!(matches!(e, Error::NoConvergence { .. }), "{e}");
    assert!(t.elapsed().as_secs_f64() < 10.0);
}

/// continuation in the contact radius passes the (near-)fold of
/// the central gap where continuation in `H(0)` stopped (mu = 15-20): at
/// mu = 20 the trace goes through a part where `|dP/dH(0)|` exceeds 1000
/// and the pull-off lies between JKR's -1.5 and the mu = 10 value -1.5095
/// (measured -1.5033).
#[test]
fn radius_continuation_passes_the_central_gap_fold() {
    let p = SphereProblem::new(20.0, Shape::Paraboloid, SolverOptions::default()).unwrap();
    let curve = p.trace().unwrap();
    let steep = curve.iter().map(|q| q.d_load.abs()).fold(0.0f64, f64::max);
    assert!(steep > 1e3, "{steep}");
    let pull = p.facts().unwrap().pull_off.load_bar;
    assert!(pull > -1.5095 && pull < -1.5, "{pull}");
}

/// at mu = 10 (default mesh) the facts trace takes a bounded
/// number of points, factorises about once per point (the corrector runs
/// chord iterations on the previous point's factorisation) and assembles
/// few compliance matrices (rescaled views share them). Before solver
/// version 4 every Newton iteration factorised (4.7-6 s).
#[test]
fn mu_ten_work_is_bounded() {
    let p = SphereProblem::new(10.0, Shape::Paraboloid, SolverOptions::default()).unwrap();
    let mut tr = trace::Tracer::new(&p);
    let st = tr
        .run(0.08, |s| {
            let l = &s.last().unwrap().sol;
            l.load > 0.05 && l.radius > 0.0 && l.dt_load > 0.0
        })
        .unwrap();
    let n = st.len();
    assert!(n < 150, "{n} points");
    assert!(tr.factorisations < 4 * n, "{} for {n}", tr.factorisations);
    assert!(
        tr.newton_iterations < 10 * n,
        "{} for {n}",
        tr.newton_iterations
    );
    assert!(tr.meshes_built < 30, "{}", tr.meshes_built);
}
