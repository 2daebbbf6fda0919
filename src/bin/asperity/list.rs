//! Comma-separated number lists of the command line (`--h -1,0,2.5`): the
//! typed command API takes the numbers, so the text stays here.

use crate::CliError;

/// The numbers of the comma-separated list given to `flag` (any `f64`
/// Rust parses; the command checks their range).
///
/// # Errors
/// [`CliError::Usage`] naming `flag` for an empty list or an entry that is
/// not a number.
pub fn parse(flag: &str, text: &str) -> Result<Vec<f64>, CliError> {
    if text.trim().is_empty() {
        return Err(CliError::Usage(format!("{flag}: empty list")));
    }
    text.split(',')
        .map(|item| {
            let t = item.trim();
            t.parse()
                .map_err(|_| CliError::Usage(format!("{flag}: cannot parse {t:?} as a number")))
        })
        .collect()
}

/// [`parse`] of an optional flag.
///
/// # Errors
/// As [`parse`].
pub fn parse_opt(flag: &str, text: Option<&str>) -> Result<Option<Vec<f64>>, CliError> {
    text.map(|t| parse(flag, t)).transpose()
}
