//! Every chart of every example scene (and of `map`, `surface` and
//! `rough-sphere`) follows the rules of a chart fit for a report, checked
//! on the SVG text:
//! - the file carries its full title in `<title>`;
//! - no text runs off the canvas (width estimated on the high side at
//!   0.6 em per character): long titles are shrunk or wrapped, not clipped;
//! - the tick labels of one axis use one notation (all plain or all
//!   scientific);
//! - no tick label is a round-off value: every non-zero label is at least
//!   1e-12 of its axis's span (`-2.22e-16` where 0 belongs fails);
//! - every axis has at least three tick labels, each at least 11 px high
//!   at the drawn size;
//! - one scale per axis: the labels' positions are linear in their values
//!   or in their logarithms (not linear near zero and logarithmic beyond);
//! - on a logarithmic axis at least half the decades hold data;
//! - the legend box covers no data (lines, bars, markers).

use std::path::{Path, PathBuf};
use std::process::Command;

fn asperity(args: &[&str]) {
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "asperity {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// One `<text>` element: position, anchor, font size, rotation, content.
#[derive(Debug)]
struct Text {
    x: f64,
    y: f64,
    anchor: String,
    size: f64,
    rotated: bool,
    body: String,
}

fn attr(tag: &str, name: &str) -> Option<String> {
    let key = format!(" {name}=\"");
    let i = tag.find(&key)? + key.len();
    let j = tag[i..].find('"')? + i;
    Some(tag[i..j].to_string())
}

fn texts(svg: &str) -> Vec<Text> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find("<text") {
        let after = &rest[i..];
        let close = after.find('>').unwrap();
        let tag = &after[..close];
        let end = after.find("</text>").unwrap();
        let body = after[close + 1..end]
            .trim()
            .replace("&lt;", "<")
            .replace("&gt;", ">")
            .replace("&amp;", "&");
        let num = |n: &str| attr(tag, n).and_then(|v| v.parse().ok()).unwrap_or(0.0);
        out.push(Text {
            x: num("x"),
            y: num("y"),
            anchor: attr(tag, "text-anchor").unwrap_or_else(|| "start".into()),
            size: num("font-size"),
            rotated: tag.contains("transform="),
            body,
        });
        rest = &after[end..];
    }
    out
}

/// An axis of tick labels: `("x", baseline)` or `("y", right edge)`.
type AxisKey = (String, i64);

fn view_width(svg: &str) -> f64 {
    let vb = attr(svg, "viewBox").expect("a viewBox");
    vb.split_whitespace().nth(2).unwrap().parse().unwrap()
}

/// Drawn pixels per viewBox unit (the `width` attribute over the viewBox's).
fn drawn_scale(svg: &str) -> f64 {
    let w: f64 = attr(svg, "width")
        .and_then(|w| w.trim_end_matches("px").parse().ok())
        .unwrap_or_else(|| view_width(svg));
    w / view_width(svg)
}

/// The opening tags named `name` (`<polyline ...`, `<rect ...`).
fn tags<'a>(svg: &'a str, name: &str) -> Vec<&'a str> {
    let open = format!("<{name} ");
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find(&open) {
        let after = &rest[i..];
        let end = after.find('>').unwrap_or(after.len());
        out.push(&after[..end]);
        rest = &after[end..];
    }
    out
}

/// An axis-aligned box `(x0, y0, x1, y1)` in viewBox units.
type Frame = (f64, f64, f64, f64);

fn rect_of(tag: &str) -> Option<Frame> {
    let n = |k: &str| attr(tag, k).and_then(|v| v.parse::<f64>().ok());
    let (x, y, w, h) = (n("x")?, n("y")?, n("width")?, n("height")?);
    Some((x, y, x + w, y + h))
}

