//! Process helpers of the tests that run the built `asperity`
//! (`use crate::common::cli;`). Each module uses some of them.
#![allow(dead_code)]
use std::path::{Path, PathBuf};
use std::process::Command;

/// The built binary.
pub fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_asperity"))
}

/// A fresh temporary directory for test `name` of the calling module: the
/// caller's file name keeps two modules' `tmp("spots")` apart in the one
/// test binary.
#[track_caller]
pub fn tmp(name: &str) -> PathBuf {
    let module = std::path::Path::new(std::panic::Location::caller().file())
        .file_stem()
        .map_or_else(|| "it".into(), |s| s.to_string_lossy().into_owned());
    let d = std::env::temp_dir().join(format!("asperity-{module}-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The text of `examples/scenes/NAME`.
pub fn example(name: &str) -> String {
    let root = env!("CARGO_MANIFEST_DIR");
    std::fs::read_to_string(format!("{root}/examples/scenes/{name}")).unwrap()
}

/// Runs the binary with `args` in `dir`: exit code, stdout, stderr.
pub fn run(args: &[&str], dir: &Path) -> (i32, String, String) {
    let o = bin().args(args).current_dir(dir).output().unwrap();
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// Runs the scene `text` (written to `dir/NAME.toml`, outputs into
/// `dir/out-NAME`) with `--json`: its summary; a failed run fails the
/// test with its stderr.
pub fn run_scene_json(dir: &Path, name: &str, text: &str) -> serde_json::Value {
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text).unwrap();
    let out = dir.join(format!("out-{name}"));
    let (code, stdout, err) = run(
        &[
            "run",
            path.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--json",
        ],
        dir,
    );
    assert_eq!(code, 0, "{name}: {err}");
    serde_json::from_str(&stdout).unwrap()
}

/// A JSON file, parsed.
pub fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// What a process run under [`run_within`] did.
#[derive(Debug)]
pub struct Outcome {
    /// Exit code; `None` when killed by a signal (a panic's abort, or the
    /// timeout).
    pub code: Option<i32>,
    /// Whether it was killed at the timeout.
    pub timed_out: bool,
    /// CPU-independent wall time (s).
    pub seconds: f64,
    /// Its stdout.
    pub stdout: String,
    /// Its stderr.
    pub stderr: String,
}

/// Runs `cmd` (stdin empty, outputs captured), killing it after `limit`
/// seconds so a hang fails the test instead of hanging it.
pub fn run_within(mut cmd: Command, limit: f64) -> Outcome {
    use std::io::Read;
    use std::process::Stdio;
    let t0 = std::time::Instant::now();
    let mut child = cmd
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Readers on threads, so a full pipe cannot stall the child.
    let mut out = child.stdout.take().unwrap();
    let mut err = child.stderr.take().unwrap();
    let t_out = std::thread::spawn(move || {
        let mut s = Vec::new();
        let _ = out.read_to_end(&mut s);
        s
    });
    let t_err = std::thread::spawn(move || {
        let mut s = Vec::new();
        let _ = err.read_to_end(&mut s);
        s
    });
    let mut timed_out = false;
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break s;
        }
        if t0.elapsed().as_secs_f64() > limit {
            timed_out = true;
            let _ = child.kill();
            break child.wait().unwrap();
        }
        std::thread::sleep(std::time::Duration::from_millis(10));
    };
    let seconds = t0.elapsed().as_secs_f64();
    Outcome {
        code: status.code(),
        timed_out,
        seconds,
        stdout: String::from_utf8_lossy(&t_out.join().unwrap()).into_owned(),
        stderr: String::from_utf8_lossy(&t_err.join().unwrap()).into_owned(),
    }
}

/// `asperity persson` on the self-affine spectrum the tests share (Hurst
/// 0.8, q 1e5 / 4e5 / 4e8 1/m, h_rms 10 nm, E* 1 GPa), before its
/// pressures.
pub const PERSSON_SPECTRUM: [&str; 13] = [
    "persson",
    "--hurst",
    "0.8",
    "--q-long",
    "1e5",
    "--q-roll",
    "4e5",
    "--q-short",
    "4e8",
    "--h-rms",
    "1e-8",
    "--estar",
    "1e9",
];
