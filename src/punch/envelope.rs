//! Small-wavelength envelopes of the wavy punch and the asymptotic energy loss per cycle.
//!
//! As `l/a -> 0`, `H0(x) = Y0(x) + 2/(pi x) + O(x^-3)` and
//! `Y0(x) ~ sqrt(2/(pi x)) sin(x - pi/4)` turn the exact curve into
//! `h(a) = h_M(a) + A l + pi A sqrt(l a) sin(2 pi a/l - pi/4) + O(l^(3/2))` and
//! `P(a) = P_M(a) + 2 pi E* A sqrt(l a^3) sin(2 pi a/l - pi/4) + O(l^(3/2))`
//! (the `A l` terms of `P` cancel between `H0` and `H1`). The oscillation is the paper's
//! `sqrt(pi a l/2) r(a/l)` with `r(x) = sqrt(2 pi) A sin(2 pi x - pi/4)`, the semi-derivative of
//! `R` (eqs. 2.18, 4.5-4.7; the extraction's minus signs restored: with `h > 0` pushing in the
//! oscillation enters `h` with a plus sign). Its extremes give the envelopes (eqs. 4.8-4.9):
//! - loading (upper): `h_+(a) = h_M(a) + pi A sqrt(l a)`, `P_+(a) = P_M(a) + 2 pi E* A sqrt(l a^3)`;
//! - unloading (lower): `h_-(a) = h_M(a) - pi A sqrt(l a)`, `P_-(a) = P_M(a) - 2 pi E* A sqrt(l a^3)`.
//!
//! The exact folds approach them at the rate `h_fold - h_+/- = A l + O(l^(3/2))`,
//! `P_fold - P_+/- = O(l^(3/2))` (`tests/it/punch_asymptotics.rs` measures both).

use super::{PunchState, WavyPunch};
use crate::numeric::roots::brent;
use std::f64::consts::PI;

/// `c0` of eq. 4.12 (the smooth JKR displacement-controlled loss, in `(w^5 R^4/E*^2)^(1/3)`):
/// `F(a4) - F(a2)` with `F(a) = (8/15) a^5 - (4/3) sqrt(2 pi) a^(7/2) + pi a^2`,
/// `a2 = (2 pi)^(1/3)`, `a4 = (pi/8)^(1/3)` (units `E* = R = w = 1`). Recomputed in closed form
/// here and by `tests/data/punch_loss.py` (mpmath, 30 digits); the paper prints 7.1.
pub const LOSS_C0: f64 = 7.092_195_971_863_958_827;
/// `c1` of eq. 4.12 (in `A sqrt(l) (w^7 R^8/E*)^(1/6)`): `d/d(A sqrt l)` of the loss of the
/// path 2-2'-4 at 0, `(4 pi^2/3) sqrt(a2) + G(a4) - G(a2)` with
/// `G(a) = -(4 pi/3) a^(7/2) + pi sqrt(2 pi) a^2`. The paper prints 29.6.
pub const LOSS_C1: f64 = 29.629_164_920_497_144_832;

/// Which envelope.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Envelope {
    /// Loading (upper) envelope `h_+`, `P_+`.
    Loading,
    /// Unloading (lower) envelope `h_-`, `P_-`.
    Unloading,
}

impl Envelope {
    fn sign(self) -> f64 {
        match self {
            Envelope::Loading => 1.0,
            Envelope::Unloading => -1.0,
        }
    }
}

/// The terms of eq. 4.12 for one displacement-controlled cycle to `h_max` (J).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LossAsymptotic {
    /// `c0 (w^5 R^4/E*^2)^(1/3)`: the smooth JKR loss.
    pub jkr: f64,
    /// `c1 A sqrt(l) (w^7 R^8/E*)^(1/6)`.
    pub c1_term: f64,
    /// `A (a_max^2 - a2^2) sqrt(8 pi^3 E* w l)` (eq. C.4).
    pub depth_term: f64,
    /// Effective maximum radius `a_max`: `h_+(a_max) = h_max` (m).
    pub a_max: f64,
    /// Radius just after jump-in `a2`: `h_+(a2) = 0` (m), eq. 4.13.
    pub a2: f64,
}

impl LossAsymptotic {
    /// The sum of the three terms (J).
    pub fn total(&self) -> f64 {
        self.jkr + self.c1_term + self.depth_term
    }
}

impl WavyPunch {
    /// The envelope state at contact radius `a >= 0`: `h_+/-(a)`, `P_+/-(a)` (eqs. 4.8-4.9).
    pub fn envelope(&self, a: f64, which: Envelope) -> PunchState {
        let s = which.sign();
        let eps = self.amplitude_sqrt_wavelength();
        PunchState {
            radius: a,
            depth: self.smooth_depth(a) + s * PI * eps * a.sqrt(),
            load: self.smooth_load(a) + s * 2.0 * PI * self.estar() * eps * (a * a * a).sqrt(),
        }
    }

