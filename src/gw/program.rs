//! Loading programs: approach to a closest separation, then retract.

use super::model::{Accuracy, GwModel, GwState, History, Outputs};
use crate::error::{finite, Allowed, Error, Result};
use crate::numeric::roots::golden_min;

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
    /// [`Error::OutOfRange`] naming `closest_separation` or `points`.
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
}

/// A load–separation curve on approach and retraction.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// The program that made it.
    pub program: LoadingProgram,
    /// Approach states, ascending in separation (index 0 = closest).
    pub approach: Vec<GwState>,
    /// Retraction states at the same separations.
    pub retract: Vec<GwState>,
}

/// Pull-off of a rough surface: the most tensile load on retraction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PullOff {
    /// Load (N), < 0.
    pub load: f64,
    /// Separation where it occurs (m).
    pub separation: f64,
}

impl Curve {
    /// Energy lost per cycle (J): `int (P_approach - P_retract) dd` over the
    /// program, trapezoidal on the program's separations (error
    /// `O(step^2)`); `None` if loads were not computed.
    pub fn hysteresis_energy(&self) -> Option<f64> {
        hysteresis_energy(
            self.approach
                .iter()
                .enumerate()
                .map(|(i, a)| (a.separation, a.load, self.retract[i].load)),
        )
    }

    /// The most tensile sampled retraction load, if any is tensile.
    pub fn sampled_pull_off(&self) -> Option<PullOff> {
        most_tensile(self.retract.iter().map(|s| (s.load, s.separation)))
    }
}

/// Energy lost per cycle (J) over `(separation, approach load, retraction
/// load)` points ascending in separation: trapezoidal
/// `int (P_approach - P_retract) dd` (error `O(step^2)`). `None` when a
/// load the rule needs is missing. Shared by [`Curve`] and
/// [`McCurve`](crate::montecarlo::McCurve).
pub(crate) fn hysteresis_energy(
    points: impl IntoIterator<Item = (f64, Option<f64>, Option<f64>)>,
) -> Option<f64> {
    let mut points = points.into_iter();
    let Some(mut prev) = points.next() else {
        return Some(0.0);
    };
    let mut w = 0.0;
    for p in points {
        let g0 = prev.1? - prev.2?;
        let g1 = p.1? - p.2?;
        w += 0.5 * (g0 + g1) * (p.0 - prev.0);
        prev = p;
    }
    Some(w)
}

/// The most tensile (most negative) of `(load, separation)` samples, if any
/// load is tensile; missing loads are skipped. Shared by [`Curve`] and
/// [`McCurve`](crate::montecarlo::McCurve).
pub(crate) fn most_tensile(
    samples: impl IntoIterator<Item = (Option<f64>, f64)>,
) -> Option<PullOff> {
    samples
        .into_iter()
        .filter_map(|(load, separation)| load.map(|p| (p, separation)))
        .filter(|&(p, _)| p < 0.0)
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(load, separation)| PullOff { load, separation })
}

impl GwModel {
    /// Runs `program`: approach states, then retraction states after the
    /// closest separation.
    ///
    /// # Errors
    /// As [`GwModel::state`].
    pub fn curve(
        &self,
        program: &LoadingProgram,
        outputs: Outputs,
        accuracy: &Accuracy,
    ) -> Result<Curve> {
        let seps = program.separations();
        let approach = seps
            .iter()
            .map(|&d| self.state(d, History::Approach, outputs, accuracy))
            .collect::<Result<Vec<_>>>()?;
        let back = History::Retract {
            closest: program.closest,
        };
        let retract = seps
            .iter()
            .map(|&d| self.state(d, back, outputs, accuracy))
            .collect::<Result<Vec<_>>>()?;
        Ok(Curve {
            program: *program,
            approach,
            retract,
        })
    }

    /// Pull-off on retraction after approaching to `closest` (m): the most
    /// tensile total load, located by sampling `samples` separations between
    /// `closest` and the interaction onset, then refined by golden-section
    /// search to `rel_tol * sigma` in separation. `None` when no retraction
    /// load is tensile.
    ///
    /// # Errors
    /// As [`GwModel::state`].
    pub fn pull_off(
        &self,
        closest: f64,
        samples: usize,
        accuracy: &Accuracy,
    ) -> Result<Option<PullOff>> {
        let top = self.interaction_onset();
        if !(top > closest) {
            return Ok(None);
        }
        let program = LoadingProgram::new(top, closest, samples.max(3))?;
        let seps = program.separations();
        let back = History::Retract { closest };
        let load = |d: f64| -> Result<f64> {
            Ok(self
                .state(d, back, Outputs::LOAD, accuracy)?
                .load
                .unwrap_or(0.0))
        };
        let loads = seps.iter().map(|&d| load(d)).collect::<Result<Vec<_>>>()?;
        let (imin, &pmin) = loads
            .iter()
            .enumerate()
            .min_by(|a, b| a.1.total_cmp(b.1))
            .expect("at least three samples");
        if !(pmin < 0.0) {
            return Ok(None);
        }
        let lo = seps[imin.saturating_sub(1)];
        let hi = seps[(imin + 1).min(seps.len() - 1)];
        let mut failure = None;
        let (d, p) = golden_min(
            |d| match load(d) {
                Ok(p) => p,
                Err(e) => {
                    failure = Some(e);
                    f64::INFINITY
                }
            },
            lo,
            hi,
            (accuracy.rel_tol * self.surface().sigma).max(1e-9 * (hi - lo)),
        );
        if let Some(e) = failure {
            return Err(e);
        }
        let (load, separation) = if p < pmin { (p, d) } else { (pmin, seps[imin]) };
        Ok(Some(PullOff { load, separation }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn program_validates_and_spaces_evenly() {
        let p = LoadingProgram::new(3.0, 1.0, 5).unwrap();
        assert_eq!(p.separations(), vec![1.0, 1.5, 2.0, 2.5, 3.0]);
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
    fn most_tensile_skips_missing_and_compressive_loads() {
        let samples = [
            (Some(1.0), 0.0),
            (None, 1.0),
            (Some(-2.0), 2.0),
            (Some(-3.0), 3.0),
            (Some(-1.0), 4.0),
        ];
        assert_eq!(
            most_tensile(samples),
            Some(PullOff {
                load: -3.0,
                separation: 3.0
            })
        );
        assert_eq!(most_tensile([(Some(0.0), 0.0), (None, 1.0)]), None);
        assert_eq!(most_tensile([]), None);
    }

    #[test]
    fn hysteresis_energy_is_the_trapezoidal_gap() {
        // Gap 0, 2, 2 over steps 1 and 2: 0.5 (0 + 2) 1 + 0.5 (2 + 2) 2 = 5.
        let pts = [
            (0.0, Some(1.0), Some(1.0)),
            (1.0, Some(0.0), Some(-2.0)),
            (3.0, Some(1.0), Some(-1.0)),
        ];
        assert_eq!(hysteresis_energy(pts), Some(5.0));
        assert_eq!(hysteresis_energy([]), Some(0.0));
        let missing = [(0.0, Some(1.0), Some(1.0)), (1.0, Some(0.0), None)];
        assert_eq!(hysteresis_energy(missing), None);
    }
}
