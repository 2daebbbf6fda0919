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
//! reference of `tests/it/rough_sphere.rs` the actual error was at most 0.4 of
//! this estimate in every case of mu in [1e-3, 100], d in [-1, 2]): three
//! levels cannot tell a
//! pre-asymptotic mesh from a converged one (at mu = 100, d = 0.5 on
//! 33/65/129 nodes `R2` was 1.7e-6 off while `|R2 - R1|` read 7e-8; the
//! raw errors there fall as `h^2.5` until the edge zone is resolved).
//! Levels are added until the load's estimate meets the tolerance.

use super::local::{LocalLaw, NodeLaw};
use super::mesh::{Grading, Mesh, MAX_NODES};
use super::newton::{Factor, Solution};
use crate::error::{Allowed, Result};
use std::sync::Arc;

/// Newton iterations per solve before the continuation step is halved.
pub(crate) const MAX_NEWTON: usize = 40;
/// Smallest continuation step (units `sigma`).
pub(crate) const MIN_STEP: f64 = 1e-9;
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
    pub(crate) fn limit(&self) -> f64 {
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
    /// [`crate::Error::OutOfRange`] naming the field.
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
pub(crate) type Continued = (Mesh, Solution, Option<Factor>, Option<Vec<f64>>);

/// Which node laws apply.
pub(crate) enum Laws<'a> {
    Approach,
    Retract(&'a Retraction),
}

impl Core {
    pub(crate) fn node_law<'a>(
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

    pub(crate) fn shape_at(&self, mesh: &Mesh) -> Vec<f64> {
        mesh.rho.iter().map(|&r| self.shape.gap(r)).collect()
    }

    /// Interpolates a gap profile onto `mesh`.
    pub(crate) fn onto(&self, from: &Mesh, h: &[f64], mesh: &Mesh) -> Vec<f64> {
        mesh.rho
            .iter()
            .map(|&r| from.gap_at(h, r, |x| self.shape.gap(x)))
            .collect()
    }

    /// Radius where the gap first rises through `top` beyond the pressure's
    /// bulk (the last crossing), by linear interpolation.
    pub(crate) fn rho_star(&self, mesh: &Mesh, h: &[f64]) -> f64 {
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
    pub(crate) fn outer_radius(&self, rho_star: f64) -> f64 {
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
    pub(crate) fn grading_for(&self, mesh: &Mesh, p: &[f64], rho_max: f64) -> Grading {
        let (edge, width) = Self::edge_zone(mesh, p);
        if rho_max / width > GRADE_RATIO && edge > 2.0 * width {
            Grading::Edge { edge, width }
        } else {
            Grading::Uniform
        }
    }

    /// Whether `mesh` still suits a state with gap profile `h` (outer
    /// radius in its band, grading still centred on the edge).
    pub(crate) fn mesh_fits(&self, mesh: &Mesh, h: &[f64], p: &[f64]) -> bool {
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
}
