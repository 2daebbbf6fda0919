//! `asperity fn`: the Greenwood–Williamson integrals
//! `F_n(h) = int_h^inf (s - h)^n phi(s) ds` of a standardised height
//! distribution (`docs/architecture.md`, height distributions).

use super::{param, CommandResult};
use crate::error::Error;
use crate::heights::{DistributionKind, Exponential, Gaussian, HeightDistribution};
use crate::named::Named;
use serde::Serialize;

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

/// The standardised distribution `dist` (gaussian or exponential: the
/// distributions whose `F_n` takes no parameter).
///
/// # Errors
/// [`Error::Invalid`] naming `{dist}` for another distribution.
pub fn distribution(dist: DistributionKind) -> CommandResult<Box<dyn HeightDistribution>> {
    match dist {
        DistributionKind::Gaussian => Ok(Box::new(Gaussian::new())),
        DistributionKind::Exponential => Ok(Box::new(Exponential::new())),
        other => Err(Error::invalid(
            param("dist"),
            format!(
                "{:?} needs its parameter (a scene's surface table); known here: gaussian, \
                 exponential",
                other.name()
            ),
        )),
    }
}

/// The distribution called `name` among those [`distribution`] takes.
///
/// # Errors
/// [`Error::Invalid`] naming `{dist}` and the known names.
pub fn dist_named(name: &str) -> CommandResult<DistributionKind> {
    match DistributionKind::parse(name) {
        Ok(d @ (DistributionKind::Gaussian | DistributionKind::Exponential)) => Ok(d),
        _ => Err(Error::invalid(
            param("dist"),
            format!("unknown distribution {name:?}; known: gaussian, exponential"),
        )),
    }
}

/// Bytes of memory per value of [`values`]: the copy of `h` a caller makes
/// and the result.
pub const BYTES_PER_VALUE: f64 = 16.0;

/// `F_n(h)` of the distribution `dist` at every `h` (finite), in the order
/// given.
///
/// # Errors
/// Naming `{dist}`, `{n}` (in [0, 100]) or the entry `{h[i]}` (also when a
/// value overflows); [`Error::OutOfMemory`] naming `{h}` when the result
/// would not fit.
pub fn values(dist: DistributionKind, n: f64, h: &[f64]) -> CommandResult<Vec<f64>> {
    let d = distribution(dist)?;
    crate::error::Allowed::closed(0.0, crate::heights::MAX_MOMENT_ORDER).check(&param("n"), n)?;
    crate::study::memory::ensure(
        &param("h"),
        &format!("F_n at {} values", h.len()),
        h.len() as f64 * 8.0,
        "give fewer values per call",
    )?;
    h.iter()
        .enumerate()
        .map(|(i, &x)| {
            d.moment_above_checked(n, x).map_err(|e| match e.field() {
                Some("n") => e.renamed(&param("n")),
                _ => e.renamed(&param(&format!("h[{i}]"))),
            })
        })
        .collect()
}

/// The table `asperity fn` prints: `F_n` of `dist` at each `h`.
///
/// # Errors
/// As [`values`].
pub fn table(dist: DistributionKind, n: f64, h: &[f64]) -> CommandResult<FnOutput> {
    let d = distribution(dist)?;
    let f = values(dist, n, h)?;
    Ok(FnOutput {
        dist: d.name(),
        n,
        values: h.iter().zip(f).map(|(&h, f)| Row { h, f }).collect(),
        closed_form: d.closed_form_moment(n),
    })
}
