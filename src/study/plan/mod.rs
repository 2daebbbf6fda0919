//! The planner: turns a [`Scene`] into a [`Plan`] — which law, which method
//! serves each output and why, and what is skipped. It only decides: the
//! physics it needs (start separation, separation at a load, the
//! interference range a program reaches, radius scaling) lives in the core,
//! and nothing expensive runs here (Chebyshev tables are built and
//! calibrations computed when the run starts; [`Plan::preview`] never runs
//! the sphere solver).
//!
//! What a plan skips, and why each skip costs nothing:
//! - outputs not asked for are not computed (the observable set);
//! - adhesion machinery when `w = 0` (Hertz, no hysteresis);
//! - the retraction leg when the law has no hysteresis
//!   (attach = detach interference): it equals the approach leg, so it is
//!   copied, not recomputed;
//! - separations where no asperity is in range: the program starts where
//!   the summits beyond the flat's reach carry less than
//!   [`START_TAIL_FRACTION`] `x rtol` of the probability
//!   ([`GwModel::start_separation`]);
//! - quadrature where closed forms `F_n` exist (Hertz/DMT on Gaussian or
//!   exponential heights);
//! - the exact Maugis–Dugdale law when a cheaper law meets the tolerance at
//!   this Tabor parameter ([`crate::law::errors`], measured against the full
//!   Lennard-Jones solution).
//!
//! [`PlanMode::EverythingOn`] switches every skip off; the tests and the
//! report compare the two to show that skipping pays and costs nothing.

mod auto;
mod budget;
mod build;
mod decision;
mod inputs;
mod law;
mod montecarlo;
mod outputs;
pub mod population;
mod preview;
mod program;
mod sphere;
mod topography;
pub mod validity;
mod wet;

pub use budget::{
    Budget, Share, CALIBRATED_MIN_RTOL, REFERENCE_RTOL, RTOL_RANGE, SPHERE_TOLERANCE_RANGE,
    START_TAIL_FRACTION, TABLE_TOLERANCE_FRACTION,
};
pub use decision::{Decision, Evaluation, LawReason, OutputReason, StartReason};
pub use inputs::{CalibrationInput, Inputs, Pending};
pub use law::{check_calibrated_rtol, FullSolver, LawChoice, LawFacts};
pub use montecarlo::McPlan;
pub use outputs::accuracy_of;
use outputs::{outputs, resistance};
pub use preview::Preview;
pub use program::start_of;
use program::{program, tabulation};
pub use sphere::SpherePlan;
pub use topography::TopographyPlan;

use crate::electrical::{Heating, ResistanceObservables, Switch};
use crate::error::{Error, Result};
use crate::gw::{Accuracy, GwModel, RoughSurface};
use crate::heights::HeightDistribution;
use crate::law::interpolated::InterpolatedLaw;
use crate::law::LawKernels;
use crate::loading::LoadingModel;
use crate::material::plastic::Plasticity;
use crate::material::AsperityContact;
use crate::study::quantity::{Quantity, QuantitySet};
use crate::study::scene::{ProgramTarget, Scene};
use std::fmt;
use std::path::Path;
use std::sync::Arc;

/// Deepest separation assumed for the table of a max-load program (in
/// height scales below the start); interferences beyond it fall back to the
/// exact law, so the guess costs speed, never accuracy.
pub const MAX_LOAD_TABLE_DEPTH: f64 = 10.0;

/// How much the planner may skip.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlanMode {
    /// Skip everything the scene does not need (the default).
    Planned,
    /// Compute everything with the most exact methods: every output, the
    /// exact law, quadrature everywhere, both legs, the full range.
    EverythingOn,
}

/// Where the approach stops.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Target {
    /// A closest separation (m).
    Separation(f64),
    /// A maximum compressive load (N); the separation is solved for.
    Load(f64),
}

