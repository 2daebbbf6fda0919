//! The converged solve of one state: continuation in the central separation
//! on a coarse mesh, the outer radius from the pressure's decay, the
//! grading from the edge zone, nested refinements and Richardson
//! extrapolation with an error estimate.
//!
//! Outer radius: the pressure is negligible (below `1e-16` of its scale,
//! [`LocalLaw::top`]) where the gap exceeds `H_top`, so the mesh ends 10 %
//! beyond the radius `rho*` where the coarse solution's gap crosses
//! `H_top`, and is enlarged during the continuation whenever the last
//! node's gap falls below it. Nothing is cut off that the tolerance can
//! see.
//!
//! Mesh error: the piecewise-linear pressure gives errors
//! `a h^2 + b h^3 + O(h^4)` once the mesh resolves the pressure (the `h^3`
//! from the kernel's logarithm; measured orders 2, then 3, then ~4). On
//! meshes `h`, `h/2`, `h/4`: `R1 = (4 v(h/2) - v(h))/3`,
//! `R2 = (8 R1(h/4) - R1(h/2))/7`. The value is `R2` of the three finest
//! levels and its error estimate half the change of `R2` from the three
//! levels before (so at least four levels; against the independent
//! reference of `tests/rough_sphere.rs` the actual error was at most 0.4 of
//! this estimate in every case of mu in [1e-3, 100], d in [-1, 2]): three
//! levels cannot tell a
//! pre-asymptotic mesh from a converged one (at mu = 100, d = 0.5 on
//! 33/65/129 nodes `R2` was 1.7e-6 off while `|R2 - R1|` read 7e-8; the
//! raw errors there fall as `h^2.5` until the edge zone is resolved).
//! Levels are added until the load's estimate meets the tolerance.

use super::local::{LocalLaw, NodeLaw};
use super::mesh::{Grading, Mesh, MAX_NODES};
use super::newton::{Factor, Solution};
use crate::error::{Allowed, Error, Result};
use std::sync::Arc;

/// Newton iterations per solve before the continuation step is halved.
const MAX_NEWTON: usize = 40;
/// Smallest continuation step (units `sigma`).
const MIN_STEP: f64 = 1e-9;
/// The outer radius is kept while `rho_max/rho*` stays in this band and
/// reset to `RHO_MARGIN rho*` outside it.
const RHO_BAND: (f64, f64) = (1.02, 1.35);
/// Outer radius over `rho*`.
const RHO_MARGIN: f64 = 1.1;
/// A mesh is graded towards the edge when its outer radius exceeds this
/// many edge-zone widths (a uniform mesh would spend most nodes inside the
/// contact, where the pressure is smooth on the scale of the contact).
const GRADE_RATIO: f64 = 40.0;

/// The undeformed shape `f(rho)` in units of `sigma`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// `f = r^2/(2R)`, i.e. `rho^2` (Greenwood & Tripp).
    Paraboloid,
    /// The true sphere `f = R - sqrt(R^2 - r^2)`, i.e.
    /// `2 rho^2/(1 + sqrt(1 - rho^2/rho_e^2))` with the equator at
    /// `rho_e = sqrt(R/(2 sigma))`.
    Sphere {
        /// `rho_e = sqrt(R/(2 sigma))`.
        equator: f64,
    },
}

impl Shape {
    /// `f(rho)/sigma`.
    #[inline]
    pub fn gap(&self, rho: f64) -> f64 {
        match *self {
            Shape::Paraboloid => rho * rho,
            Shape::Sphere { equator } => {
                let x = (rho / equator).min(1.0);
                2.0 * rho * rho / (1.0 + (1.0 - x * x).sqrt())
            }
        }
    }

    /// Largest radius the mesh may reach.
    fn limit(&self) -> f64 {
        match *self {
            Shape::Paraboloid => f64::INFINITY,
            Shape::Sphere { equator } => equator,
        }
    }
}

/// Numerical controls of the rough-sphere solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverOptions {
    /// Relative error asked of the load (the Richardson estimate against
    /// `int |p|`), in `[1e-10, 1e-2]`. Default `1e-6`.
    pub tolerance: f64,
    /// Nodes of the coarsest mesh, in `[9, 257]`. Default 17.
    pub base_nodes: usize,
    /// Most nodes of the finest mesh (the refinement stops there with a
    /// warning), in `[8 base - 7, 2049]`. Default 1025.
    pub max_nodes: usize,
    /// Newton tolerance on the gap residual (units `sigma`). Default `1e-12`.
    pub newton_tolerance: f64,
}

impl Default for SolverOptions {
    fn default() -> Self {
        SolverOptions {
            tolerance: 1e-6,
            base_nodes: 17,
            max_nodes: 1025,
            newton_tolerance: 1e-12,
        }
    }
}

