//! A histogram of a sample with marked values: the pull-off distribution
//! of a switch's populations, with the integral's pull-off and the
//! quantiles marked.

use super::{frame, Axis, COLOURS};
use crate::error::{Error, Result};
use plotters::prelude::*;
use std::path::Path;

/// A histogram chart: the sample (in display units), its bins, and
/// labelled vertical markers.
#[derive(Debug, Clone)]
pub struct Histogram {
    /// Title on top.
    pub title: String,
    /// x-axis label with its unit.
    pub x_label: String,
    /// The sample, in display units.
    pub values: Vec<f64>,
    /// Vertical markers `(label, x)` in display units.
    pub markers: Vec<(String, f64)>,
}

impl Histogram {
    /// Writes the histogram (counts in `sqrt(n)` bins, 5 to 40) as an SVG
    /// file of `width x height` pixels.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `chart` without finite values; an
    /// [`Error::Io`] when the file cannot be written.
    pub fn write_svg(&self, path: &Path, width: u32, height: u32) -> Result<()> {
        let v: Vec<f64> = self
            .values
            .iter()
            .copied()
            .filter(|x| x.is_finite())
            .collect();
        if v.is_empty() {
            return Err(Error::invalid("chart", "no finite value to draw"));
        }
        let fail = |e: String| Error::io(path.display(), e);
        let marks = self.markers.iter().map(|m| m.1).filter(|x| x.is_finite());
        let lo = v
            .iter()
            .copied()
            .chain(marks.clone())
            .fold(f64::INFINITY, f64::min);
        let hi = v
            .iter()
            .copied()
            .chain(marks)
            .fold(f64::NEG_INFINITY, f64::max);
        let span = if hi > lo { hi - lo } else { lo.abs().max(1.0) };
        let (x0, x1) = (lo - 0.05 * span, hi + 0.05 * span);
        let bins = ((v.len() as f64).sqrt() as usize).clamp(5, 40);
        let w = (hi - lo).max(span * 1e-9) / bins as f64;
        let mut counts = vec![0usize; bins];
        for x in &v {
            counts[(((x - lo) / w) as usize).min(bins - 1)] += 1;
        }
        // Headroom above the bars for the legend (about 20 px per entry of
        // a ~400 px plot): the markers stop at the bars' height, so the
        // legend covers neither bars nor markers.
        let tallest = *counts.iter().max().unwrap_or(&1) as f64;
        let entries = 1.0 + self.markers.len() as f64;
        let top = tallest * 1.08 / (1.0 - (0.06 * entries + 0.04)).max(0.4);
        let mark_top = tallest * 1.08;
        let root = frame::titled_root_at(path, &self.title, width, height, 1)?;
        let (xa, ya) = (Axis::linear(x0, x1), Axis::linear(0.0, top));
        let mut chart = frame::axes_chart(&mut ChartBuilder::on(&root), (12, 48, 64), &xa, &ya)
            .map_err(fail)?;
        let titles = (self.x_label.as_str(), "populations");
        frame::draw_axes(&mut chart, (&xa, &ya), titles, 16, true).map_err(fail)?;
        let bar = COLOURS[0];
        chart
            .draw_series(counts.iter().enumerate().map(|(k, &c)| {
                let a = lo + k as f64 * w;
                Rectangle::new([(a, 0.0), (a + w, c as f64)], bar.mix(0.5).filled())
            }))
            .map_err(|e| fail(e.to_string()))?
            .label(format!("{} populations", v.len()))
            .legend(move |(x, y)| {
                Rectangle::new([(x, y - 5), (x + 20, y + 5)], bar.mix(0.5).filled())
            });
        // Markers differ by dash pattern as well as colour (solid, long
        // dash, short dash, dotted, ...): readable in grey print.
        const DASHES: [(u32, u32); 5] = [(0, 0), (12, 5), (6, 4), (2, 4), (12, 4)];
        for (k, (label, x)) in self.markers.iter().enumerate() {
            let c = COLOURS[1 + k % (COLOURS.len() - 1)];
            let style = c.stroke_width(2);
            let (dash, gap) = DASHES[k % DASHES.len()];
            let line = vec![(*x, 0.0), (*x, mark_top)];
            let drawn = if dash == 0 {
                chart.draw_series(LineSeries::new(line, style))
            } else {
                chart.draw_series(DashedLineSeries::new(line, dash, gap, style))
            };
            drawn
                .map_err(|e| fail(e.to_string()))?
                .label(label.clone())
                .legend(move |(x, y)| {
                    if dash == 0 {
                        PathElement::new(vec![(x, y), (x + 20, y)], style).into_dyn()
                    } else {
                        plotters::element::DashedPathElement::new(
                            vec![(x, y), (x + 20, y)],
                            dash.min(8),
                            gap.min(4),
                            style,
                        )
                        .into_dyn()
                    }
                });
        }
        let size = (width, height);
        let corner = SeriesLabelPosition::UpperLeft;
        frame::legend_and_finish(&mut chart, &root, path, &self.title, size, corner)
    }
}
