//! Continuation in the central gap `H_0` (Greenwood 2009: "taking the minimum
//! film thickness as the independent variable"), with a mesh that follows
//! the contact edge, adaptive steps and refinement of the critical points.
//!
//! Mesh following: near the axis the mesh is rebuilt around the edge as it
//! moves (`O(n^2)` elliptic integrals). Once the edge is beyond
//! [`SCALABLE_EDGE`] cohesive zones, the mesh is a base mesh assembled with
//! spacings `1/SCALE_BAND` finer than asked, viewed at the scale
//! `lambda = a/a_base` that puts its plateau on the edge (`C -> lambda C`, exact,
//! `O(n)`: the compliance entries are updated, not recomputed); it is
//! reassembled only when `lambda` leaves `[1/SCALE_BAND, SCALE_BAND]`, so
//! spacings stay between `1/SCALE_BAND^2` and 1 times the nominal ones. States
//! on one base mesh share its matrix.

use super::disc::{BaseMesh, Discretisation};
use super::newton::{Constraint, Lu, Metric, Solution};
use super::{Shape, SpherePoint, SphereProblem};
use crate::error::{Error, Result};
use std::sync::Arc;

/// Edge radius, in cohesive-zone widths, above which meshes are rescaled
/// rather than rebuilt.
pub(crate) const SCALABLE_EDGE: f64 = 6.0;
/// Largest scale change of a base mesh (and its spacing refinement).
pub(crate) const SCALE_BAND: f64 = 1.2;

/// `(9 pi^2/16)^(1/3)`: `alpha/z0 = Dbar * mu * MAUGIS_INTERFERENCE`.
pub(crate) const MAUGIS_INTERFERENCE: f64 = 1.770_682_754_000_227_1;
/// `(3 pi/4)^(1/3)`: `r/(R^2 w/E*)^(1/3) = A * MAUGIS_RADIUS`.
pub(crate) const MAUGIS_RADIUS: f64 = 1.330_670_039_491_468_8;

/// A solved state and the mesh it lives on.
#[derive(Debug, Clone)]
pub(crate) struct State {
    pub disc: Arc<Discretisation>,
    pub sol: Solution,
    /// Arc length from the start in the step metric `hypot(dP, c dalpha)`.
    pub arc: f64,
}

impl State {
    pub fn central_gap(&self) -> f64 {
        self.sol.h[0]
    }
}

/// A continuation step whose Newton needs more iterations than this is
/// retried smaller: a good predictor converges in 2-5, and a long search may
/// land on a spurious solution of a neighbouring branch.
const STEP_ITERATIONS: usize = 12;

pub(crate) struct Tracer<'a, 'b> {
    p: &'a SphereProblem,
    metric: Metric,
    progress: Option<&'b mut dyn FnMut(&SpherePoint)>,
    pub meshes_built: usize,
    pub newton_iterations: usize,
}

impl<'a, 'b> Tracer<'a, 'b> {
    pub fn new(p: &'a SphereProblem) -> Self {
        let pa = 1.0 / (p.mu * MAUGIS_INTERFERENCE).max(1.0);
        Tracer {
            p,
            metric: Metric {
                gap: 0.0,
                approach: pa,
            },
            progress: None,
            meshes_built: 0,
            newton_iterations: 0,
        }
    }

    pub fn with_progress(mut self, f: Option<&'b mut dyn FnMut(&SpherePoint)>) -> Self {
        self.progress = f;
        self
    }

    fn build(&mut self, edge: f64, refined: bool) -> Arc<Discretisation> {
        self.meshes_built += 1;
        let mut spec = self.p.mesh_spec(edge);
        if refined {
            spec.h0 /= SCALE_BAND;
            spec.growth /= SCALE_BAND;
            spec.r_max *= SCALE_BAND;
        }
        Arc::new(Discretisation::view(
            Arc::new(BaseMesh::new(spec)),
            1.0,
            self.p.mu,
            self.p.shape,
        ))
    }

