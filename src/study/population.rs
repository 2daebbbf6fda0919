//! Running the pull-off distribution of a plan: the populations' pull-offs
//! beside the integral's, the number of summits that carry the integral's
//! pull-off, and what the two say together.

use super::plan::population::PopulationPlan;
use super::plan::Plan;
use crate::error::Result;
use crate::law::LawKernels;
use crate::loading::{History, LoadingModel, LoadingProgram, Observables, PullOff};
use crate::montecarlo::pull_off::{agrees_with_integral, scatter_below};
use crate::montecarlo::pull_off::{
    candidate_separations, population_model, pull_off_evaluations, pull_off_populations,
    retraction_loads_at, widest_coverage, PullOffStatistics, INTERVAL_CONFIDENCE,
};
use crate::montecarlo::{MonteCarlo, RadiusSpec, SummitLaw};
use crate::numeric::mix::{derive_seed, Stream};
use crate::study::Warning;
use std::sync::Arc;
use std::time::Instant;

/// Populations whose retraction curves the charts draw.
pub const EXAMPLE_CURVES: usize = 3;

/// The example curves are drawn at every this many program separations
/// (and wherever the pull-off can lie).
pub const EXAMPLE_STRIDE: usize = 4;

/// Fewest populations drawn when the cost bound cuts their number.
pub const MIN_POPULATIONS: usize = 20;

/// Largest estimated CPU time (s) of the populations; beyond it fewer are
/// drawn (never below [`MIN_POPULATIONS`]) and the summary says so.
pub const POPULATION_CPU_BUDGET: f64 = 0.5;

/// Estimated CPU time (ns) to draw one summit exactly from the top (its
/// exponential, the prefix sum, an `exp` and the quantile; 27-46 ns
/// measured on 1,990-10,000 summits by `examples/population_cost.rs`).
const DRAW_NS: f64 = 40.0;

/// Estimated fixed CPU time (ns) of one population: the pruning's
/// bookkeeping and buffers (40 us measured on 100 summits).
const POPULATION_OVERHEAD_NS: f64 = 40_000.0;

/// The pull-off distribution of a run.
#[derive(Debug, Clone)]
pub struct PopulationResults {
    /// The plan's populations.
    pub plan: PopulationPlan,
    /// Populations drawn (fewer than asked when the cost bound cut them).
    pub drawn: usize,
    /// Their pull-offs, `None` when skipped.
    pub statistics: Option<PullOffStatistics>,
    /// Expected summits in contact at the integral's pull-off separation
    /// (on retraction).
    pub carriers: Option<f64>,
    /// The integral's pull-off (N).
    pub integral: Option<f64>,
    /// Why no populations were drawn, or why fewer than asked.
    pub note: Option<String>,
    /// The retraction legs `(separation, load)` of the first
    /// [`EXAMPLE_CURVES`] populations, by seed, for the charts.
    pub examples: Vec<(u64, Vec<(f64, f64)>)>,
    /// Wall-clock time (s).
    pub seconds: f64,
}

/// The summit law of the populations: the run's law for one radius (as the
/// Monte Carlo mode sums it), rescaled per radius with a spread.
fn summit_law(plan: &Plan, run_law: &Arc<dyn LawKernels>, p: &PopulationPlan) -> Result<SummitLaw> {
    let r = plan.surface.radius;
    match (p.spec.radius, plan.law.law.radius_scaling()) {
        (RadiusSpec::LogNormal { .. }, Some(s)) => SummitLaw::scaled(plan.law.law.clone(), r, s),
        _ => SummitLaw::fixed(run_law.clone(), r),
    }
}

/// Estimated CPU seconds of one population over `program`, priced on the
/// first one, `first` (with its `candidates`): its draw (the summits the
/// flat can reach), and its pull-off
/// search's law evaluations
/// ([`pull_off_evaluations`], deterministic) at the law's batch cost.
fn cost_per_population(
    law: &SummitLaw,
    first: &MonteCarlo,
    candidates: &[f64],
    program: &LoadingProgram,
) -> f64 {
    let draw = first.population().len() as f64 * DRAW_NS;
    let evaluations = pull_off_evaluations(first, program, candidates) as f64;
    (POPULATION_OVERHEAD_NS + draw + evaluations * law.law().batch_cost_ns()) * 1e-9
}

