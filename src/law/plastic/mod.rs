//! Elastic-plastic asperities: a deformable sphere of radius `R` against a
//! rigid flat, loaded past first yield.
//!
//! | law | module | elastic up to | fully plastic beyond | jumps |
//! |---|---|---|---|---|
//! | Kogut–Etsion 2002 | [`kogut_etsion`] | `omega_c` | `110 omega_c` (`P = H A`) | load +3 %, +1.7 %, +8 % at `w = 1, 6, 110` |
//! | Jackson–Green 2005 | [`jackson_green`] | `1.9 omega_c` | none | small, at `w = 1.9` |
//! | Chang–Etsion–Bogy 1987 | [`chang_etsion_bogy`] | `omega_c` | `omega_c` (`P = K H A`) | load x1.5 at `w = 1` |
//! | Zhao–Maietta–Chang 2000 | [`zhao_maietta_chang`] | `omega_1` | `54 omega_1` (`P = H A`) | none (smooth blend) |
//!
//! Loading (`state(delta, _)`) follows the law's fit; the fit's
//! breakpoints (critical-interference multiples) are returned by
//! [`AsperityLaw::breakpoints`](crate::law::AsperityLaw::breakpoints) so quadrature splits there. After the
//! interference reached `delta_max`, [`AsperityLaw::state_after`](crate::law::AsperityLaw::state_after) unloads
//! (and reloads) elastically from the flattened shape with a residual
//! interference ([`unloading`]); [`AdhesivePlastic`] adds JKR adhesion on
//! that shape, so the pull-off grows with the maximum load reached.
//! [`diagnostics`] gives the plasticity index and the regime fractions.
//!
//! The material data these laws take (yield strength, hardness, the
//! yielding body's Poisson ratio, critical interferences, plasticity index)
//! are in [`crate::material::plastic`]; build them from a
//! [`Material`](crate::material::Material) with
//! [`Plasticity::of`](crate::material::plastic::Plasticity::of).
//!
//! Every law here scales with the radius as `delta ~ R`, `P ~ R^2`, `a ~ R`
//! at fixed `E*`, `Y`, `H` (its fit is in `w = delta/omega_c`, `omega_c ~ R`,
//! `P_c ~ R^2`), i.e. a Monte Carlo `RadiusScaling { interference: 1,
//! load: 2, contact_radius: 1 }`; the adhesive wrapper does not scale so.

pub mod adhesion;
pub mod chang_etsion_bogy;
pub mod diagnostics;
pub mod jackson_green;
pub mod kogut_etsion;
pub mod unloading;
pub mod zhao_maietta_chang;

pub use adhesion::AdhesivePlastic;
pub use chang_etsion_bogy::ChangEtsionBogy;
pub use diagnostics::{contact_fractions, elastic_law_warning, ElasticLawYields, RegimeFractions};
pub use jackson_green::JacksonGreen;
pub use kogut_etsion::KogutEtsion;
pub use unloading::{MaxInterference, Unloading};
pub use zhao_maietta_chang::ZhaoMaiettaChang;

use super::{ContactState, Hertz, LawKernels};
use crate::error::{positive, Result};
use crate::material::plastic::{Plasticity, RegimeLimits, Variant};
use std::fmt;
use std::sync::Arc;

/// Radius-scaling exponents `(interference, load, contact radius)` of every
/// non-adhesive law here: `(1, 2, 1)` (see the module notes).
pub const RADIUS_SCALING_EXPONENTS: (f64, f64, f64) = (1.0, 2.0, 1.0);

/// The virgin loading curve of an elastic-plastic law: what each variant
/// provides; [`AsperityLaw`](crate::law::AsperityLaw) (with unloading) is built on it.
pub trait PlasticLoading: Send + Sync + fmt::Debug {
    /// Which variant.
    fn variant(&self) -> Variant;
    /// The asperity: radius, modulus, plastic data.
    fn asperity(&self) -> &PlasticAsperity;
    /// Non-adhesive loading state at interference `delta` (m).
    fn loading(&self, delta: f64) -> ContactState;
    /// Critical interference (m): `omega_c` (`omega_1` for ZMC).
    fn critical_interference(&self) -> f64;
    /// Multiples of the critical interference where load or area jumps or
    /// kinks (ascending, > 0).
    fn breakpoint_multiples(&self) -> &'static [f64];

    /// Interference (m) up to which loading is exactly Hertz.
    fn elastic_limit(&self) -> f64 {
        self.variant().regime_multiples().0 * self.critical_interference()
    }

