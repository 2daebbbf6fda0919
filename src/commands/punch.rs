//! `asperity punch` and `asperity punch-fit`: the wavy paraboloidal punch of Kesari & Lew
//! (exact curve, envelopes, displacement-controlled evolution, energy loss per cycle) and
//! the fit of `E*`, `w`, `A sqrt(l)` to measured `(radius, load)` pairs.

use super::{CommandError as CliError, Report};
use crate::punch::{fit_envelopes, Envelope, Evolution, FitPoint, Phase, PunchState, WavyPunch};
use serde::Serialize;
use std::f64::consts::PI;
use std::fmt::Write as _;
use std::path::PathBuf;

/// Arguments of `asperity punch`.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "cli", derive(clap::Args))]
pub struct PunchArgs {
    /// Contact modulus E* (Pa).
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub estar: f64,
    /// Work of adhesion w (J/m^2).
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub w: f64,
    /// Radius of curvature R of the paraboloid (m).
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub radius: f64,
    /// Dimensionless roughness amplitude A: surface r^2/(2R) + l A (1 - cos(2 pi r/l)).
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub amplitude: f64,
    /// Roughness wavelength l (m), smaller than --radius.
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub wavelength: f64,
    /// Comma-separated contact radii (m) for the exact curve and the envelopes.
    #[cfg_attr(feature = "cli", arg(long, allow_hyphen_values = true))]
    pub radii: Option<String>,
    /// Comma-separated depths (m, may be negative) for the loading and unloading paths.
    #[cfg_attr(feature = "cli", arg(long, allow_hyphen_values = true))]
    pub depths: Option<String>,
    /// A displacement-controlled cycle HMIN:HMAX (m) whose energy loss is printed.
    #[cfg_attr(feature = "cli", arg(long, allow_hyphen_values = true))]
    pub cycle: Option<String>,
    /// Print one JSON object instead of tables.
    #[cfg_attr(feature = "cli", arg(long))]
    pub json: bool,
}

/// Arguments of `asperity punch-fit`.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "cli", derive(clap::Args))]
pub struct PunchFitArgs {
    /// CSV file with header `phase,radius_m,load_N`, phase `loading` or `unloading`.
    #[cfg_attr(feature = "cli", arg(value_name = "DATA.csv"))]
    pub data: PathBuf,
    /// Radius of curvature R of the punch (m).
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub radius: f64,
    /// Print one JSON object instead of a table.
    #[cfg_attr(feature = "cli", arg(long))]
    pub json: bool,
}

/// A path state with the depth first (the evolution is indexed by depth).
#[derive(Serialize, Debug)]
struct PathRow {
    depth_m: f64,
    radius_m: f64,
    #[serde(rename = "load_N")]
    load_n: f64,
}

impl From<PunchState> for PathRow {
    fn from(s: PunchState) -> Self {
        PathRow {
            depth_m: s.depth,
            radius_m: s.radius,
            load_n: s.load,
        }
    }
}

#[derive(Serialize, Debug)]
struct PunchOut {
    curve: Vec<PunchState>,
    envelope_loading: Vec<PunchState>,
    envelope_unloading: Vec<PunchState>,
    loading: Vec<PathRow>,
    unloading: Vec<PathRow>,
    #[serde(
        rename = "energy_loss_per_cycle_J",
        skip_serializing_if = "Option::is_none"
    )]
    energy_loss_per_cycle_j: Option<f64>,
}

