//! The rough sphere as a [`LoadingModel`]: the separation is the remote
//! separation `s = d - w(0)` (m, minus the approach of distant points), so
//! the one curve runner, pull-off finder, separation-at-a-load solver and
//! hysteresis integral of [`crate::loading`] serve the sphere as they serve
//! a flat: `int (P_approach - P_retract) ds` is the work lost per cycle by
//! a machine moving the sphere's far side.

use super::problem::RoughSphere;
use crate::error::Result;
use crate::loading::{History, LoadingModel, MethodUsed, Observables, State, Totals, SLOTS};

impl RoughSphere {
    fn totals_state(
        &self,
        separation: f64,
        history: History,
        observables: &Observables,
    ) -> Result<State> {
        history.check(separation)?;
        let u = self.units();
        let sigma = u.sigma;
        let s = match history {
            History::Approach => self.approach_remote(separation / sigma)?,
            History::Retract { closest } => {
                self.retract_remote(separation / sigma, closest / sigma)?
            }
        };
        let mut values = [0.0; SLOTS];
        let mut errors = [0.0; SLOTS];
        let load = self.core.load(&s);
        values[0] = load.value * u.load();
        errors[0] = load.error * u.load();
        let rest = observables.area || observables.count || !observables.extras().is_empty();
        // the spots' spread over the bump, when their conductance is totalled
        let conductance = self.spots.as_ref().and_then(|g| observables.slot(g));
        let mut inverse_distance = None;
        if rest {
            let (t, inverse) = self.core.totals(&s, observables, conductance)?;
            for k in 1..SLOTS {
                if let Some(e) = t[k] {
                    values[k] = e.value * u.area();
                    errors[k] = e.error * u.area();
                }
            }
            inverse_distance = inverse.map(|i| i.value / u.length());
        }
        let evaluations = s.levels.iter().map(|l| l.mesh.len()).sum();
        let totals = Totals::new(values, errors, observables.mask());
        Ok(State {
            separation,
            totals: match inverse_distance {
                Some(i) => totals.with_inverse_distance(i),
                None => totals,
            },
            method: MethodUsed::Quadrature,
            evaluations,
        })
    }
}

impl LoadingModel for RoughSphere {
    /// Totals over the bump at remote separation `separation` (m) after
    /// `history` (`closest`: the closest remote separation). The load is
    /// the integral of the local pressure over the apparent area, the other
    /// observables integrals of the local GW totals; errors are the mesh
    /// extrapolation's estimates. `method` is [`MethodUsed::Quadrature`]
    /// (an integral over the apparent area with estimated error). With
    /// [`RoughSphere::with_spot_conductance`] and that conductance among
    /// `observables`, the totals carry the spots' conductance-weighted
    /// mean inverse distance over the bump
    /// ([`Totals::inverse_distance`]), extrapolated over the mesh levels
    /// like the totals.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `separation` or
    /// `closest_separation`; [`crate::Error::NoConvergence`].
    fn state(&self, separation: f64, history: History, observables: &Observables) -> Result<State> {
        self.totals_state(separation, history, observables)
    }

    /// The steps in the order a continuation follows them (approach from
    /// far, then each retraction from its closest state), returned in the
    /// order given.
    ///
    /// # Errors
    /// As [`LoadingModel::state`].
    fn states(&self, steps: &[(f64, History)], observables: &Observables) -> Result<Vec<State>> {
        let mut order: Vec<usize> = (0..steps.len()).collect();
        let key = |i: usize| match steps[i].1 {
            History::Approach => (0, f64::INFINITY, -steps[i].0),
            History::Retract { closest } => (1, closest, steps[i].0),
        };
        order.sort_by(|&a, &b| {
            let (ka, kb) = (key(a), key(b));
            ka.0.cmp(&kb.0)
                .then(ka.1.total_cmp(&kb.1))
                .then(ka.2.total_cmp(&kb.2))
        });
        let mut out: Vec<Option<State>> = vec![None; steps.len()];
        for i in order {
            crate::cancel::check()?;
            let (d, h) = steps[i];
            out[i] = Some(self.state(d, h, observables)?);
        }
        Ok(out
            .into_iter()
            .map(|s| s.expect("every step solved"))
            .collect())
    }

    /// `sigma H_top`: no pressure is felt beyond (below `1e-16` of its
    /// scale).
    fn interaction_onset(&self) -> f64 {
        self.units().sigma * self.top()
    }

    /// `1e-9 sigma`.
    fn separation_tolerance(&self) -> f64 {
        1e-9 * self.units().sigma
    }

    /// `sigma`.
    fn height_scale(&self) -> f64 {
        self.units().sigma
    }

    /// The solver's tolerance on the load.
    fn load_tolerance(&self) -> f64 {
        self.core.options.tolerance
    }
}
