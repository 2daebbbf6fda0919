//! Measured summits as a population: the exact sum of a law over the
//! summits of a characterised height map, each with its own height and
//! radius, scaled to a nominal area.
//!
//! Summit `i` of the map ([`crate::surface::Summit`]) has height `z_i`
//! above the mean plane and mean curvature `kappa_i` (5-point Laplacian);
//! here it is a paraboloid cap of radius `R_i = 1/kappa_i` at height
//! `z_i - z_mean`, where `z_mean` is the mean summit height (sum in map
//! order divided by N): separations are measured from the mean summit
//! plane, the origin GW uses. The totals at separation `d` are
//!
//! ```text
//! X(d) = f sum_i x(z_i - z_mean - d; R_i),   f = A_n / (candidates dx^2)
//! ```
//!
//! with `x` the law's load, area or count and `f` the ratio of the nominal
//! area to the area the summits were searched on (1 for a periodic map with
//! the default nominal area). Laws are rescaled per radius through their
//! [`RadiusScaling`](crate::law::RadiusScaling) ([`SummitLaw`]); laws without one (Maugis–Dugdale,
//! calibrated) cannot serve summits of different radii and are refused.
//! The standard errors a [`MonteCarlo`] attaches are kept (scaled by `f`)
//! but mean nothing here: the sum is over the whole measured population.

use super::{MonteCarlo, Population, Radii, SummitLaw};
use crate::error::{positive, Error, Result};
use crate::loading::{History, LoadingModel, Observables, State};
use crate::surface::Characterisation;
use std::sync::Arc;

/// The exact sum over measured summits (see the module documentation).
#[derive(Debug, Clone)]
pub struct MeasuredSummits {
    sum: MonteCarlo,
    factor: f64,
    origin: f64,
}

impl MeasuredSummits {
    /// The summits of `c` with `law` (built for any reference radius, with a
    /// radius scaling), scaled to `nominal_area` (m^2).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `nominal_area` unless finite and > 0;
    /// [`Error::Invalid`] naming `topography` with fewer than 2 summits or a
    /// summit of non-positive curvature, and naming `radius` when the law
    /// has no radius scaling.
    pub fn new(c: &Characterisation, law: SummitLaw, nominal_area: f64) -> Result<Self> {
        positive("nominal_area", nominal_area)?;
        let n = c.summits.len();
        if n < 2 {
            return Err(Error::invalid(
                "topography",
                format!("{n} summits; at least 2 are needed"),
            ));
        }
        if let Some(s) = c.summits.iter().find(|s| !(s.curvature_per_m > 0.0)) {
            return Err(Error::invalid(
                "topography",
                format!(
                    "summit at row {}, column {} has curvature {:e} 1/m: no radius",
                    s.row, s.col, s.curvature_per_m
                ),
            ));
        }
        let origin = c.summits.iter().map(|s| s.height_m).sum::<f64>() / n as f64;
        let heights = c.summits.iter().map(|s| s.height_m - origin).collect();
        let radii = c.summits.iter().map(|s| 1.0 / s.curvature_per_m).collect();
        let population = Population::from_summits(heights, Radii::PerSummit(radii))?;
        let area = c.stats.candidates as f64 * c.pixel_size_m * c.pixel_size_y_m;
        Ok(MeasuredSummits {
            sum: MonteCarlo::new(Arc::new(population), law)?,
            factor: nominal_area / area,
            origin,
        })
    }

    /// The population (heights from the mean summit plane, ascending, with
    /// their radii).
    pub fn population(&self) -> &Population {
        self.sum.population()
    }

    /// `f`: nominal area over the area searched for summits.
    pub fn factor(&self) -> f64 {
        self.factor
    }

    /// The mean summit height above the map's mean plane (m): the origin of
    /// separations.
    pub fn origin_m(&self) -> f64 {
        self.origin
    }
}

impl LoadingModel for MeasuredSummits {
    /// `f` times the exact sum at `separation` after `history`.
    ///
    /// # Errors
    /// As [`MonteCarlo`]'s `state`.
    fn state(&self, separation: f64, history: History, observables: &Observables) -> Result<State> {
        Ok(self
            .sum
            .state(separation, history, observables)?
            .scaled(self.factor))
    }

    fn states(&self, steps: &[(f64, History)], observables: &Observables) -> Result<Vec<State>> {
        Ok(self
            .sum
            .states(steps, observables)?
            .iter()
            .map(|s| s.scaled(self.factor))
            .collect())
    }

    fn interaction_onset(&self) -> f64 {
        self.sum.interaction_onset()
    }

    fn separation_tolerance(&self) -> f64 {
        self.sum.separation_tolerance()
    }

    fn height_scale(&self) -> f64 {
        self.sum.height_scale()
    }

    fn load_tolerance(&self) -> f64 {
        self.sum.load_tolerance()
    }

    fn is_discrete(&self) -> bool {
        true
    }
}
