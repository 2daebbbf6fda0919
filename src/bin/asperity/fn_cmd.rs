//! `asperity fn`: the Greenwood–Williamson integrals `F_n(h)` of a height
//! distribution.

use crate::CliError;
use asperity::heights::{Exponential, Gaussian, HeightDistribution};
use clap::Args;
use serde::Serialize;

/// Arguments of `asperity fn`.
#[derive(Args, Debug)]
pub struct FnArgs {
    /// Height distribution: gaussian or exponential.
    #[arg(long)]
    dist: String,
    /// Order n in [0, 100] of F_n(h) = int_h^inf (s-h)^n phi(s) ds.
    #[arg(long, allow_negative_numbers = true)]
    n: f64,
    /// Comma-separated standardised separations h, e.g. -1,0,2.5.
    #[arg(long, allow_hyphen_values = true)]
    h: String,
    /// Print one JSON object instead of a table.
    #[arg(long)]
    json: bool,
}

#[derive(Serialize, Debug)]
struct Row {
    h: f64,
    #[serde(rename = "F")]
    f: f64,
}

#[derive(Serialize, Debug)]
struct Output {
    dist: &'static str,
    n: f64,
    values: Vec<Row>,
}

/// Parses the comma-separated `--h` list: every entry a finite number.
fn parse_list(text: &str) -> Result<Vec<f64>, CliError> {
    if text.trim().is_empty() {
        return Err(CliError::Usage("--h: empty list".into()));
    }
    text.split(',')
        .map(|item| {
            let t = item.trim();
            let x: f64 = t
                .parse()
                .map_err(|_| CliError::Usage(format!("--h: cannot parse {t:?} as a number")))?;
            asperity::error::finite("--h", x)?;
            Ok(x)
        })
        .collect()
}

pub fn run(args: &FnArgs) -> crate::CliResult {
    let dist: Box<dyn HeightDistribution> = match args.dist.as_str() {
        "gaussian" => Box::new(Gaussian::new()),
        "exponential" => Box::new(Exponential::new()),
        other => {
            return Err(CliError::Usage(format!(
                "--dist: unknown distribution {other:?}; known: gaussian, exponential"
            )))
        }
    };
    asperity::error::non_negative("--n", args.n)?;
    let hs = parse_list(&args.h)?;
    let values: Vec<Row> = hs
        .iter()
        .map(|&h| {
            let f = dist
                .moment_above_checked(args.n, h)
                .map_err(|e| match e.field() {
                    Some("n") => e.renamed("--n"),
                    _ => e.renamed("--h"),
                })?;
            Ok(Row { h, f })
        })
        .collect::<Result<_, CliError>>()?;
    let out = Output {
        dist: dist.name(),
        n: args.n,
        values,
    };
    if args.json {
        let s = serde_json::to_string(&out).map_err(|e| CliError::Failed(e.to_string()))?;
        println!("{s}");
    } else {
        let how = if dist.closed_form_moment(args.n) {
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
