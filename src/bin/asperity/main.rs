//! The `asperity` command line: a thin layer over the library. Parsing,
//! printing and exit codes live here; no physics does.
//!
//! Exit codes: 0 success, 2 bad input (one line on stderr naming the
//! argument), 1 a computation that failed, 130 interrupted (Ctrl-C: the
//! computation stops at its next step, files are whole or absent), 141
//! stdout closed by its reader (e.g. `| head`; quiet, see `pipe.rs`).

mod bem_cmd;
mod default_study;
mod fn_cmd;
mod heating_cmd;
mod interrupt;
mod law_cmd;
mod liquid_args;
mod list;
mod map_cmd;
mod map_read;
mod persson_cmd;
mod pipe;
mod progress;
mod punch_cmd;
mod rough_sphere_cmd;
mod run_cmd;
mod schema_cmd;
mod shape_cmd;
mod sphere_cmd;
mod spots_cmd;
mod surface_cmd;
mod sweep_cmd;

use asperity::study::text::edit_distance;
use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// Adhesive contact between rough surfaces.
#[derive(Parser, Debug)]
#[command(
    name = "asperity",
    version,
    about,
    long_about = None,
    after_help = "Without a command, `asperity` runs the default study: it prints its \
                  tables and writes curve.csv, summary.json and SVG charts into \
                  ./asperity-out/ (the same as `cargo run --release` in the repository).\n\
                  Scenes to start from: examples/scenes/*.toml; sample inputs: examples/data/."
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Dimensionless facts of one single-asperity law (Maugis units).
    Law(law_cmd::LawArgs),
    /// Run a scene file: tables, JSON summary and SVG charts.
    Run(run_cmd::RunArgs),
    /// Sweep scene fields over a grid or a Latin hypercube (resumable).
    Sweep(sweep_cmd::SweepArgs),
    /// Join the results of sweep shards.
    Merge(sweep_cmd::MergeArgs),
    /// Adhesion map: where each law is within a tolerance of the full solution.
    Map(map_cmd::MapArgs),
    /// Greenwood–Williamson integrals F_n(h) of a height distribution.
    Fn(fn_cmd::FnArgs),
    /// Full Lennard-Jones sphere solver: pull-off facts and the S-curve.
    Sphere(sphere_cmd::SphereArgs),
    /// Rough sphere (Greenwood–Tripp): load, deflection and pressure at central separations.
    RoughSphere(rough_sphere_cmd::RoughSphereArgs),
    /// Wavy punch (Kesari & Lew): exact curve, envelopes, evolution, energy loss per cycle.
    Punch(punch_cmd::PunchArgs),
    /// Fit E*, w and A sqrt(l) to measured (radius, load) on loading and unloading.
    PunchFit(punch_cmd::PunchFitArgs),
    /// Characterise a measured height map: moments, summits, GW parameters.
    Surface(surface_cmd::SurfaceArgs),
    /// Resistance of explicit contact spots (CSV x_m,y_m,radius_m).
    Spots(spots_cmd::SpotsArgs),
    /// Peak contact temperature from the contact voltage, or the reverse.
    Heating(heating_cmd::HeatingArgs),
    /// JKR adhesion of an axisymmetric profile (paraboloid, sphere, cone, flat, power).
    Shape(shape_cmd::ShapeArgs),
    /// Persson's theory on a self-affine spectrum, GW on the same spectrum.
    Persson(persson_cmd::PerssonArgs),
    /// Exact elastic contact of a map by FFT boundary elements, beside GW and Persson.
    Bem(bem_cmd::BemArgs),
    /// The JSON Schema of scene files (draft 2020-12): every key's type, unit, default, range and description.
    Schema(schema_cmd::SchemaArgs),
}

/// The subcommand within two edits of the one typed (`rn` -> `run`) when
/// clap's own similarity test finds none (it needs longer names).
fn nearest_command(e: &clap::Error) -> Option<String> {
    use clap::error::{ContextKind, ContextValue};
    use clap::CommandFactory;
    let Some(ContextValue::String(typed)) = e.get(ContextKind::InvalidSubcommand) else {
        return None;
    };
    Cli::command()
        .get_subcommands()
        .map(|c| c.get_name().to_string())
        // Ties go to the name with the same first letter (`rn`: `run`, not `fn`).
        .map(|n| {
            let other_start = n.chars().next() != typed.chars().next();
            (edit_distance(typed, &n), other_start, n)
        })
        .filter(|(d, _, _)| *d <= 2)
        .min()
        .map(|(_, _, n)| n)
}

