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
        let plan = Plan::preview(scene, mode)?;
        crate::out!("{plan}");
        for w in &plan.warnings {
            crate::outln!("  warning: {w}");
        }
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
    match summary.law_model_error {
        Some(e) => crate::outln!(
            "  model error        law {} differs from the full Lennard-Jones solution by {:.2} % \
             (rtol {:e} bounds only the numerics)",
            summary.law,
            100.0 * e,
            summary.rtol
        ),
        None => crate::outln!("  model error        not measured for law {}", summary.law),
    }
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
            "    sampled pull-off {} (this realisation: the minimum of its own load curve)",
            show(m.pull_off_load, "N")
        );
        if let Some(s) = &m.spots {
            crate::outln!(
                "    sample's spots   {} at random positions in a {:.3e} m square: parallel {:.4e} Ohm, Greenwood {:.4e} Ohm, exact {}",
                s.count,
                s.side_m,
                s.parallel_ohm,
                s.greenwood_ohm,
                s.exact_ohm.map_or("- (more than 3000 spots)".into(), |r| format!("{r:.4e} Ohm"))
            );
        }
        crate::outln!(
            "    integral         {} (minimum of the mean load at the same separations, \
             not the mean of the realisations' minima)",
            show(m.integral_sampled_pull_off_load, "N")
        );
        match (m.pull_off_seed_mean, m.pull_off_seed_std) {
            (Some(mean), Some(sd)) => crate::outln!(
                "    one switch's pull-off over {} seeds: mean {mean:.4e} N, std {sd:.2e} N",
                1 + m.pull_off_other_seeds.len()
            ),
            _ => crate::outln!(
                "    pull-off scatter over seeds: not computed (population too large)"
            ),
        }
        if m.states_without_standard_error > 0 {
            crate::outln!(
                "    {} states with fewer than 20 summits in contact: no standard error there",
                m.states_without_standard_error
            );
        }
        crate::outln!(
            "    worst deviation of the curve from the integral: {} standard errors (< 5 expected)",
            m.max_abs_z.map_or("-".into(), |z| format!("{z:.2}"))
        );
    }
    if let Some(r) = summary.resistance_ohm {
        crate::outln!("  resistance         {r:.4e} Ohm at the closest approach");
    }
    if let Some(h) = &summary.heating {
        let show = |x: Option<f64>, unit: &str| {
            x.map_or("- (no contact)".into(), |v| format!("{v:.4e} {unit}"))
        };
        crate::outln!(
            "  heating            {:.3e} A: contact voltage {}, peak temperature {} (bulk {:.2} K)",
            h.current_a,
            show(h.contact_voltage_v, "V"),
            show(h.max_temperature_k, "K"),
            h.bulk_temperature_k
        );
    }
    if let Some(p) = &summary.plasticity {
        let pct = |x: Option<f64>| x.map_or("-".into(), |v| format!("{:.1} %", 100.0 * v));
        crate::outln!(
            "  plasticity index   {:.3} (H = {:.3e} Pa); contacts at the closest approach: elastic {}, elastic-plastic {}, fully plastic {}",
            p.plasticity_index,
            p.hardness_pa,
            pct(p.elastic_fraction),
            pct(p.elastic_plastic_fraction),
            pct(p.fully_plastic_fraction)
        );
    }
    if let Some(s) = &summary.stiction {
        crate::outln!(
            "  stiction           pull-off {:.4e} N, spring k x travel {:.4e} N, margin {:.4e} N: {}",
            s.pull_off_n,
            s.restoring_force_n,
            s.margin_n,
            if s.sticks { "STICKS (margin < 0)" } else { "reopens" }
        );
    }
    if let Some(states) = &summary.states {
        crate::outln!("  listed states (approach):");
        crate::outln!(
            "    {:>13} {:>13} {:>13} {:>11} {:>13}",
            "separation m",
            "load N",
            "area m^2",
            "contacts",
            "resistance Ohm"
        );
        for st in states {
            crate::outln!(
                "    {:>13.5e} {:>13.5e} {:>13.5e} {:>11.4} {:>13}",
                st.separation_m,
                st.load_n.unwrap_or(f64::NAN),
                st.real_area_m2.unwrap_or(f64::NAN),
                st.contacts.unwrap_or(f64::NAN),
                match st.resistance_ohm {
                    Some(Some(r)) => format!("{r:.5e}"),
                    Some(None) => "no contact".into(),
                    None => "-".into(),
                }
            );
        }
    }
    if let Some(t) = &summary.topography {
        crate::outln!(
            "  topography         {} ({} x {}), {} summits, model {}",
            t.file,
            t.rows,
            t.cols,
            t.summits.count,
            t.model
        );
        if let Some(o) = &t.other {
            crate::outln!(
                "    {} model: max load {}, contacts {}, pull-off {}",
                o.model,
                show(o.max_load, "N"),
                num(o.max_count),
                show(o.pull_off_load, "N")
            );
        }
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
