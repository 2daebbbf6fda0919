//! The humidity charts of a sweep over `adhesion.relative_humidity` alone:
//! the pull-off and the sticking probability against RH, wet (the sweep's
//! rows) beside dry (the base scene without the meniscus, run once), as
//! `pull-off-humidity.svg` and `sticking-humidity.svg` in the sweep's
//! directory. `results.csv` is not touched.

use super::SweepSpec;
use crate::error::Result;
use crate::study::output::Summary;
use crate::study::plot::{Chart, Series};
use crate::study::{Plan, PlanMode, Scene};
use std::path::{Path, PathBuf};

/// The varied field that draws the charts.
pub const HUMIDITY_PATH: &str = "adhesion.relative_humidity";

/// Draws the humidity charts when `spec` varies `adhesion.relative_humidity`
/// alone and `results` (the sweep's `results.csv`) holds `pull_off_N` or
/// `sticks_probability`; returns the files written (none otherwise).
///
/// # Errors
/// The dry run's errors; I/O failures naming the chart.
pub fn humidity_charts(
    base: &Scene,
    spec: &SweepSpec,
    results: &Path,
    out: &Path,
) -> Result<Vec<PathBuf>> {
    if spec.vary.len() != 1 || spec.vary[0].path != HUMIDITY_PATH {
        return Ok(Vec::new());
    }
    let text = std::fs::read_to_string(results)
        .map_err(|e| crate::error::Error::io(results.display(), e.to_string()))?;
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap_or("").split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name);
    let Some(x_col) = col(HUMIDITY_PATH) else {
        return Ok(Vec::new());
    };
    let rows: Vec<Vec<f64>> = lines
        .map(|l| {
            l.split(',')
                .map(|v| v.parse().unwrap_or(f64::NAN))
                .collect()
        })
        .collect();
    let series = |c: usize, scale: f64| -> Vec<(f64, f64)> {
        rows.iter()
            .filter(|r| r.len() > c && r[x_col].is_finite() && r[c].is_finite())
            .map(|r| (r[x_col], scale * r[c]))
            .collect()
    };
    let mut dry_scene = base.clone();
    dry_scene.adhesion.relative_humidity = None;
    let plan = Plan::new(&dry_scene, PlanMode::Planned)?;
    let dry = Summary::new(&plan, &plan.run()?);
    let dry_value = |name: &str| {
        dry.scalars()
            .into_iter()
            .find(|(k, _)| k == name)
            .and_then(|(_, v)| v)
    };
    let mut written = Vec::new();
    let xs = series(x_col, 1.0);
    let (x0, x1) = (
        xs.iter().map(|p| p.0).fold(f64::INFINITY, f64::min),
        xs.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max),
    );
    let title = base.title.clone().unwrap_or_default();
    for (name, file, label, scale) in [
        (
            "pull_off_N",
            "pull-off-humidity.svg",
            "pull-off force |P| (uN)",
            -1e6,
        ),
        (
            "sticks_probability",
            "sticking-humidity.svg",
            "sticking probability",
            1.0,
        ),
    ] {
        let Some(c) = col(name) else { continue };
        let wet = series(c, scale);
        if wet.is_empty() {
            continue;
        }
        let mut lines = vec![Series::solid("wet: menisci at RH", wet)];
        if let Some(v) = dry_value(name) {
            lines.push(Series::dashed(
                "dry (no meniscus)",
                vec![(x0, scale * v), (x1, scale * v)],
            ));
        }
        let what = if name == "pull_off_N" {
            "pull-off"
        } else {
            "sticking probability"
        };
        let chart = Chart {
            title: if title.is_empty() {
                format!("{what} against relative humidity")
            } else {
                format!("{title}: {what} against relative humidity")
            },
            x_label: "relative humidity RH".into(),
            y_label: label.into(),
            series: lines,
            y_range: (name == "sticks_probability").then_some((-0.02, 1.02)),
            y_symlog: false,
        };
        let path = out.join(file);
        chart.write_svg(&path, 800, 500)?;
        written.push(path);
    }
    Ok(written)
}
