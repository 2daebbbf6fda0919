//! The pull-off of a switch as one realisation of its summits, and its
//! spread over realisations.
//!
//! A finite contact of `N = eta A_n` summits is one draw of `N` heights.
//! Its pull-off is the most tensile load of *its own* retraction curve;
//! the GW integral gives the minimum of the *mean* load curve instead,
//! which is not the mean of the realisations' minima: where few summits
//! carry the tension, each realisation's few tensile summits detach at
//! their own separations, and the integral's pull-off can be far shallower
//! than every realisation's. [`realised_pull_off`] is one realisation's
//! pull-off (the same number for the Monte Carlo mode and for the
//! statistics); [`pull_off_populations`] draws many; [`PullOffStatistics`]
//! summarises them with standard errors and distribution-free intervals
//! (order statistics whose ranks come from the exact binomial distribution).

pub use super::quantiles::{quantile_ranks, widest_coverage, QuantileInterval, RankInterval};
use super::{MonteCarlo, Population, PopulationSpec, RadiusSpec, SummitLaw};
use crate::error::{Error, Result};
use crate::heights::HeightDistribution;
use crate::loading::{History, LoadingModel, LoadingProgram, Observables};
use crate::numeric::mix::{derive_seed, Stream};
use rayon::prelude::*;
use std::sync::Arc;

/// The pull-off (N, signed: negative is tensile) of one population over
/// `program`: the most tensile load of its retraction leg at the program's
/// separations, its totals multiplied by `factor` (the population's share
/// of the surface); 0 when no retraction load is tensile (the contact
/// opens without pulling).
///
/// Numerical error: the minimum is sampled at the program's separations,
/// so it is within one step's change of the load of the true minimum of
/// the population's (piecewise continuous) load curve.
///
/// Cost: the load is summed exactly ([`MonteCarlo::states`], the Monte
/// Carlo mode's own sums, so the value is the same to the last bit) only
/// at the separations that can hold the minimum
/// ([`candidate_separations`]); the rest are ruled out by bounds.
///
/// # Errors
/// As [`MonteCarlo::states`](crate::loading::LoadingModel::states).
pub fn realised_pull_off(mc: &MonteCarlo, program: &LoadingProgram, factor: f64) -> Result<f64> {
    let back = History::Retract {
        closest: program.closest,
    };
    let steps: Vec<(f64, History)> = candidate_separations(mc, program)
        .into_iter()
        .map(|d| (d, back))
        .collect();
    if steps.is_empty() {
        return Ok(0.0);
    }
    let states = mc.states(&steps, &Observables::LOAD)?;
    Ok(states
        .iter()
        .filter_map(|s| Some(s.load()? * factor))
        .fold(0.0f64, f64::min))
}

/// Fewest program points for which [`candidate_separations`] prunes.
pub const PRUNE_FROM_POINTS: usize = 16;

/// Relative roundoff allowance of the pruning bounds: far above the
/// rounding of sums of ~1e8 terms (`~1e-8` at worst) and of the laws'
/// monotone pieces evaluated in floating point.
const BOUND_SLACK: f64 = 1e-7;

/// The program's retraction separations (m, ascending) at which a
/// population's load can be most tensile (or negative at all): the loads
/// at every `m`-th separation (`m ~ sqrt(points/2)`) and, between each
/// pair, a lower bound at each separation ([`MonteCarlo::retraction_bounds`],
/// [`RetractionBounds::lower_at`](super::RetractionBounds::lower_at));
/// only the separations whose bound reaches below the least of those loads
/// (and below zero, since a contact that never pulls has pull-off 0) are
/// kept. All of them when the law gives no bounds or the program is
/// short (fewer than [`PRUNE_FROM_POINTS`]). Typically a fifth of the
/// separations are left.
pub fn candidate_separations(mc: &MonteCarlo, program: &LoadingProgram) -> Vec<f64> {
    let all = program.separations();
    let k = all.len();
    if k < PRUNE_FROM_POINTS {
        return all;
    }
    let coarse = coarse_indices(k);
    let at: Vec<f64> = coarse.iter().map(|&i| all[i]).collect();
    let Some(b) = mc.retraction_bounds(&at, program.closest) else {
        return all;
    };
    let least = b.loads.iter().copied().fold(0.0f64, f64::min);
    let threshold = least + BOUND_SLACK * b.magnitude;
    let mut keep = vec![false; k];
    for (j, &lower) in b.lower.iter().enumerate() {
        if lower > threshold {
            continue;
        }
        // Each separation of the window against its own bound (the chord
        // of the concave summits at its place).
        let (first, last) = (coarse[j], coarse[j + 1]);
        let width = all[last] - all[first];
        for i in first..=last {
            let t = ((all[i] - all[first]) / width).clamp(0.0, 1.0);
            keep[i] |= b.lower_at(j, t) <= threshold;
        }
    }
    all.into_iter()
        .zip(keep)
        .filter_map(|(d, kept)| kept.then_some(d))
        .collect()
}

