//! Load–separation curves: approach and retraction legs of a program.

use super::program::LoadingProgram;
use super::state::State;

/// A curve on approach and retraction.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// The program that made it.
    pub program: LoadingProgram,
    /// Approach states, ascending in separation (index 0 = closest).
    pub approach: Vec<State>,
    /// Retraction states at the same separations.
    pub retract: Vec<State>,
}

/// Pull-off of a rough surface: the most tensile load on retraction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PullOff {
    /// Load (N), < 0.
    pub load: f64,
    /// Separation where it occurs (m).
    pub separation: f64,
    /// Whether it is the load at the upper end of the retraction searched
    /// (the program's start) while that end is still within the law's
    /// reach: the load may still have been falling there, so the contact
    /// had not pulled off within the program and the true pull-off lies
    /// beyond it (callers warn; start further out, or at the model's
    /// interaction onset, to find it).
    pub at_start: bool,
}

impl Curve {
    /// Energy lost per cycle (J): `int (P_approach - P_retract) dd` over the
    /// program, trapezoidal on the program's separations (error
    /// `O(step^2)`); `None` if loads were not computed.
    pub fn hysteresis_energy(&self) -> Option<f64> {
        hysteresis_energy(
            self.approach
                .iter()
                .zip(&self.retract)
                .map(|(a, r)| (a.separation, a.load(), r.load())),
        )
    }

    /// The most tensile sampled retraction load, if any is tensile.
    pub fn sampled_pull_off(&self) -> Option<PullOff> {
        most_tensile(self.retract.iter().map(|s| (s.load(), s.separation)))
    }

    /// Law evaluations spent on both legs.
    pub fn evaluations(&self) -> usize {
        self.approach
            .iter()
            .chain(&self.retract)
            .map(|s| s.evaluations)
            .sum()
    }

    /// The same curve with every total multiplied by `factor`.
    pub fn scaled(&self, factor: f64) -> Curve {
        let scale = |v: &[State]| v.iter().map(|s| s.scaled(factor)).collect();
        Curve {
            program: self.program,
            approach: scale(&self.approach),
            retract: scale(&self.retract),
        }
    }
}

/// Energy lost per cycle (J) over `(separation, approach load, retraction
/// load)` points ascending in separation: trapezoidal
/// `int (P_approach - P_retract) dd` (error `O(step^2)`). `None` when a
/// load the rule needs is missing.
pub fn hysteresis_energy(
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
/// load is tensile; missing loads are skipped.
///
/// The samples are in ascending separation (a retraction leg as
/// [`Curve`] stores it): [`PullOff::at_start`] is set when the most
/// tensile is the last sample.
pub fn most_tensile(samples: impl IntoIterator<Item = (Option<f64>, f64)>) -> Option<PullOff> {
    let loaded: Vec<(f64, f64)> = samples
        .into_iter()
        .filter_map(|(load, separation)| load.map(|p| (p, separation)))
        .collect();
    let last = loaded.len().checked_sub(1)?;
    loaded
        .iter()
        .enumerate()
        .filter(|(_, &(p, _))| p < 0.0)
        .min_by(|a, b| a.1 .0.total_cmp(&b.1 .0))
        .map(|(i, &(load, separation))| PullOff {
            load,
            separation,
            at_start: i == last,
        })
}

#[cfg(test)]
mod tests {
    use super::*;

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
                separation: 3.0,
                at_start: false,
            })
        );
        assert_eq!(most_tensile([(Some(0.0), 0.0), (None, 1.0)]), None);
        assert_eq!(most_tensile([]), None);
        // Still most tensile at the last (largest) separation: cut off.
        let cut = most_tensile([(Some(-1.0), 0.0), (Some(-2.0), 1.0)]).unwrap();
        assert!(cut.at_start);
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
