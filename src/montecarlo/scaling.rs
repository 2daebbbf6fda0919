//! One law for summits of many radii.
//!
//! A law object is built for one radius. Rather than building a law per
//! summit (an allocation and, for Maugis–Dugdale, a root solve each), the
//! Monte Carlo sum uses the radius scaling of laws whose dimensionless form
//! does not depend on `R`: with `rho = R_i / R_ref`,
//!
//! ```text
//! delta_i -> delta_i rho^-alpha,   P_i = rho^beta P_ref(delta_i rho^-alpha),   a_i = rho^gamma a_ref(...)
//! ```
//!
//! - Maugis units (`Dbar = delta/(pi^2 w^2 R/K^2)^(1/3)`, `Pbar = P/(pi w R)`,
//!   `A = a/(pi w R^2/K)^(1/3)`, Maugis 1992) give `(alpha, beta, gamma) =
//!   (1/3, 1, 2/3)` for every law whose `Pbar(Dbar)` is universal: JKR,
//!   DMT, and Hertz (where it reduces to `P ~ R^(1/2) delta^(3/2)`, `a^2 = R delta`).
//! - Bradley's rigid-sphere force `F = 2 pi w R f(delta/z0)` (Derjaguin)
//!   gives `(0, 1, 0)`.
//! - Maugis–Dugdale is *not* scalable this way: `lambda ~ R^(1/3)` changes
//!   the dimensionless curve, so it needs one law per radius; with varying
//!   radii it is refused ([`SummitLaw::from_kind`]) rather than approximated.
//!
//! Cost: three multiplications per summit evaluation and 24 bytes of
//! precomputed factors per summit (`rho^-alpha, rho^beta, rho^gamma`),
//! against one law build per summit otherwise.
//!
//! **Tabulation.** An expensive law ([`LawKind::worth_tabulating`]: exact
//! Maugis–Dugdale, about 0.2-0.5 us per call) built by
//! [`SummitLaw::from_kind`] is replaced, when a [`MonteCarlo`](super::MonteCarlo)
//! binds it to a population, by an [`InterpolatedLaw`] over the
//! interferences the population can reach (from the law's cutoff to the
//! height range, in reference-radius units; summits beyond it fall back to
//! the exact law). Tolerance: [`TABLE_TOLERANCE_FRACTION`] of the requested
//! relative accuracy ([`SummitLaw::with_accuracy`]; default
//! [`Accuracy::DEFAULT`]'s `1e-8`, so `1e-9` relative to `|P| + P_s`), the
//! rule the study planner uses for GW curves. [`SummitLaw::exact`] turns it
//! off.

use crate::error::{positive, Error, Result};
use crate::gw::Accuracy;
use crate::law::interpolated::InterpolatedLaw;
use crate::law::{LawKernels, LawKind, RadiusScaling};
use crate::material::AsperityContact;
use std::sync::Arc;

/// A law for the summits of a population: a law built for
/// `reference_radius`, and how to rescale it for other radii (if it can be).
#[derive(Debug, Clone)]
pub struct SummitLaw {
    law: Arc<dyn LawKernels>,
    reference_radius: f64,
    scaling: Option<RadiusScaling>,
    /// Chebyshev-table tolerance when the law is to be tabulated.
    table_tolerance: Option<f64>,
}

/// Table tolerance as a fraction of the requested relative accuracy (the
/// study planner's rule for GW curves).
pub const TABLE_TOLERANCE_FRACTION: f64 = 0.1;

/// The tolerance of a law's Chebyshev table for a run to relative
/// tolerance `rtol`: [`TABLE_TOLERANCE_FRACTION`]` * rtol`, kept in the
/// table's range `[1e-13, 1e-2]` (`0.1 * 0.1` rounds to
/// `0.010000000000000002`, just above it, which refused `rtol = 0.1`).
pub fn table_tolerance(rtol: f64) -> f64 {
    (TABLE_TOLERANCE_FRACTION * rtol).clamp(1e-13, 1e-2)
}

impl SummitLaw {
    /// A law valid only for summits of exactly `radius` (m).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `radius`.
    pub fn fixed(law: Arc<dyn LawKernels>, radius: f64) -> Result<Self> {
        positive("radius", radius)?;
        Ok(SummitLaw {
            law,
            reference_radius: radius,
            scaling: None,
            table_tolerance: None,
        })
    }

