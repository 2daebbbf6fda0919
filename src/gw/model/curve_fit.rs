//! Many approach states from one interpolant of the curve in the separation.
//!
//! On a density analytic on the whole line (the Gaussian) every approach
//! total `F(d) = N int f(sigma s - d) phi(s) ds` of a law smooth in the root
//! of its interference is, after `u = sigma s - d`,
//! `N int_0^inf f(u) phi((u + d)/sigma) du/sigma`: the separation enters
//! only through `phi`, so `F` is an entire function of `d`, and positive
//! (every summit above the flat pushes, and the Gaussian puts summits at
//! every height), kinks of the law (Kogut–Etsion's jumps) included. Its
//! logarithm `ln F`, about `-d^2/(2 sigma^2)` far out, is then analytic on
//! the real line, and a Chebyshev interpolant in `d` converges
//! geometrically: on `[-sigma, 4 sigma]` degree 16 reaches 1e-9 and degree
//! 24 1e-14 (Hertz load, area and count; `docs/performance.md`).
//!
//! A curve of many states is then computed as a few panels of
//! Chebyshev–Lobatto nodes `d_j = mid + half cos(pi j/n)`, `n` = 16, 32, 64
//! (nested: each level adds the odd nodes), each node a quadrature state at
//! a tenth of the tolerance ([`NODE_RTOL_SHARE`]), and every state of the
//! program from the interpolant: `exp` of a Clenshaw sum per total. A panel
//! whose estimate misses the tolerance at `n = 64` is halved, up to
//! [`MAX_DEPTH`] times; past that its states are computed one by one.
//!
//! Error per state and total, relative: the interpolant's, `2 (|c_{n-1}| +
//! |c_n|)` (the two last coefficients of `ln F`, whose error is `F`'s
//! relative error), plus the nodes' largest relative estimate times the
//! Lebesgue constant of the Lobatto nodes, `1 + (2/pi) ln(n + 1)`.

use super::root_rule::{RootPlan, ROOT_BATCH};
use super::GwModel;
use crate::error::Result;
use crate::loading::{History, LoadingModel, MethodUsed, Observables, State, Totals, SLOTS};
use crate::numeric::chebyshev::clenshaw_lanes_dyn;
use crate::special::normal::exp_lane;
use rayon::prelude::*;

/// Fewest states of a curve worth an interpolant (a panel costs 17 to 65
/// quadrature states).
pub(super) const CURVE_FIT_MIN_STATES: usize = 128;
/// Tightest tolerance the interpolant serves (its nodes then at 1e-11).
pub(super) const CURVE_FIT_MIN_RTOL: f64 = 1e-10;
/// Nodes' tolerance as a share of the curve's.
const NODE_RTOL_SHARE: f64 = 0.1;
/// Lobatto orders tried on a panel before it is halved.
const LEVELS: [usize; 3] = [16, 32, 64];
/// Most halvings of the whole range.
const MAX_DEPTH: usize = 4;
/// States evaluated per parallel task.
const EVAL_CHUNK: usize = 4096;
/// States whose series are summed together (two AVX-512 vectors).
const LANES: usize = 16;

/// `ln F` of every total in use on `[lo, hi]`, as Chebyshev coefficients.
struct Panel {
    lo: f64,
    hi: f64,
    /// `coef[k]`: the coefficients of total `k` (empty when not in use).
    coef: [Vec<f64>; SLOTS],
    /// Relative error estimate per total (interpolant and nodes).
    error: [f64; SLOTS],
}

/// What a panel of the range became.
enum Fit {
    Interpolant(Panel),
    /// States of `[lo, hi]` computed one by one.
    Direct {
        lo: f64,
        hi: f64,
    },
}

