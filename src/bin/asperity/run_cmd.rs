//! `asperity run SCENE.toml [--out DIR] [--json] [--plan]`, and the default
//! run of the embedded gold-microswitch scene.

use crate::CliError;
use asperity::study::{write_outputs, Plan, PlanMode, Results, Scene, Summary};
use clap::Args;
use std::path::{Path, PathBuf};

/// Arguments of `asperity run`.
#[derive(Args, Debug)]
pub struct RunArgs {
    /// The scene file (TOML).
    scene: PathBuf,
    /// Directory for curve.csv, summary.json and the SVG charts.
    #[arg(long, default_value = "asperity-out")]
    out: PathBuf,
    /// Print the JSON summary to stdout instead of the text summary.
    #[arg(long)]
    json: bool,
    /// Print the plan (methods, skips and reasons) and stop.
    #[arg(long)]
    plan: bool,
    /// Switch every skip off (for comparison with the planned run).
    #[arg(long)]
    everything: bool,
}

pub fn run(args: &RunArgs) -> crate::CliResult {
    let text = std::fs::read_to_string(&args.scene).map_err(|e| {
        CliError::Usage(format!("scene: cannot read {}: {e}", args.scene.display()))
    })?;
    let scene = Scene::from_toml(&text)?;
    let mode = if args.everything {
        PlanMode::EverythingOn
    } else {
        PlanMode::Planned
    };
    if scene.surface.topography.is_some() {
        // The map's path is relative to the scene file's directory.
        let base = args.scene.parent().unwrap_or(Path::new("."));
        let plan = if args.plan {
            print!("{}", Plan::preview_in(&scene, mode, base)?);
            return Ok(());
        } else {
            Plan::new_in(&scene, mode, base)?
        };
        let results = plan.run()?;
        return report(&plan, &results, &args.out, args.json);
    }
    execute(&scene, mode, &args.out, args.json, args.plan)
}

/// Plans, runs and writes one scene; prints the plan, a summary or JSON.
pub fn execute(
    scene: &Scene,
    mode: PlanMode,
    out: &Path,
    json: bool,
    plan_only: bool,
) -> crate::CliResult {
    if plan_only {
        print!("{}", Plan::preview(scene, mode)?);
        return Ok(());
    }
    let plan = Plan::new(scene, mode)?;
    let results = plan.run()?;
    report(&plan, &results, out, json)
}

/// Writes a run's files and prints its summary (text or JSON).
pub fn report(plan: &Plan, results: &Results, out: &Path, json: bool) -> crate::CliResult {
    let (plan, results) = (plan, results);
    let files = write_outputs(plan, results, out)?;
    let summary = Summary::new(plan, results);
    // Warnings go to stderr as well, so that stdout stays parseable.
    for w in &summary.warnings {
        eprintln!("warning: {w}");
    }
    if json {
        println!("{}", summary.to_json());
        return Ok(());
    }
    let show = |x: Option<f64>, unit: &str| x.map_or("-".into(), |v| format!("{v:.4e} {unit}"));
    let num = |x: Option<f64>| x.map_or("-".to_string(), |v| format!("{v:.4}"));
    println!(
        "{} — law {}, mu = {}, lambda = {}, {} summits",
        summary.title.as_deref().unwrap_or("scene"),
        summary.law,
        num(summary.tabor_mu),
        num(summary.maugis_lambda),
        summary.summits
    );
    println!(
        "  separations {:.3e} .. {:.3e} m, {} points per leg, rtol {:e}",
        summary.closest_separation, summary.start_separation, summary.points, summary.rtol
    );
    println!("  max load           {}", show(summary.max_load, "N"));
    println!("  max real area      {}", show(summary.max_area, "m^2"));
    println!("  max contacts       {}", show(summary.max_count, ""));
    let pull = match (summary.pull_off_load, plan.pull_off) {
        (Some(p), _) => format!("{p:.4e} N"),
        (None, true) => "none: no tensile load on retraction".into(),
        (None, false) => "-".into(),
    };
    println!("  pull-off force     {pull}");
    println!(
        "  hysteresis energy  {}",
        show(summary.hysteresis_energy, "J")
    );
    println!(
        "  run time           {:.3} s ({} law evaluations)",
        summary.seconds, summary.evaluations
    );
    if let Some(m) = &summary.montecarlo {
        println!(
            "  Monte Carlo        {} summits (seed {}), {:.3} s",
            m.summits, m.seed, m.seconds
        );
        if let (Some(p), Some(se)) = (m.max_load, m.max_load_standard_error) {
            println!("    max load         {p:.4e} N +- {se:.2e} N (standard error)");
        }
        println!(
            "    sampled pull-off {} (integral at the same separations: {})",
            show(m.pull_off_load, "N"),
            show(m.integral_sampled_pull_off_load, "N")
        );
        println!(
            "    worst deviation from the integral: {} standard errors (< 5 expected)",
            m.max_abs_z.map_or("-".into(), |z| format!("{z:.2}"))
        );
    }
    if let Some(t) = &summary.topography {
        println!(
            "  topography         {} ({} x {}), {} summits, model {}",
            t.file, t.rows, t.cols, t.summits.count, t.model
        );
        if let Some(o) = &t.other {
            println!(
                "    {} model: max load {}, contacts {}, pull-off {}",
                o.model,
                show(o.max_load, "N"),
                num(o.max_count),
                show(o.pull_off_load, "N")
            );
        }
    }
    if !summary.warnings.is_empty() {
        println!("  warnings:");
        for w in &summary.warnings {
            println!("    {w}");
        }
    }
    println!("  wrote:");
    for f in files {
        println!("    {}", f.display());
    }
    Ok(())
}
