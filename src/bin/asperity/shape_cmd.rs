//! `asperity shape`: JKR adhesion of an axisymmetric profile (computed by
//! [`asperity::commands::shape`]).

use asperity::commands::shape::{profile_named, shape, ShapeInput};
use clap::Args;

/// Arguments of `asperity shape`.
#[derive(Args, Debug)]
pub struct ShapeArgs {
    /// Profile: paraboloid, sphere, cone, flat or power (tabulated only in scenes).
    #[arg(long)]
    profile: String,
    /// Sphere radius (paraboloid, sphere) or punch radius (flat), m.
    #[arg(long, allow_hyphen_values = true)]
    radius: Option<f64>,
    /// tan(beta) of the cone f(r) = r tan(beta).
    #[arg(long = "tan-angle", allow_hyphen_values = true)]
    tan_angle: Option<f64>,
    /// Exponent n of the power law f(r) = A r^n (JKR needs n > 1/2).
    #[arg(long, allow_hyphen_values = true)]
    exponent: Option<f64>,
    /// Coefficient A of the power law f(r) = A r^n, m^(1-n).
    #[arg(long, allow_hyphen_values = true)]
    coefficient: Option<f64>,
    /// Contact modulus E*, Pa.
    #[arg(long, allow_hyphen_values = true)]
    estar: f64,
    /// Work of adhesion w, J/m^2.
    #[arg(long, allow_hyphen_values = true)]
    w: f64,
    /// Contact radii (m, comma-separated) at which to print the curve. For
    /// the flat punch, radii below the punch radius are the receding-crack
    /// equilibria.
    #[arg(long, allow_hyphen_values = true)]
    radii: Option<String>,
    /// Dugdale stress sigma0 (Pa): Maugis–Dugdale adhesion (range w/sigma0)
    /// instead of JKR; not for the flat punch.
    #[arg(long, allow_hyphen_values = true)]
    stress: Option<f64>,
    /// Print one JSON object instead of a table.
    #[arg(long)]
    json: bool,
}

pub fn run(args: &ShapeArgs) -> crate::CliResult {
    let out = shape(&ShapeInput {
        profile: profile_named(&args.profile)?,
        radius: args.radius,
        tan_angle: args.tan_angle,
        exponent: args.exponent,
        coefficient: args.coefficient,
        estar: args.estar,
        w: args.w,
        radii: crate::list::parse_opt("--radii", args.radii.as_deref())?,
        stress: args.stress,
    })?;
    for w in &out.warnings {
        eprintln!("warning: {w}");
    }
    crate::print_output(&out, &out.text, args.json)
}
