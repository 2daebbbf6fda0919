//! One asperity law integrated over one summit-height distribution.
//!
//! With summit heights `z = sigma s` (`s` standardised, density `phi`), a flat
//! at separation `d` from the reference plane, and interference
//! `delta = z - d`, the totals are (Greenwood & Williamson 1966):
//!
//! ```text
//! load  P(d) = eta A_n int P_law(sigma s - d) phi(s) ds        (N)
//! area  A(d) = eta A_n int pi a(sigma s - d)^2 phi(s) ds       (m^2)
//! count n(d) = eta A_n int [a(sigma s - d) > 0] phi(s) ds      (-)
//! ```
//!
//! Each asperity's branch follows the loading history: on approach every
//! asperity is on its approach branch; on retraction after the flat came to
//! `d_min`, an asperity is on [`AsperityLaw::state_after`]`(z - d, z - d_min)`,
//! which gives the adhesive hysteresis of Fuller & Tabor (1975, JKR
//! asperities) and Morrow et al. (2003, Maugis–Dugdale asperities).
//!
//! Two methods: closed forms `c sigma^n F_n((d + onset)/sigma)` when the law
//! is a sum of powers ([`AsperityLaw::power_form`]: Hertz, DMT) and the
//! distribution has closed-form `F_n`; otherwise adaptive Gauss–Kronrod
//! quadrature in `s`, split at every point where the integrand jumps, with
//! an error estimate measured against `int |integrand|`.

use crate::error::{finite, Allowed, Error, Result};
use crate::gw::RoughSurface;
use crate::heights::HeightDistribution;
use crate::law::{AsperityLaw, Branch, ContactState};
use crate::numeric::quadrature::{integrate_pieces_n, kronrod21_n, QuadOptions};
use std::sync::Arc;

/// Which totals to compute; the others are skipped (reported as `None`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Outputs {
    /// Total load (N).
    pub load: bool,
    /// Real contact area (m^2).
    pub area: bool,
    /// Number of contacts.
    pub count: bool,
}

impl Outputs {
    /// Load, area and count.
    pub const ALL: Outputs = Outputs {
        load: true,
        area: true,
        count: true,
    };
    /// Load only.
    pub const LOAD: Outputs = Outputs {
        load: true,
        area: false,
        count: false,
    };

    fn mask(&self) -> [f64; 3] {
        [
            f64::from(u8::from(self.load)),
            f64::from(u8::from(self.area)),
            f64::from(u8::from(self.count)),
        ]
    }
}

/// Where in the loading program the flat is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum History {
    /// Approaching from far away: every asperity on its approach branch.
    Approach,
    /// Retracting after the flat came as close as `closest` (m).
    Retract {
        /// Closest separation reached (m).
        closest: f64,
    },
}

/// How to integrate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Closed forms where they exist, adaptive quadrature otherwise.
    Auto,
    /// Closed forms only; an error when the law or distribution has none.
    ClosedForm,
    /// Adaptive quadrature always (for checks and the accuracy report).
    Quadrature,
    /// A fixed rule, no adaptivity: every piece between breakpoints split
    /// into `panels` equal panels of the 21-point Kronrod rule. Cost is
    /// known in advance; the error estimate is reported, not enforced.
    Fixed {
        /// Panels per piece, >= 1.
        panels: usize,
    },
}

/// Which method served a result.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MethodUsed {
    /// `F_n` closed forms.
    ClosedForm,
    /// Adaptive Gauss–Kronrod quadrature.
    Quadrature,
    /// A fixed composite Kronrod rule.
    Fixed,
    /// An exact average over a finite sample of heights (measured summits).
    SampleSum,
}

/// Accuracy asked of the integration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Accuracy {
    /// Relative tolerance, in `[1e-13, 0.1]`, measured against the integral
    /// of the magnitude of each integrand.
    pub rel_tol: f64,
    /// Method choice.
    pub method: Method,
    /// Most quadrature subintervals per state before failing.
    pub max_intervals: usize,
}

impl Accuracy {
    /// Tolerance `rel_tol` with [`Method::Auto`].
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `rel_tol` outside `[1e-13, 0.1]`.
    pub fn new(rel_tol: f64) -> Result<Self> {
        Allowed::closed(1e-13, 0.1).check("rel_tol", rel_tol)?;
        Ok(Accuracy {
            rel_tol,
            method: Method::Auto,
            max_intervals: 4000,
        })
    }

