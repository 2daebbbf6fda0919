//! Exact sums of a law over a population, with their standard errors.
//!
//! At separation `d` summit `i` (height `z_i`, radius `R_i`) has
//! interference `delta_i = z_i - d`; its state follows the loading history
//! exactly: on approach `state(delta_i, Approach)`; on retraction after the
//! flat came to `d_min`, `state_after(delta_i, z_i - d_min)`. The totals
//! `P = sum P_i`, `A = sum pi a_i^2`, `n = #{a_i > 0}` are exact for the
//! drawn population; as estimates of the Greenwood–Williamson expectation
//! (`N E[x]`) each carries the standard error `sqrt(N s^2)`, `s^2` the
//! sample variance of the per-summit values (zeros included).
//!
//! **Skipping.** Heights are sorted, so the summits that can contribute
//! (`delta_i >= cutoff_interference`, rescaled per radius) are a suffix
//! found by binary search; the rest are never touched.
//!
//! **Determinism.** The suffix is cut at fixed multiples of [`SUM_BLOCK`];
//! blocks of every step are summed in parallel, each sequentially, and the
//! block partials of a step are added in block order. Results are
//! bit-identical for any number of threads.
//!
//! **Speed.** Inside a block the law is called once per chunk of
//! [`CHUNK`] summits ([`LawKernels::state_batch`](crate::law::LawKernels::state_batch):
//! one virtual call per chunk, not per summit), and the six sums (load,
//! area, count and their squares) run in [`LANES`] independent lanes:
//! summit `i` of a chunk adds to lane `i mod LANES`, and the lanes are
//! combined in a fixed tree at the end of the block. Rust never reorders
//! floating-point additions, so the result is the same whatever SIMD width
//! the CPU offers (picked at run time by [`pulp::Arch`]); the sums differ
//! from a single sequential accumulator only by the rounding of a
//! different (8-way interleaved) order. Fewer than [`SERIAL_BELOW`]
//! evaluations per call run on the calling thread (same blocks, same
//! order, same bits): below it rayon's start-up costs more than it saves.

use super::population::Population;
use super::scaling::SummitLaw;
use crate::error::{finite, Error, Result};
use crate::law::{Branch, Prepared};
use crate::loading::{History, LoadingModel, MethodUsed, Observables, State, Totals, SLOTS};
use rayon::prelude::*;

mod bounds;
mod lanes;
pub use bounds::RetractionBounds;
use lanes::{Accumulator, Buffers};
use std::sync::Arc;

/// Summits per summation block (fixed: part of the reduction order).
pub const SUM_BLOCK: usize = 8192;

/// Summits per law call inside a block (stack buffers, L1-resident).
pub const CHUNK: usize = 256;

/// Accumulator lanes (fixed: part of the reduction order;
/// [`StateSums`](crate::numeric::lanes::StateSums)' lanes).
pub const LANES: usize = crate::numeric::lanes::STATE_LANES;

/// Law evaluations (summits in range times steps) below which a call runs
/// serially. Measured (`benches/montecarlo.rs`, `mc_small`): see
/// docs/performance.md.
pub const SERIAL_BELOW: usize = 1 << 16;

/// Per-summit rescaling factors `[rho^-alpha, rho^beta, rho^gamma]`.
#[derive(Debug, Clone)]
enum Factors {
    Uniform([f64; 3]),
    PerSummit(Vec<[f64; 3]>),
}

/// A population bound to a law: sums over the summits.
#[derive(Debug, Clone)]
pub struct MonteCarlo {
    population: Arc<Population>,
    law: SummitLaw,
    factors: Factors,
    /// Smallest and largest `rho^-alpha` (for the range search).
    inv_len: (f64, f64),
}

/// Partial sums of one block: values and squares per slot (load, area and
/// count always, in slots 0-2; further observables after them).
#[derive(Debug, Clone, Copy, Default)]
struct Partial {
    sum: [f64; SLOTS],
    sq: [f64; SLOTS],
}

impl Partial {
    fn add(&mut self, p: &Partial) {
        for i in 0..SLOTS {
            self.sum[i] += p.sum[i];
            self.sq[i] += p.sq[i];
        }
    }
}

