//! `asperity shape`: JKR adhesion of an axisymmetric profile (paraboloid,
//! true sphere, cone, flat punch, power law): pull-off under load and
//! displacement control and, with `--radii`, the curve; with `--stress`,
//! Maugis–Dugdale instead of JKR. SI units.

use super::{CommandError as CliError, Report};
use crate::axisym::{
    sphere_exact, AxisymJkr, AxisymMd, MdPoint, Profile, ProfileKind, ProfileParams,
};
use crate::law::Instability;
use crate::named::Named;
use serde::Serialize;
use std::fmt::Write as _;

/// Arguments of `asperity shape`.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "cli", derive(clap::Args))]
pub struct ShapeArgs {
    /// Profile: paraboloid, sphere, cone, flat or power (tabulated only in scenes).
    #[cfg_attr(feature = "cli", arg(long))]
    pub profile: String,
    /// Sphere radius (paraboloid, sphere) or punch radius (flat), m.
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub radius: Option<f64>,
    /// tan(beta) of the cone f(r) = r tan(beta).
    #[cfg_attr(
        feature = "cli",
        arg(long = "tan-angle", allow_negative_numbers = true)
    )]
    pub tan_angle: Option<f64>,
    /// Exponent n of the power law f(r) = A r^n (JKR needs n > 1/2).
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub exponent: Option<f64>,
    /// Coefficient A of the power law f(r) = A r^n, m^(1-n).
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub coefficient: Option<f64>,
    /// Contact modulus E*, Pa.
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub estar: f64,
    /// Work of adhesion w, J/m^2.
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub w: f64,
    /// Contact radii (m, comma-separated) at which to print the curve. For
    /// the flat punch, radii below the punch radius are the receding-crack
    /// equilibria.
    #[cfg_attr(feature = "cli", arg(long, allow_hyphen_values = true))]
    pub radii: Option<String>,
    /// Dugdale stress sigma0 (Pa): Maugis–Dugdale adhesion (range w/sigma0)
    /// instead of JKR; not for the flat punch.
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub stress: Option<f64>,
    /// Print one JSON object instead of a table.
    #[cfg_attr(feature = "cli", arg(long))]
    pub json: bool,
}

#[allow(non_snake_case)]
#[derive(Serialize, Debug)]
struct Point {
    load_N: f64,
    radius_m: f64,
    interference_m: f64,
}

#[allow(non_snake_case)]
#[derive(Serialize, Debug)]
struct CurvePoint {
    radius_m: f64,
    load_N: f64,
    interference_m: f64,
}

#[derive(Serialize, Debug)]
struct Output {
    pull_off_load_control: Point,
    jump_out_displacement_control: Point,
    #[serde(skip_serializing_if = "Option::is_none")]
    curve: Option<Vec<CurvePoint>>,
    warnings: Vec<String>,
}

fn point(i: Instability) -> Point {
    Point {
        load_N: i.load,
        radius_m: i.radius,
        interference_m: i.interference,
    }
}

/// Core parameter names to the flags as the command line spells them.
fn flag(e: crate::Error) -> CliError {
    let name = match e.field() {
        Some("radius") => Some("--radius"),
        Some("tan_angle") => Some("--tan-angle"),
        Some("exponent") => Some("--exponent"),
        Some("coefficient") => Some("--coefficient"),
        Some("contact_modulus") => Some("--estar"),
        Some("work_of_adhesion") => Some("--w"),
        Some("stress") => Some("--stress"),
        Some("profile") => Some("--profile"),
        _ => None,
    };
    match name {
        Some(n) => e.renamed(n).into(),
        None => e.into(),
    }
}

/// An error of the model's scales (instabilities beyond the floating-point
/// range, a pull-off lost to underflow, a solver that fails on them)
/// named by the input furthest (in decades) from a typical value: E* 1
/// GPa, w 0.1 J/m^2, radius 1 um, tan(beta) 0.3, exponent 2, coefficient
/// 1e6 m^(1-n), sigma0 100 MPa. Errors naming a single input that is not
/// about the scales keep their name.
fn scale_flag(args: &ShapeArgs, e: crate::Error) -> CliError {
    let about_scales = !e.is_bad_input()
        || matches!(&e, crate::Error::Invalid { name, .. }
            if name == "exponent" || name == "work_of_adhesion");
    if !about_scales {
        return flag(e);
    }
    let given = [
        ("--estar", Some(args.estar), 1e9),
        ("--w", Some(args.w), 0.1),
        ("--radius", args.radius, 1e-6),
        ("--tan-angle", args.tan_angle, 0.3),
        ("--exponent", args.exponent, 2.0),
        ("--coefficient", args.coefficient, 1e6),
        ("--stress", args.stress, 1e8),
    ];
    let worst = given
        .iter()
        .filter_map(|&(f, x, t)| x.map(|x| (f, (x / t).abs().log10().abs())))
        .fold(
            ("--w", f64::NEG_INFINITY),
            |b, c| if c.1 > b.1 { c } else { b },
        )
        .0;
    CliError::Usage(format!(
        "{worst}: {e} ({worst} is the input furthest from typical values: E* 1e9 Pa, w 0.1 \
         J/m^2, radius 1e-6 m, tan-angle 0.3, exponent 2, coefficient 1e6, stress 1e8 Pa)"
    ))
}

