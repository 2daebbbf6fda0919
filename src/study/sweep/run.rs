//! Running a sweep: each missing point of this shard is planned and run in
//! parallel (rayon) and its row appended as soon as it is finished.

use super::edit::set_field;
use super::spec::{Shard, SweepPoint, SweepSpec};
use super::store::{ResultsFile, SweepMeta};
use crate::error::{Error, Result};
use crate::study::cpu_time::process_cpu_seconds;
use crate::study::{Plan, PlanMode, Quantity, Scene, Summary, Table};
use rayon::prelude::*;
use serde::Deserialize;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// How to run a sweep.
#[derive(Debug, Clone, Default)]
#[non_exhaustive]
pub struct SweepOptions {
    /// The slice to run (`None`: all points).
    pub shard: Option<Shard>,
    /// Worker threads (`None`: rayon's default, one per core).
    pub threads: Option<usize>,
    /// Quantities added to every point's plan ([`Plan::with_quantity`]):
    /// each asked one with a headline number gets a column.
    pub quantities: Vec<Quantity>,
    /// Most CPU time (s) the points still to run may take, estimated from
    /// the first point's time (it runs alone) times their number; beyond
    /// it the sweep stops after that first point with an error naming
    /// `max_cpu_seconds` and the estimate (`None`: no limit). The command
    /// line and Python default to [`DEFAULT_MAX_CPU_SECONDS`].
    pub max_cpu_seconds: Option<f64>,
}

/// Default limit of a sweep's estimated CPU time (s): one CPU-day. A longer
/// sweep is refused with its estimate unless the limit is raised
/// (`--max-cpu-seconds`, `max_cpu_seconds=`), or sharded.
pub const DEFAULT_MAX_CPU_SECONDS: f64 = 86_400.0;

/// The estimate of a sweep's remaining CPU time from its first point's
/// (`seconds`, the larger of its wall and CPU time), checked against
/// `limit`.
///
/// # Errors
/// [`Error::Invalid`] naming `max_cpu_seconds` with the estimate.
fn check_estimate(seconds: f64, remaining: usize, limit: Option<f64>) -> Result<()> {
    let estimate = seconds * remaining as f64;
    match limit {
        Some(max) if estimate > max => Err(Error::invalid(
            "max_cpu_seconds",
            format!(
                "the first point took {seconds:.3e} s, so the {remaining} others need an \
                 estimated {estimate:.3e} s of CPU, more than the limit {max:e} s: raise the \
                 limit, run fewer points, or shard the sweep"
            ),
        )),
        _ => Ok(()),
    }
}

/// Runs `first` alone and returns its result with its time (s): the larger
/// of the wall-clock and the process CPU time it took.
fn timed<R>(first: impl FnOnce() -> R) -> (R, f64) {
    let (wall, cpu) = (std::time::Instant::now(), process_cpu_seconds());
    let r = first();
    let wall = wall.elapsed().as_secs_f64();
    let cpu = match (cpu, process_cpu_seconds()) {
        (Some(a), Some(b)) => b - a,
        _ => 0.0,
    };
    (r, wall.max(cpu))
}

/// `plan` with the sweep's extra quantities.
fn with_quantities(plan: Plan, options: &SweepOptions) -> Result<Plan> {
    options
        .quantities
        .iter()
        .try_fold(plan, |p, q| p.with_quantity(q.clone()))
}

/// What a sweep run did.
#[derive(Debug, Clone)]
pub struct PointOutcome {
    /// Points of this shard.
    pub planned: usize,
    /// Points found already done (resumed).
    pub resumed: usize,
    /// Points computed now.
    pub computed: usize,
    /// Points computed now whose scene failed (their row says why).
    pub failed: usize,
    /// Rows of this shard, resumed or computed now, whose status is not
    /// `ok`; when it equals `planned` the sweep produced nothing.
    pub failed_rows: usize,
    /// The status of the first failed row (lowest index) and its index.
    pub first_failure: Option<(usize, String)>,
    /// Whether a half-written last row was repaired.
    pub repaired: bool,
    /// Rows found on resuming that were recomputed, and why (a checksum
    /// that does not match, a file without checksums): one note each.
    pub notes: Vec<String>,
    /// The results file.
    pub path: PathBuf,
}

