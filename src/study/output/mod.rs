//! Result tables (the curve as CSV, a JSON summary) and the figures.

mod figures;
mod topography;

pub use figures::{charts, si_prefix, si_prefix_area, write_outputs};
pub use topography::{HeadlineJson, MeasuredJson, MomentsJson, TopographySummary};

use crate::loading::State;
use crate::study::plan::Plan;
use crate::study::run::Results;
use serde::Serialize;
use std::fmt::Write as _;

/// The JSON summary of a run (SI units; `null` where not computed).
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    /// Scene title.
    pub title: Option<String>,
    /// Law used.
    pub law: String,
    /// Tabor parameter `mu` of one summit (`null` without adhesion).
    pub tabor_mu: Option<f64>,
    /// Maugis `lambda = 1.1570 mu` (`null` without adhesion).
    pub maugis_lambda: Option<f64>,
    /// Contact modulus `E*` (Pa).
    pub contact_modulus: f64,
    /// Number of summits `eta A_n`.
    pub summits: f64,
    /// Separation where the program started and ended (m).
    pub start_separation: f64,
    /// Closest separation reached (m).
    pub closest_separation: f64,
    /// Points per leg.
    pub points: usize,
    /// Largest approach load (N).
    pub max_load: Option<f64>,
    /// Real contact area at the closest separation (m^2).
    pub max_area: Option<f64>,
    /// Number of contacts at the closest separation.
    pub max_count: Option<f64>,
    /// Pull-off force (N, negative = tensile).
    pub pull_off_load: Option<f64>,
    /// Separation of the pull-off (m).
    pub pull_off_separation: Option<f64>,
    /// Energy lost per cycle (J).
    pub hysteresis_energy: Option<f64>,
    /// Requested relative tolerance.
    pub rtol: f64,
    /// Wall-clock time of the run (s).
    pub seconds: f64,
    /// Law evaluations spent by quadrature.
    pub evaluations: usize,
    /// The explicit population beside the integral, if asked for.
    pub montecarlo: Option<McSummary>,
    /// The plan's decisions: `what: choice (why)`.
    pub plan: Vec<String>,
    /// Where the scene or its results lie outside a model's validity, one
    /// sentence each (empty when none).
    pub warnings: Vec<String>,
    /// The measured map (`[surface] topography`): its characterisation, the
    /// model used and, when asked, the other model's headline numbers.
    /// Absent without a map.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub topography: Option<TopographySummary>,
}

/// The Monte Carlo part of a summary.
#[derive(Debug, Clone, Serialize)]
pub struct McSummary {
    /// Summits drawn.
    pub summits: usize,
    /// Seed.
    pub seed: u64,
    /// Largest approach load of the population (N), scaled to the surface.
    pub max_load: Option<f64>,
    /// Its standard error (N).
    pub max_load_standard_error: Option<f64>,
    /// Most tensile sampled retraction load (N).
    pub pull_off_load: Option<f64>,
    /// The integral's most tensile load at the same sampled separations
    /// (N), to compare with `pull_off_load`.
    pub integral_sampled_pull_off_load: Option<f64>,
    /// Largest deviation from the integral over the curve, in standard
    /// errors (`< 5` expected when the population follows the model).
    pub max_abs_z: Option<f64>,
    /// Wall-clock time of drawing and summing (s).
    pub seconds: f64,
}

