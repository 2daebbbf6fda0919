//! `asperity fn`: the Greenwood–Williamson integrals
//! `F_n(h) = int_h^inf (s - h)^n phi(s) ds` of a standardised height
//! distribution (`docs/architecture.md`, height distributions).

use super::{list, CommandError, CommandResult};
use crate::heights::{Exponential, Gaussian, HeightDistribution};
use serde::Serialize;

/// Arguments of `asperity fn`.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "cli", derive(clap::Args))]
pub struct FnArgs {
    /// Height distribution: gaussian or exponential.
    #[cfg_attr(feature = "cli", arg(long))]
    pub dist: String,
    /// Order n in [0, 100] of F_n(h) = int_h^inf (s-h)^n phi(s) ds.
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub n: f64,
    /// Comma-separated standardised separations h, e.g. -1,0,2.5.
    #[cfg_attr(feature = "cli", arg(long, allow_hyphen_values = true))]
    pub h: String,
    /// Print one JSON object instead of a table.
    #[cfg_attr(feature = "cli", arg(long))]
    pub json: bool,
}

/// One value: `{"h": .., "F": ..}`.
#[derive(Serialize, Debug, Clone, Copy)]
pub struct Row {
    /// Standardised separation `h = d / sigma`.
    pub h: f64,
    /// `F_n(h)` (dimensionless).
    #[serde(rename = "F")]
    pub f: f64,
}

/// What `asperity fn --json` prints.
#[derive(Serialize, Debug, Clone)]
pub struct FnOutput {
    /// The distribution's name.
    pub dist: &'static str,
    /// The order `n`.
    pub n: f64,
    /// `F_n` at each `h`, in the order given.
    pub values: Vec<Row>,
    /// Whether `F_n` is in closed form (else adaptive quadrature).
    #[serde(skip)]
    pub closed_form: bool,
}

/// The distribution named by `--dist`.
pub fn distribution(name: &str) -> CommandResult<Box<dyn HeightDistribution>> {
    match name {
        "gaussian" => Ok(Box::new(Gaussian::new())),
        "exponential" => Ok(Box::new(Exponential::new())),
        other => Err(CommandError::Usage(format!(
            "--dist: unknown distribution {other:?}; known: gaussian, exponential"
        ))),
    }
}

/// `F_n(h)` of the distribution `dist` at every `h` (finite; errors name
/// `--dist`, `--n` (in [0, 100]) or `--h`, also when a value overflows), in
/// the order given.
pub fn values(dist: &str, n: f64, h: &[f64]) -> CommandResult<Vec<f64>> {
    let d = distribution(dist)?;
    crate::error::Allowed::closed(0.0, crate::heights::MAX_MOMENT_ORDER).check("--n", n)?;
    h.iter()
        .map(|&x| {
            d.moment_above_checked(n, x).map_err(|e| {
                match e.field() {
                    Some("n") => e.renamed("--n"),
                    _ => e.renamed("--h"),
                }
                .into()
            })
        })
        .collect()
}

/// Runs `asperity fn`.
pub fn run(args: &FnArgs) -> CommandResult<FnOutput> {
    let dist = distribution(&args.dist)?;
    let hs = list::parse("--h", &args.h)?;
    let f = values(&args.dist, args.n, &hs)?;
    Ok(FnOutput {
        dist: dist.name(),
        n: args.n,
        values: hs.iter().zip(f).map(|(&h, f)| Row { h, f }).collect(),
        closed_form: dist.closed_form_moment(args.n),
    })
}
