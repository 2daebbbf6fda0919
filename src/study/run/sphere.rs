//! The run of a rough-sphere scene (`[sphere]`): what follows the curve
//! on the bump rather than on a nominal area.
//!
//! - The state at the closest approach ([`SphereState`]: the radius holding
//!   95 % of the load against Hertz's, the approach, the central
//!   deflection, the mesh) with its model warnings.
//! - Greenwood's interaction per state over the bump's apparent area is
//!   not set here: each state of the sphere carries the spots'
//!   conductance-weighted mean inverse distance `I`
//!   ([`crate::loading::Totals::inverse_distance`], [`with_spots`]), and
//!   the resistance, the contact voltage and the temperature are derived
//!   from its totals like a flat's, over the square of side `c_sq / I`
//!   instead of the nominal area's.
//! - The regime fractions at the centre of the bump (its closest local
//!   gap), and the elastic law's approach states on the same sphere.

use super::Results;
use crate::electrical::Interaction;
use crate::error::Result;
use crate::loading::History;
use crate::roughsphere::{BumpElectrics, RoughSphere, SphereQuery, SphereState};
use crate::study::plan::Plan;

/// The bump's state at remote separation `separation` after `history`,
/// with area, count and (with `[electrical]`) the resistance.
fn state(
    plan: &Plan,
    sphere: &RoughSphere,
    separation: f64,
    history: History,
) -> Result<SphereState> {
    let query = SphereQuery {
        area_and_count: true,
        electrics: plan.resistance.as_ref().map(|r| BumpElectrics {
            spot: *r.spot(),
            interaction: r.interaction(),
        }),
        ..SphereQuery::default()
    };
    sphere.sphere_state(separation, history, &query)
}

/// `sphere` for `plan`'s run: with Greenwood's interaction, its states
/// carry the spread of the spots' conductance over the bump
/// ([`RoughSphere::with_spot_conductance`]), from which the records'
/// resistance takes the bump's own square.
pub(super) fn with_spots(plan: &Plan, sphere: RoughSphere) -> RoughSphere {
    match &plan.resistance {
        Some(res) if res.interaction() == Interaction::Greenwood => {
            sphere.with_spot_conductance(res.conductance().clone())
        }
        _ => sphere,
    }
}

/// Completes `r`, a run of `plan` on `sphere`.
///
/// # Errors
/// As [`RoughSphere::sphere_state`].
pub(super) fn finish(plan: &Plan, sphere: &RoughSphere, r: &mut Results) -> Result<()> {
    let closest = state(plan, sphere, r.curve.program.closest, History::Approach)?;
    r.warnings.extend(
        closest
            .warnings
            .iter()
            .cloned()
            .map(crate::study::Warning::RoughSphere),
    );
    r.regimes = plan.regimes_at(closest.central_separation);
    if let Some(law) = plan.elastic_law()? {
        let elastic = plan
            .sphere
            .as_ref()
            .expect("a sphere plan")
            .on(plan.model_with(law)?)?;
        r.elastic_approach = Some(super::elastic_approach(&elastic, &r.curve)?);
    }
    r.sphere = Some(closest);
    Ok(())
}

/// How many decades from typical an input must lie for a failed sphere
/// run to be blamed on it.
pub const BLAME_DECADES: f64 = 8.0;

/// The plasticity index above which a failed rough-sphere run of a plastic
/// law is blamed on its yield strength (metals: 0.1 .. 100).
pub const BLAME_PSI: f64 = 1e4;

/// A failed rough-sphere run of a scene with an input
/// [`BLAME_DECADES`] or more from a typical gold microswitch: bad input
/// naming that input, with the failure (the solver cannot be expected to
/// converge for, say, `adhesion.w = 1e300`); other failures pass
/// unchanged.
pub(super) fn blame(plan: &Plan, e: crate::Error) -> crate::Error {
    let scene = &plan.scene;
    // A yield strength far below any metal's (1e3 Pa: psi ~ 3e6) leaves
    // the plastic fits so far beyond their range that the sphere's local
    // pressure has no usable shape.
    if let Some(p) = plan
        .plasticity
        .as_ref()
        .filter(|_| e.is_bad_input() || matches!(e, crate::Error::NoConvergence { .. }))
    {
        let c = &plan.contact;
        let psi = crate::material::plastic::plasticity_index(
            c.contact_modulus,
            p.hardness(),
            plan.surface.sigma,
            plan.surface.radius,
        )
        .unwrap_or(f64::NAN);
        if psi > BLAME_PSI {
            let (field, value) = if scene.materials.hardness.is_some() {
                ("materials.hardness", p.hardness())
            } else {
                ("materials.yield_strength", p.yield_strength())
            };
            return crate::Error::invalid(
                field,
                format!(
                    "the rough sphere failed ({e}): {field} = {value:e} Pa gives a plasticity \
                     index psi = {psi:.3e}, far beyond any metal's (0.1 .. 100, yield strengths \
                     of 1e7 .. 1e10 Pa)"
                ),
            );
        }
    }
    let pick = crate::study::scene::most_extreme_input(scene, &[]);
    if crate::study::scene::decades_from_typical(scene, pick) < BLAME_DECADES {
        return e;
    }
    crate::Error::invalid(
        pick,
        format!(
            "the rough sphere failed ({e}): {pick} is {:.0} decades from typical values",
            crate::study::scene::decades_from_typical(scene, pick)
        ),
    )
}