    /// The same tolerance with another method.
    pub fn with_method(mut self, method: Method) -> Self {
        self.method = method;
        self
    }
}

/// Totals at one separation. Outputs not asked for are `None`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GwState {
    /// Separation `d` of the flat from the reference plane (m).
    pub separation: f64,
    /// Total load (N), > 0 compressive.
    pub load: Option<f64>,
    /// Real contact area (m^2).
    pub area: Option<f64>,
    /// Expected number of contacts.
    pub count: Option<f64>,
    /// Estimated absolute errors of (load, area, count), same units.
    pub error: [f64; 3],
    /// Method that produced the numbers.
    pub method: MethodUsed,
    /// Law evaluations spent (0 for closed forms).
    pub evaluations: usize,
}

/// Relative accuracy credited to closed forms: the `F_n` promise (1e-13)
/// times a margin for the handful of products and sums.
const CLOSED_FORM_REL_ERROR: f64 = 1e-12;
/// Tail probability beyond which heights are skipped: below any double.
const SUPPORT_EPS: f64 = 1e-300;

/// A rough surface with one asperity law and one height distribution.
#[derive(Debug, Clone)]
pub struct GwModel {
    surface: RoughSurface,
    distribution: Arc<dyn HeightDistribution>,
    law: Arc<dyn AsperityLaw>,
}

impl GwModel {
    /// Combines a surface, a standardised height distribution and a law built
    /// for the surface's summit radius.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `law` when the law diverges at a finite
    /// interference (rigid Bradley) while heights are unbounded above.
    pub fn new(
        surface: RoughSurface,
        distribution: Arc<dyn HeightDistribution>,
        law: Arc<dyn AsperityLaw>,
    ) -> Result<Self> {
        let (_, hi) = distribution.support();
        if law.max_interference().is_finite() && !hi.is_finite() {
            return Err(Error::invalid(
                "law",
                format!(
                    "{} diverges at a finite interference; it needs heights bounded above \
                     (e.g. a truncated Gaussian), not {}",
                    law.name(),
                    distribution.name()
                ),
            ));
        }
        Ok(GwModel {
            surface,
            distribution,
            law,
        })
    }

    /// The surface.
    pub fn surface(&self) -> &RoughSurface {
        &self.surface
    }

    /// The law.
    pub fn law(&self) -> &dyn AsperityLaw {
        self.law.as_ref()
    }

    /// The height distribution.
    pub fn distribution(&self) -> &dyn HeightDistribution {
        self.distribution.as_ref()
    }

    /// Largest separation (m) at which any asperity within the numerical
    /// support feels the flat: `sigma s_max - cutoff`. Beyond it every total
    /// is exactly zero.
    pub fn interaction_onset(&self) -> f64 {
        let (_, s_hi) = self.distribution.numerical_support(SUPPORT_EPS);
        self.surface.sigma * s_hi - self.law.cutoff_interference()
    }

    /// Load, area and count at separation `d` (m) after `history`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] for a non-finite separation or a retraction
    /// from a `closest` separation above `d`; [`Error::Invalid`] when
    /// [`Method::ClosedForm`] is asked of a law without one;
    /// [`Error::NoConvergence`] when quadrature cannot meet the tolerance.
    pub fn state(
        &self,
        separation: f64,
        history: History,
        outputs: Outputs,
        accuracy: &Accuracy,
    ) -> Result<GwState> {
        finite("separation", separation)?;
        if let History::Retract { closest } = history {
            finite("closest_separation", closest)?;
            if closest > separation {
                return Err(Error::OutOfRange {
                    name: "separation".into(),
                    value: separation,
                    allowed: Allowed::closed(closest, f64::INFINITY),
                });
            }
        }
        let closed = match accuracy.method {
            Method::Quadrature | Method::Fixed { .. } => None,
            Method::Auto => self.closed_form(separation, outputs),
            Method::ClosedForm => Some(self.closed_form(separation, outputs).ok_or_else(|| {
                Error::invalid(
                    "method",
                    format!(
                        "no closed form for law {} on {} heights",
                        self.law.name(),
                        self.distribution.name()
                    ),
                )
            })?),
        };
        match (closed, self.distribution.sample_points(), accuracy.method) {
            (Some(s), _, _) => Ok(s),
            (None, Some(points), Method::Auto | Method::Quadrature) => {
                Ok(self.sample_sum(points, separation, history, outputs))
            }
            _ => self.quadrature(separation, history, outputs, accuracy),
        }
    }

