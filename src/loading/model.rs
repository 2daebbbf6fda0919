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
use crate::error::{positive, Allowed, Error, Result};
use crate::numeric::roots::{golden_min, try_brent};

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

    /// Relative tolerance to which
    /// [`separation_at_load`](LoadingModel::separation_at_load) meets its
    /// target load (default `1e-9`: exact sums; models computed to a
    /// tolerance return it).
    fn load_tolerance(&self) -> f64 {
        1e-9
    }

    /// Whether totals are step functions of the separation (a finite
    /// population): searches then bisect instead of interpolating.
    fn is_discrete(&self) -> bool {
        false
    }

    /// Separations (m) where the cycle's load gap `P_approach(d) -
    /// P_retract(d)` after a closest approach `closest` has a kink (or
    /// jump) of its own: a cycle integral splits its quadrature there
    /// ([`hysteresis_energy_to`](super::hysteresis_energy_to)). Default:
    /// none known.
    fn cycle_kinks(&self, _closest: f64) -> Vec<f64> {
        Vec::new()
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

    /// Pull-off on retraction after approaching to `closest` (m) in a
    /// program that starts (and ends) at `start` (m): the most tensile total
    /// load within the program, located by sampling `samples` separations
    /// between `closest` and `min(start, interaction onset)`, then refined by
    /// golden-section search to
    /// [`separation_tolerance`](LoadingModel::separation_tolerance). `None`
    /// when no retraction load within the program is tensile (the flat
    /// never goes beyond `start`, so a tensile load above it is never
    /// felt). `start = f64::INFINITY` searches up to the interaction onset
    /// ([`LoadingModel::pull_off_in`] takes a program's own start). When
    /// the most tensile sample is the start itself and the start is within
    /// the law's reach, [`PullOff::at_start`] says the answer is cut off.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `start_separation` when `start` is NaN;
    /// as [`LoadingModel::state`].
    fn pull_off(&self, closest: f64, start: f64, samples: usize) -> Result<Option<PullOff>> {
        if start.is_nan() {
            return Err(Error::OutOfRange {
                name: "start_separation".into(),
                value: start,
                allowed: Allowed::closed_open(closest, f64::INFINITY),
            });
        }
        let top = self.interaction_onset().min(start);
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
        let steps: Vec<(f64, History)> = seps.iter().map(|&d| (d, back)).collect();
        let loads: Vec<f64> = self
            .states(&steps, &Observables::LOAD)?
            .iter()
            .map(|s| s.load().unwrap_or(0.0))
            .collect();
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
        // The least sample at the top, below the interaction onset: the
        // load may still fall beyond the start.
        let at_start = imin == seps.len() - 1 && top < self.interaction_onset();
        Ok(Some(PullOff {
            load,
            separation,
            at_start,
        }))
    }

    /// [`pull_off`](LoadingModel::pull_off) over `program`: from its
    /// closest separation up to its own start.
    ///
    /// # Errors
    /// As [`LoadingModel::pull_off`].
    fn pull_off_in(&self, program: &LoadingProgram, samples: usize) -> Result<Option<PullOff>> {
        self.pull_off(program.closest, program.start, samples)
    }

    /// Separation (m) at which the approach load reaches `target` (N, > 0)
    /// coming down from `start`: steps of one height scale down to
    /// `start - 50` height scales bracket the first crossing, then Brent's
    /// method (continuous models) or bisection keeping the side whose load
    /// is `>= target` (discrete models) refines it down to a few ulps of the
    /// separation, and the load found must meet the target to
    /// [`load_tolerance`](LoadingModel::load_tolerance):
    /// `|P(d) - target| <= load_tolerance * target`. A load that jumps over
    /// the target (summits jumping into contact one by one, or a
    /// discontinuous law) is refused rather than reported as the target.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `max_load` for a target that is not
    /// finite and positive; [`Error::Invalid`] naming `start_separation`
    /// when the load at `start` already reaches the target (the crossing
    /// lies above the start); [`Error::Invalid`] naming `max_load` when the
    /// load is not reached within the search depth, or is only reached by a
    /// jump (the message gives the loads on either side); as
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
        // Coming down from a start where the target is already exceeded
        // would miss the crossing above it.
        let at_start = load(start)?;
        if at_start >= target {
            return Err(Error::invalid(
                "start_separation",
                format!(
                    "the approach load at the start d = {start:e} m is already {at_start:e} N \
                     >= the target {target:e} N, so the separation of the target lies above \
                     the start: start further out (the model's interaction onset is {:e} m)",
                    self.interaction_onset()
                ),
            ));
        }
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
        // Down to a few ulps of the separation: the load, not the
        // separation, carries the tolerance (a steep load moves by many
        // tolerances over `rtol sigma`).
        let tol = 4.0 * f64::EPSILON * lo.abs().max(hi.abs()).max(scale);
        let root = if self.is_discrete() {
            bisect_to_load(&load, target, (lo, hi), tol)?
        } else {
            try_brent(|d| Ok(load(d)? - target), lo, hi, tol)?
                .ok_or_else(|| Error::invalid("max_load", "could not bracket the load"))?
        };
        let met = load(root)?;
        let rtol = self.load_tolerance();
        if (met - target).abs() <= rtol * target {
            return Ok(root);
        }
        // The crossing is a jump: report the loads on either side.
        let step = (tol * 4.0).max(f64::EPSILON * root.abs());
        let (below, above) = (load(root + step)?, load(root - step)?);
        Err(Error::invalid(
            "max_load",
            format!(
                "{target:e} N cannot be met to rtol {rtol:e}: the approach load jumps from \
                 {below:.4e} N to {above:.4e} N at d = {root:.6e} m (summits jumping into contact); \
                 ask for a load outside the jump, or a separation"
            ),
        ))
    }
}

