//! `asperity sweep` / `asperity merge`: a real sweep killed with SIGKILL and
//! resumed ends with the same file as an uninterrupted one; shards merged
//! reproduce it exactly; bad arguments exit 2.
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_asperity"))
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("asperity-cli-sweep-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A scene slow enough (tens of ms a point) to be killed mid-sweep.
fn slow_scene(dir: &Path) -> PathBuf {
    let base = std::fs::read_to_string(format!(
        "{}/examples/scenes/mems-gold.toml",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap();
    // Maugis-Dugdale without the full-solver reference and the pull-off
    // populations: `auto` would take the long-range calibrated law, whose
    // populations cost seconds a point.
    let text = base
        .replacen("points = 200", "points = 300", 1)
        .replacen("kind = \"auto\"", "kind = \"maugis\"", 1)
        .replacen("rtol = 1e-6", "rtol = 1e-9\nmodel_error = false", 1)
        .replacen("[outputs]", "[outputs]\npull_off_population = false", 1);
    assert!(text.contains("kind = \"maugis\"") && text.contains("pull_off_population = false"));
    let path = dir.join("slow.toml");
    std::fs::write(&path, text).unwrap();
    path
}

const VARY: [&str; 4] = [
    "--vary",
    "surface.sigma=3e-9:7e-9:8",
    "--vary",
    "surface.density=5e11:2e12:6",
];

fn sweep(scene: &Path, out: &Path, extra: &[&str]) -> (i32, String) {
    let o = bin()
        .arg("sweep")
        .arg(scene)
        .args(VARY)
        .args(["--threads", "1", "--out"])
        .arg(out)
        .args(extra)
        .output()
        .unwrap();
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

fn rows(path: &Path) -> usize {
    std::fs::read_to_string(path)
        .map(|t| t.lines().count().saturating_sub(1))
        .unwrap_or(0)
}

#[test]
fn killed_sweep_resumes_to_the_same_file_and_shards_merge_to_it() {
    let dir = tmp("kill");
    let scene = slow_scene(&dir);
    let full = dir.join("full");
    let (code, err) = sweep(&scene, &full, &[]);
    assert_eq!(code, 0, "{err}");
    let reference = std::fs::read(full.join("results.csv")).unwrap();
    let text = String::from_utf8(reference.clone()).unwrap();
    assert_eq!(text.lines().count(), 1 + 48);
    assert!(text.lines().skip(1).all(|l| l.contains(",ok,")), "{text}");

    // Kill a real sweep after a few rows have landed.
    let part = dir.join("part");
    let mut child = bin()
        .arg("sweep")
        .arg(&scene)
        .args(VARY)
        .args(["--threads", "1", "--out"])
        .arg(&part)
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let t0 = Instant::now();
    let csv = part.join("results.csv");
    while rows(&csv) < 3 && t0.elapsed() < Duration::from_secs(60) {
        std::thread::sleep(Duration::from_millis(2));
    }
    child.kill().unwrap(); // SIGKILL: no chance to clean up
    child.wait().unwrap();
    let done = rows(&csv);
    assert!(
        (3..48).contains(&done),
        "killed after {done} rows: make the scene slower"
    );
    // As if the kill had landed mid-write.
    let mut torn = std::fs::read_to_string(&csv).unwrap();
    torn.push_str("47,7e-9,123,o");
    std::fs::write(&csv, torn).unwrap();
    let (code, err) = sweep(&scene, &part, &[]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains(&format!("{done} already done")), "{err}");
    assert!(err.contains("half-written"), "{err}");
    assert_eq!(
        std::fs::read(&csv).unwrap(),
        reference,
        "resumed file differs"
    );
    // Rerunning a finished sweep computes nothing and changes nothing.
    let (code, err) = sweep(&scene, &part, &[]);
    assert_eq!(code, 0);
    assert!(err.contains("48 already done, 0 computed"), "{err}");
    assert_eq!(std::fs::read(&csv).unwrap(), reference);

    // Three shards, merged.
    let shards: Vec<PathBuf> = (1..=3).map(|k| dir.join(format!("s{k}"))).collect();
    for (k, s) in shards.iter().enumerate() {
        let (code, err) = sweep(&scene, s, &["--shard", &format!("{}/3", k + 1)]);
        assert_eq!(code, 0, "{err}");
        assert_eq!(rows(&s.join("results.csv")), 16);
    }
    let merged = dir.join("merged");
    let o = bin()
        .arg("merge")
        .args(&shards)
        .arg("--out")
        .arg(&merged)
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert_eq!(
        std::fs::read(merged.join("results.csv")).unwrap(),
        reference
    );
    // A missing shard is a gap.
    let o = bin()
        .arg("merge")
        .args(&shards[..2])
        .arg("--out")
        .arg(dir.join("m2"))
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("16 of 48 points missing"));
    // A different sweep in the same directory is refused.
    let o = bin()
        .arg("sweep")
        .arg(&scene)
        .args(["--vary", "surface.sigma=1e-9:2e-9:3", "--out"])
        .arg(&full)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn latin_hypercube_rows_are_reproducible_and_failures_are_recorded() {
    let dir = tmp("lhs");
    let scene = format!(
        "{}/examples/scenes/soft-jkr.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let run = |out: &str, seed: &str| {
        bin()
            .args([
                "sweep",
                &scene,
                "--vary",
                "adhesion.w=0.01:0.1",
                "--vary",
                "surface.sigma=1e-7:3e-7",
            ])
            .args(["--samples", "5", "--seed", seed, "--out", out])
            .current_dir(&dir)
            .output()
            .unwrap()
    };
    assert_eq!(run("a", "7").status.code(), Some(0));
    assert_eq!(run("b", "7").status.code(), Some(0));
    let a = std::fs::read(dir.join("a/results.csv")).unwrap();
    assert_eq!(a, std::fs::read(dir.join("b/results.csv")).unwrap());
    // A point whose scene is invalid records its error instead of stopping.
    let o = bin()
        .args([
            "sweep",
            &scene,
            "--vary",
            "materials.nu1=0.3:0.6:2",
            "--out",
            "c",
        ])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0));
    let c = std::fs::read_to_string(dir.join("c/results.csv")).unwrap();
    assert!(
        c.contains(",ok,") && c.contains("error: materials.nu1"),
        "{c}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_sweep_arguments_exit_2() {
    let dir = tmp("bad");
    let scene = format!(
        "{}/examples/scenes/soft-jkr.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    for (args, field) in [
        (vec!["--vary", "surface.sigma"], "--vary"),
        (vec!["--vary", "surface.sigma=1:2:0"], "--vary"),
        // A grid without N used to run one point silently.
        (vec!["--vary", "surface.sigma=1e-7:2e-7"], "has no N"),
        (vec!["--vary", "nosuch.x=1:2:3"], "nosuch.x"),
        (vec!["--vary", "title=1:2:3"], "title"),
        (vec!["--vary", "surface.sigma=-1:2:3", "--log"], "--log"),
        (
            vec!["--vary", "surface.sigma=1e-9:2e-9:2", "--shard", "0/2"],
            "--shard",
        ),
        (
            vec!["--vary", "surface.sigma=1e-9:2e-9:2", "--samples", "0"],
            "--samples",
        ),
    ] {
        let o = bin()
            .arg("sweep")
            .arg(&scene)
            .args(&args)
            .current_dir(&dir)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(field), "{args:?}: {err}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_second_sweep_into_a_busy_directory_is_refused() {
    let dir = tmp("lock");
    let scene = slow_scene(&dir);
    let out = dir.join("out");
    let first = bin()
        .arg("sweep")
        .arg(&scene)
        .args(VARY)
        .args(["--threads", "1", "--out"])
        .arg(&out)
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let csv = out.join("results.csv");
    let t0 = Instant::now();
    while rows(&csv) < 1 && t0.elapsed() < Duration::from_secs(60) {
        std::thread::sleep(Duration::from_millis(2));
    }
    // The same sweep (and a different one) started meanwhile must not
    // write into the directory nor exit 0.
    let (code, err) = sweep(&scene, &out, &[]);
    let o = first.wait_with_output().unwrap();
    let first_err = String::from_utf8_lossy(&o.stderr);
    assert!(
        rows(&csv) < 48 || code != 0,
        "the first sweep ended too soon"
    );
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("another asperity sweep"), "{err}");
    assert!(err.contains(&out.display().to_string()), "{err}");
    assert_eq!(o.status.code(), Some(0), "{first_err}");
    assert!(
        first_err.contains("0 already done, 48 computed"),
        "{first_err}"
    );
    // Non-terminal stderr gets plain progress lines, ending at 48/48.
    assert!(
        first_err.contains("sweep: 48/48 points (100 %)"),
        "{first_err}"
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(text.lines().count(), 1 + 48);
    // The lock dies with its process: after the first sweep a rerun works.
    let (code, err) = sweep(&scene, &out, &[]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("48 already done"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn merge_refuses_rows_outside_the_sweep_naming_the_shard() {
    let dir = tmp("mergebad");
    let scene = format!(
        "{}/examples/scenes/soft-jkr.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let shards: Vec<PathBuf> = (1..=2).map(|k| dir.join(format!("s{k}"))).collect();
    for (k, s) in shards.iter().enumerate() {
        let o = bin()
            .args(["sweep", &scene, "--vary", "adhesion.w=0.01:0.1:4"])
            .args(["--shard", &format!("{}/2", k + 1), "--out"])
            .arg(s)
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(0));
    }
    let csv = shards[1].join("results.csv");
    let text = std::fs::read_to_string(&csv).unwrap();
    let last = text.lines().last().unwrap();
    let foreign = format!("99{}", &last[last.find(',').unwrap()..]);
    std::fs::write(&csv, format!("{text}{foreign}\n")).unwrap();
    let o = bin()
        .arg("merge")
        .args(&shards)
        .arg("--out")
        .arg(dir.join("m"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("point 99 lies outside the sweep"), "{err}");
    assert!(err.contains(&shards[1].display().to_string()), "{err}");
    assert!(!err.contains("--out"), "{err}");
    assert!(!dir.join("m/results.csv").exists());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_sweep_where_every_point_fails_exits_1() {
    let dir = tmp("allfail");
    let scene = format!(
        "{}/examples/scenes/soft-jkr.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    // Every value out of the field's own range is refused before any
    // point runs (found by the CLI fuzz): exit 2, nothing written.
    let o = bin()
        .args(["sweep", &scene, "--vary", "materials.nu1=0.6:0.7:2"])
        .args(["--out", "o"])
        .current_dir(&dir)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("materials.nu1: every value is out of"),
        "{err}"
    );
    assert!(!dir.join("o/results.csv").exists());
    // Values in range where every point fails (summits pressed deeper than
    // their radius): the points run, and the sweep exits 1.
    let o = bin()
        .args(["sweep", &scene, "--vary", "surface.sigma=0.5:0.9:2"])
        .args(["--out", "o"])
        .current_dir(&dir)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("every one of the 2 points failed"), "{err}");
    assert!(err.contains("surface.sigma"), "{err}");
    // Rerunning (nothing left to compute) still does not report success.
    let o = bin()
        .args(["sweep", &scene, "--vary", "surface.sigma=0.5:0.9:2"])
        .args(["--out", "o"])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(1));
    std::fs::remove_dir_all(&dir).ok();
}
