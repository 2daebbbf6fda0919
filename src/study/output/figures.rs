//! Writing a run's outputs to a directory: `curve.csv`, `summary.json` and
//! SVG charts of load against separation, real area against load and
//! contact count against load.

use super::{curve_csv, Summary};
use crate::error::{Error, Result};
use crate::loading::State;
use crate::study::plan::Plan;
use crate::study::plot::{Chart, Series};
use crate::study::run::Results;
use std::path::{Path, PathBuf};

/// A display unit for a set of values: the SI prefix that puts the largest
/// magnitude in `[1, 1000)`, e.g. `(1e-6, "u")`.
pub fn si_prefix(values: impl Iterator<Item = f64>) -> (f64, &'static str) {
    let max = values
        .filter(|v| v.is_finite())
        .fold(0.0f64, |m, v| m.max(v.abs()));
    const PREFIXES: [(f64, &str); 9] = [
        (1e-18, "a"),
        (1e-15, "f"),
        (1e-12, "p"),
        (1e-9, "n"),
        (1e-6, "u"),
        (1e-3, "m"),
        (1.0, ""),
        (1e3, "k"),
        (1e6, "M"),
    ];
    if max == 0.0 {
        return (1.0, "");
    }
    PREFIXES
        .iter()
        .rev()
        .find(|(s, _)| max >= *s)
        .copied()
        .unwrap_or(PREFIXES[0])
}

/// A display unit for areas: the length prefix that puts the largest
/// `sqrt(area)` in `[1, 1000)`, squared, e.g. `(1e-12, "u")` for um^2.
pub fn si_prefix_area(values: impl Iterator<Item = f64>) -> (f64, &'static str) {
    let (s, p) = si_prefix(values.map(|v| v.abs().sqrt()));
    (s * s, p)
}

/// Writes `curve.csv`, `summary.json` and the charts the scene's outputs
/// allow into `dir` (created if missing). Returns the files written.
///
/// # Errors
/// [`Error::Invalid`] naming `out` when the directory or a file cannot be
/// written.
pub fn write_outputs(plan: &Plan, results: &Results, dir: &Path) -> Result<Vec<PathBuf>> {
    let io = |e: std::io::Error| Error::invalid("out", format!("{}: {e}", dir.display()));
    std::fs::create_dir_all(dir).map_err(io)?;
    let mut written = Vec::new();
    let csv = dir.join("curve.csv");
    std::fs::write(&csv, curve_csv(results, plan)).map_err(io)?;
    written.push(csv);
    if let Some(text) = super::montecarlo_csv(results) {
        let path = dir.join("montecarlo.csv");
        std::fs::write(&path, text).map_err(io)?;
        written.push(path);
    }
    let json = dir.join("summary.json");
    std::fs::write(&json, Summary::new(plan, results).to_json() + "\n").map_err(io)?;
    written.push(json);
    for chart in charts(plan, results) {
        let path = dir.join(&chart.0);
        chart.1.write_svg(&path, 800, 560)?;
        written.push(path);
    }
    written.extend(super::topography::write_charts(plan, dir)?);
    Ok(written)
}

/// The charts of a run: `(file name, chart)`.
pub fn charts(plan: &Plan, results: &Results) -> Vec<(String, Chart)> {
    let o = plan.scene.outputs;
    let c = &results.curve;
    let legs = [("approach", &c.approach), ("retraction", &c.retract)];
    let title = plan.scene.title.clone().unwrap_or_default();
    let all = || c.approach.iter().chain(&c.retract);
    let (ls, lp) = si_prefix(all().filter_map(|s| s.load()));
    let (ds, dp) = si_prefix(all().map(|s| s.separation));
    let mut out = Vec::new();
    let pick = |f: &dyn Fn(&State) -> Option<(f64, f64)>, leg: &[State]| -> Vec<(f64, f64)> {
        leg.iter().filter_map(f).collect()
    };
    if o.load {
        let mut series: Vec<Series> = legs
            .iter()
            .map(|(name, leg)| Series {
                label: (*name).into(),
                points: pick(&|s| Some((s.separation / ds, s.load()? / ls)), leg),
            })
            .collect();
        if let Some(m) = &results.montecarlo {
            for (name, leg) in [
                ("Monte Carlo approach", &m.curve.approach),
                ("Monte Carlo retraction", &m.curve.retract),
            ] {
                series.push(Series {
                    label: name.into(),
                    points: leg
                        .iter()
                        .filter_map(|s| Some((s.separation / ds, s.load()? / ls)))
                        .collect(),
                });
            }
        }
        out.push((
            "load_separation.svg".into(),
            Chart {
                title: format!("{title}: load against separation ({})", plan.law.name),
                x_label: format!("separation d ({dp}m)"),
                y_label: format!("load P ({lp}N), > 0 compressive"),
                series,
                y_range: None,
            },
        ));
        // The adhesive part is invisible at full scale: zoom on it.
        if let Some(p) = results.pull_off {
            let (ps, pp) = si_prefix([p.load].into_iter());
            let series = legs
                .iter()
                .map(|(name, leg)| Series {
                    label: (*name).into(),
                    points: pick(&|s| Some((s.separation / ds, s.load()? / ps)), leg),
                })
                .collect();
            let m = p.load.abs() / ps;
            out.push((
                "load_separation_adhesive.svg".into(),
                Chart {
                    title: format!("{title}: adhesive range, pull-off {:.3} {pp}N", p.load / ps),
                    x_label: format!("separation d ({dp}m)"),
                    y_label: format!("load P ({pp}N), < 0 tensile"),
                    series,
                    y_range: Some((-1.3 * m, 3.0 * m)),
                },
            ));
        }
    }
    if o.load && o.area {
        let (s_a, p_a) = si_prefix_area(all().filter_map(|s| s.area()));
        let series = legs
            .iter()
            .map(|(name, leg)| Series {
                label: (*name).into(),
                points: pick(&|s| Some((s.load()? / ls, s.area()? / s_a)), leg),
            })
            .collect();
        out.push((
            "area_load.svg".into(),
            Chart {
                title: format!("{title}: real contact area against load"),
                x_label: format!("load P ({lp}N)"),
                y_label: format!("real contact area ({p_a}m^2)"),
                series,
                y_range: None,
            },
        ));
    }
    if o.load && o.count {
        let series = legs
            .iter()
            .map(|(name, leg)| Series {
                label: (*name).into(),
                points: pick(&|s| Some((s.load()? / ls, s.count()?)), leg),
            })
            .collect();
        out.push((
            "count_load.svg".into(),
            Chart {
                title: format!("{title}: number of contacts against load"),
                x_label: format!("load P ({lp}N)"),
                y_label: "number of contacts (-)".into(),
                series,
                y_range: None,
            },
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn prefixes_put_the_largest_value_in_one_to_a_thousand() {
        assert_eq!(si_prefix([2.5e-6, -1e-7].into_iter()), (1e-6, "u"));
        assert_eq!(si_prefix([999e-9].into_iter()), (1e-9, "n"));
        assert_eq!(si_prefix([0.0].into_iter()), (1.0, ""));
        assert_eq!(si_prefix([f64::NAN, 3.0].into_iter()), (1.0, ""));
        let (s, p) = si_prefix_area([2.2e-11].into_iter());
        assert_eq!(p, "u");
        assert!((s - 1e-12).abs() < 1e-27);
    }
}
