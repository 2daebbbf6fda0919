//! Loading programs and the history rule every integrator follows.

use crate::error::{finite, Allowed, Error, Result};

/// Where in the loading program the flat is.
///
/// On approach every asperity is on its approach branch; on retraction after
/// the flat came as close as `closest`, an asperity of height `z` is in
/// [`AsperityLaw::state_after`](crate::law::AsperityLaw::state_after)`(z - d,
/// z - closest)`: it remembers its maximum interference. This is the one rule
/// of the Greenwood–Williamson integral and of the Monte Carlo sum.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum History {
    /// Approaching from far away: every asperity on its approach branch.
    Approach,
    /// Retracting after the flat came as close as `closest` (m).
    Retract {
        /// Closest separation reached (m).
        closest: f64,
    },
}

impl History {
    /// Checks that the history can hold at separation `d` (m): both finite
    /// and, on retraction, `d >= closest`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `separation` or `closest_separation`.
    pub fn check(&self, d: f64) -> Result<()> {
        finite("separation", d)?;
        if let History::Retract { closest } = *self {
            finite("closest_separation", closest)?;
            if closest > d {
                return Err(Error::OutOfRange {
                    name: "separation".into(),
                    value: d,
                    allowed: Allowed::closed(closest, f64::INFINITY),
                });
            }
        }
        Ok(())
    }
}

/// Approach from `start` down to `closest` in `points` equal steps, then
/// retract back to `start` through the same separations (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadingProgram {
    /// Separation where the program starts and ends (m).
    pub start: f64,
    /// Closest separation (m), `< start`.
    pub closest: f64,
    /// Separations per leg, >= 2.
    pub points: usize,
}

impl LoadingProgram {
    /// Validates `closest < start` (both finite) and `points >= 2`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `start_separation`, `closest_separation`
    /// or `points`.
    pub fn new(start: f64, closest: f64, points: usize) -> Result<Self> {
        finite("start_separation", start)?;
        finite("closest_separation", closest)?;
        if !(closest < start) {
            return Err(Error::OutOfRange {
                name: "closest_separation".into(),
                value: closest,
                allowed: Allowed::open(f64::NEG_INFINITY, start),
            });
        }
        if points < 2 {
            return Err(Error::OutOfRange {
                name: "points".into(),
                value: points as f64,
                allowed: Allowed::closed(2.0, f64::INFINITY),
            });
        }
        Ok(LoadingProgram {
            start,
            closest,
            points,
        })
    }

    /// The separations of one leg, from `closest` up to `start` (ascending).
    pub fn separations(&self) -> Vec<f64> {
        let n = self.points - 1;
        (0..=n)
            .map(|i| self.closest + (self.start - self.closest) * i as f64 / n as f64)
            .collect()
    }

    /// Every step of the program: the approach leg's separations (ascending,
    /// as [`Curve`](super::Curve) stores them), then the retraction leg's.
    pub fn steps(&self) -> Vec<(f64, History)> {
        let seps = self.separations();
        let back = History::Retract {
            closest: self.closest,
        };
        seps.iter()
            .map(|&d| (d, History::Approach))
            .chain(seps.iter().map(|&d| (d, back)))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn program_validates_and_spaces_evenly() {
        let p = LoadingProgram::new(3.0, 1.0, 5).unwrap();
        assert_eq!(p.separations(), vec![1.0, 1.5, 2.0, 2.5, 3.0]);
        assert_eq!(p.steps().len(), 10);
        assert_eq!(p.steps()[5], (1.0, History::Retract { closest: 1.0 }));
        assert_eq!(
            LoadingProgram::new(1.0, 1.0, 5).unwrap_err().field(),
            Some("closest_separation")
        );
        assert_eq!(
            LoadingProgram::new(3.0, 1.0, 1).unwrap_err().field(),
            Some("points")
        );
        assert!(LoadingProgram::new(f64::NAN, 1.0, 5).is_err());
    }

    #[test]
    fn history_check_names_the_separation() {
        let back = History::Retract { closest: 2.0 };
        assert!(back.check(2.0).is_ok());
        assert_eq!(back.check(1.0).unwrap_err().field(), Some("separation"));
        assert!(History::Approach.check(f64::NAN).is_err());
    }
}
