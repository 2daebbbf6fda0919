//! The local pressure of the rough surface at a gap, in Greenwood–Tripp
//! units: the Greenwood–Williamson load per unit nominal area of a
//! [`GwModel`] at separation `sigma H`, divided by the pressure unit
//! `E* sqrt(sigma/(8R))` of the sphere.
//!
//! Two forms, both with the exact derivative Newton needs:
//! - closed: a law that is a sum of powers ([`PowerForm`](crate::law::PowerForm):
//!   Hertz, DMT) on heights with closed `F_n`:
//!   `p(H) = sum_k c_k F_(n_k)(H + onset/sigma)`, `p'(H) = -sum_k c_k n_k F_(n_k - 1)`
//!   (`-c_k phi` for `n_k = 0`), Greenwood & Williamson (1966);
//! - tabulated: any other law or distribution, piecewise Chebyshev in `H`
//!   ([`Table`]) from the model's own states (adaptive quadrature).
//!
//! On retraction a summit remembers its largest interference, so the local
//! pressure at a radius depends on the closest gap `H_min` reached there
//! ([`History::Retract`] with `closest = sigma H_min`). Laws that remember
//! their maximum interference (plastic) use one two-dimensional table
//! `p(H, H_min)` ([`RetractTable`]) over the closest gaps of a retraction,
//! built when it starts ([`LocalLaw::prepare_retraction`]) and read by
//! every node ([`LocalLaw::after`]); other laws with hysteresis (JKR) one
//! table per node; laws without hysteresis reuse the approach law.

use super::retract_table::{RetractTable, Weights};
use super::shared_heights::SharedHeights;
use super::table::Table;
use crate::error::{Error, Result};
use crate::gw::{Accuracy, GwModel};
use crate::loading::{History, LoadingModel, Observables};
use std::sync::{Arc, Mutex};

/// Tolerance of the tables relative to the solver's: 10 % of it (the local
/// law's error then adds at most 10 % to the load's), within
/// [`TABLE_TOL_RANGE`]. On the plastic bump at rtol 1e-6 (tables at 1e-7)
/// the outputs are within 1.5e-10 of those with tables at 1e-9 (the pull-off
/// separation, a flat minimum's argument, within 6.9e-7), for 0.75x the CPU
/// time of tables at 1e-8.
const TABLE_TOL_FRACTION: f64 = 0.1;
/// Bounds of the tables' relative tolerance (against `|p| + 1e-4 |p(0)|`).
const TABLE_TOL_RANGE: (f64, f64) = (1e-11, 1e-7);
/// The model's quadrature is asked this much better than the tables, so
/// that panels are not split chasing its noise.
const QUAD_MARGIN: f64 = 0.01;
/// Absolute floor of the retraction table's tolerance, as a fraction of
/// the pressure scale: `tol (|p| + RETRACT_FLOOR scale)` (the solver's
/// load tolerance is relative to `int |p|`; adhesive retraction pressures
/// cross zero, where a purely relative demand would chase quadrature noise).
const RETRACT_FLOOR: f64 = 1e-2;
/// The model's quadrature on retraction is asked this fraction of the
/// table's tolerance: its noise is then 1 % of what the tables may err
/// (at 1e-1 the Kogut–Etsion bump's tables chased it: 591 tables instead
/// of 105; 1e-2 gave the pull-off of 1e-4 to 1e-13 and cost about 20 % less).
const RETRACT_QUAD: f64 = 1e-2;
/// Relative tolerance of the law's own Chebyshev tables used while
/// tabulating the local pressure.
const LAW_TABLE_TOL: f64 = 1e-12;
/// `|p|` below this fraction of the pressure scale counts as none: the
/// outer mesh radius is where the gap reaches [`LocalLaw::top`].
pub(crate) const NEGLIGIBLE: f64 = 1e-16;
/// Tables start this many height units below the lowest summit the
/// distribution represents (`1e-16` of the probability).
const BELOW_LOWEST: f64 = 4.0;

#[derive(Debug, Clone)]
enum Form {
    Closed {
        /// The model, for its distribution's `F_n`.
        model: GwModel,
        /// `(c_k, n_k)` in pressure units.
        terms: Vec<(f64, f64)>,
        /// `onset/sigma`.
        shift: f64,
    },
    Table(Arc<Table>),
    /// A radius's slice of the retraction table.
    Retract(Weights),
    /// No pressure at any gap (a node that never came close).
    Zero,
}

