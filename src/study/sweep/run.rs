//! Running a sweep: each missing point of this shard is planned and run in
//! parallel (rayon) and its row appended as soon as it is finished.

use super::edit::set_field;
use super::spec::{Shard, SweepPoint, SweepSpec};
use super::store::{ResultsFile, SweepMeta};
use crate::error::{Error, Result};
use crate::study::{Plan, PlanMode, Quantity, Scene, Summary};
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
    /// The results file.
    pub path: PathBuf,
}

fn cell(x: Option<f64>) -> String {
    x.map_or(String::new(), |v| format!("{v:e}"))
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
/// the points (a sweep may cross a model's limits; those points fail).
///
/// # Errors
/// [`Error::Invalid`] naming the varied path, the value and the reason.
fn check_fields(base: &toml::Value, spec: &SweepSpec, points: &[SweepPoint]) -> Result<()> {
    let Some(first) = points.first() else {
        return Ok(());
    };
    for (d, v) in spec.vary.iter().enumerate() {
        let mut seen = std::collections::HashSet::new();
        for p in points {
            let x = p.values[d];
            if !seen.insert(x.to_bits()) {
                continue;
            }
            if seen.len() > CHECKED_VALUES {
                break;
            }
            let mut value = base.clone();
            for (w, y) in spec.vary.iter().zip(&first.values) {
                set_field(&mut value, &w.path, *y)?;
            }
            set_field(&mut value, &v.path, x)?;
            Scene::deserialize(value).map_err(|e| {
                Error::invalid(&v.path, format!("at {x:e}: {}", e.message().trim()))
            })?;
        }
    }
    Ok(())
}

/// Computes one point's row: `index, values.., seed, status, outputs..`.
fn point_row(
    base: &toml::Value,
    spec: &SweepSpec,
    options: &SweepOptions,
    cols: &[String],
    p: &SweepPoint,
) -> (String, bool) {
    let mut row: Vec<String> = vec![p.index.to_string()];
    row.extend(p.values.iter().map(|v| format!("{v:e}")));
    row.push(p.seed.to_string());
    let outcome = (|| -> Result<Summary> {
        let mut scene_value = base.clone();
        for (v, x) in spec.vary.iter().zip(&p.values) {
            set_field(&mut scene_value, &v.path, *x)?;
        }
        let mut scene = Scene::deserialize(scene_value)
            .map_err(|e| Error::invalid("scene", e.message().to_string()))?;
        // Each point draws its own population, unless the seed is varied.
        if let Some(mc) = scene.montecarlo.as_mut() {
            if !spec.vary.iter().any(|v| v.path == "montecarlo.seed") {
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
    let ok = outcome.is_ok();
    match outcome {
        Ok(s) => {
            row.push("ok".into());
            for c in cols {
                row.push(cell(value(&s, c)));
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
    (row.join(","), ok)
}

/// Runs the points of `spec` over the scene `base` that are not yet in
/// `out/results.csv`, calling `progress(done, total)` as points finish.
///
/// # Errors
/// Invalid specs or scenes (naming the field) and I/O failures (naming
/// `--out`). A point whose scene fails does not stop the sweep: its row
/// records the error.
pub fn run_sweep(
    base: &Scene,
    spec: &SweepSpec,
    out: &Path,
    options: &SweepOptions,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<PointOutcome> {
    spec.validate()?;
    base.validate()?;
    let normalised = base.to_toml();
    let base_value: toml::Value = toml::from_str(&normalised)
        .map_err(|e| Error::invalid("scene", e.message().to_string()))?;
    let points = spec.points();
    check_fields(&base_value, spec, &points)?;
    // The base plan gives the columns (and gathers a calibration once, for
    // every point to read from the cache).
    let cols = with_quantities(Plan::new(base, PlanMode::Planned)?, options)?.result_columns();
    let mut header: Vec<String> = vec!["index".into()];
    header.extend(spec.vary.iter().map(|v| v.path.clone()));
    header.extend(["seed".into(), "status".into()]);
    header.extend(cols.iter().map(|c| c.to_string()));
    let header = header.join(",");
    let meta = SweepMeta {
        scene: normalised,
        spec: spec.clone(),
        total: points.len(),
        shard: options.shard,
        header: header.clone(),
    };
    let file = ResultsFile::open(out, &meta)?;
    let repaired = file.repaired;
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
    let work = || {
        todo.par_iter().try_for_each(|p| -> Result<()> {
            let (row, ok) = point_row(&base_value, spec, options, &cols, p);
            if !ok {
                failed.fetch_add(1, Ordering::Relaxed);
            }
            file.lock()
                .map_err(|_| Error::invalid("out", "results file lock poisoned"))?
                .append(p.index, &row)?;
            progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);
            Ok(())
        })
    };
    match options.threads {
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n.max(1))
            .build()
            .map_err(|e| Error::invalid("threads", e.to_string()))?
            .install(work)?,
        None => work()?,
    }
    let file = file
        .into_inner()
        .map_err(|_| Error::invalid("out", "results file lock poisoned"))?;
    // Status column: after the index, the varied values and the seed.
    let status_col = spec.vary.len() + 2;
    let failures: Vec<(usize, String)> = file
        .rows()
        .filter(|(i, _)| options.shard.is_none_or(|s| s.contains(*i)))
        .filter_map(|(i, r)| {
            let status = r.split(',').nth(status_col).unwrap_or("");
            (status != "ok").then(|| (i, status.to_string()))
        })
        .collect();
    let path = file.finish(&header)?;
    Ok(PointOutcome {
        planned: total,
        resumed,
        computed: todo.len(),
        failed: failed.into_inner(),
        failed_rows: failures.len(),
        first_failure: failures.into_iter().next(),
        repaired,
        path,
    })
}
