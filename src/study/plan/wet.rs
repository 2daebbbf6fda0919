//! Menisci beside the dry law: with `adhesion.relative_humidity`, the law
//! the planner chose becomes the two-zone law (exact, for elastic laws) or
//! the dry law with the rigid meniscus beside it, by the model-error rule:
//! the rigid (Derjaguin) meniscus when its pull-off is within the
//! law-choice tolerance of the elastic meniscus' Maugis–Dugdale solution,
//! the exact two-zone law otherwise. Without a meniscus the dry choice is
//! returned untouched (bit for bit the dry run).

use super::budget::Budget;
use super::decision::{Decision, LawReason};
use super::law::{FullSolver, LawChoice, LawFacts};
use super::PlanMode;
use crate::capillary::{derjaguin_error, Meniscus, TwoZone, WithMeniscus, Zone, MOLECULAR_SIZE};
use crate::error::Result;
use crate::law::LawKernels;
use crate::material::AsperityContact;
use crate::study::scene::Scene;
use crate::study::Warning;
use std::sync::Arc;

/// The wet law for `scene` from the dry `law`, with the validity warnings.
pub(super) fn apply(
    scene: &Scene,
    contact: &AsperityContact,
    sigma: f64,
    law: LawChoice,
    mode: PlanMode,
    budget: &Budget,
    decisions: &mut Vec<Decision>,
) -> Result<(LawChoice, Vec<Warning>)> {
    let Some(m) = scene.adhesion.meniscus()? else {
        return Ok((law, Vec::new()));
    };
    let (r, e) = (contact.radius, contact.contact_modulus);
    let error = derjaguin_error(&m, r, e);
    let rtol = budget.law_choice();
    // Elastic laws (analytic or the full solver's): the ones with a full-solver counterpart.
    let elastic = law.facts.full_solver != FullSolver::NoCounterpart;
    let exact = elastic && (mode == PlanMode::EverythingOn || error.is_none_or(|x| x > rtol));
    let (name, built): (String, Arc<dyn LawKernels>) = if exact {
        let mut zones = vec![m.zone()];
        let ad = contact.adhesion;
        if ad.work() > 0.0 {
            zones.push(Zone {
                stress: ad.dugdale_stress(),
                range: ad.dugdale_range(),
            });
        }
        let tz = TwoZone::new(r, e, &zones).map_err(|x| x.in_table("adhesion"))?;
        ("two-zone (meniscus + solid)".into(), Arc::new(tz))
    } else {
        (
            format!("{} + meniscus", law.name),
            Arc::new(WithMeniscus::new(law.law.clone(), &m, r)),
        )
    };
    decisions.push(Decision::Law {
        name: name.clone(),
        reason: LawReason::Meniscus {
            dry: law.name.clone(),
            exact,
            error,
            rtol,
            kelvin_radius: m.kelvin_radius(),
            height: m.height(),
        },
        mu: contact.tabor(),
        lambda: m.lambda(r, e),
    });
    let warnings = warnings(&m, r, sigma, error, rtol, exact);
    let choice = LawChoice {
        name,
        source: law.source,
        facts: LawFacts {
            full_solver: FullSolver::NoCounterpart,
            rebuild: None,
            ..law.facts
        },
        law: built,
        measured_error: None,
    };
    Ok((choice, warnings))
}

/// The validity warnings of per-summit menisci (docs/physics.md,
/// "Capillary (wet) adhesion").
pub fn warnings(
    m: &Meniscus,
    radius: f64,
    sigma: f64,
    error: Option<f64>,
    rtol: f64,
    exact: bool,
) -> Vec<Warning> {
    let mut w = Vec::new();
    let rk = m.kelvin_radius();
    if rk < MOLECULAR_SIZE {
        w.push(Warning::MeniscusMolecular { kelvin_radius: rk });
    }
    if rk > radius || m.height() > sigma {
        w.push(Warning::MenisciMerge {
            kelvin_radius: rk,
            height: m.height(),
            radius,
            sigma,
        });
    }
    if let (false, Some(e)) = (exact, error) {
        if e > rtol {
            w.push(Warning::MeniscusRigid { error: e, rtol });
        }
    }
    w
}
