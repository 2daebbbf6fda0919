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
//! `d_min`, an asperity is on [`AsperityLaw::state_after`](crate::law::AsperityLaw::state_after)`(z - d, z - d_min)`,
//! which gives the adhesive hysteresis of Fuller & Tabor (1975, JKR
//! asperities) and Morrow et al. (2003, Maugis–Dugdale asperities).
//!
//! Two methods: closed forms `c sigma^n F_n((d + onset)/sigma)` when the law
//! is a sum of powers ([`AsperityLaw::power_form`](crate::law::AsperityLaw::power_form): Hertz, DMT) and the
//! distribution has closed-form `F_n`; otherwise adaptive Gauss–Kronrod
//! quadrature in `s`, split at every point where the integrand jumps, with
//! an error estimate measured against `int |integrand|`. Laws smooth in the
//! root of their interference are integrated in `t = sqrt(s - s0)`: at
//! tolerances of 1e-7 and looser by fixed Gauss–Legendre rules over many
//! states at once, each state's estimate from its own nodes (`root_rule`),
//! adaptively otherwise.

use crate::error::{Allowed, Error, Result};
use crate::gw::RoughSurface;
use crate::heights::HeightDistribution;
use crate::law::{Branch, ContactState, LawCursor, LawKernels};
use crate::loading::{History, LoadingModel, MethodUsed, Observables, State, Totals, SLOTS};
use crate::numeric::quadrature::{
    integrate_pieces_batch, kronrod21_batch, kronrod21_pieces, QuadOptions,
};
use curve_fit::{CURVE_FIT_MIN_RTOL, CURVE_FIT_MIN_STATES};
use rayon::prelude::*;
use root_rule::{RootPlan, FIXED_RULE_MIN_RTOL, ROOT_BATCH};
use std::sync::Arc;

mod curve_fit;
mod root_rule;

/// How to integrate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
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

/// Accuracy asked of the integration.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
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
    /// `rel_tol = 1e-8` with [`Method::Auto`].
    pub const DEFAULT: Accuracy = Accuracy {
        rel_tol: 1e-8,
        method: Method::Auto,
        max_intervals: 4000,
    };

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

/// Relative accuracy credited to closed forms: the `F_n` promise (1e-13)
/// times a margin for the handful of products and sums.
const CLOSED_FORM_REL_ERROR: f64 = 1e-12;
/// Tail probability beyond which heights are skipped: below any double.
const SUPPORT_EPS: f64 = 1e-300;
/// Lowest interference of [`GwModel::reachable_interferences`], in
/// standard deviations: laws with a long-range tail contribute nothing
/// measurable from summits further below the flat.
pub const REACH_FLOOR_SIGMAS: f64 = 10.0;
/// Highest summit of [`GwModel::reachable_interferences`], in standard
/// deviations: Gaussian tails underflow f64 near 38.5.
pub const REACH_CEILING_SIGMAS: f64 = 40.0;

/// A rough surface with one asperity law and one height distribution.
///
/// # Examples
/// Hertz summits on Gaussian heights at the mean plane (`d = 0`): the
/// closed forms `P = (4/3) E* sqrt(R) N sigma^(3/2) F_3/2(0)`,
/// `A = pi R sigma N F_1(0)`, `n = N F_0(0) = N/2` with `F_3/2(0) =
/// 0.430020`, `F_1(0) = 1/sqrt(2 pi)` (mpmath): 97.22 mN, 62.67 um^2 and
/// 5000 contacts for the gold switch surface.
/// ```
/// use asperity::prelude::*;
/// use std::sync::Arc;
///
/// let surface = RoughSurface::gold_microswitch(); // 1e4 summits, R 1 um, sigma 5 nm
/// let contact = AsperityContact::gold_microswitch();
/// let hertz = LawKind::Hertz.build(&contact)?;
/// let model = GwModel::new(surface, Arc::new(Gaussian::new()), Arc::from(hertz))?;
/// let s = model.state(0.0, History::Approach, &Observables::ALL)?;
/// assert!((s.load().unwrap() / 0.0972216862214102 - 1.0).abs() < 1e-12);
/// assert!((s.area().unwrap() / 6.26657068657750e-11 - 1.0).abs() < 1e-12);
/// assert!((s.count().unwrap() - 5000.0).abs() < 1e-9);
/// # Ok::<(), asperity::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct GwModel {
    surface: RoughSurface,
    distribution: Arc<dyn HeightDistribution>,
    law: Arc<dyn LawKernels>,
    accuracy: Accuracy,
    /// `distribution.numerical_support(SUPPORT_EPS)`, computed once.
    support: (f64, f64),
}