    /// Regime limits (m).
    fn regime_limits(&self) -> RegimeLimits {
        let (e, p) = self.variant().regime_multiples();
        let wc = self.critical_interference();
        RegimeLimits {
            elastic: e * wc,
            fully_plastic: p * wc,
        }
    }

    /// Interferences (m) where loading jumps or kinks: 0 and the multiples.
    fn breakpoint_interferences(&self) -> Vec<f64> {
        let wc = self.critical_interference();
        std::iter::once(0.0)
            .chain(self.breakpoint_multiples().iter().map(|m| m * wc))
            .collect()
    }

    /// Elastic unloading after the interference reached `delta_max` (m).
    fn unloading(&self, delta_max: f64) -> Unloading {
        if delta_max <= self.elastic_limit() {
            Unloading::elastic(self.asperity().radius)
        } else {
            Unloading::from_peak(
                delta_max,
                self.loading(delta_max),
                self.asperity().contact_modulus,
            )
        }
    }
}

/// The inputs every elastic-plastic law shares, validated once.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlasticAsperity {
    /// Sphere radius `R` (m).
    pub radius: f64,
    /// Contact modulus `E*` (Pa).
    pub contact_modulus: f64,
    /// Plastic data of the yielding body.
    pub plasticity: Plasticity,
    /// The Hertz law of the same sphere (the elastic range).
    pub hertz: Hertz,
}

impl PlasticAsperity {
    /// The state below the plastic range, shared by every fit: free for
    /// `delta <= 0`, Hertz for `0 < delta <= elastic_limit` (m); `None`
    /// beyond it, where the law's own fit applies.
    #[inline]
    pub fn elastic_state(&self, delta: f64, elastic_limit: f64) -> Option<ContactState> {
        if !(delta > 0.0) {
            return Some(ContactState::FREE);
        }
        (delta <= elastic_limit).then(|| ContactState {
            load: self.hertz.load_at(delta),
            radius: self.hertz.radius_at(delta),
        })
    }

    /// Radius `R` (m, > 0), contact modulus `E*` (Pa, > 0), plastic data.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `radius` or `contact_modulus`.
    pub fn new(radius: f64, contact_modulus: f64, plasticity: Plasticity) -> Result<Self> {
        positive("radius", radius)?;
        positive("contact_modulus", contact_modulus)?;
        Ok(PlasticAsperity {
            radius,
            contact_modulus,
            plasticity,
            hertz: Hertz::new(radius, contact_modulus)?,
        })
    }

    /// Critical interference (m) of `variant`.
    pub fn critical_interference(&self, variant: Variant) -> f64 {
        self.plasticity
            .critical_interference(variant, self.radius, self.contact_modulus)
    }
}

/// Builds the non-adhesive law of `variant`.
///
/// # Errors
/// As [`PlasticAsperity::new`].
pub fn build(
    variant: Variant,
    radius: f64,
    contact_modulus: f64,
    plasticity: Plasticity,
) -> Result<Arc<dyn PlasticLaw>> {
    let a = PlasticAsperity::new(radius, contact_modulus, plasticity)?;
    Ok(match variant {
        Variant::KogutEtsion => Arc::new(KogutEtsion::from_asperity(a)),
        Variant::JacksonGreen => Arc::new(JacksonGreen::from_asperity(a)),
        Variant::ChangEtsionBogy => Arc::new(ChangEtsionBogy::from_asperity(a)),
        Variant::ZhaoMaiettaChang => Arc::new(ZhaoMaiettaChang::from_asperity(a)),
    })
}

/// An elastic-plastic law usable both as an [`AsperityLaw`](crate::law::AsperityLaw) (with its
/// [`LawKernels`]) and through its loading curve.
pub trait PlasticLaw: LawKernels + PlasticLoading {
    /// Upcast to the law with its kernels (what integrators hold).
    fn as_law(self: Arc<Self>) -> Arc<dyn LawKernels>;
    /// Upcast to the loading trait.
    fn as_loading(self: Arc<Self>) -> Arc<dyn PlasticLoading>;
}

/// The constructor `new(radius, contact_modulus, plasticity)` every
/// variant has: a validated [`PlasticAsperity`], then the variant's own
/// `from_asperity`.
macro_rules! plastic_constructor {
    () => {
        /// Radius `R` (m), contact modulus `E*` (Pa), plastic data of the
        /// yielding body.
        ///
        /// # Errors
        /// [`crate::Error::OutOfRange`] naming `radius` or `contact_modulus`.
        pub fn new(radius: f64, contact_modulus: f64, plasticity: Plasticity) -> Result<Self> {
            Ok(Self::from_asperity(PlasticAsperity::new(
                radius,
                contact_modulus,
                plasticity,
            )?))
        }
    };
}
pub(crate) use plastic_constructor;

