//! SVG line charts of result curves (plotters, SVG backend; no fonts or
//! system libraries needed).

pub mod axis;
pub mod frame;
mod histogram;
mod loglog;
mod map;
mod markers;
pub mod plastic;
pub mod punch;
pub mod surface;

pub use histogram::Histogram;
pub use map::{adhesion_map_csv, write_adhesion_map};

pub use axis::Axis;

use crate::error::{Error, Result};
use plotters::coord::ranged1d::Ranged;
use plotters::prelude::*;
use std::path::Path;

/// Marker polygons written after the chart: (placeholder, SVG text) pairs.
type Placeholders = Vec<(String, String)>;

/// A chart's plotting context: an SVG drawing with both axes [`Axis`].
type Plotted<'a> = ChartContext<'a, SVGBackend<'a>, Cartesian2d<Axis, Axis>>;

/// How a series is drawn. Every series also gets its own colour and marker
/// shape (circle, triangle, square, cross, by position), so lines that
/// coincide stay distinguishable, in print too.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Stroke {
    /// A solid line with a few markers (approach, loading).
    #[default]
    Solid,
    /// A dashed line with a few markers (retraction, unloading).
    Dashed,
    /// Markers only, one per point (listed states, measurements).
    Markers,
}

/// One named line of a chart.
#[derive(Debug, Clone)]
pub struct Series {
    /// Legend label.
    pub label: String,
    /// Points `(x, y)` in the chart's units.
    pub points: Vec<(f64, f64)>,
    /// Line style.
    pub stroke: Stroke,
}

impl Series {
    /// A solid series.
    pub fn solid(label: impl Into<String>, points: Vec<(f64, f64)>) -> Series {
        Series {
            label: label.into(),
            points,
            stroke: Stroke::Solid,
        }
    }

    /// A dashed series.
    pub fn dashed(label: impl Into<String>, points: Vec<(f64, f64)>) -> Series {
        Series {
            stroke: Stroke::Dashed,
            ..Series::solid(label, points)
        }
    }

    /// The conventional stroke of a loading leg: dashed for a label that
    /// names a retraction or unloading, solid otherwise.
    pub fn leg(label: impl Into<String>, points: Vec<(f64, f64)>) -> Series {
        let label = label.into();
        let back = label.contains("retract") || label.contains("unload");
        Series {
            stroke: if back { Stroke::Dashed } else { Stroke::Solid },
            ..Series::solid(label, points)
        }
    }
}

/// A line chart: title, axis labels (with units) and series.
#[derive(Debug, Clone)]
pub struct Chart {
    /// Title on top (shrunk or wrapped to fit; kept whole in the SVG's
    /// `<title>`).
    pub title: String,
    /// x-axis label, with units, e.g. `separation d (nm)`.
    pub x_label: String,
    /// y-axis label, with units.
    pub y_label: String,
    /// The lines.
    pub series: Vec<Series>,
    /// Fixed y range (zoom); `None` fits the data.
    pub y_range: Option<(f64, f64)>,
    /// A symmetric-logarithmic y axis when the data span more than three
    /// decades beyond the deepest negative value (or beyond 1e-4 of the
    /// largest when none is negative): loads from pull-off to full
    /// closure. Ignored with `y_range`.
    pub y_symlog: bool,
}

pub(crate) const COLOURS: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(140, 86, 75),
    RGBColor(23, 190, 207),
    RGBColor(127, 127, 127),
];

/// The y magnitude that must stay readable on a symmetric-log axis: the
/// deepest tensile value, or 1e-4 of the largest when none is negative.
fn linear_scale(ys: &[f64]) -> f64 {
    let lo = ys.iter().copied().fold(0.0f64, f64::min);
    let hi = ys.iter().copied().fold(0.0f64, |m, v| m.max(v.abs()));
    if lo < 0.0 {
        -lo
    } else {
        1e-4 * hi
    }
}

impl Chart {
    /// Writes the chart as an SVG file of `width x height` pixels: a
    /// linear x axis; a linear y axis, or with [`Chart::y_symlog`] a
    /// symmetric-logarithmic one when the data span decades, so the
    /// adhesive range and the compressive decades both show.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `chart` when there is nothing finite to
    /// plot or the file cannot be written.
    pub fn write_svg(&self, path: &Path, width: u32, height: u32) -> Result<()> {
        let all = self.finite_points(|p| p.0.is_finite() && p.1.is_finite());
        if all.is_empty() {
            return Err(Error::invalid(
                "chart",
                format!("{}: no finite points", self.title),
            ));
        }
        let (xs, ys): (Vec<f64>, Vec<f64>) = all.iter().copied().unzip();
        // A zoom fits x to the parts of the lines inside it.
        let xs: Vec<f64> = match self.y_range {
            Some((a, b)) => self
                .series
                .iter()
                .flat_map(|s| {
                    let pts: Vec<(f64, f64)> = s
                        .points
                        .iter()
                        .filter(|p| p.0.is_finite() && p.1.is_finite())
                        .copied()
                        .collect();
                    clip_runs(&pts, a, b).into_iter().flatten().map(|p| p.0)
                })
                .collect(),
            None => xs,
        };
        let (x0, x1) = if xs.is_empty() {
            min_max(&all.iter().map(|p| p.0).collect::<Vec<_>>())
        } else {
            min_max(&xs)
        };
        let x = Axis::fit(x0, x1, None);
        let y = match self.y_range {
            Some((a, b)) => Axis::linear(a, b),
            None => {
                let (y0, y1) = min_max(&ys);
                Axis::fit(y0, y1, self.y_symlog.then(|| linear_scale(&ys)))
            }
        };
        self.draw(path, width, height, x, y)
    }