impl GwModel {
    /// Combines a surface, a standardised height distribution and a law built
    /// for the surface's summit radius, integrated to [`Accuracy::DEFAULT`]
    /// (change it with [`GwModel::with_accuracy`]).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `law` when the law diverges at a finite
    /// interference (rigid Bradley) while heights are unbounded above.
    pub fn new(
        surface: RoughSurface,
        distribution: Arc<dyn HeightDistribution>,
        law: Arc<dyn LawKernels>,
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
        let support = distribution.numerical_support(SUPPORT_EPS);
        Ok(GwModel {
            surface,
            distribution,
            law,
            accuracy: Accuracy::DEFAULT,
            support,
        })
    }

    /// The same model with its law replaced by piecewise Chebyshev tables
    /// ([`crate::law::interpolated::InterpolatedLaw`], relative tolerance
    /// `tol`) over the interferences a program coming as close as
    /// `closest` (m) reaches ([`GwModel::reachable_interferences`]): the
    /// same totals to about `tol`, several times faster for laws that solve
    /// an equation per evaluation (JKR: 4.5x on retraction states).
    ///
    /// Laws that remember their maximum interference (elastic-plastic:
    /// the unloading branch depends on it continuously) are refused: the
    /// tables hold one retraction branch.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `law` for a law that remembers its maximum;
    /// as [`crate::law::interpolated::InterpolatedLaw::new`] (an empty
    /// interval, a bad `tol`).
    pub fn with_tabulated_law(&self, closest: f64, tol: f64) -> Result<Self> {
        if self.law.remembers_maximum() {
            return Err(Error::invalid(
                "law",
                format!(
                    "{} remembers its maximum interference: one retraction table cannot hold it",
                    self.law.name()
                ),
            ));
        }
        let (lo, hi) = self.reachable_interferences(closest);
        let hi = hi.min(0.999 * self.law.max_interference());
        let table = crate::law::interpolated::InterpolatedLaw::new(self.law.clone(), lo, hi, tol)?;
        Ok(GwModel {
            law: Arc::new(table),
            ..self.clone()
        })
    }

    /// The same model integrated to `accuracy`.
    pub fn with_accuracy(mut self, accuracy: Accuracy) -> Self {
        self.accuracy = accuracy;
        self
    }

    /// The surface.
    pub fn surface(&self) -> &RoughSurface {
        &self.surface
    }

    /// The law.
    pub fn law(&self) -> &dyn LawKernels {
        self.law.as_ref()
    }

    /// The height distribution.
    pub fn distribution(&self) -> &dyn HeightDistribution {
        self.distribution.as_ref()
    }

    /// The accuracy asked of the integration.
    pub fn accuracy(&self) -> &Accuracy {
        &self.accuracy
    }

    /// Whether the law and distribution give closed forms for `observables`
    /// (a sum of powers over `F_n` with closed forms: load, area, count and
    /// the observables that are sums of powers of the law's interference,
    /// [`PerAsperity::power_terms`](crate::loading::PerAsperity::power_terms)).
    pub fn has_closed_form(&self, observables: &Observables) -> bool {
        self.law.power_form().is_some_and(|f| {
            let closed = |terms: &[(f64, f64)]| {
                terms
                    .iter()
                    .all(|&(_, n)| self.distribution.closed_form_moment(n))
            };
            closed(&f.load)
                && closed(&f.area)
                && self.distribution.closed_form_moment(0.0)
                && observables
                    .extras()
                    .iter()
                    .all(|e| e.power_terms(&f).is_some_and(|t| closed(&t)))
        })
    }

    /// Default start of a program (m): the separation beyond which the
    /// summits the flat can reach (`z > d + range`, `range` the law's
    /// [`interaction_range`](crate::law::AsperityLaw::interaction_range), its cutoff
    /// for laws whose load vanishes) make up less than `fraction` of all
    /// summits, `sigma q(1 - fraction) - range`, capped at the
    /// [interaction onset](LoadingModel::interaction_onset).
    pub fn start_separation(&self, fraction: f64) -> f64 {
        let s = self.distribution.quantile(1.0 - fraction);
        let top = self.interaction_onset();
        (self.surface.sigma * s - self.law.interaction_range()).min(top)
    }

    /// Interferences (m) the summits reach in a program that comes as close
    /// as `closest` (m): from the law's cutoff (but no lower than
    /// [`REACH_FLOOR_SIGMAS`] `sigma` below contact) up to the highest
    /// represented summit (no higher than [`REACH_CEILING_SIGMAS`] `sigma`)
    /// minus `closest`. A table of the law over this interval serves the
    /// whole program.
    pub fn reachable_interferences(&self, closest: f64) -> (f64, f64) {
        let sigma = self.surface.sigma;
        let (_, s_top) = self.support;
        let lo = self
            .law
            .cutoff_interference()
            .max(-REACH_FLOOR_SIGMAS * sigma);
        let hi = sigma * s_top.min(REACH_CEILING_SIGMAS) - closest;
        (lo, hi)
    }

