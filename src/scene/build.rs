//! Scene values to library objects, naming the scene field on error.

use super::schema::{Scene, SurfaceSpec};
use crate::error::{Error, Result};
use crate::gw::RoughSurface;
use crate::heights::HeightDistribution;
use crate::material::{contact_modulus, Adhesion, AsperityContact, Material};
use std::sync::Arc;

/// Prefixes the field of an error with the scene table (`radius` ->
/// `surface.radius`), so messages point into the file.
pub(crate) fn in_table(table: &str, e: Error) -> Error {
    match e {
        Error::OutOfRange {
            name,
            value,
            allowed,
        } => Error::OutOfRange {
            name: format!("{table}.{name}"),
            value,
            allowed,
        },
        Error::Invalid { name, reason } => Error::Invalid {
            name: format!("{table}.{name}"),
            reason,
        },
        other => other,
    }
}

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
            Some("work_of_adhesion") => rename(e, "adhesion.w"),
            _ => rename(e, "adhesion.z0"),
        })?;
    AsperityContact::new(scene.surface.radius, contact_modulus(&b1, &b2), adhesion)
        .map_err(|e| in_table("surface", e))
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
            .map_err(|e| in_table("surface", e))?
            .std_m(),
        _ => s.sigma,
    };
    RoughSurface::new(s.density, s.radius, sigma, s.nominal_area)
        .map_err(|e| in_table("surface", e))
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
    crate::heights::by_name(&spec.distribution, &params).map_err(|e| {
        if e.field().is_some_and(|f| f.starts_with("surface.")) {
            e
        } else {
            in_table("surface", e)
        }
    })
}

fn field(e: Error, modulus: &str, poisson: &str) -> Error {
    match e.field() {
        Some("youngs_modulus") => rename(e, modulus),
        _ => rename(e, poisson),
    }
}

/// The same error, naming `name` instead.
pub(crate) fn rename(e: Error, name: &str) -> Error {
    match e {
        Error::OutOfRange { value, allowed, .. } => Error::OutOfRange {
            name: name.into(),
            value,
            allowed,
        },
        Error::Invalid { reason, .. } => Error::Invalid {
            name: name.into(),
            reason,
        },
        other => other,
    }
}
