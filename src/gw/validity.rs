//! Where a Greenwood–Williamson computation leaves its model.
//!
//! GW treats the summits as independent paraboloids (Greenwood &
//! Williamson 1966, Proc. R. Soc. A 295, 300): it needs
//! - a real contact area that is a small fraction of the nominal one
//!   (neighbouring contacts must not merge or interact elastically):
//!   a finding above [`AREA_FRACTION_WARN`] (Ciavarella et al. 2008, J.
//!   Mech. Phys. Solids 56, 3432), an impossible one above 1;
//! - interferences small against the summit radius (Hertz/JKR/Maugis are
//!   small-strain paraboloid theories, and the plastic fits were fitted
//!   to finite elements at small `a/R`): the highest expected summit's
//!   contact radius (the Hertz estimate `a = sqrt(R delta)`, or the law's
//!   own when larger, as for the plastic fits) against
//!   [`CONTACT_RADIUS_WARN`] `R`; impossible when `delta > R` (a cap
//!   deeper than the radius is no paraboloid);
//! - `eta R sigma`, the one dimensionless group of the GW surface:
//!   measured surfaces give 0.03–0.05 (GW 1966; McCool 1986); above
//!   [`ETA_R_SIGMA_WARN`] the real area reaches `pi eta R sigma F_1(h)`,
//!   i.e. 10 % of the nominal area within one sigma of the mean plane;
//! - a program that resolves the contact: [`MIN_POINTS_IN_RANGE`] points
//!   per leg where summits are in range.
//!
//! The findings are data; a caller decides which are warnings and which
//! refuse the input (and which input to name).

use super::{GwModel, RoughSurface};
use crate::heights::HeightDistribution;
use crate::law::{AsperityLaw, Branch};
use crate::loading::{Curve, LoadingModel};
use std::fmt;

/// Real-area fraction `A_r/A_n` above which contacts interact.
pub const AREA_FRACTION_WARN: f64 = 0.1;

/// Contact radius of the highest expected summit, in units of `R` (the
/// larger of the Hertz estimate and the law's own), above which the
/// paraboloid (small-strain) laws and the plastic fits lose accuracy.
pub const CONTACT_RADIUS_WARN: f64 = 0.3;

/// `eta R sigma` above which the surface is outside GW's measured range.
pub const ETA_R_SIGMA_WARN: f64 = 0.1;

/// Points per leg, where summits are in range, below which the curve does
/// not resolve the contact.
pub const MIN_POINTS_IN_RANGE: f64 = 10.0;

/// One way a computation leaves the GW model.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Finding {
    /// `eta R sigma` above [`ETA_R_SIGMA_WARN`].
    EtaRSigma {
        /// `eta R sigma`.
        value: f64,
    },
    /// The highest expected summit's contact radius (Hertz estimate, or
    /// the law's own when larger) above [`CONTACT_RADIUS_WARN`] `R`.
    ContactRadius {
        /// Its interference (m).
        depth: f64,
        /// `a/R`.
        ratio: f64,
        /// Whether `a` is the law's own contact radius (larger than the
        /// Hertz estimate `sqrt(R delta)`, e.g. a plastic fit's) rather
        /// than the Hertz estimate.
        from_law: bool,
    },
    /// The highest expected summit pressed deeper than its radius
    /// (impossible for a paraboloid).
    DeeperThanRadius {
        /// Its interference (m).
        depth: f64,
        /// Its height above the distribution's origin (m).
        top: f64,
        /// The closest separation (m).
        closest: f64,
    },
    /// The real area above [`AREA_FRACTION_WARN`] of the nominal area.
    AreaFraction {
        /// `A_r/A_n` at its largest.
        fraction: f64,
    },
    /// The real area above the nominal area (impossible).
    AreaAboveNominal {
        /// `A_r/A_n` at its largest.
        fraction: f64,
    },
    /// Too few points of the program where summits are in range.
    Resolution {
        /// Points per leg in range.
        inside: f64,
        /// Points per leg.
        points: usize,
        /// Separation where the first summit comes in range (m).
        onset: f64,
        /// The program's start (m).
        start: f64,
    },
}

