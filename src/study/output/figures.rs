//! Writing a run's outputs to a directory: `curve.csv`, `summary.json` and
//! SVG charts of load against separation, real area against load and
//! contact count against load.

use super::format::si_prefix_area;
use super::{curve_csv, si_prefix, Summary};
use crate::error::{Error, Result};
use crate::loading::State;
use crate::study::plan::Plan;
use crate::study::plot::{Chart, Histogram, Series};
use crate::study::run::Results;
use std::path::{Path, PathBuf};

/// Every file [`write_outputs`] may write: the ones a run does not write
/// this time are removed from the directory, so no output of an earlier run
/// (a `montecarlo.csv` beside a run without a population) is left to be
/// read as this run's.
pub const OUTPUT_FILES: [&str; 12] = [
    "curve.csv",
    "montecarlo.csv",
    "summary.json",
    "load_separation.svg",
    "load_separation_adhesive.svg",
    "area_load.svg",
    "count_load.svg",
    "pull_off_distribution.svg",
    "resistance_force.svg",
    "load_area_plastic.svg",
    "summit_heights.svg",
    "summit_map.svg",
];

/// The first numeric cell of a CSV text that is not finite:
/// `(column, row's first two cells, value)`.
fn non_finite_cell(csv: &str) -> Option<(String, String, String)> {
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next()?.split(',').collect();
    for line in lines {
        let cells: Vec<&str> = line.split(',').collect();
        for (i, c) in cells.iter().enumerate() {
            // Only a cell with a letter other than the exponent's `e` can
            // read as a non-finite number (`inf`, `NaN`, `infinity`): the
            // numbers need no parse.
            if !c
                .bytes()
                .any(|b| b.is_ascii_alphabetic() && !b.eq_ignore_ascii_case(&b'e'))
            {
                continue;
            }
            if c.parse::<f64>().is_ok_and(|v| !v.is_finite()) {
                let col = header.get(i).copied().unwrap_or("?");
                let at = cells.iter().take(2).copied().collect::<Vec<_>>().join(" ");
                return Some((col.to_string(), at, c.to_string()));
            }
        }
    }
    None
}

/// The scalar results of a summary, by name, to check they are finite
/// (JSON has no `inf`: `serde_json` would silently write `null`).
fn summary_values(s: &Summary) -> Vec<(String, Option<f64>)> {
    let mut v: Vec<(String, Option<f64>)> = vec![
        ("tabor_mu".into(), s.tabor_mu),
        ("maugis_lambda".into(), s.maugis_lambda),
        ("contact_modulus".into(), Some(s.contact_modulus)),
        ("summits".into(), s.summits),
        ("start_separation".into(), Some(s.start_separation)),
        ("closest_separation".into(), Some(s.closest_separation)),
    ];
    v.extend(s.headlines.0.iter().map(|(h, x)| (h.key.clone(), *x)));
    v.extend(
        s.scalars()
            .into_iter()
            .skip(s.headlines.0.len())
            .map(|(k, x)| (format!("summary.{k}"), x)),
    );
    if let Some(m) = &s.montecarlo {
        v.push((
            "montecarlo.integral_sampled_pull_off_load".into(),
            m.integral_sampled_pull_off_load,
        ));
    }
    v
}

/// The check [`write_outputs`] makes before writing anything, for callers
/// that keep the outputs in memory: every number of the tables and the
/// summary must be finite.
///
/// # Errors
/// [`Error::Invalid`] naming the quantity when a result is not finite.
pub fn check_outputs(plan: &Plan, results: &Results, summary: &Summary) -> Result<()> {
    let curve = curve_csv(results, plan);
    let mc = super::montecarlo_csv(results, plan);
    let mut tables = vec![("curve.csv", curve.as_str())];
    if let Some(text) = &mc {
        tables.push(("montecarlo.csv", text.as_str()));
    }
    check_finite(&tables, summary)
}

/// Refuses a run's outputs when any number in them is not finite.
fn check_finite(files: &[(&str, &str)], summary: &Summary) -> Result<()> {
    let refuse = |name: &str, what: String| {
        Error::invalid(
            name,
            format!(
                "{what} is not finite, so no output was written: the scene's \
                 magnitudes overflow f64 (check surface.nominal_area, \
                 surface.density and the loads they imply)"
            ),
        )
    };
    for (file, text) in files {
        if let Some((col, at, v)) = non_finite_cell(text) {
            return Err(refuse(col.as_str(), format!("{file}: {col} = {v} at {at}")));
        }
    }
    for (name, v) in summary_values(summary) {
        if let Some(x) = v.filter(|x| !x.is_finite()) {
            return Err(refuse(&name, format!("summary.json: {name} = {x}")));
        }
    }
    Ok(())
}

