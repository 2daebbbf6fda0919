//! Kogut & Etsion (2002): finite-element fit for a deformable sphere on a
//! rigid flat, `w = delta/omega_c`:
//!
//! ```text
//! omega_c = (pi K H / (2 E*))^2 R,  K = 0.454 + 0.41 nu,  H = hardness (default 2.8 Y)
//! P_c = (2/3) pi K H R omega_c (the Hertz load at omega_c),  A_c = pi R omega_c
//! w <= 1:        P/P_c = w^1.5,          A/A_c = w          (Hertz)
//! 1 < w <= 6:    P/P_c = 1.03 w^1.425,   A/A_c = 0.93 w^1.136
//! 6 < w <= 110:  P/P_c = 1.40 w^1.263,   A/A_c = 0.94 w^1.146
//! w > 110:       P/P_c = (3/K) w,        A/A_c = 2 w        (fully plastic: P = H A)
//! ```
//!
//! The fit jumps at `w = 1, 6, 110` (load +3 %, +1.7 %, +8 %); the jumps are
//! kept, and the law reports the three points as breakpoints.

use super::{
    plastic_asperity_law, plastic_constructor, plastic_loading_accessors, PlasticAsperity,
    PlasticLoading,
};
use crate::error::Result;
use crate::law::ContactState;
use crate::material::plastic::{Plasticity, Variant};
use std::f64::consts::PI;

/// Breakpoints `w = 1, 6, 110`.
pub const BREAKPOINTS: [f64; 3] = [1.0, 6.0, 110.0];

/// Kogut–Etsion 2002 loading, with elastic unloading from the flattened
/// shape on `state_after`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KogutEtsion {
    asperity: PlasticAsperity,
    omega_c: f64,
    p_c: f64,
    a_c: f64,
    /// `3/K`.
    plastic_slope: f64,
}

impl KogutEtsion {
    plastic_constructor!();

    /// From validated inputs.
    pub fn from_asperity(asperity: PlasticAsperity) -> Self {
        let k = asperity.plasticity.ke_factor();
        let h = asperity.plasticity.hardness();
        let r = asperity.radius;
        let omega_c = asperity.critical_interference(Variant::KogutEtsion);
        KogutEtsion {
            asperity,
            omega_c,
            p_c: 2.0 / 3.0 * PI * k * h * r * omega_c,
            a_c: PI * r * omega_c,
            plastic_slope: 3.0 / k,
        }
    }

    /// Critical load `P_c` (N).
    pub fn critical_load(&self) -> f64 {
        self.p_c
    }

    /// Dimensionless `(P/P_c, A/A_c)` at `w = delta/omega_c > 0`.
    #[inline]
    pub fn bar(&self, w: f64) -> (f64, f64) {
        // c w^n as c exp(n ln w): one logarithm shared by load and area.
        if w <= 1.0 {
            (w * w.sqrt(), w)
        } else if w <= 6.0 {
            let l = w.ln();
            (1.03 * (1.425 * l).exp(), 0.93 * (1.136 * l).exp())
        } else if w <= 110.0 {
            let l = w.ln();
            (1.40 * (1.263 * l).exp(), 0.94 * (1.146 * l).exp())
        } else {
            (self.plastic_slope * w, 2.0 * w)
        }
    }
}

impl PlasticLoading for KogutEtsion {
    plastic_loading_accessors!(Variant::KogutEtsion, omega_c);

    #[inline]
    fn loading(&self, delta: f64) -> ContactState {
        if let Some(s) = self.asperity.elastic_state(delta, self.omega_c) {
            return s;
        }
        let (p, a) = self.bar(delta / self.omega_c);
        ContactState {
            load: p * self.p_c,
            radius: (a * self.a_c / PI).sqrt(),
        }
    }
}

plastic_asperity_law!(KogutEtsion);