/// A result cell: `true`/`false` for the boolean column `sticks` (1/0 in
/// [`Summary::scalars`]), else the number in Rust's shortest round-trip
/// scientific form; empty when the run has no such value.
fn cell(column: &str, x: Option<f64>) -> String {
    match x {
        None => String::new(),
        Some(v) if column == "sticks" => (v != 0.0).to_string(),
        Some(v) => format!("{v:e}"),
    }
}

/// The value of output column `c` in a summary.
fn value(s: &Summary, c: &str) -> Option<f64> {
    s.scalars()
        .into_iter()
        .find(|(k, _)| k == c)
        .and_then(|(_, v)| v)
}

/// Most distinct values per varied field checked before the first point.
const CHECKED_VALUES: usize = 4096;

/// Fails early, before any point runs, on a bad path, a key the scene does
/// not have (`surface.sigm`) or a value its field's type cannot hold (a
/// fractional `montecarlo.summits`): every distinct value of each varied
/// field (up to [`CHECKED_VALUES`]), the others at the first point's,
/// deserialised into a scene. Values out of a field's range are left to
/// the points (a sweep may cross a model's limits; those points fail),
/// unless every value is (every point would fail: refused).
///
/// # Errors
/// [`Error::Invalid`] naming the varied path, the value and the reason.
fn check_fields(base: &toml::Value, paths: &[String], points: &[SweepPoint]) -> Result<()> {
    let Some(first) = points.first() else {
        return Ok(());
    };
    for (d, path) in paths.iter().enumerate() {
        let mut seen = std::collections::HashSet::new();
        // The first value out of the field's own range, and whether every
        // checked value is (then every point would fail: refused).
        let mut out_of_range: Option<Error> = None;
        let mut all_out = true;
        for p in points {
            let x = p.values[d];
            if !seen.insert(x.to_bits()) {
                continue;
            }
            if seen.len() > CHECKED_VALUES {
                break;
            }
            let mut value = base.clone();
            for (w, y) in paths.iter().zip(&first.values) {
                set_field(&mut value, w, *y)?;
            }
            set_field(&mut value, path, x)?;
            let scene = Scene::deserialize(value)
                .map_err(|e| Error::invalid(path, format!("at {x:e}: {}", e.message().trim())))?;
            match scene.validate() {
                Err(e) if e.field() == Some(path.as_str()) => {
                    out_of_range.get_or_insert(e);
                }
                _ => all_out = false,
            }
        }
        if let (true, Some(e)) = (all_out, out_of_range) {
            return Err(Error::invalid(
                path,
                format!("every value is out of the field's range, so every point would fail ({e})"),
            ));
        }
    }
    Ok(())
}

