//! The planner: turns a [`Scene`] into a [`Plan`] — which law, which method
//! serves each output and why, and what is skipped.
//!
//! What a plan skips, and why each skip costs nothing:
//! - outputs not asked for are not computed (the integrator's masks);
//! - adhesion machinery when `w = 0` (Hertz, no hysteresis);
//! - the retraction leg when the law has no hysteresis
//!   (attach = detach interference): it equals the approach leg, so it is
//!   copied, not recomputed;
//! - separations where no asperity is in range: the program starts where
//!   the summits beyond the flat's reach carry less than `rtol / 100` of
//!   the probability (see [`start_separation`]);
//! - quadrature where closed forms `F_n` exist (Hertz/DMT on Gaussian or
//!   exponential heights);
//! - the exact Maugis–Dugdale law when a cheaper law meets the tolerance at
//!   this Tabor parameter ([`crate::law::errors`], measured against the full
//!   Lennard-Jones solution).
//!
//! [`PlanMode::EverythingOn`] switches every skip off; the tests and the
//! report compare the two to show that skipping pays and costs nothing.

use super::build::{build_contact, build_distribution, build_surface};
use super::schema::{MonteCarloSpec, Scene};
use crate::error::{Error, Result};
use crate::gw::{Accuracy, GwModel, History, Method, Outputs, RoughSurface};
use crate::heights::HeightDistribution;
use crate::law::errors::LawErrorTable;
use crate::law::interpolated::InterpolatedLaw;
use crate::law::{AsperityLaw, LawKind};
use crate::material::AsperityContact;
use crate::montecarlo::{PopulationSpec, RadiusSpec, SummitLaw, MAX_SUMMITS};
use crate::numeric::roots::brent;
use std::fmt;
use std::sync::Arc;

/// How much the planner may skip.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlanMode {
    /// Skip everything the scene does not need (the default).
    Planned,
    /// Compute everything with the most exact methods: every output, the
    /// exact law, quadrature everywhere, both legs, the full range.
    EverythingOn,
}

/// One decision of the plan: what is done, how, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct Decision {
    /// What the decision is about (`"law"`, `"load"`, `"retraction"`, ...).
    pub what: String,
    /// The choice (`"jkr"`, `"closed form F_n"`, `"skipped"`, ...).
    pub choice: String,
    /// Why.
    pub why: String,
}

/// The law a plan uses.
#[derive(Debug, Clone)]
pub struct LawChoice {
    /// Its name (`"hertz"`, `"maugis"`, ...).
    pub name: String,
    /// The built law.
    pub law: Arc<dyn AsperityLaw>,
    /// The law's measured error against the full Lennard-Jones solution at
    /// this Tabor parameter (relative, from [`LawErrorTable`]), if known.
    pub measured_error: Option<f64>,
}

/// The Monte Carlo part of a plan.
#[derive(Debug, Clone)]
pub struct McPlan {
    /// The scene's request.
    pub spec: MonteCarloSpec,
    /// Summits drawn.
    pub summits: usize,
    /// `eta A_n / summits`: totals are multiplied by it.
    pub factor: f64,
    /// The per-summit law (the plan's law; rescaled per radius with a
    /// radius spread).
    pub law: SummitLaw,
}

impl McPlan {
    fn new(
        spec: &MonteCarloSpec,
        surface: &RoughSurface,
        contact: &AsperityContact,
        law: &LawChoice,
    ) -> Result<McPlan> {
        let expected = surface.summits();
        let summits = match spec.summits {
            Some(n) => n,
            None => {
                if !(expected >= 0.5 && expected <= MAX_SUMMITS as f64) {
                    return Err(Error::invalid(
                        "montecarlo.summits",
                        format!(
                            "eta A_n = {expected:e} summits is not a population size in 1 ..= {MAX_SUMMITS}; \
                             give montecarlo.summits"
                        ),
                    ));
                }
                expected.round() as usize
            }
        };
        let summit_law = if spec.radius_log_std == 0.0 {
            SummitLaw::fixed(law.law.clone(), contact.radius)?
        } else {
            let kind = LawKind::parse(&law.name)
                .ok()
                .filter(|k| matches!(k, LawKind::Hertz | LawKind::Dmt | LawKind::Jkr))
                .ok_or_else(|| {
                    Error::invalid(
                        "montecarlo.radius_log_std",
                        format!(
                            "a radius spread needs a law that scales with R (hertz, dmt, jkr), not {}",
                            law.name
                        ),
                    )
                })?;
            SummitLaw::from_kind(kind, contact)?
        };
        Ok(McPlan {
            spec: *spec,
            summits,
            factor: expected / summits as f64,
            law: summit_law,
        })
    }

