//! What a newcomer sees first: the top-level help says what a bare
//! `asperity` does, and a mistyped command or flag gets clap's
//! "did you mean" tip on the one error line.

use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn help_says_a_bare_asperity_runs_the_default_study_into_asperity_out() {
    let (code, out, _) = run(&["--help"]);
    assert_eq!(code, 0);
    assert!(out.contains("Without a command"), "{out}");
    assert!(out.contains("default study"), "{out}");
    assert!(out.contains("./asperity-out/"), "{out}");
}

#[test]
fn mistyped_commands_and_flags_keep_the_tip_on_one_line() {
    let (code, _, err) = run(&["rn"]);
    assert_eq!(code, 2);
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(
        err.contains("'rn'") && err.contains("tip:") && err.contains("'run'"),
        "{err}"
    );
    let (code, _, err) = run(&["run", "examples/scenes/mems-gold.toml", "--outt", "x"]);
    assert_eq!(code, 2);
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains("--outt") && err.contains("'--out'"), "{err}");
}

#[test]
fn schema_prints_the_library_schema_and_one_line_per_key() {
    let (code, out, err) = run(&["schema", "--json"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out, asperity::study::scene::scene_schema_text());
    let (code, out, err) = run(&["schema"]);
    assert_eq!(code, 0, "{err}");
    let keys = asperity::study::scene::scene_keys();
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), keys.len(), "{out}");
    for (line, key) in lines.iter().zip(&keys) {
        assert!(line.starts_with(&format!("{} ", key.path)), "{line}");
    }
    let sigma = lines
        .iter()
        .find(|l| l.starts_with("surface.sigma "))
        .unwrap();
    let cells: Vec<&str> = sigma.split_whitespace().collect();
    assert_eq!(
        &cells[..7],
        [
            "surface.sigma",
            "number",
            "m",
            "default",
            "-",
            "range",
            "[1e-15,"
        ],
        "{sigma}"
    );
    assert!(sigma.contains("standard deviation"), "{sigma}");
    let rtol = lines
        .iter()
        .find(|l| l.starts_with("accuracy.rtol "))
        .unwrap();
    assert!(
        rtol.contains("default 1e-6") && rtol.contains("range [1e-12, 0.1]"),
        "{rtol}"
    );
}
