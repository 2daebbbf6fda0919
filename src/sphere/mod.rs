//! The full single-sphere adhesive solver (Greenwood 1997, Feng 2000,
//! Greenwood 2009 appendix 1): an elastic half-space and a rigid paraboloid or
//! true sphere interacting through the Lennard-Jones (Derjaguin 9-3) traction
//! `sigma(h) = (8w/(3 z0)) [(z0/h)^9 - (z0/h)^3]` (Derjaguin approximation).
//!
//! The problem depends only on the Tabor parameter
//! `mu = (R w^2/(E*^2 z0^3))^(1/3)` (and, for a true sphere, on `rho = R/z0`).
//! Internally radii are in `(R^2 w/E*)^(1/3)`, gaps in `z0`, pressures in
//! `(w E*^2/R)^(1/3)` (physics.md); results are also given in Maugis units
//! (`Pbar = P/(pi w R)`, `Dbar = delta/(pi^2 w^2 R/K^2)^(1/3)`,
//! `A = a/(pi w R^2/K)^(1/3)`, `K = 4E*/3`) to compare with [`crate::law`].
//!
//! Method: piecewise-linear pressure on a radial mesh graded towards the
//! contact edge ([`mesh`]), the compliance matrix of
//! [`compliance`] (elliptic integrals with the log singularity treated
//! exactly), Newton–Raphson on the gaps at a prescribed central gap `H(0)`
//! before contact and a prescribed contact radius after it (`newton`), and
//! continuation in that parameter (`trace`) so that the whole S-shaped
//! load–approach curve, unstable parts included, is traced. The mesh follows
//! the edge (rebuilt near the axis, rescaled further out).
//!
//! ```
//! use asperity::sphere::{Shape, SolverOptions, SphereProblem};
//! let p = SphereProblem::new(1.0, Shape::Paraboloid, SolverOptions::coarse())?;
//! let facts = p.facts()?;
//! // Between JKR (-1.5) and DMT/Bradley (-2) in units of pi w R.
//! assert!(facts.pull_off.load_bar < -1.5 && facts.pull_off.load_bar > -2.0);
//! # Ok::<(), asperity::Error>(())
//! ```

pub mod calibrate;
pub mod compliance;
mod disc;
pub mod force_law;
pub mod mesh;
mod newton;
mod quadrature;
mod trace;

pub use calibrate::Calibration;

use crate::error::{positive, Allowed, Error, Result};
use mesh::MeshSpec;
use serde::{Deserialize, Serialize};
use trace::{point, State, Tracer, MAUGIS_INTERFERENCE, MAUGIS_RADIUS};

/// Bump when a change alters solver results: calibrations cached on disk are
/// keyed by it.
pub const SOLVER_VERSION: u32 = 5;

/// Smallest Tabor parameter accepted (the rigid Bradley limit is within
/// 0.01% there).
pub const MIN_TABOR: f64 = 0.005;

/// Largest Tabor parameter accepted. Since solver version 5 (tangents
/// along the meshes that move with the contact edge, start outside the
/// jump-in) mu = 10-100 traces in about 0.3-1.2 s at the default resolution
/// and converges toward JKR: at mu = 100 pull-off -1.50044, jump-out load
/// -0.83347 and interference -0.90881, zero-load radius 1.81712 (JKR -1.5,
/// -5/6, -0.90856, 6^(1/3) = 1.81712), each within 2e-4 of resolution 2
/// (docs/performance.md, tests/it/sphere_large_mu.rs). Versions 1-4 stopped at
/// 10: the jump-out drifted from JKR above mu ~ 20 and mu = 50-100 gave
/// wrong pull-offs.
pub const MAX_TABOR: f64 = 100.0;

/// `H(0) = JUMP_IN_START mu^(3/7)`: the smallest central gap where tracing
/// starts ([`SphereProblem::start_gap`]).
const JUMP_IN_START: f64 = 2.2;

/// Smallest size ratio `rho = R/z0` accepted for the true sphere.
pub const MIN_SIZE_RATIO: f64 = 10.0;

