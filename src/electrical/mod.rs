//! Electrical contact of rough surfaces: constriction resistance of the
//! contact spots, their interaction, contact heating and the stiction
//! margin of an ohmic MEMS switch (physics.md, "Contact resistance").
//!
//! - [`spot`]: one spot (Maxwell/Holm, Sharvin, Wexler; two metals; film).
//! - [`interaction`]: many spots in parallel and Greenwood's mean-field
//!   interaction from their sums.
//! - [`observable`]: the spot conductance as a per-asperity observable, so
//!   the GW integral and the Monte Carlo sum give the resistance of any law
//!   on any surface, and the resistance, contact voltage and temperature as
//!   derived quantities of a state.
//! - [`spots`]: explicit spots (parallel, Greenwood 1966, exact
//!   equal-potential solve).
//! - [`heating`]: Holm's phi-theta relation with Wiedemann–Franz.
//! - [`switch`]: restoring force against pull-off.
//!
//! ```
//! use asperity::electrical::{SpotResistance, Spreading};
//! // One gold spot of radius 100 nm: Wexler between Maxwell and Maxwell + Sharvin.
//! let w = SpotResistance::same_metal(Spreading::Wexler, 2.44e-8, Some(3.46e-8))?;
//! let r = w.resistance(1e-7);
//! assert!(r > 2.44e-8 / 2e-7);
//! # Ok::<(), asperity::Error>(())
//! ```

pub mod heating;
pub mod interaction;
pub mod observable;
pub mod sample;
pub mod spot;
pub mod spots;
pub mod switch;

pub use heating::{Heating, SpotWarning};
pub use interaction::{greenwood_mean_field, ContactResistance, Interaction, SpotSums, C_SQ};
pub use observable::{ContactHeating, ResistanceObservables, SpotConductance};
pub use sample::{population_spots, SampleResistance, EXACT_MAX_SPOTS};
pub use spot::{Conductor, SpotResistance, Spreading};
pub use spots::{Merged, Spots};
pub use switch::{Stiction, StictionOdds, Switch};
