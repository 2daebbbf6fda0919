//! `asperity spots`: resistance of explicit contact spots read from a CSV
//! file (`x_m,y_m,radius_m`): independent parallel spots, Greenwood's
//! (1966) formula and the exact equal-potential solution.

use crate::CliError;
use asperity::electrical::{SpotResistance, Spots, Spreading};
use asperity::error::positive;
use clap::Args;
use serde::Serialize;

/// Arguments of `asperity spots`.
#[derive(Args, Debug)]
pub struct SpotsArgs {
    /// CSV file with header `x_m,y_m,radius_m` (any column order), one spot
    /// per line, SI units.
    file: String,
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

#[derive(Serialize, Debug)]
struct Output {
    parallel_ohm: f64,
    greenwood_ohm: f64,
    exact_ohm: f64,
}

const COLUMNS: [&str; 3] = ["x_m", "y_m", "radius_m"];

/// Parses the spots CSV: a header naming [`COLUMNS`], then numbers. Errors
/// name the column (and line).
fn parse_csv(text: &str) -> Result<Spots, CliError> {
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty());
    let (_, header) = lines.next().ok_or_else(|| {
        CliError::Usage("spots file: empty, expected header x_m,y_m,radius_m".into())
    })?;
    let names: Vec<&str> = header.split(',').map(str::trim).collect();
    let mut index = [0usize; 3];
    for (k, col) in COLUMNS.iter().enumerate() {
        index[k] = names.iter().position(|n| n == col).ok_or_else(|| {
            CliError::Usage(format!(
                "{col}: missing column in the spots file header {header:?}"
            ))
        })?;
    }
    let mut cols: [Vec<f64>; 3] = Default::default();
    for (i, line) in lines {
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        for (k, col) in COLUMNS.iter().enumerate() {
            let at = format!("{col} (line {})", i + 1);
            let t = fields
                .get(index[k])
                .ok_or_else(|| CliError::Usage(format!("{at}: missing value")))?;
            let x: f64 = t
                .parse()
                .map_err(|_| CliError::Usage(format!("{at}: cannot parse {t:?} as a number")))?;
            if k == 2 {
                positive(&at, x)?;
            } else {
                asperity::error::finite(&at, x)?;
            }
            cols[k].push(x);
        }
    }
    if cols[0].is_empty() {
        return Err(CliError::Usage(
            "spots file: no spots after the header".into(),
        ));
    }
    let [x, y, r] = cols;
    Ok(Spots::new(x, y, r)?)
}

pub fn run(args: &SpotsArgs) -> crate::CliResult {
    positive("--resistivity", args.resistivity)?;
    if let Some(l) = args.mean_free_path {
        positive("--mean-free-path", l)?;
    }
    let spreading = match args.mean_free_path {
        Some(_) => Spreading::Wexler,
        None => Spreading::Maxwell,
    };
    let spot = SpotResistance::same_metal(spreading, args.resistivity, args.mean_free_path)?;
    let text =
        std::fs::read_to_string(&args.file).map_err(|e| asperity::Error::io(&args.file, e))?;
    let spots = parse_csv(&text)?;
    let out = Output {
        parallel_ohm: spots.parallel(&spot),
        greenwood_ohm: spots.greenwood(&spot),
        exact_ohm: spots.exact(&spot)?,
    };
    if args.json {
        let s = serde_json::to_string(&out).map_err(|e| CliError::Failed(e.to_string()))?;
        println!("{s}");
    } else {
        println!(
            "{} spots, {} self resistance",
            spots.len(),
            spreading.name()
        );
        println!("parallel (Holm)     {:.9e} Ohm", out.parallel_ohm);
        println!("Greenwood (1966)    {:.9e} Ohm", out.greenwood_ohm);
        println!("exact (equal pot.)  {:.9e} Ohm", out.exact_ohm);
    }
    Ok(())
}