/// Computes one point's row: `index, values.., seed, status, outputs..`
/// and whether it is `ok` (a failed scene is a row saying why).
///
/// # Errors
/// [`Error::Cancelled`] only: a cancelled point has no row.
fn point_row(
    base: &toml::Value,
    paths: &[String],
    options: &SweepOptions,
    cols: &[String],
    p: &SweepPoint,
) -> Result<(String, bool)> {
    crate::cancel::check()?;
    let mut row: Vec<String> = vec![p.index.to_string()];
    row.extend(p.values.iter().map(|v| format!("{v:e}")));
    row.push(p.seed.to_string());
    let outcome = (|| -> Result<Summary> {
        let mut scene_value = base.clone();
        for (path, x) in paths.iter().zip(&p.values) {
            set_field(&mut scene_value, path, *x)?;
        }
        let mut scene = Scene::deserialize(scene_value)
            .map_err(|e| Error::invalid("scene", e.message().to_string()))?;
        // Each point draws its own population, unless the seed is varied.
        if let Some(mc) = scene.montecarlo.as_mut() {
            if !paths.iter().any(|path| path == "montecarlo.seed") {
                mc.seed = p.seed;
            }
        }
        scene.validate()?;
        let plan = with_quantities(Plan::new(&scene, PlanMode::Planned)?, options)?;
        let results = plan.run()?;
        Ok(Summary::new(&plan, &results))
    })()
    .and_then(|s| {
        // A value that is not finite is never written as a result.
        let bad = cols
            .iter()
            .map(|c| (c, value(&s, c)))
            .find(|(_, v)| v.is_some_and(|x| !x.is_finite()));
        match bad {
            Some((c, Some(v))) => Err(Error::invalid(
                c.as_str(),
                format!("{v} is not finite (the scene's magnitudes overflow)"),
            )),
            _ => Ok(s),
        }
    });
    if let Err(Error::Cancelled) = outcome {
        return Err(Error::Cancelled);
    }
    let ok = outcome.is_ok();
    match outcome {
        Ok(s) => {
            row.push("ok".into());
            for c in cols {
                row.push(cell(c, value(&s, c)));
            }
        }
        Err(e) => {
            let msg: String = e
                .to_string()
                .chars()
                .map(|c| {
                    if matches!(c, ',' | '\n' | '\r' | '"') {
                        ';'
                    } else {
                        c
                    }
                })
                .collect();
            row.push(format!("error: {msg}"));
            row.extend(cols.iter().map(|_| String::new()));
        }
    }
    Ok((row.join(","), ok))
}

/// The header of `results.csv`: `index`, the varied paths, `seed`,
/// `status`, the output columns.
fn results_header(paths: &[String], cols: &[String]) -> String {
    let mut header: Vec<String> = vec!["index".into()];
    header.extend(paths.iter().cloned());
    header.extend(["seed".into(), "status".into()]);
    header.extend(cols.iter().cloned());
    header.join(",")
}

/// The normalised scene as a TOML value, after checking every path can be
/// set (to `first[i]`) before any point runs.
fn base_value(base: &Scene, paths: &[String], first: &[f64]) -> Result<(String, toml::Value)> {
    base.validate()?;
    let normalised = base.to_toml();
    let value: toml::Value = toml::from_str(&normalised)
        .map_err(|e| Error::invalid("scene", e.message().to_string()))?;
    for (path, x) in paths.iter().zip(first) {
        set_field(&mut value.clone(), path, *x)?;
    }
    Ok((normalised, value))
}