#[derive(Serialize, Debug)]
struct FitOut {
    #[serde(rename = "estar_Pa")]
    estar: f64,
    #[serde(rename = "estar_Pa_stderr")]
    estar_stderr: f64,
    #[serde(rename = "w_J_per_m2")]
    w: f64,
    #[serde(rename = "w_J_per_m2_stderr")]
    w_stderr: f64,
    amplitude_sqrt_wavelength_m_half: f64,
    amplitude_sqrt_wavelength_m_half_stderr: f64,
    #[serde(rename = "residual_rms_N")]
    residual_rms: f64,
    points: usize,
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

/// `HMIN:HMAX` with `HMIN < HMAX`.
fn parse_cycle(text: &str) -> Result<(f64, f64), CliError> {
    let bad = || CliError::Usage(format!("--cycle: expected HMIN:HMAX (m), got {text:?}"));
    let (a, b) = text.split_once(':').ok_or_else(bad)?;
    let (lo, hi): (f64, f64) = (
        a.trim().parse().map_err(|_| bad())?,
        b.trim().parse().map_err(|_| bad())?,
    );
    crate::error::finite("--cycle", lo)?;
    crate::error::finite("--cycle", hi)?;
    if lo >= hi {
        return Err(CliError::Usage(format!(
            "--cycle: HMIN {lo} must be below HMAX {hi}"
        )));
    }
    Ok((lo, hi))
}

fn build_punch(args: &PunchArgs) -> Result<WavyPunch, CliError> {
    if args.radius > 0.0 && args.wavelength >= args.radius {
        return Err(CliError::Usage(format!(
            "--wavelength = {:e} m must be smaller than --radius = {:e} m",
            args.wavelength, args.radius
        )));
    }
    WavyPunch::new(
        args.estar,
        args.w,
        args.radius,
        args.amplitude,
        args.wavelength,
    )
    .map_err(|e| {
        let flag = format!("--{}", e.field().unwrap_or("estar"));
        CliError::from(e.renamed(&flag))
    })
}

/// The flag among `among` whose value is furthest (in decades) from a
/// typical one: E* 1 GPa, w 0.1 J/m^2, R 100 um, A 0.1, l 10 um (Kesari &
/// Lew's scales). When a scale of the punch overflows or a scan would take
/// too long, that flag is the likely culprit.
fn furthest_from_typical(p: &WavyPunch, among: &[&'static str]) -> &'static str {
    let typical = [
        ("--estar", p.estar(), 1e9),
        ("--w", p.w(), 0.1),
        ("--radius", p.radius(), 1e-4),
        ("--amplitude", p.amplitude(), 0.1),
        ("--wavelength", p.wavelength(), 1e-5),
    ];
    typical
        .iter()
        .filter(|(f, ..)| among.contains(f))
        .map(|&(f, x, t)| (f, (x / t).log10().abs()))
        .fold(
            ("--w", f64::NEG_INFINITY),
            |b, c| if c.1 > b.1 { c } else { b },
        )
        .0
}

/// A punch library error at depths from `depths_flag` (`--depths` or
/// `--cycle`, or `None` when the depths are the defaults) with the flag the
/// user wrote: `w` is the adhesion (`--w` or `--estar`), `depth` the depths
/// (or, for default depths, the input furthest from typical).
fn punch_error(
    p: &WavyPunch,
    e: crate::Error,
    depths_flag: Option<&str>,
    deepest: f64,
) -> CliError {
    if matches!(&e, crate::Error::Invalid { name, .. }
        if matches!(name.as_str(), "w" | "wavelength" | "depth" | "punch"))
    {
        // A scan refused for its size: every input sets it; the one
        // furthest (in decades) from typical is named, the depths (typical
        // 1 um) among them when the user gave them.
        let all = ["--estar", "--w", "--radius", "--amplitude", "--wavelength"];
        let flag = furthest_from_typical(p, &all);
        let decades = |f: &str| match f {
            "--estar" => (p.estar() / 1e9).log10().abs(),
            "--w" => (p.w() / 0.1).log10().abs(),
            "--radius" => (p.radius() / 1e-4).log10().abs(),
            "--amplitude" => (p.amplitude() / 0.1).log10().abs(),
            _ => (p.wavelength() / 1e-5).log10().abs(),
        };
        let flag = match depths_flag {
            Some(df) if (deepest.abs() / 1e-6).log10().abs() > decades(flag) => df,
            _ => flag,
        };
        return CliError::from(e.renamed(flag));
    }
    let flag = match e.field() {
        Some("w") => furthest_from_typical(p, &["--w", "--estar"]),
        Some("wavelength") => "--wavelength",
        Some("punch") => furthest_from_typical(
            p,
            &["--estar", "--w", "--radius", "--amplitude", "--wavelength"],
        ),
        _ => match depths_flag {
            Some(f) => return CliError::from(e.renamed(f)),
            None => furthest_from_typical(
                p,
                &["--estar", "--w", "--radius", "--amplitude", "--wavelength"],
            ),
        },
    };
    CliError::from(e.renamed(flag))
}

/// Evenly spaced `n` values from `lo` to `hi`.
fn linspace(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64)
        .collect()
}

/// Runs `asperity punch`.
pub fn run(args: &PunchArgs) -> super::CommandResult<Report> {
    let p = build_punch(args)?;
    let cycle = args.cycle.as_deref().map(parse_cycle).transpose()?;
    let (depths, depths_flag) = match (&args.depths, cycle) {
        (Some(t), _) => (parse_list("--depths", t)?, Some("--depths")),
        (None, Some((lo, hi))) => (linspace(lo, hi, 201), Some("--cycle")),
        (None, None) => {
            // From below the pull-off to the depth of three JKR zero-depth radii.
            let a0 = (2.0 * PI * p.w() * p.radius().powi(2) / p.estar()).cbrt();
            let top = p.envelope(3.0 * a0, Envelope::Loading).depth;
            let bottom = p
                .envelope(p.envelope_minimum(Envelope::Unloading), Envelope::Unloading)
                .depth;
            if !(top.is_finite() && bottom.is_finite()) {
                let flag = furthest_from_typical(
                    &p,
                    &["--estar", "--w", "--radius", "--amplitude", "--wavelength"],
                );
                return Err(CliError::Usage(format!(
                    "{flag}: the default depths (from the JKR scales of --estar, --w, --radius \
                     and the envelopes of --amplitude, --wavelength) are not finite \
                     ({bottom:e} .. {top:e} m): {flag} is the input furthest from typical \
                     values (E* 1e9 Pa, w 0.1 J/m^2, R 1e-4 m, A 0.1, l 1e-5 m); give values \
                     whose scales are finite, or --depths"
                )));
            }
            (linspace(1.2 * bottom, top, 101), None)
        }
    };
    let (loading, unloading) = paths(&p, &depths, depths_flag)?;
    let energy_loss_per_cycle_j = match cycle {
        Some((lo, hi)) => Some(
            Evolution::new(&p, hi)
                .map_err(|e| punch_error(&p, e, Some("--cycle"), hi))?
                .energy_loss(lo),
        ),
        None => None,
    };
    let radii = match &args.radii {
        Some(t) => {
            let r = parse_list("--radii", t)?;
            for &a in &r {
                crate::error::non_negative("--radii", a)?;
                p.check_radius(a).map_err(|e| e.renamed("--radii"))?;
            }
            r
        }
        None => {
            let top = loading
                .iter()
                .chain(&unloading)
                .map(|s| s.radius_m)
                .fold(0.0, f64::max);
            let top = if top > 0.0 {
                1.05 * top
            } else {
                3.0 * p.jkr_detach_radius()
            };
            linspace(top / 400.0, top, 400)
        }
    };
    let out = PunchOut {
        curve: radii.iter().map(|&a| p.state(a)).collect(),
        envelope_loading: radii
            .iter()
            .map(|&a| p.envelope(a, Envelope::Loading))
            .collect(),
        envelope_unloading: radii
            .iter()
            .map(|&a| p.envelope(a, Envelope::Unloading))
            .collect(),
        loading,
        unloading,
        energy_loss_per_cycle_j,
    };
    Report::new(&out, print_tables(&p, &out))
}

/// Loading (ascending depths) and unloading (descending from the deepest) paths.
fn paths(
    p: &WavyPunch,
    depths: &[f64],
    depths_flag: Option<&str>,
) -> Result<(Vec<PathRow>, Vec<PathRow>), CliError> {
    let mut up = depths.to_vec();
    up.sort_by(f64::total_cmp);
    let Some(&deepest) = up.last() else {
        return Ok((vec![], vec![]));
    };
    let ev = Evolution::new(p, deepest).map_err(|e| punch_error(p, e, depths_flag, deepest))?;
    let loading = up.iter().map(|&h| ev.loading(h).into()).collect();
    let unloading = up.iter().rev().map(|&h| ev.unloading(h).into()).collect();
    Ok((loading, unloading))
}

fn print_tables(p: &WavyPunch, out: &PunchOut) -> String {
    let mut t = String::new();
    let _ = writeln!(t,
        "wavy punch: E* = {} Pa, w = {} J/m^2, R = {} m, A = {}, l = {} m (A sqrt(l) = {:.6e} m^1/2)",
        p.estar(),
        p.w(),
        p.radius(),
        p.amplitude(),
        p.wavelength(),
        p.amplitude_sqrt_wavelength()
    );
    let _ = writeln!(
        t,
        "{:>14} {:>14} {:>14} {:>14} {:>14}",
        "radius_m", "depth_m", "load_N", "h_+ (m)", "h_- (m)"
    );
    for ((c, u), d) in out
        .curve
        .iter()
        .zip(&out.envelope_loading)
        .zip(&out.envelope_unloading)
    {
        let _ = writeln!(
            t,
            "{:>14.6e} {:>14.6e} {:>14.6e} {:>14.6e} {:>14.6e}",
            c.radius, c.depth, c.load, u.depth, d.depth
        );
    }
    for (name, rows) in [("loading", &out.loading), ("unloading", &out.unloading)] {
        let _ = writeln!(t, "{name}:");
        let _ = writeln!(t, "{:>14} {:>14} {:>14}", "depth_m", "radius_m", "load_N");
        for r in rows {
            let _ = writeln!(
                t,
                "{:>14.6e} {:>14.6e} {:>14.6e}",
                r.depth_m, r.radius_m, r.load_n
            );
        }
    }
    if let Some(e) = out.energy_loss_per_cycle_j {
        let _ = writeln!(t, "energy loss per cycle: {e:.9e} J");
    }
    t
}

/// Parses the CSV (std only): header `phase,radius_m,load_N`, one point per line.
fn parse_csv(name: &str, text: &str) -> Result<Vec<FitPoint>, CliError> {
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim().trim_start_matches('\u{feff}')))
        .filter(|(_, l)| !l.is_empty());
    let header: Vec<&str> = lines
        .next()
        .map(|(_, l)| l.split(',').map(str::trim).collect())
        .unwrap_or_default();
    if header != ["phase", "radius_m", "load_N"] {
        return Err(CliError::Usage(format!(
            "{name}: the header must be phase,radius_m,load_N"
        )));
    }
    let mut out = Vec::new();
    for (n, line) in lines {
        let f: Vec<&str> = line.split(',').map(str::trim).collect();
        let bad = |what: &str| CliError::Usage(format!("{name}: line {n}: {what}"));
        if f.len() != 3 {
            return Err(bad("expected 3 fields"));
        }
        let phase = match f[0] {
            "loading" => Phase::Loading,
            "unloading" => Phase::Unloading,
            other => return Err(bad(&format!("phase {other:?} is not loading or unloading"))),
        };
        let radius: f64 = f[1].parse().map_err(|_| bad("radius_m is not a number"))?;
        let load: f64 = f[2].parse().map_err(|_| bad("load_N is not a number"))?;
        out.push(FitPoint {
            phase,
            radius,
            load,
        });
    }
    Ok(out)
}

