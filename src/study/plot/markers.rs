//! Markers: their outlines, and a markers-only series' polygons written
//! as plotters' SVG backend writes them.

use super::Plotted;
use plotters::prelude::*;

/// The outline of marker shape `k` (circle, triangle, square, cross) of
/// radius `r`, as polygon vertices around the origin.
pub(super) fn outline(k: usize, r: i32) -> Vec<(i32, i32)> {
    let rf = r as f64;
    let ring = |n: usize, rr: f64, turn: f64| -> Vec<(i32, i32)> {
        (0..n)
            .map(|j| {
                let a = turn + std::f64::consts::TAU * j as f64 / n as f64;
                ((rr * a.cos()).round() as i32, (rr * a.sin()).round() as i32)
            })
            .collect()
    };
    match k {
        0 => ring(16, rf, 0.0),
        1 => ring(3, 1.3 * rf, -std::f64::consts::FRAC_PI_2),
        2 => ring(4, 1.15 * rf, std::f64::consts::FRAC_PI_4),
        _ => {
            let (a, b) = (r, r / 3);
            vec![
                (-b, -a),
                (b, -a),
                (b, -b),
                (a, -b),
                (a, b),
                (b, b),
                (b, a),
                (-b, a),
                (-b, b),
                (-a, b),
                (-a, -b),
                (-b, -b),
            ]
        }
    }
}

/// The markers of a series drawn with markers only, as the polygons
/// plotters' SVG backend would write (`<polygon opacity=".."
/// fill="#RRGGBB" points="x,y x,y .. "/>`, one line each, the same
/// bytes) at `marks`: a thousand listed states were a thousand trips
/// through its element and attribute machinery, most of the chart's
/// time.
pub(super) fn polygons(
    chart: &Plotted<'_>,
    colour: RGBColor,
    outline: &[(i32, i32)],
    marks: &[(f64, f64)],
) -> String {
    use std::fmt::Write as _;
    let colour = colour.to_backend_color();
    let mut out = String::with_capacity(marks.len() * (48 + 10 * outline.len()));
    if colour.alpha == 0.0 {
        return out;
    }
    let (r, g, b) = colour.rgb;
    let head = format!(
        "<polygon opacity=\"{}\" fill=\"#{r:02X}{g:02X}{b:02X}\" points=\"",
        colour.alpha
    );
    for p in marks {
        let (ax, ay) = chart.backend_coord(p);
        out.push_str(&head);
        for (dx, dy) in outline {
            let _ = write!(out, "{},{} ", ax + dx, ay + dy);
        }
        out.push_str("\"/>\n");
    }
    out
}
