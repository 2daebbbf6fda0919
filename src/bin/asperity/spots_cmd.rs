//! `asperity spots`: resistance of explicit contact spots read from a CSV
//! file (`x_m,y_m,radius_m`), computed by [`asperity::commands::spots`].

use crate::CliError;
pub use asperity::commands::spots::SpotsArgs;

pub fn run(args: &SpotsArgs) -> crate::CliResult {
    let (out, spots) = asperity::commands::spots::run(args)?;
    if args.json {
        let s = serde_json::to_string(&out).map_err(|e| CliError::Failed(e.to_string()))?;
        println!("{s}");
    } else {
        let spreading = if args.mean_free_path.is_some() {
            asperity::electrical::Spreading::Wexler
        } else {
            asperity::electrical::Spreading::Maxwell
        };
        println!(
            "{} spots, {} self resistance",
            spots.len(),
            spreading.name()
        );
        println!("parallel (Holm)     {:.9e} Ohm", out.parallel_ohm);
        println!("Greenwood (1966)    {:.9e} Ohm", out.greenwood_ohm);
        println!("exact (equal pot.)  {:.9e} Ohm", out.exact_ohm);
    }
    Ok(())
}
