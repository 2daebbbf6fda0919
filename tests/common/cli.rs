//! Process helpers of the CLI tests that run the built `asperity` (in a
//! test binary by `#[path = "common/cli.rs"] mod cli;`).
use std::path::{Path, PathBuf};
use std::process::Command;

/// The built binary.
pub fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_asperity"))
}

/// A fresh temporary directory for test `name` of this test binary.
pub fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!(
        "asperity-{}-{name}-{}",
        env!("CARGO_CRATE_NAME"),
        std::process::id()
    ));
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

/// A JSON file, parsed.
pub fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}
