//! Scene values to library objects, naming the scene field on error.

use super::schema::{Scene, SurfaceSpec};
use crate::error::{Error, Result};
use crate::gw::RoughSurface;
use crate::heights::HeightDistribution;
use crate::material::{contact_modulus, gold, Adhesion, AsperityContact, Material};
use std::sync::Arc;

/// The asperity contact: summit radius, contact modulus of the two
/// materials, adhesion.
///
/// # Errors
/// Bad materials or adhesion, naming the scene field.
pub fn build_contact(scene: &Scene) -> Result<AsperityContact> {
    let m = &scene.materials;
    let b1 = Material::new(m.e1, m.nu1).map_err(|e| field(e, "materials.e1", "materials.nu1"))?;
    let b2 = Material::new(m.e2, m.nu2).map_err(|e| field(e, "materials.e2", "materials.nu2"))?;
    let adhesion =
        Adhesion::new(scene.adhesion.w, scene.adhesion.z0).map_err(|e| match e.field() {
            Some("work_of_adhesion") => e.renamed("adhesion.w"),
            _ => e.renamed("adhesion.z0"),
        })?;
    AsperityContact::new(scene.surface.radius, contact_modulus(&b1, &b2), adhesion)
        .map_err(|e| e.in_table("surface"))
}

/// The surface statistics. For `distribution = "empirical"` the height
/// scale is the measured heights' standard deviation (divisor N), whatever
/// `surface.sigma` says, and separations are measured from their mean.
/// With `[sphere]` the nominal area is [`SPHERE_REFERENCE_AREA`]: the
/// rough sphere integrates the surface's densities over its own apparent
/// area, and nothing reads the placeholder as an area.
///
/// # Errors
/// Bad values, naming the scene field.
pub fn build_surface(scene: &Scene) -> Result<RoughSurface> {
    let s = &scene.surface;
    let sigma = match (s.distribution, &s.heights) {
        (crate::heights::DistributionKind::Empirical, Some(h)) => crate::heights::Empirical::new(h)
            .map_err(|e| e.in_table("surface"))?
            .std_m(),
        _ => s.sigma,
    };
    let area = if scene.sphere.is_some() {
        SPHERE_REFERENCE_AREA
    } else {
        s.nominal_area
    };
    RoughSurface::new(s.density, s.radius, sigma, area).map_err(|e| e.in_table("surface"))
}

/// The nominal area (m^2) of the surface model under a rough sphere: a
/// unit reference area, so that the model's totals are densities per
/// square metre (the sphere divides by it and integrates over its own
/// apparent area; the value drops out of every output).
pub const SPHERE_REFERENCE_AREA: f64 = 1.0;

/// The standardised height distribution named by `surface.distribution`.
///
/// # Errors
/// Unknown names or bad parameters, naming the scene field.
pub fn build_distribution(spec: &SurfaceSpec) -> Result<Arc<dyn HeightDistribution>> {
    let params = crate::heights::DistributionParams {
        weibull_shape: spec.weibull_shape,
        truncation: spec.truncation,
        heights: spec.heights.clone(),
    };
    spec.distribution
        .build(&params)
        .map_err(|e| e.in_table("surface"))
}

fn field(e: Error, modulus: &str, poisson: &str) -> Error {
    match e.field() {
        Some("youngs_modulus") => e.renamed(modulus),
        _ => e.renamed(poisson),
    }
}

/// Typical values of the numeric scene inputs (a gold microswitch), the
/// reference against which [`map_derived`] finds the input furthest out.
const TYPICAL: [(&str, f64); 8] = [
    ("materials.e1", gold::YOUNGS_MODULUS),
    ("materials.e2", gold::YOUNGS_MODULUS),
    ("surface.density", gold::SUMMIT_DENSITY),
    ("surface.radius", gold::SUMMIT_RADIUS),
    ("surface.sigma", gold::SUMMIT_SIGMA),
    ("surface.nominal_area", gold::NOMINAL_AREA),
    ("adhesion.w", gold::WORK_OF_ADHESION),
    ("adhesion.z0", gold::FORCE_RANGE),
];

fn input(scene: &Scene, name: &str) -> f64 {
    let (m, s, a) = (&scene.materials, &scene.surface, &scene.adhesion);
    match name {
        "materials.e1" => m.e1,
        "materials.e2" => m.e2,
        "surface.density" => s.density,
        "surface.radius" => s.radius,
        "surface.sigma" => s.sigma,
        "surface.nominal_area" => s.nominal_area,
        "adhesion.w" => a.w,
        _ => a.z0,
    }
}

/// The numeric input furthest (in `|ln(value/typical)|`) from a typical
/// gold microswitch ([`crate::material::gold`]); with `among`, only those inputs.
pub fn most_extreme_input(scene: &Scene, among: &[&str]) -> &'static str {
    TYPICAL
        .iter()
        .filter(|(n, _)| among.is_empty() || among.contains(n))
        .filter(|(n, _)| input(scene, n) > 0.0)
        .max_by(|x, y| {
            let d = |(n, t): &(&str, f64)| (input(scene, n) / t).ln().abs();
            d(x).total_cmp(&d(y))
        })
        .map_or("materials.e1", |x| x.0)
}

/// How far (in decades) `name`'s value lies from a typical gold microswitch
/// ([`crate::material::gold`]); `inf` for a value that is not positive.
pub fn decades_from_typical(scene: &Scene, name: &str) -> f64 {
    let typical = TYPICAL.iter().find(|t| t.0 == name).map_or(1.0, |t| t.1);
    let v = input(scene, name);
    if v > 0.0 {
        (v / typical).log10().abs()
    } else {
        f64::INFINITY
    }
}

