//! Greenwood–Williamson statistical integration: one single-asperity law
//! over one summit-height distribution gives the load, real contact area and
//! number of contacts of a rough surface against a flat, on approach and on
//! retraction (adhesive hysteresis).
//!
//! - [`RoughSurface`]: summit density, radius, height scale, nominal area.
//! - [`GwModel`]: surface + distribution + law; [`GwModel::state`] at one
//!   separation, [`GwModel::curve`] over a [`LoadingProgram`],
//!   [`GwModel::pull_off`].
//! - [`dimensionless`]: Fuller–Tabor's adhesion parameter and friends.

pub mod dimensionless;
mod model;
mod program;
mod surface;

pub use model::{Accuracy, GwModel, GwState, History, Method, MethodUsed, Outputs};
pub(crate) use program::{hysteresis_energy, most_tensile};
pub use program::{Curve, LoadingProgram, PullOff};
pub use surface::RoughSurface;

#[cfg(test)]
mod tests;