/// Above mu = 10 the true sphere needs `rho >= SIZE_RATIO_PER_TABOR mu`:
/// the contact radius is then at most `2.4 sqrt(mu/rho) R ~ 0.24 R` at the
/// zero-load radius (in units of `R`, the solver radius `a` is
/// `a sqrt(mu/rho)`), where the Derjaguin approximation holds, and the
/// meshes stay inside the equator so that they can move with the edge
/// (`rho = 100 mu` traces in ~1 s; smaller `rho` falls back to meshes rebuilt
/// as the edge moves, 50-100 s at mu = 100 with contacts wider than `R`).
/// mu <= 10 keeps [`MIN_SIZE_RATIO`].
pub const SIZE_RATIO_PER_TABOR: f64 = 100.0;

/// Coarsest mesh resolution accepted. Coarser meshes do not resolve the
/// contact edge: at 0.2 the mu = 1 jump-out load is 72% off and at 0.05 the
/// pull-off is -3.23 (beyond Bradley's -2); at 0.5 (`SolverOptions::coarse`)
/// the pull-off is within 1.5e-3 of the converged value for mu in
/// [0.1, 5] (docs/performance.md, mesh convergence).
pub const MIN_RESOLUTION: f64 = 0.5;

/// Finest mesh resolution accepted (spacings 1/64 of the default).
pub const MAX_RESOLUTION: f64 = 64.0;

/// Largest mesh accepted, checked before anything is allocated: one
/// compliance matrix is `8 n^2` bytes (128 MiB here) and each Newton
/// factorisation `O(n^3)`.
pub const MAX_NODES: usize = 4096;

/// The undeformed shape of the rigid body.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub enum Shape {
    /// `f(r) = r^2/(2R)` (Hertz).
    Paraboloid,
    /// True sphere `f(r) = R - sqrt(R^2 - r^2)`, integrated out to `r = R`,
    /// with size ratio `rho = R/z0 >= 10` (Greenwood 2009).
    Sphere {
        /// `rho = R/z0`.
        rho: f64,
    },
}

/// Numerical controls; [`Default`] meets the accuracy targets of
/// docs/performance.md (pull-off converged to < 1e-3).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct SolverOptions {
    /// Mesh resolution multiplier (> 0): spacing at the edge and grading
    /// scale as `1/resolution`. Default 1.
    pub resolution: f64,
    /// Rigid gap (units `z0`) at the outer mesh radius; the force beyond is
    /// added in closed form. Default 60.
    pub far_gap: f64,
    /// Central gap `H(0)/z0` where tracing starts (far apart). Default 6.
    /// Raised to [`SphereProblem::start_gap`] `= 2.2 mu^(3/7)` when that is
    /// larger (mu > 10 at the default), so that the trace starts on the
    /// stable approach branch, before the jump-in.
    pub start_gap: f64,
    /// Tracing stops once the load exceeds this, in units of `pi w R`. Default 2.
    pub max_load_bar: f64,
    /// Step along the curve, `hypot(dPbar, dD)` with `D` the interference
    /// in Maugis units (`Dbar`) or, when `mu (9 pi^2/16)^(1/3) < 1` (small mu,
    /// where `Dbar` spans hundreds), in units of `z0`. Default 0.02.
    pub arc_step: f64,
    /// Smallest central gap `H(0)/z0` traced. Default 0.3.
    pub min_gap: f64,
    /// Newton tolerance on the gap residual (units `z0`). Default 1e-10.
    pub tolerance: f64,
    /// Newton iterations before a step is retried smaller. Default 30.
    pub max_newton_iterations: usize,
}

impl Default for SolverOptions {
    fn default() -> Self {
        SolverOptions {
            resolution: 1.0,
            far_gap: 60.0,
            start_gap: 6.0,
            max_load_bar: 2.0,
            arc_step: 0.02,
            min_gap: 0.3,
            tolerance: 1e-10,
            max_newton_iterations: 30,
        }
    }
}

impl SolverOptions {
    /// A coarse, fast setting for tests and examples (~1% accuracy).
    pub fn coarse() -> Self {
        SolverOptions {
            resolution: 0.5,
            far_gap: 30.0,
            arc_step: 0.1,
            ..Self::default()
        }
    }

