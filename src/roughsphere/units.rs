//! Greenwood–Tripp units and the closed-form limits in them.
//!
//! Greenwood & Tripp (1967, J. Appl. Mech. 34, 153; Johnson, *Contact
//! Mechanics*, sec. 13.4) scale the rough sphere (radius `R`, their `B`) on a
//! Greenwood–Williamson surface (summit density `eta`, summit radius `beta`,
//! summit-height standard deviation `sigma`, contact modulus `E*`) as
//!
//! | quantity | unit |
//! |---|---|
//! | radius `rho` | `sqrt(2 R sigma)` |
//! | gaps, approach, displacements | `sigma` |
//! | pressure | `E* sqrt(sigma/(8R))` |
//! | load `P* = 2 pi int p rho drho` | `E* sqrt(sigma/(8R)) 2 R sigma` |
//!
//! With Hertz summits on Gaussian heights the local pressure is then
//! `p = mu F_3/2(H)`, `mu = (8/3) eta sigma sqrt(2 R beta)`
//! ([`greenwood_tripp_mu`]): the GW pressure
//! `(4/3) eta E* beta^(1/2) sigma^(3/2) F_3/2` divided by the pressure unit.
//! The elastic displacement is `u = (1/2) C p` with `C` the half-space
//! compliance in radius units (`E* w = C p` for `r` in metres), so the
//! central deflection is `u(0) = int_0^inf p drho`.

use crate::error::{positive, Result};
use crate::special::gaussian_fn::gaussian_fn;
use std::f64::consts::PI;

/// The Greenwood–Tripp scales of one sphere on one surface (SI in, SI out).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GreenwoodTrippUnits {
    /// Sphere radius `R` (m).
    pub sphere_radius: f64,
    /// Summit-height standard deviation `sigma` (m).
    pub sigma: f64,
    /// Contact modulus `E*` (Pa) of the sphere and the rough body's bulk.
    pub contact_modulus: f64,
}

impl GreenwoodTrippUnits {
    /// Validates `R`, `sigma`, `E*` (finite, > 0).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `sphere_radius`, `sigma` or
    /// `contact_modulus`.
    pub fn new(sphere_radius: f64, sigma: f64, contact_modulus: f64) -> Result<Self> {
        positive("sphere_radius", sphere_radius)?;
        positive("sigma", sigma)?;
        positive("contact_modulus", contact_modulus)?;
        Ok(GreenwoodTrippUnits {
            sphere_radius,
            sigma,
            contact_modulus,
        })
    }

    /// Radius unit `sqrt(2 R sigma)` (m).
    pub fn length(&self) -> f64 {
        (2.0 * self.sphere_radius * self.sigma).sqrt()
    }

    /// Gap unit `sigma` (m).
    pub fn gap(&self) -> f64 {
        self.sigma
    }

    /// Pressure unit `E* sqrt(sigma/(8R))` (Pa).
    pub fn pressure(&self) -> f64 {
        self.contact_modulus * (self.sigma / (8.0 * self.sphere_radius)).sqrt()
    }

    /// Load unit `E* sqrt(sigma/(8R)) 2 R sigma` (N).
    pub fn load(&self) -> f64 {
        self.pressure() * 2.0 * self.sphere_radius * self.sigma
    }

    /// Area unit `2 R sigma` (m^2).
    pub fn area(&self) -> f64 {
        2.0 * self.sphere_radius * self.sigma
    }
}

/// Greenwood–Tripp's `mu = (8/3) eta sigma sqrt(2 R beta)` (dimensionless)
/// for summit density `eta` (1/m^2), summit-height standard deviation
/// `sigma` (m), sphere radius `R` (m) and summit radius `beta` (m): the
/// ratio of the asperities' stiffness to the bulk's (Greenwood & Tripp
/// 1967; Johnson sec. 13.4 writes it with `B` for `R`). Large `mu`: the
/// rough layer is stiff against the bulk (Hertz-like); small: the bulk is
/// rigid against it (GW without bulk deformation).
pub fn greenwood_tripp_mu(density: f64, sigma: f64, sphere_radius: f64, summit_radius: f64) -> f64 {
    8.0 / 3.0 * density * sigma * (2.0 * sphere_radius * summit_radius).sqrt()
}

