//! Roughness-induced adhesion hysteresis of a wavy paraboloidal punch under JKR adhesion
//! (Kesari & Lew 2011).
//!
//! A rigid punch with profile `f(r) + l R(r/l)`, `f(r) = r^2/(2 radius)`,
//! `R(x) = A (1 - cos 2 pi x)` (so the surface is `r^2/(2 radius) + l A (1 - cos(2 pi r/l))`,
//! `A` dimensionless, `l` the wavelength), is pressed to a depth `h` into an elastic half-space
//! of contact modulus `E*`, with work of adhesion `w` (JKR: the contact edge is a crack,
//! simply-connected circular contact of radius `a`). Sign conventions: `h > 0` pushes in;
//! `P > 0` compressive.
//!
//! Exact equilibrium curve (re-derived from the paper's eq. 2.9 with Sneddon's
//! `psi(t) = (2/pi)[h - t int_0^t (f' + R'(r/l)) / sqrt(t^2 - r^2) dr]`,
//! `P = pi E* int_0^a psi`, and the JKR condition `psi(a) = -sqrt(8 w a/(pi E*))`;
//! `int_0^a sin(k r)/sqrt(a^2 - r^2) dr = (pi/2) H0(k a)`, `int_0^a t H0(k t) dt = a H1(k a)/k`),
//! with `k = 2 pi / l`:
//! - `h(a) = a^2/R - sqrt(2 pi w a/E*) + pi^2 A a H0(k a)`                         (eq. 4.3)
//! - `P(a) = 4 E* a^3/(3R) - sqrt(8 pi w E* a^3) + 2 E* [pi^2 A a^2 H0(k a) - (pi A a l/2) H1(k a)]` (eq. 4.4)
//!
//! Modules: [`envelope`] (small-`l` envelopes, eq. 4.8-4.9; the asymptotic energy loss,
//! eq. 4.12), [`landscape`] (the folds of `h(a)`), [`evolution`] (the contact radius under
//! displacement control, eqs. 3.6-3.8; the energy lost per cycle), [`barrier`] (potential
//! energy, eq. 4.14, and barriers between neighbouring equilibria), [`fit`] (least-squares fit
//! of `E*`, `w`, `A sqrt(l)` to measured `(a, P)` on both phases).

pub mod barrier;
pub mod envelope;
pub mod evolution;
pub mod fit;
pub mod landscape;

pub use envelope::{Envelope, LossAsymptotic};
pub use evolution::Evolution;
pub use fit::{fit_envelopes, FitPoint, Phase, PunchFit};

use crate::error::{positive, Allowed, Result};
use crate::special::struve::struve_h0_h1;
use std::f64::consts::PI;

/// A wavy paraboloidal punch on an elastic half-space with JKR adhesion. SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WavyPunch {
    estar: f64,
    w: f64,
    radius: f64,
    amplitude: f64,
    wavelength: f64,
}

/// One equilibrium (or path) state: contact radius `a` (m), depth `h` (m), load `P` (N).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct PunchState {
    /// Contact radius `a` (m); 0 when detached.
    #[serde(rename = "radius_m")]
    pub radius: f64,
    /// Indentation depth `h` (m), positive pushing in.
    #[serde(rename = "depth_m")]
    pub depth: f64,
    /// Load `P` (N), positive compressive.
    #[serde(rename = "load_N")]
    pub load: f64,
}

impl WavyPunch {
    /// A punch of radius of curvature `radius` (m) with sinusoidal roughness of dimensionless
    /// amplitude `amplitude` (`A`) and wavelength `wavelength` (`l`, m) against a half-space of
    /// contact modulus `estar` (Pa) with work of adhesion `w` (J/m^2).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `estar`, `w`, `radius`, `amplitude` or
    /// `wavelength` when one is not finite and positive, or (naming `wavelength`) when the
    /// wavelength is not smaller than the radius.
    pub fn new(estar: f64, w: f64, radius: f64, amplitude: f64, wavelength: f64) -> Result<Self> {
        positive("estar", estar)?;
        positive("w", w)?;
        positive("radius", radius)?;
        positive("amplitude", amplitude)?;
        positive("wavelength", wavelength)?;
        Allowed::open(0.0, radius).check("wavelength", wavelength)?;
        Ok(WavyPunch {
            estar,
            w,
            radius,
            amplitude,
            wavelength,
        })
    }

