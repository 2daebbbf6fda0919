//! Continuation in the central gap `H_0` (Greenwood 2009: "taking the minimum
//! film thickness as the independent variable"), with a mesh that follows
//! the contact edge, adaptive steps and refinement of the critical points.

use super::newton::{Discretisation, Solution};
use super::{SpherePoint, SphereProblem};
use crate::error::{Error, Result};
use std::sync::Arc;

/// `(9 pi^2/16)^(1/3)`: `alpha/z0 = Dbar * mu * MAUGIS_INTERFERENCE`.
pub(crate) const MAUGIS_INTERFERENCE: f64 = 1.770_682_754_000_227_1;
/// `(3 pi/4)^(1/3)`: `r/(R^2 w/E*)^(1/3) = A * MAUGIS_RADIUS`.
pub(crate) const MAUGIS_RADIUS: f64 = 1.330_670_039_491_468_8;

/// A solved state and the mesh it lives on.
#[derive(Debug, Clone)]
pub(crate) struct State {
    pub disc: Arc<Discretisation>,
    pub sol: Solution,
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

pub(crate) struct Tracer<'a> {
    p: &'a SphereProblem,
    pub meshes_built: usize,
    pub newton_iterations: usize,
}

impl<'a> Tracer<'a> {
    pub fn new(p: &'a SphereProblem) -> Self {
        Tracer {
            p,
            meshes_built: 0,
            newton_iterations: 0,
        }
    }

    fn mesh(&mut self, edge: f64) -> Arc<Discretisation> {
        self.meshes_built += 1;
        Arc::new(Discretisation::new(
            self.p.mesh_spec(edge),
            self.p.mu,
            self.p.shape,
        ))
    }

    fn newton(&mut self, disc: &Discretisation, h0: f64, guess: &[f64]) -> Result<Solution> {
        let o = &self.p.options;
        let s = disc.solve(h0, guess, o.tolerance, o.max_newton_iterations)?;
        self.newton_iterations += s.iterations;
        Ok(s)
    }

    /// Newton from a predictor: more than [`STEP_ITERATIONS`] is a failure.
    fn newton_step(&mut self, disc: &Discretisation, h0: f64, guess: &[f64]) -> Result<Solution> {
        let o = &self.p.options;
        let limit = o.max_newton_iterations.min(STEP_ITERATIONS);
        let s = disc.solve(h0, guess, o.tolerance, limit)?;
        self.newton_iterations += s.iterations;
        Ok(s)
    }

    /// The rigid start at the largest central gap.
    pub fn start(&mut self) -> Result<State> {
        let h0 = self.p.options.start_gap;
        let disc = self.mesh(0.0);
        let guess: Vec<f64> = disc.f.iter().map(|f| h0 + f).collect();
        let sol = self.newton(&disc, h0, &guess)?;
        self.follow_edge(State { disc, sol })
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
            let disc = self.mesh(a);
            let guess = disc.interpolate(&st.disc.r, &st.sol.h);
            match self.newton_step(&disc, st.central_gap(), &guess) {
                Ok(sol) => st = State { disc, sol },
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
        self.follow_edge(State {
            disc: from.disc.clone(),
            sol,
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
    }
}
