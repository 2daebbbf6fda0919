//! Validity diagnostics of the Greenwood–Williamson model for a planned and
//! a finished run: where the scene lies outside the model, a warning (a
//! sentence naming the quantity, its value and the bound); where the result
//! would be physically impossible, an error naming the scene field.
//!
//! GW treats the summits as independent paraboloids (Greenwood &
//! Williamson 1966, Proc. R. Soc. A 295, 300): it needs
//! - a real contact area that is a small fraction of the nominal one
//!   (neighbouring contacts must not merge or interact elastically):
//!   warning above [`AREA_FRACTION_WARN`], error above 1 (a real area larger
//!   than the nominal area is impossible);
//! - interferences small against the summit radius (Hertz/JKR/Maugis are
//!   small-strain paraboloid theories): the highest expected summit's
//!   contact radius `a = sqrt(R delta)` (Hertz) against
//!   [`CONTACT_RADIUS_WARN`] `R` (the bound used for the exact sphere in
//!   `src/axisym`), error when `delta > R` (a cap deeper than the radius is
//!   no paraboloid);
//! - `eta R sigma` (summit density x radius x height std), the one
//!   dimensionless group of the GW surface: measured surfaces give
//!   0.03–0.05 (GW 1966, McCool 1986); above [`ETA_R_SIGMA_WARN`] the real
//!   area reaches `pi eta R sigma F_1(h)`, i.e. 10 % of the nominal area
//!   within one sigma of the mean plane;
//! - a program that resolves the contact: [`MIN_POINTS_IN_RANGE`] points per
//!   leg where summits are in range;
//! - a non-negative dissipated energy: a negative hysteresis energy beyond
//!   the integration tolerance is an error, one within it is zero.

use crate::error::{Error, Result};
use crate::loading::{Curve, LoadingModel};
use crate::study::plan::{Plan, Target};

/// Real-area fraction `A_r/A_n` above which GW's independent-asperity
/// assumption is no longer a good approximation (contacts start to
/// interact; Ciavarella et al. 2008, J. Mech. Phys. Solids 56, 3432).
pub const AREA_FRACTION_WARN: f64 = 0.1;

/// Contact radius of the highest expected summit, in units of `R`, above
/// which the paraboloid (small-strain) laws lose accuracy.
pub const CONTACT_RADIUS_WARN: f64 = 0.3;

/// `eta R sigma` above which the surface is outside GW's measured range.
pub const ETA_R_SIGMA_WARN: f64 = 0.1;

/// Points per leg, where summits are in range, below which the curve does
/// not resolve the contact.
pub const MIN_POINTS_IN_RANGE: f64 = 10.0;

/// The height (m, from the distribution's origin) of the highest of the
/// `N = eta A_n` summits one expects: `sigma Q^-1(1/N)` (`N >= 2`; the
/// probability is floored at 1e-15 so that the quantile stays finite).
fn top_summit(plan: &Plan) -> f64 {
    let n = plan.surface.summits().max(2.0);
    let p = (1.0 / n).max(1e-15);
    plan.surface.sigma * plan.distribution.quantile(1.0 - p)
}

/// The scene field that sets the closest separation.
fn program_field(plan: &Plan) -> &'static str {
    match plan.target {
        Target::Load(_) => "program.max_load",
        _ => "program.closest_separation",
    }
}

/// `eta R sigma` of the plan's surface.
pub fn eta_r_sigma(plan: &Plan) -> f64 {
    let s = &plan.surface;
    s.density * s.radius * s.sigma
}

