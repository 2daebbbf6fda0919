//! The height density at one quadrature panel's 21 nodes `z_j`, shifted
//! by every closest gap `h_k`: `phi(z_j + h_k)`, the weights of the
//! vector integrand of `shared_heights.rs`.
//!
//! Any distribution: one density per pair ([`HeightDistribution::pdf_batch`]).
//! Standard normal heights
//! ([`HeightDistribution::is_standard_normal`]) have the product form
//!
//! ```text
//! phi(s + d) = phi(s) exp(-s d) exp(-d^2/2)
//! ```
//!
//! so with the closest gaps in ascending order, `h_i = h_(i-1) + d_i`,
//!
//! ```text
//! phi(z_j + h_i) = phi(z_j + h_(i-1)) exp(-z_j d_i) exp(-h_(i-1) d_i - d_i^2/2)
//! ```
//!
//! The last factor does not depend on the node (one `exp` per closest gap
//! and call), and `exp(-z_j d)` only on the step: the retraction table's
//! closest gaps are Chebyshev–Lobatto nodes of panels of equal width, whose
//! steps take a handful of values. Each step is rounded to a multiple
//! `d'` of [`QUANTUM`], and `exp(-z_j (d - d'))` restored by its
//! second-order Taylor polynomial (`|z_j (d - d')| <= 1.1e-6`: remainder
//! below `2.2e-19`). A panel then costs one `exp` per node and distinct
//! step plus one direct density per node every [`RESTART`] closest gaps
//! (which bounds the rounding carried along the chain to a few ulp per
//! step), instead of one per pair. Every factor of the chain is the density
//! at a height within the panel's range, so nothing underflows where that
//! range stays within [`MAX_HEIGHT`] (otherwise the panel is direct).

use crate::heights::HeightDistribution;
use crate::special::normal;

/// Steps between closest gaps are rounded to multiples of this (`2^-24`).
const QUANTUM: f64 = 1.0 / 16_777_216.0;
/// Every this many closest gaps (ascending) one row of direct densities.
const RESTART: usize = 8;
/// Largest `|z + h|` of a panel stepped by the product form: the density
/// there, `phi(36) ~ 1e-282`, is a normal number, as is every factor of
/// the chain (all densities at heights of the panel's range).
const MAX_HEIGHT: f64 = 36.0;
/// Largest step `|d|` taken by the product form (`exp(+-36 d)` and the
/// chain's factors stay far from overflow); wider gaps restart the chain.
const MAX_STEP: f64 = 1.0;

/// One closest gap in ascending order: its row, how it is reached.
#[derive(Debug, Clone, Copy)]
struct Step {
    /// Row (index of the closest gap as given).
    k: usize,
    /// Row it steps from, `None` for a direct row.
    from: Option<usize>,
    /// Index of its rounded step `d'` in [`Shifts::steps`].
    slot: usize,
    /// `d - d'`.
    eps: f64,
    /// `exp(-h_(i-1) d - d^2/2)`.
    factor: f64,
}

/// The shifted densities of one set of closest gaps, for any panel.
pub(crate) struct Shifts<'a> {
    dist: &'a dyn HeightDistribution,
    h: &'a [f64],
    /// `(min, max)` of `h`.
    span: (f64, f64),
    /// The product-form plan (standard normal heights where it saves work).
    plan: Option<Vec<Step>>,
    /// Distinct rounded steps `d'`.
    steps: Vec<f64>,
}

