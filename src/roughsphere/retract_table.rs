//! The local retraction pressure of every radius from one two-dimensional
//! table: `p(H, H_min)`, the Greenwood–Williamson load per unit nominal
//! area at gap `H` after the closest gap `H_min` (units of `sigma`, pressure
//! in Greenwood–Tripp units).
//!
//! A summit of height `z` is at interference `z - H` having reached at most
//! `z - H_min`, so with `t = H - H_min >= 0` and `z' = z - H_min`
//!
//! ```text
//! p(H_min + t, H_min) = eta int F(z' - t, z') phi(z' + H_min) dz'
//! ```
//!
//! (`F(delta, delta_max)` the law's force after its maximum, `phi` the
//! height density). Every kink of the law (branch breakpoints `b`, history
//! thresholds `c`, detachment) sits at a fixed `t = (c - b)/sigma`, while
//! `H_min` enters only through the shifted density, which is smooth (analytic
//! for Gaussian heights). Hence: for each Chebyshev–Lobatto node `H_min,k`
//! of panels in `H_min`, an adaptive piecewise Chebyshev table in `t`
//! ([`Table`], split at the kinks), and between the nodes barycentric
//! Chebyshev interpolation in `H_min` (degree [`DEG`]); the derivative
//! `dp/dH` at fixed `H_min` is `dp/dt`, interpolated the same way.
//!
//! Accuracy: the tables in `t` are built to a quarter of the tolerance; at
//! the [`DEG`] interleaved Chebyshev points of every `H_min` panel and
//! [`T_SAMPLES`] gaps `t`, the interpolated pressure is compared with the
//! model's own state there, and a panel whose largest difference exceeds
//! `tol (|p| + scale)` is bisected. The largest measured ratio is kept
//! ([`RetractTable::error`]). The cost is a few dozen tables in `t`,
//! whatever the number of mesh nodes (one table per node before); with
//! Kogut–Etsion summits and adhesion each table in `t` still needs about
//! 15 000 GW states (docs/performance.md).

use super::table::{Table, DEG};
use crate::error::{Error, Result};
use std::f64::consts::PI;
use std::sync::Arc;

/// Gaps `t` per panel at which the interpolation in `H_min` is checked
/// (clustered towards `t = 0`, where summits detach).
pub(crate) const T_SAMPLES: usize = 33;
/// Widest first panel in `H_min` (units `sigma`): the density varies on
/// the scale of one (on the Kogut–Etsion bump, panels of 2 failed their
/// check by 10-70 times and were halved; panels of 1 pass at 0.06-0.24).
const FIRST_WIDTH: f64 = 1.0;
/// Narrowest panel in `H_min` (units `sigma`): accepted as it is.
const MIN_WIDTH: f64 = 1e-3;
/// Most panels in `H_min`.
const MAX_PANELS: usize = 200;
/// The tables in `t` get this fraction of the tolerance (the Lebesgue
/// constant of degree-10 Lobatto interpolation is below 2.5, so their
/// share of the interpolated error is at most 0.6 of the tolerance; the
/// check at the test points measures the total).
const T_TABLE_SHARE: f64 = 0.25;
/// A halved panel whose error is still above this fraction of its
/// parent's has not gained from the halving: its error is not the
/// interpolation in `H_min` (degree-10 interpolation gains about 2^11 a
/// halving) but the tables in `t` or the states it is checked against,
/// which no halving reduces (on the Kogut–Etsion bump at 10 uN and rtol
/// 1e-7 panels stayed at 1.53 times the tolerance from a width of 1 sigma
/// down to 1e-3: 200 halvings at 0.2 s each, then a failure).
const STALLED: f64 = 0.5;
/// Such a panel is accepted while its error is at most this many times the
/// tolerance (the tables get a tenth of the solver's tolerance, so at most
/// the solver's own), its error kept in [`RetractTable::error`].
const STALLED_ACCEPTED: f64 = 10.0;

/// The pressures at closest gaps `h_mins` and gaps `h_min + t` for every
/// `t` of `ts`: per `t`, one value per closest gap (one set of law
/// evaluations serves them all, `shared_heights.rs`).
pub(crate) type Slices<'a> = dyn Fn(&[f64], &[f64]) -> Result<Vec<Vec<f64>>> + Sync + 'a;

