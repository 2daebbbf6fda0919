//! The model error of a run's headline outputs, measured on the scene's own
//! surface: the same program with the full Lennard-Jones sphere solver's
//! law (the calibrated law) in place of the chosen analytic law.
//!
//! One summit's error (the law-error table) says little about a rough
//! surface: the Dugdale and JKR laws cut the attraction at about `z0`,
//! while the Lennard-Jones attraction of the many summits just out of
//! contact carries much of a rough surface's pull-off when `sigma/z0` is
//! large (docs/physics.md, "Model error on a rough surface").

use super::plan::Plan;
use crate::error::Result;
use crate::gw::Accuracy;
use crate::loading::{hysteresis_energy_to, History, LoadingModel, LoadingProgram, Observables};
use crate::study::plan::FullSolver;
use crate::study::warning::{ModelErrorOutput, Warning};

use super::map_error::MapModelError;
use super::map_pull_off::MapPullOff;
pub use crate::study::plan::REFERENCE_RTOL;

/// A model error larger than this (relative) is a warning.
pub const MODEL_ERROR_WARN: f64 = 0.1;

/// The model error of a run's headline outputs.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelError {
    /// What it is measured against (a sentence).
    pub reference: String,
    /// `(law - reference)/|reference|` of the pull-off.
    pub pull_off: Option<f64>,
    /// The same of the load at the closest approach (`max_load`).
    pub max_load: Option<f64>,
    /// The same of the hysteresis energy.
    pub hysteresis_energy: Option<f64>,
    /// The reference's pull-off (N).
    pub reference_pull_off: Option<f64>,
    /// The reference's load at the closest approach (N).
    pub reference_max_load: Option<f64>,
    /// The reference's hysteresis energy (J).
    pub reference_hysteresis_energy: Option<f64>,
    /// Of the load at each listed state (`[program] separations` or
    /// `loads`, in order), at the state's separation; empty when none are
    /// listed or the error is unmeasured.
    pub listed_loads: Vec<Option<f64>>,
    /// On a measured map: GW's model error against the exact elastic
    /// solution of the map ([`super::map_error`]), or why it is not
    /// measured.
    pub map: Option<MapModelError>,
    /// On a measured map with adhesion: GW's pull-off against the adhesive
    /// boundary-element solution of the map ([`super::map_pull_off`]), or
    /// why it is not measured.
    pub map_pull_off: Option<MapPullOff>,
}

impl ModelError {
    fn unmeasured(reference: impl Into<String>) -> ModelError {
        ModelError {
            reference: reference.into(),
            pull_off: None,
            max_load: None,
            hysteresis_energy: None,
            reference_pull_off: None,
            reference_max_load: None,
            reference_hysteresis_energy: None,
            listed_loads: Vec::new(),
            map: None,
            map_pull_off: None,
        }
    }

    /// The reference sentence with the map's: what the per-state errors
    /// are measured against, then what the headline outputs' are.
    pub fn full_reference(&self) -> String {
        let elastic = self.elastic_reference();
        match self.map_pull_off.as_ref().filter(|p| p.exact.is_some()) {
            Some(p) => format!("{elastic}. Pull-off on the map: GW against {}", p.reference),
            None => elastic,
        }
    }

    /// [`ModelError::full_reference`] without the map's pull-off.
    fn elastic_reference(&self) -> String {
        match &self.map {
            Some(m) if !m.states.is_empty() => format!(
                "{}. Pull-off, max load and hysteresis energy: {}",
                m.reference, self.reference
            ),
            Some(m) => format!(
                "{}; area, load and mean gap: {}",
                self.reference, m.reference
            ),
            None => self.reference.clone(),
        }
    }

    /// On a measured map, GW against the exact boundary-element solutions
    /// of the map: the elastic states ([`super::map_error::measure`], at the
    /// closest separation `closest`, m) and, with adhesion, the pull-off
    /// ([`super::map_pull_off::measure`], GW's `pull_off` and `max_load`,
    /// N), each within the budget of the GW run's own time since `t0` (or
    /// the floor).
    ///
    /// # Errors
    /// As the two measurements.
    pub fn measure_map(
        &mut self,
        plan: &Plan,
        closest: f64,
        pull_off: Option<f64>,
        max_load: Option<f64>,
        t0: std::time::Instant,
    ) -> Result<()> {
        let gw_seconds = t0.elapsed().as_secs_f64();
        self.map = super::map_error::measure(plan, closest, gw_seconds)?;
        self.map_pull_off = super::map_pull_off::measure(plan, pull_off, max_load, gw_seconds)?;
        Ok(())
    }

