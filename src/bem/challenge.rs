//! The contact-mechanics challenge (Müser, Dapp, Bugnicourt et al., "Meeting
//! the contact-mechanics challenge", Tribol. Lett. 65, 118 (2017)): its
//! published surface spectrum, material and interaction, and a surface
//! generated from that spectrum with a fixed seed.
//!
//! The spectrum: isotropic, self-affine with Hurst exponent `H = 0.8`,
//! `C(q)` flat from the longest wavelength `L = 0.1 mm` (the periodic side)
//! to the roll-off wavelength `lambda_r = 20 um`, `C ~ q^(-2(1+H))` from
//! there to the short cut-off `lambda_s = 0.1 um`, zero beyond
//! ([`crate::spectrum::Spectrum::self_affine`] with `q = 2 pi/lambda`). The
//! map ([`crate::spectrum::synthesis::random_phase_map`], seed [`SEED`]) is
//! scaled so that its RMS gradient ([`slope_rms`], periodic forward
//! differences) is exactly 1, the challenge's `g`; on a grid whose pixel is
//! coarser than `lambda_s/2` (512^2: 195 nm) the grid's Nyquist wavevector
//! cuts the spectrum before `q_s`.
//!
//! The problem: contact modulus `E* = 25 MPa`, work of adhesion
//! `w = 50 mJ/m^2`, reference pressure `p = 0.01 E* g = 250 kPa`. The
//! challenge's interaction range `rho = 2.071 nm` needs a pixel of a few nm
//! (the published runs used 32768^2); on the 512^2 or 2048^2 grids here the
//! range is [`RANGE_FACTOR`] times longer, as in Adhesion 0.93's example on
//! the challenge's 512^2 topography (Müser's `mu_rho = sqrt(w dx/(E*
//! rho^2)) = 0.318` at 512^2, below the 0.5 that resolves the interaction;
//! Wang, Zhou & Müser, Lubricants 9, 17 (2021)).

use crate::error::{Allowed, Result};
use crate::spectrum::{synthesis::random_phase_map, Normalisation, Spectrum};
use crate::surface::HeightMap;
use std::f64::consts::PI;

/// The seed of the generated surface's random phases.
pub const SEED: u64 = 2017;
/// Side of the periodic square (m): 0.1 mm.
pub const SIDE: f64 = 1e-4;
/// Hurst exponent.
pub const HURST: f64 = 0.8;
/// Roll-off wavelength (m): 20 um.
pub const ROLL_OFF_WAVELENGTH: f64 = 20e-6;
/// Short cut-off wavelength (m): 0.1 um.
pub const SHORT_WAVELENGTH: f64 = 0.1e-6;
/// Contact modulus `E*` (Pa): 25 MPa.
pub const CONTACT_MODULUS: f64 = 25e6;
/// Work of adhesion `w` (J/m^2): 50 mJ/m^2.
pub const ADHESION_ENERGY: f64 = 0.05;
/// The challenge's interaction range `rho` (m): 2.071 nm.
pub const PUBLISHED_RANGE: f64 = 2.071e-9;
/// The range used on the coarse grids, as a multiple of
/// [`PUBLISHED_RANGE`] (Adhesion 0.93's example at 512^2): 30.
pub const RANGE_FACTOR: f64 = 30.0;
/// The RMS gradient `g` the map is scaled to (dimensionless): 1.
pub const SLOPE_RMS: f64 = 1.0;

/// The challenge on an `n x n` grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Challenge {
    /// Pixels per side.
    pub n: usize,
    /// Contact modulus `E*` (Pa).
    pub contact_modulus: f64,
    /// Work of adhesion `w` (J/m^2).
    pub adhesion_energy: f64,
    /// Reference mean pressure `0.01 E* g` (Pa).
    pub reference_pressure: f64,
}

impl Challenge {
    /// The challenge on `n x n` pixels of side `SIDE/n`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `n` (16 to 8192).
    pub fn at(n: usize) -> Result<Self> {
        Allowed::closed(16.0, 8192.0).check("n", n as f64)?;
        Ok(Challenge {
            n,
            contact_modulus: CONTACT_MODULUS,
            adhesion_energy: ADHESION_ENERGY,
            reference_pressure: 0.01 * CONTACT_MODULUS * SLOPE_RMS,
        })
    }

    /// Pixel size `SIDE/n` (m).
    pub fn pixel_size(&self) -> f64 {
        SIDE / self.n as f64
    }

    /// The interaction range used (m): `RANGE_FACTOR x PUBLISHED_RANGE`.
    pub fn adhesion_range(&self) -> f64 {
        RANGE_FACTOR * PUBLISHED_RANGE
    }

    /// The published spectrum, normalised to RMS gradient [`SLOPE_RMS`]
    /// over its whole band (the map is scaled again on its grid,
    /// [`Challenge::surface`]). `q_long = pi/SIDE` (half the grid's
    /// smallest wavevector: `C` is flat there, so every grid wavevector
    /// from `2 pi/SIDE` up is inside the spectrum whatever its rounding).
    ///
    /// # Errors
    /// None for these constants (the spectrum's own checks).
    pub fn spectrum() -> Result<Spectrum> {
        Spectrum::self_affine(
            HURST,
            PI / SIDE,
            2.0 * PI / ROLL_OFF_WAVELENGTH,
            2.0 * PI / SHORT_WAVELENGTH,
            Normalisation::SlopeRms(SLOPE_RMS),
        )
    }

    /// The periodic surface (heights in m, row-major, mean 0): random
    /// phases of seed [`SEED`] on the spectrum ([`Challenge::spectrum`]),
    /// scaled to `slope_rms = 1` exactly on the grid.
    ///
    /// # Errors
    /// None for these constants (the synthesis' own checks).
    pub fn surface(&self) -> Result<HeightMap> {
        let dx = self.pixel_size();
        let map = random_phase_map(&Challenge::spectrum()?, self.n, self.n, dx, SEED)?;
        let g = slope_rms(&map, dx);
        map.scaled(SLOPE_RMS / g)
    }
}

/// RMS gradient of a periodic square-pixel map (dimensionless):
/// `sqrt(mean((h[i][j+1] - h[i][j])^2 + (h[i+1][j] - h[i][j])^2))/dx`,
/// indices modulo the map's size (periodic forward differences).
pub fn slope_rms(map: &HeightMap, dx: f64) -> f64 {
    let (rows, cols) = (map.rows(), map.cols());
    let h = map.heights();
    let mut s = 0.0;
    for i in 0..rows {
        let down = ((i + 1) % rows) * cols;
        for j in 0..cols {
            let k = i * cols + j;
            let right = i * cols + (j + 1) % cols;
            s += (h[right] - h[k]).powi(2) + (h[down + j] - h[k]).powi(2);
        }
    }
    (s / (rows * cols) as f64).sqrt() / dx
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_surface_has_unit_slope_and_the_reference_pressure_is_250_kpa() {
        let c = Challenge::at(64).unwrap();
        let map = c.surface().unwrap();
        assert!((slope_rms(&map, c.pixel_size()) - 1.0).abs() < 1e-12);
        assert_eq!(c.reference_pressure, 250e3);
        assert!((c.adhesion_range() - 62.13e-9).abs() < 1e-20);
        assert_eq!(map, c.surface().unwrap());
        assert!(Challenge::at(8).is_err());
    }
}
