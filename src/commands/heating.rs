//! `asperity heating`: Holm's phi-theta relation with Wiedemann–Franz, the
//! peak contact temperature from the contact voltage or the reverse
//! ([`crate::electrical::heating`]).

use super::{param, CommandResult};
use crate::electrical::heating::{
    Heating, SpotCondition, GOLD_MELTING_TEMPERATURE, GOLD_SOFTENING_TEMPERATURE,
};
use crate::Error;
use serde::Serialize;

/// What [`heating`] computes: the peak temperature at a contact voltage,
/// or the voltage that reaches a peak temperature.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum HeatingTarget {
    /// Contact voltage `U = I R` (V), >= 0: the peak temperature.
    Voltage(f64),
    /// Peak contact temperature (K), from the bulk to the melting
    /// temperature: the voltage that reaches it.
    MaxTemperature(f64),
}

impl HeatingTarget {
    /// The target from the two optional inputs, exactly one of which is
    /// given.
    ///
    /// # Errors
    /// [`crate::Error::Invalid`] naming `{voltage}` and `{max_temperature}`.
    pub fn from_options(voltage: Option<f64>, max_temperature: Option<f64>) -> CommandResult<Self> {
        match (voltage, max_temperature) {
            (Some(u), None) => Ok(HeatingTarget::Voltage(u)),
            (None, Some(t)) => Ok(HeatingTarget::MaxTemperature(t)),
            _ => Err(Error::invalid(
                format!("{}, {}", param("voltage"), param("max_temperature")),
                "give exactly one of them",
            )),
        }
    }
}

/// The input of [`heating`].
#[derive(Debug, Clone, Copy)]
pub struct HeatingInput {
    /// What to compute.
    pub target: HeatingTarget,
    /// Bulk temperature `T0` (K), in (0, melting temperature); default
    /// [`crate::electrical::heating::DEFAULT_BULK_TEMPERATURE`].
    pub bulk_temperature: f64,
    /// Softening temperature of the metal (K), > 0; default gold's
    /// (373.15 K, Holm): above it the spot yields and a warning says so.
    pub softening_temperature: f64,
    /// Melting temperature of the metal (K), > the softening temperature;
    /// default gold's (1337.33 K): no temperature is given above it.
    pub melting_temperature: f64,
}

impl HeatingInput {
    /// `target` with gold's defaults.
    pub fn new(target: HeatingTarget) -> Self {
        HeatingInput {
            target,
            bulk_temperature: crate::electrical::heating::DEFAULT_BULK_TEMPERATURE,
            softening_temperature: GOLD_SOFTENING_TEMPERATURE,
            melting_temperature: GOLD_MELTING_TEMPERATURE,
        }
    }
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

/// Holm's phi-theta relation (`asperity heating`); also returns the bulk
/// temperature used.
///
/// # Errors
/// Naming `{voltage}`, `{max_temperature}`, `{bulk_temperature}`,
/// `{softening_temperature}` or `{melting_temperature}`.
pub fn heating(input: &HeatingInput) -> CommandResult<(HeatingOutput, f64)> {
    // The pair's order, named by both inputs (a huge softening temperature
    // was blamed on the melting temperature alone).
    super::check_order(
        ("softening_temperature", input.softening_temperature),
        ("melting_temperature", input.melting_temperature),
        " K",
        true,
    )?;
    let heating = Heating::for_metal(
        input.bulk_temperature,
        input.softening_temperature,
        input.melting_temperature,
    )
    .map_err(|e| {
        let name = match e.field() {
            Some("softening_temperature") => "softening_temperature",
            Some("melting_temperature") => "melting_temperature",
            _ => "bulk_temperature",
        };
        e.renamed(&param(name))
    })?;
    let out = match input.target {
        HeatingTarget::Voltage(u) => {
            let rename = |e: Error| e.renamed(&param("voltage"));
            HeatingOutput::Temperature {
                max_temperature: heating.peak_temperature(u).map_err(rename)?,
                condition: heating.condition(u).map_err(rename)?,
                warnings: (heating.warning(u).map_err(rename)?.iter())
                    .map(ToString::to_string)
                    .collect(),
            }
        }
        HeatingTarget::MaxTemperature(t) => HeatingOutput::Voltage {
            voltage: heating
                .voltage_for(t)
                .map_err(|e| e.renamed(&param("max_temperature")))?,
        },
    };
    Ok((out, heating.bulk_temperature()))
}
