//! Stiction margin of an ohmic MEMS switch: can the spring reopen the
//! contact against adhesion?
//!
//! The spring (constant `k`, N/m) deflected by its travel `t` (m) pulls back
//! with `F_r = k t`; the rough contact holds with its pull-off `P_c < 0`
//! (tensile). Margin `F_r - |P_c|`; the switch sticks when it is negative.

use crate::error::{finite, positive, Result};

/// A switch spring.
///
/// # Examples
/// A 10 N/m spring over 2 um of travel pulls back with 20 uN; a pull-off
/// of -30 uN holds the contact shut by 10 uN.
/// ```
/// use asperity::prelude::*;
/// let s = Switch::new(10.0, 2e-6)?.stiction(-3e-5)?;
/// assert!((s.restoring_force - 2e-5).abs() < 1e-20);
/// assert!((s.margin + 1e-5).abs() < 1e-20 && s.sticks);
/// # Ok::<(), asperity::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Switch {
    spring_constant: f64,
    travel: f64,
}

/// The stiction verdict (the `"stiction"` JSON object).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stiction {
    /// Pull-off of the rough contact (N), negative (tensile).
    pub pull_off: f64,
    /// Restoring force `k t` (N).
    pub restoring_force: f64,
    /// `k t - |pull_off|` (N).
    pub margin: f64,
    /// Whether the margin is negative.
    pub sticks: bool,
}

impl Switch {
    /// Spring constant `k > 0` (N/m) and travel `t > 0` (m).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `spring_constant` or `travel`.
    pub fn new(spring_constant: f64, travel: f64) -> Result<Self> {
        Ok(Switch {
            spring_constant: positive("spring_constant", spring_constant)?,
            travel: positive("travel", travel)?,
        })
    }

    /// Restoring force `k t` (N).
    pub fn restoring_force(&self) -> f64 {
        self.spring_constant * self.travel
    }

    /// Verdict against a contact of pull-off `pull_off` (N; its sign is
    /// taken as tensile whatever is given: `-|pull_off|` is reported).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `pull_off` when not finite.
    pub fn stiction(&self, pull_off: f64) -> Result<Stiction> {
        let p = finite("pull_off", pull_off)?.abs();
        let margin = self.restoring_force() - p;
        Ok(Stiction {
            pull_off: -p,
            restoring_force: self.restoring_force(),
            margin,
            sticks: margin < 0.0,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn margin_is_restoring_force_minus_adhesion() {
        let s = Switch::new(10.0, 2e-6).unwrap();
        assert!((s.restoring_force() - 2e-5).abs() < 1e-20);
        let v = s.stiction(-5e-6).unwrap();
        assert_eq!(v.pull_off, -5e-6);
        assert!((v.margin - 1.5e-5).abs() < 1e-20);
        assert!(!v.sticks);
        let v = s.stiction(-3e-5).unwrap();
        assert!(v.sticks && v.margin < 0.0);
        // No adhesion: the margin is the whole restoring force.
        assert_eq!(s.stiction(0.0).unwrap().margin, s.restoring_force());
    }

    #[test]
    fn bad_input_names_the_field() {
        assert_eq!(
            Switch::new(-1.0, 1.0).unwrap_err().field(),
            Some("spring_constant")
        );
        assert_eq!(
            Switch::new(1.0, f64::NAN).unwrap_err().field(),
            Some("travel")
        );
        let s = Switch::new(1.0, 1.0).unwrap();
        assert_eq!(
            s.stiction(f64::INFINITY).unwrap_err().field(),
            Some("pull_off")
        );
    }
}
