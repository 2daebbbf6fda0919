//! The program's decisions: where it starts and stops, the listed states,
//! and the table of an expensive law over the interferences it reaches.

use super::LawChoice;
use super::{Budget, Decision, PlanMode, StartReason, Target, MAX_LOAD_TABLE_DEPTH};
use crate::error::{Error, Result};
use crate::gw::GwModel;
use crate::loading::LoadingModel;
use crate::study::scene::{ProgramTarget, Scene};

/// The default start of a program on `model`: where the summits beyond the
/// flat's reach carry less than the budget's tail probability (everything
/// on: where the first summit comes in range).
pub fn start_of(model: &GwModel, budget: &Budget, mode: PlanMode) -> (f64, StartReason) {
    match mode {
        PlanMode::Planned => (
            model.start_separation(budget.start_tail()),
            StartReason::TailFraction(budget.start_tail()),
        ),
        PlanMode::EverythingOn => (model.interaction_onset(), StartReason::EverythingOn),
    }
}

/// Where the program starts and where its approach stops, and the listed
/// states (`separations` or `loads`), if any.
pub(super) fn program(
    scene: &Scene,
    mode: PlanMode,
    budget: &Budget,
    model: &GwModel,
    decisions: &mut Vec<Decision>,
) -> Result<(Target, f64, Option<ProgramTarget>)> {
    let given = scene.program_target()?;
    let (target, listed) = match &given {
        ProgramTarget::Separation(d) => (Target::Separation(*d), None),
        ProgramTarget::Load(p) => (Target::Load(*p), None),
        ProgramTarget::Separations(xs) => (
            Target::Separation(xs.iter().copied().fold(f64::INFINITY, f64::min)),
            Some(given.clone()),
        ),
        ProgramTarget::Loads(xs) => (
            Target::Load(xs.iter().copied().fold(0.0, f64::max)),
            Some(given.clone()),
        ),
    };
    let (start, reason) = match (scene.program.start_separation, mode) {
        (Some(s), _) => (s, StartReason::Given),
        (None, _) => start_of(model, budget, mode),
    };
    if !start.is_finite() {
        // Derived from sigma, the distribution and the force range: named
        // by the caller's mapping to the input furthest out.
        return Err(Error::invalid(
            "start separation",
            format!("the program's start separation is {start:e} m"),
        ));
    }
    decisions.push(Decision::Start {
        separation: start,
        reason,
    });
    if let Some(l) = &listed {
        let (count, loads) = match l {
            ProgramTarget::Separations(xs) => (xs.len(), false),
            ProgramTarget::Loads(xs) => (xs.len(), true),
            _ => (0, false),
        };
        decisions.push(Decision::Listed { count, loads });
    }
    if let Target::Separation(d) = target {
        if !(start > d) {
            let name = if listed.is_some() {
                "program.separations"
            } else {
                "program.closest_separation"
            };
            return Err(Error::OutOfRange {
                name: name.into(),
                value: d,
                allowed: crate::error::Allowed::open(f64::NEG_INFINITY, start),
            });
        }
    }
    Ok((target, start, listed))
}

/// The table of an expensive law ([`LawKernels::worth_tabulating`](crate::law::LawKernels::worth_tabulating)):
/// the interference interval the program reaches ([`GwModel::reachable_interferences`])
/// and the table's tolerance; `None` when not worth it.
pub(super) fn tabulation(
    law: &LawChoice,
    model: &GwModel,
    start: f64,
    target: Target,
    budget: &Budget,
    mode: PlanMode,
) -> Option<((f64, f64), f64)> {
    // Laws that are already tables (calibrated, shaped) or cheap say so.
    let worth = law.law.worth_tabulating();
    if mode == PlanMode::EverythingOn || !worth {
        return None;
    }
    let closest = match target {
        Target::Separation(d) => d,
        Target::Load(_) => start - MAX_LOAD_TABLE_DEPTH * model.surface().sigma,
    };
    let (lo, hi) = model.reachable_interferences(closest);
    (hi > lo).then_some(((lo, hi), budget.table()))
}
