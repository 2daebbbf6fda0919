//! The loading vocabulary shared by every rough-contact model: programs and
//! the history rule, observables and their totals, states, curves, and the
//! searches (pull-off, separation at a load) written once for the
//! Greenwood–Williamson integral ([`crate::gw`]) and Monte Carlo populations
//! ([`crate::montecarlo`]).

mod curve;
mod hysteresis;
mod model;
pub(crate) mod observable;
mod program;
mod state;

pub use curve::{hysteresis_energy, most_tensile, Curve, PullOff};
pub use hysteresis::hysteresis_energy_to;
pub use model::LoadingModel;
pub use observable::{Derived, Observable, Observables, PerAsperity, Totals, EXTRA_SLOTS, SLOTS};
pub use program::{History, LoadingProgram};
pub use state::{MethodUsed, State};
