//! Summits of an isotropic Gaussian surface from its moments (Nayak 1971,
//! McCool 1986), and the GW parameters they give.
//!
//! For an isotropic Gaussian surface with profile moments `m0, m2, m4` the
//! summits (gradient 0, Hessian negative definite; Rice's formula) have,
//! with the mean curvature `kappa = -(z_xx + z_yy)/2`:
//! - density `eta = m4 / (6 pi sqrt(3) m2)`;
//! - mean curvature `(8 / (3 sqrt(pi))) sqrt(m4)`, so `R = 0.375 sqrt(pi/m4)`;
//! - mean height `4 sqrt(m0 / (pi alpha))`;
//! - height variance `m0 (1 - C/alpha)`, `C = 16/pi + 1 - 3 sqrt(3) = 0.8968058`.
//!
//! These are exact for every `alpha` (not large-`alpha` limits): with
//! `s = (z_xx + z_yy)/2` (variance `2 m4/3`) and the deviatoric part of the
//! Hessian (Rayleigh, parameter `m4/3`) the Rice integrand integrates in
//! closed form, `E[|det H|; H < 0 | s] = s^2 - (2 m4/3)(1 - exp(-3 s^2/(2 m4)))`,
//! and the conditional height is Gaussian with mean `-3 m2 s/(2 m4)`. The
//! derivation is checked against mpmath quadrature of the same Rice
//! integrals in `tests/data/nayak_summits.py`.

use super::Moments;
use crate::error::Result;
use crate::material::plastic::plasticity_index;
use std::f64::consts::PI;

/// The exact summit-height variance constant `16/pi + 1 - 3 sqrt(3)`.
pub const NAYAK_HEIGHT_CONSTANT: f64 = 0.896_805_756_234_018_9;

/// McCool's rounded constant `0.8968`, the one the `gw_from_moments`
/// contract of `asperity surface` fixes.
pub const MCCOOL_HEIGHT_CONSTANT: f64 = 0.8968;

/// GW parameters predicted from the moments (McCool's relations).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GwParameters {
    /// `eta = m4 / (6 pi sqrt(3) m2)` (1/m^2).
    pub density_per_m2: f64,
    /// `R = 0.375 sqrt(pi / m4)` (m).
    pub radius_m: f64,
    /// `sigma_s = sqrt(m0 (1 - 0.8968/alpha))` (m); `None` when
    /// `alpha <= 0.8968` (impossible for a continuum surface, `alpha >= 1.5`).
    pub sigma_m: Option<f64>,
}

impl GwParameters {
    /// McCool's relations applied to `m`.
    pub fn from_moments(m: &Moments) -> Self {
        let v = m.m0 * (1.0 - MCCOOL_HEIGHT_CONSTANT / m.alpha());
        GwParameters {
            density_per_m2: m.m4 / (6.0 * PI * 3f64.sqrt() * m.m2),
            radius_m: 0.375 * (PI / m.m4).sqrt(),
            sigma_m: (v > 0.0).then(|| v.sqrt()),
        }
    }

    /// GW's plasticity index with these `sigma` and `R`; `None` without a
    /// `sigma`. See [`plasticity_index`](crate::material::plastic::plasticity_index).
    ///
    /// # Errors
    /// As [`plasticity_index`](crate::material::plastic::plasticity_index).
    pub fn plasticity_index(&self, contact_modulus: f64, hardness: f64) -> Result<Option<f64>> {
        self.sigma_m
            .map(|s| plasticity_index(contact_modulus, hardness, s, self.radius_m))
            .transpose()
    }
}

/// The continuum summit statistics of an isotropic Gaussian surface
/// (exact for every `alpha`, see the module documentation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NayakPrediction {
    /// Summits per unit area (1/m^2).
    pub density_per_m2: f64,
    /// Mean of the summits' mean curvature (1/m).
    pub mean_curvature_per_m: f64,
    /// Mean summit height above the mean plane (m).
    pub mean_height_m: f64,
    /// Standard deviation of summit heights (m).
    pub height_std_m: f64,
}

impl NayakPrediction {
    /// The prediction for moments `m`.
    pub fn from_moments(m: &Moments) -> Self {
        let alpha = m.alpha();
        NayakPrediction {
            density_per_m2: m.m4 / (6.0 * PI * 3f64.sqrt() * m.m2),
            mean_curvature_per_m: 8.0 / (3.0 * PI.sqrt()) * m.m4.sqrt(),
            mean_height_m: 4.0 * (m.m0 / (PI * alpha)).sqrt(),
            height_std_m: (m.m0 * (1.0 - NAYAK_HEIGHT_CONSTANT / alpha)).sqrt(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants_and_relations() {
        let c = 16.0 / PI + 1.0 - 3.0 * 3f64.sqrt();
        assert!((c - NAYAK_HEIGHT_CONSTANT).abs() < 1e-15);
        // Gaussian autocorrelation, l = 1 um, m0 = 1 nm^2: alpha = 3.
        let l = 1e-6;
        let m = Moments::new(1e-18, 1e-18 / (l * l), 3e-18 / l.powi(4)).unwrap();
        let gw = GwParameters::from_moments(&m);
        let p = NayakPrediction::from_moments(&m);
        assert!((gw.density_per_m2 * l * l - 1.0 / (2.0 * PI * 3f64.sqrt())).abs() < 1e-15);
        assert!((gw.radius_m * p.mean_curvature_per_m - 1.0).abs() < 1e-15);
        let s = gw.sigma_m.unwrap();
        assert!((s / p.height_std_m - 1.0).abs() < 2e-6);
        let psi = gw.plasticity_index(4.8e10, 1e9).unwrap().unwrap();
        assert!((psi - 48.0 * (s / gw.radius_m).sqrt()).abs() < 1e-12);
        assert_eq!(
            plasticity_index(1.0, 0.0, 1.0, 1.0).unwrap_err().field(),
            Some("hardness")
        );
        let flat = Moments::new(1.0, 1.0, 0.5).unwrap();
        assert_eq!(GwParameters::from_moments(&flat).sigma_m, None);
    }
}
