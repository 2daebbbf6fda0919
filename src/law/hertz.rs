//! Hertz (1882): elastic sphere on a flat, no adhesion.
//!
//! `a^2 = R delta`, `P = (4/3) E* R^(1/2) delta^(3/2) = K a^3 / R` for
//! `delta > 0`, zero otherwise (Johnson, *Contact Mechanics*, eq. 4.22-4.23).

use super::{AsperityLaw, Branch, ContactState, Control, Instability, LawKernels, PowerForm};
use crate::error::{positive, Result};
use std::f64::consts::PI;

/// Hertz law for a sphere of radius `R` (m) with contact modulus `E*` (Pa).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hertz {
    radius: f64,
    /// `R^(1/2)` (m^(1/2)): `a = R^(1/2) delta^(1/2)` shares the load's
    /// square root (one `sqrt` per summit in a Monte Carlo sum).
    sqrt_radius: f64,
    /// `(4/3) E* R^(1/2)` (N/m^(3/2)).
    stiffness: f64,
}

impl Hertz {
    /// Sphere radius `R` (m) and contact modulus `E*` (Pa), both finite and > 0.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `radius` or `contact_modulus`.
    pub fn new(radius: f64, contact_modulus: f64) -> Result<Self> {
        positive("radius", radius)?;
        positive("contact_modulus", contact_modulus)?;
        Ok(Hertz {
            radius,
            sqrt_radius: radius.sqrt(),
            stiffness: 4.0 / 3.0 * contact_modulus * radius.sqrt(),
        })
    }

    /// Load `P = (4/3) E* R^(1/2) delta^(3/2)` (N), 0 for `delta <= 0`.
    #[inline]
    pub fn load_at(&self, delta: f64) -> f64 {
        if delta > 0.0 {
            self.stiffness * delta * delta.sqrt()
        } else {
            0.0
        }
    }

    /// Contact radius `a = (R delta)^(1/2)` (m), 0 for `delta <= 0`.
    #[inline]
    pub fn radius_at(&self, delta: f64) -> f64 {
        if delta > 0.0 {
            self.sqrt_radius * delta.sqrt()
        } else {
            0.0
        }
    }
}

impl AsperityLaw for Hertz {
    identity_of_kind!(Hertz);

    #[inline]
    fn state(&self, delta: f64, _branch: Branch) -> ContactState {
        ContactState {
            load: self.load_at(delta),
            radius: self.radius_at(delta),
        }
    }

    #[inline]
    fn load(&self, delta: f64, _branch: Branch) -> f64 {
        self.load_at(delta)
    }

    /// The branch is ignored: no hysteresis, no memory.
    fn reversible(&self) -> bool {
        true
    }

    /// `P = (4/3) E* sqrt(R) t^3`, `a = sqrt(R) t`: polynomials in `t`.
    fn smooth_in_root(&self) -> bool {
        true
    }

    critical_at_first_contact!();

    fn breakpoints(&self, _branch: Branch) -> Vec<f64> {
        vec![0.0]
    }

    /// Load control: the most tensile load on the curve is 0 at `delta = 0`.
    /// Displacement control: nothing snaps (`None`).
    fn pull_off(&self, control: Control) -> Option<Instability> {
        match control {
            Control::Load => Some(Instability {
                load: 0.0,
                interference: 0.0,
                radius: 0.0,
            }),
            Control::Displacement => None,
        }
    }

    fn zero_load_radius(&self) -> Option<f64> {
        None
    }

    /// `P = (4/3) E* R^(1/2) delta^(3/2)`, `pi a^2 = pi R delta`.
    fn power_form(&self) -> Option<PowerForm> {
        Some(PowerForm {
            onset: 0.0,
            load: vec![(self.stiffness, 1.5)],
            area: vec![(PI * self.radius, 1.0)],
        })
    }
}

impl LawKernels for Hertz {
    fn cost_ns(&self) -> f64 {
        super::LawKind::Hertz.cost_ns()
    }

    /// The load rises with the interference, zero out of contact.
    fn retraction_minimum(&self, _delta_max: f64) -> Option<super::RetractionMinimum> {
        Some(super::RetractionMinimum::MONOTONE)
    }

    /// Branch-free (`delta <= 0` clamped to 0, which gives exactly the
    /// free state), so the loop vectorises; SIMD width picked at run time
    /// ([`pulp::Arch`]). No history: `delta_max` is ignored. Bit for bit
    /// equal to [`Hertz::load_at`] and [`Hertz::radius_at`].
    fn state_batch(
        &self,
        delta: &[f64],
        _delta_max: Option<&[f64]>,
        load: &mut [f64],
        radius: &mut [f64],
    ) {
        let (k, sr) = (self.stiffness, self.sqrt_radius);
        crate::numeric::simd::arch().dispatch(
            #[inline(always)]
            || {
                for ((&d, l), a) in delta.iter().zip(load.iter_mut()).zip(radius.iter_mut()) {
                    (*l, *a) = root_monomial_state(d, k, sr);
                }
            },
        );
    }

    /// `(K sqrt(R), sqrt(R))`: `P = K sqrt(R) d^(3/2)` as `k * d * sqrt(d)`,
    /// `a = sqrt(R d)` as `sqrt(R) * sqrt(d)`, as in the batch above.
    fn root_monomials(&self) -> Option<(f64, f64)> {
        Some((self.stiffness, self.sqrt_radius))
    }
}

/// `(P, a) = (k d sqrt(d), c sqrt(d))` with `d = max(delta, 0)`, branch-free
/// (it vectorises): Hertz's state from `(k, c)` =
/// [`LawKernels::root_monomials`], the one formula of the batch and of the
/// Monte Carlo sums that fuse it (so they agree bit for bit).
#[inline(always)]
pub fn root_monomial_state(delta: f64, k: f64, c: f64) -> (f64, f64) {
    let d = if delta > 0.0 { delta } else { 0.0 };
    let s = d.sqrt();
    (k * d * s, c * s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn textbook_values() {
        // R = 1 mm, E* = 100 GPa, delta = 1 um: a = 31.6 um, P = (4/3) 1e11 sqrt(1e-3) 1e-9.
        let h = Hertz::new(1e-3, 1e11).unwrap();
        let s = h.state(1e-6, Branch::Approach);
        assert!((s.radius - 1e-9f64.sqrt()).abs() < 1e-18);
        let p = 4.0 / 3.0 * 1e11 * 1e-3f64.sqrt() * 1e-9;
        assert!((s.load / p - 1.0).abs() < 1e-14);
        // P = K a^3 / R
        let k = 4.0 / 3.0 * 1e11;
        assert!((s.load / (k * s.radius.powi(3) / 1e-3) - 1.0).abs() < 1e-13);
        assert_eq!(h.state(-1e-9, Branch::Retract), ContactState::FREE);
    }

    #[test]
    fn rejects_bad_input() {
        assert_eq!(Hertz::new(0.0, 1.0).unwrap_err().field(), Some("radius"));
        assert_eq!(
            Hertz::new(1.0, f64::NAN).unwrap_err().field(),
            Some("contact_modulus")
        );
    }
}
