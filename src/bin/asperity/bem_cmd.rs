//! `asperity bem`: exact elastic contact of a measured map by FFT boundary
//! elements, beside GW and Persson on the same map (computed by
//! [`asperity::commands::bem`]).

pub use asperity::commands::bem::BemArgs;

pub fn run(args: &BemArgs) -> crate::CliResult {
    let report = asperity::commands::bem::run(args)?;
    crate::print_report(&report, args.json);
    Ok(())
}
