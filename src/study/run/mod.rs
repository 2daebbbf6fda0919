//! Executing a [`Plan`]: the loading program, pull-off and hysteresis energy.

mod auto;
mod sphere;

use super::plan::{McPlan, Plan};
use super::scene::ProgramTarget;
use crate::electrical::heating::SpotCondition;
use crate::electrical::{population_spots, Interaction, SampleResistance, Stiction, StictionOdds};
use crate::error::Result;
use crate::law::plastic::{contact_fractions, RegimeFractions};
use crate::law::LawKernels;
use crate::loading::{
    hysteresis_energy_to, Curve, History, LoadingModel, LoadingProgram, Observable, Observables,
    PullOff, State, SLOTS,
};
use crate::material::plastic::{RegimeLimits, Variant};
use crate::montecarlo::{Comparison, MonteCarlo, Population, SummitLaw};
use crate::numeric::mix::{derive_seed, Stream};
use crate::study::quantity::{QuantitySet, Record};
use crate::study::warning::{ModelErrorOutput, Warning};
use std::sync::Arc;
use std::time::Instant;

pub use crate::montecarlo::MIN_SUMMITS_FOR_Z;

/// Number of retraction samples the pull-off search starts from.
const PULL_OFF_SAMPLES: usize = 64;

/// What a run produced. Outputs not asked for are `None` (or absent from
/// the states).
#[derive(Debug, Clone)]
pub struct Results {
    /// The program's curve: approach and retraction states at the same
    /// separations (ascending; index 0 is the closest separation).
    pub curve: Curve,
    /// The curve's states with every quantity's value (the same order).
    pub records: LegRecords,
    /// Pull-off of the rough surface (most tensile retraction load), when
    /// asked for and tensile.
    pub pull_off: Option<PullOff>,
    /// Energy lost per cycle (J), when asked for.
    pub hysteresis_energy: Option<f64>,
    /// Wall-clock time of the run (s).
    pub seconds: f64,
    /// Law evaluations spent by quadrature (0 for closed forms).
    pub evaluations: usize,
    /// The explicit population's curve and its comparison with the
    /// integral, when the scene asks for one.
    pub montecarlo: Option<McResults>,
    /// The states listed in `[program]` (`separations` or `loads`), on
    /// approach, in the listed order, with every quantity's value (empty
    /// without a list).
    pub listed: Vec<Record>,
    /// Contact-regime fractions at the closest approach, when the materials
    /// give a yield strength.
    pub regimes: Option<RegimeFractions>,
    /// The switch's stiction verdict, with `[switch]` (at the confidence
    /// quantile of the populations' pull-offs when there are any).
    pub stiction: Option<Stiction>,
    /// The probability that a switch sticks, over the populations.
    pub stiction_odds: Option<StictionOdds>,
    /// For an elastic-plastic law: the approach states of the elastic law it
    /// reduces to as `psi -> 0` (JKR with adhesion, Hertz without) at the
    /// same separations, for the load–area comparison.
    pub elastic_approach: Option<Vec<State>>,
    /// Where the results lie outside a model's validity (each a sentence
    /// naming the quantity, its value and the bound).
    pub warnings: Vec<Warning>,
    /// The measured map's part (the other model's headline numbers when
    /// asked), when the scene has `[surface] topography`.
    pub topography: Option<super::measured::TopographyResults>,
    /// The pull-off distribution over populations of the surface's
    /// summits, when the pull-off is searched on a finite surface.
    pub pull_off_population: Option<super::population::PopulationResults>,
    /// The model error of the headline outputs on this surface.
    pub model_error: Option<super::model_error::ModelError>,
    /// With `[sphere]`: the bump's state at the closest approach (contact
    /// radius against Hertz's, approach, central deflection, mesh, model
    /// warnings).
    pub sphere: Option<crate::roughsphere::SphereState>,
    /// The plan these results are of when the run replaced the planned one
    /// (`law.kind = "auto"` whose analytic law missed `rtol` on the
    /// scene's surface ran again with the full-solver law); `None` when
    /// they are of the plan that was run. See [`Results::plan`].
    pub replanned: Option<Box<Plan>>,
}