/// A planned study: everything needed to run it, and the reasons.
#[derive(Debug, Clone)]
pub struct Plan {
    /// The scene planned.
    pub scene: Scene,
    /// The mode it was planned in.
    pub mode: PlanMode,
    /// The splits of the scene's tolerance.
    pub budget: Budget,
    /// The asperity contact (summit radius, E*, adhesion).
    pub contact: AsperityContact,
    /// The surface statistics.
    pub surface: RoughSurface,
    /// The height distribution.
    pub distribution: Arc<dyn HeightDistribution>,
    /// The law.
    pub law: LawChoice,
    /// The full-solver (calibrated) law the model error of an analytic
    /// adhesive law is measured against (`accuracy.model_error`).
    pub reference: Option<Arc<dyn LawKernels>>,
    /// The quantities of the run's states (load, area, count, the
    /// resistance with `[electrical]`, ...) and the observables the curve
    /// totals for them (load also when only the hysteresis energy needs
    /// it).
    pub quantities: QuantitySet,
    /// Integration accuracy and method.
    pub accuracy: Accuracy,
    /// Separation where the program starts and ends (m).
    pub start: f64,
    /// Where the approach stops.
    pub target: Target,
    /// Points per leg.
    pub points: usize,
    /// The Chebyshev table to build for the run: interference interval (m)
    /// and relative tolerance.
    pub tabulation: Option<((f64, f64), f64)>,
    /// Whether the retraction leg is computed (otherwise copied from the
    /// approach: the law has no hysteresis).
    pub compute_retraction: bool,
    /// Whether the pull-off force is searched for.
    pub pull_off: bool,
    /// Whether the hysteresis energy is integrated.
    pub hysteresis_energy: bool,
    /// The explicit random population, when the scene asks for one.
    pub montecarlo: Option<McPlan>,
    /// The populations whose pull-offs give the pull-off distribution, or
    /// why there are none.
    pub pull_off_population:
        std::result::Result<population::PopulationPlan, population::NoPopulation>,
    /// The decisions, in order.
    pub decisions: Vec<Decision>,
    /// Plastic data of the yielding body, when the materials give it.
    pub plasticity: Option<Plasticity>,
    /// The states listed in `[program]` (`separations` or `loads`).
    pub listed: Option<ProgramTarget>,
    /// The contact resistance's observables, with `[electrical]`.
    pub resistance: Option<ResistanceObservables>,
    /// The switch spring, with `[switch]`.
    pub switch: Option<Switch>,
    /// The current (A) and Holm's heating relation, with
    /// `electrical.current`.
    pub heating: Option<(f64, Heating)>,
    /// Where the scene lies outside a model's validity, found while
    /// planning (the run adds its own, [`crate::study::Results::warnings`]);
    /// the summary lists both.
    pub warnings: Vec<crate::study::Warning>,
    /// The measured map, when the scene has `[surface] topography`.
    pub topography: Option<TopographyPlan>,
    /// The rough sphere, when the scene has `[sphere]`: every total is
    /// then over the bump, and separations are remote.
    pub sphere: Option<SpherePlan>,
}

/// A refusal with the measured map's warnings appended (a height unit
/// that is probably wrong explains most refusals of a measured scene).
fn with_map_warnings(e: Error, inputs: &Inputs) -> Error {
    let warnings = inputs.map.as_ref().map_or(&[][..], |r| &r.warnings[..]);
    match e {
        Error::Invalid { name, reason } if !warnings.is_empty() => Error::Invalid {
            name,
            reason: format!(
                "{reason}; note: {}",
                warnings
                    .iter()
                    .map(ToString::to_string)
                    .collect::<Vec<_>>()
                    .join("; ")
            ),
        },
        other => other,
    }
}

impl Plan {
    /// Gathers the scene's expensive inputs ([`Inputs::gather`]: a measured
    /// map is read, a `calibrated` law's calibration taken from the cache
    /// or computed) and plans it in `mode`: the start of a run. Map paths
    /// are relative to the working directory ([`Plan::new_in`] takes the
    /// scene file's directory).
    ///
    /// # Errors
    /// Whatever the scene's values make impossible (validated again here),
    /// naming the scene field.
    pub fn new(scene: &Scene, mode: PlanMode) -> Result<Plan> {
        Plan::new_in(scene, mode, Path::new("."))
    }

    /// As [`Plan::new`] for a scene read from a file in `base_dir`: a
    /// `[surface] topography` path is relative to it.
    ///
    /// # Errors
    /// As [`Plan::new`], and [`Inputs::gather`].
    pub fn new_in(scene: &Scene, mode: PlanMode, base_dir: &Path) -> Result<Plan> {
        scene.validate()?;
        let inputs = Inputs::gather(scene, base_dir)
            .map_err(|e| crate::study::scene::map_derived(scene, e))?;
        Plan::decide(scene, mode, &inputs)
    }

    /// Plans `scene` in `mode` from its gathered `inputs`: decisions only,
    /// nothing expensive runs here.
    ///
    /// # Errors
    /// As [`Plan::new`].
    pub fn decide(scene: &Scene, mode: PlanMode, inputs: &Inputs) -> Result<Plan> {
        Plan::build(scene, mode, inputs)
            .map_err(|e| crate::study::scene::map_derived(scene, e))
            .and_then(validity::checked)
            .map_err(|e| with_map_warnings(e, inputs))
    }

