//! What every rough-contact model answers, and the searches built on it.
//!
//! [`GwModel`](crate::gw::GwModel) (an integral over a height distribution)
//! and [`MonteCarlo`](crate::montecarlo::MonteCarlo) (a sum over a drawn
//! population) both implement [`LoadingModel`]; curves, the pull-off finder
//! and the separation-at-a-load solver are written once, here.

use super::curve::{Curve, PullOff};
use super::observable::Observables;
use super::program::{History, LoadingProgram};
use super::state::State;
use crate::error::{positive, Error, Result};
use crate::numeric::roots::{brent, golden_min};

/// How far below its start the separation-at-a-load search looks, in
/// height scales: 50 sigma is below any summit a distribution represents
/// (Gaussian tails end near 38 sigma in f64).
const LOAD_SEARCH_DEPTH: f64 = 50.0;

/// A rough contact that gives totals of observables at a separation after
/// a loading history.
pub trait LoadingModel: Sync {
    /// Totals at separation `d` (m) after `history`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] for a separation the history cannot have (see
    /// [`History::check`]); model-specific failures otherwise.
    fn state(&self, separation: f64, history: History, observables: &Observables) -> Result<State>;

    /// Totals at several steps (default: one after another; models may
    /// compute them together).
    ///
    /// # Errors
    /// As [`LoadingModel::state`].
    fn states(&self, steps: &[(f64, History)], observables: &Observables) -> Result<Vec<State>> {
        steps
            .iter()
            .map(|&(d, h)| self.state(d, h, observables))
            .collect()
    }

    /// Largest separation (m) at which any asperity feels the flat.
    fn interaction_onset(&self) -> f64;

    /// Absolute separation tolerance (m) of the searches.
    fn separation_tolerance(&self) -> f64;

    /// Height scale (m), e.g. the summit-height standard deviation: the
    /// step of the load search.
    fn height_scale(&self) -> f64;

    /// Whether totals are step functions of the separation (a finite
    /// population): searches then bisect instead of interpolating.
    fn is_discrete(&self) -> bool {
        false
    }

    /// Runs `program`: approach states, then retraction states after the
    /// closest separation.
    ///
    /// # Errors
    /// As [`LoadingModel::state`].
    fn curve(&self, program: &LoadingProgram, observables: &Observables) -> Result<Curve> {
        let mut approach = self.states(&program.steps(), observables)?;
        let retract = approach.split_off(program.points);
        Ok(Curve {
            program: *program,
            approach,
            retract,
        })
    }

    /// Pull-off on retraction after approaching to `closest` (m): the most
    /// tensile total load, located by sampling `samples` separations between
    /// `closest` and the interaction onset, then refined by golden-section
    /// search to [`separation_tolerance`](LoadingModel::separation_tolerance).
    /// `None` when no retraction load is tensile.
    ///
    /// # Errors
    /// As [`LoadingModel::state`].
    fn pull_off(&self, closest: f64, samples: usize) -> Result<Option<PullOff>> {
        let top = self.interaction_onset();
        if !(top > closest) {
            return Ok(None);
        }
        let program = LoadingProgram::new(top, closest, samples.max(3))?;
        let seps = program.separations();
        let back = History::Retract { closest };
        let load = |d: f64| -> Result<f64> {
            Ok(self
                .state(d, back, &Observables::LOAD)?
                .load()
                .unwrap_or(0.0))
        };
        let loads = seps.iter().map(|&d| load(d)).collect::<Result<Vec<_>>>()?;
        let Some((imin, &pmin)) = loads.iter().enumerate().min_by(|a, b| a.1.total_cmp(b.1)) else {
            return Ok(None);
        };
        if !(pmin < 0.0) {
            return Ok(None);
        }
        let lo = seps[imin.saturating_sub(1)];
        let hi = seps[(imin + 1).min(seps.len() - 1)];
        let mut failure = None;
        let (d, p) = golden_min(
            |d| match load(d) {
                Ok(p) => p,
                Err(e) => {
                    failure = Some(e);
                    f64::INFINITY
                }
            },
            lo,
            hi,
            self.separation_tolerance().max(1e-9 * (hi - lo)),
        );
        if let Some(e) = failure {
            return Err(e);
        }
        let (load, separation) = if p < pmin { (p, d) } else { (pmin, seps[imin]) };
        Ok(Some(PullOff { load, separation }))
    }

    /// Separation (m) at which the approach load reaches `target` (N, > 0)
    /// coming down from `start`: steps of one height scale down to
    /// `start - 50` height scales bracket the first crossing, then Brent's
    /// method (continuous models) or bisection keeping the side whose load
    /// is `>= target` (discrete models) refines it to
    /// [`separation_tolerance`](LoadingModel::separation_tolerance).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `max_load` for a target that is not
    /// finite and positive; [`Error::Invalid`] naming `max_load` when the
    /// load is not reached within the search depth; as
    /// [`LoadingModel::state`].
    fn separation_at_load(&self, target: f64, start: f64) -> Result<f64> {
        positive("max_load", target)?;
        let scale = self.height_scale();
        let load = |d: f64| -> Result<f64> {
            Ok(self
                .state(d, History::Approach, &Observables::LOAD)?
                .load()
                .unwrap_or(0.0))
        };
        let (mut lo, mut hi) = (start - scale, start);
        loop {
            let p = load(lo)?;
            if p.is_nan() {
                // Not the target's fault: the model broke down (a derived
                // quantity out of floating-point range).
                return Err(Error::invalid(
                    "law",
                    format!("the total load is NaN at separation {lo:e} m"),
                ));
            }
            if p >= target {
                break;
            }
            hi = lo;
            lo -= scale;
            if lo < start - LOAD_SEARCH_DEPTH * scale {
                return Err(Error::invalid(
                    "max_load",
                    format!(
                        "{target:e} N is not reached on approach above d = {:e} m \
                         ({LOAD_SEARCH_DEPTH} height scales below the start)",
                        start - LOAD_SEARCH_DEPTH * scale
                    ),
                ));
            }
        }
        let tol = self.separation_tolerance();
        if self.is_discrete() {
            while hi - lo > tol {
                let mid = 0.5 * (lo + hi);
                if !(mid > lo && mid < hi) {
                    break;
                }
                if load(mid)? >= target {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            return Ok(lo);
        }
        let mut failure = None;
        let root = brent(
            |d| match load(d) {
                Ok(p) => p - target,
                Err(e) => {
                    failure = Some(e);
                    f64::NAN
                }
            },
            lo,
            hi,
            tol,
        );
        if let Some(e) = failure {
            return Err(e);
        }
        root.ok_or_else(|| Error::invalid("max_load", "could not bracket the load"))
    }
}