    /// The population spec (heights scale `sigma`, radii, seed).
    ///
    /// # Errors
    /// Bad values, naming the `montecarlo.` field.
    pub fn population_spec(&self, surface: &RoughSurface) -> Result<PopulationSpec> {
        let radius = if self.spec.radius_log_std > 0.0 {
            RadiusSpec::LogNormal {
                median: surface.radius,
                log_std: self.spec.radius_log_std,
            }
        } else {
            RadiusSpec::Fixed(surface.radius)
        };
        PopulationSpec::new(self.summits, surface.sigma, radius, self.spec.seed)
            .map_err(|e| e.in_table("montecarlo"))
    }
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
    /// The asperity contact (summit radius, E*, adhesion).
    pub contact: AsperityContact,
    /// The surface statistics.
    pub surface: RoughSurface,
    /// The height distribution.
    pub distribution: Arc<dyn HeightDistribution>,
    /// The law.
    pub law: LawChoice,
    /// Outputs computed on the curve (load also when only the hysteresis
    /// energy needs it).
    pub curve_outputs: Outputs,
    /// Integration accuracy and method.
    pub accuracy: Accuracy,
    /// Separation where the program starts and ends (m).
    pub start: f64,
    /// Where the approach stops.
    pub target: Target,
    /// Points per leg.
    pub points: usize,
    /// Whether the retraction leg is computed (otherwise copied from the
    /// approach: the law has no hysteresis).
    pub compute_retraction: bool,
    /// Whether the pull-off force is searched for.
    pub pull_off: bool,
    /// Whether the hysteresis energy is integrated.
    pub hysteresis_energy: bool,
    /// The explicit random population, when the scene asks for one.
    pub montecarlo: Option<McPlan>,
    /// The decisions, in order, for printing.
    pub decisions: Vec<Decision>,
}

