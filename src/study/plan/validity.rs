//! The GW validity findings of a plan and a run ([`crate::gw::validity`])
//! as the scene sees them: warnings, or errors naming the scene input that
//! drove an impossible result; and the sign check of the hysteresis
//! energy (a negative energy within the budget is zero).

use crate::error::{Error, Result};
use crate::gw::validity::Finding;
use crate::gw::GwModel;
use crate::loading::{Curve, LoadingModel};
use crate::study::plan::{Plan, Target};
use crate::study::Warning;

/// The scene field that sets the closest separation, as the user wrote it.
fn program_field(plan: &Plan) -> &'static str {
    plan.target_field()
}

/// A finding as a warning, or as an error naming the input that drove it
/// when it makes the result impossible.
fn judge(plan: &Plan, f: Finding, closest: f64, warnings: &mut Vec<Warning>) -> Result<()> {
    let s = &plan.surface;
    match f {
        Finding::DeeperThanRadius {
            depth,
            top,
            closest,
        } => {
            // The height scale when the highest summit alone is deeper
            // than R, the program otherwise.
            let field = if top > s.radius && top > -closest {
                "surface.sigma"
            } else {
                program_field(plan)
            };
            Err(Error::invalid(
                field,
                format!(
                    "the highest of the {:.3e} summits would be pressed {depth:.3e} m deep, more \
                     than its radius surface.radius = {:e} m (closest separation {closest:.3e} m, \
                     surface.sigma = {:e} m): a paraboloidal summit has no meaning there (GW \
                     needs interferences small against R)",
                    s.summits(),
                    s.radius,
                    s.sigma
                ),
            ))
        }
        Finding::AreaAboveNominal { fraction } => {
            let ers = s.eta_r_sigma();
            if ers <= crate::gw::validity::ETA_R_SIGMA_WARN {
                if let Some(e) = law_blame(plan, fraction, closest) {
                    return Err(e);
                }
            }
            let field = if ers > crate::gw::validity::ETA_R_SIGMA_WARN {
                "surface.sigma"
            } else {
                program_field(plan)
            };
            Err(Error::invalid(
                field,
                format!(
                    "the real contact area would be {fraction:.3e} x the nominal area \
                     surface.nominal_area (impossible; GW needs a small fraction): eta R sigma = \
                     {ers:.3e} (surface.density x surface.radius x surface.sigma)"
                ),
            ))
        }
        other => {
            warnings.push(Warning::Validity(other));
            Ok(())
        }
    }
}

/// An impossible real area that the elastic, non-adhesive (Hertz) law on
/// the same surface and program keeps below the nominal area: under a
/// plastic law the yield strength (or hardness) the user wrote drove it,
/// far outside the plastic fits' range; under another law the moduli or
/// the adhesion (the one furthest from typical values), not the program.
/// `None` when the Hertz area is impossible too (then the program or the
/// surface is to blame).
fn law_blame(plan: &Plan, fraction: f64, closest: f64) -> Option<Error> {
    if !closest.is_finite() {
        return None;
    }
    let c = &plan.contact;
    let hertz = crate::law::Hertz::new(c.radius, c.contact_modulus).ok()?;
    let elastic = plan.model_with(std::sync::Arc::new(hertz)).ok()?;
    let area = elastic
        .state(
            closest,
            crate::loading::History::Approach,
            &crate::loading::Observables::standard(false, true, false),
        )
        .ok()?
        .area()?;
    let elastic_fraction = area / plan.surface.nominal_area;
    if !(elastic_fraction <= 1.0) {
        return None;
    }
    let Some(plasticity) = plan.plasticity.as_ref() else {
        // An adhesive or shaped law spreads the contacts where Hertz does
        // not: the moduli or the adhesion drove it.
        let pick = crate::study::scene::most_extreme_input(
            &plan.scene,
            &["materials.e1", "materials.e2", "adhesion.w", "adhesion.z0"],
        );
        return Some(Error::invalid(
            pick,
            format!(
                "the law's real contact area would be {fraction:.3e} x the nominal area \
                 (impossible), where the non-adhesive Hertz law on the same surface and program \
                 gives {elastic_fraction:.3e} x: {pick} is the input furthest from typical \
                 values (a gold microswitch: E = 79e9 Pa, w = 0.5 J/m^2, z0 = 0.3e-9 m)"
            ),
        ));
    };
    let (field, value) = if plan.scene.materials.hardness.is_some() {
        ("materials.hardness", plasticity.hardness())
    } else {
        ("materials.yield_strength", plasticity.yield_strength())
    };
    let psi = crate::material::plastic::plasticity_index(
        c.contact_modulus,
        plasticity.hardness(),
        plan.surface.sigma,
        plan.surface.radius,
    )
    .ok()?;
    Some(Error::invalid(
        field,
        format!(
            "{field} = {value:e} Pa makes the plastic law's real contact area {fraction:.3e} x \
             the nominal area (impossible), where the elastic (Hertz) law on the same surface \
             and program gives {elastic_fraction:.3e} x: the plastic fit is extrapolated far \
             beyond its range (plasticity index psi = {psi:.3e}; metals give 0.1 .. 100, \
             yield strengths of 1e7 .. 1e10 Pa)"
        ),
    ))
}