/// `p(H, H_min)` for `H_min` in `[lo, hi_min]` and `t` in `[0, t_max]`.
#[derive(Debug)]
pub(crate) struct RetractTable {
    /// Panel edges in `H_min`.
    edges: Vec<f64>,
    /// Per panel, the tables in `t` at its Lobatto nodes
    /// `x_k = cos(pi k/DEG)` (`k = 0` at the panel's right end).
    nodes: Vec<Vec<Arc<Table>>>,
    /// Largest gap `t` tabulated.
    t_max: f64,
    /// Largest `|interpolated - direct|` over `tol (|p| + scale)` at the
    /// test points, times `tol`.
    #[cfg_attr(not(test), allow(dead_code))]
    error: f64,
}

/// The weights of one radius: tables and barycentric weights at its
/// `H_min` (one table with weight 1 on a node).
#[derive(Debug, Clone)]
pub(crate) struct Weights {
    terms: Vec<(f64, Arc<Table>)>,
    /// The terms as one table when they share their panels in `t`.
    combined: Option<Table>,
    h_min: f64,
    t_max: f64,
}

/// Lobatto nodes of `[a, b]`, from `b` down to `a` (ends and centre
/// exact, so that neighbours and halves share their tables).
fn lobatto(a: f64, b: f64) -> [f64; DEG + 1] {
    std::array::from_fn(|k| match k {
        0 => b,
        DEG => a,
        _ if 2 * k == DEG => 0.5 * (a + b),
        _ => 0.5 * (a + b) + 0.5 * (b - a) * (PI * k as f64 / DEG as f64).cos(),
    })
}

/// Normalised barycentric weights of the Lobatto nodes at `x` in `[-1, 1]`
/// (Berrut & Trefethen 2004: `w_k = (-1)^k`, halved at the ends).
fn barycentric(x: f64) -> Vec<(usize, f64)> {
    let mut out = Vec::with_capacity(DEG + 1);
    let mut sum = 0.0;
    for k in 0..=DEG {
        let xk = (PI * k as f64 / DEG as f64).cos();
        let dx = x - xk;
        if dx == 0.0 {
            return vec![(k, 1.0)];
        }
        let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
        let end = if k == 0 || k == DEG { 0.5 } else { 1.0 };
        let w = sign * end / dx;
        sum += w;
        out.push((k, w));
    }
    for o in &mut out {
        o.1 /= sum;
    }
    out
}

/// The first panels of `[lo, hi_min]`, at most [`FIRST_WIDTH`] wide, in
/// the order a stack pops them (lowest first).
fn first_panels(lo: f64, hi_min: f64) -> Vec<(f64, f64)> {
    let n0 = ((hi_min - lo) / FIRST_WIDTH).ceil().max(1.0) as usize;
    (0..n0)
        .rev()
        .map(|i| {
            let w = (hi_min - lo) / n0 as f64;
            (
                lo + i as f64 * w,
                if i + 1 == n0 {
                    hi_min
                } else {
                    lo + (i + 1) as f64 * w
                },
            )
        })
        .collect()
}

/// The largest error of the panel `[a, b]`'s interpolant (its Lobatto
/// nodes' `tables`) against the direct states of `slice` at the
/// interleaved Chebyshev points, in units of the tolerance `tol (|p| +
/// scale)`, over the gaps `h_min + ts`.
///
/// # Errors
/// `slices`' errors.
fn panel_error(
    a: f64,
    b: f64,
    tables: &[Arc<Table>],
    ts: &[f64],
    tol: f64,
    scale: f64,
    slices: &Slices<'_>,
) -> Result<f64> {
    let tests: Vec<f64> = (0..DEG)
        .map(|k| (PI * (k as f64 + 0.5) / DEG as f64).cos())
        .collect();
    let h_mins: Vec<f64> = tests
        .iter()
        .map(|&x| 0.5 * (a + b) + 0.5 * (b - a) * x)
        .collect();
    let direct = slices(&h_mins, ts)?;
    let mut worst = 0.0f64;
    for (i, &x) in tests.iter().enumerate() {
        let w = barycentric(x);
        for (j, &t) in ts.iter().enumerate() {
            let p = direct[j][i];
            let v: f64 = w.iter().map(|&(k, c)| c * tables[k].eval(t).0).sum();
            worst = worst.max((v - p).abs() / (tol * (p.abs() + scale)));
        }
    }
    Ok(worst)
}

