//! `asperity law`: dimensionless pull-off facts of one law, in Maugis units
//! (computed by [`asperity::commands::law`]).

use crate::CliError;
pub use asperity::commands::law::LawArgs;

pub fn run(args: &LawArgs) -> crate::CliResult {
    let facts = asperity::commands::law::run(args)?;
    if args.json {
        let s = serde_json::to_string(&facts).map_err(|e| CliError::Failed(e.to_string()))?;
        crate::outln!("{s}");
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