impl GwModel {
    /// The states of `steps` in order when the rules in the root
    /// serve enough of them for one interpolant of the curve: those from
    /// the interpolant ([`GwModel::fitted_states`]), the others one by one;
    /// `None` when the interpolant does not apply.
    pub(super) fn curve_states(
        &self,
        steps: &[(f64, History)],
        obs: &Observables,
    ) -> Option<Result<Vec<State>>> {
        // Bounded heights: the density has an edge, and `F` a kink.
        let (lo, hi) = self.distribution.support();
        if steps.len() < CURVE_FIT_MIN_STATES || lo > f64::MIN || hi < f64::MAX {
            return None;
        }
        let plans: Vec<Option<RootPlan>> =
            join(chunks(steps, EVAL_CHUNK, |c| self.root_plans(c, true)));
        let batch: Vec<RootPlan> = plans.iter().flatten().copied().collect();
        let fitted = match self.fitted_states(&batch, obs)? {
            Ok(v) => v,
            Err(e) => return Some(Err(e)),
        };
        if fitted.len() == steps.len() {
            return Some(Ok(fitted));
        }
        let others: Vec<(f64, History)> = steps
            .iter()
            .zip(&plans)
            .filter(|(_, p)| p.is_none())
            .map(|(&s, _)| s)
            .collect();
        let others: Result<Vec<State>> = chunks(&others, 1, |c| self.state(c[0].0, c[0].1, obs))
            .into_iter()
            .collect();
        let others = match others {
            Ok(v) => v,
            Err(e) => return Some(Err(e)),
        };
        let (mut fitted, mut others) = (fitted.into_iter(), others.into_iter());
        Some(Ok(plans
            .iter()
            .map(|p| match p {
                Some(_) => fitted.next(),
                None => others.next(),
            })
            .map(|s| s.expect("one state per step"))
            .collect()))
    }

