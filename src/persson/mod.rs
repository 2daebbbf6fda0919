//! Persson's contact theory on an isotropic spectrum (GW on the same
//! spectrum's moments is [`crate::gw::GwOnMoments`]).
//!
//! With the contact modulus `E*`, the spectrum `C(q)` from `q_0 = q_min`
//! and (Persson 2001; Persson 2007; Yang & Persson 2008;
//! `docs/physics.md`, "Persson's theory"):
//! - `w(q) = (pi int_{q0}^{q} q'^3 C(q') dq')^(-1/2)`,
//! - the relative area at magnification `q`: `P(q, p) = erf(p w(q)/E*)`;
//!   for the whole spectrum `A/A0 = erf(sqrt(2) p/(E* g))`,
//!   `g^2 = 2 pi int q^3 C dq` (`w(q_max) = sqrt(2)/g`);
//! - the elastic energy stored in the contact regions
//!   `U/A0 = (pi E*/2) int q^2 C(q) W(q, p) dq`,
//!   `W = P (gamma + (1 - gamma) P^2)`, and the mean separation from
//!   `p = -dU/du / A0`, `u(inf) = 0`:
//!   `u(p) = sqrt(pi) int q^2 C w [gamma E1(s^2)/2 + 3 (1 - gamma) F(s)] dq`,
//!   `s = w(q) p/E*`, `F(s) = int_s^inf erf(x)^2 exp(-x^2)/x dx`;
//! - at light load `u = -u0 ln p + const`, `u0 = gamma sqrt(pi) int q^2 C w dq`;
//! - the full-contact elastic energy `U_full/A0 = (pi E*/2) int q^2 C dq`.
//!
//! The `q` integrals are adaptive Gauss–Kronrod over each segment of the
//! spectrum: in `t = sqrt(q - q0)` on the first one (where `w ~ (q - q0)^(-1/2)`),
//! in `ln q` elsewhere; `F` is a Gauss–Kronrod integral of its own. The
//! relative tolerance is [`QUAD_RTOL`].

pub mod gaps;
pub mod special;

pub use gaps::{GapStatistics, GAP_RTOL};

use crate::error::{positive, Allowed, Error, Result};
use crate::numeric::quadrature::{integrate, integrate_pieces, QuadOptions};
use crate::spectrum::Spectrum;
use special::{e1, erf};
use std::f64::consts::PI;

/// Relative tolerance of the wavevector quadratures.
pub const QUAD_RTOL: f64 = 1e-12;

/// Persson's theory for one spectrum and contact modulus.
#[derive(Debug, Clone, PartialEq)]
pub struct Persson {
    spectrum: Spectrum,
    contact_modulus: f64,
    gamma: f64,
}

/// Persson's prediction at one mean pressure (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PerssonState {
    /// Mean (nominal) pressure `p` (Pa).
    pub pressure: f64,
    /// `A/A0 = erf(sqrt(2) p/(E* g))`.
    pub area_fraction: f64,
    /// Mean interfacial separation `u(p)` (m).
    pub mean_gap: f64,
    /// Estimated absolute quadrature error of `mean_gap` (m).
    pub mean_gap_error: f64,
}

impl Persson {
    /// Persson's theory on `spectrum` with contact modulus `E*` (Pa) and the
    /// Yang–Persson factor `gamma` (1: the elastic energy of every contact
    /// region counts in full; Yang & Persson 2008 found about 0.4-0.45).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `contact_modulus` (> 0) or `gamma`
    /// (in [0, 1]).
    pub fn new(spectrum: Spectrum, contact_modulus: f64, gamma: f64) -> Result<Self> {
        positive("contact_modulus", contact_modulus)?;
        Allowed::closed(0.0, 1.0).check("gamma", gamma)?;
        Ok(Persson {
            spectrum,
            contact_modulus,
            gamma,
        })
    }

    /// The spectrum.
    pub fn spectrum(&self) -> &Spectrum {
        &self.spectrum
    }

    /// The Yang–Persson factor.
    pub fn gamma(&self) -> f64 {
        self.gamma
    }

    /// `w(q) = (pi int_{q0}^{q} q^3 C dq)^(-1/2)` (dimensionless).
    fn w(&self, q: f64) -> f64 {
        1.0 / (PI * self.spectrum.cumulative(3.0, q)).sqrt()
    }

    /// `A/A0 = erf(sqrt(2) p/(E* g))` at mean pressure `p` (Pa).
    pub fn area_fraction(&self, pressure: f64) -> f64 {
        erf(std::f64::consts::SQRT_2 * pressure
            / (self.contact_modulus * self.spectrum.slope_rms()))
    }

    /// `int f(q) dq` over the spectrum (module documentation).
    fn integrate_q<F: Fn(f64) -> f64>(&self, f: F) -> (f64, f64) {
        let segs = self.spectrum.segments();
        let first = segs.iter().position(|s| s.c > 0.0).unwrap_or(0);
        let q0 = segs[first].q_lo;
        // Where w stops being steep: the first segment or 2 q0.
        let qb = segs[first].q_hi.min(2.0 * q0);
        integrate_from(f, q0, qb, segs[first..].iter().map(|s| s.q_hi))
    }

