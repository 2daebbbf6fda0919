//! Continuation along the load–approach curve in one monotone parameter `t`:
//! `t = 3^(1/6) - H_0` before contact (the central gap, Greenwood 2009:
//! "taking the minimum film thickness as the independent variable") and
//! `t = a`, the contact radius, once the central gap is below `3^(1/6)`.
//! The two meet at `t = 0`. The contact radius passes the folds of the
//! approach (jumps), of the load (pull-off) and the near-fold of the central
//! gap (just after contact forms, mu ~ 15-20), so one parameter traces every
//! mu (the role arc length plays in Feng 2000). Tracing starts outside the
//! jump-in ([`SphereProblem::start_gap`]).
//!
//! Mesh following: the mesh is chosen from `t` before solving (the contact
//! radius is prescribed). Near the axis the mesh is rebuilt around the edge
//! when the edge leaves its plateau (`O(n^2)` elliptic integrals). Once the
//! edge is beyond [`SCALABLE_EDGE`] cohesive zones, the mesh is a base mesh
//! assembled with spacings `1/SCALE_BAND` finer than asked, viewed at the
//! scale `lambda = a/a_base` that puts its plateau centre on the edge
//! (`C -> lambda C`, exact, `O(n)`: the compliance entries are updated, not
//! recomputed); it is reassembled only when `lambda` leaves
//! `[1/SCALE_BAND, SCALE_BAND]`, so spacings stay between `1/SCALE_BAND^2`
//! and 1 times the nominal ones. States on one base mesh share its matrix,
//! and the corrector runs chord iterations on the previous point's
//! factorisation when it lives on the same base mesh. Such views move with
//! the edge (`Discretisation::moving`): their tangents are taken along the
//! moving nodes (solver version 5, `newton.rs`), so that `dP/dt` and
//! `dalpha/dt`, whose sign changes locate the pull-off and the jumps, are
//! the derivatives of the curve actually traced. A true sphere's meshes
//! move only while every view stays inside its equator.
//!
//! Predictor: the previous profile and its tangent, moved with the edge
//! (`h(r a_new/a_old)`, exact to first order in `dt`), so that the edge
//! region, narrow at large mu, is not smeared by a fixed-node extrapolation;
//! on moving meshes the gap itself is extrapolated inside the contact (flat
//! on the repulsive wall) and the deformation outside it.

use super::disc::{shape_gap, sphere_edge, BaseMesh, Discretisation};
use super::force_law::GAP_MAX_TENSION;
use super::newton::{Constraint, Lu, Solution};
use super::{SpherePoint, SphereProblem};
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
    /// The continuation parameter `t` (see the module documentation).
    pub param: f64,
    /// Arc length from the start in the step metric `hypot(dP, c dalpha)`.
    pub arc: f64,
}

impl State {
    pub fn central_gap(&self) -> f64 {
        self.sol.h[0]
    }
}

/// A continuation step whose Newton needs more iterations than this is
/// retried smaller: a good predictor converges in 2-5 (chord iterations
/// in up to ~10), and a long search may land on a spurious solution of a
/// neighbouring branch.
const STEP_ITERATIONS: usize = 14;

pub(crate) struct Tracer<'a, 'b> {
    p: &'a SphereProblem,
    /// `c`: `alpha/z0` to the step metric's interference unit.
    per_alpha: f64,
    progress: Option<&'b mut dyn FnMut(&SpherePoint)>,
    /// The last factorisation and the base mesh it belongs to.
    chord: Option<(Arc<BaseMesh>, Lu)>,
    pub meshes_built: usize,
    pub newton_iterations: usize,
    pub factorisations: usize,
}