    /// The states of `plans` (approach, or a reversible law: functions of
    /// `d` alone) from an interpolant of the curve, in order; `None` where
    /// the interpolant does not apply: fewer than [`CURVE_FIT_MIN_STATES`]
    /// states, or a node whose totals are not all positive. The heights
    /// are unbounded ([`GwModel::curve_states`] checks).
    fn fitted_states(&self, plans: &[RootPlan], obs: &Observables) -> Option<Result<Vec<State>>> {
        if plans.len() < CURVE_FIT_MIN_STATES {
            return None;
        }
        let (a, b) = plans
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                (a.min(p.d), b.max(p.d))
            });
        if !(b > a) {
            return None;
        }
        let mut node_model = self.clone();
        node_model.accuracy.rel_tol = self.accuracy.rel_tol * NODE_RTOL_SHARE;
        let mut fits = Vec::new();
        let mut evaluations = 0;
        let mut queue = vec![(a, b, 0usize)];
        while let Some((lo, hi, depth)) = queue.pop() {
            match node_model.fit_panel(lo, hi, obs, self.accuracy.rel_tol, &mut evaluations)? {
                Some(panel) => fits.push(Fit::Interpolant(panel)),
                None if depth < MAX_DEPTH => {
                    let mid = 0.5 * (lo + hi);
                    queue.push((mid, hi, depth + 1));
                    queue.push((lo, mid, depth + 1));
                }
                None => fits.push(Fit::Direct { lo, hi }),
            }
        }
        fits.sort_by(|x, y| x.lo().total_cmp(&y.lo()));
        // The nodes' evaluations shared out over the states.
        let share = evaluations.div_ceil(plans.len());
        let mask = obs.mask();
        // Consecutive states on one panel are evaluated together.
        let eval = |chunk: &[RootPlan]| -> Result<Vec<State>> {
            let mut out = Vec::with_capacity(chunk.len());
            let mut rest = chunk;
            while let Some(first) = rest.first() {
                let fit = &fits[fits
                    .partition_point(|f| f.hi() < first.d)
                    .min(fits.len() - 1)];
                let run = rest
                    .iter()
                    .position(|p| !(p.d >= fit.lo() && p.d <= fit.hi()))
                    .unwrap_or(rest.len())
                    .max(1);
                let (here, next) = rest.split_at(run);
                match fit {
                    Fit::Interpolant(panel) => panel.states(here, mask, share, &mut out),
                    Fit::Direct { .. } => {
                        for st in self.root_states_any(here, obs) {
                            out.push(st?);
                        }
                    }
                }
                rest = next;
            }
            Ok(out)
        };
        Some(
            chunks(plans, EVAL_CHUNK, eval)
                .into_iter()
                .collect::<Result<Vec<Vec<State>>>>()
                .map(join),
        )
    }

    /// The interpolant of `[lo, hi]` at the first Lobatto order in
    /// [`LEVELS`] whose estimate meets `rtol` in every total, `Ok(None)` if
    /// none does, `None` when a node's totals are not all positive and
    /// finite (or a node has no heights in contact range). `self` is the
    /// node model (its tolerance a share of `rtol`); the nodes' law
    /// evaluations are added to `evaluations`.
    fn fit_panel(
        &self,
        lo: f64,
        hi: f64,
        obs: &Observables,
        rtol: f64,
        evaluations: &mut usize,
    ) -> Option<Option<Panel>> {
        let mask = obs.mask();
        let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
        // ln F and relative error at the nodes of the current level.
        let mut values: Vec<[f64; SLOTS]> = Vec::new();
        let mut node_error = [0.0f64; SLOTS];
        let mut n_prev = 0;
        for &n in &LEVELS {
            // The new nodes: all at the first level, the odd ones after.
            let new: Vec<usize> = (0..=n).filter(|j| n_prev == 0 || j % 2 == 1).collect();
            let ranges = self.height_ranges();
            let plans: Option<Vec<RootPlan>> = new
                .iter()
                .map(|&j| {
                    let x = (std::f64::consts::PI * j as f64 / n as f64).cos();
                    let d = mid + half * x;
                    let (s_lo, s_hi, far) = ranges.at(d);
                    (s_hi > s_lo && far.is_none()).then_some(RootPlan { d, s_lo, s_hi })
                })
                .collect();
            let states = join(chunks(&plans?, ROOT_BATCH, |c| {
                self.root_states_any(c, obs)
            }));
            let mut fresh = Vec::with_capacity(states.len());
            for st in states {
                let st = st.ok()?;
                *evaluations += st.evaluations;
                let mut v = [0.0; SLOTS];
                for k in (0..SLOTS).filter(|&k| mask[k]) {
                    let (f, e) = (st.totals.get(k)?, st.totals.error(k)?);
                    if !(f > 0.0 && f.is_finite()) {
                        return None;
                    }
                    v[k] = f.ln();
                    node_error[k] = node_error[k].max(e / f);
                }
                fresh.push(v);
            }
            values = if n_prev == 0 {
                fresh
            } else {
                // Interleave: even j from the previous level, odd j new.
                let mut fresh = fresh.into_iter();
                (0..=n)
                    .map(|j| {
                        if j % 2 == 0 {
                            values[j / 2]
                        } else {
                            fresh.next().expect("one per odd node")
                        }
                    })
                    .collect()
            };
            let lebesgue = 1.0 + std::f64::consts::FRAC_2_PI * ((n + 1) as f64).ln();
            let mut coef: [Vec<f64>; SLOTS] = Default::default();
            let mut error = [0.0; SLOTS];
            let cos = lobatto_cosines(n);
            for k in (0..SLOTS).filter(|&k| mask[k]) {
                let y: Vec<f64> = values.iter().map(|v| v[k]).collect();
                coef[k] = lobatto_coefficients(&y, &cos);
                error[k] =
                    2.0 * (coef[k][n - 1].abs() + coef[k][n].abs()) + lebesgue * node_error[k];
            }
            if (0..SLOTS).all(|k| !mask[k] || error[k] <= rtol) {
                return Some(Some(Panel {
                    lo,
                    hi,
                    coef,
                    error,
                }));
            }
            n_prev = n;
        }
        Some(None)
    }
}

impl Fit {
    fn lo(&self) -> f64 {
        match self {
            Fit::Interpolant(p) => p.lo,
            Fit::Direct { lo, .. } => *lo,
        }
    }

    fn hi(&self) -> f64 {
        match self {
            Fit::Interpolant(p) => p.hi,
            Fit::Direct { hi, .. } => *hi,
        }
    }
}

impl Panel {
    /// The states at `plans` (separations in `[lo, hi]`), appended to
    /// `out`: `exp` of each total's series.
    fn states(
        &self,
        plans: &[RootPlan],
        mask: [bool; SLOTS],
        evaluations: usize,
        out: &mut Vec<State>,
    ) {
        crate::numeric::simd::arch().dispatch(PanelStates {
            panel: self,
            plans,
            mask,
            evaluations,
            out,
        });
    }
}

