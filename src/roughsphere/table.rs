//! A smooth function of one variable as piecewise Chebyshev interpolants
//! with its derivative: the local Greenwood–Williamson pressure `p(H)` of a
//! law without closed forms, tabulated once from
//! [`GwModel`](crate::gw::GwModel) states so that Newton's Jacobian has an
//! exact derivative of the same function its residual uses.
//!
//! Panels are bisected until the degree-[`DEG`] interpolant through the
//! Chebyshev–Lobatto nodes matches the function at the interleaved
//! midpoints within `tol (|f| + scale)`; panels narrower than
//! `MIN_WIDTH` of the interval are accepted as they are (a kink of the
//! function, e.g. where summits start to touch, is then resolved by
//! geometric refinement towards it).

use crate::error::{Error, Result};
use crate::numeric::chebyshev::{clenshaw, lobatto_coefficients, lobatto_nodes};
use std::collections::HashMap;
use std::f64::consts::PI;
use std::sync::Arc;

/// Polynomial degree per panel.
pub(crate) const DEG: usize = 10;
/// Narrowest panel, as a fraction of the table's interval: next to a
/// kink with a fractional power (a JKR fold seen through the height
/// integral, `(H_k - H)^(3/2)`) geometric refinement stops here, where the
/// function changes by about `1e-10` of its scale across a panel.
const MIN_WIDTH: f64 = 1e-7;
/// Most panels in one table.
const MAX_PANELS: usize = 20_000;

/// `n` functions at once: per point, the `n` values ([`Table::build_many`]).
pub(crate) type Many<'a> = dyn Fn(&[f64]) -> Result<Vec<Vec<f64>>> + 'a;

/// `f` and `f'` as piecewise Chebyshev series on `[lo, hi]`.
#[derive(Debug, Clone)]
pub(crate) struct Table {
    /// Panel edges (shared by the tables of one [`Table::build_many`]).
    edges: Arc<[f64]>,
    coef: Vec<[f64; DEG + 1]>,
    /// Coefficients of the derivative (in the panel's own variable).
    dcoef: Vec<[f64; DEG + 1]>,
}

/// Chebyshev coefficients of the derivative (d/dx on `[-1, 1]`).
fn derivative(c: &[f64; DEG + 1]) -> [f64; DEG + 1] {
    let mut d = [0.0; DEG + 1];
    // d_{k-1} = d_{k+1} + 2 k c_k, d_DEG = 0
    for k in (1..=DEG).rev() {
        let next = if k < DEG { d[k + 1] } else { 0.0 };
        d[k - 1] = next + 2.0 * k as f64 * c[k];
    }
    d[0] *= 0.5;
    d
}

/// The Lobatto nodes of `[a, b]` in the order of [`lobatto_nodes`], the
/// ends and the centre exact (shared with neighbours and halves).
fn panel_nodes(a: f64, b: f64) -> [f64; DEG + 1] {
    let nodes: [f64; DEG + 1] = lobatto_nodes();
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    std::array::from_fn(|k| match k {
        0 => b,
        DEG => a,
        _ if 2 * k == DEG => mid,
        _ => mid + half * nodes[k],
    })
}

/// The `DEG` interleaved Chebyshev points of `[-1, 1]` (between the
/// nodes), where a panel's interpolant is checked.
fn interleaved() -> [f64; DEG] {
    std::array::from_fn(|k| (PI * (k as f64 + 0.5) / DEG as f64).cos())
}

/// The values found so far, by point.
#[derive(Default)]
struct Known {
    values: HashMap<u64, Vec<f64>>,
}

impl Known {
    /// Evaluates `f` at the points of `xs` not yet known, in one call.
    ///
    /// # Errors
    /// `f`'s error.
    fn fill<'x>(&mut self, xs: impl Iterator<Item = &'x f64>, f: &Many<'_>) -> Result<()> {
        let mut want: Vec<f64> = Vec::new();
        for &x in xs {
            if !self.values.contains_key(&x.to_bits()) && !want.contains(&x) {
                want.push(x);
            }
        }
        if want.is_empty() {
            return Ok(());
        }
        let ys = f(&want)?;
        for (x, y) in want.into_iter().zip(ys) {
            self.values.insert(x.to_bits(), y);
        }
        Ok(())
    }

    /// The values at `x` (evaluated by [`Known::fill`]).
    fn get(&self, x: f64) -> &[f64] {
        &self.values[&x.to_bits()]
    }
}

