//! Random summit populations: heights from any [`HeightDistribution`],
//! optionally lognormal radii, drawn reproducibly.
//!
//! **Heights** are drawn from the top down as sorted order statistics
//! (Rényi's representation): with `E_1 .. E_N` independent standard
//! exponentials and `S_k = E_1/N + E_2/(N - 1) + .. + E_k/(N - k + 1)`,
//! the `k`-th highest of `N` uniforms is distributed exactly as
//! `exp(-S_k)` (Rényi 1953; Devroye, *Non-Uniform Random Variate
//! Generation*, 1986, §V.3), so the `k`-th highest summit is
//! `z_k = sigma Q_up(1 - exp(-S_k))`, `Q_up` the upper quantile (the
//! height with that probability above it; its argument `-expm1(-S_k)` is
//! exact where it is small, the quantile of `exp(-S_k)` is taken in the
//! lower half). An exact sample of `N` heights, already sorted, and its
//! highest summits come first: the summits above a height are drawn
//! without the rest ([`Population::sample_above`]), at a cost that does
//! not grow with `N`. Cost: a logarithm, an exponential and a quantile
//! per summit drawn.
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
//! gives bit-identical populations for any number of threads, and its
//! highest summits drawn alone are bit for bit those of the full draw. Values can
//! change only if `rand_distr`'s normal sampler changes (radii) or the
//! distribution's quantile does.

use crate::error::{non_negative, positive, Error, Result};
use crate::gw::RoughSurface;
use crate::heights::HeightDistribution;
use crate::numeric::mix::{derive_seed, Stream};
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
/// non-fixed radii, each summit's radius (m); when drawn above a height
/// ([`Population::sample_above`]), the number of summits below it, not
/// stored.
#[derive(Debug, Clone, PartialEq)]
pub struct Population {
    heights: Vec<f64>,
    omitted: usize,
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

    /// The summits of the population [`Population::sample`] draws that are
    /// at or above `min_height` (m), bit for bit (heights and radii), the
    /// others only counted ([`Population::omitted`]); at least the highest
    /// is kept. Only these are drawn: the cost is that of the summits kept,
    /// whatever `N`. Sums over the summits a flat reaches at separations
    /// where the lower ones are out of range are those of the full
    /// population.
    ///
    /// # Errors
    /// As [`Population::sample`]; [`Error::Invalid`] naming `min_height`
    /// for NaN.
    pub fn sample_above(
        spec: &PopulationSpec,
        distribution: &dyn HeightDistribution,
        min_height: f64,
    ) -> Result<Self> {
        if min_height.is_nan() {
            return Err(Error::invalid(
                "min_height",
                "a height (m) or -inf for every summit, not NaN",
            ));
        }
        Population::draw(spec, distribution, min_height)
    }

    fn draw(
        spec: &PopulationSpec,
        distribution: &dyn HeightDistribution,
        min_height: f64,
    ) -> Result<Self> {
        spec.validate()?;
        let n = spec.summits;
        let lognormal = match spec.radius {
            RadiusSpec::LogNormal { log_std, .. } if log_std > 0.0 => Some(log_std),
            _ => None,
        };
        // A summit is at or above `min_height` when its S is at most
        // `-ln P(S <= min_height)`; the margin keeps every summit whose
        // height could round to or above the bound.
        let s_max = if min_height == f64::NEG_INFINITY {
            f64::INFINITY
        } else {
            let q = distribution.tail(min_height / spec.sigma);
            -(-q).ln_1p() * (1.0 + 1e-12) + 1e-300
        };
        // S_k of the summits from the top (rank 0 the highest): per block,
        // its partial sums and the offset of the blocks above it.
        let (mut top, offsets) = if s_max == f64::INFINITY {
            every_rank(spec)
        } else {
            (ranks_up_to(spec, s_max), Vec::new())
        };
        let mut radii = lognormal.map(|ls| radii_from_the_top(spec, ls, top.len()));
        let sigma = spec.sigma;
        top.par_chunks_mut(SAMPLING_BLOCK)
            .enumerate()
            .for_each(|(b, h)| {
                // (`S + 0.0 = S`: the partial draw's sums are complete.)
                let off = offsets.get(b).copied().unwrap_or(0.0);
                for hj in h.iter_mut() {
                    *hj = sigma * height_of_rank(distribution, *hj + off);
                }
            });
        if let Some(bad) = top.iter().find(|z| !z.is_finite()) {
            return Err(Error::invalid(
                "distribution",
                format!(
                    "quantile of {} gave a non-finite height ({bad})",
                    distribution.name()
                ),
            ));
        }
        // Stored ascending.
        top.reverse();
        if let Some(r) = radii.as_mut() {
            r.reverse();
        }
        let mut heights = top;
        // A quantile that is not exactly monotone in floating point would
        // break the ordering; restore it (rare, deterministic).
        if !heights.is_sorted() {
            sort_together(&mut heights, radii.as_mut());
        }
        Ok(Population {
            omitted: n - heights.len(),
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
            omitted: 0,
            radii,
            reference_radius,
        })
    }