    /// Closed forms: `eta A_n sum c sigma^n F_n((d + onset)/sigma)` of
    /// every observable's terms (the extra observables' from
    /// [`Observable::power_terms`](crate::loading::Observable::power_terms)).
    fn closed_form(&self, d: f64, observables: &Observables) -> Option<State> {
        if !self.has_closed_form(observables) {
            return None;
        }
        let form = self.law.power_form()?;
        let dist = self.distribution.as_ref();
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
        let mut values = [0.0; SLOTS];
        let mut errors = [0.0; SLOTS];
        if observables.load {
            (values[0], errors[0]) = sum(&form.load);
        }
        if observables.area {
            (values[1], errors[1]) = sum(&form.area);
        }
        let count = n_total * dist.moment_above(0.0, h);
        values[2] = count;
        errors[2] = count * CLOSED_FORM_REL_ERROR;
        for (j, extra) in observables.extras().iter().enumerate() {
            (values[3 + j], errors[3 + j]) = sum(&extra.power_terms(&form)?);
        }
        Some(State {
            separation: d,
            totals: Totals::new(values, errors, observables.mask()),
            method: MethodUsed::ClosedForm,
            evaluations: 0,
        })
    }

    /// Exact totals over a finite sample of standardised heights `s_i`:
    /// `eta A_n (1/n) sum f(sigma s_i - d)`; only summits above the law's
    /// cutoff are visited (the points are sorted). Error: rounding only.
    fn sample_sum(&self, points: &[f64], d: f64, history: History, obs: &Observables) -> State {
        let sigma = self.surface.sigma;
        let law = self.law.as_ref();
        let first = points.partition_point(|&s| sigma * s - d < law.cutoff_interference());
        let mut sum = [0.0; SLOTS];
        for &s in &points[first..] {
            let delta = sigma * s - d;
            let st = match history {
                History::Approach => law.state(delta, Branch::Approach),
                History::Retract { closest } => law.state_after(delta, sigma * s - closest),
            };
            let v = obs.evaluate(&st);
            for k in 0..SLOTS {
                sum[k] += v[k];
            }
        }
        let scale = self.surface.summits() / points.len() as f64;
        let visited = points.len() - first;
        let values = sum.map(|x| scale * x);
        let mut errors = values.map(|x| 4.0 * f64::EPSILON * x.abs() * (visited as f64).sqrt());
        errors[2] = 0.0; // counting is exact
        State {
            separation: d,
            totals: Totals::new(values, errors, obs.mask()),
            method: MethodUsed::SampleSum,
            evaluations: visited,
        }
    }

    /// Adaptive quadrature over standardised heights, split where the
    /// integrand jumps.
    fn quadrature(&self, d: f64, history: History, obs: &Observables) -> Result<State> {
        let sigma = self.surface.sigma;
        let law = self.law.as_ref();
        let dist = self.distribution.as_ref();
        let (s_lo, s_hi, far) = self.height_range(d);
        let mask = obs.mask();
        if !(s_hi > s_lo) {
            return Ok(no_contact(d, mask));
        }
        if far.is_none() && self.root_rule_applies(history) {
            let plan = RootPlan { d, s_lo, s_hi };
            return self
                .root_states_any(&[plan], obs)
                .pop()
                .unwrap_or_else(|| self.quadrature_in_root(d, s_lo, s_hi, obs));
        }
        let points = self.split_points(d, history, s_lo, s_hi);
        let load_only = obs.load_only();
        // Consecutive nodes lie in one quadrature panel: a tabulated law
        // finds its own panel by a short walk from the previous one
        // (`state_near`, the same values as `state`).
        let mut cursor = LawCursor::default();
        let weight = |s: f64| match far {
            Some(r) => dist.pdf_ratio(s, r),
            None => dist.pdf(s),
        };
        let delta_max = |s: f64| match history {
            History::Approach => None,
            History::Retract { closest } => Some(sigma * s - closest),
        };
        let n_total = match far {
            Some(r) => FarTailScale::new(self.surface.summits(), dist.log_pdf(r)),
            None => FarTailScale::new(self.surface.summits(), 0.0),
        };
        // Load alone needs no contact radius (cheaper for tabulated laws),
        // and a one-component integrand spares the rule the four empty
        // slots: every operation on the load is the same, so the same bits.
        // A panel's 21 nodes are evaluated in one call, ascending: one walk
        // through a table's panels, and a tabulated law's sums interleaved
        // (`load_near_batch`, the same values as `load_near`).
        let (value, error, evaluations, method) = if load_only {
            let eval = |x: &[f64; 21], out: &mut [[f64; 1]; 21]| {
                let delta = x.map(|s| sigma * s - d);
                let mut load = [0.0; 21];
                match history {
                    History::Approach => law.load_near_batch(&delta, None, &mut load, &mut cursor),
                    History::Retract { closest } => {
                        let dm = x.map(|s| sigma * s - closest);
                        law.load_near_batch(&delta, Some(&dm), &mut load, &mut cursor)
                    }
                }
                for k in 0..21 {
                    out[k] = [load[k] * weight(x[k])];
                }
            };
            let (v, e, n, m) = self.integrate(eval, &points, d)?;
            let mut value = [0.0; SLOTS];
            let mut error = [0.0; SLOTS];
            (value[0], error[0]) = (v[0], e[0]);
            (value, error, n, m)
        } else {
            // A law that prepares each peak's history (a plastic summit's
            // unloading shape) takes the panel's states in one batch (its
            // roots in vector lanes; the same bits).
            let batch = law.prepares_history();
            let eval = |x: &[f64; 21], out: &mut [[f64; SLOTS]; 21]| {
                if batch {
                    let (load, radius) = panel_states(law, x, sigma, d, history);
                    for k in 0..21 {
                        let st = ContactState {
                            load: load[k],
                            radius: radius[k],
                        };
                        let w = weight(x[k]);
                        out[k] = obs.evaluate(&st).map(|v| v * w);
                    }
                    return;
                }
                for (o, &s) in out.iter_mut().zip(x) {
                    let st = law.state_near(sigma * s - d, delta_max(s), &mut cursor);
                    let w = weight(s);
                    *o = obs.evaluate(&st).map(|x| x * w);
                }
            };
            self.integrate(eval, &points, d)?
        };
        Ok(State {
            separation: d,
            totals: Totals::new(
                value.map(|x| n_total.apply(x)),
                error.map(|x| n_total.apply(x)),
                mask,
            ),
            method,
            evaluations,
        })
    }