/// Where an example curve is drawn: at every [`EXAMPLE_STRIDE`]-th
/// separation of `program` and wherever the minimum can lie
/// (`candidates`), so the pull-off is the least of these loads, as
/// `realised_pull_off` finds it.
fn shown_at(program: &LoadingProgram, candidates: &[f64]) -> Vec<f64> {
    let all = program.separations();
    let last = all.len() - 1;
    all.iter()
        .enumerate()
        .filter(|&(i, d)| i % EXAMPLE_STRIDE == 0 || i == last || candidates.contains(d))
        .map(|(_, &d)| d)
        .collect()
}

/// The number of summits in contact at the integral's pull-off on
/// `model` (`None` without a pull-off): how many carry the tension.
fn carriers(
    model: &dyn LoadingModel,
    program: &LoadingProgram,
    pull_off: Option<PullOff>,
) -> Result<Option<f64>> {
    let Some(po) = pull_off else {
        return Ok(None);
    };
    let retract = History::Retract {
        closest: program.closest,
    };
    let count = Observables::standard(false, false, true);
    Ok(model.state(po.separation, retract, &count)?.count())
}

/// The pull-off distribution of `plan` over `program` on `model` (the
/// integral), beside its pull-off `pull_off`.
///
/// # Errors
/// As [`pull_off_populations`] and the model's states.
pub fn run(
    plan: &Plan,
    p: &PopulationPlan,
    model: &dyn LoadingModel,
    run_law: &Arc<dyn LawKernels>,
    program: &LoadingProgram,
    pull_off: Option<PullOff>,
) -> Result<PopulationResults> {
    let t0 = Instant::now();
    let carriers = carriers(model, program, pull_off)?;
    let mut out = PopulationResults {
        plan: p.clone(),
        drawn: 0,
        statistics: None,
        carriers,
        integral: pull_off.map(|x| x.load),
        note: None,
        examples: Vec::new(),
        seconds: 0.0,
    };
    let rtol = plan.budget.population_scatter();
    if let Some(c) = carriers.filter(|&c| scatter_below(c, rtol)) {
        out.note = Some(format!(
            "populations skipped: {c:.3e} summits carry the integral's pull-off, so one \
             switch's pull-off scatters by ~1/sqrt({c:.3e}) = {:.1e} < rtol = {rtol:e} around it",
            1.0 / c.sqrt()
        ));
        out.seconds = t0.elapsed().as_secs_f64();
        return Ok(out);
    }
    let law = summit_law(plan, run_law, p)?;
    let draw_one = |k: u64| {
        population_model(
            &p.spec,
            plan.distribution.as_ref(),
            &law,
            program,
            derive_seed(p.first_seed, Stream::Population(k)),
        )
    };
    // The first population prices the others (its pruned search is then
    // its example curve's).
    let first_mc = draw_one(0)?;
    let first_candidates = candidate_separations(&first_mc, program);
    let per = cost_per_population(&law, &first_mc, &first_candidates, program);
    let mut first = Some((first_mc, first_candidates));
    let affordable = (POPULATION_CPU_BUDGET / per.max(1e-12)).floor() as usize;
    let drawn = p.seeds.min(affordable.max(MIN_POPULATIONS));
    if drawn < p.seeds {
        out.note = Some(format!(
            "{drawn} of the {} populations asked for drawn: each costs an estimated {per:.2e} s \
             of CPU ({} summits{}), and the populations are held to about \
             {POPULATION_CPU_BUDGET} s (montecarlo.seeds sets the number)",
            p.seeds,
            p.summits,
            if law.law().cutoff_interference().is_finite() {
                ""
            } else {
                ", every one in range of this long-range law"
            }
        ));
    }
    // The first populations' retraction curves are kept for the chart;
    // their pull-offs are the minima of those curves (what
    // `pull_off_populations` computes), so each population is summed once.
    let shown = EXAMPLE_CURVES.min(drawn);
    let mut values = Vec::with_capacity(drawn);
    for k in 0..shown as u64 {
        let seed = derive_seed(p.first_seed, Stream::Population(k));
        let (mc, candidates) = match first.take() {
            Some(drawn) => drawn,
            None => {
                let mc = draw_one(k)?;
                let c = candidate_separations(&mc, program);
                (mc, c)
            }
        };
        let curve = retraction_loads_at(&mc, program, &shown_at(program, &candidates), p.factor)?;
        values.push(curve.iter().fold(0.0f64, |m, &(_, load)| m.min(load)));
        out.examples.push((seed, curve));
    }
    if drawn > shown {
        values.extend(pull_off_populations(
            &p.spec,
            plan.distribution.as_ref(),
            &law,
            program,
            p.factor,
            derive_seed(p.first_seed, Stream::Population(shown as u64)),
            drawn - shown,
        )?);
    }
    out.drawn = drawn;
    out.statistics = Some(PullOffStatistics::new(values)?);
    out.seconds = t0.elapsed().as_secs_f64();
    Ok(out)
}

