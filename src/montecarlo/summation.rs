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

use super::population::Population;
use super::scaling::SummitLaw;
use crate::error::{finite, Error, Result};
use crate::law::{Branch, ContactState};
use crate::loading::{
    History, LoadingModel, MethodUsed, Observables, State, Totals, EXTRA_SLOTS, SLOTS,
};
use rayon::prelude::*;
use std::f64::consts::PI;
use std::sync::Arc;

/// Summits per summation block (fixed: part of the reduction order).
pub const SUM_BLOCK: usize = 8192;

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
    /// factors.
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
        let mut attached = vec![false; n];
        let mut prev_lo = n;
        let mut out = Vec::with_capacity(separations.len());
        for &d in separations {
            let lo = self.first_above(d, cut);
            if lo > prev_lo {
                // Summits that left the range are detached.
                attached[prev_lo..lo].fill(false);
            }
            prev_lo = lo;
            let partials: Vec<Partial> = attached
                .par_chunks_mut(SUM_BLOCK)
                .enumerate()
                .skip(lo / SUM_BLOCK)
                .map(|(b, flags)| {
                    let base = b * SUM_BLOCK;
                    let start = base.max(lo);
                    let end = base + flags.len();
                    self.block_flagged(
                        start,
                        end,
                        &mut flags[start - base..],
                        d,
                        (attach, detach),
                        observables,
                    )
                })
                .collect();
            let mut total = Partial::default();
            for p in &partials {
                total.add(p);
            }
            out.push(self.finish(d, &total, lo, observables)?);
        }
        Ok(out)
    }

    /// Sums summits `a..b` at `d`, updating their attached flags.
    fn block_flagged(
        &self,
        a: usize,
        b: usize,
        flags: &mut [bool],
        d: f64,
        (attach, detach): (f64, f64),
        extras: &Observables,
    ) -> Partial {
        let z = &self.population.heights()[a..b];
        let law = self.law.law();
        let mut p = Partial::default();
        let mut one = |zi: f64, flag: &mut bool, f: [f64; 3]| {
            let x = (zi - d) * f[0];
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
            let st = law.state(x, branch);
            add(&mut p, st.load * f[1], st.radius * f[2], extras);
        };
        match &self.factors {
            Factors::Uniform(f) => {
                for (&zi, flag) in z.iter().zip(flags.iter_mut()) {
                    one(zi, flag, *f);
                }
            }
            Factors::PerSummit(v) => {
                for ((&zi, flag), f) in z.iter().zip(flags.iter_mut()).zip(&v[a..b]) {
                    one(zi, flag, *f);
                }
            }
        }
        p
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
        let partials: Vec<Vec<Partial>> = (first_block..blocks)
            .into_par_iter()
            .map(|b| {
                let (start, end) = (b * SUM_BLOCK, ((b + 1) * SUM_BLOCK).min(n));
                steps
                    .iter()
                    .zip(&firsts)
                    .map(|(&(d, history), &lo)| {
                        if lo < end {
                            self.block(start.max(lo), end, d, history, observables)
                        } else {
                            Partial::default()
                        }
                    })
                    .collect()
            })
            .collect();
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

    /// Sums over summits `a..b` at separation `d`.
    fn block(&self, a: usize, b: usize, d: f64, history: History, obs: &Observables) -> Partial {
        let z = &self.population.heights()[a..b];
        let law = self.law.law();
        match (&self.factors, history) {
            (Factors::Uniform(f), History::Approach) => {
                sum_uniform(z, *f, |x, _| law.state(x, Branch::Approach), d, 0.0, obs)
            }
            (Factors::Uniform(f), History::Retract { closest }) => {
                sum_uniform(z, *f, |x, m| law.state_after(x, m), d, closest, obs)
            }
            (Factors::PerSummit(v), History::Approach) => sum_per_summit(
                z,
                &v[a..b],
                |x, _| law.state(x, Branch::Approach),
                d,
                0.0,
                obs,
            ),
            (Factors::PerSummit(v), History::Retract { closest }) => {
                sum_per_summit(z, &v[a..b], |x, m| law.state_after(x, m), d, closest, obs)
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

    /// The top summit's height minus the law's cutoff (per radius, the
    /// loosest).
    fn interaction_onset(&self) -> f64 {
        let z = self.population.heights();
        let cut = self.law.law().cutoff_interference();
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

/// Adds one summit's load, area and count (slots 0-2) and any further
/// observables to a partial.
#[inline(always)]
fn add(p: &mut Partial, load: f64, radius: f64, obs: &Observables) {
    let area = PI * radius * radius;
    let c = if radius > 0.0 { 1.0 } else { 0.0 };
    p.sum[0] += load;
    p.sum[1] += area;
    p.sum[2] += c;
    p.sq[0] += load * load;
    p.sq[1] += area * area;
    p.sq[2] += c;
    if !obs.extras().is_empty() {
        let st = ContactState { load, radius };
        for (k, e) in obs.extras().iter().take(EXTRA_SLOTS).enumerate() {
            let v = e.value(&st);
            p.sum[3 + k] += v;
            p.sq[3 + k] += v * v;
        }
    }
}

/// One radius for all summits: the factors are constants.
#[inline(always)]
fn sum_uniform<S>(
    z: &[f64],
    f: [f64; 3],
    state: S,
    d: f64,
    closest: f64,
    obs: &Observables,
) -> Partial
where
    S: Fn(f64, f64) -> ContactState,
{
    let mut p = Partial::default();
    for &zi in z {
        let st = state((zi - d) * f[0], (zi - closest) * f[0]);
        add(&mut p, st.load * f[1], st.radius * f[2], obs);
    }
    p
}

/// Per-summit radii: factors read alongside the heights.
#[inline(always)]
fn sum_per_summit<S>(
    z: &[f64],
    f: &[[f64; 3]],
    state: S,
    d: f64,
    closest: f64,
    obs: &Observables,
) -> Partial
where
    S: Fn(f64, f64) -> ContactState,
{
    let mut p = Partial::default();
    for (&zi, fi) in z.iter().zip(f) {
        let st = state((zi - d) * fi[0], (zi - closest) * fi[0]);
        add(&mut p, st.load * fi[1], st.radius * fi[2], obs);
    }
    p
}