    fn validate(&self) -> Result<()> {
        positive("resolution", self.resolution)?;
        Allowed::closed(MIN_RESOLUTION, MAX_RESOLUTION).check("resolution", self.resolution)?;
        Allowed::open(2.0, 1e6).check("far_gap", self.far_gap)?;
        Allowed::open(1.3, 1e3).check("start_gap", self.start_gap)?;
        positive("max_load_bar", self.max_load_bar)?;
        positive("arc_step", self.arc_step)?;
        Allowed::open(0.05, 1.0).check("min_gap", self.min_gap)?;
        Allowed::open(0.0, 1e-3).check("tolerance", self.tolerance)?;
        if self.max_newton_iterations == 0 {
            return Err(Error::invalid("max_newton_iterations", "must be >= 1"));
        }
        Ok(())
    }
}

/// One point of the load–approach curve.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SpherePoint {
    /// Central gap `H(0)/z0` (the continuation parameter before contact;
    /// after it, the contact radius is).
    pub central_gap: f64,
    /// Approach (interference) `alpha/z0`; 0 when the rigid sphere's apex
    /// is at `z0` from the undeformed half-space.
    pub approach: f64,
    /// Load `P/(pi w R)`, > 0 compressive.
    pub load_bar: f64,
    /// Contact radius (radius of maximum tension) in `(R^2 w/E*)^(1/3)`.
    pub radius: f64,
    /// Interference in Maugis units `Dbar = alpha/(pi^2 w^2 R/K^2)^(1/3)`
    /// `= (alpha/z0) / (mu (9 pi^2/16)^(1/3))`.
    pub interference_bar: f64,
    /// Contact radius in Maugis units `A = a/(pi w R^2/K)^(1/3)`.
    pub radius_bar: f64,
    /// `d(alpha/z0)/dH(0)` along the curve (large where `H(0)` nearly
    /// folds).
    pub d_approach: f64,
    /// `d(P/(pi w R))/dH(0)` along the curve.
    pub d_load: f64,
    /// Arc length from the start of the trace, `int hypot(dPbar, c dalpha)`
    /// (`c` converts `alpha/z0` to Maugis units when mu is large), trapezoidal
    /// between traced points.
    pub arc: f64,
}

impl SpherePoint {
    /// The point as an instability in Maugis units (load, interference,
    /// contact radius), without the solver's own coordinates.
    pub fn bar(&self) -> crate::law::InstabilityBar {
        crate::law::InstabilityBar {
            load_bar: self.load_bar,
            interference_bar: self.interference_bar,
            radius_bar: self.radius_bar,
        }
    }
}

/// The derived facts of one solver curve.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SphereFacts {
    /// Pull-off under load control: the minimum load (the traced point
    /// there, refined to where `dP/dt` changes sign).
    pub pull_off: SpherePoint,
    /// Jump-out under displacement control (local minimum of the approach
    /// along the curve); `None` when the curve has no S (small mu).
    pub jump_out: Option<SpherePoint>,
    /// Jump-in on approach (local maximum of the approach); `None` without S.
    pub jump_in: Option<SpherePoint>,
    /// Contact radius `A` at zero load on the contact branch.
    pub zero_load_radius_bar: Option<f64>,
    /// Mesh nodes at the pull-off.
    pub nodes: usize,
}

/// Gap and pressure profiles at one central gap.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Profile {
    /// Radii in `(R^2 w/E*)^(1/3)`.
    pub radius: Vec<f64>,
    /// Gaps `h/z0`.
    pub gap: Vec<f64>,
    /// Pressures `p/(w E*^2/R)^(1/3)` (> 0 compressive).
    pub pressure: Vec<f64>,
    /// The curve point.
    pub point: SpherePoint,
}

/// Estimated size and cost of one solve ([`SphereProblem::cost`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CostEstimate {
    /// Mesh nodes.
    pub nodes: usize,
    /// Peak memory, bytes.
    pub memory_bytes: f64,
    /// Wall-clock time of `facts()` in an optimised build, seconds.
    pub seconds: f64,
}

/// A single-sphere problem: Tabor parameter, shape and numerical options.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SphereProblem {
    mu: f64,
    shape: Shape,
    options: SolverOptions,
}