    /// The mesh for a contact edge at `edge`: `cur` rescaled when the edge is
    /// far enough from the axis and within the scale band, else a new mesh
    /// (with room to move on in the same direction).
    fn mesh_for(&mut self, cur: &Arc<Discretisation>, edge: f64) -> Arc<Discretisation> {
        let big = SCALABLE_EDGE * self.p.zone();
        let scalable = matches!(self.p.shape, Shape::Paraboloid) && edge >= big;
        if !scalable {
            return self.build(edge, false);
        }
        let base_edge = cur.base.spec.edge;
        let lam = edge / base_edge;
        let (mu, shape) = (self.p.mu, self.p.shape);
        if base_edge >= big && (1.0 / SCALE_BAND..=SCALE_BAND).contains(&lam) {
            return Arc::new(Discretisation::view(cur.base.clone(), lam, mu, shape));
        }
        let target = if edge > cur.spec.edge {
            edge * SCALE_BAND
        } else {
            edge / SCALE_BAND
        };
        let base = self.build(target, true).base.clone();
        let lam = edge / base.spec.edge;
        Arc::new(Discretisation::view(base, lam, mu, shape))
    }

    fn solve(
        &mut self,
        disc: &Discretisation,
        h0: f64,
        guess: &[f64],
        limit: usize,
    ) -> Result<Solution> {
        let o = &self.p.options;
        let limit = o.max_newton_iterations.min(limit);
        let con = Constraint::Gap(h0);
        let (s, _lu): (Solution, Lu) =
            disc.solve(guess, &con, self.metric, None, o.tolerance, limit)?;
        self.newton_iterations += s.iterations;
        Ok(s)
    }

    fn newton(&mut self, disc: &Discretisation, h0: f64, guess: &[f64]) -> Result<Solution> {
        self.solve(disc, h0, guess, usize::MAX)
    }

    /// Newton from a predictor: more than [`STEP_ITERATIONS`] is a failure.
    fn newton_step(&mut self, disc: &Discretisation, h0: f64, guess: &[f64]) -> Result<Solution> {
        self.solve(disc, h0, guess, STEP_ITERATIONS)
    }

    /// The rigid start at the largest central gap.
    pub fn start(&mut self) -> Result<State> {
        let h0 = self.p.options.start_gap;
        let disc = self.build(0.0, false);
        let guess: Vec<f64> = disc.f.iter().map(|f| h0 + f).collect();
        let sol = self.newton(&disc, h0, &guess)?;
        self.follow_edge(State {
            disc,
            sol,
            arc: 0.0,
        })
    }

    /// Remesh around the current contact edge when it has left the plateau's
    /// centre by more than half the finest zone.
    fn follow_edge(&mut self, mut st: State) -> Result<State> {
        for _ in 0..4 {
            let spec = st.disc.spec;
            let a = st.sol.radius;
            if (a - spec.edge).abs() <= 0.5 * spec.inner.min(spec.outer) {
                break;
            }
            let disc = self.mesh_for(&st.disc, a);
            let guess = disc.interpolate(&st.disc.r, &st.sol.h);
            match self.newton_step(&disc, st.central_gap(), &guess) {
                Ok(sol) => {
                    st = State {
                        disc,
                        sol,
                        arc: st.arc,
                    }
                }
                // Keep the old mesh: the next step's remesh tries again.
                Err(_) => break,
            }
        }
        Ok(st)
    }

    /// Solve at central gap `h0` starting from `from`; when Newton fails,
    /// get there in two halves (recursively, at most 2^8 sub-steps).
    pub fn goto(&mut self, from: &State, h0: f64) -> Result<State> {
        self.goto_depth(from, h0, 8)
    }

    fn goto_depth(&mut self, from: &State, h0: f64, depth: u32) -> Result<State> {
        match self.goto_once(from, h0) {
            Ok(s) => Ok(s),
            Err(e) if depth == 0 => Err(e),
            Err(_) => {
                let mid = 0.5 * (from.central_gap() + h0);
                let half = self.goto_depth(from, mid, depth - 1)?;
                self.goto_depth(&half, h0, depth - 1)
            }
        }
    }

    /// Solve at central gap `h0` starting from `from` (tangent predictor).
    fn goto_once(&mut self, from: &State, h0: f64) -> Result<State> {
        let dh = h0 - from.central_gap();
        let guess: Vec<f64> = from
            .sol
            .h
            .iter()
            .zip(&from.sol.tangent)
            .map(|(h, t)| (h + t * dh).max(0.5 * h))
            .collect();
        let sol = self.newton_step(&from.disc, h0, &guess)?;
        // arc length by the trapezoid on the speed |d(P, c alpha)/dH_0|
        let speed = |s: &Solution| s.d_load.hypot(s.d_approach * self.metric.approach);
        let arc = from.arc + 0.5 * (speed(&from.sol) + speed(&sol)) * dh.abs();
        self.follow_edge(State {
            disc: from.disc.clone(),
            sol,
            arc,
        })
    }