    /// The standardised heights `(s_lo, s_hi)` quadrature covers at
    /// separation `d`, and `Some(s_lo)` when the density is factored out
    /// there ([`far_tail_reference`]).
    fn height_range(&self, d: f64) -> (f64, f64, Option<f64>) {
        self.height_ranges().at(d)
    }

    /// [`GwModel::height_range`] with the law's and density's constants
    /// read once, for many separations.
    fn height_ranges(&self) -> HeightRanges<'_> {
        let law = self.law.as_ref();
        HeightRanges {
            sigma: self.surface.sigma,
            cutoff: law.cutoff_interference(),
            max_interference: law.max_interference(),
            support: self.support,
            dist: self.distribution.as_ref(),
        }
    }

    /// Whether the fixed rules in the root ([`root_rule`]) may serve
    /// states asking for `obs`: [`Method::Auto`] at a tolerance of at
    /// least [`FIXED_RULE_MIN_RTOL`], no closed form, no finite sample of
    /// heights, a law smooth in the root of its interference.
    fn fixed_root_rule(&self, obs: &Observables) -> bool {
        self.accuracy.rel_tol >= FIXED_RULE_MIN_RTOL && self.root_rule_serves(obs)
    }

    /// Whether the rules in the root (fixed or adaptive) serve approach
    /// states asking for `obs`: [`Method::Auto`], no closed form, no
    /// finite sample of heights, a law smooth in the root of its
    /// interference.
    fn root_rule_serves(&self, obs: &Observables) -> bool {
        self.accuracy.method == Method::Auto
            && self.law.smooth_in_root()
            && !self.has_closed_form(obs)
            && self.distribution.sample_points().is_none()
    }

    /// For each step, the state at `d` after `history` as
    /// [`LoadingModel::state`] computes it with the fixed rules in the
    /// root, when it does; `None` for every other state. `fixed` is
    /// [`GwModel::fixed_root_rule`] of the observables.
    fn root_plans(&self, steps: &[(f64, History)], fixed: bool) -> Vec<Option<RootPlan>> {
        let ranges = self.height_ranges();
        let applies = [History::Approach, History::Retract { closest: 0.0 }]
            .map(|h| fixed && self.root_rule_applies(h));
        steps
            .iter()
            .map(|&(d, history)| {
                let applies = applies[usize::from(history != History::Approach)];
                if !applies || history.check(d).is_err() {
                    return None;
                }
                let (s_lo, s_hi, far) = ranges.at(d);
                (s_hi > s_lo && far.is_none()).then_some(RootPlan { d, s_lo, s_hi })
            })
            .collect()
    }

    /// The states of `steps` in order: those the fixed rules in the root
    /// serve in one batch, the others one by one.
    fn batch_states(&self, steps: &[(f64, History)], obs: &Observables) -> Vec<Result<State>> {
        let fixed = self.fixed_root_rule(obs);
        let plans = self.root_plans(steps, fixed);
        let batch: Vec<RootPlan> = plans.iter().flatten().copied().collect();
        let mut root = self.root_states(&batch, obs).into_iter();
        steps
            .iter()
            .zip(&plans)
            .map(|(&(d, h), p)| match p.and_then(|_| root.next()) {
                Some(r) => r,
                None => self.state(d, h, obs),
            })
            .collect()
    }

    /// Whether [`GwModel::quadrature_in_root`] serves this state: adaptive
    /// quadrature asked for by [`Method::Auto`], a law smooth in the root
    /// of its interference ([`AsperityLaw::smooth_in_root`](crate::law::AsperityLaw::smooth_in_root)) on its
    /// approach branch (or on retraction when it is
    /// [reversible](AsperityLaw::reversible)).
    fn root_rule_applies(&self, history: History) -> bool {
        self.accuracy.method == Method::Auto
            && self.law.smooth_in_root()
            && (history == History::Approach || self.law.reversible())
    }

    /// The approach totals by adaptive Gauss–Kronrod in `t = sqrt(s - s0)`
    /// (tolerances below [`FIXED_RULE_MIN_RTOL`], and states the fixed
    /// rules of [`root_rule`] could not certify),
    /// `s0 = (d + cutoff)/sigma` the height where contact starts: `ds = 2t
    /// dt`, the interference `sigma t^2 + cutoff` exact (no cancellation),
    /// and every total smooth in `t` between the law's breakpoints, so the
    /// first two panels per piece usually meet the tolerance (the height
    /// integral needs a ladder of panels refined towards the square-root
    /// onset). Heights end at [`HeightDistribution::decay_end`] with a drop
    /// of [`ROOT_RULE_DROP`] (far below any tolerance) or the support.
    fn quadrature_in_root(&self, d: f64, s_lo: f64, s_hi: f64, obs: &Observables) -> Result<State> {
        let sigma = self.surface.sigma;
        let law = self.law.as_ref();
        let dist = self.distribution.as_ref();
        let cutoff = law.cutoff_interference();
        let s0 = (d + cutoff) / sigma;
        let s_top = s_hi.min(dist.decay_end(s_lo, ROOT_RULE_DROP));
        let mask = obs.mask();
        let (t_lo, t_hi) = ((s_lo - s0).max(0.0).sqrt(), (s_top - s0).max(0.0).sqrt());
        if !(t_hi > t_lo) {
            return Ok(no_contact(d, mask));
        }
        let mut points = Vec::with_capacity(16);
        points.extend([t_lo, t_hi]);
        for b in law.breakpoints(Branch::Approach) {
            let t = ((b - cutoff) / sigma).max(0.0).sqrt();
            if t > t_lo && t < t_hi {
                points.push(t);
            }
        }
        points.sort_by(f64::total_cmp);
        points.dedup();
        // Two panels per piece: one K21 panel over a Gaussian's whole
        // range in `t` misses 1e-6 (measured: resistance curve, 7e-2
        // estimated), two meet it with estimates near 1e-8.
        for k in 1..points.len() {
            let mid = 0.5 * (points[k - 1] + points[k]);
            points.push(mid);
        }
        points.sort_by(f64::total_cmp);
        let mut cursor = LawCursor::default();
        let (value, error, evaluations, method) = if obs.load_only() {
            let eval = |t: &[f64; 21], out: &mut [[f64; 1]; 21]| {
                let delta = t.map(|t| sigma * t * t + cutoff);
                let mut load = [0.0; 21];
                law.load_near_batch(&delta, None, &mut load, &mut cursor);
                let mut w = [0.0; 21];
                dist.pdf_batch(&t.map(|t| s0 + t * t), &mut w);
                for k in 0..21 {
                    out[k] = [load[k] * (2.0 * t[k] * w[k])];
                }
            };
            let (v, e, n, m) = self.integrate_checked(eval, &points, d, &[true])?;
            let mut value = [0.0; SLOTS];
            let mut error = [0.0; SLOTS];
            (value[0], error[0]) = (v[0], e[0]);
            (value, error, n, m)
        } else {
            // The panel at once: the law, the density and each observable
            // over all 21 nodes (loops in vector registers).
            let eval = |t: &[f64; 21], out: &mut [[f64; SLOTS]; 21]| {
                let delta = t.map(|t| sigma * t * t + cutoff);
                let (mut load, mut radius, mut w) = ([0.0; 21], [0.0; 21], [0.0; 21]);
                law.state_batch(&delta, None, &mut load, &mut radius);
                dist.pdf_batch(&t.map(|t| s0 + t * t), &mut w);
                for k in 0..21 {
                    w[k] *= 2.0 * t[k];
                }
                obs.evaluate_batch(&load, &radius, &w, out);
            };
            self.integrate_checked(eval, &points, d, &mask)?
        };
        let n_total = self.surface.summits();
        Ok(State {
            separation: d,
            totals: Totals::new(value.map(|x| n_total * x), error.map(|x| n_total * x), mask),
            method,
            evaluations,
        })
    }

    /// One K21 panel per piece of `points` ([`kronrod21_pieces`], only the
    /// `present` components summed); when an estimate misses the
    /// tolerance (against `int |f|`, as the adaptive rule measures it),
    /// the adaptive rule over the same pieces ([`GwModel::integrate`]).
    ///
    /// # Errors
    /// As [`GwModel::integrate`].
    fn integrate_checked<const N: usize, F: FnMut(&[f64; 21], &mut [[f64; N]; 21])>(
        &self,
        mut eval: F,
        points: &[f64],
        d: f64,
        present: &[bool; N],
    ) -> Result<([f64; N], [f64; N], usize, MethodUsed)> {
        let rtol = self.accuracy.rel_tol;
        if rtol < FIRST_PASS_MIN_RTOL {
            return self.integrate(eval, points, d);
        }
        let (value, error, magnitude, n) = kronrod21_pieces(&mut eval, points, present);
        if (0..N).all(|i| error[i] <= rtol * magnitude[i].abs()) {
            return Ok((value, error, n, MethodUsed::Quadrature));
        }
        let (v, e, more, m) = self.integrate(eval, points, d)?;
        Ok((v, e, n + more, m))
    }

    /// The accuracy's rule over the pieces `points`: values, error
    /// estimates, evaluations and the method used.
    ///
    /// # Errors
    /// [`Error::NoConvergence`] when adaptive quadrature misses the
    /// tolerance (at separation `d`, for the message).
    fn integrate<const N: usize, F: FnMut(&[f64; 21], &mut [[f64; N]; 21])>(
        &self,
        eval: F,
        points: &[f64],
        d: f64,
    ) -> Result<([f64; N], [f64; N], usize, MethodUsed)> {
        if let Method::Fixed { panels } = self.accuracy.method {
            let (v, e, n) = fixed_rule(eval, points, panels.max(1));
            return Ok((v, e, n, MethodUsed::Fixed));
        }
        let opts = QuadOptions {
            rel_tol: self.accuracy.rel_tol,
            abs_tol: 0.0,
            max_intervals: self.accuracy.max_intervals,
            relative_to_magnitude: true,
        };
        let q = integrate_pieces_batch(eval, points, &opts);
        if !q.converged {
            let worst = (0..N)
                .map(|i| q.error[i] / q.value[i].abs().max(f64::MIN_POSITIVE))
                .fold(0.0, f64::max);
            return Err(Error::NoConvergence {
                what: format!("GW quadrature of {} at separation {d:e} m", self.law.name()),
                iterations: q.evaluations,
                residual: worst,
            });
        }
        Ok((q.value, q.error, q.evaluations, MethodUsed::Quadrature))
    }

    /// Panel ends in `s`: the range, every law breakpoint (both branches),
    /// the history thresholds, and a geometric ladder from the lower end so
    /// the first panels resolve the bulk of the density.
    fn split_points(&self, d: f64, history: History, s_lo: f64, s_hi: f64) -> Vec<f64> {
        let sigma = self.surface.sigma;
        let law = self.law.as_ref();
        let mut pts = Vec::with_capacity(16);
        pts.extend([s_lo, s_hi]);
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
                // Where summits have just lost contact on retraction.
                for m in law.contact_loss_peaks(d - closest) {
                    add((closest + m) / sigma);
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

/// Fall of `ln phi` (from the start of the integral or the bulk) at which
/// [`GwModel::quadrature_in_root`] stops: the density beyond carries about
/// `exp(-42) = 6e-19` of the totals, times the growth of the law (a Hertz
/// load at 9 sigma against 1 sigma: 27), below the tightest tolerance.
const ROOT_RULE_DROP: f64 = 42.0;

/// Tightest tolerance for which [`GwModel::integrate_checked`] tries one
/// panel per piece before adapting: at 1e-8 the QUADPACK estimates of the
/// first pass missed on a quarter of the resistance curve's states, whose
/// second pass cost more than the first saved (75 against 59 evaluations
/// per state).
const FIRST_PASS_MIN_RTOL: f64 = 1e-7;

/// Density below which quadrature factors the density out of the integrand
/// ([`far_tail_reference`]): far above any value of the central range, so
/// ordinary states are computed exactly as without the factoring.
const FAR_TAIL_PDF: f64 = 1e-250;
/// Fall of `ln phi` from the lower end at which a far-tail integral stops:
/// `exp(-750)` is below the smallest subnormal relative to the first term.
const FAR_TAIL_DROP: f64 = 750.0;

/// `Some(s_lo)` when the density at the integral's lower end `s_lo` is
/// below [`FAR_TAIL_PDF`] in the upper tail (so it is factored out there).
fn far_tail_reference(dist: &dyn HeightDistribution, s_lo: f64) -> Option<f64> {
    let (_, hi) = dist.support();
    let far = s_lo.is_finite()
        && s_lo > 0.0
        && s_lo < hi
        && dist.pdf(s_lo) < FAR_TAIL_PDF
        && dist.log_pdf(s_lo).is_finite();
    far.then_some(s_lo)
}

/// The constants of [`GwModel::height_range`].
struct HeightRanges<'a> {
    sigma: f64,
    cutoff: f64,
    max_interference: f64,
    support: (f64, f64),
    dist: &'a dyn HeightDistribution,
}

/// The state at separation `d` of an empty range of heights: no summit in
/// contact, nothing evaluated.
fn no_contact(d: f64, mask: [bool; SLOTS]) -> State {
    State {
        separation: d,
        totals: Totals::new([0.0; SLOTS], [0.0; SLOTS], mask),
        method: MethodUsed::Quadrature,
        evaluations: 0,
    }
}

impl HeightRanges<'_> {
    /// [`GwModel::height_range`] at `d`.
    fn at(&self, d: f64) -> (f64, f64, Option<f64>) {
        let (sup_lo, sup_hi) = self.support;
        // Below the cutoff every branch gives exactly zero: skip.
        let s_lo = ((d + self.cutoff) / self.sigma).max(sup_lo);
        // Far in the upper tail the density is factored out at `s_lo` (so
        // neither it nor the integral underflows before the end of the
        // result's own range) and the upper end is where the density has
        // fallen by FAR_TAIL_DROP from there, not the fixed support.
        let far = far_tail_reference(self.dist, s_lo);
        let top = match far {
            Some(_) => far_tail_end(self.dist, s_lo),
            None => sup_hi,
        };
        // A rigid law is bounded by its own divergence (checked in `new`).
        let s_hi = top.min((d + self.max_interference) / self.sigma);
        (s_lo, s_hi, far)
    }
}

