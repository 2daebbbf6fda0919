//! Charts of a measured topography: the summit-height histogram against the
//! Gaussian model predicted from the moments, and the summit map.

use super::{frame, Axis, COLOURS};
use crate::error::{Error, Result};
use crate::heights::{Gaussian, HeightDistribution};
use crate::surface::Characterisation;
use plotters::prelude::*;
use std::path::Path;

/// A length unit for axes: nm below 1 um, um below 1 mm, else mm.
fn unit(scale_m: f64) -> (f64, &'static str) {
    if scale_m < 1e-6 {
        (1e-9, "nm")
    } else if scale_m < 1e-3 {
        (1e-6, "um")
    } else {
        (1e-3, "mm")
    }
}

fn fail(path: &Path, e: impl std::fmt::Display) -> Error {
    Error::io(path.display(), e)
}

/// The histogram of summit heights (probability density, `sqrt(N)` bins
/// between 8 and 60) against the Gaussian model of the GW parameters
/// predicted from the moments: mean `4 sqrt(m0/(pi alpha))`, standard
/// deviation `sqrt(m0 (1 - 0.8968/alpha))` (McCool). SVG, 800 x 500.
///
/// # Errors
/// [`Error::Invalid`] named `chart` when the map has fewer than 2 summits
/// or the file cannot be written.
pub fn write_summit_heights(path: &Path, c: &Characterisation) -> Result<()> {
    let n = c.summits.len();
    if n < 2 {
        return Err(Error::invalid(
            "chart",
            format!("{}: {n} summits: no histogram", path.display()),
        ));
    }
    let (u, name) = unit(c.moments.rms_height());
    let h: Vec<f64> = c.summits.iter().map(|s| s.height_m / u).collect();
    let lo = h.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = h.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let bins = ((n as f64).sqrt() as usize).clamp(8, 60);
    let width = ((hi - lo) / bins as f64).max(f64::MIN_POSITIVE);
    let mut counts = vec![0usize; bins];
    for v in &h {
        counts[(((v - lo) / width) as usize).min(bins - 1)] += 1;
    }
    let dens: Vec<f64> = counts
        .iter()
        .map(|&k| k as f64 / (n as f64 * width))
        .collect();
    let mean = c.nayak().mean_height_m / u;
    let sd = c
        .gw_from_moments()
        .sigma_m
        .unwrap_or(c.moments.rms_height())
        / u;
    let (x0, x1) = (lo.min(mean - 4.0 * sd), hi.max(mean + 4.0 * sd));
    let model: Vec<(f64, f64)> = (0..=200)
        .map(|k| {
            let x = x0 + (x1 - x0) * k as f64 / 200.0;
            (x, Gaussian::new().pdf((x - mean) / sd) / sd)
        })
        .collect();
    let ymax = dens
        .iter()
        .chain(model.iter().map(|p| &p.1))
        .copied()
        .fold(0.0, f64::max)
        * 1.08
        // Headroom for the legend in the upper right corner: it covers
        // neither bars nor the curve.
        / 0.8;
    let title = format!("Summit heights ({n} summits)");
    let root = frame::titled_root_at(path, &title, 800, 500, 1)?;
    let (xa, ya) = (Axis::linear(x0, x1), Axis::linear(0.0, ymax));
    let mut chart = frame::axes_chart(&mut ChartBuilder::on(&root), (12, 48, 78), &xa, &ya)
        .map_err(|e| fail(path, e))?;
    let x_desc = format!("summit height above the mean plane ({name})");
    let y_desc = format!("probability density (1/{name})");
    frame::draw_axes(&mut chart, (&xa, &ya), (&x_desc, &y_desc), 16, true)
        .map_err(|e| fail(path, e))?;
    let bar = COLOURS[0];
    chart
        .draw_series(dens.iter().enumerate().map(|(k, d)| {
            let a = lo + k as f64 * width;
            Rectangle::new([(a, 0.0), (a + width, *d)], bar.mix(0.5).filled())
        }))
        .map_err(|e| fail(path, e))?
        .label("measured summits")
        .legend(move |(x, y)| Rectangle::new([(x, y - 5), (x + 20, y + 5)], bar.mix(0.5).filled()));
    let line = COLOURS[1];
    chart
        .draw_series(LineSeries::new(model, line.stroke_width(2)))
        .map_err(|e| fail(path, e))?
        .label("Gaussian, GW parameters from moments")
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], line.stroke_width(2)));
    let corner = SeriesLabelPosition::UpperRight;
    frame::legend_and_finish(&mut chart, &root, path, &title, (800, 500), corner)
}

