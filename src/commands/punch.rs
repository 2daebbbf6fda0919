//! `asperity punch` and `asperity punch-fit`: the wavy paraboloidal punch of Kesari & Lew
//! (exact curve, envelopes, displacement-controlled evolution, energy loss per cycle) and
//! the fit of `E*`, `w`, `A sqrt(l)` to measured `(radius, load)` pairs.

use super::{param, CommandResult};
use crate::punch::{fit_envelopes, Envelope, Evolution, FitPoint, Phase, PunchState, WavyPunch};
use crate::Error;
use serde::Serialize;
use std::f64::consts::PI;
use std::fmt::Write as _;

/// The input of [`punch`]: the wavy punch and what to compute.
#[derive(Debug, Clone, Default)]
pub struct PunchInput {
    /// Contact modulus E* (Pa).
    pub estar: f64,
    /// Work of adhesion w (J/m^2).
    pub w: f64,
    /// Radius of curvature R of the paraboloid (m).
    pub radius: f64,
    /// Dimensionless roughness amplitude A: surface r^2/(2R) + l A (1 -
    /// cos(2 pi r/l)).
    pub amplitude: f64,
    /// Roughness wavelength l (m), smaller than `radius`.
    pub wavelength: f64,
    /// Contact radii (m) for the exact curve and the envelopes (default:
    /// 400 up to past the deepest path's radius).
    pub radii: Option<Vec<f64>>,
    /// Depths (m, may be negative) for the loading and unloading paths
    /// (default: from below the pull-off to three JKR zero-depth radii).
    pub depths: Option<Vec<f64>>,
    /// A displacement-controlled cycle `(hmin, hmax)` (m) whose energy loss
    /// is given.
    pub cycle: Option<(f64, f64)>,
}

/// A path state with the depth first (the evolution is indexed by depth).
#[derive(Serialize, Debug, Clone)]
pub struct PathRow {
    /// Depth (m).
    pub depth_m: f64,
    /// Contact radius (m).
    pub radius_m: f64,
    /// Load (N).
    #[serde(rename = "load_N")]
    pub load_n: f64,
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

/// What `asperity punch --json` prints.
#[derive(Serialize, Debug, Clone)]
pub struct PunchOutput {
    /// The exact equilibrium curve at the radii.
    pub curve: Vec<PunchState>,
    /// The loading envelope `h_+` at the radii.
    pub envelope_loading: Vec<PunchState>,
    /// The unloading envelope `h_-` at the radii.
    pub envelope_unloading: Vec<PunchState>,
    /// The loading path at ascending depths.
    pub loading: Vec<PathRow>,
    /// The unloading path from the deepest depth.
    pub unloading: Vec<PathRow>,
    /// Energy lost per displacement-controlled cycle (J), with a cycle.
    #[serde(
        rename = "energy_loss_per_cycle_J",
        skip_serializing_if = "Option::is_none"
    )]
    pub energy_loss_per_cycle_j: Option<f64>,
    /// The tables the command line prints (not in the JSON).
    #[serde(skip)]
    pub text: String,
}

/// What `asperity punch-fit --json` prints: the fitted values with their
/// standard errors.
#[derive(Serialize, Debug, Clone)]
pub struct FitOutput {
    /// Contact modulus E* (Pa).
    #[serde(rename = "estar_Pa")]
    pub estar: f64,
    /// Its standard error (Pa).
    #[serde(rename = "estar_Pa_stderr")]
    pub estar_stderr: f64,
    /// Work of adhesion w (J/m^2).
    #[serde(rename = "w_J_per_m2")]
    pub w: f64,
    /// Its standard error (J/m^2).
    #[serde(rename = "w_J_per_m2_stderr")]
    pub w_stderr: f64,
    /// `A sqrt(l)` (m^1/2).
    pub amplitude_sqrt_wavelength_m_half: f64,
    /// Its standard error (m^1/2).
    pub amplitude_sqrt_wavelength_m_half_stderr: f64,
    /// RMS load residual (N).
    #[serde(rename = "residual_rms_N")]
    pub residual_rms: f64,
    /// Points fitted.
    pub points: usize,
    /// The table the command line prints (not in the JSON).
    #[serde(skip)]
    pub text: String,
}