    /// Persson's state at mean pressure `p > 0` (Pa).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `pressure` unless finite and > 0.
    pub fn state(&self, pressure: f64) -> Result<PerssonState> {
        positive("pressure", pressure)?;
        let (e, gamma) = (self.contact_modulus, self.gamma);
        let (u, err) = self.integrate_q(|q| {
            let c = self.spectrum.c(q);
            if c == 0.0 {
                return 0.0;
            }
            let w = self.w(q);
            let s = w * pressure / e;
            let mut inner = 0.5 * gamma * e1(s * s);
            if gamma < 1.0 {
                inner += 3.0 * (1.0 - gamma) * f_erf2(s);
            }
            if inner == 0.0 {
                return 0.0;
            }
            q * q * c * w * inner
        });
        Ok(PerssonState {
            pressure,
            area_fraction: self.area_fraction(pressure),
            mean_gap: PI.sqrt() * u,
            mean_gap_error: PI.sqrt() * err,
        })
    }

    /// The light-load slope `u0 = gamma sqrt(pi) int q^2 C w dq` (m) of
    /// `u = -u0 ln p + const`.
    pub fn mean_gap_slope(&self) -> f64 {
        let (v, _) = self.integrate_q(|q| {
            let c = self.spectrum.c(q);
            if c == 0.0 {
                0.0
            } else {
                q * q * c * self.w(q)
            }
        });
        self.gamma * PI.sqrt() * v
    }

    /// `U_full/A0 = (pi E*/2) int q^2 C dq` (J/m^2): the elastic energy per
    /// nominal area to flatten the surface into full contact.
    pub fn full_contact_energy(&self) -> f64 {
        0.5 * PI * self.contact_modulus * self.spectrum.integral(2.0)
    }

    /// The Persson–Tosatti adhesion number `U_full/(A0 w)` for the work of
    /// adhesion `w` (J/m^2): below 1 the adhesion energy pays for full
    /// contact (Persson & Tosatti 2001), above 1 roughness wins.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `adhesion_energy` unless finite and > 0.
    pub fn persson_tosatti_number(&self, adhesion_energy: f64) -> Result<f64> {
        positive("adhesion_energy", adhesion_energy)?;
        Ok(self.full_contact_energy() / adhesion_energy)
    }
}

/// `F(s) = int_s^inf erf(x)^2 exp(-x^2)/x dx` for `s >= 0` (the
/// `(1 - gamma)` term of the mean separation); the integrand is cut at
/// `max(s, 0) + 7`, where `exp(-x^2)` is below `e^-49` of its value at `s`.
pub fn f_erf2(s: f64) -> f64 {
    if !(s >= 0.0) {
        return f64::NAN;
    }
    if s > 26.0 {
        return 0.0;
    }
    let opts = QuadOptions::relative(1e-13);
    integrate(
        |x| {
            if x == 0.0 {
                0.0
            } else {
                let e = erf(x);
                e * e * (-x * x).exp() / x
            }
        },
        s,
        s + 7.0,
        &opts,
    )
    .value
}

/// Errors unless the pressures are finite and > 0 (a helper for callers
/// that validate lists).
pub fn check_pressures(name: &str, pressures: &[f64]) -> Result<()> {
    if pressures.is_empty() {
        return Err(Error::invalid(name, "no pressures"));
    }
    for p in pressures {
        positive(name, *p)?;
    }
    Ok(())
}

/// `int f(q) dq` from `q0` over the spectrum's segments ending at `ends`
/// (ascending, rad/m): on `[q0, qb]` by `q = q0 + t^2` (the integrands'
/// `(q - q0)^(-1/2)` start becomes smooth), above `qb` by `q = e^v`, a
/// piece per segment end beyond `qb`; each to [`QUAD_RTOL`]. Returns the
/// value and its error estimate (the sum of both parts').
fn integrate_from<F: Fn(f64) -> f64>(
    f: F,
    q0: f64,
    qb: f64,
    ends: impl Iterator<Item = f64>,
) -> (f64, f64) {
    let opts = QuadOptions::relative(QUAD_RTOL);
    let near = integrate(
        |t| {
            let q = q0 + t * t;
            2.0 * t * f(q)
        },
        0.0,
        (qb - q0).sqrt(),
        &opts,
    );
    let mut points: Vec<f64> = vec![qb.ln()];
    points.extend(ends.filter(|&q| q > qb).map(f64::ln));
    if points.len() < 2 {
        return (near.value, near.error);
    }
    let far = integrate_pieces(
        |v| {
            let q = v.exp();
            q * f(q)
        },
        &points,
        &opts,
    );
    (near.value + far.value, near.error + far.error)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spectrum::Normalisation;

    #[test]
    fn light_load_limits() {
        let s = Spectrum::self_affine(0.8, 1e5, 1e5, 1e8, Normalisation::HRms(1e-9)).unwrap();
        let m = Persson::new(s, 1e9, 1.0).unwrap();
        let g = m.spectrum().slope_rms();
        // A/A0 -> sqrt(8/pi) p/(E* g) at light load.
        let p = 1e-6 * 1e9 * g;
        let lin = (8.0 / PI).sqrt() * p / (1e9 * g);
        assert!((m.area_fraction(p) / lin - 1.0).abs() < 1e-11);
        // u(p1) - u(p2) -> u0 ln(p2/p1) at light load.
        let (p1, p2) = (1e-9 * 1e9 * g, 2e-9 * 1e9 * g);
        let du = m.state(p1).unwrap().mean_gap - m.state(p2).unwrap().mean_gap;
        let u0 = m.mean_gap_slope();
        assert!((du / (u0 * 2f64.ln()) - 1.0).abs() < 1e-6, "{du} {u0}");
        assert!(Persson::new(m.spectrum().clone(), 1e9, 1.5).is_err());
        // F(0) = int_0^inf erf^2 e^-x^2 / x dx is finite and F decreases.
        assert!(f_erf2(0.0) > f_erf2(0.5) && f_erf2(0.5) > 0.0);
    }
}