/// Runs `asperity punch-fit`.
pub fn run_fit(args: &PunchFitArgs) -> super::CommandResult<Report> {
    let name = "DATA.csv";
    let path = args.data.display();
    let text = super::read_input(name, &args.data)?;
    let data_name = format!("{name} ({path})");
    let data = parse_csv(&data_name, &text)?;
    fit(&data, args.radius, "--radius", &data_name)
}

/// The points of a fit from columns: each `phase` `loading` or
/// `unloading`, contact radii (m) and loads (N); errors name `phase`.
pub fn fit_points(
    phase: &[String],
    radius: &[f64],
    load: &[f64],
) -> super::CommandResult<Vec<FitPoint>> {
    if phase.len() != radius.len() || phase.len() != load.len() {
        return Err(CliError::Usage(format!(
            "phase, radius, load: lengths {}, {}, {} differ",
            phase.len(),
            radius.len(),
            load.len()
        )));
    }
    phase
        .iter()
        .zip(radius.iter().zip(load))
        .enumerate()
        .map(|(i, (ph, (&radius, &load)))| {
            let phase = match ph.as_str() {
                "loading" => Phase::Loading,
                "unloading" => Phase::Unloading,
                other => {
                    return Err(CliError::Usage(format!(
                        "phase[{i}]: {other:?} is not loading or unloading"
                    )))
                }
            };
            Ok(FitPoint {
                phase,
                radius,
                load,
            })
        })
        .collect()
}

