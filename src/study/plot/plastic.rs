//! Load against real contact area, elastic against elastic-plastic
//! summits: the chart that shows how much an elastic law over-predicts
//! the load at a given area when summits yield.

use super::{Chart, Series};
use crate::loading::Curve;

/// A chart of load (mN) against real contact area (um^2) on approach, one
/// line per labelled curve (e.g. `hertz`, `kogut-etsion`, ...). Points
/// without a load or an area are skipped.
pub fn load_area_chart(title: &str, curves: &[(String, Curve)]) -> Chart {
    let series = curves
        .iter()
        .map(|(label, c)| {
            Series::leg(
                label.clone(),
                c.approach
                    .iter()
                    .filter_map(|s| Some((s.area()? * 1e12, s.load()? * 1e3)))
                    .collect(),
            )
        })
        .collect();
    Chart {
        title: title.to_string(),
        x_label: "real contact area (um^2)".into(),
        y_label: "load (mN)".into(),
        series,
        y_range: None,
        y_symlog: false,
    }
}
