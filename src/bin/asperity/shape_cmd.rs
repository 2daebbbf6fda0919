//! `asperity shape`: JKR adhesion of an axisymmetric profile (computed by
//! [`asperity::commands::shape`]).

pub use asperity::commands::shape::ShapeArgs;

pub fn run(args: &ShapeArgs) -> crate::CliResult {
    let report = asperity::commands::shape::run(args)?;
    crate::print_report(&report, args.json);
    Ok(())
}