impl Finding {
    /// Whether the finding makes the result impossible (not only
    /// inaccurate).
    pub fn is_impossible(&self) -> bool {
        matches!(
            self,
            Finding::DeeperThanRadius { .. } | Finding::AreaAboveNominal { .. }
        )
    }
}

impl fmt::Display for Finding {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Finding::EtaRSigma { value } => write!(
                f,
                "eta R sigma = {value:.3e} (surface.density x surface.radius x surface.sigma) > \
                 {ETA_R_SIGMA_WARN}: measured surfaces give 0.03-0.05; the real area reaches \
                 {:.0} % of the nominal area near the mean plane, outside GW's independent summits",
                100.0 * std::f64::consts::PI * value * 0.4
            ),
            Finding::ContactRadius {
                depth,
                ratio,
                from_law: false,
            } => write!(
                f,
                "interference: the highest expected summit is pressed {depth:.3e} m deep, contact \
                 radius a/R = {ratio:.2} > {CONTACT_RADIUS_WARN} (Hertz estimate): the \
                 small-strain asperity laws lose accuracy"
            ),
            Finding::ContactRadius {
                depth,
                ratio,
                from_law: true,
            } => write!(
                f,
                "interference: the highest expected summit is pressed {depth:.3e} m deep, where \
                 the law's own contact radius is a/R = {ratio:.2} > {CONTACT_RADIUS_WARN}: \
                 outside the range its fit or theory assumes (small a/R; the plastic fits' \
                 finite-element data stay well below a/R = 1), the result is an extrapolation"
            ),
            Finding::DeeperThanRadius {
                depth,
                top,
                closest,
            } => write!(
                f,
                "the highest summit (height {top:.3e} m) would be pressed {depth:.3e} m deep at \
                 the closest separation {closest:.3e} m, more than its radius: a paraboloidal \
                 summit has no meaning there (GW needs interferences small against R)"
            ),
            Finding::AreaFraction { fraction } => write!(
                f,
                "real area: A_r/A_n = {fraction:.3} > {AREA_FRACTION_WARN} at the closest \
                 separation: contacts interact, outside GW's independent summits"
            ),
            Finding::AreaAboveNominal { fraction } => write!(
                f,
                "the real contact area would be {fraction:.3e} x the nominal area (impossible; GW \
                 needs a small fraction)"
            ),
            Finding::Resolution { inside, points, .. } if inside >= points as f64 => write!(
                f,
                "resolution: {points} points per leg (program.points), all where summits are in \
                 range, are fewer than {MIN_POINTS_IN_RANGE}: the curve, pull-off and hysteresis \
                 energy are not resolved"
            ),
            Finding::Resolution {
                inside,
                points,
                onset,
                start,
            } => write!(
                f,
                "resolution: only {inside:.1} of the {points} points per leg lie where summits \
                 are in range (below {onset:.3e} m; program.start_separation = {start:.3e} m): \
                 the curve, pull-off and hysteresis energy are not resolved"
            ),
        }
    }
}

/// The height (m, from the distribution's origin) of the highest of the
/// `N = eta A_n` summits one expects: `sigma Q^-1(1/N)` (`N >= 2`; the
/// probability is floored at 1e-15 so that the quantile stays finite).
pub fn top_summit(surface: &RoughSurface, distribution: &dyn HeightDistribution) -> f64 {
    let n = surface.summits().max(2.0);
    let p = (1.0 / n).max(1e-15);
    surface.sigma * distribution.quantile(1.0 - p)
}

impl RoughSurface {
    /// `eta R sigma` (dimensionless).
    pub fn eta_r_sigma(&self) -> f64 {
        self.density * self.radius * self.sigma
    }
}

impl GwModel {
    /// Findings about the surface alone and a program that comes as close
    /// as `closest` (m): `eta R sigma`, the highest summit's interference.
    pub fn findings_at(&self, closest: f64) -> Vec<Finding> {
        let mut out = Vec::new();
        let s = self.surface();
        let ers = s.eta_r_sigma();
        if ers > ETA_R_SIGMA_WARN {
            out.push(Finding::EtaRSigma { value: ers });
        }
        out.extend(interference(
            s,
            self.distribution(),
            Some(self.law()),
            closest,
        ));
        out
    }

