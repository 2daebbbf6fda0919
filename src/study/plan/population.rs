//! The pull-off distribution's part of a plan: how many populations of
//! the surface's `N = eta A_n` summits, from which seed, drawn how, or why
//! none.

use super::{Decision, LawChoice};
use crate::error::{Error, Result};
use crate::gw::RoughSurface;
use crate::heights::HeightDistribution;
use crate::montecarlo::{PopulationSpec, RadiusSpec, MAX_SUMMITS};
use crate::study::scene::{Scene, DEFAULT_POPULATIONS, DEFAULT_SEED};

/// The populations whose pull-offs the run draws.
#[derive(Debug, Clone, PartialEq)]
pub struct PopulationPlan {
    /// Populations asked for (`montecarlo.seeds`, default
    /// [`DEFAULT_POPULATIONS`]); the run may draw fewer within its cost
    /// bound, and says so.
    pub seeds: usize,
    /// Seed of the first (`montecarlo.seed`, default [`DEFAULT_SEED`]).
    pub first_seed: u64,
    /// Summits of each, `N = eta A_n` rounded.
    pub summits: usize,
    /// `eta A_n / N`: the totals are scaled by it.
    pub factor: f64,
    /// The heights' spec (scale, radii; the seed is set per population).
    pub spec: PopulationSpec,
}

/// Why a scene has no pull-off distribution.
#[derive(Debug, Clone, PartialEq)]
pub enum NoPopulation {
    /// The pull-off is not searched (not asked for, or no adhesion).
    NoPullOff,
    /// `outputs.pull_off_population = false`.
    Off,
    /// The summits are a measured sample: the run is one realisation.
    MeasuredSummits,
    /// `eta A_n` is below one summit or beyond what can be counted.
    NotFinite(f64),
    /// A rough sphere (`[sphere]`): its summits are those of an apparent
    /// area the solution sets, not a fixed population.
    RoughSphere,
}

impl std::fmt::Display for NoPopulation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            NoPopulation::NoPullOff => write!(f, "no pull-off is searched"),
            NoPopulation::Off => write!(
                f,
                "outputs.pull_off_population = false: the pull-off is the integral's (the mean \
                 surface), not one switch's"
            ),
            NoPopulation::MeasuredSummits => write!(
                f,
                "the summits are a measured sample: the run is already one realisation"
            ),
            NoPopulation::NotFinite(n) => {
                write!(f, "eta A_n = {n:e} summits is no population to draw")
            }
            NoPopulation::RoughSphere => write!(
                f,
                "a rough sphere: its summits are those of an apparent area the load sets (no \
                 fixed population of eta A_n summits to redraw); the pull-off is the sphere's \
                 own (the GW densities integrated over the bump), and [switch] uses it (basis \
                 \"integral\")"
            ),
        }
    }
}

/// The populations of a scene whose pull-off is searched, with the
/// decision; `Err` with the reason when there are none.
///
/// # Errors
/// Bad values naming the `montecarlo.` field.
pub(super) fn plan(
    scene: &Scene,
    pull_off: bool,
    surface: &RoughSurface,
    distribution: &dyn HeightDistribution,
    law: &LawChoice,
    sphere: bool,
    decisions: &mut Vec<Decision>,
) -> Result<std::result::Result<PopulationPlan, NoPopulation>> {
    let why = if !pull_off {
        Some(NoPopulation::NoPullOff)
    } else if sphere {
        Some(NoPopulation::RoughSphere)
    } else if !scene.outputs.pull_off_population {
        Some(NoPopulation::Off)
    } else if distribution.sample_points().is_some() {
        Some(NoPopulation::MeasuredSummits)
    } else {
        let n = surface.summits().round();
        (!(n >= 1.0 && n <= MAX_SUMMITS as f64)).then_some(NoPopulation::NotFinite(n))
    };
    if let Some(why) = why {
        if why != NoPopulation::NoPullOff {
            decisions.push(Decision::PullOffPopulation {
                seeds: 0,
                summits: 0,
                why: why.to_string(),
            });
        }
        return Ok(Err(why));
    }
    let mc = scene.montecarlo.as_ref();
    let seeds = mc.and_then(|m| m.seeds).unwrap_or(DEFAULT_POPULATIONS);
    let first_seed = mc.map_or(DEFAULT_SEED, |m| m.seed);
    let n = surface.summits().round();
    let summits = n as usize;
    let radius = match mc.map(|m| m.radius_log_std) {
        Some(s) if s > 0.0 => {
            if law.law.radius_scaling().is_none() {
                return Err(Error::invalid(
                    "montecarlo.radius_log_std",
                    format!(
                        "a radius spread needs a law that scales with R, not {}",
                        law.name
                    ),
                ));
            }
            RadiusSpec::LogNormal {
                median: surface.radius,
                log_std: s,
            }
        }
        _ => RadiusSpec::Fixed(surface.radius),
    };
    let spec = PopulationSpec::new(summits, surface.sigma, radius, first_seed)
        .map_err(|e| e.in_table("montecarlo"))?;
    decisions.push(Decision::PullOffPopulation {
        seeds,
        summits,
        why: format!(
            "the pull-off of one switch is the minimum of its own {summits} summits' retraction \
             curve, not the integral's minimum of the mean load: {seeds} populations with seeds \
             {first_seed}.. (each the population [montecarlo] seed = s draws, its summits \
             within the flat's reach drawn from the top), each summed exactly on the \
             retraction leg"
        ),
    });
    Ok(Ok(PopulationPlan {
        seeds,
        first_seed,
        summits,
        factor: surface.summits() / n,
        spec,
    }))
}
