//! The approach totals of laws smooth in the root of their interference
//! by fixed Gauss–Legendre rules in `t = sqrt(s - s0)`, many states at once.
//!
//! `s0 = (d + cutoff)/sigma` is the height where contact starts; in `t`
//! (`ds = 2t dt`, interference `sigma t^2 + cutoff`) the totals are smooth
//! between the law's breakpoints, which are fixed in `t` (independent of
//! the separation). Each piece of a state gets an `n`-point rule,
//! `n = ceil(n_tol sqrt(width/span))` (`span` the state's whole range in
//! `t`, `n_tol` from the tolerance, [`base_nodes`]), and an error estimate
//! from the decay of the integrand's Legendre coefficients on the same
//! nodes ([`crate::numeric::gauss`]). A state whose estimate misses
//! `rtol int |f|` in any total is redone with 1.5 times the nodes, up to
//! [`MAX_BASE_NODES`]; past that the adaptive rule
//! ([`GwModel::quadrature_in_root`]) takes it.
//!
//! Heights end where the density has fallen by `ln(1/rtol) + TAIL_MARGIN`
//! ([`HeightDistribution::decay_end`](crate::heights::HeightDistribution::decay_end)),
//! capped at [`ROOT_RULE_DROP`]: the totals beyond are at most about
//! `(1 + drop)^2 exp(-drop)` (a few per cent of `rtol`) of the whole (the
//! square: a power-law growth of the law, up to `delta^2`, over the tail
//! of an exponential density, the slowest-falling one), added to each
//! error estimate.
//!
//! All states' nodes go through the law ([`LawKernels::state_batch`]),
//! the density ([`HeightDistribution::pdf_batch`]) and the observables
//! ([`Observables::evaluate_columns`]) in one long batch, so every loop
//! runs in full vector registers; the per-state arithmetic does not
//! depend on the batch, so a state's bits are the same alone or in any
//! batch.

use super::{GwModel, ROOT_RULE_DROP};
use crate::error::Result;
use crate::heights::HeightDistribution;
use crate::law::{Branch, LawCursor, LawKernels};
use crate::loading::{MethodUsed, Observables, State, Totals, SLOTS};
use crate::numeric::gauss::{gauss_rule, GaussRule, MAX_NODES};

/// Tightest tolerance the fixed rules serve; below it the adaptive rule
/// runs directly.
pub(super) const FIXED_RULE_MIN_RTOL: f64 = 1e-7;
/// Margin of the height range's end beyond `ln(1/rtol)`: the tail's share
/// `(1 + drop)^2 exp(-drop)` is then 1.5 % of the tolerance at 1e-3 and
/// 2.8 % at 1e-6.
const TAIL_MARGIN: f64 = 10.0;
/// Fewest nodes on a piece.
const MIN_PIECE_NODES: usize = 6;
/// Most nodes `n_tol` of the ladder before the adaptive rule takes over.
pub(super) const MAX_BASE_NODES: usize = 48;
/// States per batch in [`GwModel::states`].
pub(super) const ROOT_BATCH: usize = 32;

/// Nodes over a state's whole range in `t` at tolerance `rtol`: 15 at
/// 1e-3, 22 at 1e-6 (measured on the Hertz and Kogut–Etsion curves of
/// `docs/performance.md`: the smallest counts whose estimates meet the
/// tolerance on nearly every state).
fn base_nodes(rtol: f64) -> usize {
    (8.0 + 2.3 * (1.0 / rtol).log10())
        .ceil()
        .max(MIN_PIECE_NODES as f64) as usize
}

/// A state the fixed rules serve: separation `d` (m) and its range of
/// standardised heights `[s_lo, s_hi]`.
#[derive(Debug, Clone, Copy)]
pub(super) struct RootPlan {
    pub d: f64,
    pub s_lo: f64,
    pub s_hi: f64,
}

/// One piece of one state: its nodes are `start..start + rule.len()`.
struct Piece {
    state: usize,
    start: usize,
    width: f64,
    rule: &'static GaussRule,
}

/// Reused buffers of one batch.
#[derive(Default)]
struct Scratch {
    t: Vec<f64>,
    s: Vec<f64>,
    delta: Vec<f64>,
    weight: Vec<f64>,
    load: Vec<f64>,
    radius: Vec<f64>,
    cols: [Vec<f64>; SLOTS],
    pieces: Vec<Piece>,
}

/// [`GwModel::root_pass`] as a [`pulp::WithSimd`] operation.
struct Pass<'a> {
    model: &'a GwModel,
    plans: &'a [RootPlan],
    pending: &'a [usize],
    n_tol: usize,
    breaks: &'a [f64],
    drop: f64,
    obs: &'a Observables,
    scratch: &'a mut Scratch,
}

