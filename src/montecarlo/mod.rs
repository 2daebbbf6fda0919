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
//! - [`SummitLaw`]: a law plus its [`RadiusScaling`], so one law object
//!   serves every radius.
//! - [`MonteCarlo`]: population + law; [`MonteCarlo::state`] at one
//!   separation after a [`History`](crate::gw::History),
//!   [`MonteCarlo::curve`] over a [`LoadingProgram`](crate::gw::LoadingProgram),
//!   with standard errors ([`McState`]); [`MonteCarlo::sequence`] for any
//!   path of separations (per-summit attach state);
//!   [`MonteCarlo::separation_for_load`] for load-limited programs;
//!   [`McState::deviation_from`] for z-scores against a
//!   [`GwState`](crate::gw::GwState).
//!
//! Laws are summed exactly as [`GwModel`](crate::gw::GwModel) integrates
//! them (same heights origin, same `state`/`state_after` calls), so a
//! population drawn from the model's distribution with `N = eta A_n`
//! summits is an unbiased estimate of the GW totals.
//!
//! ```
//! use asperity::gw::{History, Outputs};
//! use asperity::heights::Exponential;
//! use asperity::law::Hertz;
//! use asperity::montecarlo::*;
//! use std::sync::Arc;
//! let spec = PopulationSpec::new(10_000, 5e-9, RadiusSpec::Fixed(1e-6), 42)?;
//! let pop = Arc::new(Population::sample(&spec, &Exponential::new())?);
//! let law = SummitLaw::scaled(Arc::new(Hertz::new(1e-6, 5e10)?), 1e-6, RadiusScaling::MAUGIS)?;
//! let mc = MonteCarlo::new(pop, law)?;
//! let s = mc.state(1e-8, History::Approach, Outputs::ALL)?;
//! // Exponential heights: E[count] = N e^(-d/sigma) = 1353, SE ~ 35.
//! let n = s.count.unwrap();
//! assert!((n - 1e4 * (-2.0f64).exp()).abs() < 5.0 * s.standard_error[2]);
//! # Ok::<(), asperity::Error>(())
//! ```

mod population;
mod scaling;
mod summation;

pub use population::{Population, PopulationSpec, Radii, RadiusSpec, MAX_SUMMITS, SAMPLING_BLOCK};
pub use scaling::{RadiusScaling, SummitLaw};
pub use summation::{McCurve, McState, MonteCarlo, SUM_BLOCK};

#[cfg(test)]
mod tests;
