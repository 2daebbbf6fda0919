//! Result tables: the curve as CSV and a JSON summary.

use super::plan::Plan;
use super::run::Results;
use crate::gw::GwState;
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
    /// The plan's decisions: `what: choice (why)`.
    pub plan: Vec<String>,
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
            max_area: closest.and_then(|s| s.area),
            max_count: closest.and_then(|s| s.count),
            pull_off_load: results.pull_off.map(|p| p.load),
            pull_off_separation: results.pull_off.map(|p| p.separation),
            hysteresis_energy: results.hysteresis_energy,
            rtol: plan.scene.accuracy.rtol,
            seconds: results.seconds,
            evaluations: results.evaluations,
            plan: plan
                .decisions
                .iter()
                .map(|d| format!("{}: {} ({})", d.what, d.choice, d.why))
                .collect(),
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
    let mut row = |leg: &str, s: &GwState| {
        let _ = writeln!(
            out,
            "{leg},{:e},{},{},{}",
            s.separation,
            cell(s.load, o.load),
            cell(s.area, o.area),
            cell(s.count, o.count)
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
