//! The scales of a map the stickiness criteria need
//! ([`crate::stickiness::Roughness`]), on the heights the solver uses (mean
//! plane removed, only the mean when periodic).
//!
//! With `h` on `rows x cols` pixels of `dx` (along a row) by `dy`:
//! - RMS gradient from forward differences, `h'^2 = mean((h[i, j+1] -
//!   h[i, j])^2/dx^2 + (h[i+1, j] - h[i, j])^2/dy^2)`;
//! - RMS curvature from central second differences, `h'' = rms(lap h)/2`,
//!   `lap h = (h[i, j+1] - 2 h + h[i, j-1])/dx^2 + (h[i+1, j] - 2 h +
//!   h[i-1, j])/dy^2`;
//!
//! both periodic (indices wrap) on a periodic map, over the pixels where
//! every neighbour exists otherwise; the full-contact energy per nominal
//! area `U_full/A0 = mean(h p)/2` with `p = K^-1 h` the periodic
//! half-space's pressure of the displacement `h` (`p_q = E* |q| h_q/2`, the
//! `q = 0` term 0), on a padded map the map taken as periodic.

use super::operator::HalfSpace;
use super::Problem;
use crate::stickiness::Roughness;

impl Problem {
    /// The map's RMS gradient, RMS curvature, full-contact energy and pixel
    /// size `dx` (module documentation).
    pub fn roughness(&self) -> Roughness {
        let (rows, cols) = (self.rows, self.cols);
        let (dx, dy) = (self.pixel_size, self.pixel_size_y);
        let h = &self.heights;
        let at = |i: usize, j: usize| h[i * cols + j];
        let (mut g2, mut ng) = (0.0, 0usize);
        let (mut l2, mut nl) = (0.0, 0usize);
        let wrap = |k: isize, n: usize| -> Option<usize> {
            if (0..n as isize).contains(&k) {
                Some(k as usize)
            } else if self.periodic {
                Some(k.rem_euclid(n as isize) as usize)
            } else {
                None
            }
        };
        for i in 0..rows {
            for j in 0..cols {
                let (ii, jj) = (i as isize, j as isize);
                let c = at(i, j);
                if let (Some(jp), Some(ip)) = (wrap(jj + 1, cols), wrap(ii + 1, rows)) {
                    g2 += ((at(i, jp) - c) / dx).powi(2) + ((at(ip, j) - c) / dy).powi(2);
                    ng += 1;
                }
                if let (Some(jp), Some(jm), Some(ip), Some(im)) = (
                    wrap(jj + 1, cols),
                    wrap(jj - 1, cols),
                    wrap(ii + 1, rows),
                    wrap(ii - 1, rows),
                ) {
                    let lap = (at(i, jp) - 2.0 * c + at(i, jm)) / (dx * dx)
                        + (at(ip, j) - 2.0 * c + at(im, j)) / (dy * dy);
                    l2 += lap * lap;
                    nl += 1;
                }
            }
        }
        let mut p = vec![0.0; h.len()];
        if self.periodic {
            self.op.pressure(h, &mut p);
        } else {
            let op = HalfSpace::with_pixels(rows, cols, (dx, dy), self.contact_modulus, true);
            op.pressure(h, &mut p);
        }
        let energy = 0.5 * h.iter().zip(&p).map(|(a, b)| a * b).sum::<f64>() / h.len() as f64;
        Roughness {
            slope_rms: (g2 / ng.max(1) as f64).sqrt(),
            curvature_rms: 0.5 * (l2 / nl.max(1) as f64).sqrt(),
            full_contact_energy: energy,
            pixel_size: dx,
        }
    }
}
