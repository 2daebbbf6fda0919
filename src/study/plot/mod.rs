//! SVG line charts of result curves (plotters, SVG backend; no fonts or
//! system libraries needed).

mod histogram;
mod loglog;
mod map;
pub mod plastic;
pub mod punch;
pub mod surface;

pub use histogram::Histogram;
pub use map::{adhesion_map_csv, write_adhesion_map};

use crate::error::{Error, Result};
use plotters::prelude::*;
use std::path::Path;

/// One named line of a chart.
#[derive(Debug, Clone)]
pub struct Series {
    /// Legend label.
    pub label: String,
    /// Points `(x, y)` in the chart's units.
    pub points: Vec<(f64, f64)>,
}

/// A line chart: title, axis labels (with units) and series.
#[derive(Debug, Clone)]
pub struct Chart {
    /// Title on top.
    pub title: String,
    /// x-axis label, with units, e.g. `separation d (nm)`.
    pub x_label: String,
    /// y-axis label, with units.
    pub y_label: String,
    /// The lines.
    pub series: Vec<Series>,
    /// Fixed y range (zoom); `None` fits the data.
    pub y_range: Option<(f64, f64)>,
}

pub(crate) const COLOURS: [RGBColor; 4] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
];

impl Chart {
    /// Writes the chart as an SVG file of `width x height` pixels.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `chart` when there is nothing finite to
    /// plot or the file cannot be written.
    pub fn write_svg(&self, path: &Path, width: u32, height: u32) -> Result<()> {
        let finite = |p: &&(f64, f64)| p.0.is_finite() && p.1.is_finite();
        let all: Vec<(f64, f64)> = self
            .series
            .iter()
            .flat_map(|s| s.points.iter().filter(finite).copied())
            .collect();
        if all.is_empty() {
            return Err(Error::invalid(
                "chart",
                format!("{}: no finite points", self.title),
            ));
        }
        let range = |v: Vec<f64>| {
            let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let pad = if hi > lo {
                0.04 * (hi - lo)
            } else {
                1.0 + lo.abs()
            };
            (lo - pad, hi + pad)
        };
        let (x0, x1) = range(all.iter().map(|p| p.0).collect());
        let (y0, y1) = self
            .y_range
            .unwrap_or_else(|| range(all.iter().map(|p| p.1).collect()));
        let fail = |e: String| Error::io(path.display(), e);
        let root = SVGBackend::new(path, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| fail(e.to_string()))?;
        let mut chart = ChartBuilder::on(&root)
            .caption(&self.title, ("sans-serif", 22))
            .margin(12)
            .x_label_area_size(48)
            .y_label_area_size(78)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(|e| fail(e.to_string()))?;
        chart
            .configure_mesh()
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .label_style(("sans-serif", 14))
            .axis_desc_style(("sans-serif", 16))
            .x_label_formatter(&|v| tick(*v))
            .y_label_formatter(&|v| tick(*v))
            .draw()
            .map_err(|e| fail(e.to_string()))?;
        for (i, s) in self.series.iter().enumerate() {
            let colour = COLOURS[i % COLOURS.len()];
            let pts: Vec<(f64, f64)> = s.points.iter().filter(finite).copied().collect();
            let mut runs = clip_runs(&pts, y0, y1).into_iter();
            let first = runs.next().unwrap_or_default();
            chart
                .draw_series(LineSeries::new(first, colour.stroke_width(2)))
                .map_err(|e| fail(e.to_string()))?
                .label(s.label.clone())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
                });
            for run in runs {
                chart
                    .draw_series(LineSeries::new(run, colour.stroke_width(2)))
                    .map_err(|e| fail(e.to_string()))?;
            }
        }
        if self.series.len() > 1 {
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .label_font(("sans-serif", 14))
                .draw()
                .map_err(|e| fail(e.to_string()))?;
        }
        root.present().map_err(|e| fail(e.to_string()))?;
        Ok(())
    }
}

/// Splits a polyline into the runs that lie inside `y0 <= y <= y1`, each
/// run ending exactly on the frame where the line leaves it (linear
/// interpolation), so zoomed charts show no false segments.
fn clip_runs(pts: &[(f64, f64)], y0: f64, y1: f64) -> Vec<Vec<(f64, f64)>> {
    let inside = |y: f64| y >= y0 && y <= y1;
    let cross = |a: (f64, f64), b: (f64, f64)| {
        let edge = if a.1 > y1 || b.1 > y1 { y1 } else { y0 };
        let t = (edge - a.1) / (b.1 - a.1);
        (a.0 + t * (b.0 - a.0), edge)
    };
    let mut runs = Vec::new();
    let mut run: Vec<(f64, f64)> = Vec::new();
    for (i, &p) in pts.iter().enumerate() {
        if inside(p.1) {
            if run.is_empty() && i > 0 {
                run.push(cross(pts[i - 1], p));
            }
            run.push(p);
        } else if !run.is_empty() {
            run.push(cross(pts[i - 1], p));
            runs.push(std::mem::take(&mut run));
        }
    }
    if !run.is_empty() {
        runs.push(run);
    }
    runs
}

/// Compact tick label: plain for moderate magnitudes, else scientific.
pub(crate) fn tick(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 {
        "0".into()
    } else if (1e-2..1e4).contains(&a) {
        let s = format!("{v:.3}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        format!("{v:.2e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_an_svg_with_labels_and_rejects_empty_charts() {
        let dir = std::env::temp_dir().join(format!("asperity-plot-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("c.svg");
        let chart = Chart {
            title: "t".into(),
            x_label: "separation d (nm)".into(),
            y_label: "load P (uN)".into(),
            series: vec![Series {
                label: "approach".into(),
                points: vec![(0.0, 1.0), (1.0, 0.5), (2.0, f64::NAN)],
            }],
            y_range: None,
        };
        chart.write_svg(&path, 400, 300).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        assert!(svg.contains("separation d (nm)") && svg.contains("load P (uN)"));
        let empty = Chart {
            series: vec![],
            ..chart
        };
        assert_eq!(
            empty.write_svg(&path, 400, 300).unwrap_err().field(),
            Some("chart")
        );
        assert_eq!(tick(0.5), "0.5");
        let runs = clip_runs(&[(0.0, 5.0), (1.0, 1.0), (2.0, 0.0), (3.0, 5.0)], -1.0, 3.0);
        assert_eq!(
            runs,
            vec![vec![(0.5, 3.0), (1.0, 1.0), (2.0, 0.0), (2.6, 3.0)]]
        );
        assert_eq!(tick(2.5e-7), "2.50e-7");
        std::fs::remove_dir_all(&dir).ok();
    }
}
