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
