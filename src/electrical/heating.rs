//! Contact-spot heating: Holm's phi-theta relation with the
//! Wiedemann–Franz law (physics.md; Holm 1967, §13).
//!
//! `int_{T0}^{Tmax} rho lambda_th dT = U^2/8` with `rho lambda_th = L T`
//! gives `Tmax^2 = T0^2 + U^2/(4 L)`, where `U` (V) is the contact voltage
//! (current times contact resistance), `T0` the bulk temperature and
//! `L = pi^2 k_B^2/(3 e^2)` the Sommerfeld Lorenz number.
//!
//! The relation holds while the spot is solid: above the metal's softening
//! temperature the spot yields and grows (the resistance computed at the
//! load no longer holds), above its melting temperature it melts and the
//! relation gives no temperature at all (Holm 1967, §13, table of
//! softening and melting voltages). [`Heating::condition`] says which,
//! [`Heating::peak_temperature`] gives no temperature above melting, and
//! [`Heating::warning`] words it; the limits default to gold's.

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

/// What the metal of a contact spot does at its peak temperature.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum SpotCondition {
    /// Below the softening temperature: Holm's relation holds.
    Solid,
    /// Between the softening and the melting temperatures: the spot
    /// yields and grows, so the resistance (and the temperature from it)
    /// computed at the given load no longer holds.
    Softened,
    /// At or above the melting temperature: the spot melts; no temperature.
    Molten,
}

/// A spot that softens or melts at its contact voltage
/// ([`Heating::warning`]); `Display` words the warning.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SpotWarning {
    /// Above the softening voltage: the spot softens and grows, so the
    /// resistance at the load and the temperature from it no longer hold.
    Softened {
        /// The contact voltage (V).
        voltage: f64,
        /// The softening voltage (V).
        softening_voltage: f64,
        /// The softening temperature (K).
        softening_temperature: f64,
        /// Holm's peak temperature at `voltage` (K).
        temperature: f64,
    },
    /// At or above the melting voltage: the spot melts; no temperature.
    Molten {
        /// The contact voltage (V).
        voltage: f64,
        /// The melting voltage (V).
        melting_voltage: f64,
        /// The melting temperature (K).
        melting_temperature: f64,
    },
}

impl std::fmt::Display for SpotWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SpotWarning::Softened {
                voltage,
                softening_voltage,
                softening_temperature,
                temperature,
            } => write!(
                f,
                "the contact voltage {voltage:.4e} V is above the softening voltage \
                 {softening_voltage:.4} V (softening temperature {softening_temperature} K): the \
                 spot softens at {temperature:.1} K and grows, so the resistance at this load and \
                 the temperature from it no longer hold"
            ),
            SpotWarning::Molten {
                voltage,
                melting_voltage,
                melting_temperature,
            } => write!(
                f,
                "the contact voltage {voltage:.4e} V is above the melting voltage \
                 {melting_voltage:.4} V (melting temperature {melting_temperature} K): the spot \
                 melts; Holm's relation gives no temperature above melting, so none is reported"
            ),
        }
    }
}

/// Holm's phi-theta relation for a bulk temperature `T0`, with the
/// softening and melting temperatures (K) of the spot's metal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Heating {
    bulk: f64,
    softening: f64,
    melting: f64,
}

impl Default for Heating {
    /// `T0` = [`DEFAULT_BULK_TEMPERATURE`], gold's softening and melting
    /// temperatures.
    fn default() -> Self {
        Heating {
            bulk: DEFAULT_BULK_TEMPERATURE,
            softening: GOLD_SOFTENING_TEMPERATURE,
            melting: GOLD_MELTING_TEMPERATURE,
        }
    }
}

impl Heating {
    /// Bulk temperature `T0` (K) in `(0, melting)` with gold's softening
    /// and melting temperatures.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `bulk_temperature`.
    pub fn new(bulk_temperature: f64) -> Result<Self> {
        Heating::for_metal(
            bulk_temperature,
            GOLD_SOFTENING_TEMPERATURE,
            GOLD_MELTING_TEMPERATURE,
        )
    }

