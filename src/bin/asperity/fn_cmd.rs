//! `asperity fn`: the Greenwood–Williamson integrals `F_n(h)` of a height
//! distribution (computed by [`asperity::commands::fn_`]).

use crate::CliError;
pub use asperity::commands::fn_::FnArgs;

pub fn run(args: &FnArgs) -> crate::CliResult {
    let out = asperity::commands::fn_::run(args)?;
    if args.json {
        let s = serde_json::to_string(&out).map_err(|e| CliError::Failed(e.to_string()))?;
        println!("{s}");
    } else {
        let how = if out.closed_form {
            "closed form"
        } else {
            "quadrature"
        };
        println!(
            "F_n(h) of the {} distribution, n = {} ({how})",
            out.dist, out.n
        );
        println!("{:>24}  {:>24}", "h", "F_n(h)");
        for r in &out.values {
            println!("{:>24}  {:>24.17e}", r.h, r.f);
        }
    }
    Ok(())
}