/// The legend box: a white filled rectangle followed by its outline.
fn legend_box(svg: &str) -> Option<Frame> {
    let rects = tags(svg, "rect");
    rects.windows(2).find_map(|w| {
        let fill = attr(w[0], "fill")?;
        let outline = attr(w[1], "fill")? == "none";
        let r = rect_of(w[0])?;
        (fill == "#FFFFFF" && outline && r.0 > 0.0 && rect_of(w[1]) == Some(r)).then_some(r)
    })
}

/// Whether the segment `a`-`b` passes through the inside of `f`
/// (Liang–Barsky clipping).
fn segment_enters(a: (f64, f64), b: (f64, f64), f: Frame) -> bool {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, a.0 - f.0),
        (dx, f.2 - a.0),
        (-dy, a.1 - f.1),
        (dy, f.3 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    t0 < t1
}

fn points_of(tag: &str) -> Vec<(f64, f64)> {
    attr(tag, "points")
        .unwrap_or_default()
        .split_whitespace()
        .filter_map(|p| {
            let (x, y) = p.split_once(',')?;
            Some((x.parse().ok()?, y.parse().ok()?))
        })
        .collect()
}

/// What the legend box covers: data polylines (not the legend's own
/// samples, which lie inside it) and filled data rectangles.
fn legend_covers(svg: &str) -> Vec<String> {
    let Some(lb) = legend_box(svg) else {
        return Vec::new();
    };
    // One pixel inside the box: a line along its edge is not covered.
    let inner = (lb.0 + 1.0, lb.1 + 1.0, lb.2 - 1.0, lb.3 - 1.0);
    let inside = |p: &(f64, f64)| p.0 >= lb.0 && p.0 <= lb.2 && p.1 >= lb.1 && p.1 <= lb.3;
    let mut out = Vec::new();
    for tag in tags(svg, "polyline") {
        let pts = points_of(tag);
        if pts.is_empty() || pts.iter().all(inside) {
            continue;
        }
        if pts.windows(2).any(|w| segment_enters(w[0], w[1], inner)) {
            out.push(format!("a line through {:?}", pts[0]));
        }
    }
    for tag in tags(svg, "rect") {
        let Some(r) = rect_of(tag) else { continue };
        let fill = attr(tag, "fill").unwrap_or_default();
        if fill == "none" || fill == "#FFFFFF" || (inside(&(r.0, r.1)) && inside(&(r.2, r.3))) {
            continue;
        }
        let overlap = r.0 < inner.2 && r.2 > inner.0 && r.1 < inner.3 && r.3 > inner.1;
        if overlap {
            out.push(format!("a bar at {r:?}"));
        }
    }
    out
}

/// Whether `v` against `pos` lies on one straight line (within 1.5 % of
/// the positions' span: labels sit on whole pixels).
fn collinear(pos: &[f64], v: &[f64]) -> bool {
    let n = pos.len() as f64;
    let (mp, mv) = (pos.iter().sum::<f64>() / n, v.iter().sum::<f64>() / n);
    let sxx: f64 = v.iter().map(|x| (x - mv).powi(2)).sum();
    let sxy: f64 = v.iter().zip(pos).map(|(x, p)| (x - mv) * (p - mp)).sum();
    if sxx == 0.0 {
        return false;
    }
    let slope = sxy / sxx;
    let span = pos.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
        - pos.iter().cloned().fold(f64::INFINITY, f64::min);
    v.iter()
        .zip(pos)
        .all(|(x, p)| (mp + slope * (x - mv) - p).abs() <= 0.015 * span + 1.0)
}

