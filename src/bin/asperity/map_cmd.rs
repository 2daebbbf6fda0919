//! `asperity map [--tolerance T] [--out DIR]`: the adhesion map.

use asperity::law::errors::LawErrorTable;
use asperity::study::plot::{adhesion_map_csv, write_adhesion_map};
use clap::Args;
use std::path::PathBuf;

/// Arguments of `asperity map`.
#[derive(Args, Debug)]
pub struct MapArgs {
    /// Relative load error a law may have, in (0, 1).
    #[arg(long, default_value_t = 0.05, allow_hyphen_values = true)]
    tolerance: f64,
    /// Directory for map.svg and map.csv.
    #[arg(long, default_value = "asperity-out")]
    out: PathBuf,
}

pub fn run(args: &MapArgs) -> crate::CliResult {
    asperity::error::Allowed::open(0.0, 1.0).check("--tolerance", args.tolerance)?;
    let table = LawErrorTable::embedded();
    let dir = &args.out;
    std::fs::create_dir_all(dir)
        .map_err(|e| crate::CliError::Failed(format!("--out: {}: {e}", dir.display())))?;
    let svg = dir.join("map.svg");
    write_adhesion_map(table, args.tolerance, &svg)?;
    let csv = dir.join("map.csv");
    asperity::study::atomic::write(&csv, adhesion_map_csv(table, args.tolerance))
        .map_err(|e| crate::CliError::Failed(format!("--out: {}: {e}", csv.display())))?;
    println!(
        "adhesion map at tolerance {:e} ({} Tabor parameters x {} loads; {})",
        args.tolerance,
        table.mu.len(),
        table.load_bar.len(),
        table.provenance
    );
    println!("  wrote {}", svg.display());
    println!("  wrote {}", csv.display());
    Ok(())
}
