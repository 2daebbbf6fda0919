//! What a solved state gives, each quantity extrapolated over the mesh
//! levels with its error estimate (Greenwood–Tripp units; `problem.rs`
//! converts to SI).
//!
//! - load `P* = 2 pi int p rho drho` and central deflection
//!   `u(0) = int p drho`, exact for the piecewise-linear pressure;
//! - the pressure at any radius from the gap interpolated between nodes
//!   (`O(h^4)`, below the extrapolation's error);
//! - the radius holding a fraction of the load (first radius where the
//!   cumulative load of the piecewise-linear pressure reaches it);
//! - totals of any [`Observables`] (real area, contacts, spot conductances)
//!   from the local Greenwood–Williamson state of every node, integrated
//!   with the same load weights (`2 pi int x(rho) rho drho`);
//! - the mean inverse distance between spots, weighted by conductance,
//!   `I = int int g(x) g(y)/|x - y| dA dA / G^2`, for Greenwood's
//!   interaction over the bump: by Boussinesq,
//!   `int q(y)/|x - y| dA_y = pi E* w[q](x)`, so `I = pi sum_i W_i g_i (C g)_i / G^2`
//!   with the same compliance `C` (for a uniform disc of radius `a` it is
//!   `16/(3 pi a)`).

use super::solve::{extrapolate, Core, Estimate, Solved};
use crate::error::Result;
use crate::loading::{History, LoadingModel, Observables, SLOTS};
use std::f64::consts::PI;

impl Core {
    /// Extrapolates `g(level)` over the levels of `s`.
    pub(crate) fn over_levels(&self, s: &Solved, g: impl Fn(usize) -> f64) -> Estimate {
        let v: Vec<f64> = (0..s.levels.len()).map(g).collect();
        extrapolate(&v)
    }

    /// `P*`.
    pub(crate) fn load(&self, s: &Solved) -> Estimate {
        self.over_levels(s, |k| {
            let l = &s.levels[k];
            2.0 * PI * l.mesh.moment(&l.sol.p)
        })
    }

    /// `u(0)`.
    pub(crate) fn central_deflection(&self, s: &Solved) -> Estimate {
        self.over_levels(s, |k| {
            let l = &s.levels[k];
            l.mesh.central_deflection(&l.sol.p)
        })
    }

    /// Gap at `rho` on level `k`.
    fn gap_at(&self, s: &Solved, k: usize, rho: f64) -> f64 {
        let l = &s.levels[k];
        l.mesh.gap_at(&l.sol.h, rho, |x| self.shape.gap(x))
    }

    /// The node law of node-or-radius `rho` on level `k` (retraction: the
    /// closest gap interpolated to `rho`).
    fn pressure_on(&self, s: &Solved, k: usize, rho: f64) -> f64 {
        let h = self.gap_at(s, k, rho);
        let approach = self.law.approach();
        match &s.retraction {
            None => approach.eval(approach, h).0,
            Some(r) => {
                let l = &s.levels[k];
                let h_min = l.mesh.gap_at(&r.h_min[k], rho, |x| self.shape.gap(x));
                // the node law at the nearest node holds the history; off
                // nodes it is rebuilt only for tabulated laws' nearest node
                let i = l
                    .mesh
                    .rho
                    .partition_point(|x| *x < rho)
                    .min(l.mesh.len() - 1);
                let j = if i > 0 && (rho - l.mesh.rho[i - 1]) < (l.mesh.rho[i] - rho) {
                    i - 1
                } else {
                    i
                };
                if (r.h_min[k][j] - h_min).abs() <= 1e-12 * (1.0 + h_min.abs()) {
                    r.laws[k][j].eval(approach, h).0
                } else {
                    match self.law.after(h_min) {
                        Ok(law) => law.eval(approach, h).0,
                        Err(_) => f64::NAN,
                    }
                }
            }
        }
    }

    /// The pressure at radius `rho`.
    pub(crate) fn pressure_at(&self, s: &Solved, rho: f64) -> Estimate {
        self.over_levels(s, |k| self.pressure_on(s, k, rho))
    }

    /// The smallest radius within which the load reaches `fraction` of the
    /// total; `None` when the total is not compressive.
    pub(crate) fn load_radius(&self, s: &Solved, fraction: f64) -> Option<Estimate> {
        let mut v = Vec::with_capacity(s.levels.len());
        for l in &s.levels {
            let (r, p) = (&l.mesh.rho, &l.sol.p);
            let total = l.mesh.moment(p);
            if !(total > 0.0) {
                return None;
            }
            let target = fraction * total;
            // int over [a, x] of the linear p times rho
            let part = |a: f64, b: f64, pa: f64, pb: f64, x: f64| {
                let k = (pb - pa) / (b - a);
                let c = pa - k * a;
                c * (x * x - a * a) / 2.0 + k * (x * x * x - a * a * a) / 3.0
            };
            let mut cum = 0.0;
            let mut found = None;
            for i in 0..r.len() - 1 {
                let seg = part(r[i], r[i + 1], p[i], p[i + 1], r[i + 1]);
                if cum + seg >= target {
                    let (mut lo, mut hi) = (r[i], r[i + 1]);
                    for _ in 0..100 {
                        let mid = 0.5 * (lo + hi);
                        if cum + part(r[i], r[i + 1], p[i], p[i + 1], mid) >= target {
                            hi = mid;
                        } else {
                            lo = mid;
                        }
                    }
                    found = Some(0.5 * (lo + hi));
                    break;
                }
                cum += seg;
            }
            v.push(found?);
        }
        Some(extrapolate(&v))
    }

