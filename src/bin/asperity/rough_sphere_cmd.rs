//! `asperity rough-sphere`: the Greenwood–Tripp rough sphere in
//! Greenwood–Tripp units (computed by [`asperity::commands::rough_sphere`]).

pub use asperity::commands::rough_sphere::RoughSphereArgs;

/// Runs `asperity rough-sphere`.
pub fn run(args: &RoughSphereArgs) -> crate::CliResult {
    let report = asperity::commands::rough_sphere::run(args)?;
    crate::print_report(&report, args.json);
    Ok(())
}
