//! Derjaguin–Muller–Toporov: Hertz deformation plus a constant adhesive pull
//! `2 pi w R` acting outside the contact (Maugis' rigid limit, `lambda -> 0`).
//!
//! `a^2 = R delta`, `P = K a^3/R - 2 pi w R` for `delta >= 0`; zero for
//! `delta < 0`. In Maugis units `Pbar = Dbar^(3/2) - 2`, `A = Dbar^(1/2)`.
//!
//! The force jumps from 0 to `-2 pi w R` at `delta = 0` on approach and back
//! at `delta = 0` on retraction, so the law itself has no hysteresis: the
//! jump-in and the jump-out are the same point. (The attraction of an
//! asperity just out of contact is the `lambda -> 0` limit of the
//! Maugis–Dugdale non-contact branch; use that law when it matters.)

use super::{AsperityLaw, Branch, ContactState, Control, Instability, LawKernels, PowerForm};
use crate::error::Result;
use crate::material::MaugisScales;
use std::f64::consts::PI;

/// `A0 = 2^(1/3)`: DMT contact radius at zero load (Maugis units).
pub const ZERO_LOAD_RADIUS: f64 = 1.259_921_049_894_873_2;

/// DMT law for a sphere of radius `R` (m), contact modulus `E*` (Pa) and
/// work of adhesion `w` (J/m^2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dmt {
    scales: MaugisScales,
    /// `(4/3) E* R^(1/2)` (N/m^(3/2)).
    stiffness: f64,
    radius: f64,
}

impl Dmt {
    /// All arguments finite and > 0.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `radius`, `contact_modulus` or
    /// `work_of_adhesion`.
    pub fn new(radius: f64, contact_modulus: f64, work: f64) -> Result<Self> {
        Ok(Dmt {
            scales: MaugisScales::new(radius, contact_modulus, work)?,
            stiffness: 4.0 / 3.0 * contact_modulus * radius.sqrt(),
            radius,
        })
    }

    /// The Maugis scales of this contact.
    pub fn scales(&self) -> MaugisScales {
        self.scales
    }
}

impl AsperityLaw for Dmt {
    identity_of_kind!(Dmt);

    #[inline]
    fn state(&self, delta: f64, _branch: Branch) -> ContactState {
        if delta >= 0.0 {
            ContactState {
                load: self.stiffness * delta * delta.sqrt() - 2.0 * self.scales.load,
                radius: (self.radius * delta).sqrt(),
            }
        } else {
            ContactState::FREE
        }
    }

    /// The branch is ignored: no hysteresis, no memory.
    fn reversible(&self) -> bool {
        true
    }

    critical_at_first_contact!();

    fn breakpoints(&self, _branch: Branch) -> Vec<f64> {
        vec![0.0]
    }

    /// Both controls: `-2 pi w R` at `delta = 0`, where the contact radius
    /// reaches zero and the force drops to zero (a snap under displacement
    /// control).
    fn pull_off(&self, _control: Control) -> Option<Instability> {
        Some(Instability {
            load: -2.0 * self.scales.load,
            interference: 0.0,
            radius: 0.0,
        })
    }

    fn zero_load_radius(&self) -> Option<f64> {
        Some(ZERO_LOAD_RADIUS * self.scales.radius)
    }

    /// `P = (4/3) E* R^(1/2) delta^(3/2) - 2 pi w R`, `pi a^2 = pi R delta`.
    fn power_form(&self) -> Option<PowerForm> {
        Some(PowerForm {
            onset: 0.0,
            load: vec![(self.stiffness, 1.5), (-2.0 * self.scales.load, 0.0)],
            area: vec![(PI * self.radius, 1.0)],
        })
    }
}

impl LawKernels for Dmt {
    fn cost_ns(&self) -> f64 {
        super::LawKind::Dmt.cost_ns()
    }

    /// `-2 pi w R` at `delta = 0`; Hertz's rise above, free below.
    fn retraction_minimum(&self, _delta_max: f64) -> Option<super::RetractionMinimum> {
        Some(super::RetractionMinimum {
            interference: 0.0,
            load: -2.0 * self.scales.load,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dimensionless_form_and_zero_load_radius() {
        let dmt = Dmt::new(2e-6, 3e10, 0.2).unwrap();
        let s = dmt.scales();
        for d in [0.0, 0.3, 1.0, 4.0, 100.0] {
            let st = dmt.state(d * s.interference, Branch::Approach);
            let pbar = st.load / s.load;
            assert!((pbar - (d * d.sqrt() - 2.0)).abs() < 1e-12 * (1.0 + d * d.sqrt()));
            assert!((st.radius / s.radius - d.sqrt()).abs() < 1e-12 * (1.0 + d));
        }
        let a0 = dmt.zero_load_radius().unwrap();
        let p0 = dmt.state(a0 * a0 / 2e-6, Branch::Retract).load;
        assert!(p0.abs() < 1e-12 * s.load, "{p0}");
        assert!((ZERO_LOAD_RADIUS - 2f64.cbrt()).abs() < 1e-15);
    }
}
