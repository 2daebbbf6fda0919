//! The energy lost per loading cycle, integrated to a tolerance.

use super::model::LoadingModel;
use super::observable::Observables;
use super::program::{History, LoadingProgram};
use crate::error::{Allowed, Error, Result};
use crate::numeric::quadrature::{integrate_pieces, kronrod21_n, QuadOptions};

/// Most K21 panels of [`hysteresis_energy_to`] before it reports
/// [`Error::NoConvergence`] (each panel costs 42 states).
const MAX_PANELS: usize = 200;

/// Energy lost per cycle (J) of `program` on `model`:
/// `W = int_closest^start (P_approach(d) - P_retract(d)) dd`, by adaptive
/// Gauss–Kronrod quadrature over the separation `d` (each integrand value is
/// an approach and a retraction state of the model), to a relative
/// tolerance `rtol` measured against `int |P_approach - P_retract| dd`, with
/// an absolute floor equal to the integrated error estimates of the states
/// themselves (`int (err_approach + err_retract) dd`, from one K21 panel
/// over the program): the loads cannot give the energy more accurately than
/// they are known. Unlike [`Curve::hysteresis_energy`](super::Curve::hysteresis_energy)
/// (trapezoidal on the program's points, error `O(step^2)` whatever the
/// tolerance), the result follows `rtol`. Meant for continuous models (a
/// discrete population's loads are step functions; its sampled trapezoid is
/// the honest estimate).
///
/// # Errors
/// [`Error::OutOfRange`] naming `rtol` outside `[1e-14, 0.1]`;
/// [`Error::NoConvergence`] when the tolerance is not met within 200 panels;
/// as [`LoadingModel::state`].
pub fn hysteresis_energy_to<M: LoadingModel + ?Sized>(
    model: &M,
    program: &LoadingProgram,
    rtol: f64,
) -> Result<f64> {
    Allowed::closed(1e-14, 0.1).check("rtol", rtol)?;
    let back = History::Retract {
        closest: program.closest,
    };
    let mut failure = None;
    // (P_approach - P_retract, err_approach + err_retract) at d.
    let mut gap = |d: f64| -> [f64; 2] {
        let pair = model
            .state(d, History::Approach, &Observables::LOAD)
            .and_then(|a| Ok((a, model.state(d, back, &Observables::LOAD)?)));
        match pair {
            Ok((a, r)) => [
                a.load().unwrap_or(0.0) - r.load().unwrap_or(0.0),
                a.totals.error(0).unwrap_or(0.0) + r.totals.error(0).unwrap_or(0.0),
            ],
            Err(e) => {
                failure.get_or_insert(e);
                [f64::NAN; 2]
            }
        }
    };
    let (a, b) = (program.closest, program.start);
    let (_, _, magnitude) = kronrod21_n(&mut gap, a, b);
    let floor = magnitude[1];
    let opts = QuadOptions {
        rel_tol: rtol,
        abs_tol: floor,
        max_intervals: MAX_PANELS,
        relative_to_magnitude: true,
    };
    // Split at the model's own kinks of the gap (the attach/detach
    // crossing): an adaptive rule's error estimate is fooled by a kink
    // inside a panel and stops early.
    let mut points = vec![a];
    points.extend(model.cycle_kinks(a).into_iter().filter(|&d| d > a && d < b));
    points.push(b);
    let q = integrate_pieces(|d| gap(d)[0], &points, &opts);
    if let Some(e) = failure {
        return Err(e);
    }
    if !q.converged {
        return Err(Error::NoConvergence {
            what: "hysteresis energy over the loading program".into(),
            iterations: q.evaluations,
            residual: q.error / q.value.abs().max(f64::MIN_POSITIVE),
        });
    }
    Ok(q.value)
}
