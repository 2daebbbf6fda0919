//! The totals at one separation, and how they were computed.

use super::observable::{Totals, SLOTS};

/// Which method produced a state.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MethodUsed {
    /// `F_n` closed forms.
    ClosedForm,
    /// Adaptive Gauss–Kronrod quadrature.
    Quadrature,
    /// A fixed composite Kronrod rule.
    Fixed,
    /// A Chebyshev interpolant of the curve's logarithm in the separation
    /// through quadrature states (many approach states of one curve).
    Interpolated,
    /// An exact average over a finite sample of heights (measured summits).
    SampleSum,
    /// An exact sum over a drawn population (Monte Carlo); the
    /// uncertainties are standard errors of the expectation.
    Population,
}

/// Totals of the requested observables at one separation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct State {
    /// Separation `d` of the flat from the height origin (m).
    pub separation: f64,
    /// The totals and their uncertainties (numerical error estimates for
    /// integrals, standard errors for populations).
    pub totals: Totals,
    /// Method that produced the numbers.
    pub method: MethodUsed,
    /// Law evaluations spent (0 for closed forms; summits in range for a
    /// population).
    pub evaluations: usize,
}

impl State {
    /// Total load (N), > 0 compressive.
    pub fn load(&self) -> Option<f64> {
        self.totals.load()
    }

    /// Real contact area (m^2).
    pub fn area(&self) -> Option<f64> {
        self.totals.area()
    }

    /// Number of contacts.
    pub fn count(&self) -> Option<f64> {
        self.totals.count()
    }

    /// The state of a surface `factor` times larger (a population drawn for
    /// a sub-area): totals and uncertainties multiplied by `factor`.
    pub fn scaled(&self, factor: f64) -> State {
        State {
            totals: self.totals.scaled(factor),
            ..*self
        }
    }

    /// Deviation of this state from `expected` in combined uncertainties,
    /// per slot: `(x - x_e) / sqrt(u^2 + u_e^2)`. For a population against
    /// the integral it is about N(0, 1) (`|z| > 5` is significant). `None`
    /// for slots missing on either side, with an undefined or zero combined
    /// uncertainty, or where a population's standard error is 0: then every
    /// summit contributed the same value (typically none is in range) and
    /// the sample says nothing about the spread, so a z-score against a
    /// tiny integration error would be meaningless (it read ~1e6).
    pub fn deviation_from(&self, expected: &State) -> [Option<f64>; SLOTS] {
        let degenerate = |s: &State, i: usize| {
            s.method == MethodUsed::Population && s.totals.error(i) == Some(0.0)
        };
        std::array::from_fn(|i| {
            let (m, e) = (self.totals.get(i)?, expected.totals.get(i)?);
            if degenerate(self, i) || degenerate(expected, i) {
                return None;
            }
            let u = self.totals.error(i)?.hypot(expected.totals.error(i)?);
            (u > 0.0).then(|| (m - e) / u)
        })
    }
}