/// `(hmin, hmax)` finite with `hmin < hmax`.
fn check_cycle((lo, hi): (f64, f64)) -> CommandResult<(f64, f64)> {
    crate::error::finite(&param("cycle"), lo)?;
    crate::error::finite(&param("cycle"), hi)?;
    if lo >= hi {
        return Err(Error::invalid(
            param("cycle"),
            format!("HMIN {lo} must be below HMAX {hi}"),
        ));
    }
    Ok((lo, hi))
}

fn build_punch(args: &PunchInput) -> CommandResult<WavyPunch> {
    if args.radius > 0.0 && args.wavelength >= args.radius {
        return Err(Error::invalid(
            param("wavelength"),
            format!(
                "{:e} m must be smaller than {} = {:e} m",
                args.wavelength,
                param("radius"),
                args.radius
            ),
        ));
    }
    WavyPunch::new(
        args.estar,
        args.w,
        args.radius,
        args.amplitude,
        args.wavelength,
    )
    .map_err(|e| {
        let name = param(e.field().unwrap_or("estar"));
        e.renamed(&name)
    })
}

/// The flag among `among` whose value is furthest (in decades) from a
/// typical one: E* 1 GPa, w 0.1 J/m^2, R 100 um, A 0.1, l 10 um (Kesari &
/// Lew's scales). When a scale of the punch overflows or a scan would take
/// too long, that flag is the likely culprit.
fn furthest_from_typical(p: &WavyPunch, among: &[&'static str]) -> &'static str {
    let typical = [
        ("estar", p.estar(), 1e9),
        ("w", p.w(), 0.1),
        ("radius", p.radius(), 1e-4),
        ("amplitude", p.amplitude(), 0.1),
        ("wavelength", p.wavelength(), 1e-5),
    ];
    typical
        .iter()
        .filter(|(f, ..)| among.contains(f))
        .map(|&(f, x, t)| (f, (x / t).log10().abs()))
        .fold(
            ("w", f64::NEG_INFINITY),
            |b, c| if c.1 > b.1 { c } else { b },
        )
        .0
}

/// Every input of the punch, for [`furthest_from_typical`].
const ALL_INPUTS: [&str; 5] = ["estar", "w", "radius", "amplitude", "wavelength"];

/// A punch library error at depths from `depths_flag` (`--depths` or
/// `--cycle`, or `None` when the depths are the defaults) with the flag the
/// user wrote: `w` is the adhesion (`--w` or `--estar`), `depth` the depths
/// (or, for default depths, the input furthest from typical).
fn punch_error(p: &WavyPunch, e: Error, depths_flag: Option<&str>, deepest: f64) -> Error {
    if matches!(&e, crate::Error::Invalid { name, .. }
        if matches!(name.as_str(), "w" | "wavelength" | "depth" | "punch"))
    {
        // A scan refused for its size: every input sets it; the one
        // furthest (in decades) from typical is named, the depths (typical
        // 1 um) among them when the user gave them.
        let flag = furthest_from_typical(p, &ALL_INPUTS);
        let decades = |f: &str| match f {
            "estar" => (p.estar() / 1e9).log10().abs(),
            "w" => (p.w() / 0.1).log10().abs(),
            "radius" => (p.radius() / 1e-4).log10().abs(),
            "amplitude" => (p.amplitude() / 0.1).log10().abs(),
            _ => (p.wavelength() / 1e-5).log10().abs(),
        };
        let flag = match depths_flag {
            Some(df) if (deepest.abs() / 1e-6).log10().abs() > decades(flag) => df,
            _ => flag,
        };
        return e.renamed(&param(flag));
    }
    let flag = match e.field() {
        Some("w") => furthest_from_typical(p, &["w", "estar"]),
        Some("wavelength") => "wavelength",
        Some("punch") => furthest_from_typical(p, &ALL_INPUTS),
        _ => match depths_flag {
            Some(f) => return e.renamed(&param(f)),
            None => furthest_from_typical(p, &ALL_INPUTS),
        },
    };
    e.renamed(&param(flag))
}

/// Evenly spaced `n` values from `lo` to `hi`.
fn linspace(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64)
        .collect()
}

/// The wavy punch's curve, envelopes, paths and energy loss (`asperity
/// punch`).
///
/// # Errors
/// Naming an input; a scale or scan beyond range names the input furthest
/// from typical values.
pub fn punch(args: &PunchInput) -> CommandResult<PunchOutput> {
    let p = build_punch(args)?;
    let cycle = args.cycle.map(check_cycle).transpose()?;
    let (depths, depths_flag) = match (&args.depths, cycle) {
        (Some(d), _) => {
            if d.is_empty() {
                return Err(Error::invalid(param("depths"), "empty list"));
            }
            for (i, &h) in d.iter().enumerate() {
                crate::error::finite(&param(&format!("depths[{i}]")), h)?;
            }
            (d.clone(), Some("depths"))
        }
        (None, Some((lo, hi))) => (linspace(lo, hi, 201), Some("cycle")),
        (None, None) => {
            // From below the pull-off to the depth of three JKR zero-depth radii.
            let a0 = (2.0 * PI * p.w() * p.radius().powi(2) / p.estar()).cbrt();
            let top = p.envelope(3.0 * a0, Envelope::Loading).depth;
            let bottom = p
                .envelope(p.envelope_minimum(Envelope::Unloading), Envelope::Unloading)
                .depth;
            if !(top.is_finite() && bottom.is_finite()) {
                let flag = param(furthest_from_typical(&p, &ALL_INPUTS));
                return Err(Error::invalid(
                    &flag,
                    format!(
                        "the default depths (from the JKR scales of {}, {}, {} and the \
                         envelopes of {}, {}) are not finite ({bottom:e} .. {top:e} m): {flag} \
                         is the input furthest from typical values (E* 1e9 Pa, w 0.1 J/m^2, R \
                         1e-4 m, A 0.1, l 1e-5 m); give values whose scales are finite, or {}",
                        param("estar"),
                        param("w"),
                        param("radius"),
                        param("amplitude"),
                        param("wavelength"),
                        param("depths")
                    ),
                ));
            }
            (linspace(1.2 * bottom, top, 101), None)
        }
    };
    let (loading, unloading) = paths(&p, &depths, depths_flag)?;
    let energy_loss_per_cycle_j = match cycle {
        Some((lo, hi)) => Some(
            Evolution::new(&p, hi)
                .map_err(|e| punch_error(&p, e, Some("cycle"), hi))?
                .energy_loss(lo),
        ),
        None => None,
    };
    let radii = match &args.radii {
        Some(r) => {
            if r.is_empty() {
                return Err(Error::invalid(param("radii"), "empty list"));
            }
            for (i, &a) in r.iter().enumerate() {
                let name = param(&format!("radii[{i}]"));
                crate::error::non_negative(&name, a)?;
                p.check_radius(a).map_err(|e| e.renamed(&name))?;
            }
            r.clone()
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
    let mut out = PunchOutput {
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
        text: String::new(),
    };
    out.text = print_tables(&p, &out);
    Ok(out)
}

/// Loading (ascending depths) and unloading (descending from the deepest) paths.
fn paths(
    p: &WavyPunch,
    depths: &[f64],
    depths_flag: Option<&str>,
) -> CommandResult<(Vec<PathRow>, Vec<PathRow>)> {
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

fn print_tables(p: &WavyPunch, out: &PunchOutput) -> String {
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

/// Parses the CSV (std only): header `phase,radius_m,load_N`, one point per
/// line; errors name `name` (the file) and the line.
///
/// # Errors
/// [`Error::Invalid`] naming the file.
pub fn parse_csv(name: &str, text: &str) -> CommandResult<Vec<FitPoint>> {
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
        return Err(Error::invalid(
            name,
            "the header must be phase,radius_m,load_N",
        ));
    }
    let mut out = Vec::new();
    for (n, line) in lines {
        let f: Vec<&str> = line.split(',').map(str::trim).collect();
        let bad = |what: &str| Error::invalid(name, format!("line {n}: {what}"));
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

/// Reads the fit data of `asperity punch-fit` from the CSV file `path`
/// (named `DATA.csv (path)` in messages); also returns that name.
///
/// # Errors
/// The file unreadable or malformed, naming it.
pub fn read_fit_data(path: &std::path::Path) -> CommandResult<(Vec<FitPoint>, String)> {
    let name = "DATA.csv";
    let text = super::read_input(name, path)?;
    let data_name = format!("{name} ({})", path.display());
    Ok((parse_csv(&data_name, &text)?, data_name))
}

/// The points of a fit from columns: each `phase` `loading` or
/// `unloading`, contact radii (m) and loads (N).
///
/// # Errors
/// Naming `{phase[i]}` or the three inputs when their lengths differ.
pub fn fit_points(phase: &[&str], radius: &[f64], load: &[f64]) -> CommandResult<Vec<FitPoint>> {
    if phase.len() != radius.len() || phase.len() != load.len() {
        return Err(Error::invalid(
            format!("{}, {}, {}", param("phase"), param("radius"), param("load")),
            format!(
                "lengths {}, {}, {} differ",
                phase.len(),
                radius.len(),
                load.len()
            ),
        ));
    }
    phase
        .iter()
        .zip(radius.iter().zip(load))
        .enumerate()
        .map(|(i, (ph, (&radius, &load)))| {
            let phase = match *ph {
                "loading" => Phase::Loading,
                "unloading" => Phase::Unloading,
                other => {
                    return Err(Error::invalid(
                        param(&format!("phase[{i}]")),
                        format!("{other:?} is not loading or unloading"),
                    ))
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

/// Fits the Kesari–Lew envelopes of a punch of radius of curvature
/// `punch_radius` (m) to `data` (`asperity punch-fit`); `data_name` names
/// the data in messages (the file, or `{radius}` for columns).
///
/// # Errors
/// Naming `{punch_radius}` or the data with the radius.
pub fn fit(data: &[FitPoint], punch_radius: f64, data_name: &str) -> CommandResult<FitOutput> {
    let fit = fit_envelopes(punch_radius, data).map_err(|e| {
        let field = if e.field() == Some("radius") {
            param("punch_radius")
        } else {
            // The data and the radius of curvature together: say both.
            let largest = data.iter().map(|p| p.radius).fold(0.0, f64::max);
            format!(
                "{data_name} with {} = {punch_radius:e} m (contact radii up to {largest:e} m)",
                param("punch_radius")
            )
        };
        e.renamed(&field)
    })?;
    let mut out = FitOutput {
        estar: fit.estar_pa,
        estar_stderr: fit.estar_pa_stderr,
        w: fit.w_j_per_m2,
        w_stderr: fit.w_j_per_m2_stderr,
        amplitude_sqrt_wavelength_m_half: fit.amplitude_sqrt_wavelength_m_half,
        amplitude_sqrt_wavelength_m_half_stderr: fit.amplitude_sqrt_wavelength_m_half_stderr,
        residual_rms: fit.residual_rms_n,
        points: fit.points,
        text: String::new(),
    };
    let mut t = String::new();
    let _ = writeln!(
        t,
        "fit of the Kesari-Lew envelopes to {} points (R = {} m):",
        out.points, punch_radius
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
    out.text = t;
    Ok(out)
}