/// Writes `curve.csv`, `summary.json` (`summary`, the run's
/// [`Summary::new`]), `montecarlo.csv` (with a population) and the charts
/// the scene's outputs allow into `dir` (created if missing), and removes
/// the files of [`OUTPUT_FILES`] this run does not write. Returns the
/// files written.
///
/// Every number is checked before anything is written: a run whose
/// results are not finite (an `inf` load from an absurd nominal area)
/// writes nothing and says which quantity.
///
/// # Errors
/// [`Error::Invalid`] naming the quantity when a result is not finite;
/// [`Error::Invalid`] naming `out` when the directory or a file cannot be
/// written.
pub fn write_outputs(
    plan: &Plan,
    results: &Results,
    summary: &Summary,
    dir: &Path,
) -> Result<Vec<PathBuf>> {
    let plan = results.plan(plan);
    let io = |e: std::io::Error| Error::io(dir.display(), e);
    let curve = curve_csv(results, plan);
    let mc = super::montecarlo_csv(results, plan);
    let mut tables = vec![("curve.csv", curve.as_str())];
    if let Some(text) = &mc {
        tables.push(("montecarlo.csv", text.as_str()));
    }
    check_finite(&tables, summary)?;
    tables.push(("summary.json", ""));
    let charts = charts(plan, results);
    std::fs::create_dir_all(dir).map_err(io)?;
    let current: Vec<&str> = tables
        .iter()
        .map(|t| t.0)
        .chain(charts.iter().map(|c| c.0.as_str()))
        .collect();
    for stale in OUTPUT_FILES.iter().filter(|f| !current.contains(f)) {
        match std::fs::remove_file(dir.join(stale)) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => return Err(io(e)),
            _ => {}
        }
    }
    let mut written = Vec::new();
    let csv = dir.join("curve.csv");
    crate::study::atomic::write(&csv, curve).map_err(io)?;
    written.push(csv);
    if let Some(text) = mc {
        let path = dir.join("montecarlo.csv");
        crate::study::atomic::write(&path, text).map_err(io)?;
        written.push(path);
    }
    let json = dir.join("summary.json");
    crate::study::atomic::write(&json, summary.to_json() + "\n").map_err(io)?;
    written.push(json);
    for chart in charts {
        let path = dir.join(&chart.0);
        chart.1.write_svg(&path, 800, 560)?;
        written.push(path);
    }
    for (name, chart, loglog) in super::feature_charts(plan, results) {
        let path = dir.join(&name);
        // A feature chart with nothing to draw (no compressive state with
        // contact, say) is left out, not an error.
        let drawable =
            chart.series.iter().flat_map(|s| &s.points).any(|p| {
                p.0.is_finite() && p.1.is_finite() && (!loglog || (p.0 > 0.0 && p.1 > 0.0))
            });
        if !drawable {
            continue;
        }
        if loglog {
            chart.write_svg_loglog(&path, 800, 560)?;
        } else {
            chart.write_svg(&path, 800, 560)?;
        }
        written.push(path);
    }
    written.extend(super::topography::write_charts(plan, dir)?);
    if let Some(h) = pull_off_histogram(plan, results) {
        let path = dir.join("pull_off_distribution.svg");
        h.write_svg(&path, 800, 500)?;
        written.push(path);
    }
    Ok(written)
}