/// `results` of an `auto` law that missed `rtol` on the surface, kept
/// because the full-solver law's run failed with `error`.
fn auto_failed(mut results: Results, error: crate::Error) -> Results {
    results.warnings.push(Warning::AutoLawFailed { error });
    results
}

/// The records of a curve's two legs.
#[derive(Debug, Clone, Default)]
pub struct LegRecords {
    /// Approach states (index 0 the closest separation).
    pub approach: Vec<Record>,
    /// Retraction states at the same separations.
    pub retract: Vec<Record>,
}

impl LegRecords {
    /// Both legs of `curve` through `quantities`.
    pub fn new(quantities: &QuantitySet, curve: &Curve) -> LegRecords {
        LegRecords {
            approach: quantities.records(&curve.approach),
            retract: quantities.records(&curve.retract),
        }
    }
}

/// A population summed over the program, beside the integral.
#[derive(Debug, Clone)]
pub struct McResults {
    /// The population's curve (totals scaled to the whole surface).
    pub curve: Curve,
    /// Its states with every quantity's value.
    pub records: LegRecords,
    /// Deviation from the integral in standard errors,
    /// `(x_MC - x_GW)/sqrt(SE^2 + err_GW^2)`, per state and output
    /// (approach states, then retraction states); `None` where fewer than
    /// [`MIN_SUMMITS_FOR_Z`] summits are in range.
    pub z: Vec<[Option<f64>; SLOTS]>,
    /// Largest `|z|` over the curve and outputs (`|z| < 5` expected when
    /// the population follows the model).
    pub max_abs_z: Option<f64>,
    /// Most tensile sampled retraction load of the population.
    pub pull_off: Option<PullOff>,
    /// Summits of the population in contact (count / scale factor; summits
    /// in range when the count is not computed), per state (approach
    /// states, then retraction states). Standard errors are reported only
    /// where at least [`MIN_SUMMITS_FOR_Z`] are.
    pub contacts: Vec<f64>,
    /// Wall-clock time of drawing and summing (s).
    pub seconds: f64,
    /// With `[electrical]`: the sample's own spots at the closest
    /// separation, at random positions in the area the sample stands for
    /// (`None` without contact or beyond [`MAX_SAMPLE_SPOTS`] spots).
    pub spots: Option<SampleResistance>,
}

/// Most contact spots of a population for which explicit-position
/// resistances are computed (Greenwood's formula is `O(n^2)`).
pub const MAX_SAMPLE_SPOTS: usize = 20_000;

/// Draws the plan's population and sums it over `program`.
fn run_montecarlo(
    plan: &Plan,
    mc: &McPlan,
    run_law: &Arc<dyn LawKernels>,
    curve: &Curve,
) -> Result<McResults> {
    let t0 = Instant::now();
    let spec = mc.population_spec(&plan.surface)?;
    let population = Arc::new(Population::sample(&spec, plan.distribution.as_ref())?);
    // One radius: the population sums the same (possibly tabulated) law as
    // the integral; a radius spread rescales the plan's scalable law.
    let law = match mc.law.scaling() {
        None => SummitLaw::fixed(run_law.clone(), mc.law.reference_radius())?,
        Some(_) => mc.law.clone(),
    };
    let summer = MonteCarlo::new(population.clone(), law.clone())?;
    let mc_curve = summer
        .curve(&curve.program, plan.quantities.observables())?
        .scaled(mc.factor);
    let Comparison {
        z,
        max_abs_z,
        contacts,
    } = Comparison::new(&mc_curve, curve, mc.factor);
    let spots = match &plan.resistance {
        Some(res) => {
            let side = (plan.surface.nominal_area / mc.factor).sqrt();
            let seed = derive_seed(mc.spec.seed, Stream::SpotPositions);
            let found = population_spots(&population, &law, curve.program.closest, side, seed)?;
            match found {
                Some(m) if m.spots.len() <= MAX_SAMPLE_SPOTS => {
                    let mut r = SampleResistance::new(&m.spots, res.spot())?;
                    r.merged = m.groups.iter().map(Vec::len).sum();
                    Some(r)
                }
                _ => None,
            }
        }
        None => None,
    };
    Ok(McResults {
        records: LegRecords::new(&plan.quantities, &mc_curve),
        spots,
        contacts,
        pull_off: mc_curve.sampled_pull_off(),
        curve: mc_curve,
        z,
        max_abs_z,
        seconds: t0.elapsed().as_secs_f64(),
    })
}