/// The rule violations of one SVG file.
fn violations(path: &Path) -> Vec<String> {
    let svg = std::fs::read_to_string(path).unwrap();
    let name = path.display();
    let mut bad = Vec::new();
    if !svg.contains("<title>") {
        bad.push(format!("{name}: no <title>"));
    }
    let width = view_width(&svg);
    let all = texts(&svg);
    for t in all.iter().filter(|t| !t.rotated && !t.body.is_empty()) {
        let w = 0.6 * t.size * t.body.chars().count() as f64;
        let (left, right) = match t.anchor.as_str() {
            "middle" => (t.x - w / 2.0, t.x + w / 2.0),
            "end" => (t.x - w, t.x),
            _ => (t.x, t.x + w),
        };
        let slack = 0.01 * width;
        if left < -slack || right > width + slack {
            bad.push(format!(
                "{name}: text {:?} spans {left:.0}..{right:.0} of 0..{width:.0}",
                t.body
            ));
        }
    }
    // Tick labels: numeric texts, grouped by axis (x: centred on one
    // baseline; y: right-aligned on one x), each with its position along
    // the axis.
    let scale = drawn_scale(&svg);
    let mut groups: Vec<(AxisKey, Vec<(String, f64)>)> = Vec::new();
    let mut places: Vec<(AxisKey, Vec<f64>)> = Vec::new();
    for t in all.iter().filter(|t| !t.rotated) {
        let Ok(v) = t.body.parse::<f64>() else {
            continue;
        };
        let (key, at) = match t.anchor.as_str() {
            "middle" => (("x".to_string(), t.y.round() as i64), t.x),
            "end" => (("y".to_string(), t.x.round() as i64), t.y),
            _ => continue,
        };
        if t.size * scale < 11.0 - 1e-9 {
            bad.push(format!(
                "{name}: tick label {:?} is {:.1} px high at the drawn size (at least 11)",
                t.body,
                t.size * scale
            ));
        }
        // Side-by-side panels share a baseline: an x label that breaks the
        // run of values (10 then 0.01) starts the next panel's axis.
        let last = places.iter().rposition(|(k, _)| *k == key);
        let same_run = |g: &[(String, f64)]| match g {
            [.., a, b] => (b.1 - a.1).signum() == (v - b.1).signum(),
            [a] => v != a.1,
            [] => true,
        };
        match last.filter(|i| key.0 != "x" || same_run(&groups[*i].1)) {
            Some(i) => {
                groups[i].1.push((t.body.clone(), v));
                places[i].1.push(at);
            }
            None => {
                groups.push((key.clone(), vec![(t.body.clone(), v)]));
                places.push((key, vec![at]));
            }
        }
    }
    for ((key, g), (_, pos)) in groups.iter().zip(&places) {
        let labels: Vec<&str> = g.iter().map(|(s, _)| s.as_str()).collect();
        if g.len() < 3 {
            bad.push(format!(
                "{name}: axis {key:?} has {} tick label(s) (at least 3): {labels:?}",
                g.len()
            ));
            continue;
        }
        let v: Vec<f64> = g.iter().map(|p| p.1).collect();
        let logs: Option<Vec<f64>> = v.iter().map(|x| (*x > 0.0).then(|| x.log10())).collect();
        let log_scale = logs.as_ref().is_some_and(|l| collinear(pos, l)) && !collinear(pos, &v);
        if !collinear(pos, &v) && !log_scale {
            bad.push(format!(
                "{name}: axis {key:?} is neither linear nor logarithmic (one scale per axis): {labels:?}"
            ));
        }
        if log_scale {
            if let Some(why) = empty_decades(&svg, key, pos, logs.as_deref().unwrap()) {
                bad.push(format!("{name}: axis {key:?}: {why}"));
            }
        }
    }
    for c in legend_covers(&svg) {
        bad.push(format!("{name}: the legend covers {c}"));
    }
    for (key, g) in groups.iter().filter(|(_, g)| g.len() >= 2) {
        let labels: Vec<&str> = g.iter().map(|(s, _)| s.as_str()).collect();
        let sci: Vec<bool> = g
            .iter()
            .filter(|(_, v)| *v != 0.0)
            .map(|(s, _)| s.contains('e'))
            .collect();
        if sci.iter().any(|s| *s) && !sci.iter().all(|s| *s) {
            bad.push(format!("{name}: axis {key:?} mixes notations: {labels:?}"));
        }
        let lo = g.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        let hi = g.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
        let span = hi - lo;
        for (s, v) in g {
            if *v != 0.0 && v.abs() < 1e-12 * span {
                bad.push(format!(
                    "{name}: round-off tick {s} on axis {key:?}: {labels:?}"
                ));
            }
        }
    }
    bad
}

