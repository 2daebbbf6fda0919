//! `asperity spots`: resistance of explicit contact spots read from a CSV
//! file (`x_m,y_m,radius_m`), computed by [`asperity::commands::spots`].

use asperity::commands::spots::{read_file, resistances, SpotsInput};
use clap::Args;
use std::path::PathBuf;

/// Arguments of `asperity spots`.
#[derive(Args, Debug)]
pub struct SpotsArgs {
    /// CSV file with header `x_m,y_m,radius_m` (any column order), one spot
    /// per line, SI units.
    file: PathBuf,
    /// Resistivity of the metal (Ohm m), > 0.
    #[arg(long, allow_hyphen_values = true)]
    resistivity: f64,
    /// Electron mean free path (m), > 0: each spot's self resistance is then
    /// Wexler's instead of Maxwell's.
    #[arg(long, allow_hyphen_values = true)]
    mean_free_path: Option<f64>,
    /// Print one JSON object instead of a table.
    #[arg(long)]
    json: bool,
}

pub fn run(args: &SpotsArgs) -> crate::CliResult {
    // The metal first, so a bad flag is named before the file is read.
    asperity::commands::spots::spot_resistance(args.resistivity, args.mean_free_path)?;
    let cols = read_file(&args.file)?;
    let out = resistances(&SpotsInput {
        x: &cols.x,
        y: &cols.y,
        radius: &cols.radius,
        resistivity: args.resistivity,
        mean_free_path: args.mean_free_path,
    })?;
    if args.json {
        crate::outln!("{}", asperity::commands::json_line(&out)?);
    } else {
        crate::outln!(
            "{} spots, {} self resistance",
            out.spots,
            out.spreading.name()
        );
        crate::outln!("parallel (Holm)     {:.9e} Ohm", out.parallel_ohm);
        crate::outln!("Greenwood (1966)    {:.9e} Ohm", out.greenwood_ohm);
        crate::outln!("exact (equal pot.)  {:.9e} Ohm", out.exact_ohm);
    }
    Ok(())
}
