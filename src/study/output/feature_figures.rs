//! Charts of the optional features: resistance against force (log-log)
//! with `[electrical]`, and load against real area for an elastic-plastic
//! law beside the elastic summits it reduces to as `psi -> 0` (JKR with
//! adhesion, Hertz without).

use crate::loading::Curve;
use crate::study::plan::Plan;
use crate::study::plot::plastic::load_area_chart;
use crate::study::plot::{Chart, Series, Stroke};
use crate::study::run::Results;

/// A feature chart: file name, chart, and whether its axes are logarithmic.
pub type FeatureChart = (String, Chart, bool);

/// The feature charts of a run.
pub fn feature_charts(plan: &Plan, results: &Results) -> Vec<FeatureChart> {
    let title = plan.scene.title.clone().unwrap_or_default();
    let mut out = Vec::new();
    let resistance = plan.quantities.find("resistance").filter(|(_, q)| q.asked);
    if let Some((k, _)) = resistance {
        let points = |leg: &[crate::study::quantity::Record]| -> Vec<(f64, f64)> {
            leg.iter()
                .filter_map(|r| Some((r.state.load()?, r.values[k]?)))
                .collect()
        };
        // With listed states (the actuation range), the force axis starts
        // one decade below the lightest of them: the curve's far tail
        // (down to 1e-14 N) would otherwise take most of the decades.
        let listed = points(&results.listed);
        let from = listed
            .iter()
            .map(|p| p.0)
            .filter(|p| *p > 0.0)
            .fold(f64::INFINITY, f64::min)
            / 10.0;
        let mut approach = points(&results.records.approach);
        if from.is_finite() {
            approach.retain(|p| p.0 >= from);
        }
        let mut series = vec![Series::leg("approach", approach)];
        if !results.listed.is_empty() {
            series.push(Series {
                stroke: Stroke::Markers,
                ..Series::solid("listed states", listed)
            });
        }
        out.push((
            "resistance_force.svg".into(),
            Chart {
                title: format!(
                    "{title}: contact resistance against force ({})",
                    plan.law.name
                ),
                x_label: "force P (N), compressive".into(),
                y_label: "contact resistance R (Ohm)".into(),
                series,
                y_range: None,
                y_symlog: false,
            },
            true,
        ));
    }
    if let Some(elastic) = &results.elastic_approach {
        let c = &results.curve;
        let hertz = Curve {
            program: c.program,
            approach: elastic.clone(),
            retract: Vec::new(),
        };
        let chart = load_area_chart(
            &format!("{title}: load against real area, elastic vs elastic-plastic"),
            &[
                (plan.law.name.clone(), c.clone()),
                (
                    if plan.contact.adhesion.work() > 0.0 {
                        "jkr (elastic)".into()
                    } else {
                        "hertz (elastic)".into()
                    },
                    hertz,
                ),
            ],
        );
        out.push(("load_area_plastic.svg".into(), chart, false));
    }
    out
}