/// Indices of the separations where [`candidate_separations`] sums the
/// loads and bounds of `k` program points: every `ceil(sqrt(k/2))`-th and
/// the last.
fn coarse_indices(k: usize) -> Vec<usize> {
    let stride = ((k as f64 / 2.0).sqrt().ceil() as usize).max(2);
    let mut coarse: Vec<usize> = (0..k).step_by(stride).collect();
    if coarse.last() != Some(&(k - 1)) {
        coarse.push(k - 1);
    }
    coarse
}

/// Law evaluations of [`realised_pull_off`] on `mc` over `program`, given
/// its `candidates` ([`candidate_separations`]): the summits in range at
/// the pruning's coarse separations (when it prunes) and at the
/// candidates. Deterministic: what prices a population.
pub fn pull_off_evaluations(
    mc: &MonteCarlo,
    program: &LoadingProgram,
    candidates: &[f64],
) -> usize {
    let all = program.separations();
    // (a search that kept every separation is counted without its bounds)
    let pruned = all.len() >= PRUNE_FROM_POINTS && candidates.len() < all.len();
    let coarse: usize = if pruned {
        coarse_indices(all.len())
            .iter()
            .map(|&i| mc.summits_in_range(all[i]))
            .sum()
    } else {
        0
    };
    coarse
        + candidates
            .iter()
            .map(|&d| mc.summits_in_range(d))
            .sum::<usize>()
}

/// The retraction leg of one population over `program`: `(separation,
/// load)` (m, N) at the program's separations, ascending, the loads
/// multiplied by `factor`.
///
/// # Errors
/// As [`MonteCarlo::states`](crate::loading::LoadingModel::states).
pub fn retraction_loads(
    mc: &MonteCarlo,
    program: &LoadingProgram,
    factor: f64,
) -> Result<Vec<(f64, f64)>> {
    retraction_loads_at(mc, program, &program.separations(), factor)
}

/// [`retraction_loads`] at `separations` (m, ascending) only.
///
/// # Errors
/// As [`MonteCarlo::states`](crate::loading::LoadingModel::states).
pub fn retraction_loads_at(
    mc: &MonteCarlo,
    program: &LoadingProgram,
    separations: &[f64],
    factor: f64,
) -> Result<Vec<(f64, f64)>> {
    let steps: Vec<(f64, History)> = separations
        .iter()
        .map(|&d| {
            (
                d,
                History::Retract {
                    closest: program.closest,
                },
            )
        })
        .collect();
    let states = mc.states(&steps, &Observables::LOAD)?;
    Ok(states
        .iter()
        .filter_map(|s| Some((s.separation, s.load()? * factor)))
        .collect())
}

/// The lowest summit height (m) that can touch or interact with the flat
/// on the retraction of `program` under `law`; `-inf` for laws without a
/// cutoff or with a radius spread.
pub fn lowest_reachable(law: &SummitLaw, radius: &RadiusSpec, program: &LoadingProgram) -> f64 {
    let cut = law.law().cutoff_interference();
    match radius {
        RadiusSpec::Fixed(r) if cut.is_finite() => {
            // The law's interferences scale with the radius ratio.
            let [fi, _, _] = law
                .scaling()
                .map_or([1.0; 3], |s| s.factors(*r / law.reference_radius()));
            program.closest + cut / fi
        }
        _ => f64::NEG_INFINITY,
    }
}

/// Whether one switch's pull-off is known to relative tolerance `rtol`
/// without drawing populations: when `carriers` summits carry the
/// integral's pull-off, a realisation's pull-off scatters around it by
/// about `1/sqrt(carriers)` (a sum of that many independent summits'
/// loads), so populations are worth drawing only while
/// `1/sqrt(carriers) >= rtol`.
pub fn scatter_below(carriers: f64, rtol: f64) -> bool {
    carriers > 0.0 && 1.0 / carriers.sqrt() < rtol
}

/// Whether the populations' mean pull-off `mean` (standard error `se`)
/// agrees with the integral's `integral` (N): within `rtol` of the larger
/// magnitude, or within two standard errors.
pub fn agrees_with_integral(mean: f64, se: f64, integral: f64, rtol: f64) -> bool {
    let gap = (mean - integral).abs();
    gap <= rtol * integral.abs().max(mean.abs()) || gap <= 2.0 * se
}

