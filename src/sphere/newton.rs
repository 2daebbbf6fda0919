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
//! more linear equation picks a point on it ([`Constraint`]): the central gap
//! (`H_0` prescribed, as Greenwood 2009) before contact, or the contact radius
//! (the gap, interpolated linearly between two nodes, equals `3^(1/6)` at a
//! prescribed radius) once in contact. The contact radius grows monotonically
//! along the whole curve, through the folds of `alpha` (jumps), of `P`
//! (pull-off) and of `H_0` (mu > ~15), as Maugis' contact radius does.
//! Afterwards `alpha = 1 - H_0 + mu^2 sum_j C_0j sigma_hat_j` (+ far field)
//! and `P/(pi w R) = 2 mu sum_j W_j sigma_hat_j` (+ far field).
//!
//! The bordered Jacobian `[grad g; dR/dx]` is factorised (faer, partial
//! pivoting) once per point; the corrector runs chord iterations on the
//! factorisation of the previous point (refactorising only when the
//! contraction is poor), and the factorisation at the converged point gives
//! the tangent exactly.

use super::disc::Discretisation;
use super::force_law::{traction, traction_slope};
use crate::error::{Error, Result};
use faer::linalg::solvers::{PartialPivLu, SolveCore};
use faer::{Conj, Mat};

/// A factorised bordered Jacobian (faer LU with partial pivoting).
#[derive(Debug)]
pub(crate) struct Lu {
    lu: PartialPivLu<f64>,
    n: usize,
}

impl Lu {
    fn new(jac: &Mat<f64>) -> Self {
        Lu {
            lu: jac.partial_piv_lu(),
            n: jac.nrows(),
        }
    }

    /// Order of the matrix.
    pub fn order(&self) -> usize {
        self.n
    }

    /// `J^-1 b`, `None` when not finite (singular `J`).
    fn solve(&self, b: &[f64]) -> Option<Vec<f64>> {
        let mut x = Mat::<f64>::from_fn(self.n, 1, |i, _| b[i]);
        self.lu.solve_in_place_with_conj(Conj::No, x.as_mut());
        let v: Vec<f64> = (0..self.n).map(|i| x[(i, 0)]).collect();
        v.iter().all(|x| x.is_finite()).then_some(v)
    }
}

/// The extra (linear) equation that selects one point of the solution curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Constraint {
    /// `H_0 = value`.
    Gap(f64),
    /// `(1 - t) H_lo + t H_(lo+1) = 3^(1/6)`: the contact edge at
    /// `r_lo + t (r_(lo+1) - r_lo)`.
    Radius { lo: usize, t: f64 },
}

impl Constraint {
    /// The constraint for an edge at `a` on nodes `r` (`0 <= a < r_max`).
    pub fn radius(r: &[f64], a: f64) -> Self {
        let n = r.len();
        let lo = r.partition_point(|x| *x <= a).clamp(1, n - 1) - 1;
        let t = ((a - r[lo]) / (r[lo + 1] - r[lo])).clamp(0.0, 1.0);
        Constraint::Radius { lo, t }
    }
}

/// A converged state on one mesh.
#[derive(Debug, Clone)]
pub(crate) struct Solution {
    /// Gaps at the nodes (units `z0`), `h[0]` the central gap.
    pub h: Vec<f64>,
    /// `dx/dt` at fixed nodes, `t` the tracer's parameter: `3^(1/6) - H_0`
    /// under [`Constraint::Gap`], the contact radius under
    /// [`Constraint::Radius`].
    pub tangent: Vec<f64>,
    /// Approach `alpha/z0`.
    pub approach: f64,
    /// `P/(pi w R)`.
    pub load: f64,
    /// `d alpha/dH_0` (infinite at a fold of `H_0`).
    pub d_approach: f64,
    /// `d load/dH_0`.
    pub d_load: f64,
    /// `d alpha/dt`.
    pub dt_approach: f64,
    /// `d load/dt`.
    pub dt_load: f64,
    /// Contact radius (radius of maximum tension) in solver units.
    pub radius: f64,
    /// Newton iterations spent.
    pub iterations: usize,
    /// LU factorisations done.
    pub factorisations: usize,
}

