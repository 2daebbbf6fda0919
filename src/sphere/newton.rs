//! Newton–Raphson on the gaps with one scalar constraint (Feng 2000;
//! Greenwood 2009 appendix 1).
//!
//! Scaled variables (physics.md): radius `r = r_phys / (R^2 w/E*)^(1/3)`,
//! gap `H = h/z0`, traction `sigma_hat` in `w/z0`. The gap at node `i` is
//! `H_i = 1 - alpha + f_i + mu^2 sum_j C_ij sigma_hat(H_j)` with `f` the
//! undeformed shape (`mu r^2/2` for the paraboloid) and `alpha` the approach
//! in units of `z0`. Eliminating `alpha` with the centre (`f_0 = 0`):
//!
//! ```text
//! R_i = H_i - H_0 - f_i - mu^2 sum_j (C_ij - C_0j) sigma_hat(H_j) = 0,  i >= 1
//! ```
//!
//! `n - 1` equations in the `n` gaps `x = (H_0, ..., H_{n-1})`: a curve. One
//! more equation picks a point on it ([`Constraint`]): the central gap
//! (`H_0` prescribed, as Greenwood 2009), or Keller's pseudo-arclength
//! condition `tau . (y(x) - y_prev) = s` on the mesh-independent observables
//! `y = (c_H H_0, c_a alpha, P/(pi w R))` (Feng 2000 continues in arc length
//! too), which passes the folds of `alpha` (jumps), of `P` (pull-off) and of
//! `H_0` (mu > ~15) alike. Afterwards
//! `alpha = 1 - H_0 + mu^2 sum_j C_0j sigma_hat_j` (+ far field) and
//! `P/(pi w R) = 2 mu sum_j W_j sigma_hat_j` (+ far field).
//!
//! The bordered Jacobian `[grad g; dR/dx]` is factorised once per point; the
//! corrector runs chord iterations on the factorisation of the previous
//! point (refactorising only when the contraction is poor), and the
//! factorisation at the converged point gives the tangent `dx/ds` exactly.

use super::disc::Discretisation;
use super::force_law::{traction, traction_slope};
use crate::error::{Error, Result};
use nalgebra::{DMatrix, DVector};

/// A factorised bordered Jacobian.
pub(crate) type Lu = nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>;

/// Weights of the observables in the arc-length metric: `c_H` on `H_0` and
/// `c_a` on `alpha` (both `z0` to Maugis interference units when `mu` is
/// large, 1 otherwise), 1 on the load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Metric {
    pub gap: f64,
    pub approach: f64,
}

/// The extra equation that selects one point of the solution curve.
///
/// The tracer continues in `H_0` (`Gap`); the pseudo-arclength `Arc` form is
/// implemented and its Jacobian tested, but not yet used by the tracer (its
/// corrector still fails too often on the mu >= 5 S-curve; see
/// docs/performance.md).
#[cfg_attr(not(test), allow(dead_code))]
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Constraint {
    /// `H_0 = value`.
    Gap(f64),
    /// `tau . (y(x) - y0) = s` with `y = metric-weighted (H_0, alpha, P)`.
    Arc { tau: [f64; 3], y0: [f64; 3], s: f64 },
}

/// A converged state on one mesh.
#[derive(Debug, Clone)]
#[allow(dead_code)] // `y`, `dy`: the arc-length observables (see `Constraint`)
pub(crate) struct Solution {
    /// Gaps at the nodes (units `z0`), `h[0]` the central gap.
    pub h: Vec<f64>,
    /// `dx/ds`, unit speed in the observables metric.
    pub tangent: Vec<f64>,
    /// Observables `y` (metric-weighted `H_0`, `alpha`, `P`).
    pub y: [f64; 3],
    /// `dy/ds` (unit vector).
    pub dy: [f64; 3],
    /// Approach `alpha/z0`.
    pub approach: f64,
    /// `P/(pi w R)`.
    pub load: f64,
    /// `d alpha/dH_0` (infinite at a fold of `H_0`).
    pub d_approach: f64,
    /// `d load/dH_0`.
    pub d_load: f64,
    /// Contact radius (radius of maximum tension) in solver units.
    pub radius: f64,
    /// Newton iterations spent.
    pub iterations: usize,
}

