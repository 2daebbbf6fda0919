//! The commands that print JSON, as functions: what `asperity law`,
//! `asperity fn`, `asperity surface`, ... compute, with their arguments named
//! by their command-line flags and their results as serialisable structs
//! whose JSON is what `--json` prints. The command line (`src/bin/asperity/`)
//! parses flags into these arguments and prints; the Python package calls
//! the same functions, so both give identical numbers and identical errors.
//!
//! Built with the feature `study`; the argument structs derive
//! [`clap::Args`](https://docs.rs/clap) only with the feature `cli`, so the
//! physics core and the study layer never depend on clap.
//!
//! ```
//! use asperity::commands::{fn_, law};
//!
//! // F_0(0) of the Gaussian heights: the fraction above the mean, 1/2.
//! let f = fn_::values("gaussian", 0.0, &[0.0])?;
//! assert!((f[0] - 0.5).abs() < 1e-15);
//! // The JKR pull-off under load control: -3/2 in units of pi w R.
//! let facts = law::run(&law::LawArgs { law: "jkr".into(), lambda: None, json: true })?;
//! assert!((facts.pull_off_load_control + 1.5).abs() < 1e-12);
//! # Ok::<(), asperity::commands::CommandError>(())
//! ```

pub mod bem;
pub mod fn_;
pub mod heating;
pub mod law;
pub mod list;
pub mod persson;
pub mod punch;
pub mod rough_sphere;
pub mod shape;
pub mod sphere;
pub mod spots;
pub mod surface;

/// Why a command failed: bad input (the CLI exits 2, Python raises
/// `ValueError`) or a computation or file that failed (exit 1,
/// `RuntimeError`). The message names the flag or field.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CommandError {
    /// Bad input: the message names the flag, field or file.
    #[error("{0}")]
    Usage(String),
    /// The computation (or a file it writes) failed.
    #[error("{0}")]
    Failed(String),
}

impl From<crate::Error> for CommandError {
    fn from(e: crate::Error) -> Self {
        if e.is_bad_input() {
            CommandError::Usage(e.to_string())
        } else {
            CommandError::Failed(e.to_string())
        }
    }
}

/// What a command prints: its JSON (`--json`) and its text table.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// The JSON object `--json` prints.
    pub json: serde_json::Value,
    /// That object as `--json` prints it (one line, keys in the order of
    /// the output's fields).
    pub json_text: String,
    /// The text printed without `--json`.
    pub text: String,
}

impl Report {
    /// A report of `out` (serialised) and `text`.
    pub fn new<T: serde::Serialize>(out: &T, text: String) -> CommandResult<Report> {
        let failed = |e: serde_json::Error| CommandError::Failed(e.to_string());
        Ok(Report {
            json: serde_json::to_value(out).map_err(failed)?,
            json_text: serde_json::to_string(out).map_err(failed)?,
            text,
        })
    }
}

/// Result of a command.
pub type CommandResult<T> = std::result::Result<T, CommandError>;

/// The text of an input file `path` (named `what` in messages, e.g.
/// `spots file`): one that cannot be read (missing, a directory, not
/// UTF-8) is bad input naming the path.
pub(crate) fn read_input(what: &str, path: &std::path::Path) -> CommandResult<String> {
    std::fs::read_to_string(path)
        .map_err(|e| CommandError::Usage(format!("{what} {}: cannot read: {e}", path.display())))
}

/// `e` with its field renamed by `map` (library name, flag), so a message
/// names the flag the user wrote.
pub(crate) fn flagged(e: crate::Error, map: &[(&str, &str)]) -> crate::Error {
    match map.iter().find(|(from, _)| e.field() == Some(*from)) {
        Some((_, to)) => e.renamed(to),
        None => e,
    }
}
