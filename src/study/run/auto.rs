//! `law.kind = "auto"` held to its promise on the scene's own surface: the
//! planner picks the cheapest analytic law whose error for one summit
//! (`data/law_errors.json`) meets `rtol`, and the run measures that law's
//! model error on the surface (`study::model_error`). When a headline output
//! misses `rtol` there (the Dugdale and JKR laws cut the Lennard-Jones
//! attraction that carries much of a rough surface's pull-off), the run is
//! repeated with the full-solver (calibrated) law, which `auto` promised.

use super::Results;
use crate::error::Result;
use crate::study::plan::{Decision, FullSolver, Inputs, LawReason, Plan};
use crate::study::scene::LawName;
use std::path::Path;

/// The headline output of `results` whose measured model error is the
/// largest above `rtol`, as `(its name, the relative error)`.
pub(super) fn missed(results: &Results, rtol: f64) -> Option<(&'static str, f64)> {
    let m = results.model_error.as_ref()?;
    let listed = m
        .listed_loads
        .iter()
        .flatten()
        .map(|&e| ("load at a listed state", e));
    [
        ("pull-off", m.pull_off),
        ("max load", m.max_load),
        ("hysteresis energy", m.hysteresis_energy),
    ]
    .into_iter()
    .filter_map(|(n, e)| e.map(|e| (n, e)))
    .chain(listed)
    .filter(|(_, e)| e.abs() > rtol || e.is_nan())
    .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
}

impl Plan {
    /// For `law.kind = "auto"` whose analytic law missed `rtol` on this
    /// surface ([`missed`]): the plan with the full-solver law, its law
    /// decision saying why; `None` when the planned law stands.
    ///
    /// # Errors
    /// As [`Plan::decide`] and [`Inputs::gather`] for the calibrated law.
    pub(super) fn auto_replanned(&self, results: &Results) -> Result<Option<Plan>> {
        if self.scene.law.kind != LawName::Auto
            || self.law.facts.full_solver != FullSolver::Reference
            || self.reference.is_none()
        {
            return Ok(None);
        }
        let rtol = self.budget.law_choice();
        let Some((output, error)) = missed(results, rtol) else {
            return Ok(None);
        };
        let mut scene = self.scene.clone();
        scene.law.kind = LawName::Calibrated;
        // (the model error is measured neither on a map nor on a sphere, so
        // no path is relative to a scene file here)
        let inputs = Inputs::gather(&scene, Path::new("."))?;
        let mut plan = Plan::decide(&scene, self.mode, &inputs)?;
        plan.scene.law.kind = LawName::Auto;
        for d in &mut plan.decisions {
            if let Decision::Law {
                reason: LawReason::Calibrated { auto, surface, .. },
                ..
            } = d
            {
                *auto = None;
                *surface = Some((rtol, self.law.name.clone(), output.to_string(), error));
            }
        }
        Ok(Some(plan))
    }
}