/// The summit map: every summit at its position (x along a row, y down the
/// columns, origin at pixel (0, 0)), coloured from blue (lowest) to red
/// (highest). SVG, about 700 pixels on the long side.
///
/// # Errors
/// [`Error::Invalid`] named `chart` when there is no summit or the file
/// cannot be written.
pub fn write_summit_map(path: &Path, c: &Characterisation) -> Result<()> {
    if c.summits.is_empty() {
        return Err(Error::invalid(
            "chart",
            format!("{}: no summits: no map", path.display()),
        ));
    }
    let (dx, dy) = (c.pixel_size_m, c.pixel_size_y_m);
    let (w, h) = (c.cols as f64 * dx, c.rows as f64 * dy);
    let (u, name) = unit(w.max(h));
    let (lo, hi) = c
        .summits
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), s| {
            (a.min(s.height_m), b.max(s.height_m))
        });
    let span = (hi - lo).max(f64::MIN_POSITIVE);
    let side = 700.0 / w.max(h);
    // Room on the right for the colour scale.
    let size = (
        ((w * side) as u32).max(200) + 190,
        ((h * side) as u32).max(200) + 70,
    );
    let title = format!("Summits ({}), coloured by height", c.summits.len());
    let root = frame::titled_root_at(path, &title, size.0, size.1, 1)?;
    let (plot, scale_area) = root.split_horizontally(size.0 - 110);
    let (xa, ya) = (
        Axis::linear(0.0, w / u),
        Axis::linear(0.0, h / u).reversed(),
    );
    let mut chart = frame::axes_chart(&mut ChartBuilder::on(&plot), (10, 40, 60), &xa, &ya)
        .map_err(|e| fail(path, e))?;
    let titles = (format!("x ({name})"), format!("y ({name})"));
    frame::draw_axes(&mut chart, (&xa, &ya), (&titles.0, &titles.1), 16, false)
        .map_err(|e| fail(path, e))?;
    let radius = if c.summits.len() > 5000 { 1 } else { 2 };
    chart
        .draw_series(c.summits.iter().map(|s| {
            Circle::new(
                (s.col as f64 * dx / u, s.row as f64 * dy / u),
                radius,
                height_colour((s.height_m - lo) / span).filled(),
            )
        }))
        .map_err(|e| fail(path, e))?;
    colour_scale(&scale_area, lo, hi, unit(c.moments.rms_height())).map_err(|e| fail(path, e))?;
    root.present().map_err(|e| fail(path, e))?;
    frame::finish_svg_at(path, &title, size.0, size.1, 1)
}

/// The colour of a summit at fraction `t` of the height range: blue (low)
/// to red (high).
fn height_colour(t: f64) -> RGBColor {
    let t = t.clamp(0.0, 1.0);
    RGBColor((255.0 * t) as u8, 40, (255.0 * (1.0 - t)) as u8)
}

/// A vertical colour bar from `lo` (bottom) to `hi` (top), heights in m,
/// labelled in `(scale, unit)`.
fn colour_scale(
    area: &DrawingArea<SVGBackend, plotters::coord::Shift>,
    lo: f64,
    hi: f64,
    (u, name): (f64, &str),
) -> std::result::Result<(), String> {
    let axis = Axis::linear(lo / u, hi / u);
    let mut chart = ChartBuilder::on(area)
        .margin_top(10)
        .margin_bottom(50)
        .margin_right(10)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..1.0, axis.clone())
        .map_err(|e| e.to_string())?;
    chart
        .configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_desc(format!("summit height ({name})"))
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 14))
        .y_label_formatter(&|v| axis.label(*v))
        .draw()
        .map_err(|e| e.to_string())?;
    let steps = 64;
    chart
        .draw_series((0..steps).map(|k| {
            let (a, b) = (k as f64 / steps as f64, (k + 1) as f64 / steps as f64);
            let y = |f: f64| (lo + f * (hi - lo)) / u;
            Rectangle::new(
                [(0.0, y(a)), (1.0, y(b))],
                height_colour((a + b) / 2.0).filled(),
            )
        }))
        .map_err(|e| e.to_string())?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::{synthetic::GaussianSurface, Topography};

    #[test]
    fn writes_both_charts_and_refuses_a_map_without_summits() {
        let dir = std::env::temp_dir().join(format!("asperity-surface-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let map = GaussianSurface::new(64, 64, 3.0, 1e-9, 1e-7, 3)
            .unwrap()
            .generate();
        let c = Topography::new(map, 1e-7)
            .unwrap()
            .characterise(true)
            .unwrap();
        write_summit_heights(&dir.join("h.svg"), &c).unwrap();
        write_summit_map(&dir.join("m.svg"), &c).unwrap();
        let svg = std::fs::read_to_string(dir.join("h.svg")).unwrap();
        assert!(
            svg.contains("summit height above the mean plane (nm)"),
            "{svg}"
        );
        let none = Characterisation {
            summits: vec![],
            ..c
        };
        assert_eq!(
            write_summit_map(&dir.join("x.svg"), &none)
                .unwrap_err()
                .field(),
            Some("chart")
        );
        std::fs::remove_dir_all(&dir).ok();
    }
}