impl<'a> Shifts<'a> {
    /// The shifts `h` (units of `sigma`) of `dist`'s density.
    pub fn new(dist: &'a dyn HeightDistribution, h: &'a [f64]) -> Self {
        let span = h
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                (a.min(x), b.max(x))
            });
        let mut shifts = Shifts {
            dist,
            h,
            span,
            plan: None,
            steps: Vec::new(),
        };
        if dist.is_standard_normal() && h.iter().all(|x| x.is_finite()) {
            shifts.plan_steps();
        }
        shifts
    }

    /// Whether panels within range take the product form.
    #[cfg(test)]
    pub fn stepped(&self) -> bool {
        self.plan.is_some()
    }

    /// The chain in ascending `h`; kept only when its `exp` rows (distinct
    /// steps and restarts) are fewer than half the direct ones.
    fn plan_steps(&mut self) {
        let n = self.h.len();
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|&x, &y| self.h[x].total_cmp(&self.h[y]));
        let mut plan = Vec::with_capacity(n);
        let mut direct = 0;
        for (i, &k) in order.iter().enumerate() {
            let prev = (i > 0).then(|| order[i - 1]);
            let d = prev.map_or(0.0, |p| self.h[k] - self.h[p]);
            let from = prev.filter(|_| i % RESTART != 0 && d.abs() <= MAX_STEP);
            let Some(p) = from else {
                direct += 1;
                plan.push(Step {
                    k,
                    from: None,
                    slot: 0,
                    eps: 0.0,
                    factor: 1.0,
                });
                continue;
            };
            let rounded = (d / QUANTUM).round() * QUANTUM;
            let slot = match self.steps.iter().position(|&s| s == rounded) {
                Some(s) => s,
                None => {
                    self.steps.push(rounded);
                    self.steps.len() - 1
                }
            };
            let hp = self.h[p];
            plan.push(Step {
                k,
                from: Some(p),
                slot,
                eps: d - rounded,
                factor: (-hp * d - 0.5 * d * d).exp(),
            });
        }
        if 2 * (direct + self.steps.len()) < n {
            self.plan = Some(plan);
        } else {
            self.steps.clear();
        }
    }

    /// `heights[21 k + j] = z[j] + h[k]` and `density[21 k + j] =
    /// phi(z[j] + h[k])` (both of length `21 h.len()`; `z` ascending).
    pub fn fill(&self, z: &[f64; 21], heights: &mut [f64], density: &mut [f64]) {
        for (k, &h) in self.h.iter().enumerate() {
            for j in 0..21 {
                heights[21 * k + j] = z[j] + h;
            }
        }
        let plan = match &self.plan {
            Some(plan)
                if (z[0] + self.span.0).abs().max((z[20] + self.span.1).abs()) <= MAX_HEIGHT =>
            {
                plan
            }
            _ => {
                self.dist.pdf_batch(heights, density);
                return;
            }
        };
        // exp(-z_j d') of every distinct step
        let mut exps = vec![0.0; 21 * self.steps.len()];
        let args: Vec<f64> = self
            .steps
            .iter()
            .flat_map(|&d| z.iter().map(move |&z| -z * d))
            .collect();
        normal::exp_batch(&args, &mut exps);
        for s in plan {
            let row = 21 * s.k;
            let Some(p) = s.from else {
                self.dist
                    .pdf_batch(&heights[row..row + 21], &mut density[row..row + 21]);
                continue;
            };
            let (from, e) = (21 * p, &exps[21 * s.slot..21 * s.slot + 21]);
            for j in 0..21 {
                let x = z[j] * s.eps;
                let fix = 1.0 - x + 0.5 * x * x;
                density[row + j] = density[from + j] * e[j] * (s.factor * fix);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::heights::{Exponential, Gaussian};
    use crate::numeric::quadrature::kronrod21_nodes;
    use proptest::prelude::*;

    /// Chebyshev–Lobatto nodes of `panels` panels of width `w` from `lo`
    /// (as the retraction table places its closest gaps), deduplicated.
    fn lobatto_set(lo: f64, w: f64, panels: usize) -> Vec<f64> {
        let mut h: Vec<f64> = (0..panels)
            .flat_map(|p| {
                let (a, b) = (lo + p as f64 * w, lo + (p + 1) as f64 * w);
                (0..=10).map(move |k| {
                    0.5 * (a + b) + 0.5 * (b - a) * (std::f64::consts::PI * k as f64 / 10.0).cos()
                })
            })
            .collect();
        h.sort_by(f64::total_cmp);
        h.dedup();
        h
    }

    /// Largest relative difference of `fill` from `pdf` at every pair, in
    /// units of the rounding both carry: the density's condition number
    /// in its argument `s = z + h` is `|s|`, so rounding `s` (half an ulp,
    /// `|s| eps/2`) errs by `s^2 eps/2`, in the direct row a chain starts
    /// from and in the reference; each of at most `RESTART - 1` steps
    /// rounds its step `d` (ulp of `|h|`), `z d'` and `h d` once (and a
    /// few products): `(RESTART - 1) (4 + |z| + |h|) eps`.
    fn worst(shifts: &Shifts, h: &[f64], z: &[f64; 21]) -> f64 {
        let (mut heights, mut density) = (vec![0.0; 21 * h.len()], vec![0.0; 21 * h.len()]);
        shifts.fill(z, &mut heights, &mut density);
        let mut worst = 0.0f64;
        for (k, &hk) in h.iter().enumerate() {
            for j in 0..21 {
                assert_eq!(heights[21 * k + j], z[j] + hk);
                let want = normal::pdf(z[j] + hk);
                let got = density[21 * k + j];
                if want == 0.0 {
                    assert_eq!(got, 0.0, "z {} h {hk}", z[j]);
                    continue;
                }
                let s = z[j] + hk;
                let steps = (RESTART - 1) as f64 * (4.0 + z[j].abs() + hk.abs());
                let unit = (s * s + steps) * f64::EPSILON;
                worst = worst.max((got - want).abs() / want / unit);
            }
        }
        worst
    }

    /// The retraction table's first closest gaps (101 Lobatto nodes of ten
    /// panels of width 1): the product form is taken and every density is
    /// within its rounding bound (`worst`) of the direct one, on panels
    /// across the whole range.
    #[test]
    fn stepped_densities_match_the_direct_ones_on_lobatto_gaps() {
        let h = lobatto_set(-3.0, 1.0, 10);
        assert_eq!(h.len(), 101);
        let shifts = Shifts::new(&Gaussian, &h);
        assert!(shifts.stepped());
        // five distinct steps of a Lobatto panel (symmetric), some split by
        // their rounding
        assert!(shifts.steps.len() <= 10, "{}", shifts.steps.len());
        for (a, b) in [
            (-20.0, -15.0),
            (-8.0, -7.5),
            (-1.0, 0.0),
            (0.3, 0.31),
            (6.0, 25.0),
        ] {
            let z = kronrod21_nodes(a, b);
            let w = worst(&shifts, &h, &z);
            assert!(w <= 1.0, "[{a}, {b}]: {w}");
        }
    }

    /// Where the product form is not allowed or saves nothing, the direct
    /// densities: another distribution, few or far-apart closest gaps, a
    /// panel out of range.
    #[test]
    fn direct_densities_where_the_product_form_is_not_taken() {
        let h = lobatto_set(0.0, 1.0, 4);
        assert!(!Shifts::new(&Exponential::new(), &h).stepped());
        assert!(!Shifts::new(&Gaussian, &[0.0, 1.0, 2.0]).stepped());
        let far: Vec<f64> = (0..40).map(|k| 1.5 * k as f64).collect();
        assert!(!Shifts::new(&Gaussian, &far).stepped());
        let shifts = Shifts::new(&Gaussian, &h);
        assert!(shifts.stepped());
        // |z + h| up to 44: direct, the batch's own densities
        let z = kronrod21_nodes(30.0, 40.0);
        let (mut heights, mut density) = (vec![0.0; 21 * h.len()], vec![0.0; 21 * h.len()]);
        shifts.fill(&z, &mut heights, &mut density);
        let mut direct = vec![0.0; heights.len()];
        normal::pdf_batch(&heights, &mut direct);
        assert_eq!(density, direct);
        // the exponential density through the default batch
        let e = Exponential::new();
        let shifts = Shifts::new(&e, &h);
        let z = kronrod21_nodes(0.5, 2.0);
        let (mut heights, mut density) = (vec![0.0; 21 * h.len()], vec![0.0; 21 * h.len()]);
        shifts.fill(&z, &mut heights, &mut density);
        for (s, d) in heights.iter().zip(&density) {
            assert_eq!(*d, e.pdf(*s));
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// Over the parameter box the retraction table reaches (closest
        /// gaps from Lobatto panels of any width in [1e-3, 1] anywhere in
        /// [-12, 12], with random extra gaps; panels anywhere their
        /// heights stay within MAX_HEIGHT): stepped within the rounding
        /// bound of direct.
        #[test]
        fn stepped_densities_match_the_direct_ones(
            lo in -12.0f64..8.0,
            w in 1e-3f64..1.0,
            panels in 1usize..12,
            extra in proptest::collection::vec(-12.0f64..12.0, 0..6),
            a in -30.0f64..20.0,
            width in 1e-6f64..10.0,
        ) {
            let mut h = lobatto_set(lo, w, panels);
            h.extend(extra);
            let z = kronrod21_nodes(a, a + width);
            let shifts = Shifts::new(&Gaussian, &h);
            let w = worst(&shifts, &h, &z);
            prop_assert!(w <= 1.0, "{}", w);
        }
    }
}