impl Plan {
    /// Plans `scene` in `mode`.
    ///
    /// # Errors
    /// Whatever the scene's values make impossible (validated again here),
    /// naming the scene field.
    pub fn new(scene: &Scene, mode: PlanMode) -> Result<Plan> {
        scene.validate()?;
        let contact = build_contact(scene)?;
        let surface = build_surface(scene)?;
        let distribution = build_distribution(&scene.surface)?;
        let mut decisions = Vec::new();
        let mut decide = |what: &str, choice: String, why: String| {
            decisions.push(Decision {
                what: what.into(),
                choice,
                why,
            })
        };
        let rtol = scene.accuracy.rtol;
        let law = choose_law(scene, &contact, mode, &mut decide)?;

        // Method per output.
        let o = scene.outputs;
        let curve_outputs = Outputs {
            load: o.load || o.hysteresis_energy || mode == PlanMode::EverythingOn,
            area: o.area || mode == PlanMode::EverythingOn,
            count: o.count || mode == PlanMode::EverythingOn,
        };
        let closed = law.law.power_form().is_some_and(|f| {
            f.load
                .iter()
                .chain(&f.area)
                .all(|&(_, n)| distribution.closed_form_moment(n))
                && distribution.closed_form_moment(0.0)
        });
        let method = match (mode, closed) {
            (PlanMode::Planned, true) => Method::Auto,
            _ => Method::Quadrature,
        };
        let accuracy = Accuracy::new(rtol)
            .map_err(|e| e.renamed("accuracy.rtol"))?
            .with_method(method);
        let how = if distribution.sample_points().is_some() && !closed {
            (
                "exact sum over the sample".to_string(),
                format!(
                    "{} heights are a finite sample: the totals are exact averages over the measured summits",
                    distribution.name()
                ),
            )
        } else if method == Method::Auto {
            (
                "closed form F_n".to_string(),
                format!(
                    "{} is a sum of powers and {} heights have closed-form F_n: exact to ~1e-13, no quadrature",
                    law.name,
                    distribution.name()
                ),
            )
        } else if closed {
            (
                "adaptive Gauss-Kronrod".to_string(),
                "everything-on mode: quadrature even where closed forms exist".to_string(),
            )
        } else {
            (
                "adaptive Gauss-Kronrod".to_string(),
                format!(
                    "no closed form for {} on {} heights; error controlled to rtol = {rtol:e} of int |integrand|",
                    law.name,
                    distribution.name()
                ),
            )
        };
        for (name, asked, needed) in [
            ("load", o.load, curve_outputs.load),
            ("area", o.area, curve_outputs.area),
            ("count", o.count, curve_outputs.count),
        ] {
            if needed {
                let why = if asked {
                    how.1.clone()
                } else if mode == PlanMode::EverythingOn {
                    "everything-on mode".to_string()
                } else {
                    "not asked for, but the hysteresis energy needs it".to_string()
                };
                decide(name, how.0.clone(), why);
            } else {
                decide(name, "skipped".into(), "not asked for in [outputs]".into());
            }
        }

        // The program.
        let model = GwModel::new(surface, distribution.clone(), law.law.clone())?;
        let target = match (scene.program.closest_separation, scene.program.max_load) {
            (Some(d), _) => Target::Separation(d),
            (None, Some(p)) => Target::Load(p),
            (None, None) => return Err(Error::invalid("program", "no target")),
        };
        let start = match scene.program.start_separation {
            Some(s) => {
                decide(
                    "start separation",
                    format!("{s:e} m"),
                    "given in the scene".into(),
                );
                s
            }
            None => {
                let (s, why) = match mode {
                    PlanMode::Planned => (
                        start_separation(&model, rtol),
                        format!(
                            "summits beyond the flat's reach there carry < rtol/100 = {:e} of the heights: \
                             separations above it are skipped",
                            rtol / 100.0
                        ),
                    ),
                    PlanMode::EverythingOn => (
                        model.interaction_onset(),
                        "everything-on mode: from the last representable summit height".into(),
                    ),
                };
                decide("start separation", format!("{s:e} m"), why);
                s
            }
        };
        if let Target::Separation(d) = target {
            if !(start > d) {
                return Err(Error::OutOfRange {
                    name: "program.closest_separation".into(),
                    value: d,
                    allowed: crate::error::Allowed::open(f64::NEG_INFINITY, start),
                });
            }
        }

        let law = tabulate_if_worth_it(law, &model, start, target, rtol, mode, &mut decide)?;
        let hysteresis_free = law.law.attach_interference() == law.law.detach_interference();
        let compute_retraction = mode == PlanMode::EverythingOn || !hysteresis_free;
        if compute_retraction {
            decide(
                "retraction",
                "computed".into(),
                if hysteresis_free {
                    "everything-on mode".into()
                } else {
                    format!(
                        "{} asperities attach at {:.3e} m and detach at {:.3e} m: hysteresis",
                        law.name,
                        law.law.attach_interference(),
                        law.law.detach_interference()
                    )
                },
            );
        } else {
            decide(
                "retraction",
                "copied from approach".into(),
                format!(
                    "{} has no hysteresis (attach = detach interference)",
                    law.name
                ),
            );
        }
        let adhesive = contact.adhesion.work() > 0.0;
        let pull_off = o.pull_off && (adhesive || mode == PlanMode::EverythingOn);
        decide(
            "pull-off",
            if pull_off { "searched" } else { "skipped" }.into(),
            if !o.pull_off && mode == PlanMode::Planned {
                "not asked for in [outputs]".into()
            } else if !adhesive && mode == PlanMode::Planned {
                "w = 0: no adhesion, no tensile load".into()
            } else {
                "sampled retraction curve, then golden-section refinement to rtol * sigma".into()
            },
        );
        let hysteresis_energy = o.hysteresis_energy || mode == PlanMode::EverythingOn;
        decide(
            "hysteresis energy",
            if hysteresis_energy {
                "trapezoid on the program"
            } else {
                "skipped"
            }
            .into(),
            if hysteresis_energy {
                "int (P_approach - P_retract) dd over the program's separations".into()
            } else {
                "not asked for in [outputs]".into()
            },
        );
        let montecarlo = match &scene.montecarlo {
            Some(spec) => {
                let mc = McPlan::new(spec, &surface, &contact, &law)?;
                decide(
                    "montecarlo",
                    format!("{} summits, seed {}", mc.summits, spec.seed),
                    format!(
                        "drawn from the {} heights{}, summed exactly with each summit's attach/detach \
                         state; compared point by point with the integral in standard errors{}",
                        distribution.name(),
                        if spec.radius_log_std > 0.0 {
                            format!(", lognormal radii (log std {})", spec.radius_log_std)
                        } else {
                            String::new()
                        },
                        if mc.factor != 1.0 {
                            format!("; totals scaled by {:.4} to the whole surface", mc.factor)
                        } else {
                            String::new()
                        }
                    ),
                );
                Some(mc)
            }
            None => None,
        };
        let plan = Plan {
            scene: scene.clone(),
            mode,
            montecarlo,
            contact,
            surface,
            distribution,
            law,
            curve_outputs,
            accuracy,
            start,
            target,
            points: scene.program.points,
            compute_retraction,
            pull_off,
            hysteresis_energy,
            decisions,
        };
        Ok(plan)
    }