/// Height above `s_lo` where `ln phi` has fallen by [`FAR_TAIL_DROP`]
/// (steps doubling from `1/(1 + s_lo)`), capped at the support's end.
fn far_tail_end(dist: &dyn HeightDistribution, s_lo: f64) -> f64 {
    let (_, hi) = dist.support();
    let target = dist.log_pdf(s_lo) - FAR_TAIL_DROP;
    let mut step = 1.0 / (1.0 + s_lo);
    let mut s = s_lo + step;
    for _ in 0..64 {
        if s >= hi || !(dist.log_pdf(s) > target) {
            break;
        }
        step *= 2.0;
        s = s_lo + step;
    }
    s.min(hi)
}

/// Multiplies integrals by `N exp(log_scale)` without underflow of the
/// factor before the product: `N x` when `log_scale = 0`.
#[derive(Debug, Clone, Copy)]
struct FarTailScale {
    summits: f64,
    log_scale: f64,
}

impl FarTailScale {
    fn new(summits: f64, log_scale: f64) -> Self {
        FarTailScale { summits, log_scale }
    }

    fn apply(&self, x: f64) -> f64 {
        let nx = self.summits * x;
        if self.log_scale == 0.0 || nx == 0.0 {
            return nx;
        }
        nx.signum() * (nx.abs().ln() + self.log_scale).exp()
    }
}

