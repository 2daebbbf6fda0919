//! # asperity
//!
//! Adhesive contact between rough surfaces: single-asperity laws (Hertz,
//! Bradley, DMT, JKR, Maugis–Dugdale, ...), their statistical integration
//! over summit heights (Greenwood–Williamson and its adhesive extensions), and
//! the full single-sphere Lennard-Jones solver that calibrates them.
//!
//! SI units throughout the API; dimensionless helpers say so in their names
//! (`*_bar`) and documentation. Sign conventions: interference `delta > 0`
//! when the undeformed bodies would overlap; load `P > 0` compressive,
//! `P < 0` tensile.
//!
//! ```
//! use asperity::prelude::*;
//!
//! // A gold microswitch asperity: R = 1 um, E* = 48 GPa, w = 0.5 J/m^2.
//! let contact = AsperityContact::gold_microswitch();
//! let jkr = LawKind::Jkr.build(&contact)?;
//! let pull = jkr.pull_off(Control::Load).unwrap();
//! // JKR pull-off: -(3/2) pi w R = -2.36 uN.
//! assert!((pull.load + 1.5 * std::f64::consts::PI * 0.5 * 1e-6).abs() < 1e-18);
//! # Ok::<(), asperity::Error>(())
//! ```
#![deny(missing_docs)]
// One module maps files into memory (`topography::mapped`, its one `unsafe`
// block allowed there with its reasons); nothing else may use `unsafe`.
#![deny(unsafe_code)]
// `!(x > y)` is the NaN-safe test this crate uses on purpose: NaN fails it.
#![allow(clippy::neg_cmp_op_on_partial_ord)]
// Constants keep the digits of their published or mpmath source.
#![allow(clippy::excessive_precision)]

pub mod axisym;
pub mod bem;
pub mod cancel;
pub mod capillary;
#[cfg(feature = "study")]
pub mod commands;
pub mod electrical;
pub mod error;
pub mod gw;
pub mod heights;
pub mod law;
pub mod loading;
pub mod material;
pub mod montecarlo;
pub mod named;
pub mod numeric;
pub mod persson;
pub mod punch;
pub mod roughsphere;
pub mod special;
pub mod spectrum;
pub mod sphere;
pub mod stickiness;
#[cfg(feature = "study")]
pub mod study;
pub mod surface;
#[cfg(test)]
mod test_threads;
#[cfg(feature = "study")]
pub mod topography;

pub use error::{Error, Result};

/// The crate's version (`Cargo.toml`), e.g. `0.1.0`.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

/// The types most programs need: one asperity and its laws (elastic,
/// elastic-plastic, with adhesion); a GW surface with any law and its
/// curve; populations; the contact resistance against force and the
/// stiction margin of a switch; measured maps.
///
/// ```
/// use asperity::prelude::*;
/// use std::sync::Arc;
///
/// // A gold switch: Hertz summits, Maxwell spots, the load and resistance
/// // of the surface 5 nm above its mean summit plane.
/// let contact = AsperityContact::gold_microswitch();
/// let law: Arc<dyn LawKernels> = Arc::from(LawKind::Hertz.build(&contact)?);
/// let model = GwModel::new(RoughSurface::gold_microswitch(), Arc::new(Gaussian::new()), law)?;
/// let spot = SpotResistance::same_metal(Spreading::Maxwell, 2.44e-8, None)?;
/// let r = ResistanceObservables::new(spot, Interaction::None, 1e-4);
/// let outputs = r.add_to(Observables::LOAD)?;
/// let s = model.state(5e-9, History::Approach, &outputs)?;
/// let ohm = r.value(&outputs, &s.totals).unwrap();
/// assert!(s.load().unwrap() > 0.0 && ohm > 0.0);
/// # Ok::<(), asperity::Error>(())
/// ```
///
/// A switch study with the prelude alone: contact resistance against the
/// actuation force (each force's separation solved on approach), then the
/// stiction margin of a 10 N/m spring over 2 um of travel after pressing
/// to 1 mN. Elastic-plastic summits with adhesion ([`AdhesivePlastic`](crate::law::plastic::AdhesivePlastic)
/// over [`build_plastic`](crate::law::plastic::build)) are one line away
/// from the JKR law used here.
///
/// ```
/// use asperity::prelude::*;
/// use std::sync::Arc;
///
/// let contact = AsperityContact::gold_microswitch();
/// let law: Arc<dyn LawKernels> = Arc::from(LawKind::Jkr.build(&contact)?);
/// let surface = RoughSurface::gold_microswitch();
/// let model = GwModel::new(surface, Arc::new(Gaussian::new()), law)?;
/// let spot = SpotResistance::new(Spreading::Wexler, Conductor::GOLD, Conductor::GOLD, 0.0)?;
/// let r = ResistanceObservables::new(spot, Interaction::Greenwood, surface.nominal_area.sqrt());
/// let outputs = r.add_to(Observables::LOAD)?;
/// let start = model.start_separation(1e-8);
/// let mut last = f64::INFINITY;
/// for force in [1e-5, 1e-4, 1e-3] {
///     let d = model.separation_at_load(force, start)?;
///     let s = model.state(d, History::Approach, &outputs)?;
///     let ohm = r.value(&outputs, &s.totals).unwrap();
///     assert!((s.load().unwrap() - force).abs() < 1e-6 * force);
///     assert!(ohm < last, "resistance falls as the force grows");
///     last = ohm;
/// }
/// let closest = model.separation_at_load(1e-3, start)?;
/// let pull = model.pull_off(closest, start, 64)?.map_or(0.0, |p| p.load);
/// let verdict = Switch::new(10.0, 2e-6)?.stiction(pull)?;
/// assert_eq!(verdict.sticks, verdict.margin < 0.0);
/// # Ok::<(), asperity::Error>(())
/// ```
pub mod prelude {
    #[doc(no_inline)]
    pub use crate::electrical::{
        Conductor, Heating, Interaction, ResistanceObservables, SpotResistance, Spreading, Switch,
    };
    #[doc(no_inline)]
    pub use crate::error::{Error, Result};
    #[doc(no_inline)]
    pub use crate::gw::{Accuracy, GwModel, Method, RoughSurface};
    #[doc(no_inline)]
    pub use crate::heights::{DistributionKind, Exponential, Gaussian, HeightDistribution};
    #[doc(no_inline)]
    pub use crate::law::plastic::{
        build as build_plastic, AdhesivePlastic, PlasticLaw, PlasticLoading,
    };
    #[doc(no_inline)]
    pub use crate::law::{
        AsperityLaw, Branch, ContactState, Control, Instability, InstabilityBar, LawKernels,
        LawKind,
    };
    #[doc(no_inline)]
    pub use crate::loading::{
        Curve, Derived, History, LoadingModel, LoadingProgram, Observable, Observables, PullOff,
        State,
    };
    #[doc(no_inline)]
    pub use crate::material::plastic::{plasticity_index, Plasticity, Variant};
    #[doc(no_inline)]
    pub use crate::material::{contact_modulus, Adhesion, AsperityContact, Material, MaugisScales};
    #[doc(no_inline)]
    pub use crate::montecarlo::{MonteCarlo, Population, PopulationSpec, RadiusSpec, SummitLaw};
    #[doc(no_inline)]
    pub use crate::named::Named;
    #[doc(no_inline)]
    pub use crate::surface::{Characterisation, HeightMap, Topography};
}