/// [`Panel::states`] as a [`pulp::WithSimd`] operation: the Clenshaw sums
/// of [`LANES`] states interleaved, then `exp` without branches
/// ([`exp_lane`]).
struct PanelStates<'a> {
    panel: &'a Panel,
    plans: &'a [RootPlan],
    mask: [bool; SLOTS],
    evaluations: usize,
    out: &'a mut Vec<State>,
}

impl pulp::WithSimd for PanelStates<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _simd: S) {
        let p = self.panel;
        let (mid, scale) = (0.5 * (p.lo + p.hi), 2.0 / (p.hi - p.lo));
        for plans in self.plans.chunks(LANES) {
            let mut x = [0.0; LANES];
            for (x, q) in x.iter_mut().zip(plans) {
                *x = ((q.d - mid) * scale).clamp(-1.0, 1.0);
            }
            let mut values = [[0.0; LANES]; SLOTS];
            for k in (0..SLOTS).filter(|&k| self.mask[k]) {
                let c = &p.coef[k];
                let y = clenshaw_lanes_dyn(c.len() - 1, &x, |_, j| c[j]);
                for (v, &y) in values[k].iter_mut().zip(&y) {
                    // Nodes are positive doubles, so ln F >= -745 there;
                    // the clamp keeps `exp_lane` in its range between them.
                    *v = exp_lane(y.max(-746.0));
                }
            }
            self.out.extend(plans.iter().enumerate().map(|(l, q)| {
                let v: [f64; SLOTS] = std::array::from_fn(|k| values[k][l]);
                State {
                    separation: q.d,
                    totals: Totals::new(v, std::array::from_fn(|k| p.error[k] * v[k]), self.mask),
                    method: MethodUsed::Interpolated,
                    evaluations: self.evaluations,
                }
            }));
        }
    }
}

/// `f` of each chunk of `items`, in order: in parallel (rayon) when the
/// pool has more than one thread, else on this thread (no hand-over).
fn chunks<T: Sync, R: Send>(
    items: &[T],
    size: usize,
    f: impl Fn(&[T]) -> R + Sync + Send,
) -> Vec<R> {
    if rayon::current_num_threads() > 1 {
        items.par_chunks(size).map(f).collect()
    } else {
        items.chunks(size).map(f).collect()
    }
}

/// The vectors of `parts` one after another (the one itself when alone:
/// no copy).
fn join<T: Clone>(mut parts: Vec<Vec<T>>) -> Vec<T> {
    if parts.len() == 1 {
        parts.pop().unwrap_or_default()
    } else {
        parts.concat()
    }
}

/// `cos(pi m/n)` for `m = 0..2n`.
fn lobatto_cosines(n: usize) -> Vec<f64> {
    (0..2 * n)
        .map(|m| (std::f64::consts::PI * m as f64 / n as f64).cos())
        .collect()
}

