//! The converged solve of one state (see `solve.rs` for the method):
//! continuation in the central separation on the coarse mesh (enlarging the
//! outer radius while the pressure reaches it), the outer radius and the
//! grading fitted to the solution, the nested finer levels (from the start
//! state's levels when their meshes still suit), and retraction on the
//! deepest approach state's meshes with per-node laws.

use super::local::NodeLaw;
use super::mesh::{Grading, Mesh};
use super::newton::Factor;
use super::solve::{
    extrapolate, Continued, Core, Laws, Level, Retraction, Solved, MAX_NEWTON, MIN_LEVELS, MIN_STEP,
};
use crate::error::{Allowed, Error, Result};
use std::sync::Arc;

impl Core {
    /// Newton on the coarse mesh by continuation in `d` from `(d0, h0)`,
    /// enlarging the outer radius whenever the last gap falls below `top`.
    #[allow(clippy::too_many_arguments)]
    fn continuation(
        &self,
        laws: &Laws,
        mut mesh: Mesh,
        d0: f64,
        h0: Vec<f64>,
        tangent0: Option<Vec<f64>>,
        chord: Option<Arc<Factor>>,
        d: f64,
        growable: bool,
    ) -> Result<Continued> {
        let tol = self.options.newton_tolerance;
        let top = self.law.top();
        let law = self.node_law(laws, 0);
        let mut f = self.shape_at(&mesh);
        let (mut cur_d, mut cur_h, mut tangent) = (d0, h0, tangent0);
        let mut fac: Option<Factor> = chord.map(|c| (*c).clone());
        let mut step = d - d0;
        if step == 0.0 {
            let (sol, fa) =
                mesh.newton(d, &cur_h, &f, &law, fac.as_ref(), tol, MAX_NEWTON, true)?;
            let t = fa.as_ref().and_then(|fa| mesh.tangent(&sol, fa));
            return Ok((mesh, sol, fa, t));
        }
        loop {
            let target = if (d - cur_d).abs() <= step.abs() * (1.0 + 1e-12) {
                d
            } else {
                cur_d + step
            };
            let guess: Vec<f64> = match &tangent {
                Some(t) => cur_h
                    .iter()
                    .zip(t)
                    .map(|(h, t)| h + t * (target - cur_d))
                    .collect(),
                None => cur_h.iter().map(|h| h + (target - cur_d)).collect(),
            };
            match mesh.newton(
                target,
                &guess,
                &f,
                &law,
                fac.as_ref(),
                tol,
                MAX_NEWTON,
                true,
            ) {
                Ok((sol, fa)) => {
                    let n = mesh.len();
                    if growable && sol.h[n - 1] < top && mesh.rho_max() < 0.99 * self.shape.limit()
                    {
                        // The pressure reaches the outer radius: enlarge it.
                        let rm = (1.5 * mesh.rho_max()).min(0.999 * self.shape.limit());
                        let bigger = Mesh::new(mesh.len(), rm, Grading::Uniform);
                        cur_h = self.onto(&mesh, &cur_h, &bigger);
                        tangent = None;
                        fac = None;
                        mesh = bigger;
                        f = self.shape_at(&mesh);
                        continue;
                    }
                    let t = fa.as_ref().and_then(|fa| mesh.tangent(&sol, fa));
                    if target == d {
                        return Ok((mesh, sol, fa, t));
                    }
                    if sol.iterations <= 3 {
                        step *= 2.0;
                    }
                    cur_d = target;
                    cur_h = sol.h.clone();
                    tangent = t;
                    fac = fa;
                }
                Err(e) => {
                    step *= 0.5;
                    fac = None;
                    if step.abs() < MIN_STEP {
                        return Err(match e {
                            Error::NoConvergence {
                                iterations,
                                residual,
                                ..
                            } => Error::NoConvergence {
                                what: format!(
                                    "rough-sphere continuation stalled at d = {cur_d:e} sigma \
                                     on the way to {d:e} (a fold of the load curve?)"
                                ),
                                iterations,
                                residual,
                            },
                            other => other,
                        });
                    }
                }
            }
        }
    }