/// The separation, to `tol` (m), where a discrete model's approach load
/// `load` crosses `target` (N) inside `(lo, hi)` with `load(lo) >=
/// target`: bisection keeping the side whose load reaches the target (a
/// step load has no root for Brent's method to converge on).
fn bisect_to_load(
    load: &dyn Fn(f64) -> Result<f64>,
    target: f64,
    (mut lo, mut hi): (f64, f64),
    tol: f64,
) -> Result<f64> {
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
    Ok(lo)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::loading::{MethodUsed, Totals, SLOTS};

    /// A toy model whose approach load is `load(d)`.
    struct Toy<F: Fn(f64) -> f64 + Sync> {
        load: F,
        discrete: bool,
    }

    impl<F: Fn(f64) -> f64 + Sync> LoadingModel for Toy<F> {
        fn state(&self, d: f64, _: History, obs: &Observables) -> Result<State> {
            let mut values = [0.0; SLOTS];
            values[0] = (self.load)(d);
            Ok(State {
                separation: d,
                totals: Totals::new(values, [0.0; SLOTS], obs.mask()),
                method: MethodUsed::ClosedForm,
                evaluations: 1,
            })
        }
        fn interaction_onset(&self) -> f64 {
            1.0
        }
        // The old search stopped here: a tenth of the height scale.
        fn separation_tolerance(&self) -> f64 {
            0.1
        }
        fn height_scale(&self) -> f64 {
            1.0
        }
        fn is_discrete(&self) -> bool {
            self.discrete
        }
        fn load_tolerance(&self) -> f64 {
            1e-6
        }
    }

    /// A steep load (a factor e per 1 % of the height scale) is met to the
    /// load tolerance, not to the separation tolerance (which allows a
    /// factor e^10), by both searches.
    #[test]
    fn a_steep_load_is_met_to_the_load_tolerance() {
        for discrete in [false, true] {
            let toy = Toy {
                load: |d: f64| if d < 0.0 { (-100.0 * d).exp_m1() } else { 0.0 },
                discrete,
            };
            for target in [1e-6, 1.0, 1e3, 1e30] {
                let d = toy.separation_at_load(target, 1.0).unwrap();
                let p = (toy.load)(d);
                assert!(
                    (p - target).abs() <= 1e-6 * target,
                    "{discrete} {target}: {p}"
                );
            }
        }
    }

    /// A load that jumps over the target is refused, naming `max_load` and
    /// the loads on either side of the jump.
    #[test]
    fn a_target_inside_a_jump_is_refused() {
        for discrete in [false, true] {
            let toy = Toy {
                load: |d: f64| if d < 0.0 { 1.0 - d } else { 0.0 },
                discrete,
            };
            let e = toy.separation_at_load(0.5, 1.0).unwrap_err();
            assert_eq!(e.field(), Some("max_load"), "{e}");
            assert!(
                e.to_string()
                    .contains("jumps from 0.0000e0 N to 1.0000e0 N"),
                "{e}"
            );
            let d = toy.separation_at_load(2.0, 1.0).unwrap();
            assert!(((toy.load)(d) - 2.0).abs() <= 2e-6);
        }
    }
}