impl pulp::WithSimd for Pass<'_> {
    type Output = Vec<Sums>;

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _simd: S) -> Vec<Sums> {
        self.model.root_pass_body(
            self.plans,
            self.pending,
            self.n_tol,
            self.breaks,
            self.drop,
            self.obs,
            self.scratch,
        )
    }
}

thread_local! {
    static SCRATCH: std::cell::RefCell<Scratch> = std::cell::RefCell::new(Scratch::default());
}

/// One state's sums over its pieces.
#[derive(Clone, Copy, Default)]
struct Sums {
    value: [f64; SLOTS],
    error: [f64; SLOTS],
    magnitude: [f64; SLOTS],
    evaluations: usize,
}

impl GwModel {
    /// Fall of `ln phi` at which the fixed rules end the heights.
    fn root_drop(&self) -> f64 {
        ((1.0 / self.accuracy.rel_tol).ln() + TAIL_MARGIN).min(ROOT_RULE_DROP)
    }

    /// The totals of `plans` (approach, or a reversible law), in order.
    ///
    /// # Errors
    /// As [`GwModel::quadrature_in_root`], for a state the fixed rules
    /// could not certify.
    pub(super) fn root_states(&self, plans: &[RootPlan], obs: &Observables) -> Vec<Result<State>> {
        let rtol = self.accuracy.rel_tol;
        let law = self.law.as_ref();
        let sigma = self.surface.sigma;
        let cutoff = law.cutoff_interference();
        // The law's breakpoints in `t`: the same for every state.
        let mut breaks: Vec<f64> = law
            .breakpoints(Branch::Approach)
            .into_iter()
            .map(|b| ((b - cutoff) / sigma).max(0.0).sqrt())
            .filter(|t| t.is_finite() && *t > 0.0)
            .collect();
        breaks.sort_by(f64::total_cmp);
        breaks.dedup();
        let drop = self.root_drop();
        let tail = (1.0 + drop) * (1.0 + drop) * (-drop).exp();
        let mask = obs.mask();
        let summits = self.surface.summits();
        let mut out: Vec<Option<Result<State>>> = plans.iter().map(|_| None).collect();
        let mut evaluations = vec![0usize; plans.len()];
        let mut pending: Vec<usize> = (0..plans.len()).collect();
        let mut n_tol = base_nodes(rtol);
        while !pending.is_empty() {
            let pass = |scratch: &mut Scratch| {
                self.root_pass(plans, &pending, n_tol, &breaks, drop, obs, scratch)
            };
            // The thread's buffers, grown once and reused by every batch.
            let sums = SCRATCH.with(|cell| match cell.try_borrow_mut() {
                Ok(mut scratch) => pass(&mut scratch),
                Err(_) => pass(&mut Scratch::default()),
            });
            let mut missed = Vec::new();
            for (&i, s) in pending.iter().zip(&sums) {
                evaluations[i] += s.evaluations;
                // The rule's estimate, the tail beyond the heights' end,
                // and rounding (QUADPACK's floor, 50 eps int |f|).
                let error: [f64; SLOTS] = std::array::from_fn(|k| {
                    s.error[k] + (tail + 50.0 * f64::EPSILON) * s.magnitude[k]
                });
                if (0..SLOTS).all(|k| !mask[k] || error[k] <= rtol * s.magnitude[k]) {
                    out[i] = Some(Ok(State {
                        separation: plans[i].d,
                        totals: Totals::new(
                            s.value.map(|x| summits * x),
                            error.map(|x| summits * x),
                            mask,
                        ),
                        method: MethodUsed::Quadrature,
                        evaluations: evaluations[i],
                    }));
                } else {
                    missed.push(i);
                }
            }
            pending = missed;
            if n_tol >= MAX_BASE_NODES {
                for &i in &pending {
                    let p = plans[i];
                    out[i] = Some(self.quadrature_in_root(p.d, p.s_lo, p.s_hi, obs).map(
                        |mut st| {
                            st.evaluations += evaluations[i];
                            st
                        },
                    ));
                }
                break;
            }
            n_tol = (n_tol * 3 / 2).min(MAX_BASE_NODES);
        }
        out.into_iter()
            .map(|r| r.expect("every state is decided"))
            .collect()
    }

    /// The states of `plans` by the rules in the root: the fixed rules in
    /// one batch at tolerances they serve, else the adaptive rule state by
    /// state (as [`LoadingModel::state`] computes them).
    pub(super) fn root_states_any(
        &self,
        plans: &[RootPlan],
        obs: &Observables,
    ) -> Vec<Result<State>> {
        if self.accuracy.rel_tol >= FIXED_RULE_MIN_RTOL {
            self.root_states(plans, obs)
        } else {
            plans
                .iter()
                .map(|p| self.quadrature_in_root(p.d, p.s_lo, p.s_hi, obs))
                .collect()
        }
    }