impl SphereProblem {
    /// A problem with Tabor parameter `mu` in `[0.005, 100]`
    /// ([`MIN_TABOR`], [`MAX_TABOR`]) and a shape (true sphere:
    /// `rho >= 10`, and `rho >= 100 mu` when mu > 10,
    /// [`SphereProblem::min_size_ratio`]).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `mu`, `rho` or the bad option.
    pub fn new(mu: f64, shape: Shape, options: SolverOptions) -> Result<Self> {
        positive("mu", mu)?;
        Allowed::closed(MIN_TABOR, MAX_TABOR).check("mu", mu)?;
        if let Shape::Sphere { rho } = shape {
            Allowed::closed(Self::min_size_ratio(mu), 1e12).check("rho", rho)?;
        }
        options.validate()?;
        let p = SphereProblem { mu, shape, options };
        let cost = p.cost();
        if cost.nodes > MAX_NODES {
            return Err(Error::invalid(
                "resolution",
                format!(
                    "{} gives a mesh of about {} nodes at mu = {mu} (~{:.0} MiB, ~{:.0} s); \
                     at most {MAX_NODES} nodes are allowed",
                    options.resolution,
                    cost.nodes,
                    cost.memory_bytes / 1048576.0,
                    cost.seconds
                ),
            ));
        }
        Ok(p)
    }

    /// Smallest size ratio `rho = R/z0` accepted for a true sphere at
    /// Tabor parameter `mu`: [`MIN_SIZE_RATIO`] up to mu = 10,
    /// [`SIZE_RATIO_PER_TABOR`]` mu` above.
    pub fn min_size_ratio(mu: f64) -> f64 {
        if mu > 10.0 {
            SIZE_RATIO_PER_TABOR * mu
        } else {
            MIN_SIZE_RATIO
        }
    }

    /// Estimated size and cost of [`facts`](Self::facts), computed without
    /// building anything: the node count of the mesh at a contact edge of
    /// JKR's zero-load radius (or at the axis, whichever is larger), memory
    /// `8 n^2 (2 + 32)` bytes (the Jacobian, its LU and up to 32 live
    /// compliance matrices: the trace keeps one per scale band of the edge,
    /// ~30 at mu = 100), and time `1e-5 n^2 (1 + n/500) (1 + mu)^0.15` s in
    /// an optimised build (solver version 5; an upper bound of the measured
    /// 0.02 s, 0.3 s, 0.4 s, 1.2 s at mu = 1, 5, 10, 100 at the default
    /// resolution, 21 s at mu = 100, resolution 4, 18 s and 113 s at
    /// mu = 10 and 30, resolution 8, on a loaded 2-core machine;
    /// docs/performance.md). The work per traced point is mostly `O(n^2)`
    /// (residuals, Jacobian fill, compliance assembly), the `O(n^3)` LU
    /// taking over above ~500 nodes. Debug builds are 10-30x slower.
    pub fn cost(&self) -> CostEstimate {
        let edge = 1.82 * MAUGIS_RADIUS;
        let n = self
            .mesh_spec(edge)
            .node_count()
            .max(self.mesh_spec(0.0).node_count());
        let nf = n as f64;
        CostEstimate {
            nodes: n,
            memory_bytes: 8.0 * nf * nf * 34.0,
            seconds: 1e-5 * nf * nf * (1.0 + nf / 500.0) * (1.0 + self.mu).powf(0.15),
        }
    }

    /// Central gap `H(0)/z0` where tracing starts: the option `start_gap`,
    /// raised to `2.2 mu^(3/7)` when that is larger. The jump-in on approach
    /// happens at `H(0) = 1.69 mu^(3/7)` (measured 2.70, 4.53, 7.26, 12.16 at
    /// mu = 3, 10, 30, 100, solver version 5; the exponent follows from the
    /// centre deflection under the far-field attraction,
    /// `2 mu^2 int sigma_hat ds ~ mu^(3/2) H^(-5/2)`, whose slope reaches 1
    /// there), so the start stays 1.3x outside it; a start inside it traces
    /// the curve from its unstable part and misses the jump-in (the default 6
    /// did so above mu ~ 15).
    pub fn start_gap(&self) -> f64 {
        self.options
            .start_gap
            .max(JUMP_IN_START * self.mu.powf(3.0 / 7.0))
    }

