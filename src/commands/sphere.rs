//! `asperity sphere`: the full Lennard-Jones sphere solver's pull-off facts
//! (Maugis units) and, on request, the traced load–approach curve as CSV.

use super::{param, CommandResult};
use crate::sphere::{
    Shape, SolverOptions, SpherePoint, SphereProblem, MAX_RESOLUTION, MAX_TABOR, MIN_RESOLUTION,
    MIN_TABOR,
};
use crate::Error;
use serde::Serialize;
use std::fmt::Write as _;

/// The input of [`sphere`].
#[derive(Debug, Clone, Default)]
pub struct SphereInput {
    /// Tabor parameter mu = (R w^2/(E*^2 z0^3))^(1/3), in [0.005, 100].
    pub mu: f64,
    /// Size ratio rho = R/z0 (>= 10, and >= 100 mu when mu > 10) for a true
    /// sphere; paraboloid if absent.
    pub rho: Option<f64>,
    /// Mesh resolution multiplier (default 1), in [0.5, 64]; runs estimated
    /// above 120 s or 2 GiB are refused with the estimate.
    pub resolution: Option<f64>,
    /// Write the traced curve (CSV with a header) to this file.
    pub curve: Option<std::path::PathBuf>,
}

/// The facts printed, in Maugis units; `None` prints as JSON `null`.
#[derive(Serialize, Debug, Clone)]
pub struct SphereOutput {
    /// The Tabor parameter.
    pub mu: f64,
    /// The size ratio `R/z0` of a true sphere (null: paraboloid).
    pub rho: Option<f64>,
    /// Most tensile load, units of `pi w R`.
    pub pull_off_load_control: f64,
    /// Load where the contact snaps off under displacement control (units
    /// `pi w R`); null when the curve has no S (small mu).
    pub jump_out_load: Option<f64>,
    /// Interference of that snap, units `(pi^2 w^2 R/K^2)^(1/3)`.
    pub jump_out_interference: Option<f64>,
    /// Interference where the approaching sphere jumps in, same units.
    pub jump_in_interference: Option<f64>,
    /// Zero-load contact radius, units `(pi w R^2/K)^(1/3)`.
    pub contact_radius_zero_load: Option<f64>,
    /// Mesh nodes at the pull-off.
    pub nodes: usize,
    /// The table the command line prints (not in the JSON).
    #[serde(skip)]
    pub text: String,
}

/// Estimated run time above which a run is refused (seconds, optimised build).
const MAX_SECONDS: f64 = 120.0;
/// Estimated memory above which a run is refused (MiB).
const MAX_MIB: f64 = 2048.0;
/// Progress appears once a run has taken this long (seconds).
const QUIET_SECONDS: f64 = 2.0;

/// Progress on stderr for runs longer than [`QUIET_SECONDS`]: one line
/// rewritten in place on a terminal, otherwise a line every 2 s.
struct Progress {
    what: &'static str,
    start: std::time::Instant,
    last: f64,
    points: usize,
    shown: bool,
    terminal: bool,
}

impl Progress {
    fn new(what: &'static str) -> Self {
        use std::io::IsTerminal;
        Progress {
            what,
            start: std::time::Instant::now(),
            last: 0.0,
            points: 0,
            shown: false,
            terminal: std::io::stderr().is_terminal(),
        }
    }

    fn tick(&mut self, p: &SpherePoint) {
        self.points += 1;
        let t = self.start.elapsed().as_secs_f64();
        let every = if self.terminal { 0.2 } else { QUIET_SECONDS };
        if t < QUIET_SECONDS || t - self.last < every {
            return;
        }
        self.last = t;
        self.shown = true;
        let line = format!(
            "{}: {} points, {:.1} s, central gap {:.4} z0, load {:.4} pi w R",
            self.what, self.points, t, p.central_gap, p.load_bar
        );
        if self.terminal {
            eprint!("\r{line}   ");
        } else {
            eprintln!("{line}");
        }
    }

    fn done(&self) {
        if self.shown && self.terminal {
            eprintln!();
        }
    }
}

