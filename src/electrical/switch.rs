//! Stiction margin of an ohmic MEMS switch: can the spring reopen the
//! contact against adhesion?
//!
//! The spring (constant `k`, N/m) deflected by its travel `t` (m) pulls back
//! with `F_r = k t`; the rough contact holds with its pull-off `P_c < 0`
//! (tensile). Margin `F_r - |P_c|`; the switch sticks when it is negative.

use crate::error::{finite, positive, Result};
use crate::montecarlo::pull_off::PullOffStatistics;

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

/// The verdict against the pull-offs of many populations of the same
/// surface ([`PullOffStatistics`]): the probability that one switch
/// sticks, and the margin at a conservative quantile of the pull-off.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StictionOdds {
    /// The verdict at the pull-off that only a fraction `1 - confidence` of
    /// the populations exceed (the `1 - confidence` quantile: the more
    /// tensile end).
    pub verdict: Stiction,
    /// The confidence of that quantile, in (0, 1).
    pub confidence: f64,
    /// Fraction of the populations whose pull-off exceeds the restoring
    /// force: the probability that one switch sticks.
    pub probability: f64,
    /// Its Clopper–Pearson interval at 95 %.
    pub interval: (f64, f64),
}

impl Switch {
    /// The odds against the pull-offs `stats` (N), the margin at
    /// confidence `confidence` in (0, 1).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `confidence` outside (0, 1).
    pub fn stiction_odds(
        &self,
        stats: &PullOffStatistics,
        confidence: f64,
    ) -> Result<StictionOdds> {
        crate::error::Allowed::open(0.0, 1.0).check("confidence", confidence)?;
        let quantile = stats.quantile(1.0 - confidence).min(0.0);
        let (probability, interval) = stats.fraction_beyond(self.restoring_force());
        Ok(StictionOdds {
            verdict: self.stiction(quantile)?,
            confidence,
            probability,
            interval,
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

    #[test]
    fn odds_count_the_populations_beyond_the_spring() {
        // Five switches; a 10 N/m spring over 2.5 um pulls back with
        // 2.5e-5 N: two of five pull off harder. At confidence 0.75 the
        // margin uses the 25 % quantile of (-4, -3, -2, -1, 0) x 1e-5,
        // i.e. -3e-5.
        let stats = PullOffStatistics::new(vec![-4e-5, -1e-5, -3e-5, -2e-5, 0.0]).unwrap();
        let odds = Switch::new(10.0, 2.5e-6)
            .unwrap()
            .stiction_odds(&stats, 0.75)
            .unwrap();
        assert_eq!(odds.probability, 0.4);
        assert!((odds.verdict.pull_off + 3e-5).abs() < 1e-20);
        assert!((odds.verdict.margin + 0.5e-5).abs() < 1e-18 && odds.verdict.sticks);
        assert!(Switch::new(1.0, 1.0)
            .unwrap()
            .stiction_odds(&stats, 1.0)
            .is_err());
    }
}
