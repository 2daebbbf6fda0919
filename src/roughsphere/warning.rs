//! The rough sphere's warnings at one state ([`super::SphereState`]): where
//! the numbers or the model (Greenwood & Tripp 1967: GW summits under an
//! elastic half-space) are stretched, each with its numbers as fields and
//! its sentence by `Display`; serialised as that sentence.

use super::report::{AREA_FRACTION_WARNING, RADIUS_RATIO_WARNING};
use serde::{Serialize, Serializer};
use std::fmt;

/// One warning of a rough-sphere state.
#[derive(Debug, Clone, PartialEq)]
pub enum SphereWarning {
    /// The load's error estimate is above the tolerance at the node limit.
    Unconverged {
        /// The load's error estimate (N).
        load_error: f64,
        /// The solver's relative tolerance.
        tolerance: f64,
        /// The node limit.
        max_nodes: usize,
    },
    /// The radius holding 95 % of the load (m) exceeds
    /// [`RADIUS_RATIO_WARNING`] times the sphere radius.
    ContactRadius {
        /// The radius (m).
        radius: f64,
    },
    /// Local gaps fall below the lowest represented summit, `bottom`
    /// (in units of the summit-height standard deviation sigma), where the
    /// local law is extrapolated.
    GapsBelowSummits {
        /// The lowest represented height (sigma).
        bottom: f64,
    },
    /// Fewer than 2 contacts: Greenwood's interaction left out of the
    /// resistance.
    InteractionSkipped,
    /// The real-area fraction at the centre is above 1 (the bump's real
    /// area is then null).
    AreaAboveOne {
        /// The fraction.
        fraction: f64,
        /// The fraction elastic summits without adhesion (Hertz) would
        /// give at the same central gap, `pi eta R sigma F_1(H)`.
        hertz: f64,
    },
    /// The real-area fraction at the centre is above
    /// [`AREA_FRACTION_WARNING`].
    AreaFraction {
        /// The fraction.
        fraction: f64,
    },
}

impl fmt::Display for SphereWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SphereWarning::Unconverged {
                load_error,
                tolerance,
                max_nodes,
            } => write!(
                f,
                "mesh: the load's error estimate {load_error:.1e} N is above the tolerance \
                 {tolerance:.0e} (relative) at the node limit {max_nodes}"
            ),
            SphereWarning::ContactRadius { radius } => write!(
                f,
                "model: the contact radius {radius:.3e} m exceeds {RADIUS_RATIO_WARNING} R: the \
                 half-space and small-slope assumptions are stretched"
            ),
            SphereWarning::GapsBelowSummits { bottom } => write!(
                f,
                "model: local gaps fall below {bottom:.2} sigma, under every represented summit; \
                 the local law is extrapolated there"
            ),
            SphereWarning::InteractionSkipped => {
                f.write_str("electrical: fewer than 2 contacts: Greenwood's interaction left out")
            }
            SphereWarning::AreaAboveOne { fraction, hertz } => write!(
                f,
                "model: the real-area fraction at the centre is {fraction:.2}, above 1: \
                 {}; GW's independent summits overlap there and their summed \
                 areas are not a fraction, so the bump's real area is null; its \
                 contacts and resistance count overlapping summits (a smaller load, \
                 or a harder material, keeps the centre below 1)",
                ExcessAreaCause(*fraction, *hertz)
            ),
            SphereWarning::AreaFraction { fraction } => write!(
                f,
                "model: the real-area fraction at the centre is {fraction:.2} (> \
                 {AREA_FRACTION_WARNING}): GW's independent summits overstate the \
                 stiffness of the rough layer there"
            ),
        }
    }
}

/// What makes the central real-area fraction `.0` exceed 1, against the
/// fraction `.1` of elastic summits without adhesion on the same heights
/// at the same gap. A summit's area is at most twice Hertz's at the same
/// interference without adhesion (fully plastic, `2 pi R delta` against
/// `pi R delta`, Abbott's flattening in Kogut & Etsion 2002), so beyond
/// twice `.1` the excess is the law's adhesion (on the Kogut–Etsion bump of
/// `examples/scenes/switch-bump-plastic.toml` at its former load of 20 uN,
/// measured on the flat at the central gap: Hertz 0.25, Kogut–Etsion without adhesion 0.49, with JKR
/// adhesion on the flattened tops 1.13); below it, the depth of the
/// contact itself.
struct ExcessAreaCause(f64, f64);

impl fmt::Display for ExcessAreaCause {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (frac, hertz) = (self.0, self.1);
        if frac > 2.0 * hertz {
            write!(
                f,
                "elastic summits without adhesion would give {hertz:.2} there and plastic ones \
                 at most twice that ({:.2}): the rest is the law's adhesion widening each \
                 contact (JKR on a plastic summit's flattened top reaches far beyond it)",
                2.0 * hertz
            )
        } else {
            write!(
                f,
                "elastic summits without adhesion would give {hertz:.2} there: the summits are \
                 pressed so deep that their areas alone exceed the nominal area"
            )
        }
    }
}

impl Serialize for SphereWarning {
    /// As its sentence (`Display`).
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

#[cfg(test)]
mod tests {
    use super::ExcessAreaCause;

    /// The plastic bump's centre at 20 uN (Hertz 0.2532 at the central gap
    /// -1.5882 sigma, from `tests/data/bump_centre_area.py`; the measured
    /// Kogut–Etsion fraction with adhesion 1.13) names adhesion; a fraction
    /// within twice Hertz names the depth.
    #[test]
    fn the_excess_area_is_blamed_on_its_measured_cause() {
        let hertz = 0.253_226;
        let adhesive = ExcessAreaCause(1.13, hertz).to_string();
        assert!(
            adhesive.contains("0.25") && adhesive.contains("0.51"),
            "{adhesive}"
        );
        assert!(adhesive.contains("adhesion widening"), "{adhesive}");
        let deep = ExcessAreaCause(1.13, 0.6).to_string();
        assert!(deep.contains("pressed so deep"), "{deep}");
        assert!(!deep.contains("adhesion widening"), "{deep}");
    }
}
