//! Text output a person reads: the report writes each value with its SI
//! prefix and four digits, counts as integers or short decimals, the
//! listed states one unit per column; `summary.json` has no last-bit
//! noise in `k x travel`; a sweep writes `sticks` as `true`/`false`.

use std::path::PathBuf;
use std::process::Command;

fn asperity(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

fn tmp(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("asperity-text-{name}-{}", std::process::id()))
}

#[test]
fn the_switch_report_reads_in_units_and_counts() {
    let dir = tmp("report");
    let report = asperity(&[
        "run",
        "examples/scenes/rf-mems-switch.toml",
        "--out",
        dir.to_str().unwrap(),
    ]);
    let line = |key: &str| {
        report
            .lines()
            .find(|l| l.trim_start().starts_with(key))
            .unwrap_or_else(|| panic!("no {key} line in\n{report}"))
            .to_string()
    };
    // SI prefixes, four digits, no exponent on the headline lines.
    for (key, unit) in [
        ("max load", " uN"),
        ("max real area", " um^2"),
        ("resistance", " mOhm"),
        ("pull-off force", " uN"),
    ] {
        let l = line(key);
        assert!(l.contains(unit) && !l.contains("e-"), "{l}");
    }
    assert!(
        line("stiction").contains("spring k x travel 20.00 uN"),
        "{}",
        line("stiction")
    );
    // A count of expected contacts: a short decimal, not 4.4461e1.
    let contacts = line("max contacts");
    assert!(!contacts.contains('e'), "{contacts}");
    // The listed states: units in the header, no exponent in the cells.
    let head = report
        .lines()
        .position(|l| l.contains("listed states"))
        .unwrap();
    let header = report.lines().nth(head + 1).unwrap();
    assert!(
        header.contains("load uN") && header.contains("separation nm"),
        "{header}"
    );
    for row in report.lines().skip(head + 2).take(6) {
        assert!(!row.contains('e'), "{row}");
    }
    // summary.json: k x travel = 10 N/m x 2 um is 2e-5 N, not 1.9999999999999998e-5.
    let json = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(
        v["stiction"]["restoring_force_N"].as_f64(),
        Some(2e-5),
        "{json}"
    );
    assert!(json.contains("\"restoring_force_N\": 0.00002,"), "{json}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_sweep_writes_sticks_as_true_or_false() {
    let dir = tmp("sweep");
    asperity(&[
        "sweep",
        "examples/scenes/rf-mems-switch.toml",
        "--vary",
        "adhesion.w=0.1:1.0:2",
        "--out",
        dir.to_str().unwrap(),
    ]);
    let csv = std::fs::read_to_string(dir.join("results.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let k = header.iter().position(|h| *h == "sticks").unwrap();
    let values: Vec<&str> = lines.map(|l| l.split(',').nth(k).unwrap()).collect();
    // w = 0.1 J/m^2 reopens, w = 1 J/m^2 sticks (README's stiction map).
    assert_eq!(values, ["false", "true"], "{csv}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn the_plan_says_its_mode_in_words() {
    let plan = asperity(&["run", "examples/scenes/mems-gold.toml", "--plan"]);
    let first = plan.lines().next().unwrap();
    assert!(first.ends_with("(what the scene needs)"), "{first}");
    assert!(!plan.contains("Planned"), "{plan}");
}