/// `p(H)` and `p'(H)` of one node (or of every node on approach).
#[derive(Debug, Clone)]
pub(crate) struct NodeLaw {
    form: Form,
    /// Below this gap the node is closer than ever before: the approach
    /// law applies (`-inf` on approach).
    below: f64,
}

/// The local law of one [`GwModel`] in Greenwood–Tripp units.
#[derive(Debug, Clone)]
pub(crate) struct LocalLaw {
    model: GwModel,
    approach: NodeLaw,
    /// Pressure unit (Pa).
    unit: f64,
    /// Summit-height scale `sigma` (m).
    sigma: f64,
    /// Gap above which `|p| < NEGLIGIBLE * scale`.
    top: f64,
    /// Lowest gap the law is defined at (`-inf` for closed forms).
    bottom: f64,
    /// Pressure scale: `max(|p(0)|, |p(bottom)|)`-like, for tolerances.
    scale: f64,
    reversible: bool,
    /// Relative tolerance of the tables.
    table_tol: f64,
    /// The retraction table (laws with history), shared by clones.
    retract: Arc<Mutex<Option<Arc<RetractTable>>>>,
}

impl NodeLaw {
    /// `p` alone (closed forms skip the slope's `F_n`).
    #[inline]
    fn pressure_form(form: &Form, h: f64) -> f64 {
        match form {
            Form::Closed {
                model,
                terms,
                shift,
            } => {
                let dist = model.distribution();
                terms
                    .iter()
                    .map(|&(c, n)| c * dist.moment_above(n, h + shift))
                    .sum()
            }
            _ => Self::eval_form(form, h).0,
        }
    }

    /// `(p, dp/dH)`.
    #[inline]
    fn eval_form(form: &Form, h: f64) -> (f64, f64) {
        match form {
            Form::Closed {
                model,
                terms,
                shift,
            } => {
                let dist = model.distribution();
                let x = h + shift;
                let (mut p, mut dp) = (0.0, 0.0);
                for &(c, n) in terms {
                    p += c * dist.moment_above(n, x);
                    dp -= c * if n == 0.0 {
                        dist.pdf(x)
                    } else {
                        n * dist.moment_above(n - 1.0, x)
                    };
                }
                (p, dp)
            }
            Form::Table(t) => {
                let (lo, hi) = t.range();
                if h >= hi {
                    (0.0, 0.0)
                } else if h < lo {
                    // extrapolated linearly (callers warn: below the table)
                    let (v, d) = t.eval(lo);
                    (v + d * (h - lo), d)
                } else {
                    t.eval(h)
                }
            }
            Form::Retract(w) => w.eval(h),
            Form::Zero => (0.0, 0.0),
        }
    }
}

/// The approach law of a model in closed form: `p = sum_i c_i eta sigma^n_i
/// F_(n_i - 1)(h - shift)` in units of `unit` (Pa).
fn closed_approach(model: &GwModel, unit: f64) -> NodeLaw {
    let surface = model.surface();
    let sigma = surface.sigma;
    let form = model
        .law()
        .power_form()
        .expect("a closed form has a power form");
    let eta = surface.density;
    let terms = form
        .load
        .iter()
        .map(|&(c, n)| (eta * c * sigma.powf(n) / unit, n))
        .collect();
    NodeLaw {
        form: Form::Closed {
            model: model.clone(),
            terms,
            shift: form.onset / sigma,
        },
        below: f64::NEG_INFINITY,
    }
}

/// The approach law as a Chebyshev table of `model`'s pressure (times
/// `per_area`) over gaps from `lo` to the interaction onset (at most 40
/// sigma), to the tolerance `table_tol`.
///
/// # Errors
/// [`Error::Invalid`] naming `law` when the interaction range leaves no
/// gap to tabulate; the model's failures.
fn tabulated_approach(model: &GwModel, lo: f64, per_area: f64, table_tol: f64) -> Result<NodeLaw> {
    let sigma = model.surface().sigma;
    let hi = (model.interaction_onset() / sigma).min(40.0);
    if !(hi > lo) {
        return Err(Error::invalid(
            "law",
            "its interaction range leaves no gap to tabulate",
        ));
    }
    let eval = |xs: &[f64]| -> Result<Vec<f64>> {
        use rayon::prelude::*;
        xs.par_iter()
            .map(|&h| {
                let s = model.state(sigma * h, History::Approach, &Observables::LOAD)?;
                Ok(s.load().unwrap_or(0.0) * per_area)
            })
            .collect()
    };
    let p0 = eval(&[0.0, lo])?;
    let scale = 1e-4 * p0[0].abs().max(1e-300);
    let t = Table::build(lo, hi, &[], table_tol, scale, &eval)?;
    Ok(NodeLaw {
        form: Form::Table(Arc::new(t)),
        below: f64::NEG_INFINITY,
    })
}