/// Curve steps computed between two progress reports.
pub const PROGRESS_CHUNK: usize = 16;

/// [`LoadingModel::curve`] in chunks of steps, reporting each chunk.
fn curve_with_progress(
    model: &dyn LoadingModel,
    program: &LoadingProgram,
    outputs: &crate::loading::Observables,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Curve> {
    let steps = program.steps();
    let mut states = Vec::with_capacity(steps.len());
    for chunk in steps.chunks(PROGRESS_CHUNK) {
        crate::cancel::check()?;
        states.extend(model.states(chunk, outputs)?);
        progress(states.len(), steps.len());
    }
    let retract = states.split_off(program.points);
    Ok(Curve {
        program: *program,
        approach: states,
        retract,
    })
}

/// Default `switch.confidence`: the margin uses the pull-off only the 5 %
/// most tensile populations exceed.
pub const DEFAULT_CONFIDENCE: f64 = 0.95;

impl Plan {
    /// The confidence of the stiction margin (`switch.confidence`).
    pub fn stiction_confidence(&self) -> f64 {
        self.scene
            .switch
            .and_then(|s| s.confidence)
            .unwrap_or(DEFAULT_CONFIDENCE)
    }
}

impl Plan {
    /// Contact-regime fractions of the summits at separation `separation`
    /// (m, from the height origin), when the materials give a yield
    /// strength (an elastic law: the Kogut–Etsion regimes as the
    /// diagnostic).
    pub fn regimes_at(&self, separation: f64) -> Option<RegimeFractions> {
        let p = self.plasticity?;
        let variant = self.law.facts.plastic.unwrap_or(Variant::KogutEtsion);
        let limits = RegimeLimits::new(
            variant,
            &p,
            self.contact.radius,
            self.contact.contact_modulus,
        );
        Some(contact_fractions(
            &limits,
            self.surface.sigma,
            separation,
            self.distribution.as_ref(),
        ))
    }

    /// For an elastic-plastic law, the elastic law it reduces to as
    /// `psi -> 0` (JKR with adhesion, Hertz without), for the load–area
    /// comparison; `None` for other laws.
    ///
    /// # Errors
    /// As the analytic constructor of [`LawFacts::elastic_limit`](super::plan::LawFacts::elastic_limit).
    pub fn elastic_law(&self) -> Result<Option<Arc<dyn LawKernels>>> {
        let Some(kind) = self.law.facts.elastic_limit else {
            return Ok(None);
        };
        Ok(Some(Arc::from(kind.build(&self.contact)?)))
    }
}

/// The approach states of `elastic` (the elastic comparison of a plastic
/// law) at the separations of `curve`'s approach: load, area and count.
fn elastic_approach<M: LoadingModel>(elastic: &M, curve: &Curve) -> Result<Vec<State>> {
    let steps: Vec<(f64, History)> = curve
        .approach
        .iter()
        .map(|s| (s.separation, History::Approach))
        .collect();
    elastic.states(&steps, &Observables::standard(true, true, false))
}

impl Results {
    /// The plan these results are of: `planned` (the plan that was run)
    /// unless the run replaced it ([`Results::replanned`]).
    pub fn plan<'a>(&'a self, planned: &'a Plan) -> &'a Plan {
        self.replanned.as_deref().unwrap_or(planned)
    }

    /// Largest approach load (N) of the curve, if loads were computed.
    pub fn max_load(&self) -> Option<f64> {
        self.curve
            .approach
            .iter()
            .filter_map(|s| s.load())
            .reduce(f64::max)
    }
}

impl Plan {
    /// Runs the plan.
    ///
    /// # Errors
    /// [`crate::Error::NoConvergence`] when quadrature cannot meet the
    /// tolerance; [`crate::Error::Invalid`] when a maximum load cannot be
    /// reached.
    pub fn run(&self) -> Result<Results> {
        self.run_with_progress(&|_, _| {})
    }

    /// [`Plan::run`], calling `progress(done, total)` as the states of the
    /// curve are computed (in chunks of [`PROGRESS_CHUNK`] steps; the
    /// states are the same as in one call).
    ///
    /// # Errors
    /// As [`Plan::run`].
    pub fn run_with_progress(&self, progress: &(dyn Fn(usize, usize) + Sync)) -> Result<Results> {
        let results = self
            .run_unmapped(progress)
            .map_err(|e| crate::study::scene::map_derived(&self.scene, e))?;
        let replanned = match self.auto_replanned(|rtol| auto::missed(&results, rtol)) {
            Ok(Some(plan)) => plan,
            Ok(None) => return Ok(results),
            Err(e) => return Ok(auto_failed(results, e)),
        };
        match replanned.run_unmapped(progress) {
            Ok(mut r) => {
                r.replanned = Some(Box::new(replanned));
                Ok(r)
            }
            Err(e) => Ok(auto_failed(results, e)),
        }
    }

    fn run_unmapped(&self, progress: &(dyn Fn(usize, usize) + Sync)) -> Result<Results> {
        let t0 = Instant::now();
        let run_law = self.run_law()?;
        let model = self.model_with(run_law.clone())?;
        if let Some(sp) = &self.sphere {
            // The same surface model under an elastic sphere: every total
            // is over the bump, separations are remote.
            let sphere = sphere::with_spots(self, sp.on(model)?);
            let run = self
                .run_on(&sphere, run_law, t0, progress)
                .and_then(|mut results| {
                    sphere::finish(self, &sphere, &mut results)?;
                    let heating = self.heating_warning(&results, &self.listed_quantities()?)?;
                    results.warnings.extend(heating);
                    results.seconds = t0.elapsed().as_secs_f64();
                    Ok(results)
                });
            return run.map_err(|e| sphere::blame(self, e));
        }
        // A measured map with summits = "measured": the exact sum over its
        // summits replaces the integral.
        let mut results = match super::measured::main_model(self)? {
            Some(m) => self.run_on(&m, run_law, t0, progress)?,
            None => self.run_on(&model, run_law, t0, progress)?,
        };
        results.topography = super::measured::results(self)?;
        Ok(results)
    }

    /// The program's curve on `model`: both legs, or the approach alone
    /// (copied as the retraction) for a law without hysteresis.
    fn curve_on<M: LoadingModel>(
        &self,
        model: &M,
        program: &LoadingProgram,
        progress: &(dyn Fn(usize, usize) + Sync),
    ) -> Result<Curve> {
        if self.compute_retraction {
            return curve_with_progress(model, program, self.quantities.observables(), progress);
        }
        let steps: Vec<_> = program
            .separations()
            .into_iter()
            .map(|d| (d, History::Approach))
            .collect();
        let approach = model.states(&steps, self.quantities.observables())?;
        Ok(Curve {
            program: *program,
            retract: approach.clone(),
            approach,
        })
    }

    /// The hysteresis energy (J), if asked for. A continuous model's
    /// energy is integrated to the scene's tolerance; a discrete one (a
    /// finite sample of summits) has step loads, and its trapezoid on the
    /// program is the honest estimate.
    fn hysteresis_on<M: LoadingModel>(
        &self,
        model: &M,
        program: &LoadingProgram,
        curve: &Curve,
    ) -> Result<Option<f64>> {
        let continuous = !model.is_discrete() && self.distribution.sample_points().is_none();
        Ok(
            if self.hysteresis_energy && self.compute_retraction && continuous {
                Some(hysteresis_energy_to(
                    model,
                    program,
                    self.budget.integrals(),
                )?)
            } else if self.hysteresis_energy {
                curve.hysteresis_energy()
            } else {
                None
            },
        )
    }

    fn run_on<M: LoadingModel>(
        &self,
        model: &M,
        run_law: Arc<dyn LawKernels>,
        t0: Instant,
        progress: &(dyn Fn(usize, usize) + Sync),
    ) -> Result<Results> {
        let closest = self.closest_separation(model)?;
        let program = LoadingProgram::new(self.start, closest, self.points)?;
        let curve = self.curve_on(model, &program, progress)?;
        let pull_off = if self.pull_off {
            model.pull_off(closest, self.start, PULL_OFF_SAMPLES)?
        } else {
            None
        };
        let pull_off_population = match &self.pull_off_population {
            Ok(p) => Some(super::population::run(
                self, p, model, &run_law, &program, pull_off,
            )?),
            Err(_) => None,
        };
        let mut hysteresis_energy = self.hysteresis_on(model, &program, &curve)?;
        // A copied retraction leg cost nothing.
        let legs: &[&[State]] = if self.compute_retraction {
            &[&curve.approach, &curve.retract]
        } else {
            &[&curve.approach]
        };
        let evaluations = legs
            .iter()
            .flat_map(|l| l.iter())
            .map(|s| s.evaluations)
            .sum();
        let mut warnings =
            super::plan::validity::run_warnings(self, &curve, &mut hysteresis_energy)?;
        warnings.extend(crate::numeric::simd::ignored_request().map(Warning::SimdNotFollowed));
        let max_load = curve.approach.first().and_then(|s| s.load());
        let mut model_error = super::model_error::measure(
            self,
            &program,
            pull_off.map(|p| p.load),
            max_load,
            hysteresis_energy,
        )?;
        model_error.measure_map(self, closest, pull_off.map(|p| p.load), max_load, t0)?;
        warnings.extend(model_error.warnings(&self.law.name, self.advises_calibrated_only()));
        if let Some(p) = pull_off.filter(|p| p.at_start) {
            warnings.push(Warning::PullOffAtStart {
                separation: p.separation,
                load: p.load,
            });
        }
        if let Some(r) = &pull_off_population {
            // How many populations the budget allowed is a note of the
            // population (in the summary and the report), not a warning:
            // the quantiles carry their intervals.
            let confidence = self.switch.as_ref().map(|_| self.stiction_confidence());
            let agreement = self.budget.population_agreement();
            warnings.extend(super::population::warning(r, agreement));
            warnings.extend(super::population::confidence_warning(r, confidence));
        }
        let montecarlo = match &self.montecarlo {
            Some(mc) => Some(run_montecarlo(self, mc, &run_law, &curve)?),
            None => None,
        };
        if let Some(s) = montecarlo.as_ref().and_then(|m| m.spots.as_ref()) {
            if s.merged > 0 {
                warnings.push(Warning::SpotsMerged {
                    merged: s.merged,
                    spots: s.spots,
                });
            }
        }
        Ok(Results {
            records: LegRecords::new(&self.quantities, &curve),
            curve,
            pull_off,
            hysteresis_energy,
            seconds: t0.elapsed().as_secs_f64(),
            evaluations,
            montecarlo,
            listed: Vec::new(),
            regimes: None,
            stiction: None,
            stiction_odds: None,
            elastic_approach: None,
            warnings,
            topography: None,
            pull_off_population,
            model_error: Some(model_error),
            sphere: None,
            replanned: None,
        })
        .and_then(|r| self.finish(model, r))
    }

    /// The warning when spots soften or melt under the scene's current at
    /// the states the summary reports (the closest approach and the listed
    /// states): the hottest of them, with their number beyond softening.
    /// The curve's far states (a fraction of one spot carrying the whole
    /// current) are left to their columns: no temperature once molten.
    fn heating_warning(&self, r: &Results, listed: &QuantitySet) -> Result<Option<Warning>> {
        let Some((current, heating)) = self.heating else {
            return Ok(None);
        };
        let voltages = |set: &QuantitySet, records: &[Record]| -> Vec<(f64, f64)> {
            let Some((k, _)) = set.find("contact_voltage") else {
                return Vec::new();
            };
            records
                .iter()
                .filter_map(|rec| Some((rec.values[k]?, rec.state.separation)))
                .collect()
        };
        let first = &r.records.approach[..1.min(r.records.approach.len())];
        let mut reported = voltages(&self.quantities, first);
        reported.extend(voltages(listed, &r.listed));
        let beyond = reported
            .iter()
            .filter(|(u, _)| heating.condition(*u).ok() != Some(SpotCondition::Solid))
            .count();
        let Some(&(u, d)) = reported.iter().max_by(|a, b| a.0.total_cmp(&b.0)) else {
            return Ok(None);
        };
        Ok(heating.warning(u)?.map(|spot| Warning::SpotHeating {
            current,
            separation: d,
            spot,
            beyond,
            reported: reported.len(),
        }))
    }

    /// The parts that follow from the curve: listed states, regime
    /// fractions, stiction, and their warnings.
    /// The quantities of the listed states: load, area and count whatever
    /// the curve carries.
    fn listed_quantities(&self) -> Result<QuantitySet> {
        self.quantities.over(
            self.quantities
                .observables()
                .clone()
                .with(Observable::Load)?
                .with(Observable::Area)?
                .with(Observable::Count)?,
        )
    }

    fn finish<M: LoadingModel>(&self, model: &M, mut r: Results) -> Result<Results> {
        let listed = self.listed_quantities()?;
        let steps: Vec<(f64, History)> = match &self.listed {
            Some(ProgramTarget::Separations(xs)) => {
                xs.iter().map(|&d| (d, History::Approach)).collect()
            }
            Some(ProgramTarget::Loads(ps)) => ps
                .iter()
                .map(|&p| {
                    model
                        .separation_at_load(p, self.start)
                        .map(|d| (d, History::Approach))
                        .map_err(|e| e.renamed("program.loads"))
                })
                .collect::<Result<_>>()?,
            _ => Vec::new(),
        };
        r.listed = listed.records(&model.states(&steps, listed.observables())?);
        if let Some(m) = r.model_error.as_mut() {
            let loads: Vec<Option<f64>> = r.listed.iter().map(|l| l.state.load()).collect();
            let separations: Vec<f64> = steps.iter().map(|&(d, _)| d).collect();
            m.measure_listed(self, &separations, &loads);
            let before = m.warnings(&self.law.name, self.advises_calibrated_only());
            let listed_state = |w: &Warning| {
                matches!(
                    w,
                    Warning::ModelError {
                        output: ModelErrorOutput::ListedLoad,
                        ..
                    }
                )
            };
            if let Some(w) = before.into_iter().find(listed_state) {
                r.warnings.push(w);
            }
        }
        if self.sphere.is_none() {
            // (a rough sphere's follows its own warnings, after
            // `sphere::finish`)
            r.warnings.extend(self.heating_warning(&r, &listed)?);
        }
        if self.sphere.is_none() {
            // (a rough sphere's are at the centre of its bump and on the
            // same sphere: `study::sphere`)
            r.regimes = self.regimes_at(r.curve.program.closest);
            if let Some(law) = self.elastic_law()? {
                r.elastic_approach = Some(elastic_approach(&self.model_with(law)?, &r.curve)?);
            }
        }
        if let Some(sw) = &self.switch {
            // The populations' pull-offs when there are any: a switch is one
            // realisation; the integral's pull-off otherwise.
            let stats = r
                .pull_off_population
                .as_ref()
                .and_then(|p| p.statistics.as_ref());
            match stats {
                Some(s) => {
                    let odds = sw
                        .stiction_odds(s, self.stiction_confidence())
                        .map_err(|e| e.renamed("switch.confidence"))?;
                    r.stiction = Some(odds.verdict);
                    r.stiction_odds = Some(odds);
                }
                None => {
                    let pull = r.pull_off.map_or(0.0, |p| p.load.min(0.0));
                    r.stiction = Some(sw.stiction(pull)?);
                }
            }
        }
        if let Some(res) = &self.resistance {
            if res.interaction() == Interaction::Greenwood {
                let skipped = r
                    .curve
                    .approach
                    .iter()
                    .chain(r.listed.iter().map(|l| &l.state))
                    .filter_map(|s| res.resistance(self.quantities.observables(), &s.totals))
                    .filter(|c| c.interaction_skipped && c.contacts > 0.0)
                    .count();
                if skipped > 0 {
                    r.warnings
                        .push(Warning::GreenwoodSkipped { states: skipped });
                }
            }
        }
        Ok(r)
    }
}