    /// The finite points of every series that pass `keep`.
    fn finite_points(&self, keep: impl Fn(&(f64, f64)) -> bool) -> Vec<(f64, f64)> {
        self.series
            .iter()
            .flat_map(|s| s.points.iter().filter(|p| keep(p)).copied())
            .collect()
    }

    /// Draws the series on the axes `x` and `y`.
    pub(crate) fn draw(
        &self,
        path: &Path,
        width: u32,
        height: u32,
        x: Axis,
        y: Axis,
    ) -> Result<()> {
        let fail = |e: String| Error::io(path.display(), e);
        let s = frame::SCALE as i32;
        let sf = s as f64;
        let mut markers = Vec::new();
        {
            let area = frame::titled_root(path, &self.title, width, height)?;
            let mut chart = ChartBuilder::on(&area)
                .margin(12 * s)
                .x_label_area_size(48 * s)
                .y_label_area_size(78 * s)
                .build_cartesian_2d(x.clone(), y.clone())
                .map_err(|e| fail(e.to_string()))?;
            chart
                .configure_mesh()
                .x_desc(&self.x_label)
                .y_desc(&self.y_label)
                .label_style(("sans-serif", 14.0 * sf))
                .axis_desc_style(("sans-serif", 16.0 * sf))
                .x_label_formatter(&|v| x.label(*v))
                .y_label_formatter(&|v| y.label(*v))
                .bold_line_style(BLACK.mix(0.25).stroke_width(s as u32))
                .light_line_style(BLACK.mix(0.06).stroke_width(s as u32))
                .axis_style(BLACK.stroke_width(s as u32))
                .set_all_tick_mark_size(4 * s)
                .draw()
                .map_err(|e| fail(e.to_string()))?;
            let mut seen = Vec::new();
            for (i, series) in self.series.iter().enumerate() {
                self.draw_one(
                    &mut chart,
                    i,
                    series,
                    (&x, &y),
                    (&mut seen, &mut markers),
                    &fail,
                )?;
            }
            if self.series.len() > 1 {
                self.draw_legend(&mut chart, &seen, &fail)?;
            }
            area.present().map_err(|e| fail(e.to_string()))?;
        }
        frame::finish_svg_with(path, &self.title, width, height, &markers)
    }