/// The fixed composite rule: `panels` K21 panels on every piece; returns
/// values, error estimates and evaluations.
fn fixed_rule<const N: usize, F: FnMut(&[f64; 21], &mut [[f64; N]; 21])>(
    mut eval: F,
    points: &[f64],
    panels: usize,
) -> ([f64; N], [f64; N], usize) {
    let (mut value, mut error) = ([0.0; N], [0.0; N]);
    let mut evaluations = 0;
    for w in points.windows(2) {
        let step = (w[1] - w[0]) / panels as f64;
        for k in 0..panels {
            let a = w[0] + step * k as f64;
            let b = if k + 1 == panels { w[1] } else { a + step };
            let (v, e, _) = kronrod21_batch(&mut eval, a, b);
            evaluations += 21;
            for i in 0..N {
                value[i] += v[i];
                error[i] += e[i];
            }
        }
    }
    (value, error, evaluations)
}

impl LoadingModel for GwModel {
    /// Totals at separation `d` (m) after `history`: closed forms where they
    /// exist (and the method allows), an exact sum over a finite sample of
    /// heights, or quadrature.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] for a non-finite separation or a retraction
    /// from a `closest` separation above `d`; [`Error::Invalid`] when
    /// [`Method::ClosedForm`] is asked of a law without one;
    /// [`Error::NoConvergence`] when quadrature cannot meet the tolerance.
    fn state(&self, separation: f64, history: History, observables: &Observables) -> Result<State> {
        history.check(separation)?;
        let closed = match self.accuracy.method {
            Method::Quadrature | Method::Fixed { .. } => None,
            Method::Auto => self.closed_form(separation, observables),
            Method::ClosedForm => {
                Some(self.closed_form(separation, observables).ok_or_else(|| {
                    Error::invalid(
                        "method",
                        format!(
                            "no closed form for law {} on {} heights",
                            self.law.name(),
                            self.distribution.name()
                        ),
                    )
                })?)
            }
        };
        match (
            closed,
            self.distribution.sample_points(),
            self.accuracy.method,
        ) {
            (Some(s), _, _) => Ok(s),
            (None, Some(points), Method::Auto | Method::Quadrature) => {
                Ok(self.sample_sum(points, separation, history, observables))
            }
            _ => self.quadrature(separation, history, observables),
        }
    }

