//! `asperity rough-sphere`: the Greenwood–Tripp rough sphere (Hertz summits on
//! Gaussian heights) in Greenwood–Tripp units: load, central deflection and
//! pressures at given central separations; charts of p(rho) against Hertz and
//! of load against approach with `--out`.

use super::{CommandError as CliError, Report};
use crate::roughsphere::units::{hertz_approach_gt, hertz_pressure_gt};
use crate::roughsphere::{GreenwoodTripp, GtState, SolverOptions};
use crate::study::plot::{Chart, Series};
use serde_json::{json, Map, Value};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Arguments of `asperity rough-sphere`.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "cli", derive(clap::Args))]
pub struct RoughSphereArgs {
    /// mu = (8/3) eta sigma sqrt(2 R beta) (> 0): summit density eta, summit-height
    /// standard deviation sigma, sphere radius R, summit radius beta.
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub mu: f64,
    /// Comma-separated separations d of the mean planes at the centre, in units of sigma.
    #[cfg_attr(feature = "cli", arg(long = "d", allow_hyphen_values = true))]
    pub d: String,
    /// Comma-separated radii rho = r/sqrt(2 R sigma) (>= 0) where the pressure is reported.
    #[cfg_attr(feature = "cli", arg(long, allow_hyphen_values = true))]
    pub rho: Option<String>,
    /// Relative error asked of the load (default 1e-6), in [1e-10, 1e-2].
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub tolerance: Option<f64>,
    /// Print one JSON object instead of a table.
    #[cfg_attr(feature = "cli", arg(long))]
    pub json: bool,
    /// With --json: add each value's numerical error estimate (keys `*_error`).
    #[cfg_attr(feature = "cli", arg(long))]
    pub errors: bool,
    /// Write charts (SVG) of p(rho) against Hertz and of load against approach here.
    #[cfg_attr(feature = "cli", arg(long))]
    pub out: Option<PathBuf>,
}

/// Parses a comma-separated list of finite numbers for `flag`.
fn parse_list(flag: &str, text: &str) -> Result<Vec<f64>, CliError> {
    if text.trim().is_empty() {
        return Err(CliError::Usage(format!("{flag}: empty list")));
    }
    text.split(',')
        .map(|item| {
            let t = item.trim();
            let x: f64 = t
                .parse()
                .map_err(|_| CliError::Usage(format!("{flag}: cannot parse {t:?} as a number")))?;
            crate::error::finite(flag, x)?;
            Ok(x)
        })
        .collect()
}

/// A core error about `mu`, `d`, `rho` or an option, renamed to its flag.
fn flagged(e: crate::Error) -> CliError {
    let flag = match e.field() {
        Some("mu") => Some("--mu"),
        Some("d") => Some("--d"),
        Some("rho") => Some("--rho"),
        Some("tolerance") => Some("--tolerance"),
        _ => None,
    };
    match flag {
        Some(f) => e.renamed(f).into(),
        None => e.into(),
    }
}

/// Runs `asperity rough-sphere`.
pub fn run(args: &RoughSphereArgs) -> super::CommandResult<Report> {
    if !(args.mu.is_finite() && args.mu > 0.0) {
        return Err(CliError::Usage(format!(
            "--mu = {} is out of range: allowed finite and > 0",
            args.mu
        )));
    }
    let ds = parse_list("--d", &args.d)?;
    let rhos = match &args.rho {
        Some(t) => parse_list("--rho", t)?,
        None => Vec::new(),
    };
    if let Some(r) = rhos.iter().find(|r| **r < 0.0) {
        return Err(CliError::Usage(format!(
            "--rho = {r} is out of range: allowed finite and >= 0"
        )));
    }
    let mut options = SolverOptions::default();
    if let Some(t) = args.tolerance {
        options.tolerance = t;
    }
    let gt = GreenwoodTripp::with_options(args.mu, options).map_err(flagged)?;
    let states = gt.states(&ds, &rhos).map_err(flagged)?;
    for s in states.iter().filter(|s| !s.converged) {
        eprintln!(
            "warning: d = {}: load error estimate {:.1e} above the tolerance at the node limit",
            s.d, s.load.error
        );
    }
    if let Some(dir) = &args.out {
        write_charts(&gt, &states, dir).map_err(|e| CliError::Failed(e.to_string()))?;
    }
    Report::new(
        &states_json(&states, args.errors),
        print_table(args.mu, &states),
    )
}

