//! `asperity persson`: Persson's contact theory on an analytic self-affine
//! spectrum, with GW on the same spectrum beside it (computed by
//! [`asperity::commands::persson`]).

pub use asperity::commands::persson::PerssonArgs;

pub fn run(args: &PerssonArgs) -> crate::CliResult {
    let report = asperity::commands::persson::run(args)?;
    crate::print_report(&report, args.json);
    Ok(())
}