    /// Bulk temperature `T0` (K) for a metal that softens at `softening`
    /// (K, finite, > 0) and melts at `melting` (K, finite, > `softening`);
    /// `T0` in `(0, melting)`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `softening_temperature`,
    /// `melting_temperature` or `bulk_temperature`.
    pub fn for_metal(bulk_temperature: f64, softening: f64, melting: f64) -> Result<Self> {
        let softening = Allowed::open(0.0, f64::MAX).check("softening_temperature", softening)?;
        let melting = Allowed::open(softening, f64::MAX).check("melting_temperature", melting)?;
        let bulk = positive("bulk_temperature", bulk_temperature)?;
        let bulk = Allowed::open(0.0, melting).check("bulk_temperature", bulk)?;
        Ok(Heating {
            bulk,
            softening,
            melting,
        })
    }

    /// Bulk temperature `T0` (K).
    pub fn bulk_temperature(&self) -> f64 {
        self.bulk
    }

    /// Softening temperature of the metal (K).
    pub fn softening_temperature(&self) -> f64 {
        self.softening
    }

    /// Melting temperature of the metal (K).
    pub fn melting_temperature(&self) -> f64 {
        self.melting
    }

    /// Contact voltage (V) at which the spot reaches a temperature `T`
    /// (K), `2 sqrt(L (T^2 - T0^2))`, 0 when `T <= T0`.
    fn voltage_at(&self, t: f64) -> f64 {
        if t <= self.bulk {
            return 0.0;
        }
        2.0 * (LORENZ * (t - self.bulk) * (t + self.bulk)).sqrt()
    }

    /// Softening voltage (V): the contact voltage that heats the spot to
    /// the softening temperature (0 when the bulk is already softer).
    pub fn softening_voltage(&self) -> f64 {
        self.voltage_at(self.softening)
    }

    /// Melting voltage (V): the contact voltage that heats the spot to the
    /// melting temperature.
    pub fn melting_voltage(&self) -> f64 {
        self.voltage_at(self.melting)
    }

    /// What the spot does at contact voltage `U >= 0` (V): solid below
    /// the softening voltage, softened below the melting voltage, molten
    /// at or above it.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `voltage` for `U < 0` or NaN.
    pub fn condition(&self, voltage: f64) -> Result<SpotCondition> {
        let t = self.max_temperature(voltage)?;
        Ok(if t >= self.melting {
            SpotCondition::Molten
        } else if t > self.softening {
            SpotCondition::Softened
        } else {
            SpotCondition::Solid
        })
    }

    /// Peak temperature (K) at contact voltage `U >= 0` (V) while the spot
    /// is not molten ([`Heating::max_temperature`]); `None` at or above the
    /// melting voltage, where Holm's relation gives no temperature.
    ///
    /// # Errors
    /// As [`Heating::max_temperature`].
    pub fn peak_temperature(&self, voltage: f64) -> Result<Option<f64>> {
        let t = self.max_temperature(voltage)?;
        Ok((t < self.melting).then_some(t))
    }

    /// A warning for contact voltage `U >= 0` (V) when the spot softens or
    /// melts ([`SpotWarning`]: the voltage against the softening or melting
    /// voltage and what it means); `None` for a solid spot.
    ///
    /// # Errors
    /// As [`Heating::max_temperature`].
    pub fn warning(&self, voltage: f64) -> Result<Option<SpotWarning>> {
        Ok(match self.condition(voltage)? {
            SpotCondition::Solid => None,
            SpotCondition::Softened => Some(SpotWarning::Softened {
                voltage,
                softening_voltage: self.softening_voltage(),
                softening_temperature: self.softening,
                temperature: self.max_temperature(voltage)?,
            }),
            SpotCondition::Molten => Some(SpotWarning::Molten {
                voltage,
                melting_voltage: self.melting_voltage(),
                melting_temperature: self.melting,
            }),
        })
    }