    /// Contact modulus `E*` (Pa).
    pub fn estar(&self) -> f64 {
        self.estar
    }
    /// Work of adhesion `w` (J/m^2).
    pub fn w(&self) -> f64 {
        self.w
    }
    /// Radius of curvature `R` of the paraboloid (m).
    pub fn radius(&self) -> f64 {
        self.radius
    }
    /// Dimensionless roughness amplitude `A`.
    pub fn amplitude(&self) -> f64 {
        self.amplitude
    }
    /// Roughness wavelength `l` (m).
    pub fn wavelength(&self) -> f64 {
        self.wavelength
    }
    /// The dimensionless adhesion of the smooth punch, `2 pi w / (E* R)`.
    pub fn adhesion_number(&self) -> f64 {
        2.0 * std::f64::consts::PI * self.w / (self.estar * self.radius)
    }

    /// `A sqrt(l)` (m^1/2), the only roughness parameter of the envelopes.
    pub fn amplitude_sqrt_wavelength(&self) -> f64 {
        self.amplitude * self.wavelength.sqrt()
    }

    /// Smooth-punch (JKR) depth `h_M(a) = a^2/R - sqrt(2 pi w a/E*)` (m), eq. 4.3a.
    pub fn smooth_depth(&self, a: f64) -> f64 {
        a * a / self.radius - (2.0 * PI * self.w * a / self.estar).sqrt()
    }

    /// Smooth-punch (JKR) load `P_M(a) = 4 E* a^3/(3R) - sqrt(8 pi w E* a^3)` (N), eq. 4.4a.
    pub fn smooth_load(&self, a: f64) -> f64 {
        4.0 * self.estar * a * a * a / (3.0 * self.radius)
            - (8.0 * PI * self.w * self.estar * a * a * a).sqrt()
    }

    /// Exact equilibrium depth `h(a)` (m) at contact radius `a >= 0` (eq. 4.3; `h(0) = 0`).
    pub fn depth(&self, a: f64) -> f64 {
        let (h0, _) = struve_h0_h1(self.k() * a);
        // Same operations as `state`, so both give identical bits.
        let pa = PI * self.amplitude * a;
        self.smooth_depth(a) + PI * pa * h0
    }

    /// Exact equilibrium load `P(a)` (N) at contact radius `a >= 0` (eq. 4.4; `P(0) = 0`).
    pub fn load(&self, a: f64) -> f64 {
        self.state(a).load
    }

    /// A contact radius `a` (m) checked for [`WavyPunch::state`] and the
    /// envelopes: finite, `>= 0`, and small enough that the exact state and
    /// both envelopes are finite (the load grows like `a^3`).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `a` when negative or not
    /// finite; [`crate::Error::Invalid`] naming `a` when a value overflows.
    pub fn check_radius(&self, a: f64) -> Result<f64> {
        let a = Allowed::closed_open(0.0, f64::INFINITY).check("a", a)?;
        let finite = |p: PunchState| p.depth.is_finite() && p.load.is_finite();
        if finite(self.state(a))
            && finite(self.envelope(a, Envelope::Loading))
            && finite(self.envelope(a, Envelope::Unloading))
        {
            Ok(a)
        } else {
            Err(crate::Error::invalid(
                "a",
                format!("at a = {a:e} m the punch's depth or load overflows f64"),
            ))
        }
    }

