//! Bradley (1932): a rigid sphere attracted to a rigid flat by the
//! Lennard-Jones (Derjaguin 9-3) surface force, integrated with the
//! Derjaguin approximation.
//!
//! With `h = z0 - delta` the gap at the centre (the sphere sits at the
//! equilibrium separation `z0` when `delta = 0`):
//!
//! ```text
//! F(h) = -(8 pi w R / 3) [ (z0/h)^2 - (1/4) (z0/h)^8 ]
//! ```
//!
//! minimum `-2 pi w R` at `h = z0` (`delta = 0`). The law is the same on both
//! branches (a rigid body does not snap), never exactly zero (it decays like
//! `h^-2`), has no contact radius, and diverges as `delta -> z0`:
//! [`AsperityLaw::max_interference`] is `z0`, and the load is `+inf` beyond.
//! It is a single-asperity reference (the `mu -> 0` limit of the full
//! solver), not a law for statistical integration over unbounded heights.

use super::{AsperityLaw, Branch, ContactState, Control, Instability, LawKernels};
use crate::error::{positive, Result};
use std::f64::consts::PI;

/// Rigid-sphere Lennard-Jones law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bradley {
    /// `8 pi w R / 3` (N).
    scale: f64,
    z0: f64,
}

impl Bradley {
    /// Sphere radius `R` (m), work of adhesion `w` (J/m^2) and equilibrium
    /// separation `z0` (m), all finite and > 0.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `radius`, `work_of_adhesion` or `z0`.
    pub fn new(radius: f64, work: f64, z0: f64) -> Result<Self> {
        positive("radius", radius)?;
        positive("work_of_adhesion", work)?;
        positive("z0", z0)?;
        Ok(Bradley {
            scale: 8.0 * PI * work * radius / 3.0,
            z0,
        })
    }

    /// Force (N) at central gap `h` (m): `-(8 pi w R/3)[(z0/h)^2 - (z0/h)^8/4]`;
    /// `+inf` for `h <= 0`.
    #[inline]
    pub fn force_at_gap(&self, h: f64) -> f64 {
        if !(h > 0.0) {
            return f64::INFINITY;
        }
        let q = self.z0 / h;
        let q2 = q * q;
        let q8 = q2 * q2 * q2 * q2;
        -self.scale * (q2 - 0.25 * q8)
    }
}

impl AsperityLaw for Bradley {
    identity_of_kind!(Bradley);

    #[inline]
    fn state(&self, delta: f64, _branch: Branch) -> ContactState {
        ContactState {
            load: self.force_at_gap(self.z0 - delta),
            radius: 0.0,
        }
    }

    /// The branch is ignored: no hysteresis, no memory.
    fn reversible(&self) -> bool {
        true
    }

    fn attach_interference(&self) -> f64 {
        f64::NEG_INFINITY
    }

    fn detach_interference(&self) -> f64 {
        f64::NEG_INFINITY
    }

    fn cutoff_interference(&self) -> f64 {
        f64::NEG_INFINITY
    }

    fn max_interference(&self) -> f64 {
        self.z0
    }

    fn breakpoints(&self, _branch: Branch) -> Vec<f64> {
        Vec::new()
    }

    /// Load control: `-2 pi w R` at `delta = 0`. Displacement control:
    /// nothing snaps (a rigid sphere follows the force curve), so `None`.
    fn pull_off(&self, control: Control) -> Option<Instability> {
        match control {
            Control::Load => Some(Instability {
                load: -0.75 * self.scale,
                interference: 0.0,
                radius: 0.0,
            }),
            Control::Displacement => None,
        }
    }

    fn zero_load_radius(&self) -> Option<f64> {
        None
    }
}

impl LawKernels for Bradley {
    fn cost_ns(&self) -> f64 {
        super::LawKind::Bradley.cost_ns()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn minimum_is_minus_two_pi_w_r_at_z0() {
        let (r, w, z0) = (1e-6, 0.5, 3e-10);
        let b = Bradley::new(r, w, z0).unwrap();
        let fmin = b.load(0.0, Branch::Approach);
        assert!((fmin / (-2.0 * PI * w * r) - 1.0).abs() < 1e-15);
        for d in [-1e-9, -1e-10, -1e-11, 1e-11, 1e-10] {
            assert!(b.load(d, Branch::Approach) > fmin);
        }
        // Zero force where (z0/h)^6 = 4: h = 4^(-1/6) z0.
        let h0 = 4f64.powf(-1.0 / 6.0) * z0;
        assert!(b.force_at_gap(h0).abs() < 1e-12 * b.scale);
        assert_eq!(b.load(z0, Branch::Retract), f64::INFINITY);
        // Far field ~ -(8 pi w R/3)(z0/h)^2.
        let h = 1e3 * z0;
        assert!((b.force_at_gap(h) / (-b.scale * 1e-6) - 1.0).abs() < 1e-12);
    }
}
