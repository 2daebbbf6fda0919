//! The outputs' decisions: which totals the curve computes and how
//! (closed forms, sample sums or quadrature), and the contact resistance.

use super::{Budget, Decision, Evaluation, LawChoice, OutputReason, PlanMode};
use crate::electrical::{Interaction, ResistanceObservables};
use crate::error::Result;
use crate::gw::{Accuracy, GwModel, Method, RoughSurface};
use crate::loading::Observables;
use crate::study::scene::Scene;

/// The contact resistance's observables and decision, with `[electrical]`.
/// On a rough sphere the interaction's square side is NaN here: the run
/// gives each state the bump's own ([`crate::study::Plan::run`]).
pub(super) fn resistance(
    scene: &Scene,
    surface: &RoughSurface,
    decisions: &mut Vec<Decision>,
) -> Result<Option<ResistanceObservables>> {
    let Some(e) = &scene.electrical else {
        return Ok(None);
    };
    let spot = e.spot_resistance()?;
    let interaction = e.interaction()?;
    decisions.push(Decision::Resistance {
        spreading: spot.spreading().name(),
        greenwood: interaction == Interaction::Greenwood,
        film: spot.has_film(),
        bump: scene.sphere.is_some(),
    });
    let side = if scene.sphere.is_some() {
        f64::NAN
    } else {
        surface.nominal_area.sqrt()
    };
    Ok(Some(ResistanceObservables::new(spot, interaction, side)))
}

/// The integration accuracy of `model`: the budget's tolerance, closed
/// forms where the law and the distribution have them, and
/// [`Method::Auto`] too for laws smooth in the root of their interference
/// (Kogut–Etsion, ...: their approach totals by the cheaper root rule of
/// [`GwModel`]); everything on: adaptive quadrature in the height
/// everywhere.
///
/// # Errors
/// [`Error::OutOfRange`](crate::Error::OutOfRange) naming `accuracy.rtol`.
pub fn accuracy_of(model: &GwModel, budget: &Budget, mode: PlanMode) -> Result<Accuracy> {
    let closed = model.has_closed_form(&Observables::ALL);
    let method = if (closed || model.law().smooth_in_root()) && mode == PlanMode::Planned {
        Method::Auto
    } else {
        Method::Quadrature
    };
    Ok(Accuracy::new(budget.integrals())
        .map_err(|e| e.renamed("accuracy.rtol"))?
        .with_method(method))
}

/// Which observables the curve computes, the integration method, and the
/// decision for each output.
pub(super) fn outputs(
    scene: &Scene,
    mode: PlanMode,
    budget: &Budget,
    model: &GwModel,
    law: &LawChoice,
    decisions: &mut Vec<Decision>,
) -> Result<(Observables, Accuracy)> {
    let o = scene.outputs;
    let all = mode == PlanMode::EverythingOn;
    let observables = Observables::standard(
        o.load || o.hysteresis_energy || all,
        o.area || all,
        o.count || all,
    );
    let closed = model.has_closed_form(&Observables::ALL);
    let accuracy = accuracy_of(model, budget, mode)?;
    let method = accuracy.method;
    let distribution = model.distribution();
    let evaluation = if distribution.sample_points().is_some() && !closed {
        Evaluation::SampleSum
    } else if method == Method::Auto && closed {
        Evaluation::ClosedForm
    } else {
        Evaluation::Quadrature
    };
    for (name, asked, needed) in [
        ("load", o.load, observables.load),
        ("area", o.area, observables.area),
        ("count", o.count, observables.count),
    ] {
        let (evaluation, reason) = if !needed {
            (Evaluation::Skipped, OutputReason::NotAsked)
        } else if asked && !all {
            (
                evaluation,
                OutputReason::Asked {
                    law: law.name.clone(),
                    distribution: distribution.name().into(),
                    rtol: budget.rtol,
                },
            )
        } else if all {
            (evaluation, OutputReason::EverythingOn)
        } else {
            (evaluation, OutputReason::NeededByHysteresis)
        };
        decisions.push(Decision::Output {
            observable: name,
            evaluation,
            reason,
        });
    }
    Ok((observables, accuracy))
}
