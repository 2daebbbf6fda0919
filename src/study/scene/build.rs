//! Scene values to library objects, naming the scene field on error.

use super::schema::{Scene, SurfaceSpec};
use crate::error::{Error, Result};
use crate::gw::RoughSurface;
use crate::heights::HeightDistribution;
use crate::material::{contact_modulus, Adhesion, AsperityContact, Material};
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
///
/// # Errors
/// Bad values, naming the scene field.
pub fn build_surface(scene: &Scene) -> Result<RoughSurface> {
    let s = &scene.surface;
    let sigma = match (s.distribution.as_str(), &s.heights) {
        ("empirical", Some(h)) => crate::heights::Empirical::new(h)
            .map_err(|e| e.in_table("surface"))?
            .std_m(),
        _ => s.sigma,
    };
    RoughSurface::new(s.density, s.radius, sigma, s.nominal_area).map_err(|e| e.in_table("surface"))
}

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
    crate::heights::DistributionKind::parse(&spec.distribution)
        .and_then(|k| k.build(&params))
        .map_err(|e| e.in_table("surface"))
}

fn field(e: Error, modulus: &str, poisson: &str) -> Error {
    match e.field() {
        Some("youngs_modulus") => e.renamed(modulus),
        _ => e.renamed(poisson),
    }
}

/// Maps an error about a derived quantity (the Maugis `lambda` or Tabor
/// `mu`, which no scene key names) back to the scene input that drove it out
/// of range; other errors pass unchanged.
///
/// `lambda = 1.1570 (R w^2 / (E*^2 z0^3))^(1/3)`: each input's share of
/// `ln lambda` against a typical gold microswitch (R = 1 um, w = 0.5 J/m^2,
/// E* = 50 GPa, z0 = 0.3 nm) is `exponent x ln(value/typical)`; the input
/// with the largest share in the direction of the failure is named (for
/// `E*`, the more compliant body's modulus), and the message lists them all.
pub fn map_derived(scene: &Scene, e: Error) -> Error {
    if !matches!(e.field(), Some("lambda" | "mu" | "tabor" | "tabor_parameter")) {
        return e;
    }
    let m = &scene.materials;
    let (e_field, e_value) = if m.e1 <= m.e2 {
        ("materials.e1", m.e1)
    } else {
        ("materials.e2", m.e2)
    };
    let s = &scene.surface;
    let a = &scene.adhesion;
    let shares = [
        ("surface.radius", s.radius, 1.0 / 3.0, 1e-6),
        ("adhesion.w", a.w, 2.0 / 3.0, 0.5),
        (e_field, e_value, -2.0 / 3.0, 5e10),
        ("adhesion.z0", a.z0, -1.0, 3e-10),
    ];
    let share = |&(_, v, p, t): &(&str, f64, f64, f64)| p * (v / t).ln();
    let too_large = match &e {
        Error::OutOfRange { value, .. } => !value.is_finite() || *value > 1.0,
        _ => true,
    };
    let pick = shares
        .iter()
        .max_by(|x, y| {
            let (sx, sy) = (share(x), share(y));
            let (sx, sy) = if too_large { (sx, sy) } else { (-sx, -sy) };
            sx.total_cmp(&sy)
        })
        .map_or("materials.e1", |x| x.0);
    Error::invalid(
        pick,
        format!(
            "{e}: the Maugis lambda = 1.1570 (R w^2/(E*^2 z0^3))^(1/3) is driven out of range by \
             {pick} (surface.radius = {:e} m, adhesion.w = {:e} J/m^2, materials.e1 = {:e} Pa, \
             materials.e2 = {:e} Pa, adhesion.z0 = {:e} m)",
            s.radius, a.w, m.e1, m.e2, a.z0
        ),
    )
}
