//! `asperity shape`: JKR adhesion of an axisymmetric profile (paraboloid,
//! true sphere, cone, flat punch, power law): pull-off under load and
//! displacement control and, with `--radii`, the curve; with `--stress`,
//! Maugis–Dugdale instead of JKR. SI units.

use super::{param, CommandResult};
use crate::axisym::{
    sphere_exact, AxisymJkr, AxisymMd, MdPoint, Profile, ProfileKind, ProfileParams,
};
use crate::law::Instability;
use crate::named::Named;
use crate::Error;
use serde::Serialize;
use std::fmt::Write as _;

/// The input of [`shape`]: a profile, the materials and what to compute.
#[derive(Debug, Clone)]
pub struct ShapeInput {
    /// The profile (tabulated profiles need their table: scenes only).
    pub profile: ProfileKind,
    /// Sphere radius (paraboloid, sphere) or punch radius (flat), m.
    pub radius: Option<f64>,
    /// tan(beta) of the cone f(r) = r tan(beta).
    pub tan_angle: Option<f64>,
    /// Exponent n of the power law f(r) = A r^n (JKR needs n > 1/2).
    pub exponent: Option<f64>,
    /// Coefficient A of the power law f(r) = A r^n, m^(1-n).
    pub coefficient: Option<f64>,
    /// Contact modulus E*, Pa.
    pub estar: f64,
    /// Work of adhesion w, J/m^2.
    pub w: f64,
    /// Contact radii (m) at which to give the curve. For the flat punch,
    /// radii below the punch radius are the receding-crack equilibria.
    pub radii: Option<Vec<f64>>,
    /// Dugdale stress sigma0 (Pa): Maugis–Dugdale adhesion (range
    /// w/sigma0) instead of JKR; not for the flat punch.
    pub stress: Option<f64>,
}

/// An instability of the adhesive contact.
#[allow(non_snake_case)]
#[derive(Serialize, Debug, Clone)]
pub struct ShapePoint {
    /// Load (N), negative tensile.
    pub load_N: f64,
    /// Contact radius (m).
    pub radius_m: f64,
    /// Interference (m).
    pub interference_m: f64,
}

/// A point of the curve at a contact radius given.
#[allow(non_snake_case)]
#[derive(Serialize, Debug, Clone)]
pub struct ShapeCurvePoint {
    /// Contact radius (m).
    pub radius_m: f64,
    /// Load (N).
    pub load_N: f64,
    /// Interference (m).
    pub interference_m: f64,
}

/// What `asperity shape --json` prints.
#[derive(Serialize, Debug, Clone)]
pub struct ShapeOutput {
    /// Pull-off under load control.
    pub pull_off_load_control: ShapePoint,
    /// Jump-out under displacement control.
    pub jump_out_displacement_control: ShapePoint,
    /// The curve at the radii given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub curve: Option<Vec<ShapeCurvePoint>>,
    /// Results outside a model's validity.
    pub warnings: Vec<String>,
    /// The table the command line prints (not in the JSON).
    #[serde(skip)]
    pub text: String,
}

fn point(i: Instability) -> ShapePoint {
    ShapePoint {
        load_N: i.load,
        radius_m: i.radius,
        interference_m: i.interference,
    }
}

/// Core argument names to the command's inputs.
fn flag(e: Error) -> Error {
    super::named(
        e,
        &[
            ("radius", "radius"),
            ("tan_angle", "tan_angle"),
            ("exponent", "exponent"),
            ("coefficient", "coefficient"),
            ("contact_modulus", "estar"),
            ("work_of_adhesion", "w"),
            ("stress", "stress"),
            ("profile", "profile"),
        ],
    )
}

