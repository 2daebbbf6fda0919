//! What every chart shares around its data: a title that fits the width
//! (smaller type, then wrapped lines; the full title kept in the SVG's
//! `<title>`), drawing at [`SCALE`] times the nominal size so lines and
//! markers sit at sub-pixel positions, and where the legend goes.

use super::Axis;
use crate::error::{Error, Result};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;

/// Drawing units per nominal pixel: plotters draws on an integer grid, so
/// charts are drawn on a grid `SCALE` times finer and the SVG's `viewBox`
/// maps it back to the nominal size (quarter-pixel positions).
pub const SCALE: u32 = 4;

/// The width of `text` in `font_px` sans-serif, estimated on the high side
/// (0.6 em per character; DejaVu Sans averages about 0.55 em).
pub fn text_width(text: &str, font_px: f64) -> f64 {
    0.6 * font_px * text.chars().count() as f64
}

/// The lines and font size (nominal pixels, as given to plotters) of a
/// title that must fit `width` pixels: 22 px if it fits, else down to
/// 16 px, else wrapped at spaces into as many 16 px lines as needed.
pub fn fit_title(title: &str, width: f64) -> (Vec<String>, f64) {
    // plotters writes a font of `s` "points" as `s / 1.24` pixels.
    let px = |size: f64| size / 1.24;
    for size in [22.0, 20.0, 18.0, 16.0] {
        if text_width(title, px(size)) <= width {
            return (vec![title.to_string()], size);
        }
    }
    let size = 16.0;
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in title.split(' ') {
        let candidate = if line.is_empty() {
            word.to_string()
        } else {
            format!("{line} {word}")
        };
        if text_width(&candidate, px(size)) > width && !line.is_empty() {
            lines.push(std::mem::take(&mut line));
            line = word.to_string();
        } else {
            line = candidate;
        }
    }
    if !line.is_empty() {
        lines.push(line);
    }
    (lines, size)
}

/// A drawing area of `width x height` nominal pixels at [`SCALE`], white,
/// with the fitted title drawn on top; returns the area below the title.
pub fn titled_root<'a>(
    path: &'a Path,
    title: &str,
    width: u32,
    height: u32,
) -> Result<DrawingArea<SVGBackend<'a>, Shift>> {
    titled_root_at(path, title, width, height, SCALE)
}

/// [`titled_root`] drawn at `scale` drawing units per pixel (1 for charts
/// whose sizes are given in pixels); [`finish_svg_at`] with the same scale
/// completes the file.
pub fn titled_root_at<'a>(
    path: &'a Path,
    title: &str,
    width: u32,
    height: u32,
    scale: u32,
) -> Result<DrawingArea<SVGBackend<'a>, Shift>> {
    let fail = |e: String| Error::io(path.display(), e);
    let s = scale as f64;
    let root = SVGBackend::new(path, (width * scale, height * scale)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| fail(e.to_string()))?;
    let (lines, size) = fit_title(title, width as f64 - 24.0);
    let line_h = (size / 1.24 * 1.3 * s) as i32;
    let top = (8.0 * s) as i32;
    for (k, line) in lines.iter().enumerate() {
        let style = ("sans-serif", size * s)
            .into_text_style(&root)
            .pos(Pos::new(HPos::Center, VPos::Top));
        root.draw_text(
            line,
            &style,
            ((width * scale / 2) as i32, top + k as i32 * line_h),
        )
        .map_err(|e| fail(e.to_string()))?;
    }
    let used = top + lines.len() as i32 * line_h;
    Ok(root.split_vertically(used).1)
}

/// Rewrites an SVG drawn at [`SCALE`] to its nominal `width x height`
/// (the `viewBox` keeps the fine grid) and puts the full `title` in the
/// file's `<title>`.
pub fn finish_svg(path: &Path, title: &str, width: u32, height: u32) -> Result<()> {
    finish_svg_at(path, title, width, height, SCALE)
}

