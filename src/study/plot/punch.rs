//! Chart of load against depth for the wavy punch (as the paper's Figs. 3 and 7): the exact
//! equilibrium curve, the displacement-controlled loading and unloading paths (with their
//! jumps) and the two envelopes.

use super::{frame, Axis, COLOURS};
use crate::error::{Error, Result};
use crate::punch::{Envelope, Evolution, WavyPunch};
use plotters::prelude::*;
use std::path::Path;

/// One series to draw: label, points, colour, stroke width.
type Styled<'a> = (&'a str, &'a Vec<(f64, f64)>, RGBColor, u32);

/// The series of the chart, each a list of `(depth m, load N)`.
#[derive(Debug, Clone)]
pub struct PunchChart {
    /// Title on top.
    pub title: String,
    /// Exact equilibrium curve `(h(a), P(a))`, `a` from 0 to the largest radius reached.
    pub curve: Vec<(f64, f64)>,
    /// Loading path from `h_min` to `h_max`.
    pub loading: Vec<(f64, f64)>,
    /// Unloading path from `h_max` to `h_min`.
    pub unloading: Vec<(f64, f64)>,
    /// Loading envelope `(h_+(a), P_+(a))`.
    pub envelope_loading: Vec<(f64, f64)>,
    /// Unloading envelope `(h_-(a), P_-(a))`.
    pub envelope_unloading: Vec<(f64, f64)>,
}

impl PunchChart {
    /// The series of a displacement-controlled cycle from `h_min` to `h_max` (m).
    ///
    /// # Errors
    /// As [`Evolution::new`]; [`Error::Invalid`] naming `h_min` unless `h_min < h_max`.
    pub fn cycle(punch: &WavyPunch, h_min: f64, h_max: f64) -> Result<Self> {
        if !(h_min < h_max) {
            return Err(Error::invalid("h_min", "must be below h_max"));
        }
        let ev = Evolution::new(punch, h_max)?;
        let a_top = ev.deepest().radius.max(punch.jkr_detach_radius());
        // 40 points a wavelength (at least 2000) for the oscillating curve.
        let n = ((40.0 * a_top / punch.wavelength()) as usize).clamp(2000, 400_000);
        let pt = |s: crate::punch::PunchState| (s.depth, s.load);
        let curve = (1..=n)
            .map(|i| pt(punch.state(a_top * i as f64 / n as f64)))
            .collect();
        let env = |which| {
            (1..=400)
                .map(|i| pt(punch.envelope(a_top * i as f64 / 400.0, which)))
                .collect()
        };
        let along = |from: f64, to: f64, out: &mut Vec<(f64, f64)>| {
            for i in 0..=16 {
                out.push(pt(punch.state(from + (to - from) * i as f64 / 16.0)));
            }
        };
        let mut loading = vec![(h_min.min(0.0), 0.0), (0.0, 0.0)];
        for s in ev.loading_stretches(h_min, h_max) {
            along(s.from, s.to, &mut loading);
        }
        let mut unloading = Vec::new();
        for s in ev.unloading_stretches(h_min, h_max) {
            along(s.from, s.to, &mut unloading);
        }
        if let Some(d) = ev.detach().filter(|d| d.depth > h_min) {
            unloading.push((d.depth, 0.0));
            unloading.push((h_min, 0.0));
        }
        Ok(PunchChart {
            title: format!(
                "wavy punch: A = {}, l/R = {}, 2 pi w/(E* R) = {:.3}",
                punch.amplitude(),
                punch.wavelength() / punch.radius(),
                punch.adhesion_number()
            ),
            curve,
            loading,
            unloading,
            envelope_loading: env(Envelope::Loading),
            envelope_unloading: env(Envelope::Unloading),
        })
    }