    /// Solves the finer levels of `state` (whose level 0 is solved) from
    /// the coarse solution, reusing `start`'s levels as guesses when they
    /// are on the same meshes, until the load's estimate meets the
    /// tolerance.
    fn refine(&self, laws: &Laws, state: &mut Solved, start: Option<&Solved>) -> Result<()> {
        let tol = self.options.newton_tolerance;
        let mut k = 1;
        loop {
            if k >= MIN_LEVELS {
                let loads: Vec<f64> = state
                    .levels
                    .iter()
                    .map(|l| l.mesh.moment(&l.sol.p))
                    .collect();
                let mags: Vec<f64> = state
                    .levels
                    .iter()
                    .map(|l| {
                        let a: Vec<f64> = l.sol.p.iter().map(|x| x.abs()).collect();
                        l.mesh.moment(&a)
                    })
                    .collect();
                let e = extrapolate(&loads);
                let mag = mags[mags.len() - 1].max(1e-300);
                if e.error <= self.options.tolerance * mag {
                    state.converged = true;
                    return Ok(());
                }
                let next = 2 * state.levels[k - 1].mesh.len() - 1;
                if next > self.options.max_nodes {
                    state.converged = false;
                    return Ok(());
                }
            }
            let prev = &state.levels[k - 1];
            let mesh = match start.and_then(|s| s.levels.get(k)) {
                Some(l) if same_mesh(&l.mesh, &prev.mesh, k) => l.mesh.clone(),
                _ => prev.mesh.refined(),
            };
            let f = self.shape_at(&mesh);
            // Guess: the start's solution on this level moved by the coarse
            // change, or the coarser level interpolated.
            let (guess, chord) = match start.and_then(|s| s.levels.get(k).map(|l| (s, l))) {
                Some((s, l)) if same_mesh(&l.mesh, &mesh, 0) => {
                    let c_new = &state.levels[0];
                    let c_old = &s.levels[0];
                    let g: Vec<f64> = mesh
                        .rho
                        .iter()
                        .zip(&l.sol.h)
                        .map(|(&r, &h)| {
                            let shape = |x: f64| self.shape.gap(x);
                            h + c_new.mesh.gap_at(&c_new.sol.h, r, shape)
                                - c_old.mesh.gap_at(&c_old.sol.h, r, shape)
                        })
                        .collect();
                    (g, l.factor.clone())
                }
                // A rescaled uniform mesh of the same size: its
                // factorisation still serves as a chord.
                _ => (
                    self.onto(&prev.mesh, &prev.sol.h, &mesh),
                    start
                        .and_then(|s| s.levels.get(k))
                        .filter(|l| {
                            l.mesh.len() == mesh.len()
                                && l.mesh.grading == Grading::Uniform
                                && mesh.grading == Grading::Uniform
                        })
                        .and_then(|l| l.factor.clone()),
                ),
            };
            let law = self.node_law(laws, k);
            let (sol, fa) = mesh.newton(
                state.d,
                &guess,
                &f,
                &law,
                chord.as_deref(),
                tol,
                MAX_NEWTON,
                false,
            )?;
            let level = Level {
                mesh,
                f,
                sol,
                factor: fa.map(Arc::new).or(chord),
            };
            if state.levels.len() > k {
                state.levels[k] = level;
            } else {
                state.levels.push(level);
            }
            k += 1;
        }
    }

    /// The state at `d` on its coarse level alone, from a continuation's
    /// `end`, not yet converged; `retraction`: its laws (`None` on approach).
    fn coarse_state(&self, d: f64, end: Continued, retraction: Option<Arc<Retraction>>) -> Solved {
        let (mesh, sol, fa, tangent) = end;
        Solved {
            d,
            levels: vec![Level {
                f: self.shape_at(&mesh),
                mesh,
                sol,
                factor: fa.map(Arc::new),
            }],
            tangent,
            retraction,
            converged: false,
        }
    }