impl SolverOptions {
    /// Checks every field.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming the field.
    pub fn validate(&self) -> Result<()> {
        Allowed::closed(1e-10, 1e-2).check("tolerance", self.tolerance)?;
        Allowed::closed(9.0, 257.0).check("base_nodes", self.base_nodes as f64)?;
        Allowed::closed((8 * self.base_nodes - 7) as f64, MAX_NODES as f64)
            .check("max_nodes", self.max_nodes as f64)?;
        Allowed::closed(1e-15, 1e-6).check("newton_tolerance", self.newton_tolerance)?;
        Ok(())
    }
}

/// A value with its estimated numerical error (same units).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Estimate {
    /// The value.
    pub value: f64,
    /// Estimated absolute error.
    pub error: f64,
}

/// Fewest mesh levels of a state (`h`, `h/2`, `h/4`, `h/8`).
pub(crate) const MIN_LEVELS: usize = 4;

/// Twice-extrapolated value `R2` of the three values on meshes `h, h/2, h/4`.
fn richardson2(a: f64, b: f64, c: f64) -> (f64, f64) {
    let r1a = (4.0 * b - a) / 3.0;
    let r1b = (4.0 * c - b) / 3.0;
    ((8.0 * r1b - r1a) / 7.0, r1b)
}

/// Richardson extrapolation of values on meshes `h, h/2, h/4, ...` (see
/// the module doc): the value is `R2` of the last three, the error
/// estimate half the change of `R2` from the previous three (four levels;
/// `R2` converges at least as `h^3`, so its error is at most a seventh of
/// that change once asymptotic: a margin of 3.5), or `|R2 - R1|` with only
/// three.
pub(crate) fn extrapolate(v: &[f64]) -> Estimate {
    let n = v.len();
    debug_assert!(n >= 3);
    let (r2, r1) = richardson2(v[n - 3], v[n - 2], v[n - 1]);
    let error = if n >= 4 {
        0.5 * (r2 - richardson2(v[n - 4], v[n - 3], v[n - 2]).0).abs()
    } else {
        (r2 - r1).abs()
    };
    Estimate { value: r2, error }
}

/// One mesh level of a solved state.
#[derive(Debug, Clone)]
pub(crate) struct Level {
    pub mesh: Mesh,
    /// Shape at the nodes.
    pub f: Vec<f64>,
    pub sol: Solution,
    pub factor: Option<Arc<Factor>>,
}

/// Per-node retraction laws of every level (the closest gaps of the
/// deepest approach state on the same meshes).
#[derive(Debug)]
pub(crate) struct Retraction {
    /// Central separation of the deepest state.
    pub closest: f64,
    /// Closest gaps per level.
    pub h_min: Vec<Vec<f64>>,
    pub laws: Vec<Vec<NodeLaw>>,
    /// The deepest state (start of every retraction solve).
    pub deepest: Arc<Solved>,
}

/// A converged state.
#[derive(Debug, Clone)]
pub(crate) struct Solved {
    /// Central separation `d` (units `sigma`).
    pub d: f64,
    pub levels: Vec<Level>,
    /// `dH/dd` on the coarse level.
    pub tangent: Option<Vec<f64>>,
    /// Retraction laws, `None` on approach.
    pub retraction: Option<Arc<Retraction>>,
    /// The load's estimate met the tolerance.
    pub converged: bool,
}

/// The dimensionless solver: a local law, a shape, options.
#[derive(Debug, Clone)]
pub(crate) struct Core {
    pub law: Arc<LocalLaw>,
    pub shape: Shape,
    pub options: SolverOptions,
}

/// A continuation's end: the (possibly enlarged) mesh, the solution, its
/// factorisation and its tangent `dH/dd`.
type Continued = (Mesh, Solution, Option<Factor>, Option<Vec<f64>>);

/// Which node laws apply.
enum Laws<'a> {
    Approach,
    Retract(&'a Retraction),
}