/// Per-iterate quantities.
struct Eval {
    dsig: Vec<f64>,
    /// residual: `g[0]` the constraint, `g[i] = R_i`
    g: Vec<f64>,
    approach: f64,
    load: f64,
    /// rounding floor of the residual sums
    magnitude: f64,
}

impl Discretisation {
    fn eval(&self, h: &[f64], con: &Constraint) -> Eval {
        let n = self.len();
        let mu2c = self.mu * self.mu * self.scale;
        let sig: Vec<f64> = h.iter().map(|&x| traction(x)).collect();
        let dsig: Vec<f64> = h.iter().map(|&x| traction_slope(x)).collect();
        // size of the two cancelling terms of sigma_hat
        let sig_abs: Vec<f64> = h
            .iter()
            .map(|&x| {
                let y = 1.0 / x;
                let y3 = y * y * y;
                (8.0 / 3.0) * (y3 * y3 * y3 + y3)
            })
            .collect();
        let c0 = self.c_row(0);
        let mut g = vec![0.0; n];
        let mut magnitude = 0.0f64;
        for i in 1..n {
            let ci = self.c_row(i);
            let (mut u, mut u_abs) = (0.0, 0.0);
            for j in 0..n {
                let cj = ci[j] - c0[j];
                u += cj * sig[j];
                u_abs += cj.abs() * sig_abs[j];
            }
            magnitude = magnitude.max(h[i].abs() + h[0] + self.f[i] + mu2c * u_abs);
            g[i] = h[i] - h[0] - self.f[i] - mu2c * u;
        }
        let (approach, load) = self.observables(h, &sig);
        g[0] = match *con {
            Constraint::Gap(v) => h[0] - v,
            Constraint::Radius { lo, t } => {
                (1.0 - t) * h[lo] + t * h[lo + 1] - super::force_law::GAP_MAX_TENSION
            }
        };
        Eval {
            dsig,
            g,
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

    /// The bordered Jacobian with the constraint's gradient in row 0.
    fn jacobian(&self, dsig: &[f64], con: &Constraint) -> Mat<f64> {
        let n = self.len();
        let mu2c = self.mu * self.mu * self.scale;
        let c0 = self.c_row(0);
        let mut jac = Mat::<f64>::zeros(n, n);
        match *con {
            Constraint::Gap(_) => jac[(0, 0)] = 1.0,
            Constraint::Radius { lo, t } => {
                jac[(0, lo)] = 1.0 - t;
                jac[(0, lo + 1)] += t;
            }
        }
        // column-major fill: column k holds dR_i/dH_k
        for k in 0..n {
            let s = -mu2c * dsig[k];
            let ck0 = c0[k];
            let col = jac.col_as_slice_mut(k);
            for (i, v) in col.iter_mut().enumerate().skip(1) {
                *v = s * (self.c_row(i)[k] - ck0);
            }
        }
        for i in 1..n {
            jac[(i, i)] += 1.0;
            jac[(i, 0)] -= 1.0;
        }
        jac
    }

    /// Solves `R(x) = 0` with the constraint `con` from `guess`: chord
    /// iterations on `chord` (a factorisation of a nearby point's bordered
    /// Jacobian on the same nodes, up to scale) when given, then on the
    /// iteration's own factorisation, refactorising when the residual falls
    /// by less than 20x. A chord step that does not reduce the residual is
    /// undone and the Jacobian refactorised there; a Newton step that does
    /// not is halved (up to 6 times). Converged when the largest residual is
    /// below `tol` or below the rounding floor
    /// `64 eps max_i(|H_i| + H_0 + f_i + mu^2 sum_j |C_ij - C_0j| (8/3)(H_j^-9 + H_j^-3))`.
    /// Returns the solution and the factorisation at it.
    pub fn solve(
        &self,
        guess: &[f64],
        con: &Constraint,
        chord: Option<&Lu>,
        tol: f64,
        max_iter: usize,
    ) -> Result<(Solution, Lu)> {
        let n = self.len();
        let mut h = guess.to_vec();
        if let Constraint::Gap(v) = con {
            h[0] = *v;
        }
        let fail = |iterations, residual| Error::NoConvergence {
            what: "sphere Newton".into(),
            iterations,
            residual,
        };
        if h.iter().any(|x| !(*x > 0.0 && x.is_finite())) {
            return Err(fail(0, f64::NAN));
        }
        let amax = |g: &[f64]| g.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let mut chord = chord.filter(|l| l.order() == n);
        // own factorisation, and whether it was made at the current iterate
        let mut own: Option<Lu> = None;
        let mut fresh = false;
        let mut factorisations = 0;
        let mut ev = self.eval(&h, con);
        let mut norm = amax(&ev.g);
        let mut iterations = 0;
        loop {
            crate::cancel::check()?;
            if norm <= tol.max(64.0 * f64::EPSILON * ev.magnitude) {
                return self.finish(h, ev, con, iterations, factorisations);
            }
            if iterations >= max_iter || !norm.is_finite() {
                return Err(fail(iterations, norm));
            }
            if own.is_none() && chord.is_none() {
                own = Some(Lu::new(&self.jacobian(&ev.dsig, con)));
                factorisations += 1;
                fresh = true;
            }
            let lu = own.as_ref().or(chord).unwrap();
            let Some(step) = lu.solve(&ev.g) else {
                return Err(fail(iterations, norm));
            };
            // never let a gap shrink by more than half
            let mut lambda = 1.0f64;
            for i in 0..n {
                if step[i] > 0.0 {
                    lambda = lambda.min(0.5 * h[i] / step[i]);
                }
            }
            let mut best: Option<(Vec<f64>, Eval, f64)> = None;
            for _ in 0..if fresh { 7 } else { 1 } {
                let trial: Vec<f64> = (0..n).map(|i| h[i] - lambda * step[i]).collect();
                let et = self.eval(&trial, con);
                let nt = amax(&et.g);
                let better = nt.is_finite() && best.as_ref().is_none_or(|b| nt < b.2);
                if better {
                    best = Some((trial, et, nt));
                }
                if nt < norm {
                    break;
                }
                lambda *= 0.5;
            }
            iterations += 1;
            match best {
                Some((trial, et, nt)) if nt < norm || fresh => {
                    let contracted = nt <= 0.05 * norm;
                    h = trial;
                    ev = et;
                    norm = nt;
                    if !contracted {
                        // refactorise at the new iterate
                        own = None;
                        chord = None;
                    }
                    fresh = false;
                }
                _ => {
                    // a chord step that did not help: refactorise here
                    own = None;
                    chord = None;
                }
            }
        }
    }

    /// Tangent and outputs at a converged point.
    ///
    /// Fixed nodes (`moving == false`): `v = J^-1 e_0` is the curve's
    /// direction per unit change of the constraint's linear form `c . x`;
    /// `dt (c . x) = -1` under `Gap` (`t = 3^(1/6) - H_0`) and `-H'(a)` (the
    /// interpolated gap slope at the edge) under `Radius`.
    ///
    /// Moving mesh ([`Discretisation::moving`], under `Radius`: the nodes a
    /// base mesh scaled by `lambda = a/a_base`, so the edge keeps its place
    /// among them): the residual depends on `lambda` through `f_i =
    /// f(lambda r_i)` and `lambda C`, `lambda dR_i/dlambda = -(r_i f'(r_i) +
    /// U_i - U_0) = -(H_i - H_0 - f_i + r_i f'(r_i))` at a solution
    /// (`U = mu^2 lambda C sigma`; `r f' = 2 f` for the paraboloid), and the
    /// constraint does not change; so the derivative of the nodal gaps along
    /// the traced family is `dx/da = J^-1 b`, `b_0 = 0`,
    /// `b_i = (H_i - H_0 - f_i + r_i f'(r_i))/a`. The observables add their
    /// explicit scale dependence: `P_mesh ~ lambda^2` and the far-field load
    /// (`+ (2 P_mesh + r_m dP_tail/dr_m)/a`), and `alpha`'s
    /// `U_0 + tail(r_m)` (`+ (U_0 + r_m dtail/dr_m)/a`; the `r_m`
    /// derivatives by central differences). These are the derivatives of the
    /// discrete solution the tracer follows, unlike the fixed-node ones, which
    /// move the edge through the nodes (at mu = 30 they put the minimum of the
    /// approach, the jump-out, 0.009 in `A` away from that of the traced
    /// curve, 2 % in the jump-out load).
    fn finish(
        &self,
        h: Vec<f64>,
        ev: Eval,
        con: &Constraint,
        iterations: usize,
        factorisations: usize,
    ) -> Result<(Solution, Lu)> {
        let n = self.len();
        let lu = Lu::new(&self.jacobian(&ev.dsig, con));
        let singular = || Error::NoConvergence {
            what: "sphere tangent: singular Jacobian".into(),
            iterations,
            residual: f64::NAN,
        };
        let (ga, gp) = self.observable_gradients(&h, &ev.dsig);
        let dot = |g: &[f64], v: &[f64]| -> f64 { (0..n).map(|j| g[j] * v[j]).sum() };
        let (tangent, dt_approach, dt_load) = match (*con, self.moving) {
            (Constraint::Radius { lo, t }, true) => {
                let a = self.r[lo] + t * (self.r[lo + 1] - self.r[lo]);
                let mut rhs: Vec<f64> = (0..n)
                    .map(|i| (h[i] - h[0] - self.f[i] + self.shape_scale_rate(i)) / a)
                    .collect();
                rhs[0] = 0.0;
                let v = lu.solve(&rhs).ok_or_else(singular)?;
                let sig: Vec<f64> = h.iter().map(|&x| traction(x)).collect();
                let mu2c = self.mu * self.mu * self.scale;
                let c0 = self.c_row(0);
                let u0: f64 = (0..n).map(|j| c0[j] * sig[j]).sum::<f64>() * mu2c;
                let p_mesh: f64 = 2.0 * self.mu * (0..n).map(|j| self.w[j] * sig[j]).sum::<f64>();
                let hm = h[n - 1];
                let rm = self.r[n - 1];
                let e = 1e-6;
                let dtail = (self.tail_centre_displacement_at(hm, rm * (1.0 + e))
                    - self.tail_centre_displacement_at(hm, rm * (1.0 - e)))
                    / (2.0 * e);
                let dtail_load = (self.tail_load_at(hm, rm * (1.0 + e))
                    - self.tail_load_at(hm, rm * (1.0 - e)))
                    / (2.0 * e);
                let da = dot(&ga, &v) + (u0 + dtail) / a;
                let dp = dot(&gp, &v) + (2.0 * p_mesh + dtail_load) / a;
                (v, da, dp)
            }
            _ => {
                let mut rhs = vec![0.0; n];
                rhs[0] = 1.0;
                let v = lu.solve(&rhs).ok_or_else(singular)?;
                let dc_dt = match *con {
                    Constraint::Gap(_) => -1.0,
                    Constraint::Radius { lo, .. } => {
                        -(h[lo + 1] - h[lo]) / (self.r[lo + 1] - self.r[lo])
                    }
                };
                if !(dc_dt < 0.0 && dc_dt.is_finite()) {
                    return Err(singular());
                }
                let da = dot(&ga, &v) * dc_dt;
                let dp = dot(&gp, &v) * dc_dt;
                let tangent: Vec<f64> = v.iter().map(|x| x * dc_dt).collect();
                (tangent, da, dp)
            }
        };
        if !(dt_approach.is_finite() && dt_load.is_finite()) {
            return Err(singular());
        }
        let radius = self.contact_radius(&h);
        let sol = Solution {
            approach: ev.approach,
            load: ev.load,
            d_approach: dt_approach / tangent[0],
            d_load: dt_load / tangent[0],
            dt_approach,
            dt_load,
            tangent,
            radius,
            iterations,
            factorisations: factorisations + 1,
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

    /// The bordered Jacobian (residuals and the radius constraint) matches
    /// central differences of the residual.
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
        let con = Constraint::radius(&disc.r, 1.13);
        let ev = disc.eval(&h, &con);
        let jac = disc.jacobian(&ev.dsig, &con);
        let Constraint::Radius { lo, .. } = con else {
            panic!("{con:?}")
        };
        for k in [0, 1, lo, lo + 1, n / 2, n - 1] {
            let e = 1e-6 * h[k];
            let mut hp = h.clone();
            hp[k] += e;
            let mut hm = h.clone();
            hm[k] -= e;
            let gp = disc.eval(&hp, &con).g;
            let gm = disc.eval(&hm, &con).g;
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
