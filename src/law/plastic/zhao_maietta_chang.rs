//! Zhao, Maietta & Chang (2000): Hertz up to `omega_1`, fully plastic
//! (`P = H A`, `A = 2 pi R delta`) beyond `omega_2 = 54 omega_1`, and in
//! between a mean pressure interpolated in `ln delta` and an area blended by
//! a cubic with zero slope at both ends:
//!
//! ```text
//! omega_1 = (3 pi K H / (4 E*))^2 R,  K = 0.6
//! p_m = H [1 - (1 - K) ln(omega_2/delta) / ln(omega_2/omega_1)]
//! A   = pi R delta [1 - 2 x^3 + 3 x^2],  x = (delta - omega_1)/(omega_2 - omega_1)
//! P   = p_m A
//! ```
//!
//! Load and area are continuous at both ends (the slope of `P` is not).

use super::{
    plastic_asperity_law, plastic_constructor, plastic_loading_accessors, PlasticAsperity,
    PlasticLoading,
};
use crate::error::Result;
use crate::law::ContactState;
use crate::material::plastic::{Plasticity, Variant, ZMC_PRESSURE_FACTOR};
use std::f64::consts::PI;

/// `omega_2 / omega_1 = 54`.
pub const FULLY_PLASTIC_MULTIPLE: f64 = 54.0;
/// Breakpoints `w = 1, 54`.
pub const BREAKPOINTS: [f64; 2] = [1.0, FULLY_PLASTIC_MULTIPLE];

/// Zhao–Maietta–Chang 2000 loading, with elastic unloading on `state_after`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZhaoMaiettaChang {
    asperity: PlasticAsperity,
    omega_1: f64,
    omega_2: f64,
    /// `1 / ln(omega_2/omega_1)`.
    inv_log: f64,
}

impl ZhaoMaiettaChang {
    plastic_constructor!();

    /// From validated inputs.
    pub fn from_asperity(asperity: PlasticAsperity) -> Self {
        let omega_1 = asperity.critical_interference(Variant::ZhaoMaiettaChang);
        ZhaoMaiettaChang {
            asperity,
            omega_1,
            omega_2: FULLY_PLASTIC_MULTIPLE * omega_1,
            inv_log: 1.0 / FULLY_PLASTIC_MULTIPLE.ln(),
        }
    }
}

impl PlasticLoading for ZhaoMaiettaChang {
    plastic_loading_accessors!(Variant::ZhaoMaiettaChang, omega_1);

    #[inline]
    fn loading(&self, delta: f64) -> ContactState {
        if let Some(s) = self.asperity.elastic_state(delta, self.omega_1) {
            return s;
        }
        let h = self.asperity.plasticity.hardness();
        let r = self.asperity.radius;
        if delta > self.omega_2 {
            let a2 = 2.0 * r * delta;
            return ContactState {
                load: h * PI * a2,
                radius: a2.sqrt(),
            };
        }
        let x = (delta - self.omega_1) / (self.omega_2 - self.omega_1);
        let pm =
            h * (1.0 - (1.0 - ZMC_PRESSURE_FACTOR) * (self.omega_2 / delta).ln() * self.inv_log);
        let a2 = r * delta * (1.0 + x * x * (3.0 - 2.0 * x));
        ContactState {
            load: pm * PI * a2,
            radius: a2.sqrt(),
        }
    }
}

plastic_asperity_law!(ZhaoMaiettaChang);