impl Table {
    /// Tabulates `f` on `[lo, hi]`, split at `splits` (its known kinks), to
    /// `tol (|f| + scale)`; `f` returns
    /// `Err` to abort (a failed quadrature). `f` is called on the points of
    /// a panel it has not seen yet, at most 14 at once (the `DEG + 1` nodes
    /// and three test points), so the caller may evaluate them in parallel.
    ///
    /// # Errors
    /// `f`'s error, or [`Error::NoConvergence`] when more than
    /// `MAX_PANELS` panels would be needed.
    pub fn build(
        lo: f64,
        hi: f64,
        splits: &[f64],
        tol: f64,
        scale: f64,
        f: &dyn Fn(&[f64]) -> Result<Vec<f64>>,
    ) -> Result<Self> {
        let many = |xs: &[f64]| -> Result<Vec<Vec<f64>>> {
            Ok(f(xs)?.into_iter().map(|y| vec![y]).collect())
        };
        let mut t = Self::build_many(lo, hi, splits, tol, scale, 1, &many)?;
        Ok(t.remove(0))
    }

    /// [`Table::build`] of `n` functions on the same panels: `f(xs)`
    /// returns, per point of `xs`, the `n` values; a panel is accepted
    /// when every function passes (functions with the same kinks, whose
    /// values share their costly part: the retraction pressures of many
    /// closest gaps from one set of law evaluations, `shared_heights.rs`).
    ///
    /// Each point is evaluated once (panels share their ends, a half its
    /// ends with its parent), and a panel's test points after its nodes in
    /// two steps: three of them first, the other seven only when those
    /// pass (a rejected panel usually fails at the first three; the
    /// decision is that of all ten, whichever order they are checked in).
    ///
    /// # Errors
    /// As [`Table::build`].
    pub fn build_many(
        lo: f64,
        hi: f64,
        splits: &[f64],
        tol: f64,
        scale: f64,
        n: usize,
        f: &Many<'_>,
    ) -> Result<Vec<Self>> {
        // Known kinks of the function start their own panels.
        let mut cuts: Vec<f64> = splits
            .iter()
            .copied()
            .filter(|x| *x > lo && *x < hi)
            .collect();
        cuts.push(lo);
        cuts.push(hi);
        cuts.sort_by(f64::total_cmp);
        cuts.dedup();
        let mut todo: Vec<(f64, f64)> = cuts.windows(2).map(|w| (w[0], w[1])).rev().collect();
        let mut done: Vec<(f64, Vec<[f64; DEG + 1]>)> = Vec::new();
        let mut known = Known::default();
        while let Some((a, b)) = todo.pop() {
            let xs = panel_nodes(a, b);
            let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
            let tests = interleaved().map(|u| (u, mid + half * u));
            // A few test points first: most rejected panels fail there,
            // and the others are evaluated only for a panel that passes.
            let first = [tests[0], tests[DEG / 2], tests[DEG - 1]];
            known.fill(xs.iter().chain(first.iter().map(|t| &t.1)), f)?;
            let cs: Vec<[f64; DEG + 1]> = (0..n)
                .map(|i| lobatto_coefficients(&xs.map(|x| known.get(x)[i])))
                .collect();
            let passes = |known: &Known, &(t, x): &(f64, f64)| {
                let y = known.get(x);
                cs.iter().enumerate().all(|(i, c)| {
                    let e = (clenshaw(c, t) - y[i]).abs();
                    e <= tol * (y[i].abs() + scale)
                })
            };
            let mut ok = first.iter().all(|t| passes(&known, t));
            if ok {
                known.fill(tests.iter().map(|t| &t.1), f)?;
                ok = tests.iter().all(|t| passes(&known, t));
            }
            if ok || b - a <= MIN_WIDTH * (hi - lo) {
                done.push((a, cs));
            } else {
                todo.push((mid, b));
                todo.push((a, mid));
            }
            if done.len() + todo.len() > MAX_PANELS {
                return Err(Error::NoConvergence {
                    what: "local pressure table".into(),
                    iterations: known.values.len(),
                    residual: f64::NAN,
                });
            }
        }
        done.sort_by(|x, y| x.0.total_cmp(&y.0));
        let mut edges: Vec<f64> = done.iter().map(|x| x.0).collect();
        edges.push(hi);
        let edges: Arc<[f64]> = edges.into();
        Ok((0..n)
            .map(|i| {
                let coef: Vec<[f64; DEG + 1]> = done.iter().map(|x| x.1[i]).collect();
                let dcoef = coef.iter().map(derivative).collect();
                Table {
                    edges: edges.clone(),
                    coef,
                    dcoef,
                }
            })
            .collect())
    }