    /// Per-node totals of `obs` per unit nominal area on level `k` (SI
    /// densities of the model), zero where the gap exceeds the law's top.
    fn node_densities(&self, s: &Solved, k: usize, obs: &Observables) -> Result<Vec<[f64; SLOTS]>> {
        use rayon::prelude::*;
        let l = &s.levels[k];
        let model = self.law.model();
        let sigma = model.surface().sigma;
        let per_area = 1.0 / model.surface().nominal_area;
        let top = self.law.top();
        l.sol
            .h
            .par_iter()
            .enumerate()
            .map(|(i, &h)| {
                if h >= top {
                    return Ok([0.0; SLOTS]);
                }
                let history = match &s.retraction {
                    Some(r) if h >= r.h_min[k][i] => History::Retract {
                        closest: sigma * r.h_min[k][i],
                    },
                    _ => History::Approach,
                };
                let st = model.state(sigma * h, history, obs)?;
                let mut out = [0.0; SLOTS];
                for (slot, o) in out.iter_mut().enumerate() {
                    *o = st.totals.get(slot).unwrap_or(0.0) * per_area;
                }
                Ok(out)
            })
            .collect()
    }

    /// Totals of `obs` over the bump, `2 pi int x rho drho` per slot (SI
    /// density times the Greenwood–Tripp area unit: multiply by `2 R sigma`
    /// for SI totals), and the conductance-weighted mean inverse distance
    /// `I` (in `1/rho` units) for the slot `conductance` when given.
    pub(crate) fn totals(
        &self,
        s: &Solved,
        obs: &Observables,
        conductance: Option<usize>,
    ) -> Result<([Option<Estimate>; SLOTS], Option<Estimate>)> {
        let mask = obs.mask();
        let mut per_slot: Vec<[f64; SLOTS]> = Vec::new();
        let mut inverse: Vec<f64> = Vec::new();
        for k in 0..s.levels.len() {
            let l = &s.levels[k];
            let x = self.node_densities(s, k, obs)?;
            let mut t = [0.0; SLOTS];
            for (slot, ts) in t.iter_mut().enumerate() {
                let col: Vec<f64> = x.iter().map(|v| v[slot]).collect();
                *ts = 2.0 * PI * l.mesh.moment(&col);
            }
            per_slot.push(t);
            if let Some(c) = conductance {
                let g: Vec<f64> = x.iter().map(|v| v[c]).collect();
                let total = 2.0 * PI * l.mesh.moment(&g);
                let cg = l.mesh.apply(&g);
                let gcg: Vec<f64> = g.iter().zip(&cg).map(|(a, b)| a * b).collect();
                let i = if total > 0.0 {
                    PI * 2.0 * PI * l.mesh.moment(&gcg) / (total * total)
                } else {
                    0.0
                };
                inverse.push(i);
            }
        }
        let out = std::array::from_fn(|slot| {
            mask[slot].then(|| {
                let v: Vec<f64> = per_slot.iter().map(|t| t[slot]).collect();
                extrapolate(&v)
            })
        });
        let inv = conductance.map(|_| extrapolate(&inverse));
        Ok((out, inv))
    }

    /// `(rho, p)` at the finest level's nodes.
    pub(crate) fn profile(&self, s: &Solved) -> (Vec<f64>, Vec<f64>) {
        let l = s.levels.last().expect("levels");
        (l.mesh.rho.clone(), l.sol.p.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::super::mesh::{Grading, Mesh};
    use std::f64::consts::PI;

    /// The conductance-weighted mean inverse distance of a uniform disc of
    /// radius `a` is `16/(3 pi a)` (mean of `1/|X - Y|` over a disc).
    #[test]
    fn mean_inverse_distance_of_a_disc() {
        let a = 1.3;
        let mut prev = None;
        for n in [257usize, 513, 1025] {
            let m = Mesh::new(n, 2.0 * a, Grading::Uniform);
            // a smoothed step would converge faster; the plain step still
            // converges (first order at the jump)
            let g: Vec<f64> = m
                .rho
                .iter()
                .map(|&r| if r <= a { 1.0 } else { 0.0 })
                .collect();
            let total = 2.0 * PI * m.moment(&g);
            let cg = m.apply(&g);
            let gcg: Vec<f64> = g.iter().zip(&cg).map(|(x, y)| x * y).collect();
            let i = PI * 2.0 * PI * m.moment(&gcg) / (total * total);
            prev = Some(i);
        }
        let exact = 16.0 / (3.0 * PI * a);
        let i = prev.unwrap();
        assert!((i - exact).abs() < 5e-3 * exact, "{i} {exact}");
    }
}