/// The largest work of adhesion (J/m^2) a failed run is not blamed on:
/// twice the surface energy of the most cohesive metals (tungsten, about
/// 3.3 J/m^2), rounded up; measured works of adhesion lie below it
/// (gold on gold: 0.5 .. 3 J/m^2; elastomers: ~0.05).
pub const PLAUSIBLE_WORK_OF_ADHESION: f64 = 10.0;

/// A run or plan failure (bad input or no convergence) of a scene whose
/// `adhesion.w` lies above [`PLAUSIBLE_WORK_OF_ADHESION`], blamed on it:
/// the adhesive pull of such a work keeps loads from being reached and
/// areas finite, whatever other input the failure names.
fn implausible_work(scene: &Scene, e: &Error) -> Option<Error> {
    let w = scene.adhesion.w;
    let fails = matches!(
        e,
        Error::OutOfRange { .. } | Error::Invalid { .. } | Error::NoConvergence { .. }
    );
    if !(w > PLAUSIBLE_WORK_OF_ADHESION) || !fails || e.field() == Some("adhesion.w") {
        return None;
    }
    Some(Error::invalid(
        "adhesion.w",
        format!(
            "adhesion.w = {w:e} J/m^2 is beyond any measured work of adhesion (0 .. \
             {PLAUSIBLE_WORK_OF_ADHESION} J/m^2: twice the surface energy of the most cohesive \
             metals), and the run failed on its adhesive pull: {e}"
        ),
    ))
}

/// Maps an error about a derived quantity, which no scene key names (the
/// Maugis `lambda` or Tabor `mu`, a start separation, a law not finite on
/// the interferences reached), back to the scene input that drove it out of
/// range; errors naming a scene field pass unchanged (a start after the
/// closest separation gets the inputs that set the start appended).
///
/// `mu = (R w^2 / (E*^2 z0^3))^(1/3)`, `lambda = 1.1570 mu`: each input's
/// share of `ln mu` against a typical gold microswitch ([`crate::material::gold`]) is
/// `exponent x ln(value/typical)`; the input with the largest share in the
/// direction of the failure is named (for `E*`, the more compliant body's
/// modulus), and the message lists them all. Other derived quantities name
/// the input furthest from typical ([`most_extreme_input`]).
pub fn map_derived(scene: &Scene, e: Error) -> Error {
    if let Some(e) = implausible_work(scene, &e) {
        return e;
    }
    let field = e.field().unwrap_or("").to_string();
    let text = e.to_string();
    if field == "program.closest_separation"
        && scene.program.start_separation.is_none()
        && matches!(e, Error::OutOfRange { .. })
    {
        let s = &scene.surface;
        let parameter = match (s.weibull_shape, s.truncation) {
            (Some(k), _) => format!(" (surface.weibull_shape = {k:e})"),
            (_, Some(k)) => format!(" (surface.truncation = {k:e})"),
            _ => String::new(),
        };
        return Error::invalid(
            field,
            format!(
                "{text}: no summit comes within range of the flat there; the start (where the \
                 first summit comes in range) follows from surface.sigma = {:e} m, \
                 surface.distribution = {:?}{parameter} and the interaction range \
                 adhesion.z0 = {:e} m",
                s.sigma, s.distribution, scene.adhesion.z0
            ),
        );
    }
    let tabor = matches!(
        field.as_str(),
        "lambda" | "mu" | "tabor" | "tabor_parameter"
    );
    if !tabor {
        let scene_field = field.contains('.')
            || matches!(
                field.as_str(),
                "program" | "surface" | "materials" | "adhesion" | "montecarlo" | "scene"
            );
        if scene_field || !e.is_bad_input() {
            return e;
        }
        let pick = most_extreme_input(scene, &[]);
        return Error::invalid(
            pick,
            format!(
                "{text}: a derived quantity left its range; {pick} = {:e} is the input furthest \
                 from typical values",
                input(scene, pick)
            ),
        );
    }
    let m = &scene.materials;
    let e_field = if m.e1 <= m.e2 {
        "materials.e1"
    } else {
        "materials.e2"
    };
    let x = crate::material::TABOR_EXPONENTS;
    let shares = [
        ("surface.radius", x.radius),
        ("adhesion.w", x.work),
        (e_field, x.contact_modulus),
        ("adhesion.z0", x.range),
    ];
    let typical = |n: &str| TYPICAL.iter().find(|t| t.0 == n).map_or(1.0, |t| t.1);
    let share = |&(n, p): &(&str, f64)| p * (input(scene, n) / typical(n)).ln();
    let total: f64 = shares.iter().map(share).sum();
    let too_large = !(total < 0.0);
    let pick = shares
        .iter()
        .max_by(|x, y| {
            let (sx, sy) = (share(x), share(y));
            let (sx, sy) = if too_large { (sx, sy) } else { (-sx, -sy) };
            sx.total_cmp(&sy)
        })
        .map_or("materials.e1", |x| x.0);
    let (s, a) = (&scene.surface, &scene.adhesion);
    Error::invalid(
        pick,
        format!(
            "{text}: the Tabor mu = (R w^2/(E*^2 z0^3))^(1/3) (Maugis lambda = 1.1570 mu) is \
             driven out of range by {pick} (surface.radius = {:e} m, adhesion.w = {:e} J/m^2, \
             materials.e1 = {:e} Pa, materials.e2 = {:e} Pa, adhesion.z0 = {:e} m)",
            s.radius, a.w, m.e1, m.e2, a.z0
        ),
    )
}
