//! DMT for an axisymmetric profile: the Sneddon (non-adhesive) contact plus
//! the adhesive force of the long-range interaction outside it, which in the
//! DMT (long-range) limit acts on the undeformed profile:
//!
//! ```text
//! delta = delta_0(a),   F = F_0(a) - 2 pi w R_apex
//! ```
//!
//! Valid only for the paraboloid (and what is locally one: the true sphere
//! for `a << R`, the power law `n = 2`); Barthel (2008, section 5.3):
//! with a Dugdale stress `sigma0` of range `h0 = w/sigma0`, the force outside
//! the contact is `pi sigma0 r_h^2` with `f(r_h) = h0`, which is
//! `2 pi w R` for the paraboloid whatever the range, but grows without bound
//! as the range grows for the cone (`pi w h0 / tan^2 beta`) and falls to zero
//! for `n > 2` (`pi w h0^(2/n - 1) / A^(2/n)`). "Except in the case of the
//! paraboloid, it is physically impossible to assume that the interaction
//! zone spreads out far away from the contact zone": other shapes need the
//! intermediate-range (Maugis–Dugdale) description or JKR. Pull-off
//! `-2 pi w R_apex` at `a = 0`.

use super::profile::Profile;
use crate::error::{positive, Error, Result};
use std::f64::consts::PI;

/// DMT contact of a profile with an apex curvature.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisymDmt {
    profile: Profile,
    estar: f64,
    force: f64,
}

impl AxisymDmt {
    /// Builds the contact.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `profile` for profiles without a finite
    /// apex curvature (the reason says why DMT does not apply);
    /// [`Error::OutOfRange`] naming `contact_modulus` or `work_of_adhesion`.
    pub fn new(profile: Profile, contact_modulus: f64, work: f64) -> Result<Self> {
        let estar = positive("contact_modulus", contact_modulus)?;
        let work = crate::error::non_negative("work_of_adhesion", work)?;
        let r = profile.apex_radius().ok_or_else(|| {
            Error::invalid(
                "profile",
                format!(
                    "DMT holds only for a paraboloid apex (paraboloid, sphere, power n = 2); \
                     the long-range force outside a {} profile's contact depends on the range \
                     (it diverges for the cone, vanishes for n > 2; Barthel 5.3): use JKR",
                    profile.name()
                ),
            )
        })?;
        Ok(AxisymDmt {
            profile,
            estar,
            force: 2.0 * PI * work * r,
        })
    }

    /// Interference `delta_0(a)` (m).
    pub fn interference(&self, a: f64) -> f64 {
        self.profile.delta0(a)
    }

    /// Load `F_0(a) - 2 pi w R_apex` (N).
    pub fn load(&self, a: f64) -> f64 {
        self.profile.load0(a, self.estar) - self.force
    }

    /// Pull-off `-2 pi w R_apex` (N), at zero contact radius.
    pub fn pull_off(&self) -> f64 {
        -self.force
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dmt_exists_only_with_an_apex_curvature() {
        let d = AxisymDmt::new(Profile::paraboloid(1e-6).unwrap(), 1e9, 0.1).unwrap();
        assert!((d.pull_off() + 2.0 * PI * 0.1 * 1e-6).abs() < 1e-20);
        let p = AxisymDmt::new(Profile::power(0.5e6, 2.0).unwrap(), 1e9, 0.1).unwrap();
        assert!((p.load(1e-7) - d.load(1e-7)).abs() < 1e-12 * d.load(1e-7).abs());
        for bad in [Profile::cone(0.1).unwrap(), Profile::flat(1e-6).unwrap()] {
            let e = AxisymDmt::new(bad, 1e9, 0.1).unwrap_err();
            assert_eq!(e.field(), Some("profile"));
        }
    }
}
