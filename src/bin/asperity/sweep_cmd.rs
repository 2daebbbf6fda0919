//! `asperity sweep` and `asperity merge`.

use crate::progress::Progress;
use crate::CliError;
use asperity::study::sweep::{
    humidity_charts, merge, run_sweep, Design, Shard, SweepOptions, SweepSpec, Vary,
    DEFAULT_MAX_CPU_SECONDS,
};
use clap::Args;
use std::path::PathBuf;

/// Arguments of `asperity sweep`.
#[derive(Args, Debug)]
pub struct SweepArgs {
    /// The base scene file (TOML).
    scene: PathBuf,
    /// A varied field, `PATH=FROM:TO:N` (repeatable), e.g.
    /// `surface.sigma=2e-9:8e-9:6`.
    #[arg(long = "vary", required = true)]
    vary: Vec<String>,
    /// Geometric spacing for every varied field.
    #[arg(long)]
    log: bool,
    /// Latin-hypercube sample of this many points instead of a grid.
    #[arg(long, allow_hyphen_values = true)]
    samples: Option<usize>,
    /// Base seed (Latin-hypercube draws and per-point seeds).
    #[arg(long, allow_hyphen_values = true, default_value_t = 0)]
    seed: u64,
    /// Run only slice K of N (`K/N`), e.g. for a Slurm job array.
    #[arg(long, conflicts_with = "shard_from_env")]
    shard: Option<String>,
    /// Take the slice from a Slurm job array task's environment:
    /// K = SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN + 1,
    /// N = SLURM_ARRAY_TASK_COUNT (stepped or sparse arrays are refused).
    #[arg(long)]
    shard_from_env: bool,
    /// Worker threads (default: one per core).
    #[arg(long, allow_hyphen_values = true)]
    threads: Option<usize>,
    /// Most CPU time (s) the sweep may take, estimated from its first
    /// point's time (which runs alone); beyond it the sweep stops after
    /// that point with the estimate. Default one CPU-day.
    #[arg(long, allow_hyphen_values = true, default_value_t = DEFAULT_MAX_CPU_SECONDS)]
    max_cpu_seconds: f64,
    /// Results directory (results.csv, sweep.json).
    #[arg(long, default_value = "sweep-out")]
    out: PathBuf,
}

/// Arguments of `asperity merge`.
#[derive(Args, Debug)]
pub struct MergeArgs {
    /// Shard directories to join.
    #[arg(required = true)]
    dirs: Vec<PathBuf>,
    /// Directory for the merged results.
    #[arg(long)]
    out: PathBuf,
}

/// The sweep layer names its own parameters (`vary`, `out`, ...); on the
/// command line they are flags.
fn as_flag(e: asperity::Error) -> asperity::Error {
    match e.field() {
        Some(
            f @ ("vary" | "log" | "samples" | "seed" | "shard" | "shard-from-env" | "threads"
            | "out" | "max_cpu_seconds"),
        ) => {
            let flag = format!("--{}", f.replace('_', "-"));
            e.renamed(&flag)
        }
        _ => e,
    }
}

/// The sweep's design and this run's slice, from the flags.
fn spec_of(args: &SweepArgs) -> Result<(SweepSpec, Option<Shard>), CliError> {
    let vary = args
        .vary
        .iter()
        .map(|v| Vary::parse(v).map_err(as_flag))
        .collect::<asperity::Result<Vec<_>>>()?;
    let spec = SweepSpec {
        vary,
        design: match args.samples {
            Some(samples) => Design::Latin { samples },
            None => Design::Grid,
        },
        log: args.log,
        seed: args.seed,
    };
    let shard = if args.shard_from_env {
        Some(Shard::from_slurm(|name| std::env::var(name).ok()).map_err(as_flag)?)
    } else {
        args.shard
            .as_deref()
            .map(Shard::parse)
            .transpose()
            .map_err(as_flag)?
    };
    Ok((spec, shard))
}

pub fn run(args: &SweepArgs) -> crate::CliResult {
    let scene = crate::run_cmd::read_scene(&args.scene)?;
    let (spec, shard) = spec_of(args)?;
    if args.threads == Some(0) {
        return Err(CliError::Usage("--threads = 0: give at least 1".into()));
    }
    asperity::error::positive("--max-cpu-seconds", args.max_cpu_seconds)?;
    // The estimates: bookkeeping memory before the first point, time after
    // the first (which runs alone).
    spec.validate().map_err(as_flag)?;
    eprintln!(
        "sweep: {} points, about {:.1} MB of bookkeeping (bounded by the memory available)",
        spec.total(),
        (spec.memory_estimate() / 1e6).max(0.1)
    );
    let threads = args.threads.unwrap_or_else(|| {
        std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get)
    });
    let first: std::sync::Mutex<Option<(std::time::Instant, usize)>> = Default::default();
    // A bar on a terminal; plain lines (every 10 % or 10 s) in logs.
    let bar = Progress::new("sweep", "points", std::time::Duration::ZERO);
    let progress = |done: usize, total: usize| {
        if let Ok(mut first) = first.lock() {
            match *first {
                None => *first = Some((std::time::Instant::now(), done)),
                Some((t0, start)) if done == start + 1 && done < total => {
                    let one = t0.elapsed().as_secs_f64();
                    let rest = (total - done) as f64;
                    eprintln!(
                        "sweep: the first point took {one:.3} s; the {} others an estimated \
                         {:.3e} s of CPU ({:.3e} s on {threads} threads)",
                        total - done,
                        one * rest,
                        one * rest / threads as f64
                    );
                }
                _ => {}
            }
        }
        bar.update(done, total)
    };
    let mut options = SweepOptions::default();
    options.shard = shard;
    options.threads = args.threads;
    options.max_cpu_seconds = Some(args.max_cpu_seconds);
    let outcome = run_sweep(&scene, &spec, &args.out, &options, &progress).map_err(as_flag)?;
    bar.finish();
    for note in &outcome.notes {
        eprintln!("note: {note}");
    }
    eprintln!(
        "{} points: {} already done, {} computed now ({} failed){}; results in {}",
        outcome.planned,
        outcome.resumed,
        outcome.computed,
        outcome.failed,
        if outcome.repaired {
            ", a half-written last row was redone"
        } else {
            ""
        },
        outcome.path.display()
    );
    // A sweep that produced no result at all is a failure, not a success.
    if outcome.planned > 0 && outcome.failed_rows == outcome.planned {
        let (i, why) = outcome.first_failure.unwrap_or_default();
        return Err(CliError::Failed(format!(
            "every one of the {} points failed (first, point {i}: {why}); see {}",
            outcome.planned,
            outcome.path.display()
        )));
    }
    // A humidity sweep also draws pull-off and sticking against RH, dry beside wet.
    if options.shard.is_none() {
        for path in humidity_charts(&scene, &spec, &outcome.path, &args.out).map_err(as_flag)? {
            eprintln!("chart: {}", path.display());
        }
    }
    Ok(())
}

pub fn run_merge(args: &MergeArgs) -> crate::CliResult {
    let path = merge(&args.dirs, &args.out).map_err(as_flag)?;
    eprintln!(
        "merged {} directories into {}",
        args.dirs.len(),
        path.display()
    );
    Ok(())
}