    /// Findings about a finished curve: the real area against the nominal
    /// area and the program's resolution (the interference is
    /// [`GwModel::findings_at`]'s).
    pub fn findings_of(&self, curve: &Curve) -> Vec<Finding> {
        let mut out = Vec::new();
        let max_area = curve
            .approach
            .iter()
            .chain(&curve.retract)
            .filter_map(|s| s.area())
            .fold(0.0, f64::max);
        let fraction = max_area / self.surface().nominal_area;
        if fraction > 1.0 {
            out.push(Finding::AreaAboveNominal { fraction });
        } else if fraction > AREA_FRACTION_WARN {
            out.push(Finding::AreaFraction { fraction });
        }
        let p = &curve.program;
        let onset = self.interaction_onset();
        let span = p.start - p.closest;
        if span > 0.0 && onset.is_finite() && onset > p.closest {
            // points in range: the closest one and the intervals' share
            let inside = (onset.min(p.start) - p.closest) / span * (p.points as f64 - 1.0) + 1.0;
            if inside < MIN_POINTS_IN_RANGE {
                out.push(Finding::Resolution {
                    inside,
                    points: p.points,
                    onset,
                    start: p.start,
                });
            }
        }
        out
    }
}

/// The interference finding of the highest expected summit at `closest`.
fn interference(
    surface: &RoughSurface,
    distribution: &dyn HeightDistribution,
    law: Option<&dyn AsperityLaw>,
    closest: f64,
) -> Option<Finding> {
    let top = top_summit(surface, distribution);
    let depth = top - closest;
    if !depth.is_finite() || depth <= 0.0 {
        return None;
    }
    if depth > surface.radius {
        return Some(Finding::DeeperThanRadius {
            depth,
            top,
            closest,
        });
    }
    // The law's own contact radius where it has one: the plastic fits
    // (Jackson–Green's `a/R = sqrt(delta/R) (w/1.9)^(B/2)`, Kogut–Etsion's
    // `A = 2 A_c w`) spread wider than Hertz, far beyond the fitted range
    // (a Jackson–Green summit at 9.5 R reaches a = 12.8 R).
    let hertz = (depth / surface.radius).sqrt();
    let own = law.map_or(0.0, |l| {
        let a = l
            .state(depth.min(l.max_interference()), Branch::Approach)
            .radius;
        if a.is_finite() {
            a / surface.radius
        } else {
            0.0
        }
    });
    let (ratio, from_law) = if own > hertz {
        (own, true)
    } else {
        (hertz, false)
    };
    (ratio > CONTACT_RADIUS_WARN).then_some(Finding::ContactRadius {
        depth,
        ratio,
        from_law,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::heights::Gaussian;
    use crate::law::Hertz;
    use std::sync::Arc;

    fn model(density: f64) -> GwModel {
        let s = RoughSurface::new(density, 1e-6, 5e-9, 1e-8).unwrap();
        GwModel::new(
            s,
            Arc::new(Gaussian::new()),
            Arc::new(Hertz::new(1e-6, 5e10).unwrap()),
        )
        .unwrap()
    }

    #[test]
    fn findings_follow_their_bounds() {
        // eta R sigma = 1e12 x 1e-6 x 5e-9 = 5e-3: quiet at the mean plane.
        assert!(model(1e12).findings_at(0.0).is_empty());
        let f = model(3e13).findings_at(0.0);
        assert!(matches!(f[0], Finding::EtaRSigma { value } if (value - 0.15).abs() < 1e-12));
        // The highest of 1e4 summits is 3.72 sigma = 18.6 nm high; pressed
        // to -1 um it is deeper than R; to -20 nm a/R = sqrt(38.6e-9/1e-6).
        let deep = model(1e12).findings_at(-1e-6);
        assert!(deep.iter().any(Finding::is_impossible), "{deep:?}");
        let near = model(1e12).findings_at(-0.1e-6);
        match near[0] {
            Finding::ContactRadius { ratio, .. } => assert!(ratio > CONTACT_RADIUS_WARN),
            ref other => panic!("{other:?}"),
        }
    }
}
