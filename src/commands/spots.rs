//! `asperity spots`: resistance of explicit contact spots read from a CSV
//! file (`x_m,y_m,radius_m`): independent parallel spots, Greenwood's
//! (1966) formula and the exact equal-potential solution
//! ([`crate::electrical::Spots`]).

use super::{param, CommandResult};
use crate::electrical::{SpotResistance, Spots, Spreading};
use crate::error::positive;
use crate::Error;
use serde::Serialize;

/// The input of [`resistances`]: spots as columns and their metal.
#[derive(Debug, Clone, Copy)]
pub struct SpotsInput<'a> {
    /// Spot centres x (m), finite.
    pub x: &'a [f64],
    /// Spot centres y (m), finite, as many as `x`.
    pub y: &'a [f64],
    /// Spot radii (m), > 0, as many as `x`.
    pub radius: &'a [f64],
    /// Resistivity of the metal (Ohm m), > 0.
    pub resistivity: f64,
    /// Electron mean free path (m), > 0: each spot's self resistance is
    /// then Wexler's instead of Maxwell's.
    pub mean_free_path: Option<f64>,
}

/// What `asperity spots --json` prints (Ohm).
#[derive(Serialize, Debug, Clone, Copy)]
pub struct SpotsOutput {
    /// Number of spots (not in the JSON).
    #[serde(skip)]
    pub spots: usize,
    /// The self resistance used (not in the JSON): Maxwell's, or Wexler's
    /// with a mean free path.
    #[serde(skip)]
    pub spreading: Spreading,
    /// Independent parallel spots (Holm).
    pub parallel_ohm: f64,
    /// Greenwood's (1966) formula.
    pub greenwood_ohm: f64,
    /// The exact equal-potential solution.
    pub exact_ohm: f64,
}

const COLUMNS: [&str; 3] = ["x_m", "y_m", "radius_m"];

/// Columns of spots read from a CSV file: centres and radii (m).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SpotColumns {
    /// Centres x (m).
    pub x: Vec<f64>,
    /// Centres y (m).
    pub y: Vec<f64>,
    /// Radii (m).
    pub radius: Vec<f64>,
}

/// Parses the spots CSV: a header naming `x_m,y_m,radius_m`, then numbers.
/// Errors name the column (and line).
///
/// # Errors
/// [`Error::Invalid`] / [`Error::OutOfRange`] naming the column and line.
pub fn parse_csv(text: &str) -> CommandResult<SpotColumns> {
    // A UTF-8 byte-order mark (spreadsheets write one) before the header,
    // accepted as in scenes.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty());
    let (_, header) = lines
        .next()
        .ok_or_else(|| Error::invalid("spots file", "empty, expected header x_m,y_m,radius_m"))?;
    let names: Vec<&str> = header.split(',').map(str::trim).collect();
    let mut index = [0usize; 3];
    for (k, col) in COLUMNS.iter().enumerate() {
        index[k] = names.iter().position(|n| n == col).ok_or_else(|| {
            Error::invalid(
                *col,
                format!("missing column in the spots file header {header:?}"),
            )
        })?;
    }
    let mut cols: [Vec<f64>; 3] = Default::default();
    for (i, line) in lines {
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        for (k, col) in COLUMNS.iter().enumerate() {
            let at = format!("{col} (line {})", i + 1);
            let t = fields
                .get(index[k])
                .ok_or_else(|| Error::invalid(&at, "missing value"))?;
            let x: f64 = t
                .parse()
                .map_err(|_| Error::invalid(&at, format!("cannot parse {t:?} as a number")))?;
            if k == 2 {
                positive(&at, x)?;
            } else {
                crate::error::finite(&at, x)?;
            }
            cols[k].push(x);
        }
    }
    if cols[0].is_empty() {
        return Err(Error::invalid("spots file", "no spots after the header"));
    }
    let [x, y, radius] = cols;
    Ok(SpotColumns { x, y, radius })
}