    /// `sum_k c_k f_k` as one table, when every `f_k` has the same panels
    /// (tables of one [`Table::build_many`]); `None` otherwise. Its value
    /// and slope are those of the sum to rounding, at the cost of one
    /// table.
    pub fn combine(terms: &[(f64, &Table)]) -> Option<Table> {
        let (_, first) = terms.first()?;
        if !terms
            .iter()
            .all(|(_, t)| Arc::ptr_eq(&t.edges, &first.edges))
        {
            return None;
        }
        let sum = |pick: fn(&Table) -> &Vec<[f64; DEG + 1]>| -> Vec<[f64; DEG + 1]> {
            (0..first.coef.len())
                .map(|i| {
                    std::array::from_fn(|j| terms.iter().map(|(c, t)| c * pick(t)[i][j]).sum())
                })
                .collect()
        };
        Some(Table {
            edges: first.edges.clone(),
            coef: sum(|t| &t.coef),
            dcoef: sum(|t| &t.dcoef),
        })
    }

    /// Interval covered.
    pub fn range(&self) -> (f64, f64) {
        (self.edges[0], self.edges[self.edges.len() - 1])
    }

    /// `(f(x), f'(x))`; outside the interval the end panels' polynomials
    /// are evaluated at the clamped point (callers stay inside).
    #[inline]
    pub fn eval(&self, x: f64) -> (f64, f64) {
        let n = self.coef.len();
        let i = self.edges.partition_point(|e| *e <= x).clamp(1, n) - 1;
        let (a, b) = (self.edges[i], self.edges[i + 1]);
        let t = ((2.0 * x - a - b) / (b - a)).clamp(-1.0, 1.0);
        let v = clenshaw(&self.coef[i], t);
        let dv = clenshaw(&self.dcoef[i], t) * 2.0 / (b - a);
        (v, dv)
    }

    /// Panels.
    #[cfg(test)]
    pub fn panels(&self) -> usize {
        self.coef.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_reproduces_a_smooth_function_and_its_slope() {
        let f = |x: f64| (-(x * x) / 2.0).exp() * (1.0 + x).sqrt();
        let df = |x: f64| {
            let e = (-(x * x) / 2.0).exp();
            e * (0.5 / (1.0 + x).sqrt() - x * (1.0 + x).sqrt())
        };
        let t = Table::build(-0.5, 6.0, &[], 1e-12, 0.0, &|xs| {
            Ok(xs.iter().map(|&x| f(x)).collect())
        })
        .unwrap();
        for k in 0..=200 {
            let x = -0.5 + 6.5 * k as f64 / 200.0;
            let (v, d) = t.eval(x);
            assert!((v - f(x)).abs() <= 1e-11 * f(x).abs() + 1e-300, "{x} {v}");
            assert!(
                (d - df(x)).abs() <= 1e-7 * (df(x).abs() + 1e-3),
                "{x} {d} {}",
                df(x)
            );
        }
        assert!(t.panels() < 200, "{}", t.panels());
    }
}
