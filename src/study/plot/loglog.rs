//! Log-log line charts (resistance against force): both axes logarithmic,
//! points with a non-positive coordinate left out.

use super::{Axis, Chart};
use crate::error::{Error, Result};
use std::path::Path;

impl Chart {
    /// Writes the chart with logarithmic x and y axes as an SVG file of
    /// `width x height` pixels (the chart's `y_range` is ignored), the
    /// axes spanning the data to the nearest 5 % of a decade.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `chart` when no point has both coordinates
    /// positive and finite, or the file cannot be written.
    pub fn write_svg_loglog(&self, path: &Path, width: u32, height: u32) -> Result<()> {
        let ok = |p: &(f64, f64)| p.0.is_finite() && p.1.is_finite() && p.0 > 0.0 && p.1 > 0.0;
        let all = self.finite_points(ok);
        if all.is_empty() {
            return Err(Error::invalid(
                "chart",
                format!("{}: no positive finite points for log axes", self.title),
            ));
        }
        let span = |v: &mut dyn Iterator<Item = f64>| {
            let (lo, hi) = v.fold((f64::INFINITY, 0.0f64), |(a, b), x| (a.min(x), b.max(x)));
            if hi > lo {
                let pad = 10f64.powf(0.05 * (hi / lo).log10().max(0.2));
                (lo / pad, hi * pad)
            } else {
                (lo / 2.0, hi * 2.0)
            }
        };
        let (x0, x1) = span(&mut all.iter().map(|p| p.0));
        let (y0, y1) = span(&mut all.iter().map(|p| p.1));
        self.draw(path, width, height, Axis::log(x0, x1), Axis::log(y0, y1))
    }
}
