//! Scenes end to end: every example scene parses, runs and matches direct
//! library calls; the planner's skips pay and cost nothing.

use asperity::gw::{Accuracy, GwModel, Method};
use asperity::law::LawKind;
use asperity::loading::{History, LoadingModel, Observables};
use asperity::study::scene::{build_contact, build_distribution, build_surface, LawName};
use asperity::study::{Plan, PlanMode, Scene};
use std::sync::Arc;

fn example(name: &str) -> Scene {
    let path = format!("{}/examples/scenes/{name}", env!("CARGO_MANIFEST_DIR"));
    Scene::from_toml(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn all_examples() -> Vec<String> {
    let dir = format!("{}/examples/scenes", env!("CARGO_MANIFEST_DIR"));
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|n| n.ends_with(".toml"))
        .collect();
    v.sort();
    v
}

#[test]
fn every_example_scene_runs_and_matches_library_calls() {
    let names = all_examples();
    assert!(names.len() >= 5, "{names:?}");
    for name in names {
        let scene = example(&name);
        if scene.surface.topography.is_some() {
            // A measured map: tests/surface_scene.rs checks it against a
            // direct sum over its summits.
            continue;
        }
        if scene.sphere.is_some() {
            // A rough sphere: tests/sphere_scene.rs checks it against the
            // library's RoughSphere (to 1e-9).
            continue;
        }
        let plan = Plan::new(&scene, PlanMode::Planned).unwrap();
        let res = plan.run().unwrap();
        // The same numbers straight from the library.
        let contact = build_contact(&scene).unwrap();
        // The calibrated law is tested against the solver in src/sphere.
        let law: Arc<dyn asperity::law::AsperityLaw> = match plan.law.source {
            LawName::Analytic(kind) => Arc::from(kind.build(&contact).unwrap()),
            _ => plan.law.law.clone(),
        };
        let model = GwModel::new(
            build_surface(&scene).unwrap(),
            build_distribution(&scene.surface).unwrap(),
            law,
        )
        .unwrap();
        let acc = Accuracy::new(scene.accuracy.rtol).unwrap();
        let closest = res.curve.program.closest;
        for k in [
            0,
            res.curve.approach.len() / 3,
            res.curve.approach.len() - 1,
        ] {
            for (leg, history) in [
                (&res.curve.approach, History::Approach),
                (&res.curve.retract, History::Retract { closest }),
            ] {
                let got = leg[k];
                let want = model
                    .clone()
                    .with_accuracy(acc)
                    .state(got.separation, history, &Observables::ALL)
                    .unwrap();
                for (g, w, asked, e) in [
                    (
                        got.load(),
                        want.load(),
                        scene.outputs.load,
                        want.totals.error(0).unwrap(),
                    ),
                    (
                        got.area(),
                        want.area(),
                        scene.outputs.area,
                        want.totals.error(1).unwrap(),
                    ),
                    (
                        got.count(),
                        want.count(),
                        scene.outputs.count,
                        want.totals.error(2).unwrap(),
                    ),
                ] {
                    if asked {
                        let (g, w) = (g.unwrap(), w.unwrap());
                        // The exact law, not the plan's table (if it made one):
                        // equal to the scene's rtol plus the error estimates.
                        let rtol = scene.accuracy.rtol;
                        let tol = 2.0 * e
                            + (0..3).filter_map(|i| got.totals.error(i)).sum::<f64>()
                            + rtol * w.abs();
                        assert!((g - w).abs() <= tol, "{name} {k}: {g} vs {w} (tol {tol})");
                    }
                }
            }
        }
        if scene.outputs.pull_off && scene.adhesion.w > 0.0 {
            // A stiff, rough surface may never go tensile: both say so.
            let direct = model
                .clone()
                .with_accuracy(acc)
                .pull_off(closest, res.curve.program.start, 64)
                .unwrap();
            match (res.pull_off, direct) {
                (Some(p), Some(d)) => {
                    let tol = scene.accuracy.rtol * d.load.abs();
                    assert!((p.load - d.load).abs() <= tol, "{name}: {p:?} vs {d:?}")
                }
                (None, None) => {}
                other => panic!("{name}: {other:?}"),
            }
        } else {
            assert!(res.pull_off.is_none(), "{name}");
        }
        if !scene.outputs.count {
            assert!(
                res.curve.approach.iter().all(|s| s.count().is_none()),
                "{name}"
            );
        }
    }
}

/// Relative difference of two optional outputs, against the larger
/// magnitude of the curve (adhesive loads cross zero).
fn worst_gap(a: &[Option<f64>], b: &[Option<f64>]) -> f64 {
    let scale = a
        .iter()
        .chain(b)
        .flatten()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    a.iter()
        .zip(b)
        .filter_map(|(x, y)| Some((x.as_ref()? - y.as_ref()?).abs() / scale))
        .fold(0.0, f64::max)
}

#[test]
fn planned_runs_do_less_work_and_agree_within_tolerance() {
    let (mut planned_evals, mut full_evals) = (0, 0);
    for name in ["hertz-exponential.toml", "soft-jkr.toml", "mems-gold.toml"] {
        let mut scene = example(name);
        // The planner's choice by one summit's error: with the surface-level
        // model error on, `auto` takes the full-solver law on mems-gold,
        // more work for a far more accurate pull-off (tests/model_error.rs).
        scene.accuracy.model_error = false;
        // Same separations for both runs.
        if scene.program.start_separation.is_none() {
            let p = Plan::new(&scene, PlanMode::Planned).unwrap();
            scene.program.start_separation = Some(p.start);
        }
        let planned = Plan::new(&scene, PlanMode::Planned).unwrap();
        let full = Plan::new(&scene, PlanMode::EverythingOn).unwrap();
        let (rp, rf) = (planned.run().unwrap(), full.run().unwrap());
        // Closed forms and cheaper laws: no more work, counted in law
        // evaluations (wall-clock seconds reversed on a loaded CI machine;
        // soft-jkr keeps its law and only drops observables).
        planned_evals += rp.evaluations;
        full_evals += rf.evaluations;
        assert!(
            rp.evaluations <= rf.evaluations,
            "{name}: planned {} evals vs everything-on {} evals",
            rp.evaluations,
            rf.evaluations
        );
        let rtol = scene.accuracy.rtol;
        for (pa, fa) in [
            (&rp.curve.approach, &rf.curve.approach),
            (&rp.curve.retract, &rf.curve.retract),
        ] {
            let loads =
                |v: &Vec<asperity::loading::State>| v.iter().map(|s| s.load()).collect::<Vec<_>>();
            let areas =
                |v: &Vec<asperity::loading::State>| v.iter().map(|s| s.area()).collect::<Vec<_>>();
            let gap = worst_gap(&loads(pa), &loads(fa)).max(worst_gap(&areas(pa), &areas(fa)));
            assert!(
                gap <= rtol,
                "{name}: planned and everything-on differ by {gap:e} > {rtol:e}"
            );
        }
        eprintln!(
            "{name}: planned {:.4} s / {} evals, everything-on {:.4} s / {} evals",
            rp.seconds, rp.evaluations, rf.seconds, rf.evaluations
        );
    }
    assert!(
        planned_evals < full_evals,
        "{planned_evals} vs {full_evals}"
    );
}

#[test]
fn plans_say_what_they_skip() {
    let plan = Plan::new(&example("hertz-exponential.toml"), PlanMode::Planned).unwrap();
    let text = plan.to_string();
    assert!(text.contains("closed form"), "{text}");
    assert!(text.contains("copied from approach"), "{text}");
    assert!(text.contains("w = 0"), "{text}");
    assert!(!plan.pull_off && !plan.compute_retraction);
    assert_eq!(plan.accuracy.method, Method::Auto);
    let plan = Plan::new(&example("max-load.toml"), PlanMode::Planned).unwrap();
    assert!(!plan.quantities.observables().count);
    assert!(plan.to_string().contains("not asked for"));
}

#[test]
fn maugis_population_agrees_with_the_integral_within_its_statistical_error() {
    let base = example("montecarlo-gold.toml");
    for seed in 1..=4 {
        let mut scene = base.clone();
        scene.montecarlo.as_mut().unwrap().seed = seed;
        let plan = Plan::new(&scene, PlanMode::Planned).unwrap();
        let res = plan.run().unwrap();
        let mc = res.montecarlo.unwrap();
        let z = mc.max_abs_z.unwrap();
        assert!(z < 5.0, "seed {seed}: worst |z| = {z}");
        // Every state with enough summits in range is compared.
        let compared = mc.z.iter().filter(|z| z[0].is_some()).count();
        assert!(compared > mc.z.len() / 3, "{compared} of {}", mc.z.len());
    }
    // Power: an integral for a 10% rougher surface is rejected.
    let plan = Plan::new(&base, PlanMode::Planned).unwrap();
    let mc = plan.run().unwrap().montecarlo.unwrap();
    let mut rough = base.clone();
    rough.surface.sigma *= 1.1;
    rough.montecarlo = None;
    rough.program.start_separation = Some(plan.start);
    let wrong = Plan::new(&rough, PlanMode::Planned).unwrap().run().unwrap();
    let worst = mc
        .curve
        .approach
        .iter()
        .zip(&wrong.curve.approach)
        .filter(|(m, _)| m.evaluations >= 20)
        .filter_map(|(m, g)| m.deviation_from(g)[0])
        .fold(0.0f64, |a, z| a.max(z.abs()));
    assert!(
        worst > 5.0,
        "a 10% sigma error went unnoticed: |z| = {worst}"
    );
}

#[test]
fn radius_spread_needs_a_law_that_scales_with_the_radius() {
    let mut scene = example("montecarlo-gold.toml");
    scene.montecarlo.as_mut().unwrap().radius_log_std = 0.2;
    let e = Plan::new(&scene, PlanMode::Planned).unwrap_err();
    assert_eq!(e.field(), Some("montecarlo.radius_log_std"), "{e}");
    scene.law.kind = LawName::Analytic(LawKind::Jkr);
    let res = Plan::new(&scene, PlanMode::Planned).unwrap().run().unwrap();
    assert!(res.montecarlo.unwrap().max_abs_z.is_some());
}
