//! The retraction pressures of many closest gaps at one gap above them,
//! from one set of law evaluations.
//!
//! With `t = H - H_min >= 0` and the summit height `z' = z - H_min`
//! above the closest gap (units of `sigma`), the local retraction pressure
//! is (Greenwood & Williamson 1966 on a retraction, `local.rs`)
//!
//! ```text
//! p(H_min + t, H_min) = eta/unit int F(sigma (z' - t), sigma z') phi(z' + H_min) dz'
//! ```
//!
//! The law's factor `F(z' - t, z')` (force after the maximum `z'`) does not
//! depend on `H_min`, nor do its kinks in `z'` (branch breakpoints `t +
//! b/sigma`, history thresholds `c/sigma`, contact-loss peaks): only the
//! shifted density does. So one adaptive Gauss–Kronrod integration in
//! `z'`, with the integrand a vector over the closest gaps `H_min,k`,
//! evaluates the law once per node for every `k` (the retraction table's
//! nodes in `H_min`: about 100 closest gaps, each of which cost its own
//! quadrature before). Each component meets its own tolerance, `rtol int
//! |f_k|` or an absolute floor, as [`GwModel`]'s quadrature does for one
//! state; the panel with the worst component is bisected first.

use super::shifted_density::Shifts;
use crate::error::{Error, Result};
use crate::gw::GwModel;
use crate::law::{Branch, LawCursor};
use crate::numeric::quadrature::{kronrod21_nodes, kronrod21_sums_columns};

/// Density at a support edge below which the edge is no breakpoint (the
/// jump there is below any double the integral keeps).
const EDGE_PDF: f64 = 1e-250;
/// Tail probability beyond which heights are left out of the integrals:
/// the density there is below `1e-28` of its peak, and the force of a
/// summit grows at most like a power of its interference, so what is left
/// out is far below any tolerance (`1e-13` at the tightest).
const TAIL: f64 = 1e-30;
/// Steps of the ladder of breakpoints from the lower end (`sigma`): the
/// first panels resolve the bulk of every shifted density.
const LADDER: [f64; 8] = [0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0];

/// The retraction pressure of one model at many closest gaps.
pub(crate) struct SharedHeights<'a> {
    model: &'a GwModel,
    /// Pressure per unit of the integral (`eta A_n per_area`).
    factor: f64,
    /// Relative tolerance against `int |f_k|`.
    rtol: f64,
    /// Absolute tolerance of each pressure (pressure units).
    floor: f64,
    /// Most panels per integration.
    max_intervals: usize,
}

/// One K21 panel of the vector integrand.
struct Panel {
    a: f64,
    b: f64,
    value: Vec<f64>,
    error: Vec<f64>,
    magnitude: Vec<f64>,
    /// Worst component's error over its target when pushed.
    key: f64,
}

impl<'a> SharedHeights<'a> {
    /// Pressures of `model` times `factor` (`eta A_n` over the nominal
    /// area and the pressure unit), each to `rtol int |f|` or `floor`
    /// (pressure units), whichever is larger.
    pub fn new(model: &'a GwModel, factor: f64, rtol: f64, floor: f64) -> Self {
        SharedHeights {
            model,
            factor,
            rtol,
            floor,
            max_intervals: model.accuracy().max_intervals,
        }
    }