/// The plan's GW model with its own law (the findings need no table).
fn model(plan: &Plan) -> Result<GwModel> {
    plan.model_with(plan.law.law.clone())
}

/// Plan-time diagnostics (closest separation given): `eta R sigma`, the
/// interference of the highest summit.
///
/// # Errors
/// [`Error::Invalid`] naming the field when the program would press the
/// highest summit deeper than its radius.
pub fn plan_warnings(plan: &Plan) -> Result<Vec<Warning>> {
    let mut warnings = Vec::new();
    let closest = match plan.target {
        Target::Separation(d) => d,
        // The interference is judged on the run's closest separation.
        Target::Load(_) => f64::INFINITY,
    };
    for f in model(plan)?.findings_at(closest) {
        // Under a rough sphere the surface has no nominal area (no fixed
        // set of summits whose highest could be judged) and the program's
        // separations are remote: only eta R sigma applies; the sphere
        // judges its own local gaps (`study::sphere`).
        if plan.sphere.is_some() && !matches!(f, Finding::EtaRSigma { .. }) {
            continue;
        }
        judge(plan, f, closest, &mut warnings)?;
    }
    Ok(warnings)
}

/// Run-time diagnostics of a finished curve; clamps a negative hysteresis
/// energy that is zero within the budget to 0 (with a warning).
///
/// # Errors
/// [`Error::Invalid`] naming the field when the real area exceeds the
/// nominal area or the highest summit is pressed deeper than its radius
/// (load-controlled programs); [`Error::NoConvergence`] (not the input's
/// fault) when the dissipated energy is negative beyond the tolerance;
/// [`Error::Invalid`] naming the input furthest from typical values when
/// outputs are not finite.
pub fn run_warnings(
    plan: &Plan,
    curve: &Curve,
    hysteresis_energy: &mut Option<f64>,
) -> Result<Vec<Warning>> {
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
    let model = model(plan)?;
    let mut findings = Vec::new();
    if plan.sphere.is_some() {
        // A rough sphere: the real area against its own apparent area and
        // its local gaps are judged by the sphere (`study::sphere`); the
        // program's resolution applies as on a flat.
        findings.extend(
            model
                .findings_of(curve)
                .into_iter()
                .filter(|f| matches!(f, Finding::Resolution { .. })),
        );
    } else if let Target::Load(_) = plan.target {
        findings.extend(
            model
                .findings_at(curve.program.closest)
                .into_iter()
                .filter(|f| !matches!(f, Finding::EtaRSigma { .. })),
        );
    }
    if plan.sphere.is_none() {
        findings.extend(model.findings_of(curve));
    }
    for f in findings {
        judge(plan, f, curve.program.closest, &mut warnings)?;
    }
    if let Some(e) = *hysteresis_energy {
        // The energy's error scale: the budget times int |P| over both legs.
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
            warnings.push(Warning::HysteresisZero {
                energy: e,
                tolerance: tol,
            });
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
        let quiet = |w: &[Warning]| w.iter().all(|s| s.to_string().starts_with("pull-off:"));
        assert!(quiet(&results.warnings), "{:?}", results.warnings);
        let mut e = Some(-1e-30);
        let w = run_warnings(&plan, &results.curve, &mut e).unwrap();
        assert_eq!(e, Some(0.0));
        assert!(
            w.iter()
                .any(|s| s.code() == "hysteresis-energy-zero"
                    && s.to_string().contains("zero within")),
            "{w:?}"
        );
        let mut e = Some(-1.0);
        let err = run_warnings(&plan, &results.curve, &mut e).unwrap_err();
        assert!(
            !err.is_bad_input() && err.to_string().contains("hysteresis"),
            "{err}"
        );
        let mut e = Some(1e-12);
        assert!(quiet(&run_warnings(&plan, &results.curve, &mut e).unwrap()));
        assert_eq!(e, Some(1e-12));
    }

    #[test]
    fn eta_r_sigma_above_the_bound_warns_at_plan_time() {
        let scene =
            Scene::from_toml(&DEFAULT_SCENE.replacen("density = 1e12", "density = 3e13", 1))
                .unwrap();
        let plan = Plan::new(&scene, PlanMode::Planned).unwrap();
        assert!((plan.surface.eta_r_sigma() - 0.15).abs() < 1e-12);
        assert!(
            plan.warnings
                .iter()
                .any(|w| w.code() == "eta-r-sigma" && w.to_string().contains("eta R sigma")),
            "{:?}",
            plan.warnings
        );
    }
}
