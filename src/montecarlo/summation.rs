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
use crate::error::{finite, Allowed, Error, Result};
use crate::gw::{self, GwState, History, LoadingProgram, Outputs, PullOff};
use crate::law::{Branch, ContactState};
use rayon::prelude::*;
use std::f64::consts::PI;
use std::sync::Arc;

/// Summits per summation block (fixed: part of the reduction order).
pub const SUM_BLOCK: usize = 8192;

/// Totals of a population at one separation. Outputs not asked for are `None`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct McState {
    /// Separation `d` of the flat from the height origin (m).
    pub separation: f64,
    /// Total load (N), > 0 compressive.
    pub load: Option<f64>,
    /// Real contact area `sum pi a_i^2` (m^2).
    pub area: Option<f64>,
    /// Number of summits in contact (`a_i > 0`), as a float.
    pub count: Option<f64>,
    /// Standard errors of (load, area, count) as estimates of the
    /// population expectation, `sqrt(N s^2)` (same units); NaN for a
    /// single summit.
    pub standard_error: [f64; 3],
    /// Summits evaluated (those within the law's range).
    pub evaluations: usize,
}

impl McState {
    /// Deviation from the Greenwood–Williamson expectation in standard
    /// errors, per output: `(x_MC - x_GW) / sqrt(SE^2 + err_GW^2)`; about
    /// N(0, 1) when the population is drawn from the model's distribution
    /// (`|z| > 5` is significant). `None` for outputs missing on either
    /// side or with a zero error (every summit in contact: the count is
    /// exact).
    pub fn deviation_from(&self, gw: &GwState) -> [Option<f64>; 3] {
        let mc = [self.load, self.area, self.count];
        let ex = [gw.load, gw.area, gw.count];
        std::array::from_fn(|i| {
            let (m, e) = (mc[i]?, ex[i]?);
            let se = self.standard_error[i].hypot(gw.error[i]);
            (se > 0.0).then(|| (m - e) / se)
        })
    }

    /// The state of a surface `factor` times larger than the population
    /// (a population drawn for a sub-area, `factor = N_surface / N`):
    /// totals and standard errors multiplied by `factor`. The errors then
    /// measure the distance to the expectation `N_surface E[x]`, not the
    /// scatter of one realisation of the whole surface.
    pub fn scaled(&self, factor: f64) -> McState {
        McState {
            load: self.load.map(|x| x * factor),
            area: self.area.map(|x| x * factor),
            count: self.count.map(|x| x * factor),
            standard_error: self.standard_error.map(|x| x * factor),
            ..*self
        }
    }
}

/// A Monte Carlo load–separation curve on approach and retraction.
#[derive(Debug, Clone, PartialEq)]
pub struct McCurve {
    /// The program that made it.
    pub program: LoadingProgram,
    /// Approach states, ascending in separation (index 0 = closest).
    pub approach: Vec<McState>,
    /// Retraction states at the same separations.
    pub retract: Vec<McState>,
}

impl McCurve {
    /// Energy lost per cycle (J), trapezoidal over the program's separations
    /// (error `O(step^2)`); `None` if loads were not computed.
    pub fn hysteresis_energy(&self) -> Option<f64> {
        gw::hysteresis_energy(
            self.approach
                .iter()
                .enumerate()
                .map(|(i, a)| (a.separation, a.load, self.retract[i].load)),
        )
    }

    /// The most tensile sampled retraction load, if any is tensile.
    pub fn sampled_pull_off(&self) -> Option<PullOff> {
        gw::most_tensile(self.retract.iter().map(|s| (s.load, s.separation)))
    }

    /// Total law evaluations spent on the curve.
    pub fn evaluations(&self) -> usize {
        self.approach
            .iter()
            .chain(&self.retract)
            .map(|s| s.evaluations)
            .sum()
    }
}

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

