//! docs/performance.md's tables are timings and accuracies measured once on
//! a machine: they are not rerun by the tests, but each must say how to
//! rerun it and where it ran. Every table's section (its heading down to
//! the next heading of the same or a higher level, with the introductions
//! of the sections above it) must hold the command that regenerates it (a
//! code block, or an inline `` `...` `` naming `cargo`, `asperity`, a Python
//! script, `perf stat` or `/usr/bin/time`) and name the CPU (`AMD EPYC`,
//! `Intel(R) Xeon(R)`, or `lscpu` beside the model it printed).
//!
//! The sections in [`NOT_RECORDED`] predate the rule: their runs did not
//! record the CPU (the machine changed between sessions: an Intel Xeon on
//! 2026-11-27, an AMD EPYC on 2026-11-29), or their numbers came from a
//! scratch program, so naming a CPU or a command now would be invented.
//! A new table cannot join them; one that gains its CPU and command must
//! leave the list (the test fails on a stale entry).

use std::path::PathBuf;

/// Sections (their heading line) whose tables lack the CPU, the command or
/// both, with what is missing.
const NOT_RECORDED: &[(&str, &str)] = &[
    ("## COS against exact Maugis–Dugdale", "cpu"),
    ("### Cost of one law evaluation", "cpu"),
    ("### Hertz asperities, Gaussian heights: 1000-point curve (load, area, count)", "cpu"),
    ("### Maugis–Dugdale asperities (lambda = 1), Gaussian heights: approach + retraction, 1000 points per leg (load)", "cpu"),
    ("### Speed (criterion, 10 samples)", "cpu"),
    ("### Mesh convergence (paraboloid, load-controlled pull-off P/(pi w R))", "cpu"),
    ("### Solver vs Maugis–Dugdale (lambda = 1.1570 mu), paraboloid, default resolution", "cpu"),
    ("### True sphere (size ratio rho = R/z0) vs paraboloid, pull-off P/(pi w R)", "cpu"),
    ("### Far-field truncation (mu = 1, default resolution)", "cpu"),
    ("## Calibrated law against the solver", "cpu, command"),
    ("### Convergence to the GW integral", "cpu"),
    ("### Throughput", "cpu"),
    ("## Scenes: planned against everything-on", "cpu"),
    ("## Analytic laws against the full Lennard-Jones solution", "cpu"),
    ("## Wavy punch (`src/punch/`)", "cpu"),
    ("## Contact resistance", "cpu"),
    ("## Shaped asperities", "cpu"),
    ("### Measured tip tables: closed-form Sneddon integrals", "cpu"),
    ("## Elastic-plastic asperities", "cpu"),
    ("## Sphere solver: rescaled meshes", "cpu"),
    ("## Sphere solver: correctness (solver version 3)", "cpu"),
    ("## Sphere solver: contact-radius continuation (solver version 4)", "cpu"),
    ("## Sphere solver: mu up to 100 (solver version 5)", "cpu"),
    ("## Core redesign: criterion medians before and after", "cpu"),
    ("### Goals", "cpu"),
    ("## Top floor reshaped (typed scene, quantities, planner split): instruction counts before and after", "cpu"),
    ("## Python package: `asperity.fn` against the same call in Rust", "cpu"),
    ("## Limits with estimates", "cpu"),
];

/// A heading's level (the number of leading `#`), 0 for other lines.
fn level(line: &str) -> usize {
    if line.starts_with('#') {
        line.len() - line.trim_start_matches('#').len()
    } else {
        0
    }
}

/// Whether line `i` starts a table (a row followed by a delimiter row).
fn starts_table(lines: &[&str], i: usize) -> bool {
    lines[i].starts_with('|')
        && lines.get(i + 1).is_some_and(|next| {
            let t = next.trim();
            t.starts_with('|')
                && t.contains('-')
                && t.chars().all(|c| matches!(c, '|' | '-' | ':' | ' '))
        })
}

