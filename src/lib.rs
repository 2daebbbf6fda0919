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
#![forbid(unsafe_code)]
// `!(x > y)` is the NaN-safe test this crate uses on purpose: NaN fails it.
#![allow(clippy::neg_cmp_op_on_partial_ord)]
// Constants keep the digits of their published or mpmath source.
#![allow(clippy::excessive_precision)]

pub mod axisym;
pub mod electrical;
pub mod error;
pub mod gw;
pub mod heights;
pub mod law;
pub mod loading;
pub mod material;
pub mod montecarlo;
pub mod numeric;
pub mod punch;
pub mod roughsphere;
pub mod special;
pub mod sphere;
#[cfg(feature = "study")]
pub mod study;
pub mod surface;

pub use error::{Error, Result};

/// The types most programs need.
pub mod prelude {
    #[doc(no_inline)]
    pub use crate::error::{Error, Result};
    #[doc(no_inline)]
    pub use crate::law::{AsperityLaw, Branch, ContactState, Control, Instability, LawKind};
    #[doc(no_inline)]
    pub use crate::material::{contact_modulus, Adhesion, AsperityContact, Material, MaugisScales};
}
