//! `asperity bem`: exact elastic contact of a measured map by FFT boundary
//! elements, beside GW and Persson on the same map (computed by
//! [`asperity::commands::bem`]).

use crate::CliError;
use asperity::commands::bem::{bem, BemAdhesion, BemInput, BemTargets};
use asperity::commands::measured::{plane_rms, unit_warnings};
use asperity::commands::surface::map_name;
use asperity::commands::Vocabulary;
use clap::Args;
use std::path::PathBuf;

/// Arguments of `asperity bem`.
#[derive(Args, Debug)]
#[command(mut_arg("scale", |a| a.help("Factor on the heights after their unit")))]
#[command(mut_arg("export", |a| a.help("Also write the map read, in m, to this `.x3p` or `.npy` file")))]
pub struct BemArgs {
    /// The rigid rough surface: any map `asperity surface` reads (an
    /// instrument file with its pixel sizes and unit, `.npy` or a text
    /// matrix).
    map: PathBuf,
    #[command(flatten)]
    read: crate::map_read::MapArgs,
    /// Contact modulus E* (Pa).
    #[arg(long, allow_hyphen_values = true)]
    estar: f64,
    /// Comma-separated mean pressures (Pa): load control.
    #[arg(
        long,
        allow_hyphen_values = true,
        conflicts_with = "gaps",
        required_unless_present = "gaps"
    )]
    pressures: Option<String>,
    /// Comma-separated mean gaps (m): mean-gap control.
    #[arg(long, allow_hyphen_values = true)]
    gaps: Option<String>,
    /// Treat the map as periodic (otherwise padded to twice its size, a
    /// non-periodic half-space; the mean plane is removed either way, only
    /// the mean when periodic).
    #[arg(long)]
    periodic: bool,
    /// Work of adhesion w (J/m^2) of the exponential interaction -w exp(-g/rho).
    #[arg(long, allow_hyphen_values = true, requires = "adhesion_range")]
    adhesion_energy: Option<f64>,
    /// Range rho (m) of the exponential interaction.
    #[arg(long, allow_hyphen_values = true, requires = "adhesion_energy")]
    adhesion_range: Option<f64>,
    /// Hardness H (Pa, > 0): the contact pressure is capped at H
    /// (elastic-perfectly-plastic); prints the plastic area fraction and the
    /// plastically displaced volume. Mean pressures up to H; with
    /// --adhesion-energy/--adhesion-range (periodic maps) the adhesive
    /// contact with the compressive pressure capped at H.
    #[arg(long, allow_hyphen_values = true)]
    hardness: Option<f64>,
    /// Yang–Persson factor gamma in [0, 1] for Persson's mean gap.
    #[arg(long, allow_hyphen_values = true, default_value_t = 1.0)]
    gamma: f64,
    /// Resistivity (Ohm m, both bodies): adds the contact resistance of the
    /// clusters (Holm/Maxwell spots + Greenwood interaction) and GW's.
    #[arg(long, allow_hyphen_values = true)]
    resistivity: Option<f64>,
    /// Residual at which the solver stops (dimensionless), in [1e-15, 1e-2].
    #[arg(long, allow_hyphen_values = true, default_value_t = 1e-10)]
    tolerance: f64,
    /// Most iterations per solve, at least 1.
    #[arg(long, allow_hyphen_values = true, default_value_t = 10_000)]
    max_iterations: usize,
    /// Memory the solver may use (MiB); larger maps are refused.
    #[arg(long, allow_hyphen_values = true, default_value_t = 1024.0)]
    memory_limit_mib: f64,
    /// A solve stopped at --max-iterations gives its last iterate, flagged
    /// converged: false with a warning (otherwise it fails, exit 1).
    #[arg(long)]
    allow_unconverged: bool,
    #[command(flatten)]
    liquid: crate::liquid_args::LiquidArgs,
    /// Write contact.npy/pressure.npy/gap.npy per state, bem.json and charts here.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Print one JSON object instead of a table.
    #[arg(long)]
    json: bool,
}

pub fn run(args: &BemArgs) -> crate::CliResult {
    let targets = BemTargets::from_options(
        crate::list::parse_opt("--pressures", args.pressures.as_deref())?,
        crate::list::parse_opt("--gaps", args.gaps.as_deref())?,
    )?;
    // The pixel size is checked once the map says whether it has its own.
    let mut input = BemInput::new(args.read.pixel_size.unwrap_or(1.0), args.estar, targets);
    input.periodic = args.periodic;
    input.adhesion = BemAdhesion::from_options(args.adhesion_energy, args.adhesion_range)?;
    input.hardness = args.hardness;
    input.gamma = args.gamma;
    input.resistivity = args.resistivity;
    input.tolerance = args.tolerance;
    input.max_iterations = args.max_iterations;
    input.memory_limit_mib = args.memory_limit_mib;
    input.allow_unconverged = args.allow_unconverged;
    input.liquid = args.liquid.liquid();
    input.out = args.out.clone();
    // The map's content is named by its file (and the scale).
    let words = Vocabulary::cli().with("heights", map_name(&args.map, args.read.scale));
    let failed = |e| CliError::with(e, &words);
    input.validate().map_err(failed)?;
    let (read, pixels, mut warnings) =
        crate::map_read::read_map(&args.map, &args.read).map_err(failed)?;
    input.pixel_size = pixels.0;
    input.pixel_size_y = Some(pixels.1);
    input.periodic = args.periodic || read.periodic;
    let rms = plane_rms(&read.map, pixels, input.periodic);
    warnings.extend(unit_warnings(rms, pixels).iter().map(ToString::to_string));
    let mut out = bem(&read.map, &input).map_err(failed)?;
    let mut words_first: Vec<String> = warnings.iter().map(|w| words.words_in(w)).collect();
    words_first.append(&mut out.assessment.warnings);
    out.assessment.warnings = words_first;
    crate::print_output(&out, &out.text(), args.json)
}
