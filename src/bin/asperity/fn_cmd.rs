//! `asperity fn`: the Greenwood–Williamson integrals `F_n(h)` of a height
//! distribution (computed by [`asperity::commands::fn_`]).

use asperity::commands::fn_;
use clap::Args;

/// Arguments of `asperity fn`.
#[derive(Args, Debug)]
pub struct FnArgs {
    /// Height distribution: gaussian or exponential.
    #[arg(long)]
    dist: String,
    /// Order n in [0, 100] of F_n(h) = int_h^inf (s-h)^n phi(s) ds.
    #[arg(long, allow_hyphen_values = true)]
    n: f64,
    /// Comma-separated standardised separations h, e.g. -1,0,2.5.
    #[arg(long, allow_hyphen_values = true)]
    h: String,
    /// Print one JSON object instead of a table.
    #[arg(long)]
    json: bool,
}

pub fn run(args: &FnArgs) -> crate::CliResult {
    let dist = fn_::dist_named(&args.dist)?;
    let hs = crate::list::parse("--h", &args.h)?;
    let out = fn_::table(dist, args.n, &hs)?;
    if args.json {
        crate::outln!("{}", asperity::commands::json_line(&out)?);
    } else {
        let how = if out.closed_form {
            "closed form"
        } else {
            "quadrature"
        };
        crate::outln!(
            "F_n(h) of the {} distribution, n = {} ({how})",
            out.dist,
            out.n
        );
        crate::outln!("{:>24}  {:>24}", "h", "F_n(h)");
        for r in &out.values {
            crate::outln!("{:>24}  {:>24.17e}", r.h, r.f);
        }
    }
    Ok(())
}
