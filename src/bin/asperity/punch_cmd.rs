//! `asperity punch` and `asperity punch-fit`: the wavy paraboloidal punch of
//! Kesari & Lew and the fit of its envelopes (computed by
//! [`asperity::commands::punch`]).

pub use asperity::commands::punch::{PunchArgs, PunchFitArgs};

pub fn run(args: &PunchArgs) -> crate::CliResult {
    let report = asperity::commands::punch::run(args)?;
    crate::print_report(&report, args.json);
    Ok(())
}

pub fn run_fit(args: &PunchFitArgs) -> crate::CliResult {
    let report = asperity::commands::punch::run_fit(args)?;
    crate::print_report(&report, args.json);
    Ok(())
}