impl LocalLaw {
    /// The local law of `model` with pressure unit `unit` (Pa).
    ///
    /// # Errors
    /// The model's quadrature failures while tabulating.
    pub fn new(model: &GwModel, unit: f64, tolerance: f64) -> Result<Self> {
        let table_tol =
            (TABLE_TOL_FRACTION * tolerance).clamp(TABLE_TOL_RANGE.0, TABLE_TOL_RANGE.1);
        let surface = model.surface();
        let sigma = surface.sigma;
        let per_area = 1.0 / (surface.nominal_area * unit);
        let law = model.law();
        let dist = model.distribution();
        let reversible = law.reversible();
        let closed = model.has_closed_form(&Observables::LOAD)
            && reversible
            && law.power_form().is_some_and(|f| {
                f.load
                    .iter()
                    .all(|&(_, n)| n == 0.0 || (n >= 1.0 && dist.closed_form_moment(n - 1.0)))
            });
        let (dlo, _) = dist.numerical_support(1e-16);
        let bottom_gap = dlo - BELOW_LOWEST;
        // The tables are built from many model states: the law is replaced
        // by its Chebyshev tables (1e-12, about 5x faster for JKR) over the
        // interferences the tabulated gaps reach; laws that remember their
        // maximum interference (plastic) are refused and used as they are.
        let tab_model = {
            let accurate = model
                .clone()
                .with_accuracy(Accuracy::new((QUAD_MARGIN * table_tol).max(1e-13))?);
            if closed {
                accurate
            } else {
                accurate
                    .with_tabulated_law(sigma * bottom_gap, LAW_TABLE_TOL)
                    .unwrap_or(accurate)
            }
        };
        let (approach, bottom) = if closed {
            (closed_approach(model, unit), f64::NEG_INFINITY)
        } else {
            let lo = bottom_gap;
            let t = tabulated_approach(&tab_model, lo, per_area, table_tol)?;
            (t, lo)
        };
        let scale = {
            let a = NodeLaw::eval_form(&approach.form, 0.0).0.abs();
            let b = NodeLaw::eval_form(&approach.form, bottom.max(-1.0)).0.abs();
            a.max(b)
        };
        if !(scale > 0.0) {
            return Err(Error::invalid(
                "law",
                "the local pressure is zero at every gap from -1 to 0 sigma",
            ));
        }
        // From the closed form, or from the model itself (a table's
        // absolute error in the far tail is far above 1e-16 of the scale).
        let top = match &approach.form {
            Form::Table(_) => {
                let per_area = 1.0 / (surface.nominal_area * unit);
                let m = &tab_model;
                negligible_above(
                    &|h| {
                        m.state(sigma * h, History::Approach, &Observables::LOAD)
                            .map(|s| s.load().unwrap_or(0.0) * per_area)
                            .unwrap_or(f64::INFINITY)
                    },
                    scale,
                )
            }
            form => negligible_above(&|h| NodeLaw::eval_form(form, h).0, scale),
        };
        Ok(LocalLaw {
            model: tab_model,
            approach,
            unit,
            sigma,
            top,
            bottom,
            scale,
            reversible,
            table_tol,
            retract: Arc::new(Mutex::new(None)),
        })
    }

    /// The approach law.
    pub fn approach(&self) -> &NodeLaw {
        &self.approach
    }

    /// Gap above which the pressure is negligible.
    pub fn top(&self) -> f64 {
        self.top
    }

    /// Lowest gap the law is defined at.
    pub fn bottom(&self) -> f64 {
        self.bottom
    }

    /// The model (with the tables' accuracy).
    pub fn model(&self) -> &GwModel {
        &self.model
    }

    /// Absolute gap beyond which no summit holds on during a retraction
    /// (the approach law's top plus the retraction's reach below contact,
    /// the cutoff, e.g. JKR's detach interference).
    fn retract_top(&self) -> f64 {
        let sigma = self.sigma;
        let reach = (-self.model.law().cutoff_interference() / sigma).clamp(0.0, 40.0);
        (self.top + reach + 0.5).min(self.model.interaction_onset() / sigma + reach)
    }

