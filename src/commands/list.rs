//! Comma-separated number lists of the command line (`--h -1,0,2.5`).

use super::{CommandError, CommandResult};

/// Parses a comma-separated list of finite numbers given to `flag`;
/// errors name the flag and the entry.
pub fn parse(flag: &str, text: &str) -> CommandResult<Vec<f64>> {
    if text.trim().is_empty() {
        return Err(CommandError::Usage(format!("{flag}: empty list")));
    }
    text.split(',')
        .map(|item| {
            let t = item.trim();
            let x: f64 = t.parse().map_err(|_| {
                CommandError::Usage(format!("{flag}: cannot parse {t:?} as a number"))
            })?;
            crate::error::finite(flag, x)?;
            Ok(x)
        })
        .collect()
}
