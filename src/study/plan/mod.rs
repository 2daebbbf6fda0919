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

mod budget;
mod decision;
mod inputs;
mod law;
mod montecarlo;
mod preview;
mod topography;

pub use budget::{Budget, Share, START_TAIL_FRACTION, TABLE_TOLERANCE_FRACTION};
pub use decision::{Decision, Evaluation, LawReason, OutputReason, StartReason};
pub use inputs::{CalibrationInput, Inputs, Pending};
pub use law::LawChoice;
pub use montecarlo::McPlan;
pub use preview::Preview;
pub use topography::TopographyPlan;

use crate::electrical::{Heating, Interaction, ResistanceObservables, Switch};
use crate::error::{Error, Result};
use crate::gw::{Accuracy, GwModel, Method, RoughSurface};
use crate::heights::HeightDistribution;
use crate::law::interpolated::InterpolatedLaw;
use crate::law::AsperityLaw;
use crate::loading::{LoadingModel, Observables};
use crate::material::plastic::Plasticity;
use crate::material::AsperityContact;
use crate::study::quantity::{Quantity, QuantitySet};
use crate::study::scene::{
    build_contact, build_distribution, build_surface, LawName, ProgramTarget, Scene,
};
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
    pub warnings: Vec<String>,
    /// The measured map, when the scene has `[surface] topography`.
    pub topography: Option<TopographyPlan>,
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
            .and_then(crate::study::validity::checked)
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

    fn build(scene: &Scene, mode: PlanMode, inputs: &Inputs) -> Result<Plan> {
        scene.validate()?;
        let resolved = inputs.map.as_ref();
        let scene = resolved.map_or(scene, |r| &r.scene);
        let contact = build_contact(scene)?;
        let surface = build_surface(scene)?;
        let distribution = build_distribution(&scene.surface)?;
        let mut decisions = Vec::new();
        let budget = Budget::new(scene.accuracy.rtol);
        let law = law::choose(
            scene,
            &contact,
            mode,
            inputs.calibration.as_ref(),
            &mut decisions,
        )?;
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
        let model = GwModel::new(surface, distribution.clone(), law.law.clone())?;
        let (observables, accuracy) = outputs(scene, mode, &model, &law, &mut decisions)?;
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
        let mut warnings = Vec::new();
        let plasticity = scene.plasticity()?;
        if let Some(p) = plasticity {
            let psi = surface
                .plasticity_index(contact.contact_modulus, p.hardness())
                .map_err(|e| e.in_table("materials"))?;
            let plastic_law = matches!(law.source, LawName::Plastic(_));
            decisions.push(Decision::Plasticity {
                psi,
                hardness: p.hardness(),
                plastic_law,
            });
            if !plastic_law {
                warnings.extend(crate::law::plastic::elastic_law_warning(&law.name, psi));
            }
        }
        let model = model.with_accuracy(accuracy);
        let (target, start, listed) = program(scene, mode, &model, &mut decisions)?;
        let tabulation = tabulation(&law, &model, start, target, &budget, mode);
        if let Some((interval, tolerance)) = tabulation {
            decisions.push(Decision::Tabulation {
                law: law.name.clone(),
                tolerance,
                interval,
            });
        }
        let hysteresis_free = !law.law.has_history();
        let compute_retraction = mode == PlanMode::EverythingOn || !hysteresis_free;
        decisions.push(Decision::Retraction {
            computed: compute_retraction,
            hysteresis: (!hysteresis_free)
                .then(|| (law.law.attach_interference(), law.law.detach_interference())),
            law: law.name.clone(),
        });
        let o = scene.outputs;
        let adhesive = contact.adhesion.work() > 0.0;
        let pull_off = o.pull_off && (adhesive || mode == PlanMode::EverythingOn);
        decisions.push(Decision::PullOff {
            searched: pull_off,
            asked: o.pull_off || mode == PlanMode::EverythingOn,
            adhesive,
        });
        let hysteresis_energy = o.hysteresis_energy || mode == PlanMode::EverythingOn;
        decisions.push(Decision::HysteresisEnergy {
            computed: hysteresis_energy,
        });
        let montecarlo = match &scene.montecarlo {
            Some(spec) => {
                let mc = McPlan::new(spec, &surface, &contact, &law)?;
                decisions.push(Decision::MonteCarlo {
                    summits: mc.summits,
                    seed: spec.seed,
                    distribution: distribution.name().into(),
                    radius_log_std: spec.radius_log_std,
                    factor: mc.factor,
                });
                Some(mc)
            }
            None => None,
        };
        Ok(Plan {
            scene: scene.clone(),
            mode,
            budget,
            montecarlo,
            contact,
            surface,
            distribution,
            law,
            quantities,
            accuracy,
            start,
            target,
            points: scene.program.points,
            tabulation,
            compute_retraction,
            pull_off,
            hysteresis_energy,
            decisions,
            plasticity,
            listed,
            resistance,
            switch: match &scene.switch {
                Some(s) => Some(
                    Switch::new(s.spring_constant, s.travel).map_err(|e| e.in_table("switch"))?,
                ),
                None => None,
            },
            heating,
            warnings,
            topography,
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
    pub fn run_law(&self) -> Result<Arc<dyn AsperityLaw>> {
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
    pub fn model_with(&self, law: Arc<dyn AsperityLaw>) -> Result<GwModel> {
        Ok(
            GwModel::new(self.surface, self.distribution.clone(), law)?
                .with_accuracy(self.accuracy),
        )
    }

    /// The closest separation (m): given, or solved from the maximum load on
    /// approach ([`LoadingModel::separation_at_load`] to `rtol * sigma`).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `program.max_load` when the load is not
    /// reached.
    pub fn closest_separation(&self, model: &impl LoadingModel) -> Result<f64> {
        match self.target {
            Target::Separation(d) => Ok(d),
            Target::Load(p) => model
                .separation_at_load(p, self.start)
                .map_err(|e| e.in_table("program")),
        }
    }
}

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
fn program(
    scene: &Scene,
    mode: PlanMode,
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
        (None, _) => start_of(model, &Budget::new(scene.accuracy.rtol), mode),
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

/// The contact resistance's observables and decision, with `[electrical]`.
fn resistance(
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
    });
    Ok(Some(ResistanceObservables::new(
        spot,
        interaction,
        surface.nominal_area.sqrt(),
    )))
}

/// The integration accuracy of `model`: the budget's tolerance, closed
/// forms where the law and the distribution have them (everything on:
/// quadrature everywhere).
///
/// # Errors
/// [`Error::OutOfRange`] naming `accuracy.rtol`.
pub fn accuracy_of(model: &GwModel, budget: &Budget, mode: PlanMode) -> Result<Accuracy> {
    let closed = model.has_closed_form(&Observables::ALL);
    let method = if closed && mode == PlanMode::Planned {
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
fn outputs(
    scene: &Scene,
    mode: PlanMode,
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
    let accuracy = accuracy_of(model, &Budget::new(scene.accuracy.rtol), mode)?;
    let method = accuracy.method;
    let distribution = model.distribution();
    let evaluation = if distribution.sample_points().is_some() && !closed {
        Evaluation::SampleSum
    } else if method == Method::Auto {
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
                    rtol: scene.accuracy.rtol,
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

/// The table of an expensive law ([`LawKind::worth_tabulating`](crate::law::LawKind::worth_tabulating)):
/// the interference interval the program reaches ([`GwModel::reachable_interferences`])
/// and the table's tolerance; `None` when not worth it.
fn tabulation(
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

impl fmt::Display for Plan {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let title = self.scene.title.as_deref().unwrap_or("untitled scene");
        writeln!(f, "plan for {title} ({:?})", self.mode)?;
        for d in &self.decisions {
            writeln!(f, "  {:<18} {:<24} {}", d.topic(), d.choice(), d.why())?;
        }
        Ok(())
    }
}