    /// Exact equilibrium state at contact radius `a >= 0`: one Struve evaluation for both
    /// `h(a)` and `P(a)`.
    pub fn state(&self, a: f64) -> PunchState {
        let (h0, h1) = struve_h0_h1(self.k() * a);
        let pa = PI * self.amplitude * a;
        let depth = self.smooth_depth(a) + PI * pa * h0;
        let load = self.smooth_load(a)
            + 2.0 * self.estar * (PI * pa * a * h0 - 0.5 * pa * self.wavelength * h1);
        PunchState {
            radius: a,
            depth,
            load,
        }
    }

    /// `dh/da` (dimensionless) of the exact curve at `a > 0`:
    /// `2a/R - sqrt(pi w/(2 E* a)) + pi^2 A [H0(x) + x (2/pi - H1(x))]`, `x = 2 pi a/l`
    /// (`H0' = 2/pi - H1`). Equilibria with `dh/da > 0` are stable (paper, eq. A.1).
    pub fn depth_slope(&self, a: f64) -> f64 {
        let x = self.k() * a;
        let (h0, h1) = struve_h0_h1(x);
        2.0 * a / self.radius - (PI * self.w / (2.0 * self.estar * a)).sqrt()
            + PI * PI * self.amplitude * (h0 + x * (2.0 / PI - h1))
    }

    /// The radius where the smooth (JKR) depth is least, `(pi w R^2/(8 E*))^(1/3)` (m):
    /// the natural small-radius scale (the JKR jump-out radius).
    pub fn jkr_detach_radius(&self) -> f64 {
        (PI * self.w * self.radius * self.radius / (8.0 * self.estar)).cbrt()
    }

    /// `k = 2 pi / l` (1/m).
    fn k(&self) -> f64 {
        2.0 * PI / self.wavelength
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fig8(l: f64) -> WavyPunch {
        WavyPunch::new(1.0, 0.05 / (2.0 * PI), 1.0, 0.14, l).unwrap()
    }

    #[test]
    fn validation_names_the_parameter() {
        let e = WavyPunch::new(f64::NAN, 1.0, 1.0, 0.1, 0.1).unwrap_err();
        assert_eq!(e.field(), Some("estar"));
        let e = WavyPunch::new(1.0, 0.0, 1.0, 0.1, 0.1).unwrap_err();
        assert_eq!(e.field(), Some("w"));
        let e = WavyPunch::new(1.0, 1.0, -1.0, 0.1, 0.1).unwrap_err();
        assert_eq!(e.field(), Some("radius"));
        let e = WavyPunch::new(1.0, 1.0, 1.0, 0.0, 0.1).unwrap_err();
        assert_eq!(e.field(), Some("amplitude"));
        let e = WavyPunch::new(1.0, 1.0, 1.0, 0.1, 1.0).unwrap_err();
        assert_eq!(e.field(), Some("wavelength"));
    }

    #[test]
    fn slope_is_the_derivative_of_depth() {
        let p = fig8(0.1);
        for a in [0.01, 0.13, 0.37, 0.8] {
            let d = 1e-6 * a;
            let fd = (p.depth(a + d) - p.depth(a - d)) / (2.0 * d);
            assert!(
                (fd - p.depth_slope(a)).abs() < 1e-7 * (1.0 + fd.abs()),
                "a {a}"
            );
        }
    }

    #[test]
    fn load_is_2_estar_integral_of_a_dh() {
        // Along the equilibrium curve dP/da = 2 E* (a h'(a) - sqrt(2 pi w a/E*)).
        let p = fig8(0.25);
        for a in [0.05, 0.3, 0.71] {
            let d = 1e-6 * a;
            let fd = (p.load(a + d) - p.load(a - d)) / (2.0 * d);
            let want =
                2.0 * p.estar * (a * p.depth_slope(a) - (2.0 * PI * p.w * a / p.estar).sqrt());
            assert!((fd - want).abs() < 1e-7 * (1.0 + want.abs()), "a {a}");
        }
    }
}
