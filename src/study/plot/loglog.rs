//! Log-log line charts (resistance against force): both axes logarithmic,
//! points with a non-positive coordinate left out.

use super::{Chart, COLOURS};
use crate::error::{Error, Result};
use plotters::prelude::*;
use std::path::Path;

impl Chart {
    /// Writes the chart with logarithmic x and y axes as an SVG file of
    /// `width x height` pixels (the chart's `y_range` is ignored).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `chart` when no point has both coordinates
    /// positive and finite, or the file cannot be written.
    pub fn write_svg_loglog(&self, path: &Path, width: u32, height: u32) -> Result<()> {
        let ok = |p: &&(f64, f64)| p.0.is_finite() && p.1.is_finite() && p.0 > 0.0 && p.1 > 0.0;
        let all: Vec<(f64, f64)> = self
            .series
            .iter()
            .flat_map(|s| s.points.iter().filter(ok).copied())
            .collect();
        if all.is_empty() {
            return Err(Error::invalid(
                "chart",
                format!("{}: no positive finite points for log axes", self.title),
            ));
        }
        let span = |v: &mut dyn Iterator<Item = f64>| {
            let (lo, hi) = v.fold((f64::INFINITY, 0.0f64), |(a, b), x| (a.min(x), b.max(x)));
            if hi > lo {
                (lo / 1.2, hi * 1.2)
            } else {
                (lo / 2.0, hi * 2.0)
            }
        };
        let (x0, x1) = span(&mut all.iter().map(|p| p.0));
        let (y0, y1) = span(&mut all.iter().map(|p| p.1));
        let fail = |e: String| Error::io(path.display(), e);
        let root = SVGBackend::new(path, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| fail(e.to_string()))?;
        let mut chart = ChartBuilder::on(&root)
            .caption(&self.title, ("sans-serif", 22))
            .margin(12)
            .x_label_area_size(48)
            .y_label_area_size(78)
            .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
            .map_err(|e| fail(e.to_string()))?;
        chart
            .configure_mesh()
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .label_style(("sans-serif", 14))
            .axis_desc_style(("sans-serif", 16))
            .x_label_formatter(&|v| format!("{v:.0e}"))
            .y_label_formatter(&|v| format!("{v:.0e}"))
            .draw()
            .map_err(|e| fail(e.to_string()))?;
        for (i, s) in self.series.iter().enumerate() {
            let colour = COLOURS[i % COLOURS.len()];
            let pts: Vec<(f64, f64)> = s.points.iter().filter(ok).copied().collect();
            chart
                .draw_series(LineSeries::new(pts, colour.stroke_width(2)))
                .map_err(|e| fail(e.to_string()))?
                .label(s.label.clone())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
                });
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