fn profile(args: &ShapeArgs) -> Result<Profile, CliError> {
    let kind = ProfileKind::parse(&args.profile).map_err(|e| flag(e.renamed("profile")))?;
    if kind == ProfileKind::Tabulated {
        return Err(CliError::Usage(
            "--profile: tabulated profiles need their table (a scene's law.profile_r and \
             law.profile_f)"
                .into(),
        ));
    }
    let p = ProfileParams {
        radius: args.radius,
        tan_angle: args.tan_angle,
        exponent: args.exponent,
        coefficient: args.coefficient,
        ..Default::default()
    };
    kind.build(&p).map_err(flag)
}

fn parse_radii(text: &str, profile: &Profile) -> Result<Vec<f64>, CliError> {
    text.split(',')
        .map(|s| {
            let a: f64 = s
                .trim()
                .parse()
                .map_err(|_| CliError::Usage(format!("--radii: {s:?} is not a number")))?;
            crate::error::positive("--radii", a)?;
            profile.check_radius("--radii", a).map_err(CliError::from)
        })
        .collect()
}

/// Runs `asperity shape`.
pub fn run(args: &ShapeArgs) -> super::CommandResult<Report> {
    let profile = profile(args)?;
    let radii = match &args.radii {
        Some(t) => Some(parse_radii(t, &profile)?),
        None => None,
    };
    let model = match args.stress {
        Some(stress) => Model::Md(
            AxisymMd::new(profile, args.estar, args.w, stress).map_err(|e| scale_flag(args, e))?,
        ),
        None => Model::Jkr(
            AxisymJkr::new(profile, args.estar, args.w).map_err(|e| scale_flag(args, e))?,
        ),
    };
    let (po, jo) = model.instabilities();
    let mut checked = vec![
        ("pull-off (load control)".to_string(), po.radius),
        ("jump-out (displacement control)".to_string(), jo.radius),
    ];
    let curve = match radii {
        Some(rs) => Some(
            rs.iter()
                .map(|&a| {
                    checked.push((format!("curve point a = {a} m"), a));
                    let (load, interference) = model.at(a)?;
                    Ok(CurvePoint {
                        radius_m: a,
                        load_N: load,
                        interference_m: interference,
                    })
                })
                .collect::<Result<Vec<_>, CliError>>()?,
        ),
        None => None,
    };
    let named: Vec<(&str, f64)> = checked.iter().map(|(s, a)| (s.as_str(), *a)).collect();
    let warnings = sphere_exact::warnings(model.profile(), &named);
    for w in &warnings {
        eprintln!("warning: {w}");
    }
    let out = Output {
        pull_off_load_control: point(po),
        jump_out_displacement_control: point(jo),
        curve,
        warnings,
    };
    let name = match args.stress {
        Some(s) => format!("Maugis-Dugdale, sigma0 = {s} Pa"),
        None => "JKR".into(),
    };
    Report::new(&out, print_table(&args.profile, &name, &out))
}

/// The adhesion model of the command.
enum Model {
    Jkr(AxisymJkr),
    Md(AxisymMd),
}

impl Model {
    fn instabilities(&self) -> (Instability, Instability) {
        let inst = |p: MdPoint| Instability {
            load: p.load,
            interference: p.interference,
            radius: p.radius,
        };
        match self {
            Model::Jkr(j) => (j.pull_off_load_control(), j.jump_out_displacement_control()),
            Model::Md(m) => (
                inst(m.pull_off_load_control()),
                inst(m.jump_out_displacement_control()),
            ),
        }
    }

    fn profile(&self) -> &Profile {
        match self {
            Model::Jkr(j) => j.profile(),
            Model::Md(m) => m.profile(),
        }
    }

    /// `(load, interference)` at contact radius `a`.
    fn at(&self, a: f64) -> Result<(f64, f64), CliError> {
        match self {
            Model::Jkr(j) => Ok(j.point(a).map_err(|e| e.renamed("--radii"))?),
            Model::Md(m) => {
                let p = m.point(a);
                if p.load.is_finite() && p.interference.is_finite() {
                    Ok((p.load, p.interference))
                } else {
                    Err(CliError::Usage(format!(
                        "--radii: at a = {a} m the Dugdale zone would pass the sphere's equator"
                    )))
                }
            }
        }
    }
}

fn print_table(profile: &str, model: &str, out: &Output) -> String {
    let mut t = String::new();
    let _ = writeln!(t, "profile {profile} ({model})");
    let _ = writeln!(
        t,
        "{:<34} {:>14} {:>14} {:>14}",
        "", "load (N)", "radius (m)", "interference (m)"
    );
    for (name, p) in [
        ("pull-off, load control", &out.pull_off_load_control),
        (
            "jump-out, displacement control",
            &out.jump_out_displacement_control,
        ),
    ] {
        let _ = writeln!(
            t,
            "{name:<34} {:>14.6e} {:>14.6e} {:>14.6e}",
            p.load_N, p.radius_m, p.interference_m
        );
    }
    if let Some(c) = &out.curve {
        let _ = writeln!(t, "curve: radius (m), load (N), interference (m)");
        for p in c {
            let _ = writeln!(
                t,
                "{:>14.6e} {:>14.6e} {:>14.6e}",
                p.radius_m, p.load_N, p.interference_m
            );
        }
    }
    t
}
