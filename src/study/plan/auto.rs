//! `law.kind = "auto"` held to its promise on the scene's own surface: the
//! planner picks the cheapest analytic law whose error for one summit
//! (`data/law_errors.json`) meets `rtol`; when the run's measured model
//! error of a headline output misses `rtol` there, the plan is decided
//! again with the full-solver (calibrated) law, which `auto` promised.

use super::{Decision, FullSolver, Inputs, LawReason, Plan};
use crate::error::Result;
use crate::study::scene::LawName;
use std::path::Path;

impl Plan {
    /// Whether a model-error warning's advice names only `calibrated` (the
    /// scene's `law.kind` is `auto`, which already gives the full-solver
    /// law where its analytic law misses `rtol`), rather than `calibrated`
    /// or `auto`.
    pub fn advises_calibrated_only(&self) -> bool {
        self.scene.law.kind == LawName::Auto
    }

    /// For `law.kind = "auto"` whose analytic law missed `rtol` on this
    /// surface (`missed(rtol)`: the headline output furthest above it and
    /// its relative error, as the run measured them): the plan with the
    /// full-solver law, its law decision saying why; `None` when the
    /// planned law stands.
    ///
    /// # Errors
    /// As [`Plan::decide`] and [`Inputs::gather`] for the calibrated law.
    pub(crate) fn auto_replanned(
        &self,
        missed: impl FnOnce(f64) -> Option<(&'static str, f64)>,
    ) -> Result<Option<Plan>> {
        if self.scene.law.kind != LawName::Auto
            || self.law.facts.full_solver != FullSolver::Reference
            || self.reference.is_none()
        {
            return Ok(None);
        }
        let rtol = self.budget.law_choice();
        let Some((output, error)) = missed(rtol) else {
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