fn states_json(states: &[GtState], errors: bool) -> Value {
    let rows: Vec<Value> = states
        .iter()
        .map(|s| {
            let mut o = Map::new();
            o.insert("d".into(), json!(s.d));
            o.insert("load".into(), json!(s.load.value));
            o.insert(
                "central_deflection".into(),
                json!(s.central_deflection.value),
            );
            if errors {
                o.insert("load_error".into(), json!(s.load.error));
                o.insert(
                    "central_deflection_error".into(),
                    json!(s.central_deflection.error),
                );
            }
            let p: Vec<Value> = s
                .pressure
                .iter()
                .map(|q| {
                    let mut m = Map::new();
                    m.insert("rho".into(), json!(q.rho));
                    m.insert("p".into(), json!(q.p.value));
                    if errors {
                        m.insert("p_error".into(), json!(q.p.error));
                    }
                    Value::Object(m)
                })
                .collect();
            o.insert("pressure".into(), Value::Array(p));
            Value::Object(o)
        })
        .collect();
    json!({ "states": rows })
}

fn print_table(mu: f64, states: &[GtState]) -> String {
    let mut t = String::new();
    let _ = writeln!(
        t,
        "Greenwood–Tripp rough sphere, mu = {mu} (Hertz summits, Gaussian heights)"
    );
    let _ = writeln!(t, "units: rho = r/sqrt(2R sigma), gaps in sigma, p in E* sqrt(sigma/(8R)), load in E* sqrt(sigma/(8R)) 2R sigma");
    for s in states {
        let _ = writeln!(t,
            "d = {:<8} load = {:.10e} ± {:.1e}  u(0) = {:.10e} ± {:.1e}  approach = {:.6e}  rho_max = {:.3}  nodes = {}",
            s.d,
            s.load.value,
            s.load.error,
            s.central_deflection.value,
            s.central_deflection.error,
            s.approach.value,
            s.outer_radius,
            s.nodes
        );
        for q in &s.pressure {
            let _ = writeln!(
                t,
                "    p({:<6}) = {:.10e} ± {:.1e}",
                q.rho, q.p.value, q.p.error
            );
        }
    }
    t
}

fn write_charts(gt: &GreenwoodTripp, states: &[GtState], dir: &Path) -> crate::Result<()> {
    std::fs::create_dir_all(dir).map_err(|e| crate::Error::io(dir.display(), e))?;
    for (i, s) in states.iter().enumerate() {
        let rough: Vec<(f64, f64)> = s.profile.clone();
        let hertz: Vec<(f64, f64)> = rough
            .iter()
            .map(|&(r, _)| (r, hertz_pressure_gt(s.load.value, r)))
            .collect();
        Chart {
            title: format!("pressure, mu = {}, d = {}", gt.mu(), s.d),
            x_label: "rho = r/sqrt(2 R sigma)".into(),
            y_label: "p / (E* sqrt(sigma/(8R)))".into(),
            series: vec![
                Series::leg("rough sphere (Greenwood–Tripp)", rough),
                Series::dashed("Hertz, same load", hertz),
            ],
            y_range: None,
            y_symlog: false,
        }
        .write_svg(&dir.join(format!("pressure_{i}.svg")), 800, 560)?;
    }
    // Load against approach: a dense curve over the separations given.
    let hi = states.iter().map(|s| s.d).fold(f64::NEG_INFINITY, f64::max);
    let lo = states.iter().map(|s| s.d).fold(f64::INFINITY, f64::min);
    let ds: Vec<f64> = if hi > lo {
        (0..=40).map(|k| hi - (hi - lo) * k as f64 / 40.0).collect()
    } else {
        vec![hi]
    };
    let curve = gt.states(&ds, &[])?;
    let rough: Vec<(f64, f64)> = curve
        .iter()
        .map(|s| (s.approach.value, s.load.value))
        .collect();
    let hertz: Vec<(f64, f64)> = curve
        .iter()
        .map(|s| (hertz_approach_gt(s.load.value), s.load.value))
        .collect();
    Chart {
        title: format!("load against approach, mu = {}", gt.mu()),
        x_label: "approach of distant points u(0) - d (sigma)".into(),
        y_label: "P* = P / (E* sqrt(sigma/(8R)) 2R sigma)".into(),
        series: vec![
            Series::leg("rough sphere (Greenwood–Tripp)", rough),
            Series::dashed("Hertz", hertz),
        ],
        y_range: None,
        y_symlog: false,
    }
    .write_svg(&dir.join("load_approach.svg"), 800, 560)
}
