//! The rough sphere's part of a plan (`[sphere]`): the sphere's radius,
//! profile and solver options, and the decision that states what a sphere
//! changes (Greenwood & Tripp 1967).

use super::{Budget, Decision};
use crate::error::Result;
use crate::gw::{GwModel, RoughSurface};
use crate::roughsphere::units::greenwood_tripp_mu;
use crate::roughsphere::{RoughSphere, SolverOptions, SphereProfile};
use crate::study::scene::{Scene, SphereShape};

/// An elastic sphere of radius `radius` on the plan's surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpherePlan {
    /// Sphere radius (m).
    pub radius: f64,
    /// Undeformed profile.
    pub profile: SphereProfile,
    /// Contact modulus `E*` (Pa) of the sphere against the rough body.
    pub contact_modulus: f64,
    /// Mesh extrapolation and Newton options (tolerance: the scene's
    /// `rtol`, clamped to `[1e-10, 1e-2]`).
    pub options: SolverOptions,
    /// Greenwood–Tripp `mu = (8/3) eta sigma sqrt(2 R beta)`.
    pub mu: f64,
}

impl SpherePlan {
    /// The rough sphere on `model` (the plan's surface with the run's law).
    ///
    /// # Errors
    /// As [`RoughSphere::new`].
    pub fn on(&self, model: GwModel) -> Result<RoughSphere> {
        RoughSphere::new(
            model,
            self.radius,
            self.contact_modulus,
            self.profile,
            self.options,
        )
    }
}

/// The sphere of `scene`, with its decision; `None` without `[sphere]`.
///
/// # Errors
/// Bad solver options (not expected: the tolerance is clamped).
pub(super) fn plan(
    scene: &Scene,
    surface: &RoughSurface,
    contact_modulus: f64,
    budget: &Budget,
    decisions: &mut Vec<Decision>,
) -> Result<Option<SpherePlan>> {
    let Some(spec) = &scene.sphere else {
        return Ok(None);
    };
    let profile = match spec.profile {
        Some(SphereShape::Sphere) => SphereProfile::Sphere,
        _ => SphereProfile::Paraboloid,
    };
    let options = SolverOptions {
        tolerance: budget.sphere_solver(),
        ..SolverOptions::default()
    };
    options.validate()?;
    let mu = greenwood_tripp_mu(surface.density, surface.sigma, spec.radius, surface.radius);
    decisions.push(Decision::Sphere {
        radius: spec.radius,
        paraboloid: profile == SphereProfile::Paraboloid,
        mu,
        tolerance: options.tolerance,
    });
    Ok(Some(SpherePlan {
        radius: spec.radius,
        profile,
        contact_modulus,
        options,
        mu,
    }))
}
