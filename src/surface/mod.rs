//! From a measured height map to the rough-contact model.
//!
//! A height map (`HeightMap`: rows x cols heights in metres, row-major)
//! comes from a reader (`npy` for NumPy `.npy`, `text` for whitespace- or
//! comma-separated matrices); both parse from memory, never from a path, so
//! the core opens no files. [`Topography`] binds the map to its pixel size and
//! [`Topography::characterise`] fits the mean plane (one pass over the map)
//! and then, in one fused pass over the residual rows (made block by block,
//! no map-sized temporary; parallel over fixed row blocks, the same result
//! on any number of threads), measures:
//!
//! - the profile moments `m0, m2, m4` by finite differences and Nayak's
//!   bandwidth `alpha = m0 m4 / m2^2` ([`Moments`]);
//! - the summits, pixels strictly higher than their 8 neighbours, with the
//!   5-point-Laplacian curvature ([`Summit`], [`SummitStats`]);
//! - the GW parameters predicted from the moments by Nayak's and McCool's
//!   relations ([`GwParameters`], [`NayakPrediction`]) and the plasticity index.
//!
//! Definitions (`docs/physics.md`, "Surface characterisation"): x runs along
//! a row (column index j), y down the columns (row index i), both in steps
//! of the pixel size `dx`. Phase 2 (scenes) uses a [`Characterisation`] two
//! ways: its `summits` as a measured population (own heights and radii), or
//! [`Characterisation::gw_from_moments`].
//!
//! [`synthetic`] makes isotropic Gaussian surfaces with a known spectrum for
//! the acceptance tests and the grid-bias table.

mod characterise;
mod map;
mod moments;
mod nayak;
pub mod npy;
mod plane;
mod scan;
mod summits;
pub mod synthetic;
pub mod text;

pub use characterise::{Characterisation, Topography, MAX_HEIGHT, PIXEL_SIZE_RANGE};
pub use map::{HeightMap, HeightSource, Heights};
pub use moments::Moments;
pub use nayak::{GwParameters, NayakPrediction, MCCOOL_HEIGHT_CONSTANT, NAYAK_HEIGHT_CONSTANT};
pub use plane::Plane;
pub use summits::{Summit, SummitStats};
