//! `asperity law`: dimensionless pull-off facts of one law, in Maugis units
//! (computed by [`asperity::commands::law`]).

use asperity::commands::law::{facts, LawInput};
use asperity::law::LawKind;
use asperity::named::Named;
use clap::Args;

/// Arguments of `asperity law`.
#[derive(Args, Debug)]
pub struct LawArgs {
    /// The law: hertz, bradley, dmt, jkr, maugis, cos.
    #[arg(long)]
    law: String,
    /// Maugis parameter lambda (> 0) for laws that depend on it (maugis,
    /// cos); default 1.
    #[arg(long, allow_hyphen_values = true)]
    lambda: Option<f64>,
    /// Print one JSON object instead of a table.
    #[arg(long)]
    json: bool,
}

pub fn run(args: &LawArgs) -> crate::CliResult {
    let law = LawKind::parse(&args.law).map_err(|e| e.renamed("{law}"))?;
    let facts = facts(&LawInput {
        law,
        lambda: args.lambda,
    })?;
    if args.json {
        crate::outln!("{}", asperity::commands::json_line(&facts)?);
    } else {
        let show =
            |x: Option<f64>| x.map_or("none (nothing snaps)".to_string(), |v| format!("{v:.6}"));
        crate::outln!("law                          {}", facts.law);
        crate::outln!(
            "pull-off, load control       {:.6}  [pi w R]",
            facts.pull_off_load_control
        );
        crate::outln!(
            "jump-out load                {}  [pi w R]",
            show(facts.jump_out_load)
        );
        crate::outln!(
            "jump-out interference        {}  [(pi^2 w^2 R/K^2)^(1/3)]",
            show(facts.jump_out_interference)
        );
        crate::outln!(
            "contact radius at zero load  {}  [(pi w R^2/K)^(1/3)]",
            facts
                .contact_radius_zero_load
                .map_or("none".to_string(), |v| format!("{v:.6}"))
        );
    }
    Ok(())
}
