//! Monte Carlo summit populations: draw `N` summits, sum a single-asperity
//! law over them exactly, and report the statistical error of each total
//! against the Greenwood–Williamson expectation ([`crate::gw::GwModel`]).
//!
//! What GW cannot do and this can: per-summit radii (lognormal),
//! one realisation of a finite surface (its scatter about the mean),
//! measured summit lists.
//!
//! - [`PopulationSpec`] / [`Population`]: draw heights from any
//!   [`HeightDistribution`](crate::heights::HeightDistribution) (exact sorted
//!   order statistics, seeded, thread-count independent), optional
//!   lognormal radii ([`RadiusSpec`]).
//! - [`SummitLaw`]: a law plus its [`RadiusScaling`](crate::law::RadiusScaling), so one law object
//!   serves every radius.
//! - [`MonteCarlo`]: population + law, a
//!   [`LoadingModel`](crate::loading::LoadingModel) like
//!   [`GwModel`](crate::gw::GwModel): `state` at one separation after a
//!   [`History`](crate::loading::History), `curve` over a
//!   [`LoadingProgram`](crate::loading::LoadingProgram), `separation_at_load`,
//!   with standard errors as the states' uncertainties;
//!   [`MonteCarlo::sequence`] for any path of separations (per-summit attach
//!   state); [`State::deviation_from`](crate::loading::State::deviation_from)
//!   for z-scores against the integral.
//!
//! Laws are summed exactly as [`GwModel`](crate::gw::GwModel) integrates
//! them (same heights origin, same `state`/`state_after` calls), so a
//! population drawn from the model's distribution with `N = eta A_n`
//! summits is an unbiased estimate of the GW totals.
//!
//! ```
//! use asperity::loading::{History, LoadingModel, Observables};
//! use asperity::heights::Exponential;
//! use asperity::law::{Hertz, RadiusScaling};
//! use asperity::montecarlo::*;
//! use std::sync::Arc;
//! let spec = PopulationSpec::new(10_000, 5e-9, RadiusSpec::Fixed(1e-6), 42)?;
//! let pop = Arc::new(Population::sample(&spec, &Exponential::new())?);
//! let law = SummitLaw::scaled(Arc::new(Hertz::new(1e-6, 5e10)?), 1e-6, RadiusScaling::MAUGIS)?;
//! let mc = MonteCarlo::new(pop, law)?;
//! let s = mc.state(1e-8, History::Approach, &Observables::ALL)?;
//! // Exponential heights: E[count] = N e^(-d/sigma) = 1353, SE ~ 35.
//! let n = s.count().unwrap();
//! assert!((n - 1e4 * (-2.0f64).exp()).abs() < 5.0 * s.totals.error(2).unwrap());
//! # Ok::<(), asperity::Error>(())
//! ```

mod comparison;
mod measured;
mod population;
pub mod pull_off;
pub mod quantiles;
mod scaling;
mod summation;

pub use comparison::{contacts_of, Comparison, MIN_SUMMITS_FOR_Z};
pub use measured::MeasuredSummits;
pub use population::{Population, PopulationSpec, Radii, RadiusSpec, MAX_SUMMITS, SAMPLING_BLOCK};
pub use scaling::{table_tolerance, SummitLaw, TABLE_TOLERANCE_FRACTION};
pub use summation::{MonteCarlo, RetractionBounds, CHUNK, LANES, SERIAL_BELOW, SUM_BLOCK};

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_batch;