/// The interference check at closest separation `closest` (m): a warning
/// when the highest expected summit's Hertz contact radius exceeds
/// [`CONTACT_RADIUS_WARN`] `R`; an error naming the input that drives it
/// when its interference exceeds `R`.
fn interference(plan: &Plan, closest: f64, warnings: &mut Vec<String>) -> Result<()> {
    let r = plan.surface.radius;
    let top = top_summit(plan);
    let delta = top - closest;
    if !(delta.is_finite()) || delta <= 0.0 {
        return Ok(());
    }
    let a_over_r = (delta / r).sqrt();
    if delta > r {
        // Which input made the interference large: the height scale when the
        // highest summit alone is deeper than R, the program otherwise.
        let field = if top > r && top > -closest {
            "surface.sigma"
        } else {
            program_field(plan)
        };
        return Err(Error::invalid(
            field,
            format!(
                "the highest of the {:.3e} summits would be pressed {delta:.3e} m deep, more than \
                 its radius surface.radius = {r:e} m (closest separation {closest:.3e} m, \
                 surface.sigma = {:e} m): a paraboloidal summit has no meaning there (GW needs \
                 interferences small against R)",
                plan.surface.summits(),
                plan.surface.sigma
            ),
        ));
    }
    if a_over_r > CONTACT_RADIUS_WARN {
        warnings.push(format!(
            "interference: the highest expected summit is pressed {delta:.3e} m deep, contact \
             radius a/R = {a_over_r:.2} > {CONTACT_RADIUS_WARN} (Hertz estimate): the \
             small-strain asperity laws lose accuracy"
        ));
    }
    Ok(())
}

/// Plan-time diagnostics (closest separation given): `eta R sigma`, the
/// interference of the highest summit, the program's resolution.
///
/// # Errors
/// [`Error::Invalid`] naming the field when the program would press the
/// highest summit deeper than its radius.
pub fn plan_warnings(plan: &Plan) -> Result<Vec<String>> {
    let mut warnings = Vec::new();
    let ers = eta_r_sigma(plan);
    if ers > ETA_R_SIGMA_WARN {
        warnings.push(format!(
            "eta R sigma = {ers:.3e} (surface.density x surface.radius x surface.sigma) > \
             {ETA_R_SIGMA_WARN}: measured surfaces give 0.03-0.05; the real area reaches \
             {:.0} % of the nominal area near the mean plane, outside GW's independent summits",
            100.0 * std::f64::consts::PI * ers * 0.4
        ));
    }
    if let Target::Separation(d) = plan.target {
        interference(plan, d, &mut warnings)?;
    }
    Ok(warnings)
}

/// Run-time diagnostics of a finished curve; clamps a negative hysteresis
/// energy that is zero within the tolerance to 0 (with a warning).
///
/// # Errors
/// [`Error::Invalid`] naming the field when the real area exceeds the
/// nominal area or the highest summit is pressed deeper than its radius
/// (load-controlled programs); [`Error::NoConvergence`] (not the input's
/// fault) when outputs are not finite or the dissipated energy is negative
/// beyond the tolerance.
pub fn run_warnings(
    plan: &Plan,
    curve: &Curve,
    hysteresis_energy: &mut Option<f64>,
) -> Result<Vec<String>> {
    let mut warnings = Vec::new();
    let bad = curve
        .approach
        .iter()
        .chain(&curve.retract)
        .flat_map(|s| [s.load(), s.area(), s.count()])
        .flatten()
        .find(|v| !v.is_finite());
    if let Some(v) = bad {
        let pick = crate::study::scene::most_extreme_input(&plan.scene, &[]);
        return Err(Error::invalid(
            pick,
            format!(
                "the curve has a non-finite value ({v}), outputs withheld: {pick} is the input \
                 furthest from typical values"
            ),
        ));
    }
    let closest = curve.program.closest;
    if let Target::Load(_) = plan.target {
        interference(plan, closest, &mut warnings)?;
    }
    let max_area = curve
        .approach
        .iter()
        .chain(&curve.retract)
        .filter_map(|s| s.area())
        .fold(0.0, f64::max);
    let fraction = max_area / plan.surface.nominal_area;
    if fraction > 1.0 {
        let ers = eta_r_sigma(plan);
        let field = if ers > ETA_R_SIGMA_WARN {
            "surface.sigma"
        } else {
            program_field(plan)
        };
        return Err(Error::invalid(
            field,
            format!(
                "the real contact area would be {fraction:.3e} x the nominal area \
                 surface.nominal_area (impossible; GW needs a small fraction): eta R sigma = \
                 {ers:.3e} (surface.density x surface.radius x surface.sigma), closest \
                 separation {closest:.3e} m"
            ),
        ));
    }
    if fraction > AREA_FRACTION_WARN {
        warnings.push(format!(
            "real area: A_r/A_n = {fraction:.3} > {AREA_FRACTION_WARN} at the closest separation: \
             contacts interact, outside GW's independent summits"
        ));
    }
    // Resolution: points per leg between the closest separation and where
    // the first summit comes in range.
    if let Ok(model) = plan.model_with(plan.law.law.clone()) {
        let onset = model.interaction_onset();
        let span = curve.program.start - closest;
        if span > 0.0 && onset.is_finite() && onset > closest {
            let inside = (onset.min(curve.program.start) - closest) / span
                * (curve.program.points as f64 - 1.0);
            if inside < MIN_POINTS_IN_RANGE {
                warnings.push(format!(
                    "resolution: only {inside:.1} of the {} points per leg lie where summits are \
                     in range (below {onset:.3e} m; program.start_separation = {:.3e} m): the \
                     curve, pull-off and hysteresis energy are not resolved",
                    curve.program.points, curve.program.start
                ));
            }
        }
    }
    if let Some(e) = *hysteresis_energy {
        // The energy's error scale: rtol times the integral of |P| over both legs.
        let scale: f64 = curve
            .approach
            .windows(2)
            .zip(curve.retract.windows(2))
            .map(|(a, r)| {
                let h = (a[1].separation - a[0].separation).abs();
                let p = |s: &crate::loading::State| s.load().unwrap_or(0.0).abs();
                0.5 * h * (p(&a[0]) + p(&a[1]) + p(&r[0]) + p(&r[1]))
            })
            .sum();
        let tol = plan.budget.energy_sign() * scale;
        if e < -tol {
            return Err(Error::NoConvergence {
                what: format!(
                    "hysteresis energy = {e:e} J < 0 beyond its tolerance {tol:.3e} J: a negative \
                     dissipated energy is impossible (the program does not resolve the loop; \
                     raise program.points)"
                ),
                iterations: 0,
                residual: e,
            });
        }
        if e < 0.0 {
            warnings.push(format!(
                "hysteresis energy: {e:.3e} J is zero within its tolerance {tol:.3e} J; \
                 reported as 0"
            ));
            *hysteresis_energy = Some(0.0);
        }
    }
    Ok(warnings)
}

