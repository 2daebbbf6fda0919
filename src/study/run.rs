//! Executing a [`Plan`]: the loading program, pull-off and hysteresis energy.

use super::plan::{McPlan, Plan};
use crate::error::Result;
use crate::law::AsperityLaw;
use crate::loading::{
    hysteresis_energy_to, Curve, History, LoadingModel, LoadingProgram, PullOff, State, SLOTS,
};
use crate::montecarlo::{MonteCarlo, Population, SummitLaw};
use std::sync::Arc;
use std::time::Instant;

/// Summits in range below which a population state is not compared with
/// the integral in standard errors.
pub const MIN_SUMMITS_FOR_Z: usize = 20;

/// Number of retraction samples the pull-off search starts from.
const PULL_OFF_SAMPLES: usize = 64;

/// What a run produced. Outputs not asked for are `None` (or absent from
/// the states).
#[derive(Debug, Clone)]
pub struct Results {
    /// The program's curve: approach and retraction states at the same
    /// separations (ascending; index 0 is the closest separation).
    pub curve: Curve,
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
    /// Where the results lie outside a model's validity (each a sentence
    /// naming the quantity, its value and the bound).
    pub warnings: Vec<String>,
}

/// A population summed over the program, beside the integral.
#[derive(Debug, Clone)]
pub struct McResults {
    /// The population's curve (totals scaled to the whole surface).
    pub curve: Curve,
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
    /// Wall-clock time of drawing and summing (s).
    pub seconds: f64,
}

/// Draws the plan's population and sums it over `program`.
fn run_montecarlo(
    plan: &Plan,
    mc: &McPlan,
    run_law: &Arc<dyn AsperityLaw>,
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
    let summer = MonteCarlo::new(population, law)?;
    let mc_curve = summer
        .curve(&curve.program, &plan.curve_outputs)?
        .scaled(mc.factor);
    let z: Vec<[Option<f64>; SLOTS]> = mc_curve
        .approach
        .iter()
        .zip(&curve.approach)
        .chain(mc_curve.retract.iter().zip(&curve.retract))
        .map(|(m, g)| {
            // The standard error means something only with enough summits
            // in range (central limit); with none in range the sum is an
            // exact 0 that a tiny expectation cannot be "many errors" from.
            if m.evaluations >= MIN_SUMMITS_FOR_Z {
                m.deviation_from(g)
            } else {
                [None; SLOTS]
            }
        })
        .collect();
    let max_abs_z = z
        .iter()
        .flatten()
        .flatten()
        .map(|v| v.abs())
        .reduce(f64::max);
    Ok(McResults {
        pull_off: mc_curve.sampled_pull_off(),
        curve: mc_curve,
        z,
        max_abs_z,
        seconds: t0.elapsed().as_secs_f64(),
    })
}

impl Results {
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
        let t0 = Instant::now();
        let run_law = self.run_law()?;
        let model = self.model_with(run_law.clone())?;
        let closest = self.closest_separation(&model)?;
        let program = LoadingProgram::new(self.start, closest, self.points)?;
        let curve = if self.compute_retraction {
            model.curve(&program, &self.curve_outputs)?
        } else {
            let steps: Vec<_> = program
                .separations()
                .into_iter()
                .map(|d| (d, History::Approach))
                .collect();
            let approach = model.states(&steps, &self.curve_outputs)?;
            Curve {
                program,
                retract: approach.clone(),
                approach,
            }
        };
        let pull_off = if self.pull_off {
            model.pull_off(closest, self.start, PULL_OFF_SAMPLES)?
        } else {
            None
        };
        let hysteresis_energy = if self.hysteresis_energy && self.compute_retraction {
            Some(hysteresis_energy_to(
                &model,
                &program,
                model.accuracy().rel_tol,
            )?)
        } else if self.hysteresis_energy {
            curve.hysteresis_energy()
        } else {
            None
        };
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
        let montecarlo = match &self.montecarlo {
            Some(mc) => Some(run_montecarlo(self, mc, &run_law, &curve)?),
            None => None,
        };
        Ok(Results {
            curve,
            pull_off,
            hysteresis_energy,
            seconds: t0.elapsed().as_secs_f64(),
            evaluations,
            montecarlo,
            warnings: Vec::new(),
        })
    }
}
