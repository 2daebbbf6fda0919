//! The radial power spectrum of a measured height map.
//!
//! 1. Detrend: the least-squares mean plane is removed (only the mean for
//!    a periodic map), as `asperity surface` does ([`crate::surface::Plane`]).
//! 2. Window (non-periodic maps only): the separable Hann window
//!    `w(i, j) = w_r(i) w_c(j)`, `w_n(k) = sin^2(pi (k + 1/2)/n)`, divided by
//!    its RMS so the windowed map keeps the variance of the detrended one
//!    (the window suppresses the leakage of the edges' discontinuity, at the
//!    cost of a resolution of about two bins). A periodic map is used as is.
//! 3. `h_q = (1/N) sum h(x) exp(-i q.x)` on the FFT grid,
//!    `q = 2 pi (kx/(cols dx), ky/(rows dy))`; `sum_q |h_q|^2 = <h^2>`.
//! 4. Annuli of width `dq = 2 pi/(dx min(rows, cols))`, the `b`-th covering
//!    `[(b - 1/2) dq, (b + 1/2) dq)`, `b = 1, 2, ...` up to the grid's corner:
//!    `C_b = sum_{q in b} |h_q|^2 / (pi (q_hi^2 - q_lo^2))`, so that
//!    `2 pi int q C dq` over the annulus is exactly its share of `<h^2>`
//!    (Parseval: `m0` of the spectrum equals the map's variance after
//!    detrending and windowing).

use super::{Segment, Spectrum};
use crate::bem::fft::{signed_index, Fft2};
use crate::error::{positive, Result};
use crate::surface::{HeightMap, Plane};
use realfft::num_complex::Complex;
use std::f64::consts::PI;

/// Detrended (and, unless periodic, Hann-windowed) heights, row-major.
pub fn prepared_heights(map: &HeightMap, pixel_size: f64, periodic: bool) -> Vec<f64> {
    prepared_heights_xy(map, (pixel_size, pixel_size), periodic)
}

/// As [`prepared_heights`] with pixels of `dx` (along x) by `dy` (m).
pub fn prepared_heights_xy(map: &HeightMap, pixels: (f64, f64), periodic: bool) -> Vec<f64> {
    let (rows, cols) = (map.rows(), map.cols());
    let plane = Plane::fit_xy(map.heights(), rows, cols, pixels, periodic);
    let mut z = plane.residual(map.heights(), cols);
    if !periodic {
        let hann = |n: usize| -> Vec<f64> {
            (0..n)
                .map(|k| (PI * (k as f64 + 0.5) / n as f64).sin().powi(2))
                .collect()
        };
        let (wr, wc) = (hann(rows), hann(cols));
        // Mean of w^2 of a separable window: product of the 1-D means (3/8 each).
        let ms = |w: &[f64]| w.iter().map(|v| v * v).sum::<f64>() / w.len() as f64;
        let norm = (ms(&wr) * ms(&wc)).sqrt();
        for (i, row) in z.chunks_mut(cols).enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                *v *= wr[i] * wc[j] / norm;
            }
        }
    }
    z
}

/// The radial spectrum of `map` (heights in m, square pixels of
/// `pixel_size` m): one flat segment per annulus (module documentation).
///
/// # Errors
/// [`crate::Error::OutOfRange`] naming `pixel_size`; [`crate::Error::Invalid`]
/// named `spectrum` when the map is flat after detrending.
pub fn radial_psd(map: &HeightMap, pixel_size: f64, periodic: bool) -> Result<Spectrum> {
    positive("pixel_size", pixel_size)?;
    radial_psd_xy(map, (pixel_size, pixel_size), periodic)
}

/// As [`radial_psd`] with pixels of `dx` (along x, a row) by `dy` (along
/// y) (m): `q = 2 pi (kx/(cols dx), ky/(rows dy))`, annuli of width
/// `dq = 2 pi / min(cols dx, rows dy)` (the coarser of the two grid
/// spacings in q); square pixels give [`radial_psd`]'s bits.
///
/// # Errors
/// As [`radial_psd`]; `pixel_size_y` for a bad `dy`.
pub fn radial_psd_xy(map: &HeightMap, (dx, dy): (f64, f64), periodic: bool) -> Result<Spectrum> {
    positive("pixel_size", dx)?;
    positive("pixel_size_y", dy)?;
    let (rows, cols) = (map.rows(), map.cols());
    let z = prepared_heights_xy(map, (dx, dy), periodic);
    let fft = Fft2::new(rows, cols);
    let mut spec = vec![Complex::new(0.0, 0.0); fft.spectrum_len()];
    let mut work = spec.clone();
    fft.forward(&z, &mut spec, &mut work);
    let n = (rows * cols) as f64;
    let (qx0, qy0) = (2.0 * PI / (cols as f64 * dx), 2.0 * PI / (rows as f64 * dy));
    let dq = qx0.max(qy0);
    let nh = fft.half_cols();
    let corner = ((cols / 2) as f64 * qx0).hypot((rows / 2) as f64 * qy0);
    let bins = (corner / dq + 0.5).floor() as usize + 1;
    let mut power = vec![0.0; bins + 1];
    for kx in 0..nh {
        // Columns 1..cols/2 (exclusive of Nyquist for even cols) stand for
        // their conjugates too.
        let weight = if kx == 0 || (cols % 2 == 0 && kx == nh - 1) {
            1.0
        } else {
            2.0
        };
        let qx = kx as f64 * qx0;
        for ky in 0..rows {
            let q = qx.hypot(signed_index(ky, rows) * qy0);
            let b = (q / dq + 0.5).floor() as usize;
            if b == 0 {
                continue;
            }
            power[b.min(bins)] += weight * spec[kx * rows + ky].norm_sqr() / (n * n);
        }
    }
    let segments = (1..=bins)
        .map(|b| {
            let (lo, hi) = ((b as f64 - 0.5) * dq, (b as f64 + 0.5) * dq);
            Segment {
                q_lo: lo,
                q_hi: hi,
                c: power[b] / (PI * (hi * hi - lo * lo)),
                exponent: 0.0,
            }
        })
        .collect();
    Spectrum::from_segments(segments)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parseval_and_a_single_ring() {
        // cos(2 pi 4 j / 32) along x, periodic: all power in the ring q = 4 dq.
        let (rows, cols, dx) = (32, 32, 1e-6);
        let h: Vec<f64> = (0..rows * cols)
            .map(|k| 1e-9 * (2.0 * PI * 4.0 * (k % cols) as f64 / cols as f64).cos())
            .collect();
        let map = HeightMap::new(rows, cols, h).unwrap();
        let s = radial_psd(&map, dx, true).unwrap();
        assert!((s.m0() / 0.5e-18 - 1.0).abs() < 1e-12, "{}", s.m0());
        let dq = 2.0 * PI / (32.0 * dx);
        let ring = s
            .segments()
            .iter()
            .max_by(|a, b| a.c.total_cmp(&b.c))
            .unwrap();
        assert!((ring.q_lo / dq - 3.5).abs() < 1e-12);
        // Windowed, non-periodic: variance kept by the normalisation.
        let s = radial_psd(&map, dx, false).unwrap();
        let z = prepared_heights(&map, dx, false);
        let var = z.iter().map(|v| v * v).sum::<f64>() / z.len() as f64;
        assert!((s.m0() / var - 1.0).abs() < 1e-12);
    }
}