/// Spots from columns: centres `x`, `y` (m, finite) and radii `radius`
/// (m, > 0), checked against [`MAX_SPOTS`] and the memory available.
///
/// # Errors
/// Naming the input and the entry (`{radius[3]}`), or `{x}` for the count.
pub fn spots_of(x: &[f64], y: &[f64], radius: &[f64]) -> CommandResult<Spots> {
    for (name, col) in [("x", x), ("y", y), ("radius", radius)] {
        for (i, &v) in col.iter().enumerate() {
            let at = param(&format!("{name}[{i}]"));
            if name == "radius" {
                positive(&at, v)?;
            } else {
                crate::error::finite(&at, v)?;
            }
        }
    }
    if x.len() != y.len() || x.len() != radius.len() {
        return Err(Error::invalid(
            format!("{}, {}, {}", param("x"), param("y"), param("radius")),
            format!("lengths {}, {}, {} differ", x.len(), y.len(), radius.len()),
        ));
    }
    if x.is_empty() {
        return Err(Error::invalid(param("x"), "no spots"));
    }
    check_cost(&param("x"), x.len())?;
    Spots::new(x.to_vec(), y.to_vec(), radius.to_vec())
}

/// The self resistance: Maxwell's, or Wexler's with a mean free path.
///
/// # Errors
/// Naming `{resistivity}` or `{mean_free_path}`.
pub fn spot_resistance(
    resistivity: f64,
    mean_free_path: Option<f64>,
) -> CommandResult<SpotResistance> {
    positive(&param("resistivity"), resistivity)?;
    if let Some(l) = mean_free_path {
        positive(&param("mean_free_path"), l)?;
    }
    let spreading = match mean_free_path {
        Some(_) => Spreading::Wexler,
        None => Spreading::Maxwell,
    };
    SpotResistance::same_metal(spreading, resistivity, mean_free_path).map_err(|e| {
        super::named(
            e,
            &[
                ("resistivity", "resistivity"),
                ("mean_free_path", "mean_free_path"),
            ],
        )
    })
}

/// The three resistances of the spots of `input` (`asperity spots`): the
/// exact solve polls [`crate::cancel`] before it starts (the solve itself,
/// at most about 80 s at [`MAX_SPOTS`], runs to its end).
///
/// # Errors
/// Naming an input (see [`spots_of`], [`spot_resistance`]); the exact
/// solve's failure naming `spots`; [`Error::Cancelled`].
pub fn resistances(input: &SpotsInput<'_>) -> CommandResult<SpotsOutput> {
    let spot = spot_resistance(input.resistivity, input.mean_free_path)?;
    let spots = spots_of(input.x, input.y, input.radius)?;
    crate::cancel::check()?;
    Ok(SpotsOutput {
        spots: spots.len(),
        spreading: spot.spreading(),
        parallel_ohm: spots.parallel(&spot),
        greenwood_ohm: spots.greenwood(&spot),
        exact_ohm: spots.exact(&spot)?,
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
/// [`Error::Invalid`] naming `what` beyond [`MAX_SPOTS`],
/// [`Error::OutOfMemory`] beyond the memory available, with the estimate.
pub fn check_cost(what: &str, n: usize) -> CommandResult<Option<String>> {
    let (seconds, bytes) = Spots::exact_cost(n);
    let estimate = format!(
        "the exact equal-potential solve of {n} spots needs an estimated {seconds:.3} s of one \
         core and {:.3} GB (1e-11 n^3 s, 16 n^2 bytes)",
        bytes / 1e9
    );
    if n > MAX_SPOTS {
        return Err(Error::invalid(
            what,
            format!("{estimate}; allowed up to {MAX_SPOTS} spots"),
        ));
    }
    crate::study::memory::ensure(
        what,
        &format!("the exact equal-potential solve of {n} spots"),
        bytes,
        "",
    )?;
    Ok((seconds > 2.0).then(|| format!("spots: {estimate}")))
}

/// Reads the spots CSV file `path` (named in every error), announcing on
/// stderr a solve estimated above 2 s.
///
/// # Errors
/// The file unreadable or malformed, naming it; beyond [`check_cost`].
pub fn read_file(path: &std::path::Path) -> CommandResult<SpotColumns> {
    let shown = path.display().to_string();
    let text = super::read_input("spots file", path)?;
    let cols = parse_csv(&text).map_err(|e| match e {
        Error::Invalid { .. } | Error::OutOfRange { .. } => {
            let field = e.field().unwrap_or("").to_string();
            e.renamed(&format!("spots file {shown}: {field}"))
        }
        other => other,
    })?;
    if let Some(note) = check_cost(&format!("spots file {shown}"), cols.x.len())? {
        eprintln!("{note}");
    }
    Ok(cols)
}
