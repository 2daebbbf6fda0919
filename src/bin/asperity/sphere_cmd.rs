//! `asperity sphere`: the full Lennard-Jones sphere solver's pull-off facts
//! (Maugis units) and, on request, the traced load–approach curve as CSV
//! (computed by [`asperity::commands::sphere`]).

pub use asperity::commands::sphere::SphereArgs;

pub fn run(args: &SphereArgs) -> crate::CliResult {
    let report = asperity::commands::sphere::run(args)?;
    crate::print_report(&report, args.json);
    Ok(())
}