impl RetractTable {
    /// Tabulates on `[lo, hi_min]` in `H_min` and `[0, t_max]` in `t`:
    /// `slices(h_mins, ts)` returns the pressures at gaps `h_min + t` after
    /// each `h_min` (the model's own states), `splits` are the kinks in
    /// `t`, `tol` and `scale` the tolerance `tol (|p| + scale)`. The tables
    /// in `t` of all the nodes missing at a step (first every node of the
    /// first panels, then those of halved panels) are built together, on
    /// the same panels in `t`.
    ///
    /// # Errors
    /// `slices`' errors; [`Error::NoConvergence`] past [`MAX_PANELS`].
    pub fn build(
        lo: f64,
        hi_min: f64,
        t_max: f64,
        splits: &[f64],
        tol: f64,
        scale: f64,
        slices: &Slices<'_>,
    ) -> Result<Self> {
        let build_t = |h_mins: &[f64]| -> Result<Vec<Arc<Table>>> {
            let f = |ts: &[f64]| slices(h_mins, ts);
            Ok(Table::build_many(
                0.0,
                t_max,
                splits,
                T_TABLE_SHARE * tol,
                scale,
                h_mins.len(),
                &f,
            )?
            .into_iter()
            .map(Arc::new)
            .collect())
        };
        let ts: Vec<f64> = (0..T_SAMPLES)
            .map(|k| {
                let s = k as f64 / (T_SAMPLES - 1) as f64;
                t_max * s * s
            })
            .collect();
        // (a, b, the error of the panel it was halved from)
        let mut todo: Vec<(f64, f64, f64)> = first_panels(lo, hi_min)
            .into_iter()
            .map(|(a, b)| (a, b, f64::INFINITY))
            .collect();
        // Tables by `H_min` (panel ends are shared with the neighbours),
        // first those of every first panel, together.
        let mut known: Vec<(f64, Arc<Table>)> = Vec::new();
        {
            let mut first: Vec<f64> = todo.iter().flat_map(|&(a, b, _)| lobatto(a, b)).collect();
            first.sort_by(f64::total_cmp);
            first.dedup();
            let built = build_t(&first)?;
            known.extend(first.into_iter().zip(built));
        }
        let mut done: Vec<(f64, Vec<Arc<Table>>)> = Vec::new();
        let mut error = 0.0f64;
        while let Some((a, b, parent)) = todo.pop() {
            let xs = lobatto(a, b);
            let missing: Vec<f64> = xs
                .iter()
                .copied()
                .filter(|x| !known.iter().any(|(k, _)| k == x))
                .collect();
            if !missing.is_empty() {
                let built = build_t(&missing)?;
                known.extend(missing.into_iter().zip(built));
            }
            let tables: Vec<Arc<Table>> = xs
                .iter()
                .map(|x| {
                    known
                        .iter()
                        .find(|(k, _)| k == x)
                        .map(|(_, t)| t.clone())
                        .expect("built above")
                })
                .collect();
            let worst = panel_error(a, b, &tables, &ts, tol, scale, slices)?;
            let stalled = worst > STALLED * parent && worst <= STALLED_ACCEPTED;
            if worst <= 1.0 || b - a <= MIN_WIDTH || stalled {
                error = error.max(worst * tol);
                done.push((a, tables));
            } else {
                let mid = 0.5 * (a + b);
                todo.push((mid, b, worst));
                todo.push((a, mid, worst));
            }
            if done.len() + todo.len() > MAX_PANELS {
                return Err(Error::NoConvergence {
                    what: "rough-sphere retraction table in the closest gap".into(),
                    iterations: known.len(),
                    residual: worst * tol,
                });
            }
        }
        done.sort_by(|x, y| x.0.total_cmp(&y.0));
        let mut edges: Vec<f64> = done.iter().map(|x| x.0).collect();
        edges.push(hi_min);
        Ok(RetractTable {
            edges,
            nodes: done.into_iter().map(|x| x.1).collect(),
            t_max,
            error,
        })
    }

    /// `[lo, hi]` in `H_min`.
    pub fn range(&self) -> (f64, f64) {
        (self.edges[0], self.edges[self.edges.len() - 1])
    }

    /// Largest relative error measured at the test points (against
    /// `|p| + scale`).
    #[cfg_attr(not(test), allow(dead_code))]
    pub fn error(&self) -> f64 {
        self.error
    }

    /// Tables in `t` built (one per distinct `H_min` node).
    #[cfg(test)]
    pub fn tables(&self) -> usize {
        self.nodes.len() * DEG + 1
    }

    /// The weights of a radius whose closest gap is `h_min` (clamped into
    /// the table's range).
    pub fn weights(&self, h_min: f64) -> Weights {
        let n = self.nodes.len();
        let (lo, hi) = self.range();
        let x = h_min.clamp(lo, hi);
        let i = self.edges.partition_point(|e| *e <= x).clamp(1, n) - 1;
        let (a, b) = (self.edges[i], self.edges[i + 1]);
        let u = ((2.0 * x - a - b) / (b - a)).clamp(-1.0, 1.0);
        let terms: Vec<(f64, Arc<Table>)> = barycentric(u)
            .into_iter()
            .map(|(k, c)| (c, self.nodes[i][k].clone()))
            .collect();
        let combined = if terms.len() > 1 {
            let refs: Vec<(f64, &Table)> = terms.iter().map(|(c, t)| (*c, t.as_ref())).collect();
            Table::combine(&refs)
        } else {
            None
        };
        Weights {
            terms,
            combined,
            h_min,
            t_max: self.t_max,
        }
    }
}