    /// Closed forms: `eta A_n sum c sigma^n F_n((d + onset)/sigma)`.
    fn closed_form(&self, d: f64, outputs: Outputs) -> Option<GwState> {
        let form = self.law.power_form()?;
        let dist = self.distribution.as_ref();
        let all_closed = form
            .load
            .iter()
            .chain(form.area.iter())
            .all(|&(_, n)| dist.closed_form_moment(n))
            && dist.closed_form_moment(0.0);
        if !all_closed {
            return None;
        }
        let sigma = self.surface.sigma;
        let h = (d + form.onset) / sigma;
        let n_total = self.surface.summits();
        let sum = |terms: &[(f64, f64)]| {
            let (mut v, mut mag) = (0.0, 0.0);
            for &(c, n) in terms {
                let t = c * sigma.powf(n) * dist.moment_above(n, h);
                v += t;
                mag += t.abs();
            }
            (n_total * v, n_total * mag * CLOSED_FORM_REL_ERROR)
        };
        let (load, load_err) = if outputs.load {
            sum(&form.load)
        } else {
            (0.0, 0.0)
        };
        let (area, area_err) = if outputs.area {
            sum(&form.area)
        } else {
            (0.0, 0.0)
        };
        let count = n_total * dist.moment_above(0.0, h);
        Some(GwState {
            separation: d,
            load: outputs.load.then_some(load),
            area: outputs.area.then_some(area),
            count: outputs.count.then_some(count),
            error: [load_err, area_err, count * CLOSED_FORM_REL_ERROR],
            method: MethodUsed::ClosedForm,
            evaluations: 0,
        })
    }

    /// Exact totals over a finite sample of standardised heights `s_i`:
    /// `eta A_n (1/n) sum f(sigma s_i - d)`; only summits above the law's
    /// cutoff are visited (the points are sorted). Error: rounding only.
    fn sample_sum(&self, points: &[f64], d: f64, history: History, outputs: Outputs) -> GwState {
        let sigma = self.surface.sigma;
        let law = self.law.as_ref();
        let first = points.partition_point(|&s| sigma * s - d < law.cutoff_interference());
        let (mut load, mut area, mut count) = (0.0, 0.0, 0.0);
        for &s in &points[first..] {
            let delta = sigma * s - d;
            let st = match history {
                History::Approach => law.state(delta, Branch::Approach),
                History::Retract { closest } => law.state_after(delta, sigma * s - closest),
            };
            load += st.load;
            area += st.area();
            count += if st.in_contact() { 1.0 } else { 0.0 };
        }
        let scale = self.surface.summits() / points.len() as f64;
        let visited = points.len() - first;
        let rounding = |x: f64| 4.0 * f64::EPSILON * x.abs() * (visited as f64).sqrt();
        GwState {
            separation: d,
            load: outputs.load.then_some(scale * load),
            area: outputs.area.then_some(scale * area),
            count: outputs.count.then_some(scale * count),
            error: [rounding(scale * load), rounding(scale * area), 0.0],
            method: MethodUsed::SampleSum,
            evaluations: visited,
        }
    }

