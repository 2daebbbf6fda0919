//! Jackson & Green (2005): finite-element fit for a deformable sphere on a
//! rigid flat, `w = delta/omega_c`, yield strength `S_y`:
//!
//! ```text
//! C = 1.295 exp(0.736 nu),  omega_c = (pi C S_y / (2 E*))^2 R
//! P_c = (4/3) (R/E*)^2 (C pi S_y / 2)^3,  B = 0.14 exp(23 S_y/E*)
//! w <= 1.9:  Hertz
//! w >  1.9:  P/P_c = exp(-0.25 w^(5/12)) w^(3/2) + (4 H_G/(C S_y)) (1 - exp(-0.04 w^(5/9))) w
//!            A = pi R delta (w/1.9)^B
//!            H_G/S_y = 2.84 (1 - exp(-0.82 (a/R)^(-0.7))),  a/R = sqrt(delta/R) (w/1.9)^(B/2)
//! ```
//!
//! This is the hardness form of Jackson & Green 2005 (a second form,
//! `H_G/S_y = 2.84 - 0.92 (1 - cos(pi a/R))`, circulates; it is not used).
//! The material's hardness `H` plays no part: the fit carries its own
//! geometry-dependent hardness `H_G`. The area is continuous at `w = 1.9`;
//! the load jumps slightly there (the fit's two pieces do not meet).

use super::{
    plastic_asperity_law, plastic_constructor, plastic_loading_accessors, PlasticAsperity,
    PlasticLoading,
};
use crate::error::Result;
use crate::law::ContactState;
use crate::material::plastic::{Plasticity, Variant};
use std::f64::consts::PI;

/// Transition `w_t = 1.9` from Hertz to the fit.
pub const TRANSITION: f64 = 1.9;
/// `ln 1.9`.
const LN_TRANSITION: f64 = 0.641_853_886_172_394_7;
/// Breakpoints: `w = 1.9`.
pub const BREAKPOINTS: [f64; 1] = [TRANSITION];

/// Jackson–Green 2005 loading, with elastic unloading on `state_after`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JacksonGreen {
    asperity: PlasticAsperity,
    omega_c: f64,
    p_c: f64,
    /// `B`.
    b: f64,
    /// `4 x 2.84 / C`: the hardness term is `(4 H_G/(C S_y))`, `H_G/S_y = 2.84 (..)`.
    hg_coef: f64,
    /// `ln(omega_c / R)`.
    ln_wc_over_r: f64,
}

impl JacksonGreen {
    plastic_constructor!();

    /// From validated inputs.
    pub fn from_asperity(asperity: PlasticAsperity) -> Self {
        let c = asperity.plasticity.jg_factor();
        let sy = asperity.plasticity.yield_strength();
        let (r, e) = (asperity.radius, asperity.contact_modulus);
        let q = c * PI * sy / 2.0;
        let omega_c = asperity.critical_interference(Variant::JacksonGreen);
        JacksonGreen {
            omega_c,
            ln_wc_over_r: (omega_c / r).ln(),
            p_c: 4.0 / 3.0 * (r / e) * (r / e) * q * q * q,
            b: 0.14 * (23.0 * sy / e).exp(),
            hg_coef: 4.0 * 2.84 / c,
            asperity,
        }
    }

    /// Critical load `P_c` (N).
    pub fn critical_load(&self) -> f64 {
        self.p_c
    }

    /// The exponent `B = 0.14 exp(23 S_y/E*)`.
    pub fn area_exponent(&self) -> f64 {
        self.b
    }
}

impl PlasticLoading for JacksonGreen {
    plastic_loading_accessors!(Variant::JacksonGreen, omega_c);

    #[inline]
    fn loading(&self, delta: f64) -> ContactState {
        if !(delta > 0.0) {
            return ContactState::FREE;
        }
        let w = delta / self.omega_c;
        if w <= TRANSITION {
            return ContactState {
                load: self.asperity.hertz.load_at(delta),
                radius: self.asperity.hertz.radius_at(delta),
            };
        }
        // Every power through one logarithm: ln w, and
        // ln(a/R) = (ln(delta/R) + B ln(w/1.9))/2 with ln(delta/R) = ln w + ln(omega_c/R).
        let r = self.asperity.radius;
        let lw = w.ln();
        let lg = self.b * (lw - LN_TRANSITION);
        let a2 = r * delta * lg.exp();
        let ln_a_over_r = 0.5 * (lw + self.ln_wc_over_r + lg);
        let hg = 1.0 - (-0.82 * (-0.7 * ln_a_over_r).exp()).exp();
        let p = (-0.25 * (5.0 / 12.0 * lw).exp()).exp() * w * w.sqrt()
            + self.hg_coef * hg * (1.0 - (-0.04 * (5.0 / 9.0 * lw).exp()).exp()) * w;
        ContactState {
            load: p * self.p_c,
            radius: a2.sqrt(),
        }
    }
}

plastic_asperity_law!(JacksonGreen);

#[cfg(test)]
mod tests {
    #[test]
    fn ln_transition_constant() {
        assert!((super::LN_TRANSITION - 1.9f64.ln()).abs() < 2e-16);
    }
}