    /// The rough-surface model of this plan.
    ///
    /// # Errors
    /// As [`GwModel::new`].
    pub fn model(&self) -> Result<GwModel> {
        GwModel::new(
            self.surface,
            self.distribution.clone(),
            self.law.law.clone(),
        )
    }

    /// The closest separation (m): given, or solved from the maximum load on
    /// approach by Brent's method to `rtol * sigma`.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `program.max_load` when no separation
    /// above `-50 sigma` reaches the load.
    pub fn closest_separation(&self, model: &GwModel) -> Result<f64> {
        let p_max = match self.target {
            Target::Separation(d) => return Ok(d),
            Target::Load(p) => p,
        };
        let sigma = self.surface.sigma;
        let load = |d: f64| -> Result<f64> {
            Ok(model
                .state(d, History::Approach, Outputs::LOAD, &self.accuracy)?
                .load
                .unwrap_or(0.0))
        };
        let mut hi = self.start;
        let mut lo = hi - sigma;
        while load(lo)? < p_max {
            hi = lo;
            lo -= sigma;
            if lo < -50.0 * sigma {
                return Err(Error::invalid(
                    "program.max_load",
                    format!("{p_max:e} N is not reached on approach above d = -50 sigma"),
                ));
            }
        }
        let mut failure = None;
        let root = brent(
            |d| match load(d) {
                Ok(p) => p - p_max,
                Err(e) => {
                    failure = Some(e);
                    f64::NAN
                }
            },
            lo,
            hi,
            self.accuracy.rel_tol * sigma,
        );
        if let Some(e) = failure {
            return Err(e);
        }
        root.ok_or_else(|| Error::invalid("program.max_load", "could not bracket the load"))
    }
}

/// Laws whose exact evaluation is expensive enough that a Chebyshev table
/// pays for itself on a curve (an exact Maugis–Dugdale state costs ~1 us,
/// a table lookup ~20 ns; the table costs a few thousand exact states).
const TABULATE: [&str; 2] = ["maugis", "cos"];

/// Replaces an expensive law by an [`InterpolatedLaw`] accurate to
/// `rtol / 10` over the interferences the program can reach.
fn tabulate_if_worth_it(
    law: LawChoice,
    model: &GwModel,
    start: f64,
    target: Target,
    rtol: f64,
    mode: PlanMode,
    decide: &mut impl FnMut(&str, String, String),
) -> Result<LawChoice> {
    if mode == PlanMode::EverythingOn || !TABULATE.contains(&law.name.as_str()) {
        return Ok(law);
    }
    let sigma = model.surface().sigma;
    let (_, s_top) = model.distribution().numerical_support(1e-300);
    // Deepest separation: given, or (max-load programs) a generous guess;
    // interferences beyond the table fall back to the exact law.
    let d_min = match target {
        Target::Separation(d) => d,
        Target::Load(_) => start - 10.0 * sigma,
    };
    let lo = law.law.cutoff_interference().max(-10.0 * sigma);
    let hi = sigma * s_top.min(40.0) - d_min;
    if !(hi > lo) {
        return Ok(law);
    }
    let table = InterpolatedLaw::new(law.law.clone(), lo, hi, rtol / 10.0)?;
    let (pa, pr) = table.panels();
    decide(
        "law evaluation",
        format!("Chebyshev table, {} panels", pa + pr),
        format!(
            "exact {} replaced by degree-6 Chebyshev interpolants to rtol/10 = {:e} on [{lo:.3e}, {hi:.3e}] m \
             ({} exact evaluations to build; exact law outside)",
            law.name,
            rtol / 10.0,
            table.build_evaluations()
        ),
    );
    Ok(LawChoice {
        law: Arc::new(table),
        ..law
    })
}

/// Default start of the program (m): the separation `d` beyond which the
/// summits the flat can reach (`z > d + cutoff`) make up less than
/// `rtol / 100` of all summits, i.e. `sigma q(1 - rtol/100) - cutoff`.
pub fn start_separation(model: &GwModel, rtol: f64) -> f64 {
    let s = model.distribution().quantile(1.0 - rtol / 100.0);
    let top = model.interaction_onset();
    (model.surface().sigma * s - model.law().cutoff_interference()).min(top)
}