/// `plan` with its plan-time warnings ([`plan_warnings`]) appended.
///
/// # Errors
/// As [`plan_warnings`].
pub fn checked(mut plan: Plan) -> Result<Plan> {
    let w = plan_warnings(&plan)?;
    plan.warnings.extend(w);
    Ok(plan)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::{PlanMode, Scene, DEFAULT_SCENE};

    #[test]
    fn negative_energy_is_zero_within_tolerance_and_an_error_beyond() {
        let scene =
            Scene::from_toml(&DEFAULT_SCENE.replacen("points = 200", "points = 20", 1)).unwrap();
        let plan = Plan::new(&scene, PlanMode::Planned).unwrap();
        let results = plan.run().unwrap();
        assert!(results.warnings.is_empty(), "{:?}", results.warnings);
        let mut e = Some(-1e-30);
        let w = run_warnings(&plan, &results.curve, &mut e).unwrap();
        assert_eq!(e, Some(0.0));
        assert!(w.iter().any(|s| s.contains("zero within")), "{w:?}");
        let mut e = Some(-1.0);
        let err = run_warnings(&plan, &results.curve, &mut e).unwrap_err();
        assert!(
            !err.is_bad_input() && err.to_string().contains("hysteresis"),
            "{err}"
        );
        let mut e = Some(1e-12);
        assert!(run_warnings(&plan, &results.curve, &mut e)
            .unwrap()
            .is_empty());
        assert_eq!(e, Some(1e-12));
    }

    #[test]
    fn eta_r_sigma_above_the_bound_warns_at_plan_time() {
        let scene =
            Scene::from_toml(&DEFAULT_SCENE.replacen("density = 1e12", "density = 3e13", 1))
                .unwrap();
        let plan = Plan::new(&scene, PlanMode::Planned).unwrap();
        assert!((eta_r_sigma(&plan) - 0.15).abs() < 1e-12);
        assert!(
            plan.warnings.iter().any(|w| w.contains("eta R sigma")),
            "{:?}",
            plan.warnings
        );
    }
}
