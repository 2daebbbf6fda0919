//! `asperity run SCENE.toml [--out DIR] [--json] [--plan]`, and the default
//! run of the embedded gold-microswitch scene.

use crate::CliError;
use asperity::study::{text_report, write_outputs, Plan, PlanMode, Results, Scene, Summary};
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

/// The scene in the file `path`; a file that cannot be read, or that is
/// not a scene (a map, a CSV, an empty file), is bad input naming it.
pub fn read_scene(path: &Path) -> Result<Scene, CliError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::Usage(format!("scene: cannot read {}: {e}", path.display())))?;
    Scene::from_toml(&text).map_err(|e| {
        if e.is_bad_input() {
            CliError::Usage(format!("{e} (scene {})", path.display()))
        } else {
            CliError::from(e)
        }
    })
}

pub fn run(args: &RunArgs) -> crate::CliResult {
    let scene = read_scene(&args.scene)?;
    let mode = if args.everything {
        PlanMode::EverythingOn
    } else {
        PlanMode::Planned
    };
    if scene.surface.topography.is_some() {
        // The map's path is relative to the scene file's directory.
        let base = args.scene.parent().unwrap_or(Path::new("."));
        let plan = if args.plan {
            let preview = Plan::preview_in(&scene, mode, base)?;
            if args.json {
                crate::outln!("{}", preview.to_json());
            } else {
                print!("{preview}");
            }
            return Ok(());
        } else {
            planning(|| Plan::new_in(&scene, mode, base))?
        };
        let results = plan.run()?;
        return report(&plan, &results, &args.out, args.json);
    }
    execute(&scene, mode, &args.out, args.json, args.plan)
}

/// `plan` with a note on stderr when it takes longer than
/// [`QUIET_FOR`](crate::progress::QUIET_FOR): a law calibrated from the full
/// Lennard-Jones sphere solver is computed on its first run (a few
/// seconds), then read from the disk cache.
pub fn planning<T>(plan: impl FnOnce() -> T) -> T {
    crate::progress::waiting(
        "plan",
        "a law calibrated from the full Lennard-Jones sphere solver is computed on its first \
         run, then read from the cache",
        crate::progress::QUIET_FOR,
        plan,
    )
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
        let preview = Plan::preview(scene, mode)?;
        if json {
            crate::outln!("{}", preview.to_json());
            return Ok(());
        }
        crate::out!("{preview}");
        for w in preview.warnings() {
            crate::outln!("  warning: {w}");
        }
        return Ok(());
    }
    let plan = planning(|| Plan::new(scene, mode))?;
    // Runs longer than ~2 s show curve states done on stderr.
    let bar = crate::progress::Progress::new("run", "curve states", crate::progress::QUIET_FOR);
    let results = plan.run_with_progress(&|done, total| bar.update(done, total));
    bar.finish();
    let results = results?;
    report(&plan, &results, out, json)
}

/// Writes a run's files and prints its summary (text or JSON).
pub fn report(plan: &Plan, results: &Results, out: &Path, json: bool) -> crate::CliResult {
    let plan = results.plan(plan);
    let summary = Summary::new(plan, results);
    let files = write_outputs(plan, results, &summary, out)?;
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
    } else {
        crate::out!("{}", text_report(plan, &summary, &files));
    }
    Ok(())
}
