//! `asperity heating`: Holm's phi-theta relation with Wiedemann–Franz,
//! peak contact temperature from the contact voltage or the reverse
//! (computed by [`asperity::commands::heating`]).

use asperity::commands::heating::{heating, HeatingInput, HeatingOutput, HeatingTarget};
use asperity::electrical::heating::{
    DEFAULT_BULK_TEMPERATURE, GOLD_MELTING_TEMPERATURE, GOLD_SOFTENING_TEMPERATURE,
};
use clap::Args;

/// Arguments of `asperity heating`: exactly one of `--voltage`,
/// `--max-temperature`.
#[derive(Args, Debug)]
pub struct HeatingArgs {
    /// Contact voltage U = I R (V), >= 0: prints the peak temperature.
    #[arg(long, allow_hyphen_values = true)]
    voltage: Option<f64>,
    /// Peak contact temperature (K), from the bulk temperature to the
    /// melting temperature: prints the voltage that reaches it.
    #[arg(long, allow_hyphen_values = true)]
    max_temperature: Option<f64>,
    /// Bulk temperature T0 (K), in (0, melting temperature).
    #[arg(long, allow_hyphen_values = true, default_value_t = DEFAULT_BULK_TEMPERATURE)]
    bulk_temperature: f64,
    /// Softening temperature of the metal (K), > 0; default gold's
    /// (373.15 K, Holm): above it the spot yields and a warning says so.
    #[arg(long, allow_hyphen_values = true, default_value_t = GOLD_SOFTENING_TEMPERATURE)]
    softening_temperature: f64,
    /// Melting temperature of the metal (K), > the softening temperature;
    /// default gold's (1337.33 K): no temperature is given above it.
    #[arg(long, allow_hyphen_values = true, default_value_t = GOLD_MELTING_TEMPERATURE)]
    melting_temperature: f64,
    /// Print one JSON object instead of a line.
    #[arg(long)]
    json: bool,
}

pub fn run(args: &HeatingArgs) -> crate::CliResult {
    let input = HeatingInput {
        target: HeatingTarget::from_options(args.voltage, args.max_temperature)?,
        bulk_temperature: args.bulk_temperature,
        softening_temperature: args.softening_temperature,
        melting_temperature: args.melting_temperature,
    };
    let (out, bulk) = heating(&input)?;
    if args.json {
        crate::outln!("{}", asperity::commands::json_line(&out)?);
        return Ok(());
    }
    match (out, input.target) {
        (
            HeatingOutput::Temperature {
                max_temperature,
                warnings,
                ..
            },
            HeatingTarget::Voltage(u),
        ) => {
            match max_temperature {
                Some(t) => {
                    crate::outln!("peak contact temperature {t:.6} K at {u} V (bulk {bulk} K)")
                }
                None => {
                    crate::outln!(
                        "no peak contact temperature at {u} V: the spot melts (bulk {bulk} K)"
                    )
                }
            }
            for w in warnings {
                eprintln!("warning: {w}");
            }
        }
        (HeatingOutput::Voltage { voltage: u }, HeatingTarget::MaxTemperature(t)) => {
            crate::outln!("contact voltage {u:.9} V reaches {t} K (bulk {bulk} K)")
        }
        _ => {}
    }
    Ok(())
}
