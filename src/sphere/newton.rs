//! Newton–Raphson on the gaps at a prescribed central gap (Feng 2000;
//! Greenwood 2009 appendix 1).
//!
//! Scaled variables (physics.md): radius `r = r_phys / (R^2 w/E*)^(1/3)`,
//! gap `H = h/z0`, traction `sigma_hat` in `w/z0`. The gap at node `i` is
//! `H_i = 1 - alpha + f_i + mu^2 sum_j C_ij sigma_hat(H_j)` with `f` the
//! undeformed shape (`mu r^2/2` for the paraboloid) and `alpha` the approach
//! in units of `z0`. Eliminating `alpha` with the centre (`f_0 = 0`) at a
//! prescribed `H_0`:
//!
//! ```text
//! R_i = H_i - H_0 - f_i - mu^2 sum_j (C_ij - C_0j) sigma_hat(H_j) = 0,  i >= 1
//! J_ik = delta_ik - mu^2 (C_ik - C_0k) sigma_hat'(H_k)
//! ```
//!
//! and afterwards `alpha = 1 - H_0 + mu^2 sum_j C_0j sigma_hat_j` (+ far field),
//! load `P/(pi w R) = 2 mu sum_j W_j sigma_hat_j` (+ far field). The tangent
//! `t = dH/dH_0` solves `J t = 1 + mu^2 (C_i0 - C_00) sigma_hat'(H_0)` with the
//! factorised `J`, giving `d alpha/dH_0` and `dP/dH_0` exactly.
//!
//! Far field beyond the last node `r_m` (the sphere then continues rigidly:
//! `H = H_m + f(r) - f(r_m)`): load `2 int sigma_hat r dr` in closed form,
//! and its displacement at the centre `2 mu^2 int sigma_hat ds` (nearly uniform
//! over the mesh, so it only shifts `alpha`) by Gauss–Legendre.

use super::compliance::{compliance_matrix, load_weights};
use super::force_law::{tail_integral, tail_moment, traction, traction_slope, GAP_MAX_TENSION};
use super::mesh::MeshSpec;
use super::quadrature::{gauss_legendre, Rule};
use super::Shape;
use crate::error::{Error, Result};
use nalgebra::{DMatrix, DVector};

/// One mesh with its compliance matrix: everything that depends only on the
/// nodes.
#[derive(Debug, Clone)]
pub(crate) struct Discretisation {
    pub spec: MeshSpec,
    pub r: Vec<f64>,
    /// `C` row-major `n x n`.
    c: Vec<f64>,
    /// `W_j = int phi_j r dr`.
    w: Vec<f64>,
    /// Undeformed shape `f_i` in units of `z0`.
    pub f: Vec<f64>,
    mu: f64,
    shape: Shape,
    tail_rule: Rule,
}

/// A converged state on one mesh.
#[derive(Debug, Clone)]
pub(crate) struct Solution {
    /// Gaps at the nodes (units `z0`), `h[0]` the central gap.
    pub h: Vec<f64>,
    /// `dH_i/dH_0`.
    pub tangent: Vec<f64>,
    /// Approach `alpha/z0`.
    pub approach: f64,
    /// `P/(pi w R)`.
    pub load: f64,
    /// `d alpha/dH_0`.
    pub d_approach: f64,
    /// `d load/dH_0`.
    pub d_load: f64,
    /// Contact radius (radius of maximum tension) in solver units.
    pub radius: f64,
    /// Newton iterations spent.
    pub iterations: usize,
}

/// Undeformed gap `f(r)/z0`: `mu r^2/2`, or `rho - sqrt(rho^2 - rho mu r^2)` for a
/// true sphere (written without cancellation).
pub(crate) fn shape_gap(shape: Shape, mu: f64, r: f64) -> f64 {
    match shape {
        Shape::Paraboloid => 0.5 * mu * r * r,
        Shape::Sphere { rho } => {
            let x = rho * mu * r * r;
            let root = (rho * rho - x).max(0.0).sqrt();
            x / (rho + root)
        }
    }
}

/// Solver-unit radius of the sphere's equator `r = R`: `sqrt(rho/mu)`.
pub(crate) fn sphere_edge(shape: Shape, mu: f64) -> f64 {
    match shape {
        Shape::Paraboloid => f64::INFINITY,
        Shape::Sphere { rho } => (rho / mu).sqrt(),
    }
}

impl Discretisation {
    pub fn new(spec: MeshSpec, mu: f64, shape: Shape) -> Self {
        let r = spec.nodes();
        let c = compliance_matrix(&r);
        let w = load_weights(&r);
        let f = r.iter().map(|&x| shape_gap(shape, mu, x)).collect();
        Discretisation {
            spec,
            r,
            c,
            w,
            f,
            mu,
            shape,
            tail_rule: gauss_legendre(16),
        }
    }

