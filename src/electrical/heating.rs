//! Contact-spot heating: Holm's phi-theta relation with the
//! Wiedemann–Franz law (physics.md; Holm 1967, §13).
//!
//! `int_{T0}^{Tmax} rho lambda_th dT = U^2/8` with `rho lambda_th = L T`
//! gives `Tmax^2 = T0^2 + U^2/(4 L)`, where `U` (V) is the contact voltage
//! (current times contact resistance), `T0` the bulk temperature and
//! `L = pi^2 k_B^2/(3 e^2)` the Sommerfeld Lorenz number.

use crate::error::{non_negative, positive, Allowed, Result};
use std::f64::consts::PI;

/// Boltzmann constant (J/K), exact in the 2019 SI.
const K_B: f64 = 1.380_649e-23;
/// Elementary charge (C), exact in the 2019 SI.
const E_CHARGE: f64 = 1.602_176_634e-19;

/// Sommerfeld Lorenz number `L = pi^2 k_B^2/(3 e^2) = 2.44300450907e-8
/// V^2/K^2` (physics.md).
pub const LORENZ: f64 = PI * PI * K_B * K_B / (3.0 * E_CHARGE * E_CHARGE);

/// Default bulk temperature `T0` (K): 20 °C.
pub const DEFAULT_BULK_TEMPERATURE: f64 = 293.15;

/// Softening temperature of gold (K), [`crate::material::gold`].
pub const GOLD_SOFTENING_TEMPERATURE: f64 = crate::material::gold::SOFTENING_TEMPERATURE;

/// Melting temperature of gold (K), [`crate::material::gold`].
pub const GOLD_MELTING_TEMPERATURE: f64 = crate::material::gold::MELTING_TEMPERATURE;

/// Holm's phi-theta relation for a bulk temperature `T0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Heating {
    bulk: f64,
}

impl Default for Heating {
    /// `T0` = [`DEFAULT_BULK_TEMPERATURE`].
    fn default() -> Self {
        Heating {
            bulk: DEFAULT_BULK_TEMPERATURE,
        }
    }
}

impl Heating {
    /// Bulk temperature `T0 > 0` (K).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `bulk_temperature`.
    pub fn new(bulk_temperature: f64) -> Result<Self> {
        Ok(Heating {
            bulk: positive("bulk_temperature", bulk_temperature)?,
        })
    }

    /// Bulk temperature `T0` (K).
    pub fn bulk_temperature(&self) -> f64 {
        self.bulk
    }

    /// Peak contact temperature (K) at contact voltage `U >= 0` (V):
    /// `sqrt(T0^2 + U^2/(4 L))`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `voltage` for `U < 0` or NaN.
    pub fn max_temperature(&self, voltage: f64) -> Result<f64> {
        let u = non_negative("voltage", voltage)?;
        Ok(self.bulk.hypot(u / (2.0 * LORENZ.sqrt())))
    }

    /// Contact voltage (V) that heats the spot to `Tmax >= T0` (K):
    /// `2 sqrt(L (Tmax^2 - T0^2))`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `max_temperature` below `T0`.
    pub fn voltage_for(&self, max_temperature: f64) -> Result<f64> {
        let t = Allowed::closed_open(self.bulk, f64::INFINITY)
            .check("max_temperature", max_temperature)?;
        Ok(2.0 * (LORENZ * (t - self.bulk) * (t + self.bulk)).sqrt())
    }

    /// Peak temperature (K) for current `I` (A) through resistance `R`
    /// (Ohm): `U = I R`.
    ///
    /// # Errors
    /// As [`Heating::max_temperature`] (naming `voltage`).
    pub fn max_temperature_at(&self, current: f64, resistance: f64) -> Result<f64> {
        self.max_temperature((current * resistance).abs())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lorenz_number_has_its_digits() {
        assert!((LORENZ / 2.443_004_509_07e-8 - 1.0).abs() < 1e-11);
    }

    #[test]
    fn voltage_and_temperature_are_inverse() {
        let h = Heating::default();
        assert_eq!(h.max_temperature(0.0).unwrap(), 293.15);
        for u in [1e-3, 0.08, 0.43, 2.0] {
            let t = h.max_temperature(u).unwrap();
            // Inverting loses T/(T - T0) in relative accuracy (t - T0 cancels).
            let tol = 4e-16 * t / (t - 293.15);
            assert!((h.voltage_for(t).unwrap() / u - 1.0).abs() < tol, "{u}");
        }
        // Gold melts near 0.4 V from room temperature (Holm: 0.43 V).
        let um = h.voltage_for(GOLD_MELTING_TEMPERATURE).unwrap();
        assert!((um - 0.407).abs() < 0.005, "{um}");
    }

    #[test]
    fn bad_input_names_the_field() {
        let h = Heating::default();
        assert_eq!(
            h.max_temperature(-1.0).unwrap_err().field(),
            Some("voltage")
        );
        assert_eq!(
            h.max_temperature(f64::NAN).unwrap_err().field(),
            Some("voltage")
        );
        assert_eq!(
            h.voltage_for(200.0).unwrap_err().field(),
            Some("max_temperature")
        );
        assert_eq!(
            Heating::new(0.0).unwrap_err().field(),
            Some("bulk_temperature")
        );
    }
}