    /// Adds the model error of the loads at the listed states (their
    /// separations `separations` (m), the run's loads `loads` (N)) when the
    /// rest was measured: the reference law's load at the same separation.
    /// A failing reference leaves them unmeasured.
    pub fn measure_listed(&mut self, plan: &Plan, separations: &[f64], loads: &[Option<f64>]) {
        if self.reference_pull_off.is_none()
            && self.reference_max_load.is_none()
            && self.reference_hysteresis_energy.is_none()
        {
            return;
        }
        let Some(reference) = &plan.reference else {
            return;
        };
        let reference_loads = || -> Result<Vec<Option<f64>>> {
            let rtol = plan.budget.model_error_reference();
            let model = plan
                .model_with(reference.clone())?
                .with_accuracy(Accuracy::new(rtol)?);
            let steps: Vec<(f64, History)> = separations
                .iter()
                .map(|&d| (d, History::Approach))
                .collect();
            Ok(model
                .states(&steps, &Observables::LOAD)?
                .iter()
                .map(|s| s.load())
                .collect())
        };
        if let Ok(r) = reference_loads() {
            self.listed_loads = loads.iter().zip(r).map(|(&l, r)| relative(l, r)).collect();
        }
    }

    /// The listed state with the largest load error, as a warning row.
    fn listed_warning(&self) -> Option<(ModelErrorOutput, Option<f64>, Option<f64>)> {
        let worst = self
            .listed_loads
            .iter()
            .flatten()
            .copied()
            .max_by(|a, b| a.abs().total_cmp(&b.abs()))?;
        Some((ModelErrorOutput::ListedLoad, Some(worst), None))
    }

    /// Warnings for the outputs whose model error exceeds
    /// [`MODEL_ERROR_WARN`], advising the full-solver law by the
    /// `law.kind` values that give it: only `calibrated` when
    /// `calibrated_only` (the planner's decision,
    /// [`Plan::advises_calibrated_only`](crate::study::Plan::advises_calibrated_only)), else also
    /// `auto`.
    pub fn warnings(&self, law: &str, calibrated_only: bool) -> Vec<Warning> {
        [
            (
                ModelErrorOutput::PullOff,
                self.pull_off,
                self.reference_pull_off,
            ),
            (
                ModelErrorOutput::MaxLoad,
                self.max_load,
                self.reference_max_load,
            ),
            (
                ModelErrorOutput::HysteresisEnergy,
                self.hysteresis_energy,
                self.reference_hysteresis_energy,
            ),
        ]
        .into_iter()
        .chain(self.listed_warning())
        .filter_map(|(output, e, reference)| {
            let e = e?;
            (e.abs() > MODEL_ERROR_WARN).then(|| Warning::ModelError {
                output,
                law: law.to_string(),
                error: e,
                reference,
                auto: calibrated_only,
            })
        })
        .chain(self.map.iter().flat_map(MapModelError::warnings))
        .chain(self.map_pull_off.iter().filter_map(MapPullOff::warning))
        .collect()
    }
}

fn relative(law: Option<f64>, reference: Option<f64>) -> Option<f64> {
    let (a, b) = (law?, reference?);
    (b != 0.0).then(|| (a - b) / b.abs())
}