/// An error of the model's scales (instabilities beyond the floating-point
/// range, a pull-off lost to underflow, a solver that fails on them)
/// named by the input furthest (in decades) from a typical value: E* 1
/// GPa, w 0.1 J/m^2, radius 1 um, tan(beta) 0.3, exponent 2, coefficient
/// 1e6 m^(1-n), sigma0 100 MPa. Errors naming a single input that is not
/// about the scales keep their name.
fn scale_flag(args: &ShapeInput, e: Error) -> Error {
    // The profile's keys were checked when it was built, so an instability
    // the profile does not hold (JKR's scan) is about the scales; the flat
    // punch's refusal of Maugis-Dugdale is about the profile.
    let about_scales = !e.is_bad_input()
        || matches!(&e, crate::Error::Invalid { name, .. }
            if name == "exponent" || name == "work_of_adhesion"
                || (name == "profile" && args.profile != ProfileKind::Flat));
    if !about_scales {
        return flag(e);
    }
    let given = [
        ("estar", Some(args.estar), 1e9),
        ("w", Some(args.w), 0.1),
        ("radius", args.radius, 1e-6),
        ("tan_angle", args.tan_angle, 0.3),
        ("exponent", args.exponent, 2.0),
        ("coefficient", args.coefficient, 1e6),
        ("stress", args.stress, 1e8),
    ];
    let worst = given
        .iter()
        .filter_map(|&(f, x, t)| x.map(|x| (f, (x / t).abs().log10().abs())))
        .fold(
            ("w", f64::NEG_INFINITY),
            |b, c| if c.1 > b.1 { c } else { b },
        )
        .0;
    let worst = param(worst);
    Error::invalid(
        &worst,
        format!(
            "{e} ({worst} is the input furthest from typical values: {} 1e9 Pa, {} 0.1 \
             J/m^2, {} 1e-6 m, {} 0.3, {} 2, {} 1e6, {} 1e8 Pa)",
            param("estar"),
            param("w"),
            param("radius"),
            param("tan_angle"),
            param("exponent"),
            param("coefficient"),
            param("stress")
        ),
    )
}

/// The profile called `name`.
///
/// # Errors
/// [`Error::Invalid`] naming `{profile}` and the known names.
pub fn profile_named(name: &str) -> CommandResult<ProfileKind> {
    ProfileKind::parse(name).map_err(|e| e.renamed(&param("profile")))
}

fn profile(args: &ShapeInput) -> CommandResult<Profile> {
    let kind = args.profile;
    if kind == ProfileKind::Tabulated {
        return Err(Error::invalid(
            param("profile"),
            "tabulated profiles need their table (a scene's law.profile_r and law.profile_f)",
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

fn check_radii(radii: &[f64], profile: &Profile) -> CommandResult<Vec<f64>> {
    radii
        .iter()
        .enumerate()
        .map(|(i, &a)| {
            let name = param(&format!("radii[{i}]"));
            crate::error::positive(&name, a)?;
            profile.check_radius(&name, a)
        })
        .collect()
}

/// JKR (or Maugis–Dugdale) adhesion of an axisymmetric profile
/// (`asperity shape`).
///
/// # Errors
/// Naming the input (`{profile}`, `{radii[i]}`, ...; an error of the
/// model's scales names the input furthest from typical values).
pub fn shape(args: &ShapeInput) -> CommandResult<ShapeOutput> {
    let profile = profile(args)?;
    let radii = match &args.radii {
        Some(r) => Some(check_radii(r, &profile)?),
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
                    Ok(ShapeCurvePoint {
                        radius_m: a,
                        load_N: load,
                        interference_m: interference,
                    })
                })
                .collect::<CommandResult<Vec<_>>>()?,
        ),
        None => None,
    };
    let named: Vec<(&str, f64)> = checked.iter().map(|(s, a)| (s.as_str(), *a)).collect();
    let warnings = sphere_exact::warnings(model.profile(), &named);
    let mut out = ShapeOutput {
        pull_off_load_control: point(po),
        jump_out_displacement_control: point(jo),
        curve,
        warnings,
        text: String::new(),
    };
    let name = match args.stress {
        Some(s) => format!("Maugis-Dugdale, sigma0 = {s} Pa"),
        None => "JKR".into(),
    };
    out.text = print_table(args.profile.name(), &name, &out);
    Ok(out)
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
    fn at(&self, a: f64) -> CommandResult<(f64, f64)> {
        match self {
            Model::Jkr(j) => j.point(a).map_err(|e| e.renamed(&param("radii"))),
            Model::Md(m) => {
                let p = m.point(a);
                if p.load.is_finite() && p.interference.is_finite() {
                    Ok((p.load, p.interference))
                } else {
                    let why = match m.profile() {
                        Profile::Sphere { .. } => "would pass the sphere's equator".to_string(),
                        p => format!(
                            "does not close within the {} profile (range w/sigma0 = {:e} m)",
                            p.name(),
                            m.range()
                        ),
                    };
                    Err(Error::invalid(
                        param("radii"),
                        format!("at a = {a:e} m the Dugdale zone {why}"),
                    ))
                }
            }
        }
    }
}

fn print_table(profile: &str, model: &str, out: &ShapeOutput) -> String {
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
