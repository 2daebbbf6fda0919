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

use super::{plastic_asperity_law, PlasticAsperity, PlasticLoading};
use crate::error::Result;
use crate::law::ContactState;
use crate::material::plastic::{Plasticity, Variant};
use std::f64::consts::PI;

/// Transition `w_t = 1.9` from Hertz to the fit.
pub const TRANSITION: f64 = 1.9;
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
}

impl JacksonGreen {
    /// Radius `R` (m), contact modulus `E*` (Pa), plastic data.
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

    /// From validated inputs.
    pub fn from_asperity(asperity: PlasticAsperity) -> Self {
        let c = asperity.plasticity.jg_factor();
        let sy = asperity.plasticity.yield_strength();
        let (r, e) = (asperity.radius, asperity.contact_modulus);
        let q = c * PI * sy / 2.0;
        JacksonGreen {
            omega_c: asperity.critical_interference(Variant::JacksonGreen),
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
    fn variant(&self) -> Variant {
        Variant::JacksonGreen
    }

    fn asperity(&self) -> &PlasticAsperity {
        &self.asperity
    }

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
        let r = self.asperity.radius;
        let g = (w / TRANSITION).powf(self.b);
        let a2 = r * delta * g;
        let a_over_r = (delta / r * g).sqrt();
        let hg = 1.0 - (-0.82 * a_over_r.powf(-0.7)).exp();
        let p = (-0.25 * w.powf(5.0 / 12.0)).exp() * w * w.sqrt()
            + self.hg_coef * hg * (1.0 - (-0.04 * w.powf(5.0 / 9.0)).exp()) * w;
        ContactState {
            load: p * self.p_c,
            radius: a2.sqrt(),
        }
    }

    fn critical_interference(&self) -> f64 {
        self.omega_c
    }

    fn breakpoint_multiples(&self) -> &'static [f64] {
        &BREAKPOINTS
    }
}

plastic_asperity_law!(JacksonGreen);