    /// `p(H_min,k + t, H_min,k)` for every `H_min,k` of `h_mins` (units of
    /// `sigma`; `t >= 0`).
    ///
    /// # Errors
    /// [`Error::NoConvergence`] when a component misses its tolerance
    /// within the model's most intervals.
    pub fn pressures(&self, t: f64, h_mins: &[f64]) -> Result<Vec<f64>> {
        let n = h_mins.len();
        let model = self.model;
        let sigma = model.surface().sigma;
        let law = model.law();
        let dist = model.distribution();
        let (sup_lo, sup_hi) = dist.numerical_support(TAIL);
        let (h_lo, h_hi) = h_mins
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &h| {
                (a.min(h), b.max(h))
            });
        // Below the cutoff every branch is exactly zero; beyond every
        // component's support, or the law's divergence, nothing is summed.
        let z_lo = (t + law.cutoff_interference() / sigma).max(sup_lo - h_hi);
        let z_hi = (sup_hi - h_lo).min(t + law.max_interference() / sigma);
        if n == 0 || !(z_hi > z_lo) {
            return Ok(vec![0.0; n]);
        }
        let points = self.pieces(t, h_mins, (z_lo, z_hi), (sup_lo, sup_hi));
        let shifts = Shifts::new(dist, h_mins);
        let mut cursor = LawCursor::default();
        let (mut heights, mut density) = (vec![0.0; 21 * n], vec![0.0; 21 * n]);
        let mut integrand = vec![0.0; 21 * n];
        let rule = |a: f64, b: f64| -> Panel {
            let z = kronrod21_nodes(a, b);
            let delta = z.map(|z| sigma * (z - t));
            let dm = z.map(|z| sigma * z);
            let mut load = [0.0; 21];
            law.load_near_batch(&delta, Some(&dm), &mut load, &mut cursor);
            let mut p = Panel {
                a,
                b,
                value: vec![0.0; n],
                error: vec![0.0; n],
                magnitude: vec![0.0; n],
                key: 0.0,
            };
            if load.iter().all(|&l| l == 0.0) {
                return p;
            }
            // Every component's density at the 21 nodes (one long vector
            // loop, or for Gaussian heights the product form's steps).
            shifts.fill(&z, &mut heights, &mut density);
            // The integrand by node, the components in a row (zero outside
            // the density's support: a component's heights ascend with the
            // nodes, so its ends tell whether any is outside), and the K21
            // sums of all components in loops over them.
            for (j, row) in integrand.chunks_exact_mut(n).enumerate() {
                let l = load[j];
                for (out, d) in row.iter_mut().zip(density[j..].iter().step_by(21)) {
                    *out = l * d;
                }
            }
            let inside = |s: f64| s >= sup_lo && s <= sup_hi;
            for (k, hs) in heights.chunks_exact(21).enumerate() {
                if !(inside(hs[0]) && inside(hs[20])) {
                    for (j, &s) in hs.iter().enumerate() {
                        if !inside(s) {
                            integrand[n * j + k] = 0.0;
                        }
                    }
                }
            }
            kronrod21_sums_columns(
                &integrand,
                0.5 * (b - a),
                &mut p.value,
                &mut p.error,
                &mut p.magnitude,
            );
            p
        };
        self.adapt(rule, &points, n, t)
    }

    /// Panel ends in `z'` on `[z_lo, z_hi]` at gap `t`: the law's kinks
    /// there (none depends on the closest gap), a ladder from the lower
    /// end, and each component's edge of a support `(sup_lo, sup_hi)`
    /// where the density jumps.
    fn pieces(&self, t: f64, h_mins: &[f64], z: (f64, f64), sup: (f64, f64)) -> Vec<f64> {
        let ((z_lo, z_hi), (sup_lo, sup_hi)) = (z, sup);
        let sigma = self.model.surface().sigma;
        let law = self.model.law();
        let dist = self.model.distribution();
        let mut points = vec![z_lo, z_hi];
        let mut add = |z: f64| {
            if z > z_lo && z < z_hi {
                points.push(z);
            }
        };
        for br in [Branch::Approach, Branch::Retract] {
            for b in law.breakpoints(br) {
                add(t + b / sigma);
            }
        }
        for c in law.history_breakpoints() {
            add(c / sigma);
        }
        for m in law.contact_loss_peaks(sigma * t) {
            add(m / sigma);
        }
        for step in LADDER {
            add(z_lo + step);
        }
        // A density that jumps at its support's own edge (not where its
        // tail is cut): each component's edge is a breakpoint.
        let (edge_lo, edge_hi) = dist.support();
        for edge in [sup_lo, sup_hi] {
            if (edge == edge_lo || edge == edge_hi) && dist.pdf(edge) > EDGE_PDF {
                for &h in h_mins {
                    add(edge - h);
                }
            }
        }
        points.sort_by(f64::total_cmp);
        points.dedup();
        points
    }

    /// Adaptive bisection of the pieces `points` with `rule(a, b)` one K21
    /// panel of the `n` components, until each meets `rtol int |f_k|` or
    /// the floor: the integrals times `factor`.
    ///
    /// # Errors
    /// [`Error::NoConvergence`] past the model's most intervals.
    fn adapt(
        &self,
        mut rule: impl FnMut(f64, f64) -> Panel,
        points: &[f64],
        n: usize,
        t: f64,
    ) -> Result<Vec<f64>> {
        let law = self.model.law();
        let floor = self.floor / self.factor;
        let target = |mag: f64| (self.rtol * mag.abs()).max(floor);
        let mut panels: Vec<Panel> = points
            .windows(2)
            .filter(|w| w[1] > w[0])
            .map(|w| rule(w[0], w[1]))
            .collect();
        let sums = |panels: &[Panel]| {
            let (mut v, mut e, mut m) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
            for p in panels {
                for k in 0..n {
                    v[k] += p.value[k];
                    e[k] += p.error[k];
                    m[k] += p.magnitude[k];
                }
            }
            (v, e, m)
        };
        let key = |p: &Panel, m: &[f64]| {
            (0..n)
                .map(|k| p.error[k] / target(m[k]).max(f64::MIN_POSITIVE))
                .fold(0.0, f64::max)
        };
        let (_, mut err, mut mag) = sums(&panels);
        for p in &mut panels {
            p.key = key(p, &mag);
        }
        let done = |e: &[f64], m: &[f64]| (0..n).all(|k| e[k] <= target(m[k]));
        while !done(&err, &mag) {
            if panels.len() >= self.max_intervals {
                let worst = (0..n)
                    .map(|k| err[k] / target(mag[k]).max(f64::MIN_POSITIVE))
                    .fold(0.0, f64::max);
                return Err(Error::NoConvergence {
                    what: format!(
                        "GW quadrature of {} on retraction at t = {t} sigma",
                        law.name()
                    ),
                    iterations: 21 * panels.len(),
                    residual: worst,
                });
            }
            let i = (0..panels.len())
                .max_by(|&x, &y| panels[x].key.total_cmp(&panels[y].key))
                .expect("at least one panel");
            let (a, b) = (panels[i].a, panels[i].b);
            let mid = 0.5 * (a + b);
            if !(mid > a && mid < b) {
                break;
            }
            let worst = panels.swap_remove(i);
            let halves = [rule(a, mid), rule(mid, b)];
            for k in 0..n {
                err[k] += halves[0].error[k] + halves[1].error[k] - worst.error[k];
                mag[k] += halves[0].magnitude[k] + halves[1].magnitude[k] - worst.magnitude[k];
            }
            for mut h in halves {
                h.key = key(&h, &mag);
                panels.push(h);
            }
        }
        // Summed in the order of the panels along `z'` (independent of the
        // order of refinement).
        panels.sort_by(|x, y| x.a.total_cmp(&y.a));
        let (value, _, _) = sums(&panels);
        Ok(value.into_iter().map(|v| v * self.factor).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gw::{Accuracy, RoughSurface};
    use crate::heights::Gaussian;
    use crate::law::plastic::{build, AdhesivePlastic, PlasticLoading};
    use crate::loading::{History, LoadingModel, Observables};
    use crate::material::plastic::{Plasticity, Variant};
    use std::sync::Arc;

    /// Kogut–Etsion summits with JKR adhesion (the plastic bump's law):
    /// the shared integral gives every closest gap's retraction load as
    /// the model's own state does, to the tolerance both are asked.
    #[test]
    fn shared_integral_matches_the_models_own_states() {
        let (r, e) = (50e-9, 47.96e9);
        let plastic = build(Variant::KogutEtsion, r, e, Plasticity::gold()).unwrap();
        let loading: Arc<dyn PlasticLoading> = plastic.as_loading();
        let law = Arc::new(AdhesivePlastic::new(loading, 0.5).unwrap());
        let sigma = 2e-9;
        let surface = RoughSurface::new(5e14, r, sigma, 1e-12).unwrap();
        let rtol = 1e-10;
        let model = GwModel::new(surface, Arc::new(Gaussian::new()), law)
            .unwrap()
            .with_accuracy(Accuracy::new(rtol).unwrap());
        let factor = 1.0 / surface.nominal_area;
        let shared = SharedHeights::new(&model, surface.summits() * factor, rtol, 0.0);
        let h_mins = [-2.0, -1.3, -0.4, 0.0, 0.7, 1.9, 3.0];
        let mut compared = 0;
        for t in [0.0, 0.05, 0.2, 0.6, 1.5] {
            let got = shared.pressures(t, &h_mins).unwrap();
            for (&h, &p) in h_mins.iter().zip(&got) {
                let back = History::Retract { closest: sigma * h };
                let s = model
                    .state(sigma * (h + t), back, &Observables::LOAD)
                    .unwrap();
                let want = s.load().unwrap() * factor;
                // each within rtol of int |f| (about |p| here, and at
                // least the summits' compressive part): 10 rtol
                // covers both estimates and the pressure's cancellation
                let scale = want.abs().max(1e-3 * got[0].abs());
                assert!(
                    (p - want).abs() <= 10.0 * rtol * scale,
                    "t {t} h_min {h}: {p} vs {want}"
                );
                compared += 1;
            }
        }
        assert_eq!(compared, 35);
        // no closest gap: no work
        assert!(shared.pressures(0.3, &[]).unwrap().is_empty());
    }
}