/// [`finish_svg`], each `(placeholder, elements)` of `replace` putting the
/// elements in place of the `<text>` element whose text is the placeholder.
pub fn finish_svg_with(
    path: &Path,
    title: &str,
    width: u32,
    height: u32,
    replace: &[(String, String)],
) -> Result<()> {
    finish_svg_replacing(path, title, (width, height, SCALE), replace)
}

/// [`finish_svg`] for a chart drawn at `scale`.
pub fn finish_svg_at(path: &Path, title: &str, width: u32, height: u32, scale: u32) -> Result<()> {
    finish_svg_replacing(path, title, (width, height, scale), &[])
}

fn finish_svg_replacing(
    path: &Path,
    title: &str,
    (width, height, scale): (u32, u32, u32),
    replace: &[(String, String)],
) -> Result<()> {
    let io = |e: std::io::Error| Error::io(path.display(), e);
    let mut svg = std::fs::read_to_string(path).map_err(io)?;
    for (key, elements) in replace {
        let found = svg.find(key.as_str()).and_then(|at| {
            let start = svg[..at].rfind("<text")?;
            let end = at + svg[at..].find("</text>\n")? + "</text>\n".len();
            Some((start, end))
        });
        let Some((start, end)) = found else {
            return Err(Error::io(
                path.display(),
                "a chart's marker placeholder is missing",
            ));
        };
        // Whole slices (`replace_range` splices byte by byte).
        let mut joined = String::with_capacity(svg.len() + elements.len());
        joined.push_str(&svg[..start]);
        joined.push_str(elements);
        joined.push_str(&svg[end..]);
        svg = joined;
    }
    let big = format!("width=\"{}\" height=\"{}\"", width * scale, height * scale);
    let Some(head_end) = svg.find('>') else {
        return Err(Error::io(path.display(), "no <svg> element written"));
    };
    let head = svg[..head_end].replacen(&big, &format!("width=\"{width}\" height=\"{height}\""), 1);
    let escaped = title
        .replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;");
    let out = format!("{head}>\n<title>{escaped}</title>{}", &svg[head_end + 1..]);
    crate::study::atomic::write(path, out).map_err(io)
}

/// A chart of `xa` by `ya` from `builder` (on its drawing area, with its
/// caption if any): `margin` px all round, `x_area` px for the x labels
/// below, `y_area` px for the y labels on the left.
///
/// # Errors
/// The drawing's message.
pub fn axes_chart<'a, DB: DrawingBackend>(
    builder: &mut ChartBuilder<'a, '_, DB>,
    (margin, x_area, y_area): (u32, u32, u32),
    xa: &Axis,
    ya: &Axis,
) -> std::result::Result<ChartContext<'a, DB, Cartesian2d<Axis, Axis>>, String> {
    builder
        .margin(margin)
        .x_label_area_size(x_area)
        .y_label_area_size(y_area)
        .build_cartesian_2d(xa.clone(), ya.clone())
        .map_err(|e| e.to_string())
}

/// Draws the axes of a chart of `xa` by `ya` ([`axes_chart`]): the
/// titles `x_desc`, `y_desc` in `desc_px` px, tick labels in 14 px by the
/// axes' own formatters, and the grid unless `grid` is false.
///
/// # Errors
/// The drawing's message.
pub fn draw_axes<DB: DrawingBackend>(
    chart: &mut ChartContext<'_, DB, Cartesian2d<Axis, Axis>>,
    (xa, ya): (&Axis, &Axis),
    (x_desc, y_desc): (&str, &str),
    desc_px: u32,
    grid: bool,
) -> std::result::Result<(), String> {
    let mut mesh = chart.configure_mesh();
    if !grid {
        mesh.disable_mesh();
    }
    mesh.x_desc(x_desc)
        .y_desc(y_desc)
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", desc_px))
        .x_label_formatter(&|v| xa.label(*v))
        .y_label_formatter(&|v| ya.label(*v))
        .draw()
        .map_err(|e| e.to_string())
}