/// A sweep over given values, in memory: the grid of every combination of
/// `vary`'s values (`(dotted scene path, values)`, the first slowest), each
/// point's seed from `seed` and its index as in [`SweepSpec::points`], run
/// in parallel (`options.threads`; `options.shard` is not used) and
/// returned as the table `results.csv` would hold (`index`, the paths,
/// `seed`, `status`, the plan's result columns), without any file. Each row
/// is computed exactly as [`run_sweep`] computes it, so a point with the same
/// values and seed gives the same numbers. `on_row(done, total, header,
/// row)` is called as each point finishes (`row` a line of `results.csv`
/// under `header`, in the order points finish; the table is in index
/// order). The first point runs
/// alone: its time gives the estimate checked against
/// `options.max_cpu_seconds`.
///
/// # Errors
/// Invalid scenes or paths (naming the field), an empty or duplicated
/// `vary` (naming `vary`), non-finite values, more than
/// 10^8 points (the limit of [`SweepSpec::validate`]), an estimate beyond
/// `options.max_cpu_seconds` (naming it), [`Error::Cancelled`].
pub fn sweep_table(
    base: &Scene,
    vary: &[(String, Vec<f64>)],
    seed: u64,
    options: &SweepOptions,
    on_row: &(dyn Fn(usize, usize, &str, &str) + Sync),
) -> Result<Table> {
    if vary.is_empty() {
        return Err(Error::invalid("vary", "give at least one path"));
    }
    for (i, (path, values)) in vary.iter().enumerate() {
        if vary[..i].iter().any(|(p, _)| p == path) {
            return Err(Error::invalid("vary", format!("{path} is varied twice")));
        }
        if values.is_empty() {
            return Err(Error::invalid("vary", format!("{path}: no values")));
        }
        for &x in values {
            crate::error::finite(path, x)?;
        }
    }
    let total = vary
        .iter()
        .try_fold(1usize, |acc, (_, v)| acc.checked_mul(v.len()))
        .filter(|&t| t <= super::spec::MAX_POINTS)
        .ok_or_else(|| Error::invalid("vary", "too many points"))?;
    let paths: Vec<String> = vary.iter().map(|(p, _)| p.clone()).collect();
    let first: Vec<f64> = vary.iter().map(|(_, v)| v[0]).collect();
    let (_, base_value) = base_value(base, &paths, &first)?;
    let cols = with_quantities(Plan::new(base, PlanMode::Planned)?, options)?.result_columns();
    let points: Vec<SweepPoint> = (0..total)
        .map(|index| {
            let mut i = index;
            let mut values = vec![0.0; vary.len()];
            for (k, (_, v)) in vary.iter().enumerate().rev() {
                values[k] = v[i % v.len()];
                i /= v.len();
            }
            SweepPoint {
                index,
                values,
                seed: SweepPoint::seed_of(seed, index),
            }
        })
        .collect();
    // As `asperity sweep`: a bad path or value fails before any point runs.
    check_fields(&base_value, &paths, &points)?;
    let header = results_header(&paths, &cols);
    let token = crate::cancel::current();
    let done = AtomicUsize::new(0);
    let row_of = |p: &SweepPoint| -> Result<String> {
        let (row, _) = crate::cancel::scope(token.as_ref(), || {
            point_row(&base_value, &paths, options, &cols, p)
        })?;
        on_row(
            done.fetch_add(1, Ordering::Relaxed) + 1,
            total,
            &header,
            &row,
        );
        Ok(row)
    };
    let work = || -> Result<Vec<String>> {
        let Some((first, rest)) = points.split_first() else {
            return Ok(Vec::new());
        };
        let (first_row, seconds) = timed(|| row_of(first));
        let first_row = first_row?;
        check_estimate(seconds, rest.len(), options.max_cpu_seconds)?;
        let mut rows = vec![first_row];
        rows.extend(rest.par_iter().map(row_of).collect::<Result<Vec<_>>>()?);
        Ok(rows)
    };
    let rows = on_threads(options.threads, work)?;
    let mut text = header;
    text.push('\n');
    for r in rows {
        text.push_str(&r);
        text.push('\n');
    }
    Ok(Table::from_csv(&text))
}

/// The rows of this shard whose status is not `ok`: `(index, status)`.
/// The status column follows the index, the varied values and the seed.
fn failed_rows(
    file: &ResultsFile,
    spec: &SweepSpec,
    options: &SweepOptions,
) -> Vec<(usize, String)> {
    let status_col = spec.vary.len() + 2;
    file.rows()
        .filter(|(i, _)| options.shard.is_none_or(|s| s.contains(*i)))
        .filter_map(|(i, r)| {
            let status = r.split(',').nth(status_col).unwrap_or("");
            (status != "ok").then(|| (i, status.to_string()))
        })
        .collect()
}