/// The rigid-sphere limit (`mu -> 0`, no bulk deformation) of the
/// Greenwood–Tripp load for Hertz summits on Gaussian heights, in
/// Greenwood–Tripp units: `P* = 2 pi mu int_0^inf F_3/2(d + rho^2) rho drho
/// = pi mu F_5/2(d)/(5/2)` (from `dF_(n+1)/dh = -(n+1) F_n`).
pub fn rigid_load_gt(mu: f64, d: f64) -> f64 {
    PI * mu * gaussian_fn(2.5, d).unwrap_or(f64::NAN) / 2.5
}

/// Hertz contact radius for a load `P*` (Greenwood–Tripp units):
/// `a = (3 P R/(4 E*))^(1/3)` becomes `rho_a = (3 P*/16)^(1/3)`; 0 for
/// `P* <= 0`.
pub fn hertz_radius_gt(load: f64) -> f64 {
    if load > 0.0 {
        (3.0 * load / 16.0).cbrt()
    } else {
        0.0
    }
}

/// Hertz pressure at `rho` for a load `P*` (Greenwood–Tripp units):
/// `p = (3 P*/(2 pi rho_a^2)) sqrt(1 - rho^2/rho_a^2)` inside `rho_a`, 0
/// outside.
pub fn hertz_pressure_gt(load: f64, rho: f64) -> f64 {
    let a = hertz_radius_gt(load);
    if a > 0.0 && rho < a {
        3.0 * load / (2.0 * PI * a * a) * (1.0 - (rho / a) * (rho / a)).sqrt()
    } else {
        0.0
    }
}

/// Hertz approach (interference of distant points) for a load `P*`, in
/// units of `sigma`: `alpha = a^2/R` becomes `2 rho_a^2`.
pub fn hertz_approach_gt(load: f64) -> f64 {
    let a = hertz_radius_gt(load);
    2.0 * a * a
}

/// Radius holding the fraction `f` of a Hertz load: `1 - (1 - x^2)^(3/2)
/// = f` gives `x = sqrt(1 - (1 - f)^(2/3))` (0.9297 for 95 %).
pub fn hertz_load_fraction_radius(fraction: f64) -> f64 {
    (1.0 - (1.0 - fraction).powf(2.0 / 3.0)).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Hertz pressure integrates to its load; the units are
    /// consistent: `P = (4/3) E* R^(1/2) alpha^(3/2)` in SI.
    #[test]
    fn hertz_in_gt_units() {
        let load = 7.3;
        let a = hertz_radius_gt(load);
        let n = 20000;
        let mut s = 0.0;
        for k in 0..n {
            let r = a * (k as f64 + 0.5) / n as f64;
            s += hertz_pressure_gt(load, r) * r * a / n as f64;
        }
        assert!((2.0 * PI * s - load).abs() < 1e-5 * load);
        let u = GreenwoodTrippUnits::new(5e-6, 3e-9, 80e9).unwrap();
        let p_si = load * u.load();
        let alpha_si = hertz_approach_gt(load) * u.gap();
        let hertz = 4.0 / 3.0 * u.contact_modulus * u.sphere_radius.sqrt() * alpha_si.powf(1.5);
        assert!((hertz - p_si).abs() < 1e-12 * p_si, "{hertz} {p_si}");
        let a_si = a * u.length();
        assert!(
            (a_si.powi(3) - 3.0 * p_si * u.sphere_radius / (4.0 * u.contact_modulus)).abs()
                < 1e-12 * a_si.powi(3)
        );
        assert!((hertz_load_fraction_radius(0.95) - 0.929_666_133_173_761_8).abs() < 1e-12);
    }
}