/// Fits the Kesari–Lew envelopes of a punch of radius `radius` (m) to
/// `data`; errors name `radius_name` (the punch radius) or `data_name`.
pub fn fit(
    data: &[FitPoint],
    radius: f64,
    radius_name: &str,
    data_name: &str,
) -> super::CommandResult<Report> {
    let fit = fit_envelopes(radius, data).map_err(|e| {
        let field = if e.field() == Some("radius") {
            radius_name.to_string()
        } else {
            // The data and the radius of curvature together: say both.
            let largest = data.iter().map(|p| p.radius).fold(0.0, f64::max);
            format!(
                "{data_name} with {radius_name} = {radius:e} m (contact radii up to {largest:e} m)"
            )
        };
        CliError::from(e.renamed(&field))
    })?;
    let out = FitOut {
        estar: fit.estar_pa,
        estar_stderr: fit.estar_pa_stderr,
        w: fit.w_j_per_m2,
        w_stderr: fit.w_j_per_m2_stderr,
        amplitude_sqrt_wavelength_m_half: fit.amplitude_sqrt_wavelength_m_half,
        amplitude_sqrt_wavelength_m_half_stderr: fit.amplitude_sqrt_wavelength_m_half_stderr,
        residual_rms: fit.residual_rms_n,
        points: fit.points,
    };
    let mut t = String::new();
    let _ = writeln!(
        t,
        "fit of the Kesari-Lew envelopes to {} points (R = {} m):",
        out.points, radius
    );
    let _ = writeln!(
        t,
        "  E*        = {:.6e} +/- {:.2e} Pa",
        out.estar, out.estar_stderr
    );
    let _ = writeln!(
        t,
        "  w         = {:.6e} +/- {:.2e} J/m^2",
        out.w, out.w_stderr
    );
    let _ = writeln!(
        t,
        "  A sqrt(l) = {:.6e} +/- {:.2e} m^1/2",
        out.amplitude_sqrt_wavelength_m_half, out.amplitude_sqrt_wavelength_m_half_stderr
    );
    let _ = writeln!(t, "  rms load residual {:.3e} N", out.residual_rms);
    Report::new(&out, t)
}
