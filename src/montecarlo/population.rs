//! Random summit populations: heights from any [`HeightDistribution`],
//! optionally lognormal radii, drawn reproducibly.
//!
//! **Heights** are drawn as sorted uniform order statistics mapped through
//! the quantile: with `E_1 .. E_(N+1)` independent standard exponentials and
//! `S_i = E_1 + .. + E_i`, the ratios `U_(i) = S_i / S_(N+1)` are distributed
//! exactly as the order statistics of `N` uniforms (Devroye, *Non-Uniform
//! Random Variate Generation*, 1986, §V.2), so `z_i = sigma Q(U_(i))` is an
//! exact sample of `N` summit heights, already ascending: no sort. Cost:
//! one logarithm and one quantile per summit.
//!
//! **Radii** (when asked) are lognormal, `R_i = R_med exp(s Z_i)` with `Z_i`
//! standard normal, independent of the heights (so they may be drawn in
//! height order).
//!
//! **Reproducibility**: the summits are cut into fixed blocks of
//! [`SAMPLING_BLOCK`]; block `b` draws its heights from its own xoshiro256++
//! generator (a portable algorithm) seeded from `(seed, b)`, and its radii
//! from another. The heights for a seed are therefore the same whatever the
//! radius spec, and scale exactly with `sigma`: sweeps over `sigma` or the
//! radius spread with one seed use common random numbers. The blocks run in
//! parallel, the prefix sums are combined in block order, so the same seed
//! gives bit-identical populations for any number of threads. Values can
//! change only if `rand_distr`'s normal sampler changes (radii) or the
//! distribution's quantile does.

use crate::error::{non_negative, positive, Error, Result};
use crate::gw::RoughSurface;
use crate::heights::HeightDistribution;
use crate::numeric::mix::splitmix64;
use rand::rngs::Xoshiro256PlusPlus;
use rand::{Rng, SeedableRng};
use rand_distr::{Distribution, StandardNormal};
use rayon::prelude::*;

/// Summits per sampling block; part of the definition of a seed's stream,
/// never to be changed.
pub const SAMPLING_BLOCK: usize = 4096;

/// Largest population [`Population::sample`] accepts (memory: 8 bytes per
/// summit, 16 with radii).
pub const MAX_SUMMITS: usize = 1 << 30;

/// How summit radii are distributed.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum RadiusSpec {
    /// Every summit has radius `R` (m), as in Greenwood–Williamson.
    Fixed(f64),
    /// `ln R` normal: `R = median exp(log_std Z)`, `Z ~ N(0, 1)`; median (m)
    /// finite and positive, `log_std` finite and non-negative (0 gives the
    /// fixed radius `median`). Mean radius `median exp(log_std^2/2)`.
    LogNormal {
        /// Median radius (m).
        median: f64,
        /// Standard deviation of `ln R`.
        log_std: f64,
    },
}

impl RadiusSpec {
    /// The radius the law is built for: the fixed radius or the median (m).
    pub fn reference(&self) -> f64 {
        match *self {
            RadiusSpec::Fixed(r) => r,
            RadiusSpec::LogNormal { median, .. } => median,
        }
    }

    fn validate(&self) -> Result<()> {
        match *self {
            RadiusSpec::Fixed(r) => positive("radius", r).map(|_| ()),
            RadiusSpec::LogNormal { median, log_std } => {
                positive("radius_median", median)?;
                non_negative("radius_log_std", log_std)?;
                Ok(())
            }
        }
    }
}

/// What to draw: how many summits, their height scale and radii, the seed.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct PopulationSpec {
    /// Number of summits `N`, in `[1, MAX_SUMMITS]`.
    pub summits: usize,
    /// Height scale `sigma` (m) applied to the standardised distribution.
    pub sigma: f64,
    /// Radii.
    pub radius: RadiusSpec,
    /// Seed: the same seed gives the same population.
    pub seed: u64,
}

impl PopulationSpec {
    /// Validates every field.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `summits`, `sigma`, `radius`,
    /// `radius_median` or `radius_log_std`.
    pub fn new(summits: usize, sigma: f64, radius: RadiusSpec, seed: u64) -> Result<Self> {
        let spec = PopulationSpec {
            summits,
            sigma,
            radius,
            seed,
        };
        spec.validate()?;
        Ok(spec)
    }

    /// One realisation of a surface: `N = round(eta A_n)` summits of radius
    /// `R` and height scale `sigma`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `summits` when `eta A_n` rounds to 0 or
    /// exceeds [`MAX_SUMMITS`] (simulate a smaller area and scale).
    pub fn from_surface(surface: &RoughSurface, seed: u64) -> Result<Self> {
        let n = surface.summits().round();
        check_count(n)?;
        PopulationSpec::new(
            n as usize,
            surface.sigma,
            RadiusSpec::Fixed(surface.radius),
            seed,
        )
    }

    fn validate(&self) -> Result<()> {
        check_count(self.summits as f64)?;
        positive("sigma", self.sigma)?;
        self.radius.validate()
    }
}