    /// What `asperity run --plan` shows, without running anything
    /// expensive or writing anything: the plan when its inputs are at hand
    /// ([`Inputs::at_hand`]); for an uncached calibration, the plan with
    /// Maugis–Dugdale at the same `lambda` standing in for the range
    /// decisions; for a measured map, what is decided when it is read.
    ///
    /// # Errors
    /// As [`Plan::new`].
    pub fn preview(scene: &Scene, mode: PlanMode) -> Result<Preview> {
        Plan::preview_in(scene, mode, Path::new("."))
    }

    /// As [`Plan::preview`] for a scene read from a file in `base_dir`.
    ///
    /// # Errors
    /// As [`Plan::new`].
    pub fn preview_in(scene: &Scene, mode: PlanMode, base_dir: &Path) -> Result<Preview> {
        scene.validate()?;
        let at_hand = Inputs::at_hand(scene, base_dir)
            .map_err(|e| crate::study::scene::map_derived(scene, e))?;
        Ok(match at_hand {
            Ok(inputs) => Preview::Ready(Box::new(Plan::decide(scene, mode, &inputs)?)),
            Err(pending @ Pending::Calibration { .. }) => Preview::Provisional(
                Box::new(Plan::decide(scene, mode, &Inputs::default())?),
                pending,
            ),
            Err(pending) => Preview::Pending {
                title: scene.title.clone(),
                mode,
                pending,
                decisions: topography::preview_decisions(scene)?,
            },
        })
    }

    /// This plan with one more quantity of the states: its column in
    /// `curve.csv`, its key in the listed states, its headline number in
    /// the summary and the sweep's results follow.
    ///
    /// # Errors
    /// When the curve's observables have no free slot for it
    /// ([`crate::loading::Observables::with`]).
    pub fn with_quantity(mut self, q: Quantity) -> Result<Plan> {
        self.quantities = self.quantities.with(q)?;
        Ok(self)
    }

    /// The law the run evaluates: the plan's law, or its Chebyshev table
    /// when the plan decided to tabulate it.
    ///
    /// # Errors
    /// As [`InterpolatedLaw::new`].
    pub fn run_law(&self) -> Result<Arc<dyn LawKernels>> {
        Ok(match self.tabulation {
            Some(((lo, hi), tol)) => {
                Arc::new(InterpolatedLaw::new(self.law.law.clone(), lo, hi, tol)?)
            }
            None => self.law.law.clone(),
        })
    }

    /// The rough-surface model of this plan with `law` (see [`Plan::run_law`]).
    ///
    /// # Errors
    /// As [`GwModel::new`].
    pub fn model_with(&self, law: Arc<dyn LawKernels>) -> Result<GwModel> {
        Ok(
            GwModel::new(self.surface, self.distribution.clone(), law)?
                .with_accuracy(self.accuracy),
        )
    }

    /// The closest separation (m): given, or solved from the maximum load on
    /// approach ([`LoadingModel::separation_at_load`]: the load met to `rtol`).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `program.max_load` when the load is not
    /// reached.
    pub fn closest_separation(&self, model: &impl LoadingModel) -> Result<f64> {
        match self.target {
            Target::Separation(d) => Ok(d),
            Target::Load(p) => model
                .separation_at_load(p, self.start)
                .map_err(|e| self.blame_target(e)),
        }
    }

    /// The scene key that sets how far the program goes, as the user wrote
    /// it: `program.loads` or `program.separations` for listed states,
    /// `program.max_load` or `program.closest_separation` otherwise.
    pub fn target_field(&self) -> &'static str {
        match (&self.target, &self.listed) {
            (Target::Load(_), Some(ProgramTarget::Loads(_))) => "program.loads",
            (Target::Load(_), _) => "program.max_load",
            (_, Some(ProgramTarget::Separations(_))) => "program.separations",
            _ => "program.closest_separation",
        }
    }

    /// An error of the separation-at-a-load search (naming the core's
    /// `max_load`) renamed to [`Plan::target_field`]; other fields put in
    /// `[program]`.
    pub(crate) fn blame_target(&self, e: crate::Error) -> crate::Error {
        if e.field() == Some("max_load") {
            e.renamed(self.target_field())
        } else {
            e.in_table("program")
        }
    }
}

impl fmt::Display for Plan {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let title = self.scene.title.as_deref().unwrap_or("untitled scene");
        let mode = match self.mode {
            PlanMode::Planned => "what the scene needs",
            PlanMode::EverythingOn => "everything on, most exact methods",
        };
        writeln!(f, "plan for {title} ({mode})")?;
        for d in &self.decisions {
            writeln!(f, "  {:<18} {:<24} {}", d.topic(), d.choice(), d.why())?;
        }
        Ok(())
    }
}