    pub fn len(&self) -> usize {
        self.r.len()
    }

    /// Far-field load `2 int_{r_m}^{r_end} sigma_hat r dr` with the rigid
    /// continuation from the last gap `hm`.
    fn tail_load(&self, hm: f64) -> f64 {
        match self.shape {
            Shape::Paraboloid => 2.0 * tail_integral(hm),
            Shape::Sphere { rho } => {
                let rm = *self.r.last().unwrap();
                let fm = shape_gap(self.shape, self.mu, rm);
                let c = hm - fm;
                let hr = c + rho;
                if hr <= hm {
                    return 0.0;
                }
                (2.0 / rho)
                    * ((rho + c) * (tail_integral(hm) - tail_integral(hr))
                        - (tail_moment(hm) - tail_moment(hr)))
            }
        }
    }

    /// Far-field displacement at the centre, `2 mu^2 int_{r_m}^{r_end} sigma_hat ds`,
    /// with `s = r_m / t`.
    fn tail_centre_displacement(&self, hm: f64) -> f64 {
        let rm = *self.r.last().unwrap();
        let r_end = sphere_edge(self.shape, self.mu);
        if r_end <= rm * (1.0 + 1e-12) {
            return 0.0;
        }
        let t_lo = rm / r_end; // 0 for the paraboloid
        let fm = shape_gap(self.shape, self.mu, rm);
        let mut sum = 0.0;
        for (x, w) in self.tail_rule.x.iter().zip(&self.tail_rule.w) {
            let t = t_lo + (1.0 - t_lo) * x;
            let s = rm / t;
            let h = hm + shape_gap(self.shape, self.mu, s) - fm;
            sum += w * traction(h) * rm / (t * t);
        }
        2.0 * self.mu * self.mu * sum * (1.0 - t_lo)
    }

    /// Linear interpolation of a gap profile `(r, h)` from another mesh onto
    /// this one; beyond its last node the sphere continues rigidly.
    pub fn interpolate(&self, r_old: &[f64], h_old: &[f64]) -> Vec<f64> {
        let n_old = r_old.len();
        let r_last = r_old[n_old - 1];
        let f_last = shape_gap(self.shape, self.mu, r_last);
        let mut k = 0;
        self.r
            .iter()
            .map(|&x| {
                if x >= r_last {
                    return h_old[n_old - 1] + shape_gap(self.shape, self.mu, x) - f_last;
                }
                while k + 2 < n_old && r_old[k + 1] < x {
                    k += 1;
                }
                let t = (x - r_old[k]) / (r_old[k + 1] - r_old[k]);
                h_old[k] + t * (h_old[k + 1] - h_old[k])
            })
            .collect()
    }

    /// Contact radius: the outermost radius where the gap rises through
    /// `3^(1/6)` (maximum tension); 0 when the central gap is above it.
    pub fn contact_radius(&self, h: &[f64]) -> f64 {
        if h[0] >= GAP_MAX_TENSION {
            return 0.0;
        }
        for i in (1..h.len()).rev() {
            if h[i - 1] < GAP_MAX_TENSION && h[i] >= GAP_MAX_TENSION {
                let t = (GAP_MAX_TENSION - h[i - 1]) / (h[i] - h[i - 1]);
                return self.r[i - 1] + t * (self.r[i] - self.r[i - 1]);
            }
        }
        *self.r.last().unwrap()
    }

    /// Pressure `p/(w E*^2/R)^(1/3) = mu sigma_hat(H)` at the nodes.
    pub fn pressure(&self, h: &[f64]) -> Vec<f64> {
        h.iter().map(|&x| self.mu * traction(x)).collect()
    }