/// A warning when the populations' pull-off and the integral's differ
/// beyond the scene's tolerance and the populations' standard error.
pub fn warning(r: &PopulationResults, rtol: f64) -> Option<Warning> {
    let s = r.statistics.as_ref()?;
    let integral = r.integral.unwrap_or(0.0);
    let (mean, se) = (s.mean(), s.mean_standard_error());
    if agrees_with_integral(mean, se, integral, rtol) {
        return None;
    }
    Some(Warning::PopulationDisagrees {
        integral: r.integral,
        carriers: r.carriers,
        summits: r.plan.summits,
        mean,
        standard_error: se,
        p05: s.quantile(0.05),
        p95: s.quantile(0.95),
        populations: s.len(),
    })
}

/// The fewest populations whose widest pair of order statistics (minimum
/// and maximum) holds the true `q`-quantile with probability at least
/// `level` ([`widest_coverage`]).
pub fn populations_needed(q: f64, level: f64) -> usize {
    (2..1_000_000)
        .find(|&n| widest_coverage(n, q) >= level)
        .unwrap_or(1_000_000)
}

/// Why the quantile intervals of `s` (the 5 % and 95 % quantiles, at
/// [`INTERVAL_CONFIDENCE`]) are null, if they are: too few populations for
/// any pair of order statistics to reach the confidence.
pub fn interval_note(s: &PullOffStatistics) -> Option<String> {
    let n = s.len();
    let (q, level) = (0.05, INTERVAL_CONFIDENCE);
    if s.quantile_interval(q).is_ok() && s.quantile_interval(1.0 - q).is_ok() {
        return None;
    }
    Some(format!(
        "p05_interval_N and p95_interval_N are null: of {n} populations, no pair of order \
         statistics holds the true 5 % (or 95 %) quantile with probability >= {:.0} % (the \
         widest, their minimum and maximum, holds it with {:.1} %, from the exact binomial \
         distribution); {} populations are needed (montecarlo.seeds)",
        100.0 * level,
        100.0 * widest_coverage(n, q),
        populations_needed(q, level)
    ))
}

/// A warning when the populations are too few for the confidence asked:
/// no interval of the 5 % and 95 % quantiles at [`INTERVAL_CONFIDENCE`]
/// ([`interval_note`]), or, with a switch, too few for its
/// `1 - confidence` quantile (`confidence`: `switch.confidence`) to lie
/// inside the sample (with fewer than `1/(1 - confidence)` populations
/// it is interpolated between the two most tensile pull-offs).
pub fn confidence_warning(r: &PopulationResults, confidence: Option<f64>) -> Vec<Warning> {
    let Some(s) = r.statistics.as_ref() else {
        return Vec::new();
    };
    let n = s.len();
    let mut out = Vec::new();
    if interval_note(s).is_some() {
        out.push(Warning::PopulationIntervals {
            populations: n,
            confidence: INTERVAL_CONFIDENCE,
            needed: populations_needed(0.05, INTERVAL_CONFIDENCE),
        });
    }
    if let Some(c) = confidence {
        let needed = (1.0 / (1.0 - c)).ceil();
        if (n as f64) < needed {
            out.push(Warning::PopulationConfidence {
                confidence: c,
                populations: n,
                needed,
            });
        }
    }
    out
}
