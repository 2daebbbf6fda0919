//! Where a scene's pull-off populations spend their time: per population,
//! the draw of its summits, the pruning bounds
//! (`montecarlo::pull_off::candidate_separations`) and the exact sums at
//! the candidates (`realised_pull_off`, which prunes again).
//!
//! `cargo run --release --example population_cost -- SCENE [POPULATIONS]`
//! (default 20); run with `RAYON_NUM_THREADS=1` so that wall time per phase
//! is CPU time. docs/performance.md, "Pull-off populations", quotes it.

use asperity::loading::LoadingProgram;
use asperity::montecarlo::pull_off::{
    candidate_separations, population_model, pull_off_evaluations, realised_pull_off,
};
use asperity::montecarlo::SummitLaw;
use asperity::study::plan::{Plan, PlanMode};
use asperity::study::scene::Scene;
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let path = args
        .get(1)
        .ok_or("usage: population_cost SCENE [POPULATIONS]")?;
    let scene = Scene::from_toml(&std::fs::read_to_string(path)?)?;
    let seeds: u64 = args.get(2).map_or(Ok(20), |s| s.parse())?;
    let plan = Plan::new(&scene, PlanMode::Planned)?;
    let p = plan
        .pull_off_population
        .clone()
        .map_err(|why| format!("no populations: {why:?}"))?;
    let law = plan.run_law()?;
    let model = plan.model_with(law.clone())?;
    let closest = plan.closest_separation(&model)?;
    let program = LoadingProgram::new(plan.start, closest, plan.points)?;
    let summit_law = SummitLaw::fixed(law, plan.surface.radius)?;
    let (mut draw, mut prune, mut sums, mut candidates, mut evaluations) = (0.0, 0.0, 0.0, 0, 0);
    let mut first = None;
    for k in 0..seeds {
        let t = Instant::now();
        let mc = population_model(
            &p.spec,
            plan.distribution.as_ref(),
            &summit_law,
            &program,
            p.first_seed + k,
        )?;
        draw += t.elapsed().as_secs_f64();
        let t = Instant::now();
        let found = candidate_separations(&mc, &program);
        prune += t.elapsed().as_secs_f64();
        candidates += found.len();
        evaluations += pull_off_evaluations(&mc, &program, &found);
        let t = Instant::now();
        let v = realised_pull_off(&mc, &program, p.factor)?;
        sums += t.elapsed().as_secs_f64();
        first.get_or_insert((v, mc.population().len()));
    }
    let n = seeds as f64;
    let (v, summits) = first.unwrap_or_default();
    println!(
        "{path}: {summits} summits drawn, {} program points; first pull-off {v:e} N",
        program.separations().len()
    );
    println!(
        "per population: draw {:.3} ms, pruning {:.3} ms, pull-off (pruning + sums) {:.3} ms, \
         {:.1} candidate separations, {:.0} law evaluations ({:.2} ns each)",
        draw / n * 1e3,
        prune / n * 1e3,
        sums / n * 1e3,
        candidates as f64 / n,
        evaluations as f64 / n,
        sums / evaluations as f64 * 1e9
    );
    Ok(())
}
