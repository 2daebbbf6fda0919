//! Adhesive contact of any axisymmetric profile against a flat (Barthel,
//! Barthel 2008): Sneddon's non-adhesive solution for the
//! profile, then JKR (short-range) adhesion as a crack at the contact edge.
//!
//! - [`profile`]: the profiles (paraboloid, true sphere, cone, flat punch,
//!   power law, table) with `delta_0(a)` and `F_0(a)`.
//! - [`tabulated`]: a measured profile, validated and PCHIP-interpolated.
//! - [`jkr`]: JKR for any profile in load and displacement control.
//! - [`sphere_exact`]: Maugis' exact-sphere closed forms and the `a/R > 0.3`
//!   warning.
//! - [`dmt`]: DMT where it is valid (finite apex curvature).
//! - [`md`]: Maugis–Dugdale for any profile (Barthel's cohesive-zone form).
//!
//! Conventions as the rest of the crate: SI units, `delta > 0` overlap,
//! load `< 0` tensile; Barthel's `calK = E*/2`. The rough-surface law built
//! on these is [`crate::law::shaped`].

/// The accessors of an adhesive contact of one profile (fields `profile`,
/// `estar`, `work`): [`AxisymJkr`] and [`AxisymMd`].
macro_rules! adhesive_profile_accessors {
    () => {
        /// The profile.
        pub fn profile(&self) -> &Profile {
            &self.profile
        }

        /// Contact modulus `E*` (Pa).
        pub fn contact_modulus(&self) -> f64 {
            self.estar
        }

        /// Work of adhesion `w` (J/m^2).
        pub fn work(&self) -> f64 {
            self.work
        }
    };
}

pub mod dmt;
pub mod jkr;
pub mod md;
pub mod profile;
pub mod sphere_exact;
pub mod tabulated;

pub use dmt::AxisymDmt;

/// A point where an axisymmetric adhesive contact snaps or is pulled off.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Instability {
    /// Load at the instability (N), on the attached side.
    pub load: f64,
    /// Interference at the instability (m).
    pub interference: f64,
    /// Contact radius on the attached side (m).
    pub radius: f64,
}
pub use jkr::AxisymJkr;
pub use md::{AxisymMd, MdPoint};
pub use profile::{Profile, ProfileKind, ProfileParams};
pub use tabulated::TabulatedProfile;