/// Result of a subcommand.
pub type CliResult = std::result::Result<(), CliError>;

/// A failure to report: bad input (exit 2) or a failed computation (exit 1).
#[derive(Debug)]
pub enum CliError {
    /// Bad input: the message names the argument.
    Usage(String),
    /// The computation failed.
    Failed(String),
    /// Interrupted by Ctrl-C (exit 130).
    Interrupted,
    /// Stdout was closed by its reader: exit quietly.
    ClosedPipe,
}

impl CliError {
    /// The library's error `e` with its inputs named by `words` (flags).
    pub fn with(e: asperity::Error, words: &asperity::commands::Vocabulary) -> Self {
        match e {
            asperity::Error::Cancelled => CliError::Interrupted,
            e if e.is_bad_input() => CliError::Usage(words.render(&e)),
            e => CliError::Failed(words.render(&e)),
        }
    }
}

impl From<asperity::Error> for CliError {
    fn from(e: asperity::Error) -> Self {
        CliError::with(e, &asperity::commands::Vocabulary::cli())
    }
}

/// Prints a command's output: its JSON on one line (`--json`), or `text`.
pub fn print_output<T: serde::Serialize>(out: &T, text: &str, json: bool) -> CliResult {
    if json {
        outln!("{}", asperity::commands::json_line(out)?);
    } else {
        out!("{text}");
    }
    Ok(())
}

fn main() -> ExitCode {
    pipe::quiet_on_closed_pipe();
    let token = interrupt::install();
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            use clap::error::ErrorKind;
            if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
                let _ = e.print();
                return ExitCode::SUCCESS;
            }
            // One line naming the argument, not clap's multi-line usage.
            let text = e.render().to_string();
            let mut lines = text.lines().map(str::trim).filter(|l| !l.is_empty());
            let first = lines.next().unwrap_or("error: bad arguments");
            // "...not provided:" names the argument on the next line;
            // clap's "tip: a similar ... exists" hint stays on the line.
            let mut line = match lines.next() {
                Some(next) if first.ends_with(':') => format!("{first} {next}"),
                _ => first.to_string(),
            };
            for tip in text
                .lines()
                .map(str::trim)
                .filter(|l| l.starts_with("tip:"))
            {
                line = format!("{line} ({tip})");
            }
            if !line.contains("tip:") && e.kind() == ErrorKind::InvalidSubcommand {
                if let Some(near) = nearest_command(&e) {
                    line = format!("{line} (tip: a similar subcommand exists: '{near}')");
                }
            }
            eprintln!("{line}");
            return ExitCode::from(2);
        }
    };
    let result = token.scope(|| match cli.command {
        None => default_study::run(),
        Some(Command::Law(args)) => law_cmd::run(&args),
        Some(Command::Run(args)) => run_cmd::run(&args),
        Some(Command::Sweep(args)) => sweep_cmd::run(&args),
        Some(Command::Merge(args)) => sweep_cmd::run_merge(&args),
        Some(Command::Map(args)) => map_cmd::run(&args),
        Some(Command::Fn(args)) => fn_cmd::run(&args),
        Some(Command::Sphere(args)) => sphere_cmd::run(&args),
        Some(Command::RoughSphere(args)) => rough_sphere_cmd::run(&args),
        Some(Command::Punch(args)) => punch_cmd::run(&args),
        Some(Command::PunchFit(args)) => punch_cmd::run_fit(&args),
        Some(Command::Surface(args)) => surface_cmd::run(&args),
        Some(Command::Spots(args)) => spots_cmd::run(&args),
        Some(Command::Heating(args)) => heating_cmd::run(&args),
        Some(Command::Shape(args)) => shape_cmd::run(&args),
        Some(Command::Persson(args)) => persson_cmd::run(&args),
        Some(Command::Bem(args)) => bem_cmd::run(&args),
        Some(Command::Schema(args)) => schema_cmd::run(&args),
    });
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(CliError::Usage(msg)) => {
            eprintln!("error: {msg}");
            ExitCode::from(2)
        }
        Err(CliError::Failed(msg)) => {
            eprintln!("error: {msg}");
            ExitCode::from(1)
        }
        Err(CliError::Interrupted) => {
            eprintln!("interrupted");
            ExitCode::from(interrupt::EXIT)
        }
        Err(CliError::ClosedPipe) => ExitCode::from(pipe::CLOSED_PIPE_EXIT),
    }
}
