//! Chang, Etsion & Bogy (1987): Hertz up to first yield, then plastic flow
//! with the volume of the sphere conserved:
//!
//! ```text
//! omega_c = (pi K H / (2 E*))^2 R,  K = 0.454 + 0.41 nu
//! delta <= omega_c:  Hertz
//! delta >  omega_c:  A = pi R delta (2 - omega_c/delta),  P = K H A
//! ```
//!
//! The area is continuous at `omega_c`; the load jumps by the factor 3/2
//! there (Hertz mean pressure `(2/3) K H` against `K H`), the model's
//! known defect. Fully plastic contact carries `P = K H A`, not `H A`.

use super::{
    plastic_asperity_law, plastic_constructor, plastic_loading_accessors, PlasticAsperity,
    PlasticLoading,
};
use crate::error::Result;
use crate::law::ContactState;
use crate::material::plastic::{Plasticity, Variant};
use std::f64::consts::PI;

/// Breakpoint `w = 1`.
pub const BREAKPOINTS: [f64; 1] = [1.0];

/// Chang–Etsion–Bogy 1987 loading, with elastic unloading on `state_after`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChangEtsionBogy {
    asperity: PlasticAsperity,
    omega_c: f64,
    /// Mean plastic pressure `K H` (Pa).
    pressure: f64,
}

impl ChangEtsionBogy {
    plastic_constructor!();

    /// From validated inputs.
    pub fn from_asperity(asperity: PlasticAsperity) -> Self {
        let p = &asperity.plasticity;
        ChangEtsionBogy {
            omega_c: asperity.critical_interference(Variant::ChangEtsionBogy),
            pressure: p.ke_factor() * p.hardness(),
            asperity,
        }
    }
}

impl PlasticLoading for ChangEtsionBogy {
    plastic_loading_accessors!(Variant::ChangEtsionBogy, omega_c);

    #[inline]
    fn loading(&self, delta: f64) -> ContactState {
        if let Some(s) = self.asperity.elastic_state(delta, self.omega_c) {
            return s;
        }
        // a^2 = R (2 delta - omega_c)
        let a2 = self.asperity.radius * (2.0 * delta - self.omega_c);
        ContactState {
            load: self.pressure * PI * a2,
            radius: a2.sqrt(),
        }
    }
}

plastic_asperity_law!(ChangEtsionBogy);
