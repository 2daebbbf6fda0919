//! `asperity rough-sphere`: the Greenwood–Tripp rough sphere (Hertz summits on
//! Gaussian heights) in Greenwood–Tripp units: load, central deflection and
//! pressures at given central separations; charts of p(rho) against Hertz and
//! of load against approach with `--out`.

use super::{param, CommandResult};
use crate::roughsphere::units::{hertz_approach_gt, hertz_pressure_gt};
use crate::roughsphere::{GreenwoodTripp, GtState, SolverOptions};
use crate::study::plot::{Chart, Series};
use crate::Error;
use serde::Serialize;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The input of [`rough_sphere`].
#[derive(Debug, Clone, Default)]
pub struct RoughSphereInput {
    /// mu = (8/3) eta sigma sqrt(2 R beta) (> 0): summit density eta,
    /// summit-height standard deviation sigma, sphere radius R, summit
    /// radius beta.
    pub mu: f64,
    /// Separations d of the mean planes at the centre, in units of sigma.
    pub d: Vec<f64>,
    /// Radii rho = r/sqrt(2 R sigma) (>= 0) where the pressure is reported.
    pub rho: Vec<f64>,
    /// Relative error asked of the load (default 1e-6), in [1e-10, 1e-2].
    pub tolerance: Option<f64>,
    /// Add each value's numerical error estimate (keys `*_error`).
    pub errors: bool,
    /// Write charts (SVG) of p(rho) against Hertz and of load against
    /// approach here.
    pub out: Option<PathBuf>,
}

/// One pressure of a state of [`RoughSphereOutput`].
#[derive(Serialize, Debug, Clone)]
pub struct PressureAt {
    /// rho = r/sqrt(2 R sigma).
    pub rho: f64,
    /// Pressure in units of E* sqrt(sigma/(8R)).
    pub p: f64,
    /// Its error estimate (with `errors`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub p_error: Option<f64>,
}

/// One central separation of [`RoughSphereOutput`].
#[derive(Serialize, Debug, Clone)]
pub struct RoughSphereState {
    /// Central separation of the mean planes (sigma).
    pub d: f64,
    /// Load P* in units of E* sqrt(sigma/(8R)) 2R sigma.
    pub load: f64,
    /// Central deflection u(0) (sigma).
    pub central_deflection: f64,
    /// The load's error estimate (with `errors`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_error: Option<f64>,
    /// The deflection's error estimate (with `errors`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub central_deflection_error: Option<f64>,
    /// The pressure at each radius given.
    pub pressure: Vec<PressureAt>,
}

/// What `asperity rough-sphere --json` prints.
#[derive(Serialize, Debug, Clone)]
pub struct RoughSphereOutput {
    /// One state per separation, in the order given.
    pub states: Vec<RoughSphereState>,
    /// States whose load error estimate stayed above the tolerance at the
    /// node limit (not in the JSON; the command line warns on stderr).
    #[serde(skip)]
    pub warnings: Vec<String>,
    /// The table the command line prints (not in the JSON).
    #[serde(skip)]
    pub text: String,
}

/// The deepest central separation (units `sigma`) the command solves.
pub const DEEPEST_D: f64 = -100.0;

/// A core error about `mu`, `d`, `rho` or an option, naming the input.
fn named(e: Error) -> Error {
    super::named(
        e,
        &[
            ("mu", "mu"),
            ("d", "d"),
            ("rho", "rho"),
            ("tolerance", "tolerance"),
        ],
    )
}

/// The Greenwood–Tripp rough sphere at central separations
/// (`asperity rough-sphere`), and its charts written to `input.out`.
///
/// # Errors
/// Naming `{mu}`, `{d[i]}`, `{rho[i]}`, `{tolerance}`; solver failures;
/// [`Error::Cancelled`].
pub fn rough_sphere(args: &RoughSphereInput) -> CommandResult<RoughSphereOutput> {
    crate::error::positive(&param("mu"), args.mu)?;
    if args.d.is_empty() {
        return Err(Error::invalid(param("d"), "empty list"));
    }
    for (i, &d) in args.d.iter().enumerate() {
        crate::error::finite(&param(&format!("d[{i}]")), d)?;
        // Deeper, Newton on the finest meshes fails (d = -1000 at mu = 10),
        // and at d = -1e300 every total came out NaN: refused with the range.
        crate::error::Allowed::closed(DEEPEST_D, f64::INFINITY)
            .check(&param(&format!("d[{i}]")), d)?;
    }
    for (i, &r) in args.rho.iter().enumerate() {
        crate::error::non_negative(&param(&format!("rho[{i}]")), r)?;
    }
    let mut options = SolverOptions::default();
    if let Some(t) = args.tolerance {
        options.tolerance = t;
    }
    let gt = GreenwoodTripp::with_options(args.mu, options).map_err(named)?;
    let states = gt.states(&args.d, &args.rho).map_err(named)?;
    let warnings = states
        .iter()
        .filter(|s| !s.converged)
        .map(|s| {
            format!(
                "d = {:e}: load error estimate {:.1e} above the tolerance at the node limit",
                s.d, s.load.error
            )
        })
        .collect();
    if let Some(dir) = &args.out {
        write_charts(&gt, &states, dir)?;
    }
    Ok(RoughSphereOutput {
        states: states_out(&states, args.errors),
        warnings,
        text: print_table(args.mu, &states),
    })
}

fn states_out(states: &[GtState], errors: bool) -> Vec<RoughSphereState> {
    let e = |x: f64| errors.then_some(x);
    states
        .iter()
        .map(|s| RoughSphereState {
            d: s.d,
            load: s.load.value,
            central_deflection: s.central_deflection.value,
            load_error: e(s.load.error),
            central_deflection_error: e(s.central_deflection.error),
            pressure: s
                .pressure
                .iter()
                .map(|q| PressureAt {
                    rho: q.rho,
                    p: q.p.value,
                    p_error: e(q.p.error),
                })
                .collect(),
        })
        .collect()
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
        let title = format!("pressure, mu = {}, d = {}", gt.mu(), s.d);
        let axes = ("rho = r/sqrt(2 R sigma)", "p / (E* sqrt(sigma/(8R)))");
        beside_hertz(title, axes, rough, ("Hertz, same load", hertz)).write_svg(
            &dir.join(format!("pressure_{i}.svg")),
            800,
            560,
        )?;
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
    let title = format!("load against approach, mu = {}", gt.mu());
    let axes = (
        "approach of distant points u(0) - d (sigma)",
        "P* = P / (E* sqrt(sigma/(8R)) 2R sigma)",
    );
    beside_hertz(title, axes, rough, ("Hertz", hertz)).write_svg(
        &dir.join("load_approach.svg"),
        800,
        560,
    )
}

/// A chart of the rough sphere's curve `rough` (solid) beside Hertz's
/// (dashed, with its legend label), axes titled `(x, y)`.
fn beside_hertz(
    title: String,
    (x_label, y_label): (&str, &str),
    rough: Vec<(f64, f64)>,
    (hertz_label, hertz): (&str, Vec<(f64, f64)>),
) -> Chart {
    Chart {
        title,
        x_label: x_label.into(),
        y_label: y_label.into(),
        series: vec![
            Series::leg("rough sphere (Greenwood–Tripp)", rough),
            Series::dashed(hertz_label, hertz),
        ],
        y_range: None,
        y_symlog: false,
    }
}