    /// Tabor parameter.
    pub fn mu(&self) -> f64 {
        self.mu
    }

    /// Shape.
    pub fn shape(&self) -> Shape {
        self.shape
    }

    /// Options.
    pub fn options(&self) -> &SolverOptions {
        &self.options
    }

    /// Width of the cohesive zone at the edge in solver radius units:
    /// the Dugdale estimate `(pi/4) E* w/sigma0^2 = 0.75 mu^-2`, capped by the
    /// rigid (Bradley) scale `sqrt(2/mu)` at small mu.
    pub(crate) fn zone(&self) -> f64 {
        (0.75 / (self.mu * self.mu)).min((2.0 / self.mu).sqrt())
    }

    /// Node density multiplier on top of `resolution`: 2 where the zone is
    /// the rigid scale `sqrt(2/mu)` (mu < ~0.83), 1 otherwise. At resolution
    /// 1 with density 1 the mu = 0.005 pull-off was -2.000034, beyond
    /// Bradley's -2 (converged -1.99964), and the mu = 0.5 zero-load radius
    /// 0.56% small; the error falls as the spacing squared, so density 2 gives
    /// 6e-5 and 0.13% (tests/it/sphere_convergence.rs) for 2x the nodes, which
    /// costs little at small mu.
    pub(crate) fn density(&self) -> f64 {
        let mu = self.mu;
        if 0.75 / (mu * mu) > (2.0 / mu).sqrt() {
            2.0
        } else {
            1.0
        }
    }

    /// Outer mesh radius for a contact edge at `edge` before the true
    /// sphere's equator caps it: where the rigid gap is `far_gap`, or
    /// `1.5 edge + 4 zone` when that is further.
    pub(crate) fn mesh_reach(&self, edge: f64) -> f64 {
        let r_far = (2.0 * self.options.far_gap / self.mu).sqrt();
        r_far.max(1.5 * edge + 4.0 * self.zone())
    }

    pub(crate) fn mesh_spec(&self, edge: f64) -> MeshSpec {
        let zone = self.zone();
        let res = self.options.resolution * self.density();
        let r_max = self
            .mesh_reach(edge)
            .min(disc::sphere_edge(self.shape, self.mu));
        MeshSpec {
            edge,
            h0: zone / (8.0 * res),
            growth: 0.12 / res,
            inner: 2.0 * zone,
            outer: 3.0 * zone,
            r_max,
        }
    }

    /// The whole load–approach curve from far apart (`start_gap`) until the
    /// load exceeds `max_load_bar`, unstable parts included, in the order
    /// traced (increasing `arc` and contact radius; `H(0)` decreases on
    /// every curve traced so far, nearly folding at mu ~ 15-20).
    ///
    /// # Errors
    /// [`Error::NoConvergence`] when Newton fails even with tiny steps.
    pub fn trace(&self) -> Result<Vec<SpherePoint>> {
        self.trace_with_progress(None)
    }

    /// [`trace`](Self::trace), calling `progress` with every new point.
    ///
    /// # Errors
    /// As [`trace`](Self::trace).
    pub fn trace_with_progress(
        &self,
        progress: Option<&mut dyn FnMut(&SpherePoint)>,
    ) -> Result<Vec<SpherePoint>> {
        let max = self.options.max_load_bar;
        let mut tr = Tracer::new(self).with_progress(progress);
        let st = tr.run(self.options.arc_step, |s| s.last().unwrap().sol.load >= max)?;
        Ok(st.iter().map(|s| point(self.mu, s)).collect())
    }

    /// Pull-off, jump-out, jump-in and zero-load radius, each refined to
    /// Newton accuracy on a coarse trace that stops once the load is
    /// compressive again.
    ///
    /// # Errors
    /// [`Error::NoConvergence`] when Newton fails.
    pub fn facts(&self) -> Result<SphereFacts> {
        self.facts_with_progress(None)
    }

