//! The adhesion map (after Johnson & Greenwood 1997): over Tabor parameter
//! and load, where each analytic law stays within a tolerance of the full
//! Lennard-Jones solution. Drawn from [`LawErrorTable`], the same measured
//! errors the planner chooses laws by.

use super::frame;
use crate::error::{Error, Result};
use crate::law::errors::LawErrorTable;
use crate::law::LawKind;
use plotters::prelude::*;
use std::fmt::Write as _;
use std::path::Path;

/// Laws shown on the map, one panel each.
pub const MAP_LAWS: [LawKind; 5] = [
    LawKind::Hertz,
    LawKind::Bradley,
    LawKind::Dmt,
    LawKind::Jkr,
    LawKind::Maugis,
];

/// The map as CSV: `mu,load_bar,<law>...` with 1 where the law is within
/// `tol` (relative load error, see [`crate::law::errors`]), 0 where not.
pub fn adhesion_map_csv(table: &LawErrorTable, tol: f64) -> String {
    let mut out = String::from("mu,load_bar");
    for k in MAP_LAWS {
        out.push(',');
        out.push_str(k.name());
    }
    out.push('\n');
    for (i, mu) in table.mu.iter().enumerate() {
        for (j, p) in table.load_bar.iter().enumerate() {
            let _ = write!(out, "{mu:e},{p:e}");
            for k in MAP_LAWS {
                let _ = write!(out, ",{}", u8::from(table.within(k, i, j, tol)));
            }
            out.push('\n');
        }
    }
    out
}

/// Cell edges of a tabulated axis: midpoints, the ends extended by half a
/// step (geometric midpoints for a log axis).
fn edges(x: &[f64], log: bool) -> Vec<f64> {
    let n = x.len();
    let mid = |a: f64, b: f64| if log { (a * b).sqrt() } else { 0.5 * (a + b) };
    let mut e = Vec::with_capacity(n + 1);
    if n == 1 {
        return if log {
            vec![x[0] / 1.5, x[0] * 1.5]
        } else {
            vec![x[0] - 0.5, x[0] + 0.5]
        };
    }
    e.push(if log {
        x[0] * x[0] / mid(x[0], x[1])
    } else {
        2.0 * x[0] - mid(x[0], x[1])
    });
    for w in x.windows(2) {
        e.push(mid(w[0], w[1]));
    }
    e.push(if log {
        x[n - 1] * x[n - 1] / mid(x[n - 2], x[n - 1])
    } else {
        2.0 * x[n - 1] - mid(x[n - 2], x[n - 1])
    });
    e
}

/// Draws the map as an SVG: one panel per law, Tabor parameter `mu` (log)
/// across, load `P/(pi w R)` up, cells filled where the law is within
/// `tol` of the full solution.
///
/// # Errors
/// [`Error::Invalid`] naming `map` for an empty table or a write failure.
pub fn write_adhesion_map(table: &LawErrorTable, tol: f64, path: &Path) -> Result<()> {
    if table.mu.is_empty() || table.load_bar.is_empty() {
        return Err(Error::invalid("map", "the error table is empty"));
    }
    let fail = |e: String| Error::invalid("map", format!("{}: {e}", path.display()));
    let xe = edges(&table.mu, true);
    let ye = edges(&table.load_bar, false);
    let (x0, x1) = (xe[0], xe[xe.len() - 1]);
    let (y0, y1) = (ye[0], ye[ye.len() - 1]);
    let title = format!(
        "Adhesion map: where each law is within {tol:e} of the Lennard-Jones sphere solution"
    );
    let root = frame::titled_root_at(path, &title, 1500, 560, 1)?;
    let (xa, ya) = (super::Axis::log(x0, x1), super::Axis::linear(y0, y1));
    let panels = root.split_evenly((1, MAP_LAWS.len()));
    let colours = [
        RGBColor(120, 120, 120),
        RGBColor(148, 103, 189),
        RGBColor(31, 119, 180),
        RGBColor(214, 39, 40),
        RGBColor(44, 160, 44),
    ];
    for ((panel, kind), colour) in panels.iter().zip(MAP_LAWS).zip(colours) {
        // A law within tolerance nowhere says so over its empty panel.
        let anywhere = (0..table.mu.len())
            .any(|i| (0..table.load_bar.len()).any(|j| table.within(kind, i, j, tol)));
        let caption = if anywhere {
            kind.name().to_string()
        } else {
            format!("{}: nowhere within {tol:e}", kind.name())
        };
        let mut builder = ChartBuilder::on(panel);
        builder.caption(caption, ("sans-serif", 18));
        let mut chart = frame::axes_chart(&mut builder, (8, 40, 48), &xa, &ya).map_err(fail)?;
        let titles = ("Tabor parameter mu", "load P / (pi w R)");
        frame::draw_axes(&mut chart, (&xa, &ya), titles, 14, true).map_err(fail)?;
        let mut cells = Vec::new();
        for i in 0..table.mu.len() {
            for j in 0..table.load_bar.len() {
                if table.within(kind, i, j, tol) {
                    cells.push(Rectangle::new(
                        [(xe[i], ye[j]), (xe[i + 1], ye[j + 1])],
                        colour.mix(0.7).filled(),
                    ));
                }
            }
        }
        chart.draw_series(cells).map_err(|e| fail(e.to_string()))?;
    }
    root.present().map_err(|e| fail(e.to_string()))?;
    frame::finish_svg_at(path, &title, 1500, 560, 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edges_bracket_every_value() {
        let x = [0.01, 0.1, 1.0];
        let e = edges(&x, true);
        assert_eq!(e.len(), 4);
        for (i, v) in x.iter().enumerate() {
            assert!(e[i] < *v && *v < e[i + 1]);
        }
        let e = edges(&[-2.0, 0.0, 4.0], false);
        assert_eq!(e, vec![-3.0, -1.0, 2.0, 6.0]);
    }
}