    /// Adaptive quadrature over standardised heights, split where the
    /// integrand jumps.
    fn quadrature(
        &self,
        d: f64,
        history: History,
        outputs: Outputs,
        accuracy: &Accuracy,
    ) -> Result<GwState> {
        let sigma = self.surface.sigma;
        let law = self.law.as_ref();
        let dist = self.distribution.as_ref();
        let (sup_lo, sup_hi) = dist.numerical_support(SUPPORT_EPS);
        // Below the cutoff every branch gives exactly zero: skip.
        let s_lo = ((d + law.cutoff_interference()) / sigma).max(sup_lo);
        // A rigid law is bounded by its own divergence (checked in `new`).
        let s_hi = sup_hi.min((d + law.max_interference()) / sigma);
        let mask = outputs.mask();
        let empty = GwState {
            separation: d,
            load: outputs.load.then_some(0.0),
            area: outputs.area.then_some(0.0),
            count: outputs.count.then_some(0.0),
            error: [0.0; 3],
            method: MethodUsed::Quadrature,
            evaluations: 0,
        };
        if !(s_hi > s_lo) {
            return Ok(empty);
        }
        let points = self.split_points(d, history, s_lo, s_hi);
        // Load alone needs no contact radius: cheaper for tabulated laws.
        let load_only = mask[1] == 0.0 && mask[2] == 0.0;
        let eval = |s: f64| -> [f64; 3] {
            let delta = sigma * s - d;
            if load_only {
                let p = match history {
                    History::Approach => law.load(delta, Branch::Approach),
                    History::Retract { closest } => law.load_after(delta, sigma * s - closest),
                };
                return [p * dist.pdf(s), 0.0, 0.0];
            }
            let st: ContactState = match history {
                History::Approach => law.state(delta, Branch::Approach),
                History::Retract { closest } => law.state_after(delta, sigma * s - closest),
            };
            let w = dist.pdf(s);
            let contact = if st.radius > 0.0 { 1.0 } else { 0.0 };
            [
                mask[0] * st.load * w,
                mask[1] * st.area() * w,
                mask[2] * contact * w,
            ]
        };
        let opts = QuadOptions {
            rel_tol: accuracy.rel_tol,
            abs_tol: 0.0,
            max_intervals: accuracy.max_intervals,
            relative_to_magnitude: true,
        };
        if let Method::Fixed { panels } = accuracy.method {
            return Ok(self.fixed_rule(d, outputs, eval, &points, panels.max(1)));
        }
        let q = integrate_pieces_n(eval, &points, &opts);
        if !q.converged {
            let worst = (0..3)
                .map(|i| q.error[i] / q.value[i].abs().max(f64::MIN_POSITIVE))
                .fold(0.0, f64::max);
            return Err(Error::NoConvergence {
                what: format!("GW quadrature of {} at separation {d:e} m", law.name()),
                iterations: q.evaluations,
                residual: worst,
            });
        }
        let n_total = self.surface.summits();
        Ok(GwState {
            separation: d,
            load: outputs.load.then_some(n_total * q.value[0]),
            area: outputs.area.then_some(n_total * q.value[1]),
            count: outputs.count.then_some(n_total * q.value[2]),
            error: [
                n_total * q.error[0],
                n_total * q.error[1],
                n_total * q.error[2],
            ],
            method: MethodUsed::Quadrature,
            evaluations: q.evaluations,
        })
    }

    /// The fixed composite rule: `panels` K21 panels on every piece.
    fn fixed_rule<F: FnMut(f64) -> [f64; 3]>(
        &self,
        d: f64,
        outputs: Outputs,
        mut eval: F,
        points: &[f64],
        panels: usize,
    ) -> GwState {
        let (mut value, mut error) = ([0.0; 3], [0.0; 3]);
        let mut evaluations = 0;
        for w in points.windows(2) {
            let step = (w[1] - w[0]) / panels as f64;
            for k in 0..panels {
                let a = w[0] + step * k as f64;
                let b = if k + 1 == panels { w[1] } else { a + step };
                let (v, e, _) = kronrod21_n(&mut eval, a, b);
                evaluations += 21;
                for i in 0..3 {
                    value[i] += v[i];
                    error[i] += e[i];
                }
            }
        }
        let n_total = self.surface.summits();
        GwState {
            separation: d,
            load: outputs.load.then_some(n_total * value[0]),
            area: outputs.area.then_some(n_total * value[1]),
            count: outputs.count.then_some(n_total * value[2]),
            error: error.map(|e| n_total * e),
            method: MethodUsed::Fixed,
            evaluations,
        }
    }

    /// Panel ends in `s`: the range, every law breakpoint (both branches),
    /// the history thresholds, and a geometric ladder from the lower end so
    /// the first panels resolve the bulk of the density.
    fn split_points(&self, d: f64, history: History, s_lo: f64, s_hi: f64) -> Vec<f64> {
        let sigma = self.surface.sigma;
        let law = self.law.as_ref();
        let mut pts = vec![s_lo, s_hi];
        let mut add = |s: f64| {
            if s > s_lo && s < s_hi {
                pts.push(s);
            }
        };
        match history {
            History::Approach => {
                for b in law.breakpoints(Branch::Approach) {
                    add((d + b) / sigma);
                }
            }
            History::Retract { closest } => {
                for br in [Branch::Approach, Branch::Retract] {
                    for b in law.breakpoints(br) {
                        add((d + b) / sigma);
                    }
                }
                for b in law.history_breakpoints() {
                    add((closest + b) / sigma);
                }
            }
        }
        for step in [0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0] {
            add(s_lo + step);
        }
        pts.sort_by(f64::total_cmp);
        pts.dedup();
        pts
    }
}
