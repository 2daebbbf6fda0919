//! Planning, step by step, from a scene and its gathered inputs: the law,
//! the map's model, the outputs and their methods, the quantities, the
//! plasticity diagnostics, the program, the legs, the population.

use super::{
    law, outputs, program, resistance, tabulation, Budget, Decision, FullSolver, Inputs, LawChoice,
    McPlan, Plan, PlanMode, TopographyPlan,
};
use crate::electrical::Switch;
use crate::error::Result;
use crate::gw::{GwModel, RoughSurface};
use crate::heights::HeightDistribution;
use crate::material::plastic::Plasticity;
use crate::material::AsperityContact;
use crate::study::quantity::QuantitySet;
use crate::study::scene::{
    build_contact, build_distribution, build_surface, MonteCarloSpec, Scene,
};

impl Plan {
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
        let reference = match (law.facts.full_solver, calibration) {
            (FullSolver::Reference, Some(c)) if contact.adhesion.work() > 0.0 => {
                let l = c.calibration.law(
                    contact.radius,
                    contact.contact_modulus,
                    contact.adhesion.work(),
                )?;
                Some(std::sync::Arc::new(l) as std::sync::Arc<dyn crate::law::LawKernels>)
            }
            _ => None,
        };
        let topography = match resolved {
            Some(r) => {
                let t = TopographyPlan::new(r, &law, &contact)?;
                decisions.push(Decision::Topography {
                    choice: t.choice(),
                    why: t.why(),
                });
                Some(t)
            }
            None => None,
        };
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
        let heating = match &scene.electrical {
            Some(e) => e.heating()?,
            None => None,
        };
        let o = scene.outputs;
        let mut quantities = QuantitySet::standard(o.load, o.area, o.count).over(observables)?;
        if let Some(r) = &resistance {
            quantities = quantities.with_electrical(r, o.resistance, heating)?;
        }
        let plasticity = scene.plasticity()?;
        let mut warnings =
            plasticity_decision(plasticity, &surface, &contact, &law, &mut decisions)?;
        warnings.extend(calibration.and_then(|c| c.note.clone()));
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
        let montecarlo = match &scene.montecarlo {
            Some(spec) => Some(montecarlo(
                spec,
                &surface,
                &contact,
                &law,
                distribution.as_ref(),
                &mut decisions,
            )?),
            None => None,
        };
        let pull_off_population = super::population::plan(
            scene,
            legs.pull_off,
            &surface,
            distribution.as_ref(),
            &law,
            sphere.is_some(),
            &mut decisions,
        )?;
        let switch = match &scene.switch {
            Some(s) => {
                Some(Switch::new(s.spring_constant, s.travel).map_err(|e| e.in_table("switch"))?)
            }
            None => None,
        };
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
) -> Result<Vec<String>> {
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
