//! Every chart of every example scene (and of `map`, `surface` and
//! `rough-sphere`) follows the rules of a chart fit for a report, checked
//! on the SVG text:
//! - the file carries its full title in `<title>`;
//! - no text runs off the canvas (width estimated on the high side at
//!   0.6 em per character): long titles are shrunk or wrapped, not clipped;
//! - the tick labels of one axis use one notation (all plain or all
//!   scientific);
//! - no tick label is a round-off value: every non-zero label is at least
//!   1e-12 of its axis's span (`-2.22e-16` where 0 belongs fails).

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
    // baseline; y: right-aligned on one x).
    let mut groups: Vec<(AxisKey, Vec<(String, f64)>)> = Vec::new();
    for t in all.iter().filter(|t| !t.rotated) {
        let Ok(v) = t.body.parse::<f64>() else {
            continue;
        };
        let key = match t.anchor.as_str() {
            "middle" => ("x".to_string(), t.y.round() as i64),
            "end" => ("y".to_string(), t.x.round() as i64),
            _ => continue,
        };
        match groups.iter_mut().find(|(k, _)| *k == key) {
            Some((_, g)) => g.push((t.body.clone(), v)),
            None => groups.push((key, vec![(t.body.clone(), v)])),
        }
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
    std::fs::remove_dir_all(&dir).ok();
}
