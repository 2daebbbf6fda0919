//! Planning, step by step, from a scene and its gathered inputs: the law,
//! the map's model, the outputs and their methods, the quantities, the
//! plasticity diagnostics, the program, the legs, the population.

use super::{
    law, outputs, program, resistance, tabulation, Budget, CalibrationInput, Decision, FullSolver,
    Inputs, LawChoice, McPlan, Plan, PlanMode, TopographyPlan,
};
use crate::electrical::{Heating, ResistanceObservables, Switch};
use crate::error::Result;
use crate::gw::{GwModel, RoughSurface};
use crate::heights::HeightDistribution;
use crate::law::LawKernels;
use crate::loading::Observables;
use crate::material::plastic::Plasticity;
use crate::material::AsperityContact;
use crate::study::quantity::QuantitySet;
use crate::study::Warning;

use crate::study::scene::{
    build_contact, build_distribution, build_surface, MonteCarloSpec, Resolved, Scene,
};
use std::sync::Arc;

impl Plan {
    // Over 100 lines, kept whole: the planning steps in order, each feeding the
    // next through the same locals.
    pub(super) fn build(scene: &Scene, mode: PlanMode, inputs: &Inputs) -> Result<Plan> {
        scene.validate()?;
        let resolved = inputs.map.as_ref();
        let scene = resolved.map_or(scene, |r| &r.scene);
        let contact = build_contact(scene)?;
        let surface = build_surface(scene)?;
        let distribution = build_distribution(&scene.surface)?;
        let mut decisions = Vec::new();
        let budget = Budget::new(scene.accuracy.rtol);
        let calibration = inputs.calibration.as_ref();
        let law = law::choose(scene, &contact, mode, &budget, calibration, &mut decisions)?;
        let (law, wet_warnings) = super::wet::apply(
            scene,
            &contact,
            surface.sigma,
            law,
            mode,
            &budget,
            &mut decisions,
        )?;
        let reference = reference_law(&law, calibration, &contact)?;
        let topography = topography_plan(resolved, &law, &contact, &mut decisions)?;
        let sphere = super::sphere::plan(
            scene,
            &surface,
            contact.contact_modulus,
            &budget,
            &mut decisions,
        )?;
        let model = GwModel::new(surface, distribution.clone(), law.law.clone())?;
        let (observables, accuracy) = outputs(scene, mode, &budget, &model, &law, &mut decisions)?;
        let resistance = resistance(scene, &surface, &mut decisions)?;
        let heating = scene
            .electrical
            .as_ref()
            .map(|e| e.heating())
            .transpose()?
            .flatten();
        let quantities = quantity_set(scene, observables, resistance.as_ref(), heating)?;
        let plasticity = scene.plasticity()?;
        let mut warnings =
            plasticity_decision(plasticity, &surface, &contact, &law, &mut decisions)?;
        warnings.extend(wet_warnings);
        warnings.extend(
            calibration
                .and_then(|c| c.note.clone())
                .map(Warning::CalibrationCache),
        );
        warnings.extend(resolved.iter().flat_map(|r| r.warnings.iter().cloned()));
        let model = model.with_accuracy(accuracy);
        let (target, start, listed) = program(scene, mode, &budget, &model, &mut decisions)?;
        let tabulation = tabulation(&law, &model, start, target, &budget, mode);
        if let Some((interval, tolerance)) = tabulation {
            decisions.push(Decision::Tabulation {
                law: law.name.clone(),
                tolerance,
                interval,
            });
        }
        let legs = legs(scene, mode, &contact, &law, &mut decisions);
        let montecarlo = scene
            .montecarlo
            .as_ref()
            .map(|spec| {
                let d = distribution.as_ref();
                montecarlo(spec, &surface, &contact, &law, d, &mut decisions)
            })
            .transpose()?;
        let pull_off_population = super::population::plan(
            scene,
            legs.pull_off,
            &surface,
            distribution.as_ref(),
            &law,
            sphere.is_some(),
            &mut decisions,
        )?;
        let switch = scene
            .switch
            .as_ref()
            .map(|s| Switch::new(s.spring_constant, s.travel).map_err(|e| e.in_table("switch")))
            .transpose()?;
        Ok(Plan {
            scene: scene.clone(),
            mode,
            budget,
            montecarlo,
            pull_off_population,
            contact,
            surface,
            distribution,
            law,
            reference,
            quantities,
            accuracy,
            start,
            target,
            points: scene.program.points,
            tabulation,
            compute_retraction: legs.retraction,
            pull_off: legs.pull_off,
            hysteresis_energy: legs.hysteresis_energy,
            decisions,
            plasticity,
            listed,
            resistance,
            switch,
            heating,
            warnings,
            topography,
            sphere,
        })
    }
}