    /// Writes the chart as an SVG file of `width x height` pixels; the view spans the two
    /// paths (the exact curve is clipped to it).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `chart` when there is nothing to plot or the file cannot be
    /// written.
    pub fn write_svg(&self, path: &Path, width: u32, height: u32) -> Result<()> {
        let pts: Vec<&(f64, f64)> = self.loading.iter().chain(&self.unloading).collect();
        if pts.is_empty() {
            return Err(Error::invalid("chart", "no path to plot"));
        }
        let span = |f: fn(&(f64, f64)) -> f64| {
            let lo = pts.iter().map(|p| f(p)).fold(f64::INFINITY, f64::min);
            let hi = pts.iter().map(|p| f(p)).fold(f64::NEG_INFINITY, f64::max);
            let pad = 0.06 * (hi - lo).max(f64::MIN_POSITIVE);
            (lo - pad, hi + pad)
        };
        let ((x0, x1), (y0, y1)) = (span(|p| p.0), span(|p| p.1));
        let fail = |e: String| Error::io(path.display(), e);
        let root = frame::titled_root_at(path, &self.title, width, height, 1)?;
        let (xa, ya) = (Axis::linear(x0, x1), Axis::linear(y0, y1));
        let mut chart = frame::axes_chart(&mut ChartBuilder::on(&root), (12, 48, 78), &xa, &ya)
            .map_err(fail)?;
        let titles = ("depth h (m)", "load P (N)");
        frame::draw_axes(&mut chart, (&xa, &ya), titles, 16, true).map_err(fail)?;
        let grey = RGBColor(190, 190, 190);
        let inside = |p: &&(f64, f64)| p.0 >= x0 && p.0 <= x1 && p.1 >= y0 && p.1 <= y1;
        let series: [Styled; 5] = [
            ("exact equilibrium curve", &self.curve, grey, 1),
            ("loading envelope", &self.envelope_loading, COLOURS[2], 1),
            (
                "unloading envelope",
                &self.envelope_unloading,
                COLOURS[3],
                1,
            ),
            ("loading path", &self.loading, COLOURS[1], 2),
            ("unloading path", &self.unloading, COLOURS[0], 2),
        ];
        for (label, pts, colour, width) in series {
            // Break the line where it leaves the view, so nothing is drawn outside.
            let mut runs: Vec<Vec<(f64, f64)>> = vec![vec![]];
            for p in pts {
                if inside(&p) {
                    runs.last_mut().unwrap().push(*p);
                } else if !runs.last().unwrap().is_empty() {
                    runs.push(vec![]);
                }
            }
            let style = colour.stroke_width(width);
            // Unloading dashed, loading solid: told apart without colour.
            let dashed = label.starts_with("unloading");
            let mut first = true;
            for run in runs.into_iter().filter(|r| r.len() > 1) {
                let drawn = if dashed {
                    chart.draw_series(DashedLineSeries::new(run, 8, 5, style))
                } else {
                    chart.draw_series(LineSeries::new(run, style))
                }
                .map_err(|e| fail(e.to_string()))?;
                if first {
                    let (a, b) = if dashed { (8, 12) } else { (20, 20) };
                    drawn.label(label).legend(move |(x, y)| {
                        EmptyElement::at((x, y))
                            + PathElement::new(vec![(0, 0), (a, 0)], style)
                            + PathElement::new(vec![(b, 0), (20, 0)], style)
                    });
                    first = false;
                }
            }
        }
        let size = (width, height);
        let corner = SeriesLabelPosition::UpperLeft;
        frame::legend_and_finish(&mut chart, &root, path, &self.title, size, corner)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_the_five_series() {
        let p = WavyPunch::new(1.0, 0.05 / (2.0 * std::f64::consts::PI), 1.0, 0.1, 0.03).unwrap();
        let c = PunchChart::cycle(&p, -0.15, 0.12).unwrap();
        assert!(c.loading.len() > 50 && c.unloading.len() > 50);
        assert_eq!(c.unloading.last().unwrap(), &(-0.15, 0.0));
        let dir = std::env::temp_dir().join(format!("asperity-punch-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("punch.svg");
        c.write_svg(&path, 800, 600).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        assert!(svg.contains("unloading envelope") && svg.contains("depth h (m)"));
        assert!(PunchChart::cycle(&p, 0.1, 0.1).is_err());
        std::fs::remove_dir_all(&dir).ok();
    }
}
