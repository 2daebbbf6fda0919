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

use crate::error::{positive, Error, Result};
use rayon::prelude::*;

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

/// Sums over one row: `z^2`, x and y first and second differences squared.
#[derive(Default, Clone, Copy)]
struct RowSums([f64; 5]);

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
    pub(crate) fn measure(z: &[f64], rows: usize, cols: usize, dx: f64, periodic: bool) -> Self {
        let row = |i: usize| &z[i * cols..(i + 1) * cols];
        let per_row: Vec<RowSums> = (0..rows)
            .into_par_iter()
            .map(|i| {
                let mut s = RowSums::default();
                let r = row(i);
                s.0[0] = r.iter().map(|v| v * v).sum();
                s.0[1] = x_first(r, periodic);
                s.0[3] = x_second(r, periodic);
                let next = if i + 1 < rows {
                    Some(i + 1)
                } else {
                    periodic.then_some(0)
                };
                if let Some(n) = next {
                    s.0[2] = row(n).iter().zip(r).map(|(a, b)| (a - b) * (a - b)).sum();
                }
                let prev = if i > 0 {
                    Some(i - 1)
                } else {
                    periodic.then_some(rows - 1)
                };
                if let (Some(p), Some(n)) = (prev, next) {
                    s.0[4] = row(n)
                        .iter()
                        .zip(r)
                        .zip(row(p))
                        .map(|((a, b), c)| {
                            let d = a - 2.0 * b + c;
                            d * d
                        })
                        .sum();
                }
                s
            })
            .collect();
        let mut t = [0.0; 5];
        for s in &per_row {
            for (a, b) in t.iter_mut().zip(s.0) {
                *a += b;
            }
        }
        let (r, c) = (rows as f64, cols as f64);
        let n = |a: f64, b: f64| if periodic { r * c } else { a * b };
        let m0 = t[0] / (r * c);
        let m2 = (t[1] / n(r, c - 1.0) + t[2] / n(r - 1.0, c)) / 2.0 / (dx * dx);
        let m4 = (t[3] / n(r, c - 2.0) + t[4] / n(r - 2.0, c)) / 2.0 / (dx * dx * dx * dx);
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

/// Sum of squared forward differences along a row (wrapped if periodic).
fn x_first(r: &[f64], periodic: bool) -> f64 {
    let inner: f64 = r.windows(2).map(|w| (w[1] - w[0]) * (w[1] - w[0])).sum();
    let wrap = r[0] - r[r.len() - 1];
    inner + if periodic { wrap * wrap } else { 0.0 }
}

/// Sum of squared 3-point second differences along a row.
fn x_second(r: &[f64], periodic: bool) -> f64 {
    let d2 = |a: f64, b: f64, c: f64| (a - 2.0 * b + c) * (a - 2.0 * b + c);
    let inner: f64 = r.windows(3).map(|w| d2(w[2], w[1], w[0])).sum();
    if !periodic {
        return inner;
    }
    let n = r.len();
    inner + d2(r[1], r[0], r[n - 1]) + d2(r[0], r[n - 1], r[n - 2])
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