/// Which state rule a step uses.
#[derive(Debug, Clone, Copy)]
enum Rule {
    Approach,
    After { closest: f64 },
}

/// Partial sums of one block: values and squares of (load, area, count).
#[derive(Debug, Clone, Copy, Default)]
struct Partial {
    sum: [f64; 3],
    sq: [f64; 3],
}

impl Partial {
    fn add(&mut self, p: &Partial) {
        for i in 0..3 {
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

    /// Totals at separation `d` (m) after `history`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] for a non-finite separation, or a retraction
    /// from a `closest` separation above `d`; [`Error::Invalid`] naming
    /// `separation` when a summit passes the law's maximum interference
    /// (rigid Bradley: infinite load).
    pub fn state(&self, separation: f64, history: History, outputs: Outputs) -> Result<McState> {
        finite("separation", separation)?;
        let rule = match history {
            History::Approach => Rule::Approach,
            History::Retract { closest } => {
                finite("closest_separation", closest)?;
                if closest > separation {
                    return Err(Error::OutOfRange {
                        name: "separation".into(),
                        value: separation,
                        allowed: Allowed::closed(closest, f64::INFINITY),
                    });
                }
                Rule::After { closest }
            }
        };
        Ok(self.run(&[(separation, rule)], outputs)?.remove(0))
    }

    /// Runs `program`: approach states, then retraction states after the
    /// closest separation; all steps in one parallel pass.
    ///
    /// # Errors
    /// As [`MonteCarlo::state`].
    pub fn curve(&self, program: &LoadingProgram, outputs: Outputs) -> Result<McCurve> {
        let seps = program.separations();
        let steps: Vec<(f64, Rule)> = seps
            .iter()
            .map(|&d| (d, Rule::Approach))
            .chain(seps.iter().map(|&d| {
                (
                    d,
                    Rule::After {
                        closest: program.closest,
                    },
                )
            }))
            .collect();
        let mut states = self.run(&steps, outputs)?;
        let retract = states.split_off(seps.len());
        Ok(McCurve {
            program: *program,
            approach: states,
            retract,
        })
    }

    /// Separation (m) at which the approach load first reaches
    /// `max_load` (N, > 0) coming from far away: the closest separation of
    /// a load-limited program (scene `program.max_load`). Brackets by
    /// doubling steps down from the top summit, then bisects to `1e-12`
    /// relative in separation; returns the bracket end whose load is
    /// `>= max_load`. The crossing is the first one when the approach load
    /// is monotone in separation (every law here in compression: each
    /// summit's load grows with its interference once in contact).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `max_load`; [`Error::NoConvergence`]
    /// when the load cannot reach it (e.g. a rigid law diverging first);
    /// as [`MonteCarlo::state`].
    pub fn separation_for_load(&self, max_load: f64) -> Result<f64> {
        crate::error::positive("max_load", max_load)?;
        let z = self.population.heights();
        let (z_lo, z_hi) = (z[0], z[z.len() - 1]);
        let load = |d: f64| -> Result<f64> {
            Ok(self
                .state(d, History::Approach, Outputs::LOAD)?
                .load
                .unwrap_or(0.0))
        };
        // Above the top summit no contact load acts (for laws with a
        // finite range the load may still be adhesive, i.e. < max_load).
        let mut hi = z_hi;
        let mut width = (z_hi - z_lo).max(z_hi.abs() * 1e-6).max(f64::MIN_POSITIVE);
        let mut lo = hi - width;
        let mut tries = 0;
        while load(lo)? < max_load {
            hi = lo;
            width *= 2.0;
            lo = hi - width;
            tries += 1;
            if tries > 200 || !lo.is_finite() {
                return Err(Error::NoConvergence {
                    what: format!("separation where the approach load reaches {max_load:e} N"),
                    iterations: tries,
                    residual: max_load,
                });
            }
        }
        for _ in 0..200 {
            if hi - lo <= 1e-12 * (hi.abs() + lo.abs()).max(z_hi - z_lo) {
                break;
            }
            let mid = 0.5 * (lo + hi);
            if load(mid)? >= max_load {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Ok(lo)
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
    pub fn sequence(&self, separations: &[f64], outputs: Outputs) -> Result<Vec<McState>> {
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
                    self.block_flagged(start, end, &mut flags[start - base..], d, attach, detach)
                })
                .collect();
            let mut total = Partial::default();
            for p in &partials {
                total.add(p);
            }
            out.push(self.finish(d, &total, lo, outputs)?);
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
        attach: f64,
        detach: f64,
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
            add(&mut p, st.load * f[1], st.radius * f[2]);
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
    fn run(&self, steps: &[(f64, Rule)], outputs: Outputs) -> Result<Vec<McState>> {
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
                    .map(|(&(d, rule), &lo)| {
                        if lo < end {
                            self.block(start.max(lo), end, d, rule)
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
            states.push(self.finish(d, &total, lo, outputs)?);
        }
        Ok(states)
    }

    /// The state from a step's total; an error if the load is not finite.
    fn finish(&self, d: f64, t: &Partial, first: usize, outputs: Outputs) -> Result<McState> {
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
        Ok(McState {
            separation: d,
            load: outputs.load.then_some(t.sum[0]),
            area: outputs.area.then_some(t.sum[1]),
            count: outputs.count.then_some(t.sum[2]),
            standard_error: se,
            evaluations: n - first,
        })
    }

    /// Sums over summits `a..b` at separation `d`.
    fn block(&self, a: usize, b: usize, d: f64, rule: Rule) -> Partial {
        let z = &self.population.heights()[a..b];
        let law = self.law.law();
        match (&self.factors, rule) {
            (Factors::Uniform(f), Rule::Approach) => {
                sum_uniform(z, *f, |x, _| law.state(x, Branch::Approach), d, 0.0)
            }
            (Factors::Uniform(f), Rule::After { closest }) => {
                sum_uniform(z, *f, |x, m| law.state_after(x, m), d, closest)
            }
            (Factors::PerSummit(v), Rule::Approach) => {
                sum_per_summit(z, &v[a..b], |x, _| law.state(x, Branch::Approach), d, 0.0)
            }
            (Factors::PerSummit(v), Rule::After { closest }) => {
                sum_per_summit(z, &v[a..b], |x, m| law.state_after(x, m), d, closest)
            }
        }
    }
}

/// Adds one summit's (load, area, count) to a partial.
#[inline(always)]
fn add(p: &mut Partial, load: f64, radius: f64) {
    let area = PI * radius * radius;
    let c = if radius > 0.0 { 1.0 } else { 0.0 };
    p.sum[0] += load;
    p.sum[1] += area;
    p.sum[2] += c;
    p.sq[0] += load * load;
    p.sq[1] += area * area;
    p.sq[2] += c;
}

/// One radius for all summits: the factors are constants.
#[inline(always)]
fn sum_uniform<S>(z: &[f64], f: [f64; 3], state: S, d: f64, closest: f64) -> Partial
where
    S: Fn(f64, f64) -> ContactState,
{
    let mut p = Partial::default();
    for &zi in z {
        let st = state((zi - d) * f[0], (zi - closest) * f[0]);
        add(&mut p, st.load * f[1], st.radius * f[2]);
    }
    p
}

/// Per-summit radii: factors read alongside the heights.
#[inline(always)]
fn sum_per_summit<S>(z: &[f64], f: &[[f64; 3]], state: S, d: f64, closest: f64) -> Partial
where
    S: Fn(f64, f64) -> ContactState,
{
    let mut p = Partial::default();
    for (&zi, fi) in z.iter().zip(f) {
        let st = state((zi - d) * fi[0], (zi - closest) * fi[0]);
        add(&mut p, st.load * fi[1], st.radius * fi[2]);
    }
    p
}