#[allow(dead_code)] // arc-length derivatives (see `Constraint`)
impl Solution {
    /// `d alpha/ds` along the traced direction.
    pub fn ds_approach(&self) -> f64 {
        self.dy[1]
    }
    /// `dP/ds` along the traced direction.
    pub fn ds_load(&self) -> f64 {
        self.dy[2]
    }
}

/// Per-iterate quantities.
struct Eval {
    dsig: Vec<f64>,
    /// residual: `g[0]` the constraint, `g[i] = R_i`
    g: DVector<f64>,
    y: [f64; 3],
    approach: f64,
    load: f64,
    /// rounding floor of the residual sums
    magnitude: f64,
}

impl Discretisation {
    fn eval(&self, h: &[f64], con: &Constraint, metric: Metric) -> Eval {
        let n = self.len();
        let mu2c = self.mu * self.mu * self.scale;
        let sig: Vec<f64> = h.iter().map(|&x| traction(x)).collect();
        let dsig: Vec<f64> = h.iter().map(|&x| traction_slope(x)).collect();
        let c0 = self.c_row(0);
        let mut g = DVector::<f64>::zeros(n);
        let mut magnitude = 0.0f64;
        for i in 1..n {
            let ci = self.c_row(i);
            let (mut u, mut u_abs) = (0.0, 0.0);
            for j in 0..n {
                let cj = ci[j] - c0[j];
                u += cj * sig[j];
                // size of the two cancelling terms of sigma_hat
                u_abs += cj.abs() * (8.0 / 3.0) * (h[j].powi(-9) + h[j].powi(-3));
            }
            magnitude = magnitude.max(h[i].abs() + h[0] + self.f[i] + mu2c * u_abs);
            g[i] = h[i] - h[0] - self.f[i] - mu2c * u;
        }
        let (approach, load) = self.observables(h, &sig);
        let y = [metric.gap * h[0], metric.approach * approach, load];
        g[0] = match con {
            Constraint::Gap(v) => h[0] - v,
            Constraint::Arc { tau, y0, s } => {
                (0..3).map(|k| tau[k] * (y[k] - y0[k])).sum::<f64>() - s
            }
        };
        Eval {
            dsig,
            g,
            y,
            approach,
            load,
            magnitude,
        }
    }

    /// `(alpha/z0, P/(pi w R))` from the gaps and tractions.
    fn observables(&self, h: &[f64], sig: &[f64]) -> (f64, f64) {
        let n = self.len();
        let mu2c = self.mu * self.mu * self.scale;
        let c0 = self.c_row(0);
        let (mut u0, mut load) = (0.0, 0.0);
        for j in 0..n {
            u0 += c0[j] * sig[j];
            load += self.w[j] * sig[j];
        }
        let hm = h[n - 1];
        let approach = 1.0 - h[0] + mu2c * u0 + self.tail_centre_displacement(hm);
        (approach, 2.0 * self.mu * load + self.tail_load(hm))
    }

    /// Gradients of `(alpha, P)` with respect to the gaps.
    fn observable_gradients(&self, h: &[f64], dsig: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let n = self.len();
        let mu2c = self.mu * self.mu * self.scale;
        let c0 = self.c_row(0);
        let mut ga: Vec<f64> = (0..n).map(|j| mu2c * c0[j] * dsig[j]).collect();
        let mut gp: Vec<f64> = (0..n)
            .map(|j| 2.0 * self.mu * self.w[j] * dsig[j])
            .collect();
        ga[0] -= 1.0;
        let hm = h[n - 1];
        let e = 1e-6 * hm;
        ga[n - 1] += (self.tail_centre_displacement(hm + e)
            - self.tail_centre_displacement(hm - e))
            / (2.0 * e);
        gp[n - 1] += (self.tail_load(hm + e) - self.tail_load(hm - e)) / (2.0 * e);
        (ga, gp)
    }