impl MonteCarlo {
    /// Binds `law` to `population`, precomputing each summit's radius
    /// factors; a law marked for tabulation ([`SummitLaw::from_kind`] of
    /// an expensive kind) is tabulated here.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `radius` when summit radii differ from the
    /// law's reference radius and the law has no radius scaling.
    pub fn new(population: Arc<Population>, law: SummitLaw) -> Result<Self> {
        let factors = match population.radii() {
            None => Factors::Uniform(law.factors_for(population.reference_radius())?),
            Some(r) => Factors::PerSummit(
                r.par_iter()
                    .map(|&x| law.factors_for(x))
                    .collect::<Result<Vec<_>>>()?,
            ),
        };
        let inv_len = match &factors {
            Factors::Uniform(f) => (f[0], f[0]),
            Factors::PerSummit(v) => v.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), f| {
                (lo.min(f[0]), hi.max(f[0]))
            }),
        };
        // An expensive law becomes a table over the interferences this
        // population reaches down to its lowest summit (see `SummitLaw`).
        let law = if law.table_tolerance().is_some() {
            let z = population.heights();
            let range = z[z.len() - 1] - z[0];
            let lo = law.law().cutoff_interference();
            law.tabulated_on(lo, lo.max(0.0) + range * inv_len.1)?
        } else {
            law
        };
        Ok(MonteCarlo {
            population,
            law,
            factors,
            inv_len,
        })
    }

    /// The population.
    pub fn population(&self) -> &Population {
        &self.population
    }

    /// The law.
    pub fn law(&self) -> &SummitLaw {
        &self.law
    }

    /// Summits the law is evaluated for at separation `d` (m): those within
    /// its reach (all of them for a law without a cutoff).
    pub fn summits_in_range(&self, d: f64) -> usize {
        self.population.len() - self.first_in_range(d)
    }

    /// Index of the first summit that can contribute at separation `d`.
    fn first_in_range(&self, d: f64) -> usize {
        self.first_above(d, self.law.law().cutoff_interference())
    }

    /// Index of the first summit with `delta rho^-alpha >= cut` possible,
    /// using the loosest factor (a superset of the summits that pass).
    fn first_above(&self, d: f64, cut: f64) -> usize {
        if cut == f64::NEG_INFINITY {
            return 0;
        }
        let inv = if cut < 0.0 {
            self.inv_len.0
        } else {
            self.inv_len.1
        };
        self.population
            .heights()
            .partition_point(|&z| (z - d) * inv < cut)
    }

    /// Runs any sequence of separations (m), in order, starting with every
    /// summit free (the flat far away): a general program (partial
    /// retractions, re-approach, cycles). Each summit keeps an attached flag:
    /// it attaches when its interference reaches the law's
    /// [`attach_interference`](crate::law::AsperityLaw::attach_interference),
    /// detaches below its
    /// [`detach_interference`](crate::law::AsperityLaw::detach_interference),
    /// and is evaluated on the `Retract` branch while attached, `Approach`
    /// otherwise. For approach-then-retract this reproduces
    /// [`MonteCarlo::curve`] bit for bit for laws with the default
    /// `state_after` (Hertz, DMT, JKR). Cost: one byte per summit and one
    /// flag update per evaluation; steps run one after another, the
    /// summits of a step in parallel.
    ///
    /// Laws that [remember their maximum
    /// interference](crate::law::AsperityLaw::remembers_maximum) (plastic
    /// laws, [`AdhesivePlastic`](crate::law::plastic::AdhesivePlastic))
    /// keep it per summit instead of the flag (8 bytes per summit), as
    /// [`MaxInterference::step`](crate::law::plastic::MaxInterference::step):
    /// at a new maximum the virgin curve `state(delta, Approach)`, below it
    /// `state_after(delta, delta_max)`; the flattening is permanent, so a
    /// second loading cycle retraces the unloading curve (elastic
    /// shakedown) and differs from the first. Approach-then-retract again
    /// equals [`MonteCarlo::curve`] bit for bit.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `separations[i]` when not finite; as
    /// [`MonteCarlo::state`] otherwise.
    pub fn sequence(&self, separations: &[f64], observables: &Observables) -> Result<Vec<State>> {
        for (i, &d) in separations.iter().enumerate() {
            finite(&format!("separations[{i}]"), d)?;
        }
        let law = self.law.law();
        let (attach, detach) = (law.attach_interference(), law.detach_interference());
        // Below both the cutoff and the detach point a summit is free and
        // detached: it is neither evaluated nor flagged.
        let cut = law.cutoff_interference().min(detach);
        let n = self.population.len();
        // Per summit: the attached flag, or (laws that remember it) the
        // largest interference so far, -inf before any contact.
        let mut memory = if law.remembers_maximum() {
            Memory::Maximum(vec![f64::NEG_INFINITY; n])
        } else {
            Memory::Attached(vec![false; n])
        };
        let mut prev_lo = n;
        let mut out = Vec::with_capacity(separations.len());
        for &d in separations {
            let lo = self.first_above(d, cut);
            if lo > prev_lo {
                // Summits that left the range are detached; a maximum
                // interference (plastic flattening) is permanent.
                if let Memory::Attached(a) = &mut memory {
                    a[prev_lo..lo].fill(false);
                }
            }
            prev_lo = lo;
            let serial = n - lo < SERIAL_BELOW;
            let one = |(b, mem): (usize, MemoryChunk<'_>)| {
                let base = b * SUM_BLOCK;
                let start = base.max(lo);
                let end = base + mem.len();
                self.block_flagged(
                    start,
                    end,
                    mem.tail(start - base),
                    d,
                    (attach, detach),
                    observables,
                )
            };
            let partials = match &mut memory {
                Memory::Attached(a) => block_partials(a, MemoryChunk::Attached, lo, serial, one),
                Memory::Maximum(m) => block_partials(m, MemoryChunk::Maximum, lo, serial, one),
            };
            let mut total = Partial::default();
            for p in &partials {
                total.add(p);
            }
            out.push(self.finish(d, &total, lo, observables)?);
        }
        Ok(out)
    }

    /// Sums summits `a..b` at `d`, updating their memory (attached flags,
    /// or maximum interferences).
    fn block_flagged(
        &self,
        a: usize,
        b: usize,
        mut memory: MemoryChunk<'_>,
        d: f64,
        (attach, detach): (f64, f64),
        extras: &Observables,
    ) -> Partial {
        let z = &self.population.heights()[a..b];
        let law = self.law.law();
        let mut acc = Accumulator::default();
        let mut buf = Buffers::new();
        for (c, zc) in z.chunks(CHUNK).enumerate() {
            let off = c * CHUNK;
            let f = self.chunk_factors(a + off, zc.len());
            for (i, &zi) in zc.iter().enumerate() {
                let fi = f.at(i);
                let x = (zi - d) * fi[0];
                let st = match &mut memory {
                    MemoryChunk::Attached(flags) => {
                        let flag = &mut flags[off + i];
                        if *flag {
                            *flag = !(x < detach);
                        } else {
                            *flag = x >= attach;
                        }
                        let branch = if *flag {
                            Branch::Retract
                        } else {
                            Branch::Approach
                        };
                        law.state(x, branch)
                    }
                    // As `plastic::MaxInterference::step`: the virgin curve
                    // at a new maximum, the history branch below it.
                    MemoryChunk::Maximum(max) => {
                        let m = &mut max[off + i];
                        if x >= *m {
                            *m = x;
                            law.state(x, Branch::Approach)
                        } else {
                            law.state_after(x, *m)
                        }
                    }
                };
                buf.load[i] = st.load * fi[1];
                buf.radius[i] = st.radius * fi[2];
            }
            acc.add_chunk(&mut buf, zc.len(), extras);
        }
        acc.finish()
    }

    /// The radius factors of summits `a..a + n`.
    #[inline]
    fn chunk_factors(&self, a: usize, n: usize) -> ChunkFactors<'_> {
        match &self.factors {
            Factors::Uniform(f) => ChunkFactors::Uniform(*f),
            Factors::PerSummit(v) => ChunkFactors::PerSummit(&v[a..a + n]),
        }
    }

    /// All steps, block-major: each block of summits (64 KiB of heights,
    /// cache-resident) is evaluated for every step that reaches it, blocks
    /// in parallel; then each step adds its block partials in block order.
    fn run(&self, steps: &[(f64, History)], observables: &Observables) -> Result<Vec<State>> {
        let n = self.population.len();
        let firsts: Vec<usize> = steps.iter().map(|&(d, _)| self.first_in_range(d)).collect();
        let lowest = firsts.iter().copied().min().unwrap_or(n);
        let first_block = lowest / SUM_BLOCK;
        let blocks = n.div_ceil(SUM_BLOCK);
        // partials[b - first_block][k]: block b at step k (zero if unreached).
        let one = |b: usize| -> Vec<Partial> {
            let (start, end) = (b * SUM_BLOCK, ((b + 1) * SUM_BLOCK).min(n));
            let prepared = self.prepare_block(start, end, steps, &firsts);
            steps
                .iter()
                .zip(&firsts)
                .map(|(&(d, history), &lo)| {
                    if lo >= end {
                        return Partial::default();
                    }
                    let a = start.max(lo);
                    let prep = match (&prepared, history) {
                        (Some(p), History::Retract { closest })
                            if closest.to_bits() == p.closest.to_bits() && a >= p.from =>
                        {
                            Some(&p.words[a - p.from..])
                        }
                        _ => None,
                    };
                    self.block(a, end, d, history, observables, prep)
                })
                .collect()
        };
        let work: usize = firsts.iter().map(|&lo| n - lo).sum();
        let partials: Vec<Vec<Partial>> = if work < SERIAL_BELOW {
            (first_block..blocks).map(one).collect()
        } else {
            (first_block..blocks).into_par_iter().map(one).collect()
        };
        let mut states = Vec::with_capacity(steps.len());
        for (k, (&(d, _), &lo)) in steps.iter().zip(&firsts).enumerate() {
            let mut total = Partial::default();
            for (i, block) in partials.iter().enumerate() {
                if (first_block + i + 1) * SUM_BLOCK > lo {
                    total.add(&block[k]);
                }
            }
            states.push(self.finish(d, &total, lo, observables)?);
        }
        Ok(states)
    }

    /// The law's words of each summit's history after the first retraction
    /// step's closest approach, for the summits of block `start..end` that
    /// any retraction step after that approach reaches: computed once here
    /// instead of once per step ([`LawKernels::prepare_after`]: a plastic
    /// summit's unloading shape). `None` for laws that prepare nothing.
    fn prepare_block(
        &self,
        start: usize,
        end: usize,
        steps: &[(f64, History)],
        firsts: &[usize],
    ) -> Option<PreparedBlock> {
        let law = self.law.law();
        if !law.prepares_history() || law.reversible() {
            return None;
        }
        let closest = steps.iter().find_map(|&(_, h)| match h {
            History::Retract { closest } => Some(closest),
            History::Approach => None,
        })?;
        let from = steps
            .iter()
            .zip(firsts)
            .filter(|&(&(_, h), &lo)| {
                lo < end
                    && matches!(h, History::Retract { closest: c } if c.to_bits() == closest.to_bits())
            })
            .map(|(_, &lo)| start.max(lo))
            .min()?;
        let z = &self.population.heights()[from..end];
        let mut delta_max = vec![0.0; z.len()];
        self.chunk_factors(from, z.len())
            .interferences(z, closest, &mut delta_max);
        let mut words = vec![[0.0; 4]; z.len()];
        law.prepare_after(&delta_max, &mut words);
        Some(PreparedBlock {
            closest,
            from,
            words,
        })
    }

    /// The state from a step's total; an error if the load is not finite.
    fn finish(&self, d: f64, t: &Partial, first: usize, obs: &Observables) -> Result<State> {
        let n = self.population.len();
        let nf = n as f64;
        if !t.sum[0].is_finite() || !t.sum[1].is_finite() {
            return Err(Error::invalid(
                "separation",
                format!(
                    "at {d:e} m a summit passes the maximum interference of law {} \
                     ({:e} m): the load is infinite",
                    self.law.law().name(),
                    self.law.law().max_interference()
                ),
            ));
        }
        // One summit has no sample variance: the standard error is
        // undefined (NaN, which `Totals::error` reports as `None`).
        let se = std::array::from_fn(|i| {
            if n < 2 {
                return f64::NAN;
            }
            let var = (t.sq[i] - t.sum[i] * t.sum[i] / nf).max(0.0) / (nf - 1.0);
            (nf * var).sqrt()
        });
        Ok(State {
            separation: d,
            totals: Totals::new(t.sum, se, obs.mask()),
            method: MethodUsed::Population,
            evaluations: n - first,
        })
    }

    /// Sums over summits `a..b` at separation `d`: per chunk, the
    /// interferences, one batch call of the law, the radius factors, the
    /// lane sums.
    fn block(
        &self,
        a: usize,
        b: usize,
        d: f64,
        history: History,
        obs: &Observables,
        prepared: Option<&[Prepared]>,
    ) -> Partial {
        let z = &self.population.heights()[a..b];
        let law = self.law.law();
        let closest = match history {
            // A reversible law retracts along its approach: no maximum
            // interferences to compute.
            History::Retract { .. } if law.reversible() => None,
            History::Approach => None,
            History::Retract { closest } => Some(closest),
        };
        let mut acc = Accumulator::default();
        let mut buf = Buffers::new();
        for (c, zc) in z.chunks(CHUNK).enumerate() {
            let n = zc.len();
            let f = self.chunk_factors(a + c * CHUNK, n);
            if let (None, ChunkFactors::Uniform([scale, 1.0, 1.0]), Some((k, c)), true) =
                (closest, f, law.root_monomials(), obs.extras().is_empty())
            {
                // Hertz at the law's own radius: the state inside the lane
                // sums, one pass over the heights.
                acc.add_root_monomials(zc, d, scale, k, c);
                continue;
            }
            if let (ChunkFactors::Uniform([scale, 1.0, 1.0]), true, true) = (
                f,
                obs.extras().is_empty(),
                closest.is_none() || prepared.is_none(),
            ) {
                if acc.add_law_states(law, zc, d, closest, scale) {
                    // A law that sums its own states (a table): no
                    // interference, load or radius buffers.
                    continue;
                }
            }
            f.interferences(zc, d, &mut buf.delta[..n]);
            if let Some(m) = closest {
                f.interferences(zc, m, &mut buf.delta_max[..n]);
            }
            let Buffers {
                delta,
                delta_max,
                load,
                radius,
            } = &mut buf;
            match (closest, prepared) {
                (Some(_), Some(p)) => law.state_batch_prepared(
                    &delta[..n],
                    &delta_max[..n],
                    &p[c * CHUNK..c * CHUNK + n],
                    &mut load[..n],
                    &mut radius[..n],
                ),
                _ => law.state_batch(
                    &delta[..n],
                    closest.map(|_| &delta_max[..n]),
                    &mut load[..n],
                    &mut radius[..n],
                ),
            }
            f.scale(&mut load[..n], &mut radius[..n]);
            acc.add_chunk(&mut buf, n, obs);
        }
        acc.finish()
    }
}

