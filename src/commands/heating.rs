//! `asperity heating`: Holm's phi-theta relation with Wiedemann–Franz, the
//! peak contact temperature from the contact voltage or the reverse
//! ([`crate::electrical::heating`]).

use super::{CommandError, CommandResult};
use crate::electrical::heating::Heating;
use serde::Serialize;

/// Arguments of `asperity heating`: exactly one of `--voltage`,
/// `--max-temperature`.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "cli", derive(clap::Args))]
pub struct HeatingArgs {
    /// Contact voltage U = I R (V), >= 0: prints the peak temperature.
    #[cfg_attr(feature = "cli", arg(long, allow_hyphen_values = true))]
    pub voltage: Option<f64>,
    /// Peak contact temperature (K), >= the bulk temperature: prints the
    /// voltage that reaches it.
    #[cfg_attr(feature = "cli", arg(long, allow_hyphen_values = true))]
    pub max_temperature: Option<f64>,
    /// Bulk temperature T0 (K), > 0.
    #[cfg_attr(
        feature = "cli",
        arg(long, allow_hyphen_values = true, default_value_t = crate::electrical::heating::DEFAULT_BULK_TEMPERATURE)
    )]
    pub bulk_temperature: f64,
    /// Print one JSON object instead of a line.
    #[cfg_attr(feature = "cli", arg(long))]
    pub json: bool,
}

/// What `asperity heating --json` prints: `{"max_temperature_K": ..}` for a
/// voltage, `{"voltage_V": ..}` for a temperature.
#[derive(Serialize, Debug, Clone, Copy)]
#[serde(untagged)]
pub enum HeatingOutput {
    /// The peak temperature at `--voltage`.
    Temperature {
        /// Peak contact temperature (K).
        #[serde(rename = "max_temperature_K")]
        max_temperature: f64,
    },
    /// The voltage that reaches `--max-temperature`.
    Voltage {
        /// Contact voltage (V).
        #[serde(rename = "voltage_V")]
        voltage: f64,
    },
}

/// Runs `asperity heating`; also returns the bulk temperature used.
pub fn run(args: &HeatingArgs) -> CommandResult<(HeatingOutput, f64)> {
    let heating =
        Heating::new(args.bulk_temperature).map_err(|e| e.renamed("--bulk-temperature"))?;
    let out = match (args.voltage, args.max_temperature) {
        (Some(u), None) => HeatingOutput::Temperature {
            max_temperature: heating
                .max_temperature(u)
                .map_err(|e| e.renamed("--voltage"))?,
        },
        (None, Some(t)) => HeatingOutput::Voltage {
            voltage: heating
                .voltage_for(t)
                .map_err(|e| e.renamed("--max-temperature"))?,
        },
        _ => {
            return Err(CommandError::Usage(
                "--voltage, --max-temperature: give exactly one of them".into(),
            ))
        }
    };
    Ok((out, heating.bulk_temperature()))
}