impl<'a, 'b> Tracer<'a, 'b> {
    pub fn new(p: &'a SphereProblem) -> Self {
        Tracer {
            p,
            per_alpha: 1.0 / (p.mu * MAUGIS_INTERFERENCE).max(1.0),
            progress: None,
            chord: None,
            meshes_built: 0,
            newton_iterations: 0,
            factorisations: 0,
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

    /// The mesh for a contact edge at `edge` (0 before contact): `cur`
    /// itself while the edge stays near its plateau centre; a rescaled view
    /// moving with the edge when the edge is far enough from the axis and
    /// within the scale band; else a new mesh (with room to move on in the
    /// same direction). A true sphere's meshes are rescaled only while they
    /// stay inside its equator `r = R` (every view of the base at most
    /// `sphere_edge`).
    fn mesh_for(&mut self, cur: &Arc<Discretisation>, edge: f64) -> Arc<Discretisation> {
        let big = SCALABLE_EDGE * self.p.zone();
        let r_end = sphere_edge(self.p.shape, self.p.mu);
        let spec = cur.spec;
        let target = if edge > spec.edge {
            edge * SCALE_BAND
        } else {
            edge / SCALE_BAND
        };
        let fits = |r_max: f64| r_max * SCALE_BAND * SCALE_BAND <= r_end;
        let scalable = edge >= big && fits(self.p.mesh_reach(target));
        if !scalable {
            if !cur.moving && (edge - spec.edge).abs() <= 0.5 * spec.inner.min(spec.outer) {
                return cur.clone();
            }
            return self.build(edge, false);
        }
        let base_edge = cur.base.spec.edge;
        let lam = edge / base_edge;
        let (mu, shape) = (self.p.mu, self.p.shape);
        if cur.moving && (1.0 / SCALE_BAND..=SCALE_BAND).contains(&lam) {
            if lam == cur.scale {
                return cur.clone();
            }
            return Arc::new(Discretisation::moving_view(
                cur.base.clone(),
                lam,
                mu,
                shape,
            ));
        }
        let base = self.build(target, true).base.clone();
        let lam = edge / base.spec.edge;
        Arc::new(Discretisation::moving_view(base, lam, mu, shape))
    }

    /// Newton at parameter `t` on `disc` from `guess`.
    fn solve(
        &mut self,
        disc: &Discretisation,
        t: f64,
        guess: &[f64],
        limit: usize,
    ) -> Result<Solution> {
        let o = &self.p.options;
        let limit = o.max_newton_iterations.min(limit);
        let con = if t <= 0.0 {
            Constraint::Gap(GAP_MAX_TENSION - t)
        } else {
            Constraint::radius(&disc.r, t)
        };
        let chord = self
            .chord
            .as_ref()
            .filter(|(b, _)| Arc::ptr_eq(b, &disc.base))
            .map(|(_, lu)| lu);
        let result = disc.solve(guess, &con, chord, o.tolerance, limit);
        let (s, lu) = result?;
        self.newton_iterations += s.iterations;
        self.factorisations += s.factorisations;
        self.chord = Some((disc.base.clone(), lu));
        Ok(s)
    }

    /// The rigid start at the largest central gap.
    pub fn start(&mut self) -> Result<State> {
        let h0 = self.p.start_gap();
        let disc = self.build(0.0, false);
        let guess: Vec<f64> = disc.f.iter().map(|f| h0 + f).collect();
        let t = GAP_MAX_TENSION - h0;
        let sol = self.solve(&disc, t, &guess, usize::MAX)?;
        Ok(State {
            disc,
            sol,
            param: t,
            arc: 0.0,
        })
    }

    /// The predicted gaps at parameter `t` on `disc`, from `from`.
    fn predict(&self, from: &State, disc: &Discretisation, t: f64) -> Vec<f64> {
        let (r, h, tan) = (&from.disc.r, &from.sol.h, &from.sol.tangent);
        let dt = t - from.param;
        let n = r.len();
        if from.param > 0.0 && t > 0.0 {
            // The deformation d = h - f moved with the edge: position r t/t0
            // gets d(r) + dt (d_t + (r/t0) d_r); the rigid shape f, whose
            // curvature mu is large, is added exactly at the new nodes.
            let a0 = from.param;
            let k = t / a0;
            let f = &from.disc.f;
            let d: Vec<f64> = (0..n).map(|i| h[i] - f[i]).collect();
            let q: Vec<f64> = if from.disc.moving {
                // The tangent is along the moving nodes, which become
                // r_i k. Inside the contact h is nearly constant (the
                // repulsive wall), so h + dt h' is right to second order
                // there, whereas d follows -f, which is quadratic in the
                // scale: predicting d would put an error ~ f (dt/a)^2 into
                // the stiff contact (residuals of 1e4 at mu = 100). Outside,
                // d + dt d' with d' = h' - r f'/a.
                let shape = from.disc.shape;
                (0..n)
                    .map(|i| {
                        if r[i] < a0 {
                            h[i] + dt * tan[i] - shape_gap(shape, self.p.mu, r[i] * k)
                        } else {
                            d[i] + dt * (tan[i] - from.disc.shape_scale_rate(i) / a0)
                        }
                    })
                    .collect()
            } else {
                let slope = |i: usize| {
                    let (l, u) = (i.saturating_sub(1), (i + 1).min(n - 1));
                    (d[u] - d[l]) / (r[u] - r[l])
                };
                (0..n)
                    .map(|i| d[i] + dt * (tan[i] + r[i] / a0 * slope(i)))
                    .collect()
            };
            let mut j = 0;
            disc.r
                .iter()
                .zip(&disc.f)
                .map(|(&x, &fx)| {
                    // quadratic in d through the three nearest nodes (exact
                    // inside the contact, where h is nearly flat and d
                    // follows -f: a linear one is off by mu dr^2/8 there, a
                    // large residual at large mu), constant beyond the
                    // last node (rigid)
                    let y = x / k;
                    while j + 2 < n && r[j + 1] < y {
                        j += 1;
                    }
                    if y >= r[n - 1] || n < 3 {
                        let u = ((y - r[j]) / (r[j + 1] - r[j])).min(1.0);
                        return (q[j] + u * (q[j + 1] - q[j]) + fx).max(0.25);
                    }
                    let s = if j == 0 {
                        0
                    } else if j + 2 >= n || y - r[j] < r[j + 1] - y {
                        j - 1
                    } else {
                        j
                    };
                    let (x0, x1, x2) = (r[s], r[s + 1], r[s + 2]);
                    let l0 = (y - x1) * (y - x2) / ((x0 - x1) * (x0 - x2));
                    let l1 = (y - x0) * (y - x2) / ((x1 - x0) * (x1 - x2));
                    let l2 = (y - x0) * (y - x1) / ((x2 - x0) * (x2 - x1));
                    (l0 * q[s] + l1 * q[s + 1] + l2 * q[s + 2] + fx).max(0.25)
                })
                .collect()
        } else {
            // before contact (or across t = 0, where dH/dt is not continuous):
            // fixed nodes, the tangent only before contact
            let step = if from.param <= 0.0 {
                dt.min(-from.param)
            } else {
                0.0
            };
            let q: Vec<f64> = (0..n)
                .map(|i| (h[i] + tan[i] * step).max(0.5 * h[i]))
                .collect();
            disc.interpolate(r, &q)
        }
    }

    /// Solve at parameter `t` from `from`: the mesh for `t`, the predictor,
    /// a Newton limited to [`STEP_ITERATIONS`].
    fn goto_once(&mut self, from: &State, t: f64) -> Result<State> {
        let disc = self.mesh_for(&from.disc, t.max(0.0));
        let guess = self.predict(from, &disc, t);
        let sol = self.solve(&disc, t, &guess, STEP_ITERATIONS)?;
        // arc length by the trapezoid on the speed |d(P, c alpha)/dt|
        let speed = |s: &Solution| s.dt_load.hypot(s.dt_approach * self.per_alpha);
        let arc = from.arc + 0.5 * (speed(&from.sol) + speed(&sol)) * (t - from.param).abs();
        Ok(State {
            disc,
            sol,
            param: t,
            arc,
        })
    }

    /// Solve at parameter `t` starting from `from`; when Newton fails,
    /// get there in two halves (recursively, at most 2^8 sub-steps).
    pub fn goto(&mut self, from: &State, t: f64) -> Result<State> {
        self.goto_depth(from, t, 8)
    }

    fn goto_depth(&mut self, from: &State, t: f64, depth: u32) -> Result<State> {
        match self.goto_once(from, t) {
            Ok(s) => Ok(s),
            Err(e) if depth == 0 => Err(e),
            Err(_) => {
                let mid = 0.5 * (from.param + t);
                let half = self.goto_depth(from, mid, depth - 1)?;
                self.goto_depth(&half, t, depth - 1)
            }
        }
    }

    /// The next parameter value from `cur`: a step of `arc_step` in the
    /// metric `hypot(dP, c dalpha)`, at most doubling the previous step,
    /// at most 10% of the central gap before contact (landing on `t = 0`
    /// exactly when crossing it), after it at most 10% of the radius and
    /// at first a quarter of the cohesive zone.
    fn next_param(&self, cur: &State, arc_step: f64, prev_dt: f64) -> f64 {
        let s = &cur.sol;
        let speed = s.dt_load.hypot(s.dt_approach * self.per_alpha);
        let t = cur.param;
        let mut dt = (arc_step / speed.max(1e-300)).min(2.0 * prev_dt);
        if t < 0.0 {
            let h0 = GAP_MAX_TENSION - t;
            dt = dt.min(0.1 * h0);
            if t + dt > 0.0 {
                dt = -t;
            }
        } else {
            let zone = self.p.zone();
            dt = dt.min(0.1 * t.max(2.5 * zone));
        }
        t + dt
    }

    /// Trace from the start gap until `stop` is true (or the central gap
    /// reaches `min_gap`).
    pub fn run(&mut self, arc_step: f64, stop: impl Fn(&[State]) -> bool) -> Result<Vec<State>> {
        let o = self.p.options;
        let mut states = vec![self.start()?];
        let mut prev_dt = f64::INFINITY;
        while !stop(&states) {
            let cur = states.last().unwrap().clone();
            if cur.central_gap() <= o.min_gap {
                break;
            }
            let mut target = self.next_param(&cur, arc_step, prev_dt);
            let mut next = None;
            let mut last_err = None;
            for _ in 0..40 {
                match self.goto_once(&cur, target) {
                    Ok(s) if s.central_gap() >= 0.5 * o.min_gap => {
                        next = Some(s);
                        break;
                    }
                    Ok(_) => {
                        last_err = None;
                    }
                    Err(e) => last_err = Some(e),
                }
                target = 0.5 * (cur.param + target);
                if (target - cur.param).abs() < 1e-13 * (1.0 + cur.param.abs()) {
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
            prev_dt = next.param - cur.param;
            if let Some(f) = self.progress.as_mut() {
                f(&point(self.p.mu, &next));
            }
            states.push(next);
        }
        Ok(states)
    }

    /// Root of `g` between two states (`g` of opposite signs), by the
    /// Illinois variant of regula falsi on the parameter.
    pub fn refine(&mut self, a: &State, b: &State, g: impl Fn(&Solution) -> f64) -> Result<State> {
        let (mut xa, mut ga, mut sa) = (a.param, g(&a.sol), a.clone());
        let (mut xb, mut gb, mut sb) = (b.param, g(&b.sol), b.clone());
        let tol = 1e-9 * (xa.abs().max(xb.abs()) + 1e-3);
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
