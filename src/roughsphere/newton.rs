//! Newton–Raphson for the gaps of the rough sphere on one mesh, at a
//! prescribed central separation `d` (Greenwood & Tripp 1967, in their units).
//!
//! With `H_i` the local gap at node `rho_i` (units `sigma`), `f_i` the
//! undeformed shape (`rho_i^2` for the paraboloid), `p(H)` the local pressure
//! law (units `E* sqrt(sigma/(8R))`) and `u = (1/2) C p` the elastic
//! displacement (units `sigma`; `C` the compliance in radius units):
//!
//! ```text
//! R_i = H_i - d - f_i - (1/2) sum_j (C_ij - C_0j) p_j(H_j) = 0,   i >= 1,   H_0 = d
//! J_ik = delta_ik - (1/2) (C_ik - C_0k) p_k'(H_k)
//! ```
//!
//! (`p_j` may differ per node: on retraction each node remembers its
//! closest gap.) The Jacobian is factorised densely (faer, partial pivoting);
//! steps that do not reduce the largest residual are halved. A
//! factorisation is kept while the residual keeps falling 4-fold per step
//! (chord iterations), and the caller's factorisation of a nearby state
//! (the previous point of a curve, possibly on a rescaled mesh) is tried
//! first.

use super::mesh::Mesh;
use crate::error::{Error, Result};
use faer::linalg::solvers::{PartialPivLu, SolveCore};
use faer::{Conj, Mat};

/// The local pressure `(p, dp/dH)` at node `i` for gap `H` (Greenwood–Tripp
/// units); the slope only when the flag asks for it (0 otherwise: chord
/// iterations need none, and for closed forms it costs a second `F_n`).
pub(crate) type NodeLaw<'a> = &'a (dyn Fn(usize, f64, bool) -> (f64, f64) + Sync);

/// A factorisation is kept while each step shrinks the residual at least
/// this much: a chord step costs `O(n^2)`, a factorisation `O(n^3)`, so a
/// slower chord (e.g. on a mesh rescaled by a few per cent since the
/// factorisation) still pays.
const CHORD_CONTRACTION: f64 = 0.25;

/// A factorised Jacobian.
#[derive(Debug, Clone)]
pub(crate) struct Factor {
    lu: PartialPivLu<f64>,
    n: usize,
}

impl Factor {
    fn solve(&self, b: &[f64]) -> Option<Vec<f64>> {
        let mut x = Mat::<f64>::from_fn(self.n, 1, |i, _| b[i]);
        self.lu.solve_in_place_with_conj(Conj::No, x.as_mut());
        let v: Vec<f64> = (0..self.n).map(|i| x[(i, 0)]).collect();
        v.iter().all(|x| x.is_finite()).then_some(v)
    }
}

/// A converged state on one mesh.
#[derive(Debug, Clone)]
pub(crate) struct Solution {
    /// Gaps at the nodes, `h[0] = d`.
    pub h: Vec<f64>,
    /// Pressures at the nodes.
    pub p: Vec<f64>,
    /// `dp/dH` at the nodes when the factorisation was made at the solution
    /// (`at_solution`), else empty.
    pub dp: Vec<f64>,
    /// Newton iterations spent.
    pub iterations: usize,
}

struct Eval {
    p: Vec<f64>,
    /// `R_i` for `i >= 1` (index `i - 1`).
    g: Vec<f64>,
    norm: f64,
    /// rounding floor of the residual
    floor: f64,
}

impl Mesh {
    /// Residuals at gaps `h`; with `floor`, also the rounding floor
    /// `64 eps max_i (|H_i| + |d| + f_i + (1/2) sum_j |D_ij p_j|)` (computed
    /// once per solve: it only sets where iterating stops paying).
    fn eval(&self, d: f64, h: &[f64], f: &[f64], law: NodeLaw, floor: bool) -> Eval {
        let n = self.len();
        let p: Vec<f64> = (0..n).map(|i| law(i, h[i], false).0).collect();
        // nodes beyond the last loaded one add nothing
        let jmax = p.iter().rposition(|x| *x != 0.0).map_or(0, |j| j + 1);
        let half_h = 0.5 * self.scale();
        let mut g = vec![0.0; n - 1];
        let mut norm = 0.0f64;
        let mut top = 0.0f64;
        for i in 1..n {
            let row = &self.relative_row(i)[..jmax];
            let u: f64 = row.iter().zip(&p[..jmax]).map(|(c, x)| c * x).sum();
            let r = h[i] - d - f[i] - half_h * u;
            g[i - 1] = r;
            norm = norm.max(r.abs());
            if floor {
                let mag: f64 = row.iter().zip(&p[..jmax]).map(|(c, x)| (c * x).abs()).sum();
                top = top.max(h[i].abs() + d.abs() + f[i] + half_h * mag);
            }
        }
        Eval {
            p,
            g,
            norm,
            floor: 64.0 * f64::EPSILON * top,
        }
    }