    /// The states of `steps` computed in parallel (rayon): each state is
    /// independent of the others and computed by the same serial code, so
    /// the results are bit-identical for any thread count, in step order.
    ///
    /// # Errors
    /// As [`LoadingModel::state`] (the first failing step's error).
    fn states(&self, steps: &[(f64, History)], observables: &Observables) -> Result<Vec<State>> {
        // States the fixed rules in the root serve go in batches of
        // ROOT_BATCH (each state's bits are those it has alone).
        let fixed = self.fixed_root_rule(observables);
        if steps.len() >= CURVE_FIT_MIN_STATES
            && self.accuracy.rel_tol >= CURVE_FIT_MIN_RTOL
            && self.root_rule_serves(observables)
        {
            // One trip into the pool: the loops inside then run on its
            // threads without handing work across (none with one thread).
            let fitted = if rayon::current_num_threads() > 1 {
                rayon::scope(|_| self.curve_states(steps, observables))
            } else {
                self.curve_states(steps, observables)
            };
            if let Some(result) = fitted {
                return result;
            }
        }
        let results: Vec<Result<State>> = if fixed {
            steps
                .par_chunks(ROOT_BATCH)
                .flat_map_iter(|chunk| self.batch_states(chunk, observables))
                .collect()
        } else {
            steps
                .par_iter()
                .map(|&(d, h)| self.state(d, h, observables))
                .collect()
        };
        // Collected in order first, so the reported error is deterministic.
        results.into_iter().collect()
    }