    /// Trace from the start gap down to the stopping rule (`stop` true).
    pub fn run(&mut self, arc_step: f64, stop: impl Fn(&[State]) -> bool) -> Result<Vec<State>> {
        let mu = self.p.mu;
        let o = self.p.options;
        let mut states = vec![self.start()?];
        let mut prev_dh = f64::INFINITY;
        while !stop(&states) {
            let cur = states.last().unwrap().clone();
            let h0 = cur.central_gap();
            if h0 <= o.min_gap {
                break;
            }
            // interference in Maugis units, or in z0 when that is larger
            // (small mu, where Dbar = alpha/(mu z0 ...) spans hundreds)
            let per_alpha = 1.0 / (mu * MAUGIS_INTERFERENCE).max(1.0);
            let speed = cur.sol.d_load.hypot(cur.sol.d_approach * per_alpha);
            let mut dh = (arc_step / speed.max(1e-300))
                .min(0.1 * h0)
                .min(2.0 * prev_dh)
                .min(h0 - 0.5 * o.min_gap);
            let mut next = None;
            let mut last_err = None;
            for _ in 0..40 {
                match self.goto_once(&cur, h0 - dh) {
                    Ok(s) => {
                        next = Some(s);
                        break;
                    }
                    Err(e) => {
                        last_err = Some(e);
                        dh *= 0.5;
                    }
                }
                if dh < 1e-13 * h0 {
                    break;
                }
            }
            let Some(next) = next else {
                return Err(last_err.unwrap_or(Error::NoConvergence {
                    what: "sphere continuation".into(),
                    iterations: 40,
                    residual: f64::NAN,
                }));
            };
            prev_dh = dh;
            if let Some(f) = self.progress.as_mut() {
                f(&point(mu, &next));
            }
            states.push(next);
        }
        Ok(states)
    }

    /// Root of `g` between two states (`g` of opposite signs), by the
    /// Illinois variant of regula falsi on the central gap.
    pub fn refine(&mut self, a: &State, b: &State, g: impl Fn(&Solution) -> f64) -> Result<State> {
        let (mut xa, mut ga, mut sa) = (a.central_gap(), g(&a.sol), a.clone());
        let (mut xb, mut gb, mut sb) = (b.central_gap(), g(&b.sol), b.clone());
        let tol = 1e-9 * xa.abs().max(xb.abs());
        let mut side = 0i32;
        for _ in 0..60 {
            if (xb - xa).abs() <= tol {
                break;
            }
            let mut x = xb - gb * (xb - xa) / (gb - ga);
            if !(x > xa.min(xb) && x < xa.max(xb)) {
                x = 0.5 * (xa + xb);
            }
            let from = if (x - xa).abs() < (x - xb).abs() {
                &sa
            } else {
                &sb
            };
            let s = self.goto(from, x)?;
            let gx = g(&s.sol);
            if gx == 0.0 {
                return Ok(s);
            }
            if (gx > 0.0) == (gb > 0.0) {
                xb = x;
                gb = gx;
                sb = s;
                if side == 1 {
                    ga *= 0.5;
                }
                side = 1;
            } else {
                xa = x;
                ga = gx;
                sa = s;
                if side == -1 {
                    gb *= 0.5;
                }
                side = -1;
            }
        }
        Ok(if ga.abs() < gb.abs() { sa } else { sb })
    }
}

/// Public view of a state.
pub(crate) fn point(mu: f64, st: &State) -> SpherePoint {
    let s = &st.sol;
    SpherePoint {
        central_gap: s.h[0],
        approach: s.approach,
        load_bar: s.load,
        radius: s.radius,
        interference_bar: s.approach / (mu * MAUGIS_INTERFERENCE),
        radius_bar: s.radius / MAUGIS_RADIUS,
        d_approach: s.d_approach,
        d_load: s.d_load,
        arc: st.arc,
    }
}