/// Draws the legend of a chart sized in pixels at `position` (white,
/// framed, 14 px labels), then completes the file at `path` with its
/// `title` ([`finish_svg_at`] at scale 1).
pub fn legend_and_finish<'c, 'a: 'c, CT: plotters::coord::CoordTranslate>(
    chart: &mut ChartContext<'c, SVGBackend<'a>, CT>,
    root: &DrawingArea<SVGBackend<'a>, Shift>,
    path: &Path,
    title: &str,
    (width, height): (u32, u32),
    position: SeriesLabelPosition,
) -> Result<()> {
    let fail = |e: String| Error::io(path.display(), e);
    chart
        .configure_series_labels()
        .position(position)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 14))
        .draw()
        .map_err(|e| fail(e.to_string()))?;
    root.present().map_err(|e| fail(e.to_string()))?;
    finish_svg_at(path, title, width, height, 1)
}

/// The legend corner (fractions of the plot: x from the left, y from the
/// bottom) covering the fewest of `points` (fractions too) for a legend box
/// of `w x h` (fractions); ties go to the upper right.
pub fn legend_corner(points: &[(f64, f64)], w: f64, h: f64) -> SeriesLabelPosition {
    let corners = [
        (SeriesLabelPosition::UpperRight, (1.0 - w, 1.0 - h)),
        (SeriesLabelPosition::UpperLeft, (0.0, 1.0 - h)),
        (SeriesLabelPosition::LowerRight, (1.0 - w, 0.0)),
        (SeriesLabelPosition::LowerLeft, (0.0, 0.0)),
        (SeriesLabelPosition::UpperMiddle, (0.5 - w / 2.0, 1.0 - h)),
        (SeriesLabelPosition::LowerMiddle, (0.5 - w / 2.0, 0.0)),
    ];
    // A margin around the box: data just beside the legend is covered too.
    let m = 0.02;
    let covered = |(x0, y0): (f64, f64)| {
        points
            .iter()
            .filter(|(x, y)| *x >= x0 - m && *x <= x0 + w + m && *y >= y0 - m && *y <= y0 + h + m)
            .count()
    };
    let mut best = corners[0].clone();
    let mut best_n = usize::MAX;
    for (pos, at) in corners {
        let n = covered(at);
        if n < best_n {
            best_n = n;
            best = (pos, at);
        }
    }
    best.0
}

/// Points every `1/n` of the way along a polyline given in fractions (the
/// samples the legend must avoid).
pub fn sample_polyline(points: &[(f64, f64)], n: usize) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
        let len = ((b.0 - a.0).powi(2) + (b.1 - a.1).powi(2)).sqrt();
        let k = ((len * n as f64).ceil() as usize).clamp(1, 4 * n);
        for i in 0..k {
            let t = i as f64 / k as f64;
            out.push((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)));
        }
    }
    out.extend(points.last().copied());
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_titles_shrink_then_wrap_within_the_width() {
        let short = "gold microswitch contact: load against separation";
        assert_eq!(fit_title(short, 776.0), (vec![short.to_string()], 22.0));
        let long = "gold microswitch, law calibrated from the full Lennard-Jones solver: \
                    load against separation (calibrated)";
        let (lines, size) = fit_title(long, 776.0);
        assert!(size < 22.0);
        assert_eq!(lines.join(" "), long);
        for l in &lines {
            assert!(text_width(l, size / 1.24) <= 776.0, "{l}");
        }
    }

    #[test]
    fn the_legend_goes_where_the_data_is_not() {
        // A curve falling from the upper left to the lower right leaves
        // the upper right and the lower left free; fill the lower left.
        let mut pts = sample_polyline(&[(0.0, 1.0), (0.3, 0.2), (1.0, 0.0)], 200);
        pts.extend(sample_polyline(&[(0.0, 0.0), (1.0, 0.05)], 200));
        let pos = legend_corner(&pts, 0.25, 0.15);
        assert!(matches!(pos, SeriesLabelPosition::UpperRight), "{pos:?}");
        let pts = sample_polyline(&[(0.0, 0.0), (1.0, 1.0)], 200);
        assert!(matches!(
            legend_corner(&pts, 0.25, 0.15),
            SeriesLabelPosition::UpperLeft
        ));
    }
}