    /// The bordered Jacobian at `h` with constraint row `row0`.
    fn jacobian(&self, dsig: &[f64], row0: &[f64]) -> DMatrix<f64> {
        let n = self.len();
        let mu2c = self.mu * self.mu * self.scale;
        let c0 = self.c_row(0);
        let mut jac = DMatrix::<f64>::zeros(n, n);
        for k in 0..n {
            jac[(0, k)] = row0[k];
        }
        for i in 1..n {
            let ci = self.c_row(i);
            for k in 0..n {
                jac[(i, k)] = -mu2c * (ci[k] - c0[k]) * dsig[k];
            }
            jac[(i, i)] += 1.0;
            jac[(i, 0)] -= 1.0;
        }
        jac
    }

    /// Gradient of the constraint.
    fn constraint_row(&self, h: &[f64], dsig: &[f64], con: &Constraint, m: Metric) -> Vec<f64> {
        let n = self.len();
        match con {
            Constraint::Gap(_) => {
                let mut row = vec![0.0; n];
                row[0] = 1.0;
                row
            }
            Constraint::Arc { tau, .. } => {
                let (ga, gp) = self.observable_gradients(h, dsig);
                let mut row: Vec<f64> = (0..n)
                    .map(|j| tau[1] * m.approach * ga[j] + tau[2] * gp[j])
                    .collect();
                row[0] += tau[0] * m.gap;
                row
            }
        }
    }

    /// Solves `R(x) = 0` with the constraint `con` from `guess`: chord
    /// iterations on `chord` (a factorisation of a nearby point's bordered
    /// Jacobian on a mesh of the same size) when given, refactorising when
    /// the residual falls by less than 4x. Converged when the largest
    /// residual is below `tol` or below the rounding floor
    /// `64 eps max_i(|H_i| + H_0 + f_i + mu^2 sum_j |C_ij - C_0j| (8/3)(H_j^-9 + H_j^-3))`.
    /// Returns the solution and the factorisation at it.
    pub fn solve(
        &self,
        guess: &[f64],
        con: &Constraint,
        metric: Metric,
        chord: Option<&Lu>,
        tol: f64,
        max_iter: usize,
    ) -> Result<(Solution, Lu)> {
        let n = self.len();
        let mut h = guess.to_vec();
        if let Constraint::Gap(v) = con {
            h[0] = *v;
        }
        let mut own: Option<Lu> = None;
        let mut use_chord = chord.filter(|l| l.l().nrows() == n).is_some();
        let mut last = f64::INFINITY;
        let mut iterations = 0;
        while iterations <= max_iter {
            if h.iter().any(|x| !(*x > 0.0)) {
                break;
            }
            let ev = self.eval(&h, con, metric);
            let norm = ev.g.amax();
            if norm <= tol.max(64.0 * f64::EPSILON * ev.magnitude) {
                return self.finish(h, ev, con, metric, iterations);
            }
            if iterations == max_iter || !norm.is_finite() {
                last = norm;
                break;
            }
            // chord while it contracts well; otherwise a fresh Jacobian
            // full Newton unless a chord matrix was given
            if chord.is_none() || norm > 0.1 * last || (own.is_none() && !use_chord) {
                let row0 = self.constraint_row(&h, &ev.dsig, con, metric);
                own = Some(self.jacobian(&ev.dsig, &row0).lu());
                use_chord = false;
            }
            last = norm;
            let lu = if use_chord {
                chord.unwrap()
            } else {
                own.as_ref().unwrap()
            };
            let Some(step) = lu.solve(&ev.g) else {
                break;
            };
            // never let a gap shrink by more than half
            let mut lambda = 1.0f64;
            for i in 0..n {
                if step[i] > 0.0 {
                    lambda = lambda.min(0.5 * h[i] / step[i]);
                }
            }
            for i in 0..n {
                h[i] -= lambda * step[i];
            }
            iterations += 1;
        }
        Err(Error::NoConvergence {
            what: "sphere Newton".into(),
            iterations,
            residual: last,
        })
    }