    /// The retraction table covering closest gaps from `lowest` up to the
    /// top (built, or rebuilt lower, when it does not yet): one table
    /// `p(H, H_min)` for every node of every mesh of a retraction.
    ///
    /// # Errors
    /// The model's quadrature failures; [`Error::NoConvergence`] when the
    /// table cannot meet its tolerance.
    pub fn prepare_retraction(&self, lowest: f64) -> Result<Option<Arc<RetractTable>>> {
        if self.reversible || !self.model.law().remembers_maximum() || !(lowest < self.top) {
            return Ok(None);
        }
        let mut slot = self
            .retract
            .lock()
            .map_err(|_| Error::invalid("law", "the retraction table's lock was poisoned"))?;
        if let Some(t) = slot.as_ref() {
            if t.range().0 <= lowest {
                return Ok(Some(t.clone()));
            }
        }
        // A margin below the lowest node: radii between nodes interpolate
        // their closest gap.
        let lo = match slot.as_ref() {
            Some(t) => (lowest - 0.25).min(t.range().0),
            None => lowest - 0.25,
        };
        let table = Arc::new(self.build_retraction(lo)?);
        *slot = Some(table.clone());
        Ok(Some(table))
    }

    /// Builds the retraction table for closest gaps in `[lo, top]`.
    fn build_retraction(&self, lo: f64) -> Result<RetractTable> {
        let sigma = self.sigma;
        let per_area = 1.0 / (self.model.surface().nominal_area * self.unit);
        let law = self.model.law();
        // Kinks: where a branch breakpoint's summit height `H + b/sigma`
        // meets a history threshold's `h_min + c/sigma`, at fixed
        // `t = H - h_min = (c - b)/sigma`.
        let mut bs = law.breakpoints(crate::law::Branch::Retract);
        bs.extend(law.breakpoints(crate::law::Branch::Approach));
        let mut cs = law.history_breakpoints();
        cs.push(0.0);
        let mut splits: Vec<f64> = bs
            .iter()
            .flat_map(|b| cs.iter().map(move |c| (c - b) / sigma))
            .collect();
        // ... and where the summits of each threshold `c` let go: their
        // detachment (or contact loss) after `c` depends on `c` (e.g. the
        // flattened shape of a plastic summit), found from the law itself.
        // The span `c - detach(c)` may jump at a threshold (the
        // Kogut–Etsion fits do): both sides.
        for &c in &cs {
            for side in [
                c,
                c + 1e-9 * c.abs().max(sigma),
                c - 1e-9 * c.abs().max(sigma),
            ] {
                if side >= 0.0 {
                    splits.push((side - detachment_after(law, side)) / sigma);
                }
            }
        }
        let t_max = (self.retract_top() - lo).max(1.0);
        // The model's quadrature well below the tables' tolerance floor
        // (its error is relative to the integral of |force| over heights,
        // about the pressure scale; a floor it cannot resolve would make
        // the tables chase its noise).
        let accurate = self
            .model
            .clone()
            .with_accuracy(Accuracy::new((RETRACT_QUAD * self.table_tol).max(1e-13))?);
        let model = &accurate;
        // One set of law evaluations per gap `t` serves every closest gap
        // (`shared_heights.rs`); its noise floor, like its relative
        // tolerance, a fraction RETRACT_QUAD of what the tables may err.
        let floor = RETRACT_FLOOR * self.scale;
        let shared = SharedHeights::new(
            model,
            self.model.surface().summits() * per_area,
            (RETRACT_QUAD * self.table_tol).max(1e-13),
            RETRACT_QUAD * self.table_tol * floor,
        );
        let shared = &shared;
        let slices = move |h_mins: &[f64], ts: &[f64]| -> Result<Vec<Vec<f64>>> {
            use rayon::prelude::*;
            ts.par_iter()
                .map(|&t| shared.pressures(t, h_mins))
                .collect()
        };
        RetractTable::build(lo, self.top, t_max, &splits, self.table_tol, floor, &slices)
    }