/// The heading above line `i` and the text of its section with the
/// introductions of the sections above it.
fn section<'a>(lines: &[&'a str], i: usize) -> (&'a str, String) {
    let head = (0..=i).rev().find(|&k| level(lines[k]) > 0).unwrap_or(0);
    let lvl = level(lines[head]);
    let end = (head + 1..lines.len())
        .find(|&k| (1..=lvl).contains(&level(lines[k])))
        .unwrap_or(lines.len());
    let mut text = lines[head..end].join("\n");
    let mut cur = lvl;
    for k in (0..head).rev() {
        let l = level(lines[k]);
        if l > 0 && l < cur {
            let next = (k + 1..lines.len()).find(|&m| level(lines[m]) > 0).unwrap();
            text = lines[k..next].join("\n") + "\n" + &text;
            cur = l;
        }
    }
    (lines[head], text)
}

/// Whether `text` holds a command: a code block or an inline span that runs
/// something.
fn has_command(text: &str) -> bool {
    const RUNS: [&str; 8] = [
        "cargo ",
        "asperity ",
        "python",
        ".py",
        "perf stat",
        "/usr/bin/time",
        "RAYON_NUM_THREADS",
        "pytest",
    ];
    text.contains("```")
        || text
            .split('`')
            .skip(1)
            .step_by(2)
            .any(|span| RUNS.iter().any(|r| span.contains(r)))
}

fn has_cpu(text: &str) -> bool {
    text.contains("AMD EPYC") || text.contains("Xeon") || text.contains("lscpu")
}

/// What is missing for each table of `md`: (heading, "cpu" / "command" /
/// "cpu, command"), once per section.
fn missing(md: &str) -> (usize, Vec<(String, String)>) {
    let lines: Vec<&str> = md.lines().collect();
    let mut out: Vec<(String, String)> = Vec::new();
    let mut tables = 0;
    for i in 0..lines.len() {
        if !starts_table(&lines, i) {
            continue;
        }
        tables += 1;
        let (head, text) = section(&lines, i);
        let what: Vec<&str> = [(!has_cpu(&text), "cpu"), (!has_command(&text), "command")]
            .into_iter()
            .filter(|(m, _)| *m)
            .map(|(_, w)| w)
            .collect();
        if !what.is_empty() && !out.iter().any(|(h, _)| h == head) {
            out.push((head.to_string(), what.join(", ")));
        }
    }
    (tables, out)
}

#[test]
fn every_performance_table_names_its_command_and_cpu() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("docs/performance.md");
    let md = std::fs::read_to_string(path).unwrap();
    let (tables, found) = missing(&md);
    assert!(tables >= 70, "{tables} tables found");
    let new: Vec<String> = found
        .iter()
        .filter(|(h, w)| !NOT_RECORDED.contains(&(h.as_str(), w.as_str())))
        .map(|(h, w)| format!("{h}: no {w}"))
        .collect();
    assert!(
        new.is_empty(),
        "docs/performance.md: tables without their command or CPU in their section:\n{}",
        new.join("\n")
    );
    let stale: Vec<&str> = NOT_RECORDED
        .iter()
        .filter(|(h, w)| !found.contains(&(h.to_string(), w.to_string())))
        .map(|(h, _)| *h)
        .collect();
    assert!(
        stale.is_empty(),
        "performance_tables.rs: NOT_RECORDED entries now recorded (remove them): {stale:?}"
    );
}

#[test]
fn a_table_without_command_or_cpu_is_found() {
    let md = "# P\n\n## A\nRun `cargo run --release --example a` on AMD EPYC.\n\n\
              | x | y |\n|---|---|\n| 1 | 2 |\n\n### A1\n\n| x |\n|---|\n| 1 |\n\n\
              ## B\nno command here\n\n| x |\n|:--|\n| 1 |\n";
    let (tables, found) = missing(md);
    assert_eq!(tables, 3);
    assert_eq!(
        found,
        vec![("## B".to_string(), "cpu, command".to_string())]
    );
}
