//! `asperity spots`: resistance of explicit contact spots read from a CSV
//! file (`x_m,y_m,radius_m`): independent parallel spots, Greenwood's
//! (1966) formula and the exact equal-potential solution
//! ([`crate::electrical::Spots`]).

use super::{CommandError, CommandResult};
use crate::electrical::{SpotResistance, Spots, Spreading};
use crate::error::positive;
use serde::Serialize;

/// Arguments of `asperity spots`.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "cli", derive(clap::Args))]
pub struct SpotsArgs {
    /// CSV file with header `x_m,y_m,radius_m` (any column order), one spot
    /// per line, SI units.
    pub file: String,
    /// Resistivity of the metal (Ohm m), > 0.
    #[cfg_attr(feature = "cli", arg(long, allow_hyphen_values = true))]
    pub resistivity: f64,
    /// Electron mean free path (m), > 0: each spot's self resistance is then
    /// Wexler's instead of Maxwell's.
    #[cfg_attr(feature = "cli", arg(long, allow_hyphen_values = true))]
    pub mean_free_path: Option<f64>,
    /// Print one JSON object instead of a table.
    #[cfg_attr(feature = "cli", arg(long))]
    pub json: bool,
}

/// What `asperity spots --json` prints (Ohm).
#[derive(Serialize, Debug, Clone, Copy)]
pub struct SpotsOutput {
    /// Independent parallel spots (Holm).
    pub parallel_ohm: f64,
    /// Greenwood's (1966) formula.
    pub greenwood_ohm: f64,
    /// The exact equal-potential solution.
    pub exact_ohm: f64,
}

const COLUMNS: [&str; 3] = ["x_m", "y_m", "radius_m"];

/// Parses the spots CSV: a header naming `x_m,y_m,radius_m`, then numbers.
/// Errors name the column (and line).
pub fn parse_csv(text: &str) -> CommandResult<Spots> {
    // A UTF-8 byte-order mark (spreadsheets write one) before the header,
    // accepted as in scenes.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty());
    let (_, header) = lines.next().ok_or_else(|| {
        CommandError::Usage("spots file: empty, expected header x_m,y_m,radius_m".into())
    })?;
    let names: Vec<&str> = header.split(',').map(str::trim).collect();
    let mut index = [0usize; 3];
    for (k, col) in COLUMNS.iter().enumerate() {
        index[k] = names.iter().position(|n| n == col).ok_or_else(|| {
            CommandError::Usage(format!(
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
                .ok_or_else(|| CommandError::Usage(format!("{at}: missing value")))?;
            let x: f64 = t.parse().map_err(|_| {
                CommandError::Usage(format!("{at}: cannot parse {t:?} as a number"))
            })?;
            if k == 2 {
                positive(&at, x)?;
            } else {
                crate::error::finite(&at, x)?;
            }
            cols[k].push(x);
        }
    }
    if cols[0].is_empty() {
        return Err(CommandError::Usage(
            "spots file: no spots after the header".into(),
        ));
    }
    let [x, y, r] = cols;
    Ok(Spots::new(x, y, r)?)
}

/// Spots from columns: centres `x`, `y` (m, finite) and radii `radius`
/// (m, > 0); errors name the argument and the index.
pub fn from_columns(x: Vec<f64>, y: Vec<f64>, radius: Vec<f64>) -> CommandResult<Spots> {
    for (name, col) in [("x", &x), ("y", &y), ("radius", &radius)] {
        for (i, &v) in col.iter().enumerate() {
            let at = format!("{name}[{i}]");
            if name == "radius" {
                positive(&at, v)?;
            } else {
                crate::error::finite(&at, v)?;
            }
        }
    }
    if x.is_empty() {
        return Err(CommandError::Usage("x: no spots".into()));
    }
    check_cost("x", x.len())?;
    Ok(Spots::new(x, y, radius)?)
}

/// The self resistance: Maxwell's, or Wexler's with a mean free path.
/// Errors name `--resistivity` or `--mean-free-path`.
pub fn spot_resistance(
    resistivity: f64,
    mean_free_path: Option<f64>,
) -> CommandResult<SpotResistance> {
    positive("--resistivity", resistivity)?;
    if let Some(l) = mean_free_path {
        positive("--mean-free-path", l)?;
    }
    let spreading = match mean_free_path {
        Some(_) => Spreading::Wexler,
        None => Spreading::Maxwell,
    };
    SpotResistance::same_metal(spreading, resistivity, mean_free_path).map_err(|e| {
        super::flagged(
            e,
            &[
                ("resistivity", "--resistivity"),
                ("mean_free_path", "--mean-free-path"),
            ],
        )
        .into()
    })
}

/// The three resistances of `spots`.
pub fn resistances(spots: &Spots, spot: &SpotResistance) -> CommandResult<SpotsOutput> {
    Ok(SpotsOutput {
        parallel_ohm: spots.parallel(spot),
        greenwood_ohm: spots.greenwood(spot),
        exact_ohm: spots.exact(spot)?,
    })
}

/// Most spots `asperity spots` solves: the exact equal-potential solve is
/// O(n^3) in time and O(n^2) in memory ([`Spots::exact_cost`]: about 80 s
/// of one core and 6.4 GB at 20,000 spots).
pub const MAX_SPOTS: usize = 20_000;

/// Checks the exact solve of `n` spots from `what` (the file or argument)
/// is within [`MAX_SPOTS`] and the memory available, before it starts.
/// `Ok(Some(note))` when it is estimated to take more than 2 s (a note
/// with the estimate, for stderr).
///
/// # Errors
/// [`CommandError::Usage`] naming `what`, with the estimate and the bound.
pub fn check_cost(what: &str, n: usize) -> CommandResult<Option<String>> {
    let (seconds, bytes) = Spots::exact_cost(n);
    let estimate = format!(
        "the exact equal-potential solve of {n} spots needs an estimated {seconds:.3} s of one \
         core and {:.3} GB (1e-11 n^3 s, 16 n^2 bytes)",
        bytes / 1e9
    );
    if n > MAX_SPOTS {
        return Err(CommandError::Usage(format!(
            "{what}: {estimate}; allowed up to {MAX_SPOTS} spots"
        )));
    }
    if let Some(free) = crate::study::memory::available() {
        if bytes > free {
            return Err(CommandError::Usage(format!(
                "{what}: {estimate}, more than the {:.3} GB this process may still use",
                free / 1e9
            )));
        }
    }
    Ok((seconds > 2.0).then(|| format!("spots: {estimate}")))
}

/// Runs `asperity spots`: also returns the spots read. Spots whose exact
/// solve is estimated above 2 s are announced on stderr with the estimate.
pub fn run(args: &SpotsArgs) -> CommandResult<(SpotsOutput, Spots)> {
    let spot = spot_resistance(args.resistivity, args.mean_free_path)?;
    let text = super::read_input("spots file", std::path::Path::new(&args.file))?;
    let spots = parse_csv(&text).map_err(|e| match e {
        CommandError::Usage(m) => CommandError::Usage(format!("spots file {}: {m}", args.file)),
        other => other,
    })?;
    if let Some(note) = check_cost(&format!("spots file {}", args.file), spots.len())? {
        eprintln!("{note}");
    }
    Ok((resistances(&spots, &spot)?, spots))
}
