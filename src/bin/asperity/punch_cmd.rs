//! `asperity punch` and `asperity punch-fit`: the wavy paraboloidal punch of
//! Kesari & Lew and the fit of its envelopes (computed by
//! [`asperity::commands::punch`]).

use crate::CliError;
use asperity::commands::punch::{fit, punch, read_fit_data, PunchInput};
use asperity::commands::Vocabulary;
use clap::Args;
use std::path::PathBuf;

/// Arguments of `asperity punch`.
#[derive(Args, Debug)]
pub struct PunchArgs {
    /// Contact modulus E* (Pa).
    #[arg(long, allow_hyphen_values = true)]
    estar: f64,
    /// Work of adhesion w (J/m^2).
    #[arg(long, allow_hyphen_values = true)]
    w: f64,
    /// Radius of curvature R of the paraboloid (m).
    #[arg(long, allow_hyphen_values = true)]
    radius: f64,
    /// Dimensionless roughness amplitude A: surface r^2/(2R) + l A (1 - cos(2 pi r/l)).
    #[arg(long, allow_hyphen_values = true)]
    amplitude: f64,
    /// Roughness wavelength l (m), smaller than --radius.
    #[arg(long, allow_hyphen_values = true)]
    wavelength: f64,
    /// Comma-separated contact radii (m) for the exact curve and the envelopes.
    #[arg(long, allow_hyphen_values = true)]
    radii: Option<String>,
    /// Comma-separated depths (m, may be negative) for the loading and unloading paths.
    #[arg(long, allow_hyphen_values = true)]
    depths: Option<String>,
    /// A displacement-controlled cycle HMIN:HMAX (m) whose energy loss is printed.
    #[arg(long, allow_hyphen_values = true)]
    cycle: Option<String>,
    /// Draw load against depth over the --cycle (exact curve, envelopes, loading and
    /// unloading paths) into this SVG file.
    #[arg(long, value_name = "FILE.svg")]
    svg: Option<PathBuf>,
    /// Print one JSON object instead of tables.
    #[arg(long)]
    json: bool,
}

/// Arguments of `asperity punch-fit`.
#[derive(Args, Debug)]
pub struct PunchFitArgs {
    /// CSV file with header `phase,radius_m,load_N`, phase `loading` or `unloading`.
    #[arg(value_name = "DATA.csv")]
    data: PathBuf,
    /// Radius of curvature R of the punch (m).
    #[arg(long, allow_hyphen_values = true)]
    radius: f64,
    /// Print one JSON object instead of a table.
    #[arg(long)]
    json: bool,
}

/// `HMIN:HMAX` as two numbers (their order is the command's to check).
fn parse_cycle(text: &str) -> Result<(f64, f64), CliError> {
    let bad = || CliError::Usage(format!("--cycle: expected HMIN:HMAX (m), got {text:?}"));
    let (a, b) = text.split_once(':').ok_or_else(bad)?;
    Ok((
        a.trim().parse().map_err(|_| bad())?,
        b.trim().parse().map_err(|_| bad())?,
    ))
}

pub fn run(args: &PunchArgs) -> crate::CliResult {
    let out = punch(&PunchInput {
        estar: args.estar,
        w: args.w,
        radius: args.radius,
        amplitude: args.amplitude,
        wavelength: args.wavelength,
        radii: crate::list::parse_opt("--radii", args.radii.as_deref())?,
        depths: crate::list::parse_opt("--depths", args.depths.as_deref())?,
        cycle: args.cycle.as_deref().map(parse_cycle).transpose()?,
    })?;
    if let Some(svg) = &args.svg {
        draw(args, svg)?;
    }
    crate::print_output(&out, &out.text, args.json)
}

/// The chart of `--svg`: the cycle's paths between the envelopes (the
/// punch and the cycle were checked by [`punch`] already).
fn draw(args: &PunchArgs, svg: &std::path::Path) -> crate::CliResult {
    let Some((lo, hi)) = args.cycle.as_deref().map(parse_cycle).transpose()? else {
        return Err(CliError::Usage(
            "--svg: the chart spans a cycle: give --cycle HMIN:HMAX (m) too".into(),
        ));
    };
    let p = asperity::punch::WavyPunch::new(
        args.estar,
        args.w,
        args.radius,
        args.amplitude,
        args.wavelength,
    )?;
    asperity::study::plot::punch::PunchChart::cycle(&p, lo, hi)?.write_svg(svg, 900, 640)?;
    eprintln!("wrote {}", svg.display());
    Ok(())
}

pub fn run_fit(args: &PunchFitArgs) -> crate::CliResult {
    // The punch's radius of curvature is `--radius` here.
    let words = Vocabulary::cli().with("punch_radius", "--radius");
    let (data, name) = read_fit_data(&args.data)?;
    let out = fit(&data, args.radius, &name).map_err(|e| CliError::with(e, &words))?;
    crate::print_output(&out, &out.text, args.json)
}