impl Core {
    fn node_law<'a>(
        &'a self,
        laws: &'a Laws<'a>,
        level: usize,
    ) -> impl Fn(usize, f64, bool) -> (f64, f64) + Sync + 'a {
        let approach = self.law.approach();
        let top = self.law.top();
        move |i: usize, h: f64, slope: bool| match laws {
            // beyond `top` the pressure is below 1e-16 of its scale
            Laws::Approach if h >= top => (0.0, 0.0),
            Laws::Approach if !slope => (approach.pressure(approach, h), 0.0),
            Laws::Approach => approach.eval(approach, h),
            Laws::Retract(r) => r.laws[level][i].eval(approach, h),
        }
    }

    fn shape_at(&self, mesh: &Mesh) -> Vec<f64> {
        mesh.rho.iter().map(|&r| self.shape.gap(r)).collect()
    }

    /// Interpolates a gap profile onto `mesh`.
    fn onto(&self, from: &Mesh, h: &[f64], mesh: &Mesh) -> Vec<f64> {
        mesh.rho
            .iter()
            .map(|&r| from.gap_at(h, r, |x| self.shape.gap(x)))
            .collect()
    }

    /// Radius where the gap first rises through `top` beyond the pressure's
    /// bulk (the last crossing), by linear interpolation.
    fn rho_star(&self, mesh: &Mesh, h: &[f64]) -> f64 {
        let top = self.law.top();
        let n = h.len();
        for i in (1..n).rev() {
            if h[i - 1] < top && h[i] >= top {
                let t = (top - h[i - 1]) / (h[i] - h[i - 1]);
                return mesh.rho[i - 1] + t * (mesh.rho[i] - mesh.rho[i - 1]);
            }
        }
        if h[0] >= top {
            0.0
        } else {
            mesh.rho_max()
        }
    }

    /// The outer radius for a state whose gap crosses `top` at `rho_star`.
    fn outer_radius(&self, rho_star: f64) -> f64 {
        // At least where the rigid gap from H(0) = top - 1 would reach top:
        // light states keep a mesh of the pressure's own width.
        (RHO_MARGIN * rho_star)
            .max(1.0)
            .min(0.999 * self.shape.limit())
    }

    /// Edge (steepest pressure fall) and edge-zone width `max |p| / max |p'|`.
    fn edge_zone(mesh: &Mesh, p: &[f64]) -> (f64, f64) {
        let pmax = p.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let mut best = (0.0, 0.0);
        for (k, w) in mesh.rho.windows(2).enumerate() {
            let s = ((p[k + 1] - p[k]) / (w[1] - w[0])).abs();
            if s > best.1 {
                best = (0.5 * (w[0] + w[1]), s);
            }
        }
        if best.1 > 0.0 {
            (best.0, pmax / best.1)
        } else {
            (0.0, f64::INFINITY)
        }
    }

    /// The grading for a state on `mesh` with pressures `p`.
    fn grading_for(&self, mesh: &Mesh, p: &[f64], rho_max: f64) -> Grading {
        let (edge, width) = Self::edge_zone(mesh, p);
        if rho_max / width > GRADE_RATIO && edge > 2.0 * width {
            Grading::Edge { edge, width }
        } else {
            Grading::Uniform
        }
    }

    /// Whether `mesh` still suits a state with gap profile `h` (outer
    /// radius in its band, grading still centred on the edge).
    fn mesh_fits(&self, mesh: &Mesh, h: &[f64], p: &[f64]) -> bool {
        let rs = self.rho_star(mesh, h);
        let rm = mesh.rho_max();
        let lo = (RHO_BAND.0 * rs).min(0.999 * self.shape.limit());
        let hi = (RHO_BAND.1 * rs).max(self.outer_radius(rs)) * (1.0 + 1e-12);
        if !(rm >= lo && rm <= hi) {
            return false;
        }
        match (mesh.grading, self.grading_for(mesh, p, rm)) {
            (Grading::Uniform, Grading::Uniform) => true,
            (
                Grading::Edge { edge, width },
                Grading::Edge {
                    edge: e2,
                    width: w2,
                },
            ) => (e2 - edge).abs() < 0.5 * width && w2 > 0.5 * width && w2 < 2.0 * width,
            _ => false,
        }
    }

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
        let mut last: Option<Solution> = None;
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
                    last = Some(sol);
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
                                    "rough-sphere continuation stalled at d = {cur_d} sigma \
                                     on the way to {d} (a fold of the load curve?)"
                                ),
                                iterations,
                                residual,
                            },
                            other => other,
                        });
                    }
                }
            }
            let _ = &last;
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
        let (mesh, sol, fa, tangent) = match start {
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
        let mut state = Solved {
            d,
            levels: vec![Level {
                f: self.shape_at(&mesh),
                mesh,
                sol,
                factor: fa.map(Arc::new),
            }],
            tangent,
            retraction: None,
            converged: false,
        };
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
                let (m, sol, fa, t) =
                    self.continuation(&laws, mesh, d, guess, None, chord, d, false)?;
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
        let (mesh, sol, fa, tangent) = self.continuation(
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
        let mut state = Solved {
            d,
            levels: vec![Level {
                f: self.shape_at(&mesh),
                mesh,
                sol,
                factor: fa.map(Arc::new),
            }],
            tangent,
            retraction: Some(retraction.clone()),
            converged: false,
        };
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
