//! The scene's one tolerance `accuracy.rtol` and how a plan splits it: each
//! use of `rtol` is a named share with its reason, so the planner, the run
//! and the diagnostics read the same numbers.

/// The summits beyond the flat's reach at the program's start carry less
/// than this fraction of `rtol` of the heights: their contribution is two
/// orders below the tolerance.
pub const START_TAIL_FRACTION: f64 = 0.01;

pub use crate::montecarlo::TABLE_TOLERANCE_FRACTION;

/// The range of the scene's `accuracy.rtol`: below `1e-12` no integral
/// of the program reaches it in double precision (sums of many summits
/// lose about `1e-14` each); above `0.1` no digit of an output is
/// certain.
pub const RTOL_RANGE: (f64, f64) = (1e-12, 0.1);

/// The range of the full sphere solver's Newton tolerance: below `1e-10`
/// its discretisation error dominates, above `1e-2` its curve is not a
/// reference.
pub const SPHERE_TOLERANCE_RANGE: (f64, f64) = (1e-10, 1e-2);

/// Loosest relative tolerance of the model-error reference run: the model
/// errors it measures are stated to about this (they are percent-level or
/// more).
pub const REFERENCE_RTOL: f64 = 1e-5;

/// A plastic law's adhesion is left out when its JKR interference scale is
/// below this fraction of `rtol x sigma`: no output can change at the
/// tolerance.
pub const NEGLIGIBLE_ADHESION_FRACTION: f64 = 1e-6;

/// Smallest relative tolerance of the hysteresis-energy sign check: a
/// negative energy within `max(rtol, this) x int |P| dd` is zero.
pub const ENERGY_SIGN_FLOOR: f64 = 1e-9;

/// Smallest `accuracy.rtol` of a calibrated (tabulated) law: the GW
/// quadrature of the interpolated solver table stalls at a relative
/// residual of about 2e-12 to 8e-12 (measured on calibrated-gold.toml and
/// mems-gold.toml: 1e-11 runs in under 1 s, 5e-12 ran 14 s and failed,
/// 1e-12 failed), so tighter tolerances are refused up front.
pub const CALIBRATED_MIN_RTOL: f64 = 1e-11;

/// One share of the tolerance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Share {
    /// What it bounds.
    pub name: &'static str,
    /// Its value (relative, or in the unit the name says).
    pub value: f64,
    /// Why this share.
    pub reason: &'static str,
}

/// The splits of one scene tolerance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Budget {
    /// The scene's `accuracy.rtol`.
    pub rtol: f64,
}

impl Budget {
    /// The budget of `rtol`.
    pub fn new(rtol: f64) -> Budget {
        Budget { rtol }
    }

    /// Relative tolerance of every GW integral (controlled against
    /// `int |integrand|`) and of the hysteresis energy.
    pub fn integrals(&self) -> f64 {
        self.rtol
    }

    /// Tail probability beyond the program's start.
    pub fn start_tail(&self) -> f64 {
        START_TAIL_FRACTION * self.rtol
    }

    /// Relative tolerance of a Chebyshev table of the law, kept in the
    /// table's range `[1e-13, 1e-2]` (`0.1 x 0.1` rounds just above
    /// `1e-2`, which refused `rtol = 0.1`, inside the scene's range).
    pub fn table(&self) -> f64 {
        crate::montecarlo::table_tolerance(self.rtol)
    }

    /// The largest measured error (relative, against the full
    /// Lennard-Jones solution) of a law `law.kind = "auto"` may pick.
    pub fn law_choice(&self) -> f64 {
        self.rtol
    }

    /// Newton tolerance of the full sphere solver, `rtol` kept in
    /// [`SPHERE_TOLERANCE_RANGE`].
    pub fn sphere_solver(&self) -> f64 {
        self.rtol
            .clamp(SPHERE_TOLERANCE_RANGE.0, SPHERE_TOLERANCE_RANGE.1)
    }

    /// Pull-off populations are skipped when one switch's pull-off
    /// scatters by less than this around the integral's
    /// ([`crate::montecarlo::pull_off::scatter_below`]).
    pub fn population_scatter(&self) -> f64 {
        self.rtol
    }

    /// The populations' mean pull-off and the integral's agree within this
    /// (relative) or two standard errors, else a warning
    /// ([`crate::montecarlo::pull_off::agrees_with_integral`]).
    pub fn population_agreement(&self) -> f64 {
        self.rtol
    }

    /// Relative tolerance of the model-error reference run: `rtol`, but
    /// no looser than [`REFERENCE_RTOL`].
    pub fn model_error_reference(&self) -> f64 {
        self.rtol.max(REFERENCE_RTOL)
    }

    /// Separation tolerance of the root and minimum searches (the pull-off,
    /// the separation at a load), in units of the height scale `sigma`.
    pub fn separation(&self) -> f64 {
        self.rtol
    }

    /// The JKR interference scale (in units of `sigma`) below which a
    /// plastic law's adhesion is left out.
    pub fn negligible_adhesion(&self) -> f64 {
        NEGLIGIBLE_ADHESION_FRACTION * self.rtol
    }

    /// Relative tolerance of the hysteresis energy's sign check.
    pub fn energy_sign(&self) -> f64 {
        self.rtol.max(ENERGY_SIGN_FLOOR)
    }

    /// Every share, for the plan's report.
    pub fn shares(&self) -> [Share; 11] {
        [
            Share {
                name: "integrals",
                value: self.integrals(),
                reason: "relative error of every GW integral and of the hysteresis energy",
            },
            Share {
                name: "start tail",
                value: self.start_tail(),
                reason: "heights beyond the program's start: two orders below rtol",
            },
            Share {
                name: "law tables",
                value: self.table(),
                reason: "Chebyshev tables of expensive laws: an order below rtol",
            },
            Share {
                name: "separations / sigma",
                value: self.separation(),
                reason: "pull-off and load-controlled separations",
            },
            Share {
                name: "adhesion / sigma",
                value: self.negligible_adhesion(),
                reason: "a plastic law's JKR scale below it: adhesion left out",
            },
            Share {
                name: "energy sign",
                value: self.energy_sign(),
                reason: "a negative hysteresis energy within it is zero",
            },
            Share {
                name: "law choice",
                value: self.law_choice(),
                reason: "law.kind = auto: the cheapest law whose measured error is within it",
            },
            Share {
                name: "sphere solver",
                value: self.sphere_solver(),
                reason: "Newton tolerance of the full sphere solver, kept in [1e-10, 1e-2]",
            },
            Share {
                name: "population scatter",
                value: self.population_scatter(),
                reason: "pull-off populations skipped when one switch scatters less",
            },
            Share {
                name: "population agreement",
                value: self.population_agreement(),
                reason: "populations' mean and the integral's pull-off differ more: a warning",
            },
            Share {
                name: "model-error reference",
                value: self.model_error_reference(),
                reason: "the reference run's tolerance, at most 1e-5",
            },
        ]
    }
}