/// The model error of a run of `plan` over `program` whose pull-off,
/// load at the closest approach and hysteresis energy are given.
///
/// # Errors
/// As the reference model's states, pull-off and energy.
pub fn measure(
    plan: &Plan,
    program: &LoadingProgram,
    pull_off: Option<f64>,
    max_load: Option<f64>,
    hysteresis_energy: Option<f64>,
) -> Result<ModelError> {
    let adhesive = plan.contact.adhesion.work() > 0.0;
    if !adhesive {
        return Ok(ModelError {
            max_load: max_load.map(|_| 0.0),
            ..ModelError::unmeasured(
                "no adhesion: Hertz summits are the exact elastic small-strain solution, which \
                 the full solver reduces to at w = 0",
            )
        });
    }
    if plan.sphere.is_some() {
        return Ok(ModelError::unmeasured(
            "not measured on a rough sphere: the reference is the same program with the \
             full-solver law, which here would repeat the whole sphere solve; the law's model \
             error on the flat of the same surface (this scene without [sphere], with a \
             surface.nominal_area) measures the law's share",
        ));
    }
    match plan.law.facts.full_solver {
        FullSolver::Itself => {
            return Ok(ModelError::unmeasured(
                "this law is the full Lennard-Jones sphere solver's (tabulated to rtol/10): its \
                 model error is that of the Lennard-Jones continuum and GW's independent \
                 summits, not measured here",
            ))
        }
        FullSolver::NoCounterpart => {
            return Ok(ModelError::unmeasured(
                "no full-solver counterpart for this law (the sphere solver is elastic and \
                 paraboloidal): its adhesion is short-range JKR, which neglects the \
                 Lennard-Jones far field; law.kind = \"jkr\" against \"calibrated\" on the same \
                 surface measures what that costs for elastic summits",
            ))
        }
        FullSolver::Reference => {}
    }
    let Some(reference) = &plan.reference else {
        let mu = plan.contact.tabor();
        return Ok(ModelError::unmeasured(
            if !plan.scene.accuracy.model_error {
                "not measured: accuracy.model_error = false (the full solver is not run)"
                    .to_string()
            } else {
                format!(
                    "not measured: the full solver covers mu in [0.005, 100], not mu = {mu:.4} \
                 (JKR is the exact large-mu limit, Bradley the small-mu one)"
                )
            },
        ));
    };
    if plan.topography.is_some() {
        return Ok(ModelError::unmeasured(
            "not measured: a measured map's summits each have their own radius, and the \
             full-solver law does not scale with the radius",
        ));
    }
    match reference_run(
        plan,
        reference,
        program,
        pull_off,
        max_load,
        hysteresis_energy,
    ) {
        Ok(m) => Ok(m),
        // The model error is a diagnosis beside the run: a reference that
        // fails leaves it unmeasured, with the reason.
        Err(e) => Ok(ModelError::unmeasured(format!(
            "not measured: the full-solver reference run failed ({e})"
        ))),
    }
}

fn reference_run(
    plan: &Plan,
    reference: &std::sync::Arc<dyn crate::law::LawKernels>,
    program: &LoadingProgram,
    pull_off: Option<f64>,
    max_load: Option<f64>,
    hysteresis_energy: Option<f64>,
) -> Result<ModelError> {
    let rtol = plan.budget.model_error_reference();
    let model = plan
        .model_with(reference.clone())?
        .with_accuracy(Accuracy::new(rtol)?);
    let ref_load = if max_load.is_some() {
        model
            .state(program.closest, History::Approach, &Observables::LOAD)?
            .load()
    } else {
        None
    };
    let ref_pull = if pull_off.is_some() || plan.pull_off {
        model
            .pull_off(program.closest, program.start, 64)?
            .map(|p| p.load)
    } else {
        None
    };
    // The run's own rule: adaptive for a continuous model, the trapezoid
    // on the program for a finite sample of summits.
    let ref_energy = match hysteresis_energy {
        Some(_) if plan.distribution.sample_points().is_some() => model
            .curve(program, &Observables::LOAD)?
            .hysteresis_energy(),
        Some(_) => Some(hysteresis_energy_to(&model, program, rtol)?),
        None => None,
    };
    Ok(ModelError {
        reference: format!(
            "the full Lennard-Jones sphere solver's law (calibrated at mu = {:.4}) on the same \
             surface and program, to rtol {rtol:e}",
            plan.contact.tabor()
        ),
        // A searched pull-off without tension is a pull-off of 0.
        pull_off: relative(pull_off.or(plan.pull_off.then_some(0.0)), ref_pull),
        max_load: relative(max_load, ref_load),
        hysteresis_energy: relative(hysteresis_energy, ref_energy),
        reference_pull_off: ref_pull,
        reference_max_load: ref_load,
        reference_hysteresis_energy: ref_energy,
        listed_loads: Vec::new(),
        map: None,
        map_pull_off: None,
    })
}
