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
