//! `asperity heating`: Holm's phi-theta relation with Wiedemann–Franz,
//! peak contact temperature from the contact voltage or the reverse.

use crate::CliError;
use asperity::electrical::heating::{
    Heating, SpotCondition, DEFAULT_BULK_TEMPERATURE, GOLD_MELTING_TEMPERATURE,
    GOLD_SOFTENING_TEMPERATURE,
};
use clap::Args;
use serde::Serialize;

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

#[derive(Serialize, Debug)]
struct Temperature {
    /// `null` once the spot melts.
    #[serde(rename = "max_temperature_K")]
    max_temperature: Option<f64>,
    /// `solid`, `softened` or `molten`.
    condition: SpotCondition,
    warnings: Vec<String>,
}

#[derive(Serialize, Debug)]
struct Voltage {
    #[serde(rename = "voltage_V")]
    voltage: f64,
}

fn print<T: Serialize>(v: &T) -> crate::CliResult {
    let s = serde_json::to_string(v).map_err(|e| CliError::Failed(e.to_string()))?;
    println!("{s}");
    Ok(())
}

pub fn run(args: &HeatingArgs) -> crate::CliResult {
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
    if args.voltage.is_some() == args.max_temperature.is_some() {
        return Err(CliError::Usage(
            "--voltage, --max-temperature: give exactly one of them".into(),
        ));
    }
    if let Some(u) = args.voltage {
        let rename = |e: asperity::Error| e.renamed("--voltage");
        let t = heating.peak_temperature(u).map_err(rename)?;
        let condition = heating.condition(u).map_err(rename)?;
        let warnings: Vec<String> = heating.warning(u).map_err(rename)?.into_iter().collect();
        if args.json {
            return print(&Temperature {
                max_temperature: t,
                condition,
                warnings,
            });
        }
        match t {
            Some(t) => println!(
                "peak contact temperature {t:.6} K at {u} V (bulk {} K)",
                heating.bulk_temperature()
            ),
            None => println!(
                "no peak contact temperature at {u} V: the spot melts (bulk {} K)",
                heating.bulk_temperature()
            ),
        }
        for w in warnings {
            eprintln!("warning: {w}");
        }
    } else if let Some(t) = args.max_temperature {
        let u = heating
            .voltage_for(t)
            .map_err(|e| e.renamed("--max-temperature"))?;
        if args.json {
            return print(&Voltage { voltage: u });
        }
        println!(
            "contact voltage {u:.9} V reaches {t} K (bulk {} K)",
            heating.bulk_temperature()
        );
    }
    Ok(())
}