fn check_count(n: f64) -> Result<()> {
    crate::error::Allowed::closed(1.0, MAX_SUMMITS as f64).check("summits", n)?;
    Ok(())
}

/// A drawn population: summit heights (m) in ascending order and, for
/// non-fixed radii, each summit's radius (m).
#[derive(Debug, Clone, PartialEq)]
pub struct Population {
    heights: Vec<f64>,
    radii: Option<Vec<f64>>,
    reference_radius: f64,
}

impl Population {
    /// Draws `spec.summits` summits with standardised heights from
    /// `distribution`, scaled by `spec.sigma` (see the module notes).
    ///
    /// # Errors
    /// As [`PopulationSpec::new`]; [`Error::Invalid`] naming `distribution`
    /// if its quantile returns a non-finite height.
    pub fn sample(spec: &PopulationSpec, distribution: &dyn HeightDistribution) -> Result<Self> {
        Population::draw(spec, distribution, f64::NEG_INFINITY)
    }

    /// The population [`Population::sample`] draws, with only the summits
    /// at or above `min_height` (m) computed: the heights below it are
    /// stored as `-inf` (their quantiles are never evaluated), everything
    /// else, the random streams, the order and the radii included, is the
    /// full draw's. Sums over the summits a flat reaches at separations
    /// where the lower ones are out of range are bit for bit those of the
    /// full population.
    ///
    /// # Errors
    /// As [`Population::sample`].
    pub fn sample_above(
        spec: &PopulationSpec,
        distribution: &dyn HeightDistribution,
        min_height: f64,
    ) -> Result<Self> {
        Population::draw(spec, distribution, min_height)
    }

    fn draw(
        spec: &PopulationSpec,
        distribution: &dyn HeightDistribution,
        min_height: f64,
    ) -> Result<Self> {
        spec.validate()?;
        let n = spec.summits;
        let blocks = n.div_ceil(SAMPLING_BLOCK);
        let lognormal = match spec.radius {
            RadiusSpec::LogNormal { log_std, .. } if log_std > 0.0 => Some(log_std),
            _ => None,
        };
        let mut heights = vec![0.0; n];
        let mut radii = lognormal.map(|_| vec![0.0; n]);
        // Per block: local prefix sums of exponentials (and radii), in parallel.
        let fill = |b: usize, h: &mut [f64], r: Option<&mut [f64]>| -> f64 {
            let mut rng = block_rng(spec.seed, b as u64);
            let mut s = 0.0;
            for hj in h.iter_mut() {
                s += standard_exponential(&mut rng);
                *hj = s;
            }
            if let Some(r) = r {
                // Radii from their own stream: the heights do not depend on
                // the radius spec (common random numbers across sweeps).
                let mut rng = block_rng(spec.seed ^ RADIUS_STREAM, b as u64);
                let (med, ls) = (spec.radius.reference(), lognormal.unwrap_or(0.0));
                for rj in r.iter_mut() {
                    let z: f64 = StandardNormal.sample(&mut rng);
                    *rj = med * (ls * z).exp();
                }
            }
            s
        };
        let totals: Vec<f64> = match radii.as_mut() {
            Some(r) => heights
                .par_chunks_mut(SAMPLING_BLOCK)
                .zip(r.par_chunks_mut(SAMPLING_BLOCK))
                .enumerate()
                .map(|(b, (h, r))| fill(b, h, Some(r)))
                .collect(),
            None => heights
                .par_chunks_mut(SAMPLING_BLOCK)
                .enumerate()
                .map(|(b, h)| fill(b, h, None))
                .collect(),
        };
        // Block offsets in block order, then the (N+1)-th exponential from
        // its own stream (block index `blocks`).
        let mut offsets = Vec::with_capacity(blocks);
        let mut acc = 0.0;
        for t in &totals {
            offsets.push(acc);
            acc += t;
        }
        let total = acc + standard_exponential(&mut block_rng(spec.seed, blocks as u64));
        // U_(i) = S_i / S_(N+1) < 1 in exact arithmetic; keep it below 1 in
        // floating point so the quantile stays finite.
        const BELOW_ONE: f64 = 1.0 - f64::EPSILON / 2.0;
        let sigma = spec.sigma;
        // Summits below `min_height` (u below `u_min`) are not computed;
        // the margin keeps every summit whose quantile could round to or
        // above the bound.
        let u_min = if min_height == f64::NEG_INFINITY {
            -1.0
        } else {
            (1.0 - distribution.tail(min_height / sigma)) * (1.0 - 1e-12) - 1e-300
        };
        heights
            .par_chunks_mut(SAMPLING_BLOCK)
            .zip(offsets.par_iter())
            .for_each(|(h, &off)| {
                for hj in h.iter_mut() {
                    let u = ((off + *hj) / total).min(BELOW_ONE);
                    *hj = if u >= u_min {
                        sigma * distribution.quantile(u)
                    } else {
                        f64::NEG_INFINITY
                    };
                }
            });
        if let Some(bad) = heights
            .iter()
            .find(|z| !z.is_finite() && **z != f64::NEG_INFINITY)
        {
            return Err(Error::invalid(
                "distribution",
                format!(
                    "quantile of {} gave a non-finite height ({bad})",
                    distribution.name()
                ),
            ));
        }
        // A quantile that is not exactly monotone in floating point would
        // break the ordering; restore it (rare, deterministic).
        if !heights.is_sorted() {
            sort_together(&mut heights, radii.as_mut());
        }
        Ok(Population {
            heights,
            radii,
            reference_radius: spec.radius.reference(),
        })
    }