/// On a logarithmic axis (label positions `pos` at `log10` values
/// `logs`): the decades between the axis ends that hold no data point,
/// when they are more than half.
fn empty_decades(svg: &str, key: &AxisKey, pos: &[f64], logs: &[f64]) -> Option<String> {
    // position -> log10 value, from the first and last label.
    let (p0, p1, l0, l1) = (pos[0], pos[pos.len() - 1], logs[0], logs[logs.len() - 1]);
    let to_log = |p: f64| l0 + (p - p0) * (l1 - l0) / (p1 - p0);
    let legend = legend_box(svg);
    let in_legend = |p: &(f64, f64)| {
        legend.is_some_and(|b| p.0 >= b.0 && p.0 <= b.2 && p.1 >= b.1 && p.1 <= b.3)
    };
    let data: Vec<f64> = tags(svg, "polyline")
        .into_iter()
        .flat_map(points_of)
        .filter(|p| !in_legend(p))
        .map(|p| to_log(if key.0 == "x" { p.0 } else { p.1 }))
        .collect();
    if data.is_empty() {
        return None;
    }
    let (lo, hi) = (l0.min(l1).floor(), l0.max(l1).ceil());
    let decades = (hi - lo) as i64;
    let held = (0..decades)
        .filter(|d| {
            let (a, b) = (lo + *d as f64, lo + *d as f64 + 1.0);
            data.iter().any(|x| *x >= a && *x <= b)
        })
        .count() as i64;
    (2 * held < decades).then(|| format!("data in {held} of {decades} decades (at least half)"))
}

fn svgs(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "svg"))
        .collect();
    v.sort();
    v
}

