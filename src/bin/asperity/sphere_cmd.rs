//! `asperity sphere`: the full Lennard-Jones sphere solver's pull-off facts
//! (Maugis units) and, on request, the traced load–approach curve as CSV
//! (computed by [`asperity::commands::sphere`]).

use asperity::commands::sphere::{sphere, SphereInput};
use clap::Args;
use std::path::PathBuf;

/// Arguments of `asperity sphere`.
#[derive(Args, Debug)]
pub struct SphereArgs {
    /// Tabor parameter mu = (R w^2/(E*^2 z0^3))^(1/3), in [0.005, 100].
    #[arg(long, allow_hyphen_values = true)]
    mu: f64,
    /// Size ratio rho = R/z0 (>= 10, and >= 100 mu when mu > 10) for a true
    /// sphere; paraboloid if absent.
    #[arg(long, allow_hyphen_values = true)]
    rho: Option<f64>,
    /// Mesh resolution multiplier (default 1), in [0.5, 64]; runs estimated
    /// above 120 s or 2 GiB are refused with the estimate.
    #[arg(long, allow_hyphen_values = true)]
    resolution: Option<f64>,
    /// Print one JSON object instead of a table.
    #[arg(long)]
    json: bool,
    /// Write the traced curve (CSV with a header) to this file.
    #[arg(long)]
    curve: Option<PathBuf>,
}

pub fn run(args: &SphereArgs) -> crate::CliResult {
    let out = sphere(&SphereInput {
        mu: args.mu,
        rho: args.rho,
        resolution: args.resolution,
        curve: args.curve.clone(),
    })?;
    crate::print_output(&out, &out.text, args.json)
}