    /// The approach state at central separation `d` (units `sigma`),
    /// continued from `start` (a nearby approach state; `None`: from far
    /// apart).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `d` when it is not finite;
    /// [`Error::NoConvergence`].
    pub fn approach(&self, d: f64, start: Option<&Solved>) -> Result<Solved> {
        crate::error::finite("d", d)?;
        let laws = Laws::Approach;
        let top = self.law.top();
        let start = start.filter(|s| s.retraction.is_none());
        let end = match start {
            Some(s) => {
                let l0 = &s.levels[0];
                self.continuation(
                    &laws,
                    l0.mesh.clone(),
                    s.d,
                    l0.sol.h.clone(),
                    s.tangent.clone(),
                    l0.factor.clone(),
                    d,
                    true,
                )?
            }
            None => {
                let d0 = d.max(top);
                let rm = self.outer_radius(((top - d0).max(0.0) + 1.0).sqrt());
                let mesh = Mesh::new(self.options.base_nodes, rm, Grading::Uniform);
                let h0: Vec<f64> = mesh.rho.iter().map(|&r| d0 + self.shape.gap(r)).collect();
                self.continuation(&laws, mesh, d0, h0, None, None, d, true)?
            }
        };
        let mut state = self.coarse_state(d, end, None);
        // Fit the outer radius and the grading, unless the start's meshes
        // still suit.
        let reuse = {
            let l0 = &state.levels[0];
            start.is_some_and(|s| same_mesh(&s.levels[0].mesh, &l0.mesh, 0))
                && self.mesh_fits(&l0.mesh, &l0.sol.h, &l0.sol.p)
        };
        if !reuse {
            for _ in 0..3 {
                let l0 = &state.levels[0];
                let rs = self.rho_star(&l0.mesh, &l0.sol.h);
                let rm = self.outer_radius(rs);
                let grading = self.grading_for(&l0.mesh, &l0.sol.p, rm);
                let mesh = Mesh::new(self.options.base_nodes, rm, grading);
                let guess = self.onto(&l0.mesh, &l0.sol.h, &mesh);
                let chord = l0
                    .factor
                    .clone()
                    .filter(|_| l0.mesh.grading == Grading::Uniform && grading == Grading::Uniform);
                // The coarse state moved onto the fitted mesh is usually
                // within Newton's reach of the solution there; deep in
                // contact (d = -50 sigma at mu = 10: the outer radius grows
                // several fold) it may not be, and the continuation from
                // far apart on the fitted mesh reaches it instead.
                let (m, sol, fa, t) =
                    match self.continuation(&laws, mesh.clone(), d, guess, None, chord, d, false) {
                        Ok(c) => c,
                        Err(Error::NoConvergence { .. }) => {
                            let d0 = d.max(top);
                            let h0: Vec<f64> =
                                mesh.rho.iter().map(|&r| d0 + self.shape.gap(r)).collect();
                            self.continuation(&laws, mesh, d0, h0, None, None, d, false)?
                        }
                        Err(e) => return Err(e),
                    };
                let fits = self.mesh_fits(&m, &sol.h, &sol.p);
                state.levels[0] = Level {
                    f: self.shape_at(&m),
                    mesh: m,
                    sol,
                    factor: fa.map(Arc::new),
                };
                state.tangent = t;
                if fits {
                    break;
                }
            }
        }
        self.refine(&laws, &mut state, start)?;
        Ok(state)
    }

    /// The per-node retraction laws after the approach reached `deepest`.
    ///
    /// # Errors
    /// The local law's tabulation failures.
    pub fn retraction(&self, deepest: Arc<Solved>) -> Result<Retraction> {
        use rayon::prelude::*;
        // One table over the closest gaps of every node of every level.
        let lowest = deepest
            .levels
            .iter()
            .flat_map(|l| l.sol.h.iter().copied())
            .fold(f64::INFINITY, f64::min);
        self.law.prepare_retraction(lowest)?;
        let mut h_min = Vec::new();
        let mut laws = Vec::new();
        for l in &deepest.levels {
            let hs = l.sol.h.clone();
            let node: Vec<NodeLaw> = hs
                .par_iter()
                .map(|&h| self.law.after(h))
                .collect::<Result<Vec<_>>>()?;
            h_min.push(hs);
            laws.push(node);
        }
        Ok(Retraction {
            closest: deepest.d,
            h_min,
            laws,
            deepest,
        })
    }

