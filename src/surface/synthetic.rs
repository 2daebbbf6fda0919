//! Synthetic isotropic Gaussian surfaces with a known spectrum, for the
//! acceptance tests and the grid-bias table.
//!
//! White noise (independent standard normals, one seeded xoshiro256++
//! stream per row) is convolved circularly with the separable Gaussian
//! kernel `g(k) = exp(-k^2 / (2 s^2))`, `s = l / sqrt(2)` pixels,
//! truncated at `|k| <= ceil(6 s)` and normalised to `sum g^2 = 1`. The
//! result is periodic and stationary with autocorrelation
//! `C(r) = m0 exp(-r^2 / (2 l^2))`: a Gaussian spectrum, isotropic, with
//! continuum moments `m2 = m0 / l^2`, `m4 = 3 m0 / l^4` (`alpha = 3`).
//! On the grid `sum_k g(k) g(k + a)` equals the continuum autocorrelation
//! to a relative `2 exp(-pi^2 s^2)` (Poisson summation): `3e-5` at
//! `l = 1.5` pixels, below `1e-9` from `l = 2.5`; the truncation costs
//! `exp(-18)`. No FFT is needed.

use super::{HeightMap, Moments};
use crate::error::{positive, Allowed, Result};
use crate::numeric::mix::{derive_seed, Stream};
use rand::rngs::Xoshiro256PlusPlus;
use rand::SeedableRng;
use rand_distr::{Distribution, StandardNormal};
use rayon::prelude::*;

/// An isotropic Gaussian random surface with a Gaussian autocorrelation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GaussianSurface {
    rows: usize,
    cols: usize,
    /// Correlation length `l` in pixels.
    l_px: f64,
    rms_m: f64,
    pixel_size_m: f64,
    seed: u64,
}

impl GaussianSurface {
    /// `rows x cols` pixels of `pixel_size_m`, correlation length
    /// `correlation_length_px` pixels (`C(r) = rms^2 exp(-r^2/(2 l^2))`),
    /// RMS height `rms_m`, noise from `seed`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `rms`, `pixel_size` (finite, > 0),
    /// `correlation_length` (in `[1, min(rows, cols)/8]` pixels) or `rows` /
    /// `cols` (at least 16).
    pub fn new(
        rows: usize,
        cols: usize,
        correlation_length_px: f64,
        rms_m: f64,
        pixel_size_m: f64,
        seed: u64,
    ) -> Result<Self> {
        let at_least_16 = Allowed::closed(16.0, f64::MAX);
        at_least_16.check("rows", rows as f64)?;
        at_least_16.check("cols", cols as f64)?;
        let max_l = rows.min(cols) as f64 / 8.0;
        Allowed::closed(1.0, max_l).check("correlation_length", correlation_length_px)?;
        Ok(GaussianSurface {
            rows,
            cols,
            l_px: correlation_length_px,
            rms_m: positive("rms", rms_m)?,
            pixel_size_m: positive("pixel_size", pixel_size_m)?,
            seed,
        })
    }

    /// The continuum moments of the spectrum: `m0 = rms^2`, `m2 = m0/l^2`,
    /// `m4 = 3 m0/l^4` with `l` in m.
    pub fn continuum_moments(&self) -> Moments {
        let m0 = self.rms_m * self.rms_m;
        let l = self.l_px * self.pixel_size_m;
        Moments {
            m0,
            m2: m0 / (l * l),
            m4: 3.0 * m0 / (l * l * l * l),
        }
    }

    /// Draws the (periodic) surface. The same seed gives the same bits for
    /// any number of threads.
    pub fn generate(&self) -> HeightMap {
        let (rows, cols) = (self.rows, self.cols);
        let s = self.l_px / 2f64.sqrt();
        let w = (6.0 * s).ceil() as usize;
        let mut g: Vec<f64> = (0..=2 * w)
            .map(|k| {
                let x = k as f64 - w as f64;
                (-x * x / (2.0 * s * s)).exp()
            })
            .collect();
        let norm = g.iter().map(|v| v * v).sum::<f64>().sqrt();
        g.iter_mut().for_each(|v| *v /= norm);
        // Pass 1: noise convolved along each row (circular).
        let mut tmp = vec![0.0; rows * cols];
        tmp.par_chunks_mut(cols).enumerate().for_each(|(i, out)| {
            let mut rng = Xoshiro256PlusPlus::seed_from_u64(derive_seed(
                self.seed,
                Stream::SyntheticRow(i as u64),
            ));
            let noise: Vec<f64> = (0..cols).map(|_| StandardNormal.sample(&mut rng)).collect();
            // Padded copy: pad[j] = noise[(j - w) mod cols].
            let pad: Vec<f64> = (0..cols + 2 * w)
                .map(|j| noise[(j + cols * (w / cols + 1) - w) % cols])
                .collect();
            for (k, gk) in g.iter().enumerate() {
                for (o, p) in out.iter_mut().zip(&pad[k..k + cols]) {
                    *o += gk * p;
                }
            }
        });
        // Pass 2: along each column, row i = sum_k g[k] tmp[(i + k - w) mod rows].
        let mut z = vec![0.0; rows * cols];
        z.par_chunks_mut(cols).enumerate().for_each(|(i, out)| {
            for (k, gk) in g.iter().enumerate() {
                let r = (i + k + rows * (w / rows + 1) - w) % rows;
                for (o, t) in out.iter_mut().zip(&tmp[r * cols..(r + 1) * cols]) {
                    *o += gk * t;
                }
            }
            out.iter_mut().for_each(|v| *v *= self.rms_m);
        });
        HeightMap::new(rows, cols, z).expect("finite heights on a >= 16 x 16 grid")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn variance_and_reproducibility() {
        let spec = GaussianSurface::new(256, 256, 4.0, 2e-9, 1e-7, 7).unwrap();
        let a = spec.generate();
        assert_eq!(a, spec.generate());
        let n = a.heights().len() as f64;
        let var = a.heights().iter().map(|z| z * z).sum::<f64>() / n;
        // m0 estimate from ~ (256/ (2.5 l))^2 ~ 650 independent patches: +-6%.
        assert!((var / 4e-18 - 1.0).abs() < 0.2, "{var}");
        assert!(GaussianSurface::new(256, 256, 40.0, 1e-9, 1e-7, 1).is_err());
        assert!(GaussianSurface::new(8, 256, 1.0, 1e-9, 1e-7, 1).is_err());
    }
}
