//! Every shell line of README.md runs as written from the repository root.
//!
//! The lines of the README's ```` ```sh ```` blocks (continuations joined,
//! comments dropped) run with `sh -c` in a fresh copy of the tracked files
//! (a new git repository), with this build's `asperity` first on the
//! `PATH`. Each must exit 0, and `git status` must be clean afterwards:
//! every output goes to a directory `.gitignore` lists. `cargo run
//! --release [-- ARGS]` runs as `asperity [ARGS]` (the same program);
//! `cargo run --release --example NAME` is checked for its `[[example]]` in
//! Cargo.toml (a release build; `tools/readme_lines.sh` runs it); `cargo
//! test` is this suite; `cargo install` is checked for `--locked` (a
//! release build takes minutes; `tools/readme_lines.sh` runs it too, and
//! the Python package's `python -m pip install ./python`, in a fresh venv).

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The shell lines of the README's `sh` blocks: `\` continuations joined,
/// comments (` #` to the end of the line, or a whole `#` line) dropped.
fn shell_lines(readme: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut in_sh = false;
    let mut pending = String::new();
    for line in readme.lines() {
        let t = line.trim_end();
        if t.starts_with("```") {
            in_sh = t == "```sh";
            continue;
        }
        if !in_sh {
            continue;
        }
        let code = match t.find(" #") {
            Some(i) => &t[..i],
            None => t,
        };
        let code = code.trim();
        if code.starts_with('#') {
            continue;
        }
        if let Some(head) = code.strip_suffix('\\') {
            pending.push_str(head.trim_end());
            pending.push(' ');
            continue;
        }
        pending.push_str(code);
        let full = std::mem::take(&mut pending).trim().to_string();
        if !full.is_empty() {
            out.push(full);
        }
    }
    out
}

fn git(dir: &Path, args: &[&str]) -> String {
    let out = Command::new("git")
        .args([
            "-c",
            "user.name=readme",
            "-c",
            "user.email=readme@localhost",
        ])
        .args(args)
        .current_dir(dir)
        .output()
        .expect("git runs");
    assert!(
        out.status.success(),
        "git {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// A fresh repository holding the tracked files as they are now.
fn fresh_copy() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("asperity-readme-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let files = git(&root(), &["ls-files", "-z"]);
    for f in files.split('\0').filter(|f| !f.is_empty()) {
        let from = root().join(f);
        if !from.is_file() {
            continue; // deleted in the work tree
        }
        let to = dir.join(f);
        std::fs::create_dir_all(to.parent().unwrap()).unwrap();
        std::fs::copy(&from, &to).unwrap();
    }
    git(&dir, &["init", "-q"]);
    git(&dir, &["add", "-A"]);
    git(&dir, &["commit", "-q", "-m", "copy"]);
    dir
}

#[test]
fn the_readme_has_the_lines_a_newcomer_needs() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let lines = shell_lines(&readme);
    assert!(
        lines.iter().any(|l| l == "cargo run --release"),
        "{lines:?}"
    );
    assert!(lines.iter().any(|l| l == "cargo test"), "{lines:?}");
    let install = lines
        .iter()
        .find(|l| l.starts_with("cargo install"))
        .expect("an install line");
    assert!(
        install.contains("--locked") && install.contains("--path ."),
        "{install}"
    );
    // Every example scene is in the scene table.
    for e in std::fs::read_dir(root().join("examples/scenes")).unwrap() {
        let name = e.unwrap().file_name().into_string().unwrap();
        assert!(
            readme.contains(&format!("| `{name}` |")),
            "{name} missing from the README's scene table"
        );
    }
    // Every example a line runs is registered in Cargo.toml with its file.
    let manifest = std::fs::read_to_string(root().join("Cargo.toml")).unwrap();
    for l in &lines {
        if let Some(rest) = l.strip_prefix("cargo run --release --example ") {
            let name = rest.split_whitespace().next().unwrap_or("");
            let entry = format!("[[example]]\nname = \"{name}\"\npath = \"");
            let at = manifest
                .find(&entry)
                .unwrap_or_else(|| panic!("{l}: no [[example]] named {name} in Cargo.toml"));
            let path: String = manifest[at + entry.len()..]
                .chars()
                .take_while(|c| *c != '"')
                .collect();
            assert!(root().join(&path).exists(), "{l}: {path} does not exist");
        }
    }
    // Every file a line names under examples/ exists.
    for l in &lines {
        for word in l.split_whitespace() {
            if word.starts_with("examples/") {
                assert!(root().join(word).exists(), "{l}: {word} does not exist");
            }
        }
    }
}

#[test]
fn every_readme_shell_line_runs_and_leaves_the_tree_clean() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let dir = fresh_copy();
    let bin = PathBuf::from(env!("CARGO_BIN_EXE_asperity"));
    let path = format!(
        "{}:{}",
        bin.parent().unwrap().display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let mut failures = Vec::new();
    let mut ran = 0;
    for line in shell_lines(&readme) {
        let cmd = if line.starts_with("cargo test") {
            continue; // this suite
        } else if line.starts_with("cargo install") {
            continue; // checked above; tools/readme_lines.sh builds it
        } else if line.starts_with("python -m pip install") {
            continue; // a release build of the wheel: tools/readme_lines.sh runs it in a venv
        } else if line.starts_with("cargo run --release --example") {
            continue; // a release build of an example: checked above, tools/readme_lines.sh runs it
        } else if let Some(rest) = line.strip_prefix("cargo run --release") {
            format!("asperity {}", rest.trim_start().trim_start_matches("--"))
        } else {
            line.clone()
        };
        let out = Command::new("sh")
            .args(["-c", &cmd])
            .current_dir(&dir)
            .env("PATH", &path)
            .output()
            .unwrap();
        ran += 1;
        if !out.status.success() {
            failures.push(format!(
                "{line}\n  exit {:?}: {}",
                out.status.code(),
                String::from_utf8_lossy(&out.stderr)
                    .lines()
                    .last()
                    .unwrap_or("")
            ));
        }
    }
    assert!(ran >= 20, "only {ran} lines ran");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    let status = git(&dir, &["status", "--porcelain"]);
    assert!(
        status.is_empty(),
        "the README's lines left files git does not ignore:\n{status}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn comments_and_continuations_are_understood() {
    let md = "text\n```sh\n# a comment\nasperity run x.toml --out out   # note\nasperity punch \\\n  --a 1 \\\n  --b 2  # c\n```\n```text\nnot run\n```\n";
    assert_eq!(
        shell_lines(md),
        vec![
            "asperity run x.toml --out out",
            "asperity punch --a 1 --b 2"
        ]
    );
}