/// Chebyshev coefficients `c_0..c_n` of the polynomial through `y_j` at the
/// Lobatto points `x_j = cos(pi j/n)`, `j = 0..n`:
/// `c_k = (2/n) sum''_j y_j cos(pi j k/n)` (first and last terms halved),
/// `c_0` and `c_n` halved again; `cos` is [`lobatto_cosines`]`(n)`.
fn lobatto_coefficients(y: &[f64], cos: &[f64]) -> Vec<f64> {
    let n = y.len() - 1;
    (0..=n)
        .map(|k| {
            let mut s = 0.5 * (y[0] + y[n] * cos[(n * k) % (2 * n)]);
            for (j, &yj) in y.iter().enumerate().take(n).skip(1) {
                s += yj * cos[(j * k) % (2 * n)];
            }
            let c = 2.0 * s / n as f64;
            if k == 0 || k == n {
                0.5 * c
            } else {
                c
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gw::tests::{assert_within_tolerance_and_estimate, root_smooth_laws};
    use crate::gw::{Accuracy, RoughSurface};
    use crate::heights::{Gaussian, TruncatedGaussian};
    use std::sync::Arc;

    /// Many approach states of Hertz (with an extra total) and
    /// Kogut–Etsion summits (three jumps) on Gaussian heights come from the
    /// interpolant of the curve: every total within the tolerance of a
    /// 1e-12 adaptive curve and within its own error estimate, the same
    /// bits on one and two threads; on bounded heights (an edge in the
    /// density) the states are computed one by one.
    #[test]
    fn interpolated_curves_meet_their_tolerance() {
        let s = RoughSurface::gold_microswitch();
        let (hertz, ke, extra) = root_smooth_laws(&s);
        // The bulk, and -6 sigma to 33 sigma, where the density is 1e-237
        // (at 1e-8 the range is halved: 65 and 17 nodes).
        let bulk: Vec<(f64, History)> = (0..CURVE_FIT_MIN_STATES + 72)
            .map(|i| ((5.0 - 0.04 * i as f64) * s.sigma, History::Approach))
            .collect();
        let wide: Vec<(f64, History)> = (0..CURVE_FIT_MIN_STATES + 72)
            .map(|i| ((-6.0 + 0.195 * i as f64) * s.sigma, History::Approach))
            .collect();
        let cases = [
            (hertz.clone(), &extra, &bulk),
            (ke, &Observables::ALL, &bulk),
            (hertz, &extra, &wide),
        ];
        for (law, obs, steps) in cases {
            let m = GwModel::new(s, Arc::new(Gaussian::new()), law.clone()).unwrap();
            let reference = m
                .clone()
                .with_accuracy(Accuracy::new(1e-12).unwrap())
                .states(steps, obs)
                .unwrap();
            for tol in [1e-8, 1e-6, 1e-3] {
                let m = m.clone().with_accuracy(Accuracy::new(tol).unwrap());
                let pool = |n| {
                    rayon::ThreadPoolBuilder::new()
                        .num_threads(n)
                        .build()
                        .unwrap()
                };
                let one = pool(1).install(|| m.states(steps, obs).unwrap());
                let two = pool(2).install(|| m.states(steps, obs).unwrap());
                assert_eq!(one, two, "{} tol {tol}: threads", law.name());
                for (st, r) in one.iter().zip(&reference) {
                    assert_eq!(st.method, MethodUsed::Interpolated);
                    assert_within_tolerance_and_estimate(st, r, tol, law.name());
                }
            }
            // A bad separation among many is named, not interpolated over.
            let mut bad = steps.clone();
            bad[7].0 = f64::NAN;
            let e = m.states(&bad, obs).unwrap_err().to_string();
            assert!(e.contains("separation"), "{e}");
            let bounded = GwModel::new(s, Arc::new(TruncatedGaussian::new(3.0).unwrap()), law)
                .unwrap()
                .with_accuracy(Accuracy::new(1e-6).unwrap());
            let states = bounded.states(steps, obs).unwrap();
            assert!(states
                .iter()
                .all(|st| st.method != MethodUsed::Interpolated));
        }
    }

    /// `sum_j c_j T_j(x)` by the lane Clenshaw of the panels, in every lane.
    fn series(c: &[f64], x: f64) -> f64 {
        let y = clenshaw_lanes_dyn(c.len() - 1, &[x; LANES], |_, j| c[j]);
        assert!(y.iter().all(|v| v.to_bits() == y[0].to_bits()));
        y[0]
    }

    /// The Lobatto coefficients reproduce a polynomial of degree `n`
    /// exactly, and its values at the nodes.
    #[test]
    fn lobatto_coefficients_interpolate() {
        let n = 16;
        let f = |x: f64| (0.3 * x).exp() - x.powi(16);
        let y: Vec<f64> = (0..=n)
            .map(|j| f((std::f64::consts::PI * j as f64 / n as f64).cos()))
            .collect();
        let c = lobatto_coefficients(&y, &lobatto_cosines(n));
        for (j, &yj) in y.iter().enumerate() {
            let x = (std::f64::consts::PI * j as f64 / n as f64).cos();
            assert!((series(&c, x) - yj).abs() < 1e-14, "node {j}");
        }
        // T_16's coefficient of -x^16 is -2^-15; exp(0.3x)'s c_16 ~ 1e-27.
        assert!((c[16] + 2f64.powi(-15)).abs() < 1e-15, "{}", c[16]);
        for x in [-0.95, -0.3, 0.123, 0.77] {
            assert!((series(&c, x) - f(x)).abs() < 1e-13, "{x}");
        }
    }
}