    /// One pass of the fixed rules (`n_tol` nodes over a whole range) over
    /// the states `pending` of `plans`: their sums, in order. Compiled for
    /// the CPU's widest vectors ([`pulp::Arch`]; the law, density and
    /// observables dispatch their own batches).
    #[allow(clippy::too_many_arguments)]
    fn root_pass(
        &self,
        plans: &[RootPlan],
        pending: &[usize],
        n_tol: usize,
        breaks: &[f64],
        drop: f64,
        obs: &Observables,
        scratch: &mut Scratch,
    ) -> Vec<Sums> {
        crate::numeric::simd::arch().dispatch(Pass {
            model: self,
            plans,
            pending,
            n_tol,
            breaks,
            drop,
            obs,
            scratch,
        })
    }

    /// [`GwModel::root_pass`]'s work, inlined into each SIMD variant.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn root_pass_body(
        &self,
        plans: &[RootPlan],
        pending: &[usize],
        n_tol: usize,
        breaks: &[f64],
        drop: f64,
        obs: &Observables,
        scratch: &mut Scratch,
    ) -> Vec<Sums> {
        let law: &dyn LawKernels = self.law.as_ref();
        let dist: &dyn HeightDistribution = self.distribution.as_ref();
        let sigma = self.surface.sigma;
        let cutoff = law.cutoff_interference();
        let rtol = self.accuracy.rel_tol;
        let sc = scratch;
        for v in [&mut sc.t, &mut sc.s, &mut sc.delta] {
            v.clear();
        }
        sc.pieces.clear();
        let mut points: Vec<f64> = Vec::with_capacity(breaks.len() + 2);
        for (j, &i) in pending.iter().enumerate() {
            let p = plans[i];
            let s0 = (p.d + cutoff) / sigma;
            let s_top = p.s_hi.min(dist.decay_end(p.s_lo, drop));
            let (t_lo, t_hi) = ((p.s_lo - s0).max(0.0).sqrt(), (s_top - s0).max(0.0).sqrt());
            if !(t_hi > t_lo) {
                continue;
            }
            points.clear();
            points.push(t_lo);
            points.extend(breaks.iter().copied().filter(|&b| b > t_lo && b < t_hi));
            points.push(t_hi);
            let span = t_hi - t_lo;
            for w in points.windows(2) {
                let width = w[1] - w[0];
                let n = ((n_tol as f64) * (width / span).sqrt()).ceil() as usize;
                let rule = gauss_rule(n.clamp(MIN_PIECE_NODES, MAX_NODES));
                sc.pieces.push(Piece {
                    state: j,
                    start: sc.t.len(),
                    width,
                    rule,
                });
                let (start, end) = (sc.t.len(), sc.t.len() + rule.len());
                for v in [&mut sc.t, &mut sc.s, &mut sc.delta] {
                    v.resize(end, 0.0);
                }
                let nodes = sc.t[start..end]
                    .iter_mut()
                    .zip(&mut sc.s[start..end])
                    .zip(&mut sc.delta[start..end])
                    .zip(&rule.x);
                for (((t, s), delta), &x) in nodes {
                    *t = w[0] + width * x;
                    *s = s0 + *t * *t;
                    *delta = sigma * *t * *t + cutoff;
                }
            }
        }
        let n = sc.t.len();
        for v in [&mut sc.weight, &mut sc.load, &mut sc.radius] {
            v.resize(n, 0.0);
        }
        if obs.load_only() {
            let mut cursor = LawCursor::default();
            law.load_near_batch(&sc.delta, None, &mut sc.load, &mut cursor);
        } else {
            law.state_batch(&sc.delta, None, &mut sc.load, &mut sc.radius);
        }
        dist.pdf_batch(&sc.s, &mut sc.weight);
        for (w, &t) in sc.weight.iter_mut().zip(&sc.t) {
            *w *= 2.0 * t;
        }
        obs.evaluate_columns(&sc.load, &sc.radius, &sc.weight, &mut sc.cols);
        let mask = obs.mask();
        let mut sums = vec![Sums::default(); pending.len()];
        for piece in &sc.pieces {
            let r = piece.rule;
            let m = r.len();
            let sum = &mut sums[piece.state];
            sum.evaluations += m;
            for k in (0..SLOTS).filter(|&k| mask[k]) {
                let (value, magnitude, c) = r.sums(&sc.cols[k][piece.start..piece.start + m]);
                sum.value[k] += piece.width * value;
                sum.magnitude[k] += piece.width * magnitude;
                // A bound instead of the estimate where it is a small
                // part of this piece's share of the tolerance.
                let enough = 0.25 * rtol * piece.width * magnitude;
                sum.error[k] += r.estimate(piece.width, c, enough);
            }
        }
        sums
    }
}