#[test]
fn every_chart_of_every_example_follows_the_rules() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let out = std::env::temp_dir().join(format!("asperity-chart-rules-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let mut dirs = Vec::new();
    let mut scenes: Vec<PathBuf> = std::fs::read_dir(root.join("examples/scenes"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    scenes.sort();
    for scene in &scenes {
        let d = out.join(scene.file_stem().unwrap());
        asperity(&["run", scene.to_str().unwrap(), "--out", d.to_str().unwrap()]);
        dirs.push(d);
    }
    let d = out.join("map");
    asperity(&["map", "--tolerance", "0.05", "--out", d.to_str().unwrap()]);
    dirs.push(d);
    let d = out.join("surface");
    asperity(&[
        "surface",
        "examples/data/measured-topography.npy",
        "--pixel-size",
        "5e-8",
        "--out",
        d.to_str().unwrap(),
    ]);
    dirs.push(d);
    let d = out.join("rough");
    asperity(&[
        "rough-sphere",
        "--mu",
        "10",
        "--d",
        "1,0,-1",
        "--rho",
        "0,0.5,1",
        "--out",
        d.to_str().unwrap(),
    ]);
    dirs.push(d);
    let mut checked = 0;
    let mut bad = Vec::new();
    for d in &dirs {
        for f in svgs(d) {
            bad.extend(violations(&f));
            checked += 1;
        }
    }
    assert!(checked >= 60, "only {checked} charts");
    // A law within tolerance nowhere on the map says so over its panel.
    let map = std::fs::read_to_string(out.join("map/map.svg")).unwrap();
    assert!(
        map.contains("hertz: nowhere within 5e-2"),
        "map.svg's empty panel"
    );
    // The switch's resistance chart spends its force decades on the
    // actuation range (listed states 1e-5 .. 5e-4 N), not on the curve's
    // tail down to 1e-14 N: its axis starts a decade below the lightest.
    let svg = std::fs::read_to_string(out.join("rf-mems-switch/resistance_force.svg")).unwrap();
    let lowest = texts(&svg)
        .iter()
        .filter(|t| t.anchor == "middle")
        .filter_map(|t| t.body.parse::<f64>().ok())
        .fold(f64::INFINITY, f64::min);
    assert!(
        (1e-7..=1e-5).contains(&lowest),
        "resistance_force.svg's force axis starts at {lowest:e}"
    );
    assert!(
        bad.is_empty(),
        "{} violations:\n{}",
        bad.len(),
        bad.join("\n")
    );
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn the_check_catches_what_it_looks_for() {
    let dir =
        std::env::temp_dir().join(format!("asperity-chart-rules-self-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("bad.svg");
    let text = |x: f64, y: f64, anchor: &str, body: &str| {
        format!("<text x=\"{x}\" y=\"{y}\" text-anchor=\"{anchor}\" font-size=\"12\">\n{body}\n</text>\n")
    };
    let mut svg = String::from("<svg width=\"800\" height=\"560\" viewBox=\"0 0 800 560\">\n");
    svg += &text(400.0, 10.0, "middle", &"a long title ".repeat(12));
    for (i, l) in ["-1.4", "-0.7", "-2.22e-16"].iter().enumerate() {
        svg += &text(80.0, 100.0 + 50.0 * i as f64, "end", l);
    }
    for (i, l) in ["0", "5000", "1.00e4"].iter().enumerate() {
        svg += &text(100.0 + 100.0 * i as f64, 540.0, "middle", l);
    }
    svg += "</svg>\n";
    std::fs::write(&p, svg).unwrap();
    let v = violations(&p).join("\n");
    assert!(v.contains("no <title>"), "{v}");
    assert!(v.contains("a long title"), "{v}");
    assert!(v.contains("round-off tick -2.22e-16"), "{v}");
    assert!(v.contains("mixes notations"), "{v}");
    // The newer rules, on a second chart drawn at half size: 10 px labels
    // (20 units at 0.5), a symlog-like y axis, a log x axis holding data in
    // one of six decades, two labels on a second x axis, a legend over a line.
    let q = dir.join("bad2.svg");
    let text = |x: f64, y: f64, anchor: &str, body: &str| {
        format!("<text x=\"{x}\" y=\"{y}\" text-anchor=\"{anchor}\" font-size=\"20\">\n{body}\n</text>\n")
    };
    let mut svg = String::from(
        "<svg width=\"800\" height=\"560\" viewBox=\"0 0 1600 1120\">\n<title>t</title>\n",
    );
    for (i, l) in ["-10", "0", "10", "100", "1000"].iter().enumerate() {
        svg += &text(160.0, 1000.0 - 200.0 * i as f64, "end", l);
    }
    for (i, l) in ["1e-6", "1e-5", "1e-4", "1e-3", "1e-2", "1e-1", "1e0"]
        .iter()
        .enumerate()
    {
        svg += &text(200.0 + 200.0 * i as f64, 1080.0, "middle", l);
    }
    svg += &text(300.0, 40.0, "middle", "1");
    svg += &text(500.0, 40.0, "middle", "2");
    svg += "<polyline fill=\"none\" points=\"1300,900 1350,500 1400,100 \"/>\n";
    svg += "<rect x=\"1200\" y=\"400\" width=\"300\" height=\"200\" fill=\"#FFFFFF\"/>\n";
    svg += "<rect x=\"1200\" y=\"400\" width=\"300\" height=\"200\" fill=\"none\"/>\n";
    svg += "</svg>\n";
    std::fs::write(&q, svg).unwrap();
    let v = violations(&q).join("\n");
    assert!(v.contains("10.0 px high"), "{v}");
    assert!(v.contains("neither linear nor logarithmic"), "{v}");
    assert!(v.contains("data in 1 of 6 decades"), "{v}");
    assert!(v.contains("has 2 tick label(s)"), "{v}");
    assert!(v.contains("the legend covers a line"), "{v}");
    std::fs::remove_dir_all(&dir).ok();
}