/// The full Lennard-Jones sphere solver's pull-off facts (`asperity
/// sphere`), and its traced curve written to `input.curve`. Progress goes
/// to stderr for runs longer than 2 s.
///
/// # Errors
/// Naming `{mu}`, `{rho}`, `{resolution}` (also for a run estimated beyond
/// 120 s or 2 GiB), `{curve}` (the file); solver failures;
/// [`Error::Cancelled`].
pub fn sphere(args: &SphereInput) -> CommandResult<SphereOutput> {
    crate::error::Allowed::closed(MIN_TABOR, MAX_TABOR).check(&param("mu"), args.mu)?;
    let shape = match args.rho {
        Some(rho) => {
            crate::error::Allowed::closed(SphereProblem::min_size_ratio(args.mu), 1e12)
                .check(&param("rho"), rho)?;
            Shape::Sphere { rho }
        }
        None => Shape::Paraboloid,
    };
    let mut opts = SolverOptions::default();
    if let Some(r) = args.resolution {
        opts.resolution = crate::error::Allowed::closed(MIN_RESOLUTION, MAX_RESOLUTION)
            .check(&param("resolution"), r)?;
    }
    let problem = SphereProblem::new(args.mu, shape, opts)
        .map_err(|e| super::named(e, &[("resolution", "resolution")]))?;
    let cost = problem.cost();
    let mib = cost.memory_bytes / 1048576.0;
    if cost.seconds > MAX_SECONDS || mib > MAX_MIB {
        return Err(Error::invalid(
            param("resolution"),
            format!(
                "{}: estimated {} nodes, ~{:.0} s and ~{:.0} MiB at mu = {}; the bounds are \
                 {MAX_SECONDS} s and {MAX_MIB} MiB (lower {})",
                opts.resolution,
                cost.nodes,
                cost.seconds,
                mib,
                args.mu,
                param("resolution")
            ),
        ));
    }
    crate::study::memory::ensure(
        &param("resolution"),
        &format!("the sphere solver's mesh of {} nodes", cost.nodes),
        cost.memory_bytes,
        "",
    )?;
    let mut progress = Progress::new("sphere facts");
    let f = problem.facts_with_progress(Some(&mut |p: &SpherePoint| progress.tick(p)))?;
    progress.done();
    let mut out = SphereOutput {
        mu: args.mu,
        rho: args.rho,
        pull_off_load_control: f.pull_off.load_bar,
        jump_out_load: f.jump_out.map(|j| j.load_bar),
        jump_out_interference: f.jump_out.map(|j| j.interference_bar),
        jump_in_interference: f.jump_in.map(|j| j.interference_bar),
        contact_radius_zero_load: f.zero_load_radius_bar,
        nodes: f.nodes,
        text: String::new(),
    };
    if let Some(path) = &args.curve {
        write_curve(&problem, path)?;
    }
    out.text = text(&out);
    Ok(out)
}

/// Traces the whole curve and writes it to `path` as CSV with a header,
/// progress on stderr for runs longer than 2 s.
///
/// # Errors
/// The solver's failures; [`Error::Io`] naming `{curve}` and the file.
fn write_curve(problem: &SphereProblem, path: &std::path::Path) -> CommandResult<()> {
    let mut progress = Progress::new("sphere curve");
    let curve = problem.trace_with_progress(Some(&mut |p: &SpherePoint| progress.tick(p)))?;
    progress.done();
    let mut text = String::from(
        "central_gap,approach,load_bar,interference_bar,radius,radius_bar,d_approach,d_load\n",
    );
    for p in &curve {
        text.push_str(&format!(
            "{},{},{},{},{},{},{},{}\n",
            p.central_gap,
            p.approach,
            p.load_bar,
            p.interference_bar,
            p.radius,
            p.radius_bar,
            p.d_approach,
            p.d_load
        ));
    }
    crate::study::atomic::write(path, text.as_bytes())
        .map_err(|e| Error::io(format!("{} {}", param("curve"), path.display()), e))?;
    Ok(())
}

/// The table `asperity sphere` prints.
fn text(out: &SphereOutput) -> String {
    let mut t = String::new();
    let show = |x: Option<f64>| x.map_or("none (no S-curve)".to_string(), |v| format!("{v:.6}"));
    let shape = out
        .rho
        .map_or("paraboloid".to_string(), |r| format!("sphere, rho = {r}"));
    let _ = writeln!(t, "full LJ sphere solver        mu = {}, {shape}", out.mu);
    let _ = writeln!(
        t,
        "pull-off, load control       {:.6}  [pi w R]",
        out.pull_off_load_control
    );
    let (load, interference, radius) = ("pi w R", "(pi^2 w^2 R/K^2)^(1/3)", "(pi w R^2/K)^(1/3)");
    for (label, value, unit) in [
        ("jump-out load", out.jump_out_load, load),
        (
            "jump-out interference",
            out.jump_out_interference,
            interference,
        ),
        (
            "jump-in interference",
            out.jump_in_interference,
            interference,
        ),
        (
            "contact radius at zero load",
            out.contact_radius_zero_load,
            radius,
        ),
    ] {
        let _ = writeln!(t, "{label:<29}{}  [{unit}]", show(value));
    }
    let _ = writeln!(t, "mesh nodes at pull-off       {}", out.nodes);
    t
}