    /// `sigma s_max - range`, `s_max` the end of the numerical support and
    /// `range` the law's [`interaction_range`](crate::law::AsperityLaw::interaction_range):
    /// beyond it every total is exactly zero (laws whose load vanishes) or
    /// negligible (long-range laws, which are never cut).
    fn interaction_onset(&self) -> f64 {
        let (_, s_hi) = self.support;
        self.surface.sigma * s_hi - self.law.interaction_range()
    }

    /// `rtol sigma`.
    fn separation_tolerance(&self) -> f64 {
        self.accuracy.rel_tol * self.surface.sigma
    }

    /// `sigma`.
    fn height_scale(&self) -> f64 {
        self.surface.sigma
    }

    /// `rtol`: the totals are integrals to this relative tolerance.
    fn load_tolerance(&self) -> f64 {
        self.accuracy.rel_tol
    }

    /// On retraction a summit of height `z` is on its retracting branch
    /// when `z - closest` passed a history breakpoint `h` (the attach
    /// interference), and that branch changes at interferences `b` (its
    /// breakpoints, the detach interference): both edges move with `d`
    /// at different rates, so the gap has a kink where they cross, `d =
    /// closest + h - b` (at lambda 0.3 the attach/detach kink, missed by
    /// an unsplit quadrature by 1.8e-3 at rtol 1e-6).
    fn cycle_kinks(&self, closest: f64) -> Vec<f64> {
        let law = self.law.as_ref();
        let mut h = law.history_breakpoints();
        h.push(law.attach_interference());
        let mut b: Vec<f64> = [Branch::Approach, Branch::Retract]
            .iter()
            .flat_map(|&br| law.breakpoints(br))
            .collect();
        b.extend([law.detach_interference(), law.attach_interference()]);
        let mut out: Vec<f64> = h
            .iter()
            .flat_map(|&h| b.iter().map(move |&b| closest + h - b))
            .filter(|d| d.is_finite())
            .collect();
        out.sort_by(f64::total_cmp);
        out.dedup();
        out
    }
}

/// The states of a quadrature panel's 21 standardised heights `x` at
/// separation `d` (m) in one [`LawKernels::state_batch`] call: `(load,
/// radius)` (N, m), bit for bit the law's `state` / `state_after`.
fn panel_states(
    law: &dyn LawKernels,
    x: &[f64; 21],
    sigma: f64,
    d: f64,
    history: History,
) -> ([f64; 21], [f64; 21]) {
    let delta = x.map(|s| sigma * s - d);
    let (mut load, mut radius) = ([0.0; 21], [0.0; 21]);
    match history {
        History::Approach => law.state_batch(&delta, None, &mut load, &mut radius),
        History::Retract { closest } => {
            let dm = x.map(|s| sigma * s - closest);
            law.state_batch(&delta, Some(&dm), &mut load, &mut radius);
        }
    }
    (load, radius)
}
