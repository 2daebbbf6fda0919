//! Executing a [`Plan`]: the loading program, pull-off and hysteresis energy.

use super::plan::Plan;
use crate::error::Result;
use crate::gw::{Curve, GwState, LoadingProgram, PullOff};
use std::time::Instant;

/// Number of retraction samples the pull-off search starts from.
const PULL_OFF_SAMPLES: usize = 64;

/// What a run produced. Outputs not asked for are `None` (or absent from
/// the states).
#[derive(Debug, Clone)]
pub struct Results {
    /// The program's curve: approach and retraction states at the same
    /// separations (ascending; index 0 is the closest separation).
    pub curve: Curve,
    /// Pull-off of the rough surface (most tensile retraction load), when
    /// asked for and tensile.
    pub pull_off: Option<PullOff>,
    /// Energy lost per cycle (J), when asked for.
    pub hysteresis_energy: Option<f64>,
    /// Wall-clock time of the run (s).
    pub seconds: f64,
    /// Law evaluations spent by quadrature (0 for closed forms).
    pub evaluations: usize,
}

impl Results {
    /// Largest approach load (N) of the curve, if loads were computed.
    pub fn max_load(&self) -> Option<f64> {
        self.curve
            .approach
            .iter()
            .filter_map(|s| s.load)
            .reduce(f64::max)
    }
}

impl Plan {
    /// Runs the plan.
    ///
    /// # Errors
    /// [`crate::Error::NoConvergence`] when quadrature cannot meet the
    /// tolerance; [`crate::Error::Invalid`] when a maximum load cannot be
    /// reached.
    pub fn run(&self) -> Result<Results> {
        let t0 = Instant::now();
        let model = self.model()?;
        let closest = self.closest_separation(&model)?;
        let program = LoadingProgram::new(self.start, closest, self.points)?;
        let curve = if self.compute_retraction {
            model.curve(&program, self.curve_outputs, &self.accuracy)?
        } else {
            let approach = program
                .separations()
                .iter()
                .map(|&d| {
                    model.state(
                        d,
                        crate::gw::History::Approach,
                        self.curve_outputs,
                        &self.accuracy,
                    )
                })
                .collect::<Result<Vec<GwState>>>()?;
            Curve {
                program,
                retract: approach.clone(),
                approach,
            }
        };
        let pull_off = if self.pull_off {
            model.pull_off(closest, PULL_OFF_SAMPLES, &self.accuracy)?
        } else {
            None
        };
        let hysteresis_energy = if self.hysteresis_energy {
            curve.hysteresis_energy()
        } else {
            None
        };
        // A copied retraction leg cost nothing.
        let legs: &[&[GwState]] = if self.compute_retraction {
            &[&curve.approach, &curve.retract]
        } else {
            &[&curve.approach]
        };
        let evaluations = legs
            .iter()
            .flat_map(|l| l.iter())
            .map(|s| s.evaluations)
            .sum();
        Ok(Results {
            curve,
            pull_off,
            hysteresis_energy,
            seconds: t0.elapsed().as_secs_f64(),
            evaluations,
        })
    }
}