/// The pull-off distribution over the populations, with the integral's
/// pull-off, the 5 % and 95 % quantiles and (with `[switch]`) the
/// spring's restoring force marked.
fn pull_off_histogram(plan: &Plan, results: &Results) -> Option<Histogram> {
    let r = results.pull_off_population.as_ref()?;
    let s = r.statistics.as_ref()?;
    let (u, p) = si_prefix(s.values.iter().copied().chain(r.integral));
    let title = plan.scene.title.clone().unwrap_or_default();
    let mut markers = vec![
        ("5 % quantile".to_string(), s.quantile(0.05) / u),
        ("95 % quantile".to_string(), s.quantile(0.95) / u),
    ];
    if let Some(i) = r.integral {
        markers.insert(0, ("GW integral".to_string(), i / u));
    }
    // The spring pulls the switch open with k x travel: a switch whose
    // pull-off is beyond -k x travel sticks.
    if let Some(st) = &results.stiction {
        markers.push((
            "spring k x travel (sticks beyond)".to_string(),
            -st.restoring_force / u,
        ));
    }
    Some(Histogram {
        title: format!(
            "{title}: pull-off of one switch ({} summits, {} populations)",
            r.plan.summits,
            s.len()
        ),
        x_label: format!("pull-off force ({p}N), < 0 tensile"),
        values: s.values.iter().map(|v| v / u).collect(),
        markers,
    })
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
            .map(|(name, leg)| {
                Series::leg(
                    *name,
                    pick(&|s| Some((s.separation / ds, s.load()? / ls)), leg),
                )
            })
            .collect();
        if let Some(m) = &results.montecarlo {
            for (name, leg) in [
                ("Monte Carlo approach", &m.curve.approach),
                ("Monte Carlo retraction", &m.curve.retract),
            ] {
                series.push(Series::leg(
                    name,
                    leg.iter()
                        .filter_map(|s| Some((s.separation / ds, s.load()? / ls)))
                        .collect(),
                ));
            }
        }
        out.push((
            "load_separation.svg".into(),
            Chart {
                title: format!("{title}: load against separation ({})", plan.law.name),
                x_label: format!("separation d ({dp}m)"),
                y_label: format!("load P ({lp}N), > 0 compressive"),
                series,
                // One scale per axis: linear (a symmetric-log axis reads as
                // log and linear mixed); the tensile range has its own
                // zoomed chart below.
                y_range: None,
                y_symlog: false,
            },
        ));
        out.extend(adhesive_chart(results, &title, (ds, dp)));
    }
    if o.load && o.area {
        let (s_a, p_a) = si_prefix_area(all().filter_map(|s| s.area()));
        let series = legs
            .iter()
            .map(|(name, leg)| {
                Series::leg(
                    *name,
                    pick(&|s| Some((s.load()? / ls, s.area()? / s_a)), leg),
                )
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
                y_symlog: false,
            },
        ));
    }
    if o.load && o.count {
        let series = legs
            .iter()
            .map(|(name, leg)| {
                Series::leg(*name, pick(&|s| Some((s.load()? / ls, s.count()?)), leg))
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
                y_symlog: false,
            },
        ));
    }
    out
}

/// The adhesive range of the load curve, invisible at full scale: the
/// integral's legs zoomed on the tensile loads, with a few switches' own
/// retraction curves (their pull-offs can be far deeper than the
/// integral's); `None` without tensile loads. Separations in units of
/// `ds` with prefix `dp`.
fn adhesive_chart(
    results: &Results,
    title: &str,
    (ds, dp): (f64, &str),
) -> Option<(String, Chart)> {
    let c = &results.curve;
    let legs = [("approach", &c.approach), ("retraction", &c.retract)];
    let pick = |f: &dyn Fn(&State) -> Option<(f64, f64)>, leg: &[State]| -> Vec<(f64, f64)> {
        leg.iter().filter_map(f).collect()
    };
    // The adhesive part is invisible at full scale: zoom on it, with a
    // few switches' own retraction curves (their pull-offs can be far
    // deeper than the integral's).
    let examples = results
        .pull_off_population
        .as_ref()
        .map_or(&[][..], |p| &p.examples[..]);
    let deepest = examples
        .iter()
        .flat_map(|(_, c)| c.iter().map(|p| p.1))
        .chain(results.pull_off.map(|p| p.load))
        .fold(0.0f64, f64::min);
    if deepest >= 0.0 {
        return None;
    }
    let (ps, pp) = si_prefix([deepest].into_iter());
    let mut series: Vec<Series> = legs
        .iter()
        .map(|(name, leg)| {
            Series::leg(
                format!("{name} (GW integral)"),
                pick(&|s| Some((s.separation / ds, s.load()? / ps)), leg),
            )
        })
        .collect();
    for (seed, c) in examples {
        series.push(Series::leg(
            format!("one switch (seed {seed}), retraction"),
            c.iter().map(|&(d, p)| (d / ds, p / ps)).collect(),
        ));
    }
    let m = deepest.abs() / ps;
    let integral = results
        .pull_off
        .map_or("none".into(), |p| format!("{:.3} {pp}N", p.load / ps));
    Some((
        "load_separation_adhesive.svg".into(),
        Chart {
            title: format!("{title}: adhesive range, integral pull-off {integral}"),
            x_label: format!("separation d ({dp}m)"),
            y_label: format!("load P ({pp}N), < 0 tensile"),
            series,
            y_range: Some((-1.3 * m, 3.0 * m)),
            y_symlog: false,
        },
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn non_finite_cells_are_found_with_their_column() {
        let ok = "leg,separation_m,load_N\napproach,1e-9,2e0\nretract,1e-9,\n";
        assert_eq!(non_finite_cell(ok), None);
        let bad = "leg,separation_m,load_N\napproach,1e-9,2e0\napproach,2e-9,inf\n";
        assert_eq!(
            non_finite_cell(bad),
            Some(("load_N".into(), "approach 2e-9".into(), "inf".into()))
        );
        assert!(non_finite_cell("a,b\nNaN,1\n").is_some());
    }
}
