//! Greenwood–Williamson statistical integration: one single-asperity law
//! over one summit-height distribution gives the load, real contact area and
//! number of contacts of a rough surface against a flat, on approach and on
//! retraction (adhesive hysteresis).
//!
//! - [`RoughSurface`]: summit density, radius, height scale, nominal area.
//! - [`GwModel`]: surface + distribution + law + [`Accuracy`]; a
//!   [`LoadingModel`](crate::loading::LoadingModel): `state` at one
//!   separation, `curve` over a [`LoadingProgram`](crate::loading::LoadingProgram),
//!   `pull_off`, `separation_at_load` (the loading vocabulary of
//!   [`crate::loading`], shared with Monte Carlo populations).
//! - [`dimensionless`]: Fuller–Tabor's adhesion parameter and friends.
//! - [`GwOnMoments`]: GW on a surface's spectral moments (McCool's
//!   parameters, Hertz summits, Gaussian heights) at a mean pressure, with
//!   the mean gap from the summit caps' volume, [`CapVolume`] (`spectral.rs`).

pub mod dimensionless;
mod model;
mod spectral;
mod surface;
pub mod validity;

pub use model::{Accuracy, GwModel, Method, REACH_CEILING_SIGMAS, REACH_FLOOR_SIGMAS};
pub use spectral::{CapVolume, GwOnMoments, GwPressureState};
pub use surface::RoughSurface;

#[cfg(test)]
mod tests;
