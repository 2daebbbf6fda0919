//! `asperity heating`: Holm's phi-theta relation with Wiedemann–Franz,
//! peak contact temperature from the contact voltage or the reverse
//! (computed by [`asperity::commands::heating`]).

use crate::CliError;
pub use asperity::commands::heating::HeatingArgs;
use asperity::commands::heating::HeatingOutput;

pub fn run(args: &HeatingArgs) -> crate::CliResult {
    let (out, bulk) = asperity::commands::heating::run(args)?;
    if args.json {
        let s = serde_json::to_string(&out).map_err(|e| CliError::Failed(e.to_string()))?;
        println!("{s}");
        return Ok(());
    }
    match (out, args.voltage, args.max_temperature) {
        (
            HeatingOutput::Temperature {
                max_temperature,
                warnings,
                ..
            },
            Some(u),
            _,
        ) => {
            match max_temperature {
                Some(t) => println!("peak contact temperature {t:.6} K at {u} V (bulk {bulk} K)"),
                None => {
                    println!("no peak contact temperature at {u} V: the spot melts (bulk {bulk} K)")
                }
            }
            for w in warnings {
                eprintln!("warning: {w}");
            }
        }
        (HeatingOutput::Voltage { voltage: u }, _, Some(t)) => {
            println!("contact voltage {u:.9} V reaches {t} K (bulk {bulk} K)")
        }
        _ => {}
    }
    Ok(())
}