    /// The retraction state at `d >= closest` on the deepest state's
    /// meshes, continued from `start` (a retraction state of the same
    /// retraction; `None`: from the deepest state).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `d` below the closest separation;
    /// [`Error::NoConvergence`].
    pub fn retract(
        &self,
        d: f64,
        retraction: &Arc<Retraction>,
        start: Option<&Solved>,
    ) -> Result<Solved> {
        crate::error::finite("d", d)?;
        if d < retraction.closest {
            return Err(Error::OutOfRange {
                name: "d".into(),
                value: d,
                allowed: Allowed::closed(retraction.closest, f64::INFINITY),
            });
        }
        let laws = Laws::Retract(retraction);
        let from: &Solved = match start {
            Some(s)
                if s.retraction
                    .as_ref()
                    .is_some_and(|r| Arc::ptr_eq(r, retraction)) =>
            {
                s
            }
            _ => &retraction.deepest,
        };
        let l0 = &from.levels[0];
        let end = self.continuation(
            &laws,
            l0.mesh.clone(),
            from.d,
            l0.sol.h.clone(),
            if std::ptr::eq(from, retraction.deepest.as_ref()) {
                None
            } else {
                from.tangent.clone()
            },
            None,
            d,
            false,
        )?;
        let mut state = self.coarse_state(d, end, Some(retraction.clone()));
        // The same meshes as the deepest state at every level.
        let n_levels = retraction.laws.len();
        let mut guide = from.clone();
        guide.levels.truncate(n_levels);
        self.refine_fixed(&laws, &mut state, &guide, n_levels)?;
        Ok(state)
    }

    /// Solves levels `1..n_levels` of `state` on `guide`'s meshes.
    fn refine_fixed(
        &self,
        laws: &Laws,
        state: &mut Solved,
        guide: &Solved,
        n_levels: usize,
    ) -> Result<()> {
        let tol = self.options.newton_tolerance;
        for k in 1..n_levels {
            let g = &guide.levels[k];
            let c_new = &state.levels[0];
            let c_old = &guide.levels[0];
            let shape = |x: f64| self.shape.gap(x);
            let guess: Vec<f64> = g
                .mesh
                .rho
                .iter()
                .zip(&g.sol.h)
                .map(|(&r, &h)| {
                    h + c_new.mesh.gap_at(&c_new.sol.h, r, shape)
                        - c_old.mesh.gap_at(&c_old.sol.h, r, shape)
                })
                .collect();
            let law = self.node_law(laws, k);
            let (sol, fa) = g.mesh.newton(
                state.d,
                &guess,
                &g.f,
                &law,
                g.factor.as_deref(),
                tol,
                MAX_NEWTON,
                false,
            )?;
            state.levels.push(Level {
                mesh: g.mesh.clone(),
                f: g.f.clone(),
                sol,
                factor: fa.map(Arc::new).or_else(|| g.factor.clone()),
            });
        }
        let loads: Vec<f64> = state
            .levels
            .iter()
            .map(|l| l.mesh.moment(&l.sol.p))
            .collect();
        let mag = {
            let l = state.levels.last().unwrap();
            let a: Vec<f64> = l.sol.p.iter().map(|x| x.abs()).collect();
            l.mesh.moment(&a).max(1e-300)
        };
        state.converged = extrapolate(&loads).error <= self.options.tolerance * mag;
        Ok(())
    }
}

/// Whether two meshes are the same family level: same length `2^k`-scaled,
/// outer radius and grading.
fn same_mesh(a: &Mesh, b: &Mesh, k: usize) -> bool {
    let n_expected = if k == 0 { b.len() } else { 2 * b.len() - 1 };
    a.len() == n_expected && a.rho_max() == b.rho_max() && a.grading == b.grading
}