    /// `dp/dH` at every node.
    fn slopes(&self, h: &[f64], law: NodeLaw) -> Vec<f64> {
        (0..self.len()).map(|i| law(i, h[i], true).1).collect()
    }

    fn factor(&self, dp: &[f64]) -> Factor {
        let n = self.len();
        let m = n - 1;
        let half_h = 0.5 * self.scale();
        let mut jac = Mat::<f64>::zeros(m, m);
        for k in 1..n {
            let s = -half_h * dp[k];
            let col = jac.col_as_slice_mut(k - 1);
            let rel = self.relative();
            for (i, v) in col.iter_mut().enumerate() {
                *v = s * rel[i * n + k];
            }
            col[k - 1] += 1.0;
        }
        Factor {
            lu: jac.partial_piv_lu(),
            n: m,
        }
    }

    /// `dH/dd` at a converged state (the tangent of a curve in `d`), from
    /// the factorisation at it: `J dH/dd = 1 + (1/2)(C_i0 - C_00) p_0'(d)`.
    pub fn tangent(&self, sol: &Solution, fac: &Factor) -> Option<Vec<f64>> {
        let n = self.len();
        let half_h = 0.5 * self.scale();
        let b: Vec<f64> = (1..n)
            .map(|i| 1.0 + half_h * self.relative_row(i)[0] * sol.dp[0])
            .collect();
        let x = fac.solve(&b)?;
        Some(std::iter::once(1.0).chain(x).collect())
    }

    /// Solves for the gaps at central separation `d` from `guess` (length
    /// `n`), the shape `f` at the nodes and the node laws; `chord` is a
    /// factorisation of a nearby state to try first. Converged when the
    /// largest residual is below `tol` (units `sigma`) or its rounding
    /// floor. Returns the solution and a factorisation: made at the solution
    /// when `at_solution` (for [`tangent`](Self::tangent)), otherwise the
    /// last one made (at a nearby iterate; a chord for the next point), if
    /// any.
    ///
    /// # Errors
    /// [`Error::NoConvergence`] after `max_iter` steps or on a singular
    /// Jacobian.
    #[allow(clippy::too_many_arguments)]
    pub fn newton(
        &self,
        d: f64,
        guess: &[f64],
        f: &[f64],
        law: NodeLaw,
        chord: Option<&Factor>,
        tol: f64,
        max_iter: usize,
        at_solution: bool,
    ) -> Result<(Solution, Option<Factor>)> {
        let n = self.len();
        let mut h = guess.to_vec();
        h[0] = d;
        let mut ev = self.eval(d, &h, f, law, true);
        let floor = ev.floor;
        let mut borrowed = chord.filter(|c| c.n == n - 1);
        let mut own: Option<Factor> = None;
        // whether `own` was made at the current iterate
        let mut fresh = false;
        let mut iterations = 0;
        let fail = |iterations, residual| Error::NoConvergence {
            what: format!("rough-sphere Newton at d = {d:e} sigma ({n} nodes)"),
            iterations,
            residual,
        };
        loop {
            crate::cancel::check()?;
            if ev.norm <= tol.max(floor) {
                let (dp, factor) = if at_solution {
                    let dp = self.slopes(&h, law);
                    let f = if fresh { own } else { Some(self.factor(&dp)) };
                    (dp, f)
                } else {
                    (Vec::new(), own)
                };
                return Ok((
                    Solution {
                        h,
                        p: ev.p,
                        dp,
                        iterations,
                    },
                    factor,
                ));
            }
            if iterations >= max_iter || !ev.norm.is_finite() {
                return Err(fail(iterations, ev.norm));
            }
            if own.is_none() && borrowed.is_none() {
                own = Some(self.factor(&self.slopes(&h, law)));
                fresh = true;
            }
            let lu = own.as_ref().or(borrowed).unwrap();
            let Some(step) = lu.solve(&ev.g) else {
                return Err(fail(iterations, ev.norm));
            };
            iterations += 1;
            let mut lambda = 1.0;
            let mut accepted = None;
            for _ in 0..if fresh { 12 } else { 1 } {
                let mut trial = h.clone();
                for i in 1..n {
                    trial[i] -= lambda * step[i - 1];
                }
                let et = self.eval(d, &trial, f, law, false);
                if et.norm < ev.norm {
                    accepted = Some((trial, et));
                    break;
                }
                lambda *= 0.5;
            }
            match accepted {
                Some((trial, et)) => {
                    let contracted = et.norm <= CHORD_CONTRACTION * ev.norm;
                    h = trial;
                    ev = et;
                    if !contracted {
                        own = None;
                        borrowed = None;
                    }
                    fresh = false;
                }
                None if fresh => return Err(fail(iterations, ev.norm)),
                None => {
                    own = None;
                    borrowed = None;
                }
            }
        }
    }
}