/// [`MonteCarlo::prepare_block`]'s words, for summits `from..` of a block.
struct PreparedBlock {
    closest: f64,
    from: usize,
    words: Vec<Prepared>,
}

/// Per-summit history of a [`MonteCarlo::sequence`].
enum Memory {
    Attached(Vec<bool>),
    Maximum(Vec<f64>),
}

/// `one` of every [`SUM_BLOCK`] block of `v` (as a [`MemoryChunk`] by
/// `wrap`, with its block index) from the block of summit `lo` on, in
/// block order: on this thread when `serial`, else in parallel (the same
/// partials either way).
fn block_partials<'a, T: Send>(
    v: &'a mut [T],
    wrap: fn(&'a mut [T]) -> MemoryChunk<'a>,
    lo: usize,
    serial: bool,
    one: impl Fn((usize, MemoryChunk<'a>)) -> Partial + Sync + Send,
) -> Vec<Partial> {
    if serial {
        v.chunks_mut(SUM_BLOCK)
            .map(wrap)
            .enumerate()
            .skip(lo / SUM_BLOCK)
            .map(one)
            .collect()
    } else {
        v.par_chunks_mut(SUM_BLOCK)
            .map(wrap)
            .enumerate()
            .skip(lo / SUM_BLOCK)
            .map(one)
            .collect()
    }
}

/// One block of a [`Memory`].
enum MemoryChunk<'a> {
    Attached(&'a mut [bool]),
    Maximum(&'a mut [f64]),
}

impl<'a> MemoryChunk<'a> {
    fn len(&self) -> usize {
        match self {
            MemoryChunk::Attached(a) => a.len(),
            MemoryChunk::Maximum(m) => m.len(),
        }
    }

    fn tail(self, from: usize) -> MemoryChunk<'a> {
        match self {
            MemoryChunk::Attached(a) => MemoryChunk::Attached(&mut a[from..]),
            MemoryChunk::Maximum(m) => MemoryChunk::Maximum(&mut m[from..]),
        }
    }
}

/// The radius factors of one chunk.
#[derive(Clone, Copy)]
enum ChunkFactors<'a> {
    Uniform([f64; 3]),
    PerSummit(&'a [[f64; 3]]),
}

impl ChunkFactors<'_> {
    #[inline(always)]
    fn at(&self, i: usize) -> [f64; 3] {
        match self {
            ChunkFactors::Uniform(f) => *f,
            ChunkFactors::PerSummit(v) => v[i],
        }
    }

    /// `out[i] = (z[i] - d) rho_i^-alpha`.
    #[inline]
    fn interferences(&self, z: &[f64], d: f64, out: &mut [f64]) {
        match *self {
            ChunkFactors::Uniform(f) => crate::numeric::simd::arch().dispatch(
                #[inline(always)]
                || {
                    for (o, &zi) in out.iter_mut().zip(z) {
                        *o = (zi - d) * f[0];
                    }
                },
            ),
            ChunkFactors::PerSummit(v) => {
                for ((o, &zi), f) in out.iter_mut().zip(z).zip(v) {
                    *o = (zi - d) * f[0];
                }
            }
        }
    }

    /// `load[i] *= rho_i^beta`, `radius[i] *= rho_i^gamma`.
    #[inline]
    fn scale(&self, load: &mut [f64], radius: &mut [f64]) {
        match *self {
            // Summits of the law's own radius: nothing to scale (a pass
            // over the chunk saved).
            ChunkFactors::Uniform([_, 1.0, 1.0]) => {}
            ChunkFactors::Uniform(f) => crate::numeric::simd::arch().dispatch(
                #[inline(always)]
                || {
                    for (l, r) in load.iter_mut().zip(radius.iter_mut()) {
                        *l *= f[1];
                        *r *= f[2];
                    }
                },
            ),
            ChunkFactors::PerSummit(v) => {
                for ((l, r), f) in load.iter_mut().zip(radius.iter_mut()).zip(v) {
                    *l *= f[1];
                    *r *= f[2];
                }
            }
        }
    }
}

impl LoadingModel for MonteCarlo {
    /// Totals at separation `d` (m) after `history`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] for a non-finite separation, or a retraction
    /// from a `closest` separation above `d`; [`Error::Invalid`] naming
    /// `separation` when a summit passes the law's maximum interference
    /// (rigid Bradley: infinite load).
    fn state(&self, separation: f64, history: History, observables: &Observables) -> Result<State> {
        history.check(separation)?;
        Ok(self.run(&[(separation, history)], observables)?.remove(0))
    }

    /// All steps in one parallel pass over the summit blocks.
    fn states(&self, steps: &[(f64, History)], observables: &Observables) -> Result<Vec<State>> {
        for &(d, h) in steps {
            h.check(d)?;
        }
        self.run(steps, observables)
    }

    /// The top summit's height minus the law's
    /// [`interaction_range`](crate::law::AsperityLaw::interaction_range) (its cutoff
    /// for laws whose load vanishes; per radius, the loosest).
    fn interaction_onset(&self) -> f64 {
        let z = self.population.heights();
        let cut = self.law.law().interaction_range();
        let top = z[z.len() - 1];
        if cut == f64::NEG_INFINITY {
            return f64::INFINITY;
        }
        let inv = if cut < 0.0 {
            self.inv_len.0
        } else {
            self.inv_len.1
        };
        top - cut / inv
    }

    /// `1e-12` of the height range: a population is a step function, and
    /// the searches land next to a step.
    fn separation_tolerance(&self) -> f64 {
        let z = self.population.heights();
        let range = (z[z.len() - 1] - z[0]).max(z[z.len() - 1].abs() * 1e-6);
        1e-12 * range.max(f64::MIN_POSITIVE)
    }

    /// The height range of the population (the step of the load search).
    fn height_scale(&self) -> f64 {
        let z = self.population.heights();
        (z[z.len() - 1] - z[0])
            .max(z[z.len() - 1].abs() * 1e-6)
            .max(f64::MIN_POSITIVE)
    }

    fn is_discrete(&self) -> bool {
        true
    }
}

impl MonteCarlo {
    /// The top summit's height (m): the start of a load search.
    pub fn top_height(&self) -> f64 {
        let z = self.population.heights();
        z[z.len() - 1]
    }
}