/// Picks the law: the scene's, or for `auto` the cheapest law whose
/// measured error meets `rtol` at this Tabor parameter.
fn choose_law(
    scene: &Scene,
    contact: &AsperityContact,
    mode: PlanMode,
    decide: &mut impl FnMut(&str, String, String),
) -> Result<LawChoice> {
    let mu = contact.tabor();
    let rtol = scene.accuracy.rtol;
    let table = LawErrorTable::embedded();
    let w = contact.adhesion.work();
    let kind_name = scene.law.kind.as_str();
    if kind_name == "calibrated" && w > 0.0 {
        return calibrated_law(contact, decide);
    }
    let (kind, why) = if w == 0.0 {
        if !matches!(kind_name, "auto" | "hertz") {
            return Err(Error::invalid(
                "law.kind",
                format!(
                    "{kind_name:?} needs adhesion, but adhesion.w = 0 (use \"hertz\" or \"auto\")"
                ),
            ));
        }
        (
            LawKind::Hertz,
            "adhesion.w = 0: no adhesion machinery, Hertz asperities".to_string(),
        )
    } else if kind_name == "auto" && mode == PlanMode::EverythingOn {
        (
            LawKind::Maugis,
            "everything-on mode: the exact Maugis-Dugdale law".to_string(),
        )
    } else if kind_name == "auto" {
        match table.cheapest_within(mu, rtol) {
            Some((k, err)) => (
                k,
                format!(
                    "cheapest law within rtol = {rtol:e} of the full Lennard-Jones solution at mu = {mu:.4} \
                     (measured error {err:.2e}; {})",
                    table.provenance_short()
                ),
            ),
            None => {
                let (k, err) = table.most_accurate(mu);
                (
                    k,
                    format!(
                        "no analytic law is within rtol = {rtol:e} of the Lennard-Jones solution at mu = {mu:.4}; \
                         {} is the closest (measured error {err:.2e}); ask for law.kind = \"calibrated\" \
                         for the full-solver law",
                        k.name()
                    ),
                )
            }
        }
    } else {
        let k = LawKind::parse(kind_name).map_err(|e| e.renamed("law.kind"))?;
        (k, "given in the scene".to_string())
    };
    let law: Arc<dyn AsperityLaw> = Arc::from(kind.build(contact)?);
    let measured_error = table.error(kind, mu);
    decide(
        "law",
        kind.name().to_string(),
        format!("{why} [mu = {mu:.4}, lambda = {:.4}]", contact.lambda()),
    );
    Ok(LawChoice {
        name: kind.name().to_string(),
        law,
        measured_error,
    })
}

/// The law calibrated from the full Lennard-Jones sphere solver at this
/// Tabor parameter (paraboloid, default resolution), from the on-disk cache
/// when it is there ([`crate::sphere::calibrate`]).
fn calibrated_law(
    contact: &AsperityContact,
    decide: &mut impl FnMut(&str, String, String),
) -> Result<LawChoice> {
    use crate::sphere::{CalibrationCache, Shape, SolverOptions, SphereProblem};
    let mu = contact.tabor();
    let problem =
        SphereProblem::new(mu, Shape::Paraboloid, SolverOptions::default()).map_err(|e| {
            Error::invalid(
                "law.kind",
                format!("\"calibrated\" needs the full solver at mu = {mu:.4}: {e}"),
            )
        })?;
    let cache = CalibrationCache::default_location();
    let cached = cache.load(&problem).is_some();
    let calibration = cache.get_or_compute(&problem)?;
    let law = calibration.law(
        contact.radius,
        contact.contact_modulus,
        contact.adhesion.work(),
    )?;
    decide(
        "law",
        "calibrated".into(),
        format!(
            "full Lennard-Jones sphere solver at mu = {mu:.4} (paraboloid), tabulated on both branches, \
             with the Lennard-Jones attraction kept out to a rigid gap of 100 z0 (the Dugdale laws cut \
             it at ~z0: on rough surfaces this tail can dominate the pull-off); {} {}",
            if cached { "read from the cache" } else { "computed and cached at" },
            cache.path_for(&problem).display()
        ),
    );
    Ok(LawChoice {
        name: "calibrated".into(),
        law: Arc::new(law),
        measured_error: None,
    })
}

impl fmt::Display for Plan {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let title = self.scene.title.as_deref().unwrap_or("untitled scene");
        writeln!(f, "plan for {title} ({:?})", self.mode)?;
        for d in &self.decisions {
            writeln!(f, "  {:<18} {:<24} {}", d.what, d.choice, d.why)?;
        }
        Ok(())
    }
}
