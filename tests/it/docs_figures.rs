//! The figures of README.md and docs/ are what their commands draw:
//! `docs/img/README.md` lists each figure with its command and the file
//! the command writes; this test runs every command (once, from a scratch
//! directory) and compares the files byte for byte. `ASPERITY_REDRAW=1`
//! writes the new drawings into `docs/img/` instead of failing. It also
//! holds the README's excerpt of the default study to what the run prints.

use crate::common::cli::{run, tmp};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// One row of `docs/img/README.md`: figure, command words, file written.
struct Figure {
    name: String,
    command: Vec<String>,
    file: String,
}

/// The rows of the figure table (cells in backticks).
fn figures() -> Vec<Figure> {
    let text = std::fs::read_to_string(root().join("docs/img/README.md")).unwrap();
    text.lines()
        .filter(|l| l.starts_with("| `"))
        .map(|l| {
            let cells: Vec<&str> = l
                .split('|')
                .map(|c| c.trim().trim_matches('`'))
                .filter(|c| !c.is_empty())
                .collect();
            assert_eq!(cells.len(), 3, "{l}");
            Figure {
                name: cells[0].to_string(),
                command: cells[1].split_whitespace().map(String::from).collect(),
                file: cells[2].to_string(),
            }
        })
        .collect()
}

/// Runs `command` (its first word `asperity`) in `dir`, paths under the
/// repository given as absolute paths: stdout.
fn run_command(command: &[String], dir: &Path) -> String {
    assert_eq!(command[0], "asperity", "{command:?}");
    let args: Vec<String> = command[1..]
        .iter()
        .map(|a| {
            let p = root().join(a);
            if a.contains('/') && p.exists() {
                p.display().to_string()
            } else {
                a.clone()
            }
        })
        .collect();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let (code, out, err) = run(&args, dir);
    assert_eq!(code, 0, "{command:?}: {err}");
    out
}

#[test]
fn every_figure_is_what_its_command_draws() {
    let figures = figures();
    let img = root().join("docs/img");
    // Every figure is listed, and every listed one is shown somewhere.
    let mut docs = std::fs::read_to_string(root().join("README.md")).unwrap();
    for d in std::fs::read_dir(root().join("docs")).unwrap() {
        let p = d.unwrap().path();
        if p.extension().is_some_and(|e| e == "md") {
            docs.push_str(&std::fs::read_to_string(p).unwrap());
        }
    }
    for e in std::fs::read_dir(&img).unwrap() {
        let name = e.unwrap().file_name().into_string().unwrap();
        if name.ends_with(".svg") {
            assert!(
                figures.iter().any(|f| f.name == name),
                "docs/img/{name} is not in docs/img/README.md's table"
            );
            assert!(
                docs.contains(&format!("img/{name}")),
                "docs/img/{name} is shown nowhere in README.md or docs/"
            );
        }
    }
    // One run per distinct command.
    let mut runs: BTreeMap<Vec<String>, PathBuf> = BTreeMap::new();
    let redraw = std::env::var_os("ASPERITY_REDRAW").is_some();
    let mut stale = Vec::new();
    for f in &figures {
        let dir = match runs.get(&f.command) {
            Some(d) => d.clone(),
            None => {
                let d = tmp(&format!("run{}", runs.len()));
                run_command(&f.command, &d);
                runs.insert(f.command.clone(), d.clone());
                d
            }
        };
        let drawn = std::fs::read(dir.join(&f.file))
            .unwrap_or_else(|e| panic!("{}: {} not written: {e}", f.command.join(" "), f.file));
        let shown = std::fs::read(img.join(&f.name)).unwrap_or_default();
        if drawn != shown {
            if redraw {
                std::fs::write(img.join(&f.name), &drawn).unwrap();
            } else {
                stale.push(format!("{} ({})", f.name, f.command.join(" ")));
            }
        }
    }
    assert!(
        stale.is_empty(),
        "docs/img differs from what the commands draw now; look at the new drawings \
         (ASPERITY_REDRAW=1 cargo test --test it docs_figures writes them): {stale:#?}"
    );
}

/// The README's excerpt of the default study (the block after "An
/// excerpt:"): each of its lines is a line the run prints.
#[test]
fn the_readme_excerpt_of_the_default_study_is_what_it_prints() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let after = &readme[readme.find("An excerpt:").expect("the excerpt")..];
    let block = after
        .split_once("```text\n")
        .and_then(|(_, b)| b.split_once("```"))
        .expect("a text block after the excerpt")
        .0;
    // The default study: `asperity` with no arguments, as `cargo run --release`.
    let out = run_command(&["asperity".to_string()], &tmp("excerpt"));
    let printed: Vec<&str> = out.lines().collect();
    let missing: Vec<&str> = block.lines().filter(|l| !printed.contains(l)).collect();
    assert!(
        block.lines().count() >= 10 && missing.is_empty(),
        "README lines the default study no longer prints: {missing:#?}\nit prints:\n{out}"
    );
}