    /// A population from given summit heights (m, any order) and either one
    /// radius or one radius per summit (m). Useful for measured summits.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `heights` when empty or `radii` when the
    /// lengths differ; [`Error::OutOfRange`] naming `heights[i]` (not
    /// finite), `radius` or `radii[i]` (not finite and > 0).
    pub fn from_summits(heights: Vec<f64>, radii: Radii) -> Result<Self> {
        let mut heights = heights;
        if heights.is_empty() {
            return Err(Error::invalid("heights", "no summits"));
        }
        check_count(heights.len() as f64)?;
        for (i, &z) in heights.iter().enumerate() {
            crate::error::finite(&format!("heights[{i}]"), z)?;
        }
        let (mut radii, reference_radius) = match radii {
            Radii::Fixed(r) => (None, positive("radius", r)?),
            Radii::PerSummit(r) => {
                if r.len() != heights.len() {
                    return Err(Error::invalid(
                        "radii",
                        format!("{} radii for {} heights", r.len(), heights.len()),
                    ));
                }
                for (i, &x) in r.iter().enumerate() {
                    positive(&format!("radii[{i}]"), x)?;
                }
                let reference = geometric_mean(&r);
                (Some(r), reference)
            }
        };
        sort_together(&mut heights, radii.as_mut());
        Ok(Population {
            heights,
            radii,
            reference_radius,
        })
    }

    /// Number of summits.
    pub fn len(&self) -> usize {
        self.heights.len()
    }

    /// Always `false`: a population has at least one summit.
    pub fn is_empty(&self) -> bool {
        self.heights.is_empty()
    }

    /// Summit heights (m), ascending.
    pub fn heights(&self) -> &[f64] {
        &self.heights
    }

    /// Per-summit radii (m), aligned with [`heights`](Population::heights);
    /// `None` when every summit has the [reference radius](Population::reference_radius).
    pub fn radii(&self) -> Option<&[f64]> {
        self.radii.as_deref()
    }

    /// The fixed radius, or the radius laws are built for when radii vary
    /// (the lognormal median; the geometric mean for given radii) (m).
    pub fn reference_radius(&self) -> f64 {
        self.reference_radius
    }

    /// Radius of summit `i` (m).
    pub fn radius(&self, i: usize) -> f64 {
        self.radii.as_ref().map_or(self.reference_radius, |r| r[i])
    }
}

/// Radii for [`Population::from_summits`].
#[derive(Debug, Clone, PartialEq)]
pub enum Radii {
    /// One radius (m) for every summit.
    Fixed(f64),
    /// One radius (m) per summit, in the order of the heights.
    PerSummit(Vec<f64>),
}

fn geometric_mean(r: &[f64]) -> f64 {
    (r.iter().map(|x| x.ln()).sum::<f64>() / r.len() as f64).exp()
}

fn sort_together(heights: &mut [f64], radii: Option<&mut Vec<f64>>) {
    match radii {
        None => heights.par_sort_unstable_by(f64::total_cmp),
        Some(r) => {
            // Full-key comparison: equal keys are identical, so the unstable
            // sort is still deterministic.
            let mut pairs: Vec<(f64, f64)> =
                heights.iter().copied().zip(r.iter().copied()).collect();
            pairs.par_sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
            for (i, (z, x)) in pairs.into_iter().enumerate() {
                heights[i] = z;
                r[i] = x;
            }
        }
    }
}

/// Seed offset of the radius streams (distinct from every height stream).
const RADIUS_STREAM: u64 = 0x5241_4449_5553_0001;

/// The generator of block `b` for `seed`: xoshiro256++ seeded from a hash of
/// both (distinct `(seed, b)` give unrelated streams).
pub(crate) fn block_rng(seed: u64, b: u64) -> Xoshiro256PlusPlus {
    Xoshiro256PlusPlus::seed_from_u64(splitmix64(splitmix64(seed) ^ b))
}

/// Uniform on the open interval `(0, 1)`: `(k + 1/2) 2^-53` from the top 53
/// bits (portable, never 0 or 1).
#[inline]
pub(crate) fn open_uniform(rng: &mut impl Rng) -> f64 {
    ((rng.next_u64() >> 11) as f64 + 0.5) * (1.0 / (1u64 << 53) as f64)
}

/// Standard exponential `-ln U`, `U` open uniform: always finite and > 0.
#[inline]
pub(crate) fn standard_exponential(rng: &mut impl Rng) -> f64 {
    -open_uniform(rng).ln()
}