/// The GW plasticity index with a yield strength, and the warning for an
/// elastic law on summits that yield.
fn plasticity_decision(
    plasticity: Option<Plasticity>,
    surface: &RoughSurface,
    contact: &AsperityContact,
    law: &LawChoice,
    decisions: &mut Vec<Decision>,
) -> Result<Vec<Warning>> {
    let Some(p) = plasticity else {
        return Ok(Vec::new());
    };
    let psi = surface
        .plasticity_index(contact.contact_modulus, p.hardness())
        .map_err(|e| e.in_table("materials"))?;
    let plastic_law = law.facts.plastic.is_some();
    decisions.push(Decision::Plasticity {
        psi,
        hardness: p.hardness(),
        plastic_law,
    });
    Ok(if plastic_law {
        Vec::new()
    } else {
        crate::law::plastic::elastic_law_warning(&law.name, psi)
            .map(Warning::ElasticLawYields)
            .into_iter()
            .collect()
    })
}

/// What the two legs compute.
struct Legs {
    retraction: bool,
    pull_off: bool,
    hysteresis_energy: bool,
}

/// Whether the retraction leg, the pull-off and the hysteresis energy are
/// computed (a law without history retracts along its approach).
fn legs(
    scene: &Scene,
    mode: PlanMode,
    contact: &AsperityContact,
    law: &LawChoice,
    decisions: &mut Vec<Decision>,
) -> Legs {
    let all = mode == PlanMode::EverythingOn;
    let history = law.law.has_history();
    let retraction = all || history;
    decisions.push(Decision::Retraction {
        computed: retraction,
        hysteresis: history.then(|| (law.law.attach_interference(), law.law.detach_interference())),
        law: law.name.clone(),
    });
    let o = scene.outputs;
    let adhesive = contact.adhesion.work() > 0.0;
    let pull_off = o.pull_off && (adhesive || all);
    decisions.push(Decision::PullOff {
        searched: pull_off,
        asked: o.pull_off || all,
        adhesive,
    });
    let hysteresis_energy = o.hysteresis_energy || all;
    decisions.push(Decision::HysteresisEnergy {
        computed: hysteresis_energy,
    });
    Legs {
        retraction,
        pull_off,
        hysteresis_energy,
    }
}

/// The population beside the integral.
fn montecarlo(
    spec: &MonteCarloSpec,
    surface: &RoughSurface,
    contact: &AsperityContact,
    law: &LawChoice,
    distribution: &dyn HeightDistribution,
    decisions: &mut Vec<Decision>,
) -> Result<McPlan> {
    let mc = McPlan::new(spec, surface, contact, law)?;
    decisions.push(Decision::MonteCarlo {
        summits: mc.summits,
        seed: spec.seed,
        distribution: distribution.name().into(),
        radius_log_std: spec.radius_log_std,
        factor: mc.factor,
    });
    Ok(mc)
}

/// The full solver's law on the scene's own asperity, the reference of
/// the model error, when the law is measured against it and a calibration
/// is at hand (adhesive contacts only).
fn reference_law(
    law: &LawChoice,
    calibration: Option<&CalibrationInput>,
    contact: &AsperityContact,
) -> Result<Option<Arc<dyn LawKernels>>> {
    Ok(match (law.facts.full_solver, calibration) {
        (FullSolver::Reference, Some(c)) if contact.adhesion.work() > 0.0 => {
            let l = c.calibration.law(
                contact.radius,
                contact.contact_modulus,
                contact.adhesion.work(),
            )?;
            Some(Arc::new(l) as Arc<dyn LawKernels>)
        }
        _ => None,
    })
}

/// The plan of a measured map's model, with its decision.
fn topography_plan(
    resolved: Option<&Resolved>,
    law: &LawChoice,
    contact: &AsperityContact,
    decisions: &mut Vec<Decision>,
) -> Result<Option<TopographyPlan>> {
    let Some(r) = resolved else {
        return Ok(None);
    };
    let t = TopographyPlan::new(r, law, contact)?;
    decisions.push(Decision::Topography {
        choice: t.choice(),
        why: t.why(),
    });
    Ok(Some(t))
}

/// The quantities of the run: the standard ones the scene's `[outputs]`
/// asks for over the planned observables, and the electrical ones with a
/// resistance.
fn quantity_set(
    scene: &Scene,
    observables: Observables,
    resistance: Option<&ResistanceObservables>,
    heating: Option<(f64, Heating)>,
) -> Result<QuantitySet> {
    let o = scene.outputs;
    let quantities = QuantitySet::standard(o.load, o.area, o.count).over(observables)?;
    match resistance {
        Some(r) => quantities.with_electrical(r, o.resistance, heating),
        None => Ok(quantities),
    }
}
