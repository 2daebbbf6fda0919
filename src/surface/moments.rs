//! Profile spectral moments by finite differences, averaged over x and y.
//!
//! With residual heights `z` (mean plane removed) and pixel size `dx`:
//! `m0 = mean z^2`;
//! `m2 = (mean (dz/dx)^2 + mean (dz/dy)^2)/2`, forward differences
//! `(z[i,j+1] - z[i,j])/dx`, `(z[i+1,j] - z[i,j])/dx`;
//! `m4` likewise with `(z[i,j+1] - 2 z[i,j] + z[i,j-1])/dx^2` and its y twin.
//! Only differences inside the array count (`rows (cols-1)` forward
//! differences along x, ...), or every pixel with wrapped neighbours for a
//! periodic map. Nayak's bandwidth `alpha = m0 m4 / m2^2`.

use super::scan::DiffSums;
use crate::error::{positive, Error, Result};

/// Spectral moments of a surface: `m0` (m^2), `m2` (1), `m4` (1/m^2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Moments {
    /// Height variance about the mean plane (m^2).
    pub m0: f64,
    /// Mean square slope of a profile (dimensionless).
    pub m2: f64,
    /// Mean square curvature of a profile (1/m^2).
    pub m4: f64,
}

impl Moments {
    /// Moments given directly (e.g. of a known spectrum).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `m0`, `m2` or `m4` unless each is finite
    /// and > 0.
    pub fn new(m0: f64, m2: f64, m4: f64) -> Result<Self> {
        Ok(Moments {
            m0: positive("m0", m0)?,
            m2: positive("m2", m2)?,
            m4: positive("m4", m4)?,
        })
    }

    /// Nayak's bandwidth parameter `alpha = m0 m4 / m2^2` (>= 1.5 for an
    /// isotropic continuum surface; 3 for a Gaussian autocorrelation).
    pub fn alpha(&self) -> f64 {
        self.m0 * self.m4 / (self.m2 * self.m2)
    }

    /// RMS height `sqrt(m0)` (m).
    pub fn rms_height(&self) -> f64 {
        self.m0.sqrt()
    }

    /// RMS slope of a profile `sqrt(m2)` (dimensionless): along x or y,
    /// averaged over both (SurfaceTopography's `rms_slope_from_profile`).
    pub fn rms_slope(&self) -> f64 {
        self.m2.sqrt()
    }

    /// RMS gradient of the surface `sqrt(2 m2)` (dimensionless):
    /// `sqrt(<|grad z|^2>)` of an isotropic surface, `sqrt(2)` times the
    /// profile slope (the easy factor to miss).
    pub fn rms_gradient(&self) -> f64 {
        (2.0 * self.m2).sqrt()
    }

    /// RMS curvature of a profile `sqrt(m4)` (1/m): the second derivative
    /// along x or y, averaged over both (SurfaceTopography's
    /// `rms_curvature_from_profile`).
    pub fn rms_curvature(&self) -> f64 {
        self.m4.sqrt()
    }

    /// Measures the finite-difference moments of residual heights `z`
    /// (row-major, `rows, cols >= 3`, pixel size `dx` in m).
    #[cfg(test)]
    pub(crate) fn measure(z: &[f64], rows: usize, cols: usize, dx: f64, periodic: bool) -> Self {
        let scan = super::scan::scan(rows, cols, (dx, dx), periodic, |i, out| {
            out.copy_from_slice(&z[i * cols..(i + 1) * cols])
        });
        Moments::from_sums(&scan.sums, rows, cols, (dx, dx), periodic)
    }

    /// The moments from the difference sums of a `rows x cols` map
    /// (`[z^2, x first, y first, x second, y second]`, see `scan.rs`):
    /// each sum divided by its number of differences, the x differences by
    /// powers of `dx`, the y ones by powers of `dy`.
    pub(crate) fn from_sums(
        t: &DiffSums,
        rows: usize,
        cols: usize,
        (dx, dy): (f64, f64),
        periodic: bool,
    ) -> Self {
        let (r, c) = (rows as f64, cols as f64);
        let n = |a: f64, b: f64| if periodic { r * c } else { a * b };
        let m0 = t[0] / (r * c);
        let (m2, m4) = if dx == dy {
            (
                (t[1] / n(r, c - 1.0) + t[2] / n(r - 1.0, c)) / 2.0 / (dx * dx),
                (t[3] / n(r, c - 2.0) + t[4] / n(r - 2.0, c)) / 2.0 / (dx * dx * dx * dx),
            )
        } else {
            (
                (t[1] / n(r, c - 1.0) / (dx * dx) + t[2] / n(r - 1.0, c) / (dy * dy)) / 2.0,
                (t[3] / n(r, c - 2.0) / (dx * dx * dx * dx)
                    + t[4] / n(r - 2.0, c) / (dy * dy * dy * dy))
                    / 2.0,
            )
        };
        Moments { m0, m2, m4 }
    }

    /// Errors unless every moment is > 0 (a flat map has none).
    pub(crate) fn check_not_flat(self) -> Result<Self> {
        if self.m0 > 0.0 && self.m2 > 0.0 && self.m4 > 0.0 {
            Ok(self)
        } else {
            Err(Error::invalid(
                super::map::NAME,
                "flat after mean-plane removal: m0, m2 or m4 is 0",
            ))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sinusoid_has_the_finite_difference_moments_of_its_formula() {
        // z = sin(k j) along x, periodic over 16 pixels: forward difference
        // squared averages to 2 (1 - cos k) * 1/2, second difference
        // to (2 - 2 cos k)^2 / 2; nothing along y.
        let (rows, cols, dx) = (3, 16, 1e-6);
        let k = 2.0 * std::f64::consts::PI / cols as f64;
        let z: Vec<f64> = (0..rows * cols)
            .map(|p| (k * (p % cols) as f64).sin())
            .collect();
        let m = Moments::measure(&z, rows, cols, dx, true);
        assert!((m.m0 - 0.5).abs() < 1e-15);
        let m2 = (1.0 - k.cos()) / 2.0 / (dx * dx);
        let m4 = (2.0 - 2.0 * k.cos()).powi(2) / 4.0 / dx.powi(4);
        assert!((m.m2 / m2 - 1.0).abs() < 1e-13, "{} {m2}", m.m2);
        assert!((m.m4 / m4 - 1.0).abs() < 1e-13, "{} {m4}", m.m4);
        assert!(Moments::new(1.0, 0.0, 1.0).is_err());
        assert!((Moments::new(2.0, 1.0, 1.5).unwrap().alpha() - 3.0).abs() < 1e-15);
    }
}