    /// `dh_+/-/da = 2a/R - sqrt(pi w/(2 E* a)) +/- (pi/2) A sqrt(l/a)`.
    pub fn envelope_slope(&self, a: f64, which: Envelope) -> f64 {
        2.0 * a / self.radius() - (PI * self.w() / (2.0 * self.estar() * a)).sqrt()
            + which.sign() * 0.5 * PI * self.amplitude_sqrt_wavelength() / a.sqrt()
    }

    /// Smallest radius beyond the envelope's minimum where `h_+/-(a) = h` (m), the effective
    /// evolution of eq. 3.14; `None` when `h` is below the envelope's minimum.
    pub fn envelope_radius(&self, h: f64, which: Envelope) -> Option<f64> {
        let a_min = self.envelope_minimum(which);
        if self.envelope(a_min, which).depth > h {
            return None;
        }
        let f = |a: f64| self.envelope(a, which).depth - h;
        let mut hi = 2.0 * a_min.max(self.radius() * 1e-9);
        while f(hi) < 0.0 {
            hi *= 2.0;
            if !hi.is_finite() {
                return None;
            }
        }
        brent(f, a_min, hi, 1e-15 * hi)
    }

    /// Radius of the envelope's minimum depth (its fold, `dh_+/-/da = 0`; for the unloading
    /// envelope this is the pull-off radius a4 of eq. C.2).
    pub fn envelope_minimum(&self, which: Envelope) -> f64 {
        // h'(a) = 2a/R - c/sqrt(a), c = sqrt(pi w/(2 E*)) -/+ (pi/2) A sqrt(l): a = (c R/2)^(2/3).
        let c = (PI * self.w() / (2.0 * self.estar())).sqrt()
            - which.sign() * 0.5 * PI * self.amplitude_sqrt_wavelength();
        if c <= 0.0 {
            0.0
        } else {
            (0.5 * c * self.radius()).powf(2.0 / 3.0)
        }
    }

    /// Eq. 4.12: the energy lost per displacement-controlled cycle from detachment to
    /// `h_max > 0` and back, to first order in `A sqrt(l)`, with the coefficients recomputed
    /// ([`LOSS_C0`], [`LOSS_C1`]). `None` if `h_max` is not positive.
    pub fn loss_asymptotic(&self, h_max: f64) -> Option<LossAsymptotic> {
        if !(h_max > 0.0) {
            return None;
        }
        let (e, w, r) = (self.estar(), self.w(), self.radius());
        let eps = self.amplitude_sqrt_wavelength();
        let a2 = self.envelope_radius(0.0, Envelope::Loading)?;
        let a_max = self.envelope_radius(h_max, Envelope::Loading)?;
        Some(LossAsymptotic {
            jkr: LOSS_C0 * (w.powi(5) * r.powi(4) / (e * e)).cbrt(),
            c1_term: LOSS_C1 * eps * (w.powi(7) * r.powi(8) / e).powf(1.0 / 6.0),
            depth_term: eps * (a_max * a_max - a2 * a2) * (8.0 * PI.powi(3) * e * w).sqrt(),
            a_max,
            a2,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coefficients_match_their_closed_forms() {
        let a2 = (2.0 * PI).cbrt();
        let a4 = (PI / 8.0).cbrt();
        let f = |a: f64| {
            8.0 / 15.0 * a.powi(5) - 4.0 / 3.0 * (2.0 * PI).sqrt() * a.powf(3.5) + PI * a * a
        };
        let g = |a: f64| -4.0 * PI / 3.0 * a.powf(3.5) + PI * (2.0 * PI).sqrt() * a * a;
        assert!((f(a4) - f(a2) - LOSS_C0).abs() < 1e-13);
        let c1 = 4.0 * PI * PI / 3.0 * a2.sqrt() + g(a4) - g(a2);
        assert!((c1 - LOSS_C1).abs() < 1e-12);
    }

    #[test]
    fn envelope_radii_solve_their_equations() {
        let p = WavyPunch::new(1.0, 0.05 / (2.0 * PI), 1.0, 0.14, 0.03).unwrap();
        for which in [Envelope::Loading, Envelope::Unloading] {
            let a = p.envelope_radius(0.05, which).unwrap();
            assert!((p.envelope(a, which).depth - 0.05).abs() < 1e-14);
            assert!(p.envelope_slope(a, which) > 0.0);
            let m = p.envelope_minimum(which);
            assert!(p.envelope_slope(m, which).abs() < 1e-10);
        }
        // The smooth limit: A -> 0 gives the JKR radii (2 pi w R^2/E*)^(1/3) at h = 0.
        let s = WavyPunch::new(1.0, 0.05 / (2.0 * PI), 1.0, 1e-12, 0.03).unwrap();
        let a2 = s.envelope_radius(0.0, Envelope::Loading).unwrap();
        assert!((a2 - 0.05f64.cbrt()).abs() < 1e-9);
    }
}
