//! `asperity heating`: Holm's phi-theta relation with Wiedemann–Franz, the
//! peak contact temperature from the contact voltage or the reverse
//! ([`crate::electrical::heating`]).

use super::{CommandError, CommandResult};
use crate::electrical::heating::{
    Heating, SpotCondition, GOLD_MELTING_TEMPERATURE, GOLD_SOFTENING_TEMPERATURE,
};
use serde::Serialize;

/// Arguments of `asperity heating`: exactly one of `--voltage`,
/// `--max-temperature`.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "cli", derive(clap::Args))]
pub struct HeatingArgs {
    /// Contact voltage U = I R (V), >= 0: prints the peak temperature.
    #[cfg_attr(feature = "cli", arg(long, allow_hyphen_values = true))]
    pub voltage: Option<f64>,
    /// Peak contact temperature (K), from the bulk temperature to the
    /// melting temperature: prints the voltage that reaches it.
    #[cfg_attr(feature = "cli", arg(long, allow_hyphen_values = true))]
    pub max_temperature: Option<f64>,
    /// Bulk temperature T0 (K), in (0, melting temperature).
    #[cfg_attr(
        feature = "cli",
        arg(long, allow_hyphen_values = true, default_value_t = crate::electrical::heating::DEFAULT_BULK_TEMPERATURE)
    )]
    pub bulk_temperature: f64,
    /// Softening temperature of the metal (K), > 0; default gold's
    /// (373.15 K, Holm): above it the spot yields and a warning says so.
    #[cfg_attr(
        feature = "cli",
        arg(long, allow_hyphen_values = true, default_value_t = GOLD_SOFTENING_TEMPERATURE)
    )]
    pub softening_temperature: f64,
    /// Melting temperature of the metal (K), > the softening temperature;
    /// default gold's (1337.33 K): no temperature is given above it.
    #[cfg_attr(
        feature = "cli",
        arg(long, allow_hyphen_values = true, default_value_t = GOLD_MELTING_TEMPERATURE)
    )]
    pub melting_temperature: f64,
    /// Print one JSON object instead of a line.
    #[cfg_attr(feature = "cli", arg(long))]
    pub json: bool,
}

/// What `asperity heating --json` prints: `{"max_temperature_K": ..}` for a
/// voltage, `{"voltage_V": ..}` for a temperature.
#[derive(Serialize, Debug, Clone)]
#[serde(untagged)]
pub enum HeatingOutput {
    /// The peak temperature at `--voltage`.
    Temperature {
        /// Peak contact temperature (K); `None` (`null`) once the spot melts.
        #[serde(rename = "max_temperature_K")]
        max_temperature: Option<f64>,
        /// `solid`, `softened` or `molten`.
        condition: SpotCondition,
        /// Softening or melting, said in words.
        warnings: Vec<String>,
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
    // The pair's order, named by both flags (a huge softening temperature
    // was blamed on the melting temperature alone).
    if args.softening_temperature >= args.melting_temperature {
        return Err(CommandError::Usage(format!(
            "--softening-temperature = {:e} K must be below --melting-temperature = {:e} K",
            args.softening_temperature, args.melting_temperature
        )));
    }
    let heating = Heating::for_metal(
        args.bulk_temperature,
        args.softening_temperature,
        args.melting_temperature,
    )
    .map_err(|e| {
        let flag = match e.field() {
            Some("softening_temperature") => "--softening-temperature",
            Some("melting_temperature") => "--melting-temperature",
            _ => "--bulk-temperature",
        };
        e.renamed(flag)
    })?;
    let out = match (args.voltage, args.max_temperature) {
        (Some(u), None) => {
            let rename = |e: crate::Error| e.renamed("--voltage");
            HeatingOutput::Temperature {
                max_temperature: heating.peak_temperature(u).map_err(rename)?,
                condition: heating.condition(u).map_err(rename)?,
                warnings: heating.warning(u).map_err(rename)?.into_iter().collect(),
            }
        }
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
