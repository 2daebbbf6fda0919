//! The statistics of a nominally flat rough surface (Greenwood & Williamson 1966).

use crate::error::{positive, Result};

/// A nominally flat rough surface against a rigid flat: spherical summits of
/// one radius with random heights.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoughSurface {
    /// Summit areal density `eta` (1/m^2).
    pub density: f64,
    /// Summit radius `R` (m), the same for every summit.
    pub radius: f64,
    /// Summit-height scale `sigma` (m): the standard deviation for Gaussian
    /// heights, the decay length for GW's exponential form.
    pub sigma: f64,
    /// Nominal (apparent) area `A_n` (m^2).
    pub nominal_area: f64,
}

impl RoughSurface {
    /// Validates every field: finite and > 0.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `density`, `radius`, `sigma` or
    /// `nominal_area`.
    pub fn new(density: f64, radius: f64, sigma: f64, nominal_area: f64) -> Result<Self> {
        positive("density", density)?;
        positive("radius", radius)?;
        positive("sigma", sigma)?;
        positive("nominal_area", nominal_area)?;
        Ok(RoughSurface {
            density,
            radius,
            sigma,
            nominal_area,
        })
    }

    /// The default gold microswitch surface: `eta = 1e12 m^-2`, `R = 1 um`,
    /// `sigma = 5 nm`, nominal area 100 um x 100 um.
    pub fn gold_microswitch() -> Self {
        use crate::material::gold;
        RoughSurface {
            density: gold::SUMMIT_DENSITY,
            radius: gold::SUMMIT_RADIUS,
            sigma: gold::SUMMIT_SIGMA,
            nominal_area: gold::NOMINAL_AREA,
        }
    }

    /// Number of summits `N = eta A_n`.
    pub fn summits(&self) -> f64 {
        self.density * self.nominal_area
    }

    /// GW's plasticity index of these summits
    /// ([`crate::material::plastic::plasticity_index`]).
    ///
    /// # Errors
    /// As [`crate::material::plastic::plasticity_index`].
    pub fn plasticity_index(&self, contact_modulus: f64, hardness: f64) -> crate::Result<f64> {
        crate::material::plastic::plasticity_index(
            contact_modulus,
            hardness,
            self.sigma,
            self.radius,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn validates_each_field() {
        assert!(RoughSurface::new(1e12, 1e-6, 5e-9, 1e-8).is_ok());
        for (i, name) in ["density", "radius", "sigma", "nominal_area"]
            .iter()
            .enumerate()
        {
            for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
                let mut v = [1e12, 1e-6, 5e-9, 1e-8];
                v[i] = bad;
                let e = RoughSurface::new(v[0], v[1], v[2], v[3]).unwrap_err();
                assert_eq!(e.field(), Some(*name));
            }
        }
    }

    #[test]
    fn derived_numbers() {
        let s = RoughSurface::gold_microswitch();
        assert!((s.summits() - 1e4).abs() < 1e-9);
        let psi = s.plasticity_index(4.8e10, 1e9).unwrap();
        assert!((psi - 48.0 * (5e-3f64).sqrt()).abs() < 1e-12);
    }
}