/// The [`PlasticLoading`] methods every variant writes alike: its
/// `variant`, its `asperity` field, its critical interference (the field
/// `critical`) and its module's `BREAKPOINTS`.
macro_rules! plastic_loading_accessors {
    ($variant:expr, $critical:ident) => {
        fn variant(&self) -> Variant {
            $variant
        }

        fn asperity(&self) -> &PlasticAsperity {
            &self.asperity
        }

        fn critical_interference(&self) -> f64 {
            self.$critical
        }

        fn breakpoint_multiples(&self) -> &'static [f64] {
            &BREAKPOINTS
        }
    };
}
pub(crate) use plastic_loading_accessors;

/// Implements [`AsperityLaw`](crate::law::AsperityLaw), [`LawKernels`] and [`PlasticLaw`] for a [`PlasticLoading`]:
/// loading on both branches, elastic unloading from the flattened shape via
/// `state_after`, no adhesion.
macro_rules! plastic_asperity_law {
    ($t:ty) => {
        impl $crate::law::AsperityLaw for $t {
            fn name(&self) -> &'static str {
                $crate::law::plastic::PlasticLoading::variant(self).name()
            }

            #[inline]
            fn state(&self, delta: f64, _branch: $crate::law::Branch) -> $crate::law::ContactState {
                $crate::law::plastic::PlasticLoading::loading(self, delta)
            }

            #[inline]
            fn state_after(&self, delta: f64, delta_max: f64) -> $crate::law::ContactState {
                $crate::law::plastic::unloading::state_after(self, delta, delta_max)
            }

            fn history_breakpoints(&self) -> Vec<f64> {
                $crate::law::plastic::PlasticLoading::breakpoint_interferences(self)
            }

            fn contact_loss_peaks(&self, recovery: f64) -> Vec<f64> {
                $crate::law::plastic::unloading::contact_loss_peaks(self, recovery)
            }

            /// Hertz below the first breakpoint, powers of `delta` (smooth
            /// in `sqrt(delta)` away from 0) between the others.
            fn smooth_in_root(&self) -> bool {
                true
            }

            /// The flattening is permanent: unloading depends on `delta_max`.
            fn remembers_maximum(&self) -> bool {
                true
            }

            /// Interferences scale with `R` (the critical interference is
            /// proportional to `R`), loads with `R^2`, areas with `R^2`.
            fn radius_scaling(&self) -> Option<$crate::law::RadiusScaling> {
                Some($crate::law::RadiusScaling::PLASTIC)
            }

            critical_at_first_contact!();

            fn breakpoints(&self, _branch: $crate::law::Branch) -> Vec<f64> {
                $crate::law::plastic::PlasticLoading::breakpoint_interferences(self)
            }

            fn pull_off(&self, control: $crate::law::Control) -> Option<$crate::law::Instability> {
                match control {
                    $crate::law::Control::Load => Some($crate::law::Instability {
                        load: 0.0,
                        interference: 0.0,
                        radius: 0.0,
                    }),
                    $crate::law::Control::Displacement => None,
                }
            }

            fn zero_load_radius(&self) -> Option<f64> {
                None
            }
        }

        impl $crate::law::LawKernels for $t {
            /// Elastic unloading of the flattened shape: the load rises
            /// with the interference, zero below the residual one.
            fn retraction_minimum(
                &self,
                _delta_max: f64,
            ) -> Option<$crate::law::RetractionMinimum> {
                Some($crate::law::RetractionMinimum::MONOTONE)
            }

            /// Measured: a Monte Carlo retraction sum of Kogut–Etsion summits
            /// costs about 42 ns per summit (docs/performance.md).
            fn cost_ns(&self) -> f64 {
                42.0
            }
        }

        impl $crate::law::plastic::PlasticLaw for $t {
            fn as_law(self: std::sync::Arc<Self>) -> std::sync::Arc<dyn $crate::law::LawKernels> {
                self
            }
            fn as_loading(
                self: std::sync::Arc<Self>,
            ) -> std::sync::Arc<dyn $crate::law::plastic::PlasticLoading> {
                self
            }
        }
    };
}
pub(crate) use plastic_asperity_law;

#[cfg(test)]
mod tests;
