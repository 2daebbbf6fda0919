//! The spot sums as per-asperity observables, so that any law and both
//! integrators (GW integral, Monte Carlo sum) give a contact resistance.
//!
//! A summit in contact with radius `a_i` is a spot of conductance
//! `G_i = 1/R(a_i)` ([`SpotResistance::spot_conductance`]). The parallel
//! resistance needs `sum G_i`, Greenwood's interaction weights also
//! `sum G_i^2` ([`SpotSums`]); the count of spots is the `count` total.

use super::heating::Heating;
use super::interaction::{ContactResistance, Interaction, SpotSums, C_SQ};
use super::spot::SpotResistance;
use crate::error::Result;
use crate::law::ContactState;
use crate::loading::{Derived, Observable, Observables, PerAsperity, Totals};
use std::sync::Arc;

/// `G_i` (S) or `G_i^2` (S^2) of one asperity's spot.
#[derive(Debug, Clone, Copy)]
pub struct SpotConductance {
    spot: SpotResistance,
    squared: bool,
}

impl PerAsperity for SpotConductance {
    fn name(&self) -> &str {
        if self.squared {
            "spot_conductance_sq_S2"
        } else {
            "spot_conductance_S"
        }
    }

    #[inline]
    fn value(&self, state: &ContactState) -> f64 {
        let g = self.spot.spot_conductance(state.radius);
        if self.squared {
            g * g
        } else {
            g
        }
    }

    /// [`SpotResistance::conductance_batch`], squared when asked.
    fn value_batch(&self, _load: &[f64], radius: &[f64], out: &mut [f64]) {
        self.spot.conductance_batch(radius, out);
        if self.squared {
            for g in out.iter_mut() {
                *g *= *g;
            }
        }
    }
}

/// The observables a resistance needs, and how to turn totals into one.
#[derive(Debug, Clone)]
pub struct ResistanceObservables {
    spot: SpotResistance,
    interaction: Interaction,
    side: f64,
    conductance: Observable,
    conductance_sq: Observable,
}

impl ResistanceObservables {
    /// For spots of `spot`, with `interaction` in a square apparent area
    /// of side `side` (m).
    pub fn new(spot: SpotResistance, interaction: Interaction, side: f64) -> Self {
        let o = |squared| Observable::Custom(Arc::new(SpotConductance { spot, squared }));
        ResistanceObservables {
            spot,
            interaction,
            side,
            conductance: o(false),
            conductance_sq: o(true),
        }
    }

    /// The side (m) of the square apparent area of the interaction.
    pub fn side(&self) -> f64 {
        self.side
    }

    /// `observables` plus the count and the two conductance sums.
    ///
    /// # Errors
    /// When `observables` has no free extra slots left.
    pub fn add_to(&self, observables: Observables) -> Result<Observables> {
        observables
            .with(Observable::Count)?
            .with(self.conductance.clone())?
            .with(self.conductance_sq.clone())
    }

    /// The contact resistance from totals computed with
    /// [`ResistanceObservables::add_to`]'s observables (`None` when they
    /// are missing); `inf` without contact. Greenwood's interaction is
    /// over the square of side [`ResistanceObservables::side`], or, where
    /// the totals carry the spots' conductance-weighted mean inverse
    /// distance `I` (a rough sphere's bump,
    /// [`Totals::inverse_distance`]), over the square with the same mean
    /// inverse distance, of side `c_sq / I` (`inf` for `I <= 0`).
    pub fn resistance(
        &self,
        observables: &Observables,
        totals: &Totals,
    ) -> Option<ContactResistance> {
        let g = totals.get(observables.slot(&self.conductance)?)?;
        let g2 = totals.get(observables.slot(&self.conductance_sq)?)?;
        let sums = SpotSums {
            contacts: totals.count()?,
            conductance: g,
            conductance_sq: g2,
        };
        let side = match totals.inverse_distance() {
            Some(i) if i > 0.0 => C_SQ / i,
            Some(_) => f64::INFINITY,
            None => self.side,
        };
        Some(ContactResistance::from_sums(
            &sums,
            &self.spot,
            self.interaction,
            side,
        ))
    }

    /// The spot conductance `G_i` (S), the observable whose totals'
    /// spread over a rough sphere's bump gives
    /// [`Totals::inverse_distance`].
    pub fn conductance(&self) -> &Observable {
        &self.conductance
    }

    /// The per-spot resistance law.
    pub fn spot(&self) -> &SpotResistance {
        &self.spot
    }

    /// The interaction asked for.
    pub fn interaction(&self) -> Interaction {
        self.interaction
    }
}

/// The contact resistance (Ohm) of a state: parallel spots plus the
/// interaction asked for ([`ResistanceObservables::resistance`]); `None`
/// without contact.
impl Derived for ResistanceObservables {
    fn needs(&self) -> Vec<Observable> {
        vec![
            Observable::Count,
            self.conductance.clone(),
            self.conductance_sq.clone(),
        ]
    }

    fn value(&self, observables: &Observables, totals: &Totals) -> Option<f64> {
        let r = self.resistance(observables, totals)?.resistance;
        r.is_finite().then_some(r)
    }
}

/// Joule heating of a contact carrying a current `I` (A): the contact
/// voltage `U = I R` (V) or Holm's peak temperature
/// `sqrt(T0^2 + U^2/(4 L))` (K, [`Heating::peak_temperature`]: none once
/// the spot melts), from the state's resistance.
#[derive(Debug, Clone)]
pub struct ContactHeating {
    resistance: ResistanceObservables,
    current: f64,
    heating: Heating,
    temperature: bool,
}

impl ContactHeating {
    /// The contact voltage `I R` (V) of a current `current` (A).
    pub fn voltage(resistance: ResistanceObservables, current: f64) -> Self {
        ContactHeating {
            resistance,
            current,
            heating: Heating::default(),
            temperature: false,
        }
    }

    /// The peak contact temperature (K) of a current `current` (A) under
    /// `heating`.
    pub fn temperature(resistance: ResistanceObservables, current: f64, heating: Heating) -> Self {
        ContactHeating {
            resistance,
            current,
            heating,
            temperature: true,
        }
    }
}

impl Derived for ContactHeating {
    fn needs(&self) -> Vec<Observable> {
        self.resistance.needs()
    }

    fn value(&self, observables: &Observables, totals: &Totals) -> Option<f64> {
        let r = self.resistance.value(observables, totals)?;
        let v = if self.temperature {
            // No temperature once the spot melts (Holm's relation ends).
            self.heating
                .peak_temperature((self.current * r).abs())
                .ok()??
        } else {
            self.current * r
        };
        v.is_finite().then_some(v)
    }
}