    /// A law built for `reference_radius` (m) that rescales to other radii
    /// by `scaling`. The caller vouches that the law obeys it.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `reference_radius` or `scaling` (exponents must be finite).
    pub fn scaled(
        law: Arc<dyn LawKernels>,
        reference_radius: f64,
        scaling: RadiusScaling,
    ) -> Result<Self> {
        positive("reference_radius", reference_radius)?;
        for x in [scaling.interference, scaling.load, scaling.contact_radius] {
            crate::error::finite("scaling", x)?;
        }
        Ok(SummitLaw {
            law,
            reference_radius,
            scaling: Some(scaling),
            table_tolerance: None,
        })
    }

    /// The law of `kind` for `contact` (at `contact.radius`), with the radius
    /// scaling the kind obeys ([`LawKind::radius_scaling`]); kinds without
    /// one (Maugis–Dugdale) serve only populations of that one radius.
    /// Expensive kinds are tabulated when bound to a population (see the
    /// module notes), to the default accuracy.
    ///
    /// # Errors
    /// As [`LawKind::build`].
    pub fn from_kind(kind: LawKind, contact: &AsperityContact) -> Result<Self> {
        let table_tolerance = kind
            .worth_tabulating()
            .then_some(table_tolerance(Accuracy::DEFAULT.rel_tol));
        Ok(SummitLaw {
            law: Arc::from(kind.build(contact)?),
            reference_radius: contact.radius,
            scaling: kind.radius_scaling(),
            table_tolerance,
        })
    }

    /// Ties the table of a tabulated law to `accuracy`: tolerance
    /// [`TABLE_TOLERANCE_FRACTION`]` * rel_tol`, kept in the table's range
    /// `[1e-13, 1e-2]` (`0.1 * 0.1` rounds to `0.010000000000000002`, just
    /// above it). No effect on laws that are not tabulated.
    pub fn with_accuracy(mut self, accuracy: &Accuracy) -> Self {
        if self.table_tolerance.is_some() {
            self.table_tolerance = Some(table_tolerance(accuracy.rel_tol));
        }
        self
    }

    /// The exact law on every summit (no table).
    pub fn exact(mut self) -> Self {
        self.table_tolerance = None;
        self
    }

    /// The tolerance of the table this law will be replaced by, if any.
    pub fn table_tolerance(&self) -> Option<f64> {
        self.table_tolerance
    }

    /// This law tabulated on `[lo, hi]` (m, reference radius) when it is
    /// to be tabulated and the interval is usable; itself otherwise.
    ///
    /// # Errors
    /// As [`InterpolatedLaw::new`].
    pub(crate) fn tabulated_on(&self, lo: f64, hi: f64) -> Result<SummitLaw> {
        let Some(tol) = self.table_tolerance else {
            return Ok(self.clone());
        };
        let hi = hi.min(self.law.max_interference());
        if !(lo.is_finite() && hi.is_finite() && hi > lo) {
            return Ok(self.clone());
        }
        Ok(SummitLaw {
            law: Arc::new(InterpolatedLaw::new(self.law.clone(), lo, hi, tol)?),
            table_tolerance: None,
            ..self.clone()
        })
    }

    /// The law at the reference radius.
    pub fn law(&self) -> &dyn LawKernels {
        self.law.as_ref()
    }

    /// The radius the law was built for (m).
    pub fn reference_radius(&self) -> f64 {
        self.reference_radius
    }

    /// The radius scaling, if the law has one.
    pub fn scaling(&self) -> Option<RadiusScaling> {
        self.scaling
    }

    /// Factors `[rho^-alpha, rho^beta, rho^gamma]` for a summit of radius
    /// `radius` (m).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `radius` when it differs from the reference
    /// and the law has no scaling.
    pub(crate) fn factors_for(&self, radius: f64) -> Result<[f64; 3]> {
        let rho = radius / self.reference_radius;
        match self.scaling {
            Some(s) => Ok(s.factors(rho)),
            None if rho == 1.0 => Ok([1.0; 3]),
            None => Err(Error::invalid(
                "radius",
                format!(
                    "law {} is built for R = {:e} m and has no radius scaling; \
                     summits of radius {radius:e} m need a law built for their radius \
                     (fixed radii) or a scalable law (hertz, dmt, jkr, bradley)",
                    self.law.name(),
                    self.reference_radius
                ),
            )),
        }
    }
}
