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
        crate::out!("{}", Plan::preview(scene, mode)?);
        return Ok(());
    }
    let plan = Plan::new(scene, mode)?;
    // Runs longer than ~2 s show curve states done on stderr.
    let bar = crate::progress::Progress::new("run", "curve states", crate::progress::QUIET_FOR);
    let results = plan.run_with_progress(&|done, total| bar.update(done, total));
    bar.finish();
    let results = results?;
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
        // stdout holds only the JSON; the files go to stderr.
        for f in &files {
            eprintln!("wrote {}", f.display());
        }
        crate::outln!("{}", summary.to_json());
        return Ok(());
    }
    let show = |x: Option<f64>, unit: &str| x.map_or("-".into(), |v| format!("{v:.4e} {unit}"));
    let num = |x: Option<f64>| x.map_or("-".to_string(), |v| format!("{v:.4}"));
    crate::outln!(
        "{} — law {}, mu = {}, lambda = {}, {} summits",
        summary.title.as_deref().unwrap_or("scene"),
        summary.law,
        num(summary.tabor_mu),
        num(summary.maugis_lambda),
        summary.summits
    );
    crate::outln!(
        "  separations {:.3e} .. {:.3e} m, {} points per leg, rtol {:e}",
        summary.closest_separation,
        summary.start_separation,
        summary.points,
        summary.rtol
    );
    crate::outln!("  max load           {}", show(summary.max_load, "N"));
    crate::outln!("  max real area      {}", show(summary.max_area, "m^2"));
    crate::outln!("  max contacts       {}", show(summary.max_count, ""));
    let pull = match (summary.pull_off_load, plan.pull_off) {
        (Some(p), _) => format!("{p:.4e} N"),
        (None, true) => "none: no tensile load on retraction".into(),
        (None, false) => "-".into(),
    };
    crate::outln!("  pull-off force     {pull}");
    crate::outln!(
        "  hysteresis energy  {}",
        show(summary.hysteresis_energy, "J")
    );
    crate::outln!(
        "  run time           {:.3} s ({} law evaluations)",
        summary.seconds,
        summary.evaluations
    );
    if let Some(m) = &summary.montecarlo {
        crate::outln!(
            "  Monte Carlo        {} summits (seed {}), {:.3} s",
            m.summits,
            m.seed,
            m.seconds
        );
        if let (Some(p), Some(se)) = (m.max_load, m.max_load_standard_error) {
            crate::outln!("    max load         {p:.4e} N +- {se:.2e} N (standard error)");
        }
        crate::outln!(
            "    sampled pull-off {} (integral at the same separations: {})",
            show(m.pull_off_load, "N"),
            show(m.integral_sampled_pull_off_load, "N")
        );
        crate::outln!(
            "    worst deviation from the integral: {} standard errors (< 5 expected)",
            m.max_abs_z.map_or("-".into(), |z| format!("{z:.2}"))
        );
    }
    if !summary.warnings.is_empty() {
        crate::outln!("  warnings:");
        for w in &summary.warnings {
            crate::outln!("    {w}");
        }
    }
    crate::outln!("  wrote:");
    for f in files {
        crate::outln!("    {}", f.display());
    }
    Ok(())
}
