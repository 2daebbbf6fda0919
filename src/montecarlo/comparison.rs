//! A population's curve against the statistical integral of the same
//! program: deviations in standard errors, where the standard error means
//! something.
//!
//! A population sum estimates the integral with a standard error from the
//! spread of its summits; the deviation `z = (x_MC - x_GW) /
//! sqrt(SE^2 + err_GW^2)` ([`State::deviation_from`]) is about standard
//! normal when the population follows the model. With few summits in
//! contact the central limit does not hold (deviations of 30 "standard
//! errors" appear), so states with fewer than [`MIN_SUMMITS_FOR_Z`] are
//! not compared; with none in range the sum is an exact 0 that a tiny
//! expectation cannot be "many errors" from.

use crate::loading::{Curve, State, SLOTS};

/// Summits in contact (and in range) below which a population state is not
/// compared with the integral in standard errors.
pub const MIN_SUMMITS_FOR_Z: usize = 20;

/// A population's curve against the integral, state by state (approach
/// states, then retraction states).
#[derive(Debug, Clone, PartialEq)]
pub struct Comparison {
    /// Deviation in standard errors per state and slot; `None` where fewer
    /// than [`MIN_SUMMITS_FOR_Z`] summits are in contact.
    pub z: Vec<[Option<f64>; SLOTS]>,
    /// Largest `|z|` over the curve and slots (`< 5` expected when the
    /// population follows the model).
    pub max_abs_z: Option<f64>,
    /// Summits of the population in contact per state (its count over the
    /// scale factor; summits in range when the count is not computed).
    pub contacts: Vec<f64>,
}

/// Summits of a population state in contact: its count over the scale
/// factor `factor` (the population's totals are scaled to the surface),
/// or the summits in range when the count is not computed.
pub fn contacts_of(state: &State, factor: f64) -> f64 {
    state
        .count()
        .map_or(state.evaluations as f64, |c| (c / factor).round())
}

impl Comparison {
    /// Compares `population` (totals scaled by `factor`) with `integral`
    /// at the same separations.
    pub fn new(population: &Curve, integral: &Curve, factor: f64) -> Comparison {
        let pairs = population
            .approach
            .iter()
            .zip(&integral.approach)
            .chain(population.retract.iter().zip(&integral.retract));
        let contacts: Vec<f64> = population
            .approach
            .iter()
            .chain(&population.retract)
            .map(|m| contacts_of(m, factor))
            .collect();
        let z: Vec<[Option<f64>; SLOTS]> = pairs
            .zip(&contacts)
            .map(|((m, g), &c)| {
                if m.evaluations >= MIN_SUMMITS_FOR_Z && c >= MIN_SUMMITS_FOR_Z as f64 {
                    m.deviation_from(g)
                } else {
                    [None; SLOTS]
                }
            })
            .collect();
        let max_abs_z = z
            .iter()
            .flatten()
            .flatten()
            .map(|v| v.abs())
            .reduce(f64::max);
        Comparison {
            z,
            max_abs_z,
            contacts,
        }
    }

    /// States where fewer than [`MIN_SUMMITS_FOR_Z`] summits are in
    /// contact (no standard error or deviation is reported there).
    pub fn states_without_standard_error(&self) -> usize {
        self.contacts
            .iter()
            .filter(|&&c| c < MIN_SUMMITS_FOR_Z as f64)
            .count()
    }
}