/// The pull-offs (N) of the populations of `spec` with seeds
/// `first_seed + k`, `k < seeds` ([`Stream::Population`]; each [`realised_pull_off`] with its
/// totals scaled by `factor`), in seed order; parallel over seeds,
/// reproducible for any thread count. Population `k` is the population
/// [`Population::sample`] draws with seed `first_seed + k`, of which only
/// the summits the flat can reach are drawn ([`population_model`]).
///
/// # Errors
/// As [`Population::sample`] and [`realised_pull_off`]; [`Error::Invalid`]
/// naming `seeds` for zero seeds.
#[allow(clippy::too_many_arguments)]
pub fn pull_off_populations(
    spec: &PopulationSpec,
    distribution: &dyn HeightDistribution,
    law: &SummitLaw,
    program: &LoadingProgram,
    factor: f64,
    first_seed: u64,
    seeds: usize,
) -> Result<Vec<f64>> {
    if seeds == 0 {
        return Err(Error::invalid("seeds", "at least one population"));
    }
    let token = crate::cancel::current();
    (0..seeds as u64)
        .into_par_iter()
        .map(|k| {
            crate::cancel::scope(token.as_ref(), crate::cancel::check)?;
            let mc = population_model(
                spec,
                distribution,
                law,
                program,
                derive_seed(first_seed, Stream::Population(k)),
            )?;
            realised_pull_off(&mc, program, factor)
        })
        .collect()
}

/// The summed population of seed `seed` as [`pull_off_populations`] draws
/// it: the summits of [`Population::sample`]'s draw that the flat can reach
/// on `program` ([`lowest_reachable`], [`Population::sample_above`]), bit
/// for bit, at a cost independent of `N` for laws with a cutoff.
///
/// # Errors
/// As [`Population::sample`].
pub fn population_model(
    spec: &PopulationSpec,
    distribution: &dyn HeightDistribution,
    law: &SummitLaw,
    program: &LoadingProgram,
    seed: u64,
) -> Result<MonteCarlo> {
    let lowest = lowest_reachable(law, &spec.radius, program);
    let mut s = *spec;
    s.seed = seed;
    let population = Population::sample_above(&s, distribution, lowest)?;
    MonteCarlo::new(Arc::new(population), law.clone())
}

/// The pull-offs of many populations and what they say.
#[derive(Debug, Clone, PartialEq)]
pub struct PullOffStatistics {
    /// The pull-offs (N, signed), in seed order.
    pub values: Vec<f64>,
    /// The same, ascending.
    sorted: Vec<f64>,
}

/// Two-sided confidence of the intervals [`PullOffStatistics`] states.
pub const INTERVAL_CONFIDENCE: f64 = 0.95;

impl PullOffStatistics {
    /// Statistics of `values` (N).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `values` when empty or not finite.
    pub fn new(values: Vec<f64>) -> Result<Self> {
        if values.is_empty() || values.iter().any(|v| !v.is_finite()) {
            return Err(Error::invalid(
                "values",
                "needs at least one finite pull-off",
            ));
        }
        let mut sorted = values.clone();
        sorted.sort_by(f64::total_cmp);
        Ok(PullOffStatistics { values, sorted })
    }

    /// Number of populations.
    pub fn len(&self) -> usize {
        self.values.len()
    }

    /// Whether there are none (never, once built).
    pub fn is_empty(&self) -> bool {
        self.values.is_empty()
    }

    /// Mean (N).
    pub fn mean(&self) -> f64 {
        self.values.iter().sum::<f64>() / self.len() as f64
    }

    /// Sample standard deviation (N, divisor `n - 1`; 0 for one value).
    pub fn std(&self) -> f64 {
        let n = self.len() as f64;
        if self.len() < 2 {
            return 0.0;
        }
        let m = self.mean();
        (self.values.iter().map(|v| (v - m).powi(2)).sum::<f64>() / (n - 1.0)).sqrt()
    }

    /// Standard error of the mean, `std / sqrt(n)` (N).
    pub fn mean_standard_error(&self) -> f64 {
        self.std() / (self.len() as f64).sqrt()
    }

    /// The `q`-quantile (N), `q` in `[0, 1]`: linear interpolation between
    /// order statistics at `(n - 1) q` (Hyndman & Fan 1996, type 7; numpy's
    /// default). `q = 0.05` is the more tensile end. The rank position
    /// `(n - 1) q` is rounded to 1e-9 of a rank, so that levels equal but
    /// for roundoff (`1 - 0.95` and `0.05`) give the same bits.
    pub fn quantile(&self, q: f64) -> f64 {
        let n = self.sorted.len();
        let h = ((n - 1) as f64 * q.clamp(0.0, 1.0) * 1e9).round() / 1e9;
        let lo = h.floor() as usize;
        let hi = (lo + 1).min(n - 1);
        self.sorted[lo] + (h - lo as f64) * (self.sorted[hi] - self.sorted[lo])
    }