    /// Newton–Raphson at central gap `h0` from the guess `guess` (gaps at the
    /// nodes of this mesh; `guess[0]` is ignored). Converged when the largest
    /// residual is below `tol` or below the rounding floor
    /// `64 eps max_i(|H_i| + H_0 + f_i + mu^2 sum_j |C_ij - C_0j| (8/3)(H_j^-9 + H_j^-3),
    /// sum_k |J_ik| H_k)` (the residual's change under one-ulp changes of the gaps).
    pub fn solve(&self, h0: f64, guess: &[f64], tol: f64, max_iter: usize) -> Result<Solution> {
        let n = self.len();
        let m = n - 1;
        let mu2 = self.mu * self.mu;
        let mut h = guess.to_vec();
        h[0] = h0;
        let mut sig = vec![0.0; n];
        let mut dsig = vec![0.0; n];
        let mut sig_abs = vec![0.0; n];
        let mut last_res = f64::INFINITY;
        for iter in 0..=max_iter {
            if h.iter().any(|x| !(*x > 0.0)) {
                break;
            }
            for j in 0..n {
                sig[j] = traction(h[j]);
                dsig[j] = traction_slope(h[j]);
                // size of the two cancelling terms of sigma_hat: its rounding scale
                sig_abs[j] = traction(h[j])
                    .abs()
                    .max((8.0 / 3.0) * (h[j].powi(-9) + h[j].powi(-3)));
            }
            let c0 = &self.c[0..n];
            let mut res = DVector::<f64>::zeros(m);
            let mut jac = DMatrix::<f64>::zeros(m, m);
            // Size of the terms summed into a residual: its rounding floor.
            let mut magnitude = 0.0f64;
            for i in 1..n {
                let ci = &self.c[i * n..(i + 1) * n];
                let mut u = 0.0;
                let mut u_abs = 0.0;
                for j in 0..n {
                    let cj = ci[j] - c0[j];
                    u += cj * sig[j];
                    u_abs += cj.abs() * sig_abs[j];
                }
                magnitude = magnitude.max(h[i].abs() + h0 + self.f[i] + mu2 * u_abs);
                res[i - 1] = h[i] - h0 - self.f[i] - mu2 * u;
                let mut row_abs = 0.0;
                for k in 1..n {
                    let jk = -mu2 * (ci[k] - c0[k]) * dsig[k];
                    jac[(i - 1, k - 1)] = jk;
                    row_abs += jk.abs() * h[k];
                }
                jac[(i - 1, i - 1)] += 1.0;
                // a one-ulp change of every gap moves the residual by up to
                // eps * sum_k |J_ik| H_k: part of the floor too
                magnitude = magnitude.max(row_abs);
            }
            let norm = res.amax();
            last_res = norm;
            let lu = jac.lu();
            // tolerance, or the rounding floor of the residual sums
            if norm <= tol.max(64.0 * f64::EPSILON * magnitude) {
                return self.finish(h, &sig, &dsig, &lu, iter);
            }
            if iter == max_iter {
                break;
            }
            let Some(step) = lu.solve(&res) else {
                break;
            };
            // dH = -step; never let a gap shrink by more than half.
            let mut lambda = 1.0f64;
            for i in 1..n {
                let d = -step[i - 1];
                if d < 0.0 {
                    lambda = lambda.min(0.5 * h[i] / -d);
                }
            }
            for i in 1..n {
                h[i] -= lambda * step[i - 1];
            }
        }
        Err(Error::NoConvergence {
            what: format!("sphere Newton at central gap {h0}"),
            iterations: max_iter,
            residual: last_res,
        })
    }

    fn finish(
        &self,
        h: Vec<f64>,
        sig: &[f64],
        dsig: &[f64],
        lu: &nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>,
        iterations: usize,
    ) -> Result<Solution> {
        let n = self.len();
        let mu2 = self.mu * self.mu;
        let c0 = &self.c[0..n];
        let mut rhs = DVector::<f64>::zeros(n - 1);
        for i in 1..n {
            rhs[i - 1] = 1.0 + mu2 * (self.c[i * n] - c0[0]) * dsig[0];
        }
        let t = lu.solve(&rhs).ok_or_else(|| Error::NoConvergence {
            what: "sphere tangent: singular Jacobian".into(),
            iterations,
            residual: f64::NAN,
        })?;
        let mut tangent = vec![1.0; n];
        for i in 1..n {
            tangent[i] = t[i - 1];
        }
        let hm = h[n - 1];
        let mut u0 = 0.0;
        let mut du0 = 0.0;
        let mut load = 0.0;
        let mut dload = 0.0;
        for j in 0..n {
            u0 += c0[j] * sig[j];
            du0 += c0[j] * dsig[j] * tangent[j];
            load += self.w[j] * sig[j];
            dload += self.w[j] * dsig[j] * tangent[j];
        }
        let tail_u = self.tail_centre_displacement(hm);
        let approach = 1.0 - h[0] + mu2 * u0 + tail_u;
        let d_approach = -1.0 + mu2 * du0;
        let eps = 1e-6 * hm;
        let tail_slope = (self.tail_load(hm + eps) - self.tail_load(hm - eps)) / (2.0 * eps);
        let load_total = 2.0 * self.mu * load + self.tail_load(hm);
        let d_load = 2.0 * self.mu * dload + tail_slope * tangent[n - 1];
        let radius = self.contact_radius(&h);
        Ok(Solution {
            h,
            tangent,
            approach,
            load: load_total,
            d_approach,
            d_load,
            radius,
            iterations,
        })
    }
}