    /// [`facts`](Self::facts), calling `progress` with every traced point.
    ///
    /// # Errors
    /// As [`facts`](Self::facts).
    pub fn facts_with_progress(
        &self,
        progress: Option<&mut dyn FnMut(&SpherePoint)>,
    ) -> Result<SphereFacts> {
        let mut tr = Tracer::new(self).with_progress(progress);
        let step = (4.0 * self.options.arc_step).max(0.05);
        let st = tr.run(step, |s| {
            let last = &s.last().unwrap().sol;
            last.load > 0.05 && last.radius > 0.0 && last.dt_load > 0.0
        })?;
        let crit = |s: &State| point(self.mu, s);
        // Pull-off: dP/dt from < 0 to >= 0 along the curve; keep the lowest.
        let mut pull: Option<State> = None;
        for w in st.windows(2) {
            if w[0].sol.dt_load < 0.0 && w[1].sol.dt_load >= 0.0 {
                let s = tr.refine(&w[0], &w[1], |x| x.dt_load)?;
                if pull.as_ref().is_none_or(|p| s.sol.load < p.sol.load) {
                    pull = Some(s);
                }
            }
        }
        let pull = match pull {
            Some(p) => p,
            None => st
                .iter()
                .min_by(|a, b| a.sol.load.total_cmp(&b.sol.load))
                .unwrap()
                .clone(),
        };
        // Jump-in: a local maximum of the approach along the curve; jump-out:
        // the local minimum after it.
        let mut jump_in = None;
        let mut jump_out = None;
        for w in st.windows(2) {
            let (a, b) = (w[0].sol.dt_approach, w[1].sol.dt_approach);
            if a > 0.0 && b <= 0.0 && jump_in.is_none() {
                jump_in = Some(tr.refine(&w[0], &w[1], |x| x.dt_approach)?);
            } else if a < 0.0 && b >= 0.0 {
                jump_out = Some(tr.refine(&w[0], &w[1], |x| x.dt_approach)?);
            }
        }
        let mut zero = None;
        for w in st.windows(2).rev() {
            if w[0].sol.load < 0.0 && w[1].sol.load >= 0.0 {
                zero = Some(tr.refine(&w[0], &w[1], |x| x.load)?);
                break;
            }
        }
        Ok(SphereFacts {
            pull_off: crit(&pull),
            jump_out: jump_out.as_ref().map(crit),
            jump_in: jump_in.as_ref().map(crit),
            zero_load_radius_bar: zero.map(|z| z.sol.radius / MAUGIS_RADIUS),
            nodes: pull.disc.len(),
        })
    }

    /// Load-controlled pull-off `P/(pi w R)` (see [`facts`](Self::facts)).
    ///
    /// # Errors
    /// As [`facts`](Self::facts).
    pub fn pull_off(&self) -> Result<SpherePoint> {
        Ok(self.facts()?.pull_off)
    }

    /// Gap and pressure profiles at central gap `central_gap` (units `z0`),
    /// reached by continuation from far apart (the first point of the curve
    /// with that central gap).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] for a gap outside `(min_gap, start_gap]`
    /// ([`start_gap`](Self::start_gap));
    /// [`Error::NoConvergence`].
    pub fn profile(&self, central_gap: f64) -> Result<Profile> {
        let o = self.options;
        Allowed {
            lo: o.min_gap,
            lo_inclusive: false,
            hi: self.start_gap(),
            hi_inclusive: true,
        }
        .check("central_gap", central_gap)?;
        let mut tr = Tracer::new(self);
        let st = tr.run(o.arc_step, |s| {
            s.last().unwrap().central_gap() <= central_gap
        })?;
        let n = st.len();
        let s = if n >= 2 {
            tr.refine(&st[n - 2], &st[n - 1], |x| x.h[0] - central_gap)?
        } else {
            st[0].clone()
        };
        Ok(Profile {
            radius: s.disc.r.clone(),
            gap: s.sol.h.clone(),
            pressure: s.disc.pressure(&s.sol.h),
            point: point(self.mu, &s),
        })
    }
}

/// Converts `alpha/z0` to Maugis' `Dbar` at Tabor parameter `mu`.
pub fn interference_bar_from_approach(mu: f64, approach: f64) -> f64 {
    approach / (mu * MAUGIS_INTERFERENCE)
}

#[cfg(test)]
mod tests;
