//! The command line does not lie or crash about its outputs: a closed
//! stdout (`| head`) ends quietly with status 141, a run leaves no file of
//! an earlier run beside its own and lists what it wrote, non-finite
//! results are refused before anything is written, and long runs report
//! progress on a non-terminal stderr.
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_asperity"))
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("asperity-cli-robust-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn scene_path(name: &str) -> String {
    format!("{}/examples/scenes/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn run(args: &[&str], dir: &Path) -> (i32, String, String) {
    let o = bin().args(args).current_dir(dir).output().unwrap();
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// Runs with stdout a pipe whose reader is closed before the program
/// starts (as `| head` does after its lines): the status and stderr.
fn with_closed_stdout(args: &[&str], dir: &Path) -> (Option<i32>, String) {
    let (reader, writer) = std::io::pipe().unwrap();
    drop(reader); // every write to stdout now fails with EPIPE
    let o = bin()
        .args(args)
        .current_dir(dir)
        .stdout(writer)
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn a_closed_stdout_ends_quietly_with_141() {
    let dir = tmp("pipe");
    let scene = scene_path("soft-jkr.toml");
    for args in [
        vec!["law", "--law", "jkr"],
        vec!["law", "--law", "maugis", "--json"],
        vec!["run", &scene, "--out", "o"],
        vec!["run", &scene, "--out", "o", "--json"],
        vec!["run", &scene, "--plan"],
        // A command still printing with println!: the panic hook.
        vec!["fn", "--dist", "gaussian", "--n", "1", "--h", "0,1,2"],
    ] {
        let (code, err) = with_closed_stdout(&args, &dir);
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        assert!(!err.contains("Broken pipe"), "{args:?}: {err}");
        // Bad arguments for `fn` would exit 2 before printing: catch that.
        assert_eq!(code, Some(141), "{args:?}: {err}");
    }
    // The run's files were written before it printed.
    assert!(dir.join("o/curve.csv").exists());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_run_removes_outputs_of_an_earlier_run_and_lists_its_own() {
    let dir = tmp("stale");
    let (code, _, err) = run(
        &["run", &scene_path("montecarlo-gold.toml"), "--out", "o"],
        &dir,
    );
    assert_eq!(code, 0, "{err}");
    assert!(dir.join("o/montecarlo.csv").exists());
    std::fs::write(dir.join("o/notes.txt"), "mine").unwrap();
    let (code, out, err) = run(&["run", &scene_path("soft-jkr.toml"), "--out", "o"], &dir);
    assert_eq!(code, 0, "{err}");
    assert!(
        !dir.join("o/montecarlo.csv").exists(),
        "a montecarlo.csv of the earlier run is left beside JKR results"
    );
    // Files the run does not own are left alone.
    assert!(dir.join("o/notes.txt").exists());
    // What is in the directory is exactly what the run says it wrote.
    let listed: Vec<String> = out
        .lines()
        .skip_while(|l| !l.contains("wrote:"))
        .skip(1)
        .map(|l| l.trim().to_string())
        .collect();
    let mut present: Vec<String> = std::fs::read_dir(dir.join("o"))
        .unwrap()
        .map(|e| format!("o/{}", e.unwrap().file_name().to_string_lossy()))
        .filter(|f| f != "o/notes.txt")
        .collect();
    present.sort();
    let mut listed_sorted = listed.clone();
    listed_sorted.sort();
    assert_eq!(listed_sorted, present, "{out}");
    // With --json, stdout is only JSON and the files are listed on stderr.
    let (code, out, err) = run(
        &["run", &scene_path("soft-jkr.toml"), "--out", "o", "--json"],
        &dir,
    );
    assert_eq!(code, 0, "{err}");
    serde_json::from_str::<serde_json::Value>(&out).unwrap();
    assert!(err.contains("wrote o/curve.csv"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn non_finite_results_are_refused_before_anything_is_written() {
    let dir = tmp("inf");
    let text = std::fs::read_to_string(scene_path("soft-jkr.toml")).unwrap();
    let huge = text.replacen("nominal_area = 1e-6", "nominal_area = 1e300", 1);
    assert_ne!(huge, text);
    std::fs::write(dir.join("huge.toml"), huge).unwrap();
    let (code, _, err) = run(&["run", "huge.toml", "--out", "o"], &dir);
    // Refused either by the scene check (surface.nominal_area) or by the
    // output check (naming the quantity): never a file full of inf.
    assert_ne!(code, 0, "{err}");
    assert_ne!(code, 101, "{err}");
    assert!(
        err.contains("surface.nominal_area") && !err.contains("chart"),
        "{err}"
    );
    assert!(!dir.join("o/curve.csv").exists());
    assert!(!dir.join("o/summary.json").exists());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_run_reports_progress_on_a_non_terminal_stderr() {
    let dir = tmp("progress");
    // The delay before progress shows (2 s) is set to 0 so a fast run
    // shows it; stderr is a pipe here, so plain lines are expected.
    let o = bin()
        .args(["run", &scene_path("soft-jkr.toml"), "--out", "o"])
        .env("ASPERITY_PROGRESS_AFTER", "0")
        .current_dir(&dir)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(err.contains("run: 240/240 curve states (100 %)"), "{err}");
    // Planning (a first-time calibration can take seconds) says when it
    // ended once the delay has passed.
    assert!(err.contains("plan: done in "), "{err}");
    let lines = err.lines().filter(|l| l.starts_with("run: ")).count();
    assert!((2..=12).contains(&lines), "{lines} progress lines:\n{err}");
    // Without the override a sub-second run stays quiet.
    let o = bin()
        .args(["run", &scene_path("soft-jkr.toml"), "--out", "o"])
        .env_remove("ASPERITY_PROGRESS_AFTER")
        .current_dir(&dir)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!err.contains("run: "), "{err}");
    assert!(!err.contains("plan: "), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

/// One exit-code rule for outputs that cannot be written (a file stands
/// where the output directory should be): not the input's fault, exit 1,
/// naming the path, for every command that writes files.
#[test]
fn unwritable_outputs_exit_1_everywhere() {
    let dir = tmp("unwritable");
    let blocker = dir.join("blocker");
    std::fs::write(&blocker, "a file, not a directory").unwrap();
    let out = blocker.join("sub");
    let out = out.to_str().unwrap();
    let map = format!(
        "{}/examples/data/measured-topography.npy",
        env!("CARGO_MANIFEST_DIR")
    );
    let curve = format!("{out}/curve.csv");
    let scene = scene_path("hertz-exponential.toml");
    let cases: Vec<Vec<&str>> = vec![
        vec!["run", &scene[..], "--out", out],
        vec!["map", "--tolerance", "0.05", "--out", out],
        vec!["sphere", "--mu", "1", "--curve", &curve[..]],
        vec![
            "surface",
            &map[..],
            "--pixel-size",
            "1e-7",
            "--scale",
            "1e-9",
            "--out",
            out,
        ],
    ];
    for args in cases {
        let (code, _, err) = run(&args, &dir);
        assert_eq!(code, 1, "{args:?}: {err}");
        assert!(err.contains("blocker"), "{args:?}: {err}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Sends SIGINT to `child` after `delay` and waits for it: its status, the
/// seconds from the signal to its exit, and its stderr.
fn interrupted(
    mut child: std::process::Child,
    delay: std::time::Duration,
) -> (Option<i32>, f64, String) {
    std::thread::sleep(delay);
    let sent = std::time::Instant::now();
    let kill = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success());
    let status = child.wait().unwrap();
    let latency = sent.elapsed().as_secs_f64();
    let mut err = String::new();
    use std::io::Read;
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut err)
        .unwrap();
    (status.code(), latency, err)
}

/// Ctrl-C stops a long boundary-element solve at its next iteration: exit
/// 130 within a second, "interrupted" on stderr, no output directory
/// half-written.
#[test]
fn ctrl_c_stops_a_long_bem_solve_with_130() {
    let dir = tmp("sigint-bem");
    // A 512 x 512 map solved at many pressures: minutes of work.
    let n = 512usize;
    let mut state = 7u64;
    let heights: Vec<f64> = (0..n * n)
        .map(|_| {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 1e-9
        })
        .collect();
    let map = asperity::surface::HeightMap::new(n, n, heights).unwrap();
    std::fs::write(dir.join("map.npy"), asperity::surface::npy::to_bytes(&map)).unwrap();
    let pressures: Vec<String> = (0..40)
        .map(|k| format!("{:e}", 1e5 * 1.2f64.powi(k)))
        .collect();
    let child = bin()
        .args([
            "bem",
            "map.npy",
            "--pixel-size",
            "1e-7",
            "--estar",
            "1e9",
            "--out",
            "o",
        ])
        .arg(format!("--pressures={}", pressures.join(",")))
        .current_dir(&dir)
        .stderr(Stdio::piped())
        .stdout(Stdio::null())
        .spawn()
        .unwrap();
    let (code, latency, err) = interrupted(child, std::time::Duration::from_millis(1500));
    assert_eq!(code, Some(130), "{err}");
    assert!(latency < 1.0, "{latency} s: {err}");
    assert!(err.contains("interrupted"), "{err}");
    assert!(!dir.join("o").join("bem.json").exists());
}

/// Ctrl-C stops a sweep between points: exit 130, the rows finished are
/// whole, and the same command resumes and completes the file.
#[test]
fn ctrl_c_stops_a_sweep_and_the_rerun_resumes() {
    let dir = tmp("sigint-sweep");
    let scene = scene_path("rf-mems-switch.toml");
    let args = [
        "sweep",
        &scene,
        "--vary",
        "surface.sigma=3e-9:8e-9:200",
        "--threads",
        "2",
        "--out",
        "s",
    ];
    let child = bin()
        .args(args)
        .current_dir(&dir)
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let (code, latency, err) = interrupted(child, std::time::Duration::from_millis(1500));
    assert_eq!(code, Some(130), "{err}");
    assert!(latency < 1.0, "{latency} s: {err}");
    let partial = std::fs::read_to_string(dir.join("s").join("results.csv")).unwrap_or_default();
    let rows = partial.lines().count().saturating_sub(1);
    assert!(rows < 200, "{rows} rows");
    for line in partial.lines().skip(1) {
        assert!(line.contains(",ok,"), "{line}");
    }
    let (code, _, err) = run(&args, &dir);
    assert_eq!(code, 0, "{err}");
    let done = std::fs::read_to_string(dir.join("s").join("results.csv")).unwrap();
    assert_eq!(done.lines().count(), 201);
}

/// A negative infinity written after a numeric option as its own word
/// (`--mu -inf`) is the option's value, refused naming the option, not
/// clap's "unexpected argument '-i' found".
#[test]
fn minus_inf_after_a_numeric_option_names_the_option() {
    let dir = tmp("minus-inf");
    let cases: [(&[&str], &str); 8] = [
        (&["sphere"], "--mu"),
        (&["rough-sphere", "--d", "1"], "--mu"),
        (&["law", "--law", "maugis"], "--lambda"),
        (&["fn", "--dist", "gaussian", "--h", "0"], "--n"),
        (&["heating"], "--voltage"),
        (
            &[
                "shape",
                "--profile",
                "cone",
                "--tan-angle",
                "0.2",
                "--w",
                "0.05",
            ],
            "--estar",
        ),
        (
            &[
                "persson",
                "--hurst",
                "0.8",
                "--q-roll",
                "4e5",
                "--q-short",
                "4e8",
                "--h-rms",
                "1e-8",
                "--estar",
                "1e9",
                "--pressures",
                "1e6",
            ],
            "--q-long",
        ),
        (&["map"], "--tolerance"),
    ];
    for (base, flag) in cases {
        let mut args: Vec<&str> = base.to_vec();
        args.extend([flag, "-inf"]);
        let (code, _, err) = run(&args, &dir);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(!err.contains("unexpected argument"), "{args:?}: {err}");
        assert!(err.contains(flag), "{args:?}: {err}");
    }
}