    /// A distribution-free interval (N) for the population's true
    /// `q`-quantile at [`INTERVAL_CONFIDENCE`]: the order statistics of the
    /// ranks [`quantile_ranks`] finds from the exact binomial distribution
    /// (the shortest pair whose coverage reaches the level), with that
    /// coverage; `Err` with the widest pair's coverage (the sample's
    /// minimum and maximum, [`widest_coverage`]) when no pair reaches it.
    pub fn quantile_interval(&self, q: f64) -> std::result::Result<QuantileInterval, f64> {
        let n = self.sorted.len();
        match quantile_ranks(n, q, INTERVAL_CONFIDENCE) {
            Some(r) => Ok(QuantileInterval {
                bounds: (self.sorted[r.lower - 1], self.sorted[r.upper - 1]),
                ranks: r,
            }),
            None => Err(widest_coverage(n, q)),
        }
    }

    /// The fraction of populations whose pull-off is more tensile than
    /// `-force` (N), with its Clopper–Pearson interval at
    /// [`INTERVAL_CONFIDENCE`] (exact binomial; Clopper & Pearson 1934).
    pub fn fraction_beyond(&self, force: f64) -> (f64, (f64, f64)) {
        let n = self.len() as u64;
        let k = self.values.iter().filter(|v| -**v > force).count() as u64;
        (
            k as f64 / n as f64,
            clopper_pearson(k, n, INTERVAL_CONFIDENCE),
        )
    }
}

/// The Clopper–Pearson interval of a binomial probability from `k`
/// successes in `n` trials at two-sided confidence `c`: the `(1-c)/2` and
/// `(1+c)/2` quantiles of `Beta(k, n - k + 1)` and `Beta(k + 1, n - k)`.
pub fn clopper_pearson(k: u64, n: u64, c: f64) -> (f64, f64) {
    use statrs::distribution::{Beta, ContinuousCDF};
    let a = 0.5 * (1.0 - c);
    let lo = if k == 0 {
        0.0
    } else {
        Beta::new(k as f64, (n - k + 1) as f64).map_or(0.0, |b| b.inverse_cdf(a))
    };
    let hi = if k == n {
        1.0
    } else {
        Beta::new((k + 1) as f64, (n - k) as f64).map_or(1.0, |b| b.inverse_cdf(1.0 - a))
    };
    (lo, hi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::heights::Gaussian;
    use crate::law::Jkr;
    use crate::montecarlo::PopulationSpec;

    fn setup() -> (PopulationSpec, SummitLaw, LoadingProgram) {
        let spec = PopulationSpec::new(2000, 5e-9, RadiusSpec::Fixed(1e-6), 1).unwrap();
        let law = SummitLaw::fixed(Arc::new(Jkr::new(1e-6, 4.8e10, 0.5).unwrap()), 1e-6).unwrap();
        let program = LoadingProgram::new(30e-9, 5e-9, 200).unwrap();
        (spec, law, program)
    }

    #[test]
    fn populations_equal_the_full_draws_seed_by_seed() {
        let (spec, law, program) = setup();
        let values =
            pull_off_populations(&spec, &Gaussian::new(), &law, &program, 1.0, 7, 3).unwrap();
        for (k, v) in values.iter().enumerate() {
            let mut s = spec;
            s.seed = 7 + k as u64;
            let full = Population::sample(&s, &Gaussian::new()).unwrap();
            let mc = MonteCarlo::new(Arc::new(full), law.clone()).unwrap();
            let curve = mc.curve(&program, &Observables::ALL).unwrap();
            let want = curve.sampled_pull_off().map_or(0.0, |p| p.load.min(0.0));
            assert_eq!(v.to_bits(), want.to_bits(), "seed {}", 7 + k);
            assert!(*v < 0.0);
        }
    }

    #[test]
    fn statistics_match_numpy_and_the_binomial() {
        let s = PullOffStatistics::new(vec![-4.0, -1.0, -3.0, -2.0, 0.0]).unwrap();
        // numpy: mean -2, std(ddof=1) 1.5811388300841898, percentile 5 -3.8
        assert_eq!(s.mean(), -2.0);
        assert!((s.std() - 1.581_138_830_084_189_8).abs() < 1e-15);
        assert!((s.quantile(0.05) + 3.8).abs() < 1e-15);
        // A level equal to 0.05 but for roundoff gives the same bits.
        assert_eq!(s.quantile(1.0 - 0.95).to_bits(), s.quantile(0.05).to_bits());
        assert_eq!(s.quantile(0.5), -2.0);
        let (p, (lo, hi)) = s.fraction_beyond(2.5);
        assert_eq!(p, 0.4);
        // scipy.stats.binomtest(2, 5).proportion_ci(method="exact"):
        // (0.0527449505, 0.8533672004)
        assert!((lo - 0.052_744_950_5).abs() < 1e-9 && (hi - 0.853_367_200_4).abs() < 1e-9);
    }
}