/// Runs the points of `spec` over the scene `base` that are not yet in
/// `out/results.csv`, calling `progress(done, total)` as points finish
/// (once before any runs; the first point runs alone, so the second call
/// comes after one point's time, the estimate of the others').
///
/// # Errors
/// Invalid specs or scenes (naming the field), I/O failures (naming
/// `out`), an estimate beyond `options.max_cpu_seconds` (naming it, after
/// the first point), [`Error::Cancelled`] (the rows of the points finished
/// are kept: a rerun resumes). A point whose scene fails does not stop the
/// sweep: its row records the error.
pub fn run_sweep(
    base: &Scene,
    spec: &SweepSpec,
    out: &Path,
    options: &SweepOptions,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<PointOutcome> {
    spec.validate()?;
    // Fail early on a bad path, before any point runs.
    let (normalised, base_value) = base_value(
        base,
        &spec.vary.iter().map(|v| v.path.clone()).collect::<Vec<_>>(),
        &spec.vary.iter().map(|v| v.from).collect::<Vec<_>>(),
    )?;
    // The base plan gives the columns (and gathers a calibration once, for
    // every point to read from the cache).
    let cols = with_quantities(Plan::new(base, PlanMode::Planned)?, options)?.result_columns();
    let paths: Vec<String> = spec.vary.iter().map(|v| v.path.clone()).collect();
    let header = results_header(&paths, &cols);
    let points = spec.points();
    // Every distinct value of every varied field parses into the scene.
    check_fields(&base_value, &paths, &points)?;
    let meta = SweepMeta {
        scene: normalised,
        spec: spec.clone(),
        total: points.len(),
        shard: options.shard,
        header: header.clone(),
    };
    let file = ResultsFile::open(out, &meta)?;
    let repaired = file.repaired;
    let notes = file.notes.clone();
    let mine: Vec<&SweepPoint> = points
        .iter()
        .filter(|p| options.shard.is_none_or(|s| s.contains(p.index)))
        .collect();
    let todo: Vec<&SweepPoint> = mine
        .iter()
        .copied()
        .filter(|p| !file.is_done(p.index))
        .collect();
    let resumed = mine.len() - todo.len();
    let total = mine.len();
    let done = AtomicUsize::new(resumed);
    let failed = AtomicUsize::new(0);
    progress(resumed, total);
    let file = Mutex::new(file);
    let token = crate::cancel::current();
    let step = |p: &&SweepPoint| -> Result<()> {
        let (row, ok) = crate::cancel::scope(token.as_ref(), || {
            point_row(&base_value, &paths, options, &cols, p)
        })?;
        if !ok {
            failed.fetch_add(1, Ordering::Relaxed);
        }
        file.lock()
            .map_err(|_| Error::invalid("out", "results file lock poisoned"))?
            .append(p.index, &row)?;
        progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);
        Ok(())
    };
    // The first point alone: its time, reported by the first progress
    // call past `resumed`, is the per-point estimate of the rest.
    let work = || match todo.split_first() {
        Some((first, rest)) => {
            let (r, seconds) = timed(|| step(first));
            r?;
            check_estimate(seconds, rest.len(), options.max_cpu_seconds)?;
            rest.par_iter().try_for_each(step)
        }
        None => Ok(()),
    };
    on_threads(options.threads, work)?;
    let file = file
        .into_inner()
        .map_err(|_| Error::invalid("out", "results file lock poisoned"))?;
    let failures = failed_rows(&file, spec, options);
    let path = file.finish(&header)?;
    Ok(PointOutcome {
        planned: total,
        resumed,
        computed: todo.len(),
        failed: failed.into_inner(),
        failed_rows: failures.len(),
        first_failure: failures.into_iter().next(),
        repaired,
        notes,
        path,
    })
}

/// Runs `work` on a pool of `threads` threads (at least one), or on the
/// global pool when `None`.
fn on_threads<T: Send>(
    threads: Option<usize>,
    work: impl FnOnce() -> Result<T> + Send,
) -> Result<T> {
    match threads {
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n.max(1))
            .build()
            .map_err(|e| Error::invalid("threads", e.to_string()))?
            .install(work),
        None => work(),
    }
}
