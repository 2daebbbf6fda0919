//! `asperity rough-sphere`: the Greenwood–Tripp rough sphere in
//! Greenwood–Tripp units (computed by [`asperity::commands::rough_sphere`]).

use asperity::commands::rough_sphere::{rough_sphere, RoughSphereInput};
use clap::Args;
use std::path::PathBuf;

/// Arguments of `asperity rough-sphere`.
#[derive(Args, Debug)]
pub struct RoughSphereArgs {
    /// mu = (8/3) eta sigma sqrt(2 R beta) (> 0): summit density eta, summit-height
    /// standard deviation sigma, sphere radius R, summit radius beta.
    #[arg(long, allow_hyphen_values = true)]
    mu: f64,
    /// Comma-separated separations d of the mean planes at the centre, in units of sigma.
    #[arg(long = "d", allow_hyphen_values = true)]
    d: String,
    /// Comma-separated radii rho = r/sqrt(2 R sigma) (>= 0) where the pressure is reported.
    #[arg(long, allow_hyphen_values = true)]
    rho: Option<String>,
    /// Relative error asked of the load (default 1e-6), in [1e-10, 1e-2].
    #[arg(long, allow_hyphen_values = true)]
    tolerance: Option<f64>,
    /// Print one JSON object instead of a table.
    #[arg(long)]
    json: bool,
    /// With --json: add each value's numerical error estimate (keys `*_error`).
    #[arg(long)]
    errors: bool,
    /// Write charts (SVG) of p(rho) against Hertz and of load against approach here.
    #[arg(long)]
    out: Option<PathBuf>,
}

/// Runs `asperity rough-sphere`.
pub fn run(args: &RoughSphereArgs) -> crate::CliResult {
    let out = rough_sphere(&RoughSphereInput {
        mu: args.mu,
        d: crate::list::parse("--d", &args.d)?,
        rho: crate::list::parse_opt("--rho", args.rho.as_deref())?.unwrap_or_default(),
        tolerance: args.tolerance,
        errors: args.errors,
        out: args.out.clone(),
    })?;
    for w in &out.warnings {
        eprintln!("warning: {w}");
    }
    crate::print_output(&out, &out.text, args.json)
}