    /// The law of a node whose closest gap was `h_min`, on retraction: its
    /// slice of the retraction table (built by
    /// [`prepare_retraction`](Self::prepare_retraction), or here when it
    /// does not reach `h_min`).
    ///
    /// # Errors
    /// As [`prepare_retraction`](Self::prepare_retraction).
    pub fn after(&self, h_min: f64) -> Result<NodeLaw> {
        if self.reversible {
            return Ok(self.approach.clone());
        }
        if h_min >= self.top {
            return Ok(NodeLaw {
                form: Form::Zero,
                below: h_min,
            });
        }
        if !self.model.law().remembers_maximum() {
            return self.after_per_node(h_min);
        }
        let table = self
            .prepare_retraction(h_min)?
            .expect("a law with history below the top");
        Ok(NodeLaw {
            form: Form::Retract(table.weights(h_min)),
            below: h_min,
        })
    }

    /// The table of one node (laws whose retraction depends on `h_min`
    /// only through whether a summit touched, e.g. JKR: cheap tables, and
    /// one per node costs less than the two-dimensional table).
    fn after_per_node(&self, h_min: f64) -> Result<NodeLaw> {
        let sigma = self.sigma;
        let per_area = 1.0 / (self.model.surface().nominal_area * self.unit);
        let back = History::Retract {
            closest: sigma * h_min,
        };
        let law = self.model.law();
        let hi = self.retract_top();
        // Kinks: where a branch breakpoint's summit height `H + b/sigma`
        // meets a history threshold's `h_min + c/sigma`.
        let mut bs = law.breakpoints(crate::law::Branch::Retract);
        bs.extend(law.breakpoints(crate::law::Branch::Approach));
        let mut cs = law.history_breakpoints();
        cs.push(0.0);
        let splits: Vec<f64> = bs
            .iter()
            .flat_map(|b| cs.iter().map(move |c| h_min + (c - b) / sigma))
            .collect();
        let eval = |xs: &[f64]| -> Result<Vec<f64>> {
            xs.iter()
                .map(|&h| {
                    let s = self
                        .model
                        .state(sigma * h.max(h_min), back, &Observables::LOAD)?;
                    Ok(s.load().unwrap_or(0.0) * per_area)
                })
                .collect()
        };
        let t = Table::build(
            h_min,
            hi.max(h_min + 1.0),
            &splits,
            self.table_tol,
            1e-4 * self.scale,
            &eval,
        )?;
        Ok(NodeLaw {
            form: Form::Table(Arc::new(t)),
            below: h_min,
        })
    }
}

impl NodeLaw {
    /// `p` at gap `h` (see [`eval`](Self::eval)).
    #[inline]
    pub fn pressure(&self, approach: &NodeLaw, h: f64) -> f64 {
        if h < self.below {
            NodeLaw::pressure_form(&approach.form, h)
        } else {
            NodeLaw::pressure_form(&self.form, h)
        }
    }

    /// `(p, dp/dH)` at gap `h`; below the node's closest gap, the approach
    /// law `approach`.
    #[inline]
    pub fn eval(&self, approach: &NodeLaw, h: f64) -> (f64, f64) {
        if h < self.below {
            NodeLaw::eval_form(&approach.form, h)
        } else {
            NodeLaw::eval_form(&self.form, h)
        }
    }
}

/// The interference (m) below which a summit that reached `delta_max`
/// (m) has let go on retraction, by bisection between the law's cutoff
/// and `delta_max` (60 halvings; `delta_max` itself when it is free there).
fn detachment_after(law: &dyn crate::law::AsperityLaw, delta_max: f64) -> f64 {
    let attached = |d: f64| {
        let s = law.state_after(d, delta_max);
        s.radius > 0.0 || s.load != 0.0
    };
    let mut lo = law.cutoff_interference().min(delta_max);
    let mut hi = delta_max;
    if !attached(hi) || attached(lo) {
        return lo;
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if attached(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

/// Smallest gap above which `|p| <= NEGLIGIBLE * scale` (scanned down from
/// 40 in steps of 1/4, refined by bisection).
fn negligible_above(p: &dyn Fn(f64) -> f64, scale: f64) -> f64 {
    let small = |h: f64| p(h).abs() <= NEGLIGIBLE * scale;
    let mut h = 40.0;
    while h > -40.0 && small(h - 0.25) {
        h -= 0.25;
    }
    // small(h) holds, small(h - 1/4) does not: bisect
    let (mut lo, mut hi) = (h - 0.25, h);
    for _ in 0..30 {
        let mid = 0.5 * (lo + hi);
        if small(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}
