//! The typed command API: what `asperity law`, `asperity fn`, `asperity
//! surface`, ... compute, as functions of typed inputs (numbers in SI units,
//! slices, enums, option structs) returning typed records whose JSON is what
//! `--json` prints. The command line (`src/bin/asperity/`) parses its flags
//! into these inputs and the Python package converts its arguments into
//! them directly (arrays as slices, no text in between), so both give
//! identical numbers and identical errors.
//!
//! **Errors name inputs, front ends word them.** Every error is a
//! [`crate::Error`]; where it names one of a command's inputs it writes the
//! input's parameter name in braces (`{pixel_size}`, an entry of a list as
//! `{pressures[2]}`). A front end renders the error in its own vocabulary
//! with [`Vocabulary::render`]: the command line as flags (`--pixel-size`),
//! Python as keyword arguments (`pixel_size`). Scene errors name key paths
//! (`surface.sigma`) and pass through unchanged.
//!
//! Built with the feature `study` (file outputs and charts); the physics
//! core never depends on it.
//!
//! ```
//! use asperity::commands::{fn_, law, Vocabulary};
//! use asperity::heights::DistributionKind;
//! use asperity::law::LawKind;
//!
//! // F_0(0) of the Gaussian heights: the fraction above the mean, 1/2.
//! let f = fn_::values(DistributionKind::Gaussian, 0.0, &[0.0])?;
//! assert!((f[0] - 0.5).abs() < 1e-15);
//! // The JKR pull-off under load control: -3/2 in units of pi w R.
//! let facts = law::facts(&law::LawInput { law: LawKind::Jkr, lambda: None })?;
//! assert!((facts.pull_off_load_control + 1.5).abs() < 1e-12);
//! // A bad input, as each front end says it.
//! let e = law::facts(&law::LawInput { law: LawKind::Maugis, lambda: Some(-1.0) }).unwrap_err();
//! assert!(Vocabulary::cli().render(&e).starts_with("--lambda = -1 is out of range"));
//! assert!(Vocabulary::python().render(&e).starts_with("lambda_ = -1 is out of range"));
//! # Ok::<(), asperity::Error>(())
//! ```

pub mod bem;
pub mod criteria;
pub mod fn_;
pub mod heating;
pub mod law;
pub mod measured;
pub mod persson;
mod persson_text;
pub mod punch;
pub mod rough_sphere;
pub mod shape;
pub mod sphere;
pub mod spots;
pub mod surface;
mod vocabulary;
pub mod wet_map;
pub mod wet_persson;

pub use vocabulary::{param, Vocabulary};

/// Result of a command: its typed output, or an error naming its input.
pub type CommandResult<T> = crate::Result<T>;

/// The order of a pair of inputs, named by both: an error naming `lo`
/// when its value is at or above `hi`'s (`strict`) or above it (else),
/// "`{lo value:e}{unit} must be below {hi} = {hi value:e}{unit}`" ("must
/// not exceed" when not strict); `unit` with its leading space, or empty.
/// NaN passes (each input's own check names it).
pub(crate) fn check_order(
    (lo, lo_value): (&str, f64),
    (hi, hi_value): (&str, f64),
    unit: &str,
    strict: bool,
) -> CommandResult<()> {
    let (bad, verb) = if strict {
        (lo_value >= hi_value, "must be below")
    } else {
        (lo_value > hi_value, "must not exceed")
    };
    if bad {
        return Err(crate::Error::invalid(
            param(lo),
            format!(
                "{lo_value:e}{unit} {verb} {} = {hi_value:e}{unit}",
                param(hi)
            ),
        ));
    }
    Ok(())
}

/// The text of an input file `path` (named `what` in messages, e.g.
/// `spots file`): one that cannot be read (missing, a directory, not
/// UTF-8) is bad input naming the path.
pub(crate) fn read_input(what: &str, path: &std::path::Path) -> CommandResult<String> {
    std::fs::read_to_string(path).map_err(|e| {
        crate::Error::invalid(
            format!("{what} {}", path.display()),
            format!("cannot read: {e}"),
        )
    })
}

/// `e` with a core argument's name replaced by the command's parameter
/// (`map`: `(core name, parameter)` pairs), so a message names the input
/// the caller gave.
pub(crate) fn named(e: crate::Error, map: &[(&str, &str)]) -> crate::Error {
    match map.iter().find(|(from, _)| e.field() == Some(*from)) {
        Some((_, to)) => e.renamed(&param(to)),
        None => e,
    }
}

/// Writes `text` to `path` whole or not at all; a failure names the path.
pub(crate) fn write_file(path: &std::path::Path, text: impl AsRef<[u8]>) -> CommandResult<()> {
    crate::study::atomic::write(path, text).map_err(|e| crate::Error::io(path.display(), e))
}

/// Creates the output directory `dir`; a failure names it.
pub(crate) fn create_dir(dir: &std::path::Path) -> CommandResult<()> {
    std::fs::create_dir_all(dir).map_err(|e| crate::Error::io(dir.display(), e))
}

/// The JSON text of a command's output, as `--json` prints it (one line).
///
/// # Errors
/// [`crate::Error::Io`] if serialisation fails (it cannot for the
/// commands' outputs, whose numbers are finite or null).
pub fn json_line<T: serde::Serialize>(out: &T) -> CommandResult<String> {
    serde_json::to_string(out).map_err(|e| crate::Error::io("json", e))
}