impl Weights {
    /// `(p, dp/dH)` at gap `h >= h_min` (0 beyond the tabulated `t`, where
    /// no summit holds on).
    #[inline]
    pub fn eval(&self, h: f64) -> (f64, f64) {
        let t = (h - self.h_min).max(0.0);
        // (rounding of `h - h_min` at the end kept inside)
        if t > self.t_max * (1.0 + 1e-12) {
            return (0.0, 0.0);
        }
        let t = t.min(self.t_max);
        if let Some(table) = &self.combined {
            return table.eval(t);
        }
        let (mut p, mut dp) = (0.0, 0.0);
        for (c, table) in &self.terms {
            let (v, d) = table.eval(t);
            p += c * v;
            dp += c * d;
        }
        (p, dp)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Values whose error does not shrink with the panels in `H_min` (a
    /// ripple of 1.5 times the tolerance far finer than the narrowest
    /// panel, as the states' own quadrature noise can be): halving stops
    /// once it no longer helps, the table is built with its measured error
    /// kept (it halved down to the narrowest panels, then failed past the
    /// most panels).
    #[test]
    fn an_error_that_halving_does_not_reduce_stops_the_halving() {
        let tol = 1e-9;
        let scale = 1e-4;
        let f = |h_min: f64, t: f64| {
            let g = (-(h_min * h_min) / 2.0).exp();
            let p = g * ((1.0 - t).max(0.0).powf(1.5) - 0.3 * (-t).exp());
            let ripple = (h_min * 2e4).sin().signum();
            p + 1.5 * tol * (p.abs() + scale) * ripple
        };
        let slices = |h_mins: &[f64], ts: &[f64]| {
            Ok(ts
                .iter()
                .map(|&t| h_mins.iter().map(|&h| f(h, t)).collect())
                .collect())
        };
        let t = RetractTable::build(-3.0, 5.0, 6.0, &[1.0], tol, scale, &slices).unwrap();
        assert!(t.error() > tol, "{}", t.error());
        assert!(t.error() <= STALLED_ACCEPTED * tol, "{}", t.error());
        // one halving of each first panel at most, not 8,000 panels of 1e-3
        assert!(t.tables() <= 2 * 8 * DEG + 1, "{}", t.tables());
    }

    /// A smooth two-variable function with a kink at a fixed `t`: the
    /// table reproduces it to its tolerance.
    #[test]
    fn table_reproduces_a_function_of_the_gap_and_closest_gap() {
        let f = |h_min: f64, t: f64| {
            let g = (-(h_min * h_min) / 2.0).exp();
            g * ((1.0 - t).max(0.0).powf(1.5) - 0.3 * (-t).exp())
        };
        let slices = |h_mins: &[f64], ts: &[f64]| {
            Ok(ts
                .iter()
                .map(|&t| h_mins.iter().map(|&h| f(h, t)).collect())
                .collect())
        };
        let tol = 1e-9;
        let t = RetractTable::build(-3.0, 5.0, 6.0, &[1.0], tol, 1e-4, &slices).unwrap();
        assert!(t.error() <= tol, "{}", t.error());
        let mut worst = 0.0f64;
        for i in 0..=97 {
            let h_min = -3.0 + 8.0 * i as f64 / 97.0;
            let w = t.weights(h_min);
            for j in 0..=61 {
                let tt = 6.0 * j as f64 / 61.0;
                let (v, _) = w.eval(h_min + tt);
                let e = (v - f(h_min, tt)).abs() / (f(h_min, tt).abs() + 1e-4);
                worst = worst.max(e);
            }
        }
        // off the test points: within a few times the tolerance
        assert!(worst <= 3.0 * tol, "{worst}");
        // the slope in H at fixed H_min
        let w = t.weights(0.37);
        let (_, d) = w.eval(0.37 + 0.5);
        let fd = (f(0.37, 0.5 + 1e-6) - f(0.37, 0.5 - 1e-6)) / 2e-6;
        assert!((d - fd).abs() < 1e-6, "{d} {fd}");
        assert!(t.tables() < 120, "{}", t.tables());
    }
}