    /// Tangent and outputs at a converged point.
    fn finish(
        &self,
        h: Vec<f64>,
        ev: Eval,
        con: &Constraint,
        m: Metric,
        iterations: usize,
    ) -> Result<(Solution, Lu)> {
        let n = self.len();
        let row0 = self.constraint_row(&h, &ev.dsig, con, m);
        let lu = self.jacobian(&ev.dsig, &row0).lu();
        let mut rhs = DVector::<f64>::zeros(n);
        rhs[0] = 1.0;
        let singular = || Error::NoConvergence {
            what: "sphere tangent: singular Jacobian".into(),
            iterations,
            residual: f64::NAN,
        };
        let t = lu.solve(&rhs).ok_or_else(singular)?;
        let (ga, gp) = self.observable_gradients(&h, &ev.dsig);
        let da: f64 = (0..n).map(|j| ga[j] * t[j]).sum();
        let dp: f64 = (0..n).map(|j| gp[j] * t[j]).sum();
        let mut dy = [m.gap * t[0], m.approach * da, dp];
        let norm = dy.iter().map(|x| x * x).sum::<f64>().sqrt();
        if !(norm > 0.0 && norm.is_finite()) {
            return Err(singular());
        }
        // unit speed; a prescribed H_0 is traced towards smaller gaps
        let sign = if matches!(con, Constraint::Gap(_)) {
            -1.0
        } else {
            1.0
        };
        let k = sign / norm;
        dy.iter_mut().for_each(|x| *x *= k);
        let tangent: Vec<f64> = t.iter().map(|x| x * k).collect();
        let radius = self.contact_radius(&h);
        let sol = Solution {
            tangent,
            y: ev.y,
            dy,
            approach: ev.approach,
            load: ev.load,
            d_approach: da / t[0],
            d_load: dp / t[0],
            radius,
            iterations,
            h,
        };
        Ok((sol, lu))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sphere::{Shape, SolverOptions, SphereProblem};
    use std::sync::Arc;

    /// The bordered Jacobian (residuals and the arc-length constraint)
    /// matches central differences of the residual.
    #[test]
    fn jacobian_matches_finite_differences() {
        let p = SphereProblem::new(2.0, Shape::Paraboloid, SolverOptions::coarse()).unwrap();
        let spec = p.mesh_spec(1.0);
        let disc = Discretisation::view(
            Arc::new(super::super::disc::BaseMesh::new(spec)),
            1.1,
            2.0,
            Shape::Paraboloid,
        );
        let n = disc.len();
        let h: Vec<f64> = disc
            .r
            .iter()
            .map(|r| 0.95 + 0.3 * r * r + 0.02 * (3.0 * r).sin())
            .collect();
        let m = Metric {
            gap: 0.1,
            approach: 0.3,
        };
        let con = Constraint::Arc {
            tau: [0.2, 0.6, 0.7746],
            y0: [0.0, 0.0, 0.0],
            s: 0.1,
        };
        let ev = disc.eval(&h, &con, m);
        let row0 = disc.constraint_row(&h, &ev.dsig, &con, m);
        let jac = disc.jacobian(&ev.dsig, &row0);
        for k in [0, 1, n / 2, n - 1] {
            let e = 1e-6 * h[k];
            let mut hp = h.clone();
            hp[k] += e;
            let mut hm = h.clone();
            hm[k] -= e;
            let gp = disc.eval(&hp, &con, m).g;
            let gm = disc.eval(&hm, &con, m).g;
            for i in 0..n {
                let fd = (gp[i] - gm[i]) / (2.0 * e);
                assert!(
                    (fd - jac[(i, k)]).abs() < 1e-5 * (1.0 + fd.abs()),
                    "({i}, {k}): fd {fd} vs {}",
                    jac[(i, k)]
                );
            }
        }
    }
}