impl Summary {
    /// Summarises a run of `plan`.
    pub fn new(plan: &Plan, results: &Results) -> Summary {
        let closest = results.curve.approach.first();
        let adhesive = plan.contact.adhesion.work() > 0.0;
        Summary {
            title: plan.scene.title.clone(),
            law: plan.law.name.clone(),
            tabor_mu: adhesive.then(|| plan.contact.tabor()),
            maugis_lambda: adhesive.then(|| plan.contact.lambda()),
            contact_modulus: plan.contact.contact_modulus,
            summits: plan.surface.summits(),
            start_separation: plan.start,
            closest_separation: results.curve.program.closest,
            points: plan.points,
            max_load: results.max_load().filter(|_| plan.scene.outputs.load),
            max_area: closest.and_then(|s| s.area()),
            max_count: closest.and_then(|s| s.count()),
            pull_off_load: results.pull_off.map(|p| p.load),
            pull_off_separation: results.pull_off.map(|p| p.separation),
            hysteresis_energy: results.hysteresis_energy,
            rtol: plan.scene.accuracy.rtol,
            seconds: results.seconds,
            evaluations: results.evaluations,
            montecarlo: results.montecarlo.as_ref().map(|m| {
                let top = m
                    .curve
                    .approach
                    .iter()
                    .filter_map(|s| s.load().map(|p| (p, s.totals.error(0).unwrap_or(f64::NAN))))
                    .max_by(|a, b| a.0.total_cmp(&b.0));
                McSummary {
                    summits: plan.montecarlo.as_ref().map_or(0, |p| p.summits),
                    seed: plan.montecarlo.as_ref().map_or(0, |p| p.spec.seed),
                    max_load: top.map(|t| t.0),
                    max_load_standard_error: top.map(|t| t.1),
                    pull_off_load: m.pull_off.map(|p| p.load),
                    integral_sampled_pull_off_load: results
                        .curve
                        .sampled_pull_off()
                        .map(|p| p.load),
                    max_abs_z: m.max_abs_z,
                    seconds: m.seconds,
                }
            }),
            plan: plan.decisions.iter().map(|d| d.to_string()).collect(),
            warnings: plan
                .warnings
                .iter()
                .chain(&results.warnings)
                .cloned()
                .collect(),
            topography: topography::summary(plan, results),
        }
    }

    /// Pretty JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default()
    }
}

/// The curve as CSV: one row per separation and leg, columns
/// `leg,separation_m,load_N,area_m2,count` (empty cells for outputs not
/// computed), approach rows from far to near, then retraction rows from
/// near to far (the order of the program).
pub fn curve_csv(results: &Results, plan: &Plan) -> String {
    let mut out = String::from("leg,separation_m,load_N,area_m2,count\n");
    let o = plan.scene.outputs;
    let cell = |x: Option<f64>, asked: bool| match x {
        Some(v) if asked => format!("{v:e}"),
        _ => String::new(),
    };
    let mut row = |leg: &str, s: &State| {
        let _ = writeln!(
            out,
            "{leg},{:e},{},{},{}",
            s.separation,
            cell(s.load(), o.load),
            cell(s.area(), o.area),
            cell(s.count(), o.count)
        );
    };
    for s in results.curve.approach.iter().rev() {
        row("approach", s);
    }
    for s in &results.curve.retract {
        row("retract", s);
    }
    out
}

/// The population's curve as CSV: `leg,separation_m,load_N,load_se_N,
/// area_m2,area_se_m2,count,count_se,z_load,z_area,z_count` (standard
/// errors and deviations from the integral in standard errors), in the
/// order of [`curve_csv`].
pub fn montecarlo_csv(results: &Results) -> Option<String> {
    let m = results.montecarlo.as_ref()?;
    let mut out = String::from(
        "leg,separation_m,load_N,load_se_N,area_m2,area_se_m2,count,count_se,z_load,z_area,z_count\n",
    );
    let cell = |x: Option<f64>| x.map_or(String::new(), |v| format!("{v:e}"));
    let n = m.curve.approach.len();
    let rows = m
        .curve
        .approach
        .iter()
        .enumerate()
        .rev()
        .map(|(i, s)| ("approach", s, m.z[i]))
        .chain(
            m.curve
                .retract
                .iter()
                .enumerate()
                .map(|(i, s)| ("retract", s, m.z[n + i])),
        );
    for (leg, s, z) in rows {
        let se = |i: usize, x: Option<f64>| cell(x.map(|_| s.totals.error(i).unwrap_or(f64::NAN)));
        let _ = writeln!(
            out,
            "{leg},{:e},{},{},{},{},{},{},{},{},{}",
            s.separation,
            cell(s.load()),
            se(0, s.load()),
            cell(s.area()),
            se(1, s.area()),
            cell(s.count()),
            se(2, s.count()),
            cell(z[0]),
            cell(z[1]),
            cell(z[2])
        );
    }
    Some(out)
}