    /// Number of summits stored (every summit, unless drawn
    /// [above a height](Population::sample_above)).
    pub fn len(&self) -> usize {
        self.heights.len()
    }

    /// Summits of the draw below the height it was drawn above, not stored
    /// (0 for a full draw).
    pub fn omitted(&self) -> usize {
        self.omitted
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

/// The generator of `stream` for `seed`: xoshiro256++ seeded by
/// [`derive_seed`] (distinct `(seed, block)` give unrelated streams).
pub(crate) fn block_rng(seed: u64, stream: Stream) -> Xoshiro256PlusPlus {
    Xoshiro256PlusPlus::seed_from_u64(derive_seed(seed, stream))
}

/// `S_k` (see the module notes) of every summit of `spec`, from the top,
/// as each block's own prefix sums of `E_i/(N - i)` (in parallel) and the
/// blocks' offsets (their totals added in block order): `S_k` is the
/// block's sum plus its offset.
fn every_rank(spec: &PopulationSpec) -> (Vec<f64>, Vec<f64>) {
    let n = spec.summits;
    let mut local = vec![0.0; n];
    let totals: Vec<f64> = local
        .par_chunks_mut(SAMPLING_BLOCK)
        .enumerate()
        .map(|(b, h)| {
            let mut rng = block_rng(spec.seed, Stream::HeightBlock(b as u64));
            let rest = n - b * SAMPLING_BLOCK;
            let mut s = 0.0;
            for (j, hj) in h.iter_mut().enumerate() {
                s += standard_exponential(&mut rng) / (rest - j) as f64;
                *hj = s;
            }
            s
        })
        .collect();
    let mut offsets = Vec::with_capacity(totals.len());
    let mut acc = 0.0;
    for t in &totals {
        offsets.push(acc);
        acc += t;
    }
    (local, offsets)
}

/// The first `S_k` of [`every_rank`], bit for bit, while they are at most
/// `s_max` (at least one): the same streams, sums and offsets, stopped
/// at the first summit below.
fn ranks_up_to(spec: &PopulationSpec, s_max: f64) -> Vec<f64> {
    let n = spec.summits;
    let mut s_k = Vec::new();
    let mut off = 0.0;
    for b in 0..n.div_ceil(SAMPLING_BLOCK) {
        let mut rng = block_rng(spec.seed, Stream::HeightBlock(b as u64));
        let rest = n - b * SAMPLING_BLOCK;
        let mut s = 0.0;
        for j in 0..rest.min(SAMPLING_BLOCK) {
            s += standard_exponential(&mut rng) / (rest - j) as f64;
            let at = s + off;
            if at > s_max && !s_k.is_empty() {
                return s_k;
            }
            s_k.push(at);
        }
        off += s;
    }
    s_k
}

/// Lognormal radii of the `count` highest summits of `spec`, in rank
/// order: block `b`'s from its own stream (independent of the heights').
fn radii_from_the_top(spec: &PopulationSpec, log_std: f64, count: usize) -> Vec<f64> {
    let med = spec.radius.reference();
    let mut r = vec![0.0; count];
    r.par_chunks_mut(SAMPLING_BLOCK)
        .enumerate()
        .for_each(|(b, rb)| {
            let mut rng = block_rng(spec.seed, Stream::RadiusBlock(b as u64));
            for rj in rb.iter_mut() {
                let z: f64 = StandardNormal.sample(&mut rng);
                *rj = med * (log_std * z).exp();
            }
        });
    r
}

/// The standardised height of the summit whose upper-tail probability is
/// `1 - exp(-s_k)`: from the upper quantile of `-expm1(-s_k)` in the top
/// half, from the quantile of `exp(-s_k)` below (each argument exact to
/// roundoff in its half).
#[inline]
fn height_of_rank(distribution: &dyn HeightDistribution, s_k: f64) -> f64 {
    if s_k <= std::f64::consts::LN_2 {
        distribution.quantile_upper(-(-s_k).exp_m1())
    } else {
        distribution.quantile((-s_k).exp())
    }
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
