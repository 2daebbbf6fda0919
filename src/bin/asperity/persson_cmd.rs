//! `asperity persson`: Persson's contact theory on an analytic self-affine
//! spectrum, with GW on the same spectrum beside it (computed by
//! [`asperity::commands::persson`]).

use asperity::commands::persson::{normalisation, persson, PerssonInput};
use clap::Args;

/// Arguments of `asperity persson`.
#[derive(Args, Debug)]
pub struct PerssonArgs {
    /// Hurst exponent H, in (0, 1].
    #[arg(long, allow_hyphen_values = true)]
    hurst: f64,
    /// Smallest wavevector q_l (rad/m): the spectrum is zero below.
    #[arg(long, allow_hyphen_values = true)]
    q_long: f64,
    /// Roll-off wavevector q_r >= q_l (rad/m): flat between q_l and q_r.
    #[arg(long, allow_hyphen_values = true)]
    q_roll: f64,
    /// Largest wavevector q_s > q_r (rad/m): C ~ q^-2(1+H) up to it.
    #[arg(long, allow_hyphen_values = true)]
    q_short: f64,
    /// RMS height (m), to normalise the spectrum (or --slope-rms).
    #[arg(
        long,
        allow_hyphen_values = true,
        conflicts_with = "slope_rms",
        required_unless_present = "slope_rms"
    )]
    h_rms: Option<f64>,
    /// RMS gradient g = sqrt(<|grad h|^2>), to normalise the spectrum.
    #[arg(long, allow_hyphen_values = true)]
    slope_rms: Option<f64>,
    /// Contact modulus E* (Pa).
    #[arg(long, allow_hyphen_values = true)]
    estar: f64,
    /// Comma-separated mean pressures (Pa), each > 0.
    #[arg(long, allow_hyphen_values = true)]
    pressures: String,
    /// Yang–Persson factor gamma in [0, 1] of the mean separation (1: all
    /// the elastic energy of the contact regions; Yang & Persson found 0.4-0.45).
    #[arg(long, allow_hyphen_values = true, default_value_t = 1.0)]
    gamma: f64,
    /// Work of adhesion w (J/m^2): adds the Persson–Tosatti number U_full/w.
    #[arg(long, allow_hyphen_values = true)]
    adhesion_energy: Option<f64>,
    /// Range rho (m) of the exponential interaction -w exp(-g/rho): with
    /// --adhesion-energy adds the stickiness criteria (Pastewka–Robbins,
    /// Persson–Tosatti, Tabor at R = 1/h'', Müser's mu_rho).
    #[arg(long, allow_hyphen_values = true, requires = "adhesion_energy")]
    adhesion_range: Option<f64>,
    #[command(flatten)]
    liquid: crate::liquid_args::LiquidArgs,
    /// Print one JSON object instead of a table.
    #[arg(long)]
    json: bool,
}

pub fn run(args: &PerssonArgs) -> crate::CliResult {
    let out = persson(&PerssonInput {
        hurst: args.hurst,
        q_long: args.q_long,
        q_roll: args.q_roll,
        q_short: args.q_short,
        normalisation: normalisation(args.h_rms, args.slope_rms)?,
        estar: args.estar,
        pressures: crate::list::parse("--pressures", &args.pressures)?,
        gamma: args.gamma,
        adhesion_energy: args.adhesion_energy,
        adhesion_range: args.adhesion_range,
        liquid: args.liquid.liquid(),
    })?;
    crate::print_output(&out, &out.text(), args.json)
}