    /// Holm's peak contact temperature (K) at contact voltage `U >= 0`
    /// (V): `sqrt(T0^2 + U^2/(4 L))`, the relation's value whatever the
    /// metal does (see [`Heating::peak_temperature`] and
    /// [`Heating::condition`]).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `voltage` for `U < 0` or NaN.
    pub fn max_temperature(&self, voltage: f64) -> Result<f64> {
        let u = non_negative("voltage", voltage)?;
        Ok(self.bulk.hypot(u / (2.0 * LORENZ.sqrt())))
    }

    /// Contact voltage (V) that heats the spot to `Tmax` (K) in
    /// `[T0, T_melting]`: `2 sqrt(L (Tmax^2 - T0^2))`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `max_temperature` below `T0` or
    /// above the melting temperature (the relation ends there).
    pub fn voltage_for(&self, max_temperature: f64) -> Result<f64> {
        let t =
            Allowed::closed(self.bulk, self.melting).check("max_temperature", max_temperature)?;
        Ok(self.voltage_at(t))
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
        for u in [1e-3, 0.08, 0.2, 0.4] {
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

    /// Holm's table (Electric Contacts, 1967, §13): gold softens at
    /// 0.08 V and melts at 0.43 V; the Sommerfeld Lorenz number from
    /// 293.15 K gives 0.0722 V and 0.408 V (physics.md).
    #[test]
    fn gold_softens_and_melts_at_holms_voltages() {
        let h = Heating::default();
        assert!((h.softening_voltage() - 0.0722).abs() < 5e-4);
        assert!((h.melting_voltage() - 0.408).abs() < 5e-4);
        assert_eq!(h.condition(0.05).unwrap(), SpotCondition::Solid);
        assert_eq!(h.condition(0.1).unwrap(), SpotCondition::Softened);
        assert_eq!(h.condition(10.0).unwrap(), SpotCondition::Molten);
        assert!(h.warning(0.05).unwrap().is_none());
        assert!(h
            .warning(0.1)
            .unwrap()
            .unwrap()
            .to_string()
            .contains("softens"));
        // `heating --voltage 10` printed 31,991 K: no temperature now.
        assert!((h.max_temperature(10.0).unwrap() - 31_991.0).abs() < 1.0);
        assert_eq!(h.peak_temperature(10.0).unwrap(), None);
        assert!(h
            .warning(10.0)
            .unwrap()
            .unwrap()
            .to_string()
            .contains("melts"));
        let below = h.peak_temperature(0.4).unwrap().unwrap();
        assert!(below < GOLD_MELTING_TEMPERATURE && below > 1300.0);
        // The inverse ends at melting.
        assert_eq!(
            h.voltage_for(1e300).unwrap_err().field(),
            Some("max_temperature")
        );
        assert_eq!(
            h.voltage_for(GOLD_MELTING_TEMPERATURE).unwrap(),
            h.melting_voltage()
        );
    }

    #[test]
    fn other_metals_name_their_limits() {
        let h = Heating::for_metal(300.0, 463.0, 1358.0).unwrap(); // copper
        assert_eq!(h.melting_temperature(), 1358.0);
        assert_eq!(h.condition(0.2).unwrap(), SpotCondition::Softened);
        for (s, m, b, field) in [
            (0.0, 1000.0, 300.0, "softening_temperature"),
            (f64::NAN, 1000.0, 300.0, "softening_temperature"),
            (500.0, 400.0, 300.0, "melting_temperature"),
            (500.0, f64::INFINITY, 300.0, "melting_temperature"),
            (500.0, 1000.0, 1000.0, "bulk_temperature"),
            (500.0, 1000.0, -1.0, "bulk_temperature"),
        ] {
            let e = Heating::for_metal(b, s, m).unwrap_err();
            assert_eq!(e.field(), Some(field), "{s} {m} {b}");
        }
    }
}