    /// Draws series `i` (its line runs clipped to the y range, then its
    /// markers with the legend entry) and adds the points it covers, as
    /// fractions of the plotting area, to `seen`.
    fn draw_one(
        &self,
        chart: &mut Plotted<'_>,
        i: usize,
        series: &Series,
        (x, y): (&Axis, &Axis),
        (seen, markers): (&mut Vec<(f64, f64)>, &mut Placeholders),
        fail: &dyn Fn(String) -> Error,
    ) -> Result<()> {
        let s = frame::SCALE as i32;
        let n = self.series.len();
        let (y_lo, y_hi) = (y.range().start, y.range().end);
        let colour = COLOURS[i % COLOURS.len()];
        let style = colour.stroke_width(2 * s as u32);
        let shape = i % 4;
        let stroke = series.stroke;
        let pts: Vec<(f64, f64)> = series
            .points
            .iter()
            .filter(|p| x.accepts(p.0) && y.accepts(p.1))
            .copied()
            .collect();
        let runs = clip_runs(&pts, y_lo, y_hi);
        for run in &runs {
            seen.extend(frame::sample_polyline(
                &run.iter()
                    .map(|p| (x.fraction(p.0), y.fraction(p.1)))
                    .collect::<Vec<_>>(),
                200,
            ));
            match series.stroke {
                Stroke::Solid => {
                    chart
                        .draw_series(LineSeries::new(run.clone(), style))
                        .map_err(|e| fail(e.to_string()))?;
                }
                Stroke::Dashed => {
                    chart
                        .draw_series(DashedLineSeries::new(run.clone(), 9 * s, 5 * s, style))
                        .map_err(|e| fail(e.to_string()))?;
                }
                Stroke::Markers => {}
            }
        }
        // Markers: every point when markers only, else about ten
        // per series, offset so coinciding series alternate.
        let inside: Vec<(f64, f64)> = pts
            .iter()
            .filter(|p| p.1 >= y_lo && p.1 <= y_hi)
            .copied()
            .collect();
        let every = match series.stroke {
            Stroke::Markers => 1,
            _ => (inside.len() / 10).max(1),
        };
        let offset = if every > 1 { i * every / n.max(1) } else { 0 };
        let marks: Vec<(f64, f64)> = inside.iter().skip(offset).step_by(every).copied().collect();
        let r = if series.stroke == Stroke::Markers {
            4
        } else {
            3
        } * s;
        let outline = markers::outline(shape, r);
        let (first, second, dot) = legend_pieces(shape, stroke, r);
        let line = colour.stroke_width((2 * s) as u32);
        // Markers only: a placeholder where they go, the polygons written
        // by `marker_polygons` and put in its place when the file is done.
        let placeholder = match (stroke, marks.first()) {
            (Stroke::Markers, Some(&first)) => {
                let key = format!("\u{E000}markers-{i}\u{E000}");
                markers.push((
                    key.clone(),
                    markers::polygons(chart, colour, &outline, &marks),
                ));
                Some(Text::new(key, first, ("sans-serif", 10.0)))
            }
            _ => None,
        };
        let drawn = if placeholder.is_some() {
            chart.draw_series(placeholder)
        } else {
            chart.draw_series(
                marks
                    .iter()
                    .map(|&p| EmptyElement::at(p) + Polygon::new(outline.clone(), colour.filled())),
            )
        };
        drawn
            .map_err(|e| fail(e.to_string()))?
            .label(series.label.clone())
            .legend(move |(lx, ly)| {
                EmptyElement::at((lx, ly))
                    + PathElement::new(first.clone(), line)
                    + PathElement::new(second.clone(), line)
                    + Polygon::new(dot.clone(), colour.filled())
            });
        Ok(())
    }

    /// The legend, in the corner of the plotting area that `seen` (the
    /// series' points, as fractions of it) leaves emptiest.
    fn draw_legend(
        &self,
        chart: &mut Plotted<'_>,
        seen: &[(f64, f64)],
        fail: &dyn Fn(String) -> Error,
    ) -> Result<()> {
        let s = frame::SCALE as i32;
        let sf = s as f64;
        let font = 14.0;
        let rows = self.series.len() as f64;
        let widest = self
            .series
            .iter()
            .map(|s| frame::text_width(&s.label, font / 1.24))
            .fold(0.0, f64::max);
        let (pw, ph) = chart.plotting_area().dim_in_pixel();
        let (pw, ph) = (pw as f64 / sf, ph as f64 / sf);
        let w = (widest + 40.0 + 30.0) / pw;
        let h = (rows * font * 1.45 + 20.0) / ph;
        chart
            .configure_series_labels()
            .position(frame::legend_corner(seen, w, h))
            .margin(8 * s)
            .legend_area_size(40 * s)
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK.stroke_width(s as u32))
            .label_font(("sans-serif", font * sf))
            .draw()
            .map_err(|e| fail(e.to_string()))?;
        Ok(())
    }
}

/// A legend entry's pieces, relative to its anchor: a short line in the
/// series' stroke (two pieces when dashed, none for markers only) and its
/// marker outline in the middle.
#[allow(clippy::type_complexity)]
fn legend_pieces(
    k: usize,
    stroke: Stroke,
    r: i32,
) -> (Vec<(i32, i32)>, Vec<(i32, i32)>, Vec<(i32, i32)>) {
    let len = 10 * r;
    let (first, second) = match stroke {
        Stroke::Solid => (vec![(0, 0), (len, 0)], vec![]),
        Stroke::Dashed => (
            vec![(0, 0), (len * 3 / 10, 0)],
            vec![(len * 7 / 10, 0), (len, 0)],
        ),
        Stroke::Markers => (vec![], vec![]),
    };
    let dot = markers::outline(k, r)
        .into_iter()
        .map(|(a, b)| (a + len / 2, b))
        .collect();
    (first, second, dot)
}

/// The smallest and largest of `v`.
fn min_max(v: &[f64]) -> (f64, f64) {
    v.iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(*x), b.max(*x))
        })
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
            series: vec![Series::leg(
                "approach",
                vec![(0.0, 1.0), (1.0, 0.5), (2.0, f64::NAN)],
            )],
            y_range: None,
            y_symlog: false,
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
        let runs = clip_runs(&[(0.0, 5.0), (1.0, 1.0), (2.0, 0.0), (3.0, 5.0)], -1.0, 3.0);
        assert_eq!(
            runs,
            vec![vec![(0.5, 3.0), (1.0, 1.0), (2.0, 0.0), (2.6, 3.0)]]
        );
        std::fs::remove_dir_all(&dir).ok();
    }
}
