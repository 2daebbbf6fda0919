//! `asperity heating`: Holm's phi-theta relation with Wiedemann–Franz,
//! peak contact temperature from the contact voltage or the reverse.

use crate::CliError;
use asperity::electrical::heating::{Heating, DEFAULT_BULK_TEMPERATURE};
use clap::Args;
use serde::Serialize;

/// Arguments of `asperity heating`: exactly one of `--voltage`,
/// `--max-temperature`.
#[derive(Args, Debug)]
pub struct HeatingArgs {
    /// Contact voltage U = I R (V), >= 0: prints the peak temperature.
    #[arg(long, allow_hyphen_values = true)]
    voltage: Option<f64>,
    /// Peak contact temperature (K), >= the bulk temperature: prints the
    /// voltage that reaches it.
    #[arg(long, allow_hyphen_values = true)]
    max_temperature: Option<f64>,
    /// Bulk temperature T0 (K), > 0.
    #[arg(long, allow_hyphen_values = true, default_value_t = DEFAULT_BULK_TEMPERATURE)]
    bulk_temperature: f64,
    /// Print one JSON object instead of a line.
    #[arg(long)]
    json: bool,
}

#[derive(Serialize, Debug)]
struct Temperature {
    #[serde(rename = "max_temperature_K")]
    max_temperature: f64,
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
    let heating =
        Heating::new(args.bulk_temperature).map_err(|e| e.renamed("--bulk-temperature"))?;
    if args.voltage.is_some() == args.max_temperature.is_some() {
        return Err(CliError::Usage(
            "--voltage, --max-temperature: give exactly one of them".into(),
        ));
    }
    if let Some(u) = args.voltage {
        let t = heating
            .max_temperature(u)
            .map_err(|e| e.renamed("--voltage"))?;
        if args.json {
            return print(&Temperature { max_temperature: t });
        }
        println!(
            "peak contact temperature {t:.6} K at {u} V (bulk {} K)",
            heating.bulk_temperature()
        );
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
