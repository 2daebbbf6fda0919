//! Johnson–Kendall–Roberts (1971): short-range adhesion acting as a surface
//! energy inside the contact.
//!
//! In Maugis units (`A = a/(pi w R^2/K)^(1/3)`, `Pbar = P/(pi w R)`,
//! `Dbar = delta/(pi^2 w^2 R/K^2)^(1/3)`, `K = 4E*/3`):
//!
//! ```text
//! Pbar = A^3 - sqrt(6 A^3)            (P = K a^3/R - sqrt(6 pi w K a^3))
//! Dbar = A^2 - sqrt(8 A / 3)          (delta = a^2/R - sqrt(8 pi w a/(3K)))
//! ```
//!
//! Stable under displacement control for `A >= A_c = 6^(-1/3)`
//! (`dDbar/dA = 0`), where `Pbar = -5/6` and `Dbar = -(3/4)(4/3)^(2/3)`.
//! Load-controlled pull-off `Pbar = -3/2` at `A^3 = 3/2`. Zero-load radius
//! `A0 = 6^(1/3)`. Jump-in on approach at `delta = 0` (Johnson, *Contact
//! Mechanics* §5.5; Maugis, *J. Colloid Interface Sci.* 150 (1992)).

use super::{AsperityLaw, Branch, ContactState, Control, Instability};
use crate::error::Result;
use crate::material::MaugisScales;

/// `sqrt(8/3)`.
const B: f64 = 1.632_993_161_855_452_1;
/// `A_c = 6^(-1/3)`: radius at the displacement-controlled jump-out.
pub const JUMP_OUT_RADIUS: f64 = 0.550_321_208_149_104_4;
/// `Dbar_c = -(3/4)(4/3)^(2/3)`: interference at the jump-out.
pub const JUMP_OUT_INTERFERENCE: f64 = -0.908_560_296_416_069_8;
/// `Pbar = -5/6` at the jump-out.
pub const JUMP_OUT_LOAD: f64 = -5.0 / 6.0;
/// `Pbar = -3/2`: load-controlled pull-off.
pub const PULL_OFF_LOAD: f64 = -1.5;
/// `A^3 = 3/2` at the load-controlled pull-off.
pub const PULL_OFF_RADIUS: f64 = 1.144_714_242_553_331_9;
/// `A0 = 6^(1/3)`: contact radius at zero load.
pub const ZERO_LOAD_RADIUS: f64 = 1.817_120_592_832_139_7;

/// Dimensionless load `Pbar = A^3 - sqrt(6 A^3)`.
#[inline]
pub fn load_bar(a: f64) -> f64 {
    let a3 = a * a * a;
    a3 - (6.0 * a3).sqrt()
}

/// Dimensionless interference `Dbar = A^2 - sqrt(8 A/3)`.
#[inline]
pub fn interference_bar(a: f64) -> f64 {
    a * a - B * a.sqrt()
}

/// Contact radius `A` on the stable branch (`A >= 6^(-1/3)`) at
/// dimensionless interference `Dbar`, or `None` below the jump-out
/// `Dbar_c = -0.9086`.
///
/// Solves `x^4 - sqrt(8/3) x - Dbar = 0` for `x = sqrt(A)` by Newton's
/// method from an upper bound: `f` is convex, so the iterates decrease
/// monotonically to the largest root. The start is the smaller of
/// `Dbar^(1/4) + b^(1/3)` (always an upper bound) and the fold expansion
/// `x_c + sqrt((Dbar - Dbar_c)/(6 x_c^2))` (an upper bound too, since the
/// cubic and quartic terms of `f` about `x_c` are positive), which keeps
/// convergence quadratic near the fold.
#[inline]
pub fn stable_radius_bar(d: f64) -> Option<f64> {
    if !(d >= JUMP_OUT_INTERFERENCE) {
        return None;
    }
    // x_c = 6^(-1/6)
    const XC: f64 = 0.741_836_375_590_402_3;
    // B^(1/3) = (8/3)^(1/6) (mpmath), a constant rather than a cbrt per call.
    const B_CBRT: f64 = 1.177_591_843_000_480_9;
    let bound = d.max(0.0).sqrt().sqrt() + B_CBRT;
    let fold = XC + ((d - JUMP_OUT_INTERFERENCE) / (6.0 * XC * XC)).sqrt();
    let mut x = bound.min(fold);
    for _ in 0..60 {
        let x2 = x * x;
        let f = x2 * x2 - B * x - d;
        let fp = 4.0 * x2 * x - B;
        if fp <= 0.0 {
            break;
        }
        let step = f / fp;
        x -= step;
        if step.abs() <= 4.0 * f64::EPSILON * x {
            break;
        }
    }
    Some(x.max(XC) * x.max(XC))
}

/// JKR law for a sphere of radius `R` (m), contact modulus `E*` (Pa) and
/// work of adhesion `w` (J/m^2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jkr {
    scales: MaugisScales,
}

impl Jkr {
    /// All arguments finite and > 0 (use [`super::Hertz`] when `w = 0`).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `radius`, `contact_modulus` or
    /// `work_of_adhesion`.
    pub fn new(radius: f64, contact_modulus: f64, work: f64) -> Result<Self> {
        Ok(Jkr {
            scales: MaugisScales::new(radius, contact_modulus, work)?,
        })
    }

    /// The Maugis scales of this contact.
    pub fn scales(&self) -> MaugisScales {
        self.scales
    }

    #[inline]
    fn attached(&self, delta: f64) -> ContactState {
        match stable_radius_bar(delta / self.scales.interference) {
            Some(a) => ContactState {
                load: load_bar(a) * self.scales.load,
                radius: a * self.scales.radius,
            },
            None => ContactState::FREE,
        }
    }
}

impl AsperityLaw for Jkr {
    fn name(&self) -> &'static str {
        "jkr"
    }

    #[inline]
    fn state(&self, delta: f64, branch: Branch) -> ContactState {
        match branch {
            Branch::Approach if delta < 0.0 => ContactState::FREE,
            _ => self.attached(delta),
        }
    }

    fn attach_interference(&self) -> f64 {
        0.0
    }

    fn detach_interference(&self) -> f64 {
        JUMP_OUT_INTERFERENCE * self.scales.interference
    }

    fn cutoff_interference(&self) -> f64 {
        self.detach_interference()
    }

    fn breakpoints(&self, branch: Branch) -> Vec<f64> {
        match branch {
            Branch::Approach => vec![0.0],
            Branch::Retract => vec![self.detach_interference()],
        }
    }

    fn pull_off(&self, control: Control) -> Option<Instability> {
        let s = self.scales;
        let (a, p) = match control {
            Control::Load => (PULL_OFF_RADIUS, PULL_OFF_LOAD),
            Control::Displacement => (JUMP_OUT_RADIUS, JUMP_OUT_LOAD),
        };
        Some(Instability {
            load: p * s.load,
            interference: interference_bar(a) * s.interference,
            radius: a * s.radius,
        })
    }

    fn zero_load_radius(&self) -> Option<f64> {
        Some(ZERO_LOAD_RADIUS * self.scales.radius)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants_match_their_formulas() {
        assert!((B - (8.0f64 / 3.0).sqrt()).abs() < 1e-16);
        assert!(((8.0f64 / 3.0).powf(1.0 / 6.0) - 1.177_591_843_000_480_9).abs() < 3e-16);
        // powf is good to ~1 ulp (1.1e-16 here).
        assert!((JUMP_OUT_RADIUS - 6f64.powf(-1.0 / 3.0)).abs() < 3e-16);
        assert!((ZERO_LOAD_RADIUS - 6f64.cbrt()).abs() < 1e-15);
        assert!((PULL_OFF_RADIUS - 1.5f64.cbrt()).abs() < 1e-15);
        assert!((JUMP_OUT_RADIUS.sqrt() - 6f64.powf(-1.0 / 6.0)).abs() < 3e-16);
        let dc = -0.75 * (4.0f64 / 3.0).powf(2.0 / 3.0);
        assert!((JUMP_OUT_INTERFERENCE - dc).abs() < 1e-15);
        assert!((interference_bar(JUMP_OUT_RADIUS) - dc).abs() < 1e-15);
        assert!((load_bar(JUMP_OUT_RADIUS) - JUMP_OUT_LOAD).abs() < 1e-15);
        assert!((load_bar(PULL_OFF_RADIUS) - PULL_OFF_LOAD).abs() < 1e-15);
        assert!(load_bar(ZERO_LOAD_RADIUS).abs() < 1e-14);
    }

    #[test]
    fn radius_inverts_interference_on_stable_branch() {
        // A from just above the fold to deep contact; round trip to ~1e-15
        // except near the fold, where the root is ill-conditioned:
        // dA ~ dD / (dD/dA) and dD/dA -> 0.
        let mut a = JUMP_OUT_RADIUS * (1.0 + 1e-6);
        while a < 1e4 {
            let d = interference_bar(a);
            let back = stable_radius_bar(d).unwrap();
            let slope = 2.0 * a - 0.5 * B / a.sqrt();
            let tol = 4e-16 * (1.0 + d.abs()) / slope + 1e-15 * a;
            assert!((back - a).abs() <= tol, "A {a}: got {back}, tol {tol}");
            a *= 1.07;
        }
        assert!(stable_radius_bar(JUMP_OUT_INTERFERENCE - 1e-12).is_none());
        assert!(stable_radius_bar(f64::NAN).is_none());
        let at_fold = stable_radius_bar(JUMP_OUT_INTERFERENCE).unwrap();
        assert!((at_fold - JUMP_OUT_RADIUS).abs() < 1e-7);
    }

    #[test]
    fn dimensional_law_matches_textbook_formulas() {
        let (r, e, w) = (1e-6, 5e10, 0.5);
        let jkr = Jkr::new(r, e, w).unwrap();
        let k = 4.0 * e / 3.0;
        for a in [2e-8, 5e-8, 1e-7, 3e-7] {
            let delta = a * a / r - (8.0 * std::f64::consts::PI * w * a / (3.0 * k)).sqrt();
            let p = k * a.powi(3) / r - (6.0 * std::f64::consts::PI * w * k * a.powi(3)).sqrt();
            let s = jkr.state(delta, Branch::Retract);
            if a >= JUMP_OUT_RADIUS * jkr.scales().radius {
                assert!((s.radius / a - 1.0).abs() < 1e-10, "{a}");
                assert!((s.load - p).abs() < 1e-10 * p.abs().max(jkr.scales().load));
            }
        }
        let pull = jkr.pull_off(Control::Displacement).unwrap();
        let dc = -0.75 * (std::f64::consts::PI.powi(2) * w * w * r / (e * e)).cbrt();
        assert!((pull.interference / dc - 1.0).abs() < 1e-14);
    }
}
