//! Random-phase synthesis of a periodic map with a given spectrum.
//!
//! `h(x) = sum_q h_q exp(i q.x)` on the FFT grid of a `rows x cols` map of
//! pixel `dx`, with `|h_q| = sqrt(C(|q|) (2 pi)^2/A)` (`A = rows cols dx^2`:
//! then `<h^2> = sum |h_q|^2` approximates `int d^2q C`), uniform random
//! phases and `h_{-q} = conj(h_q)`; `h_0 = 0`. The same seed gives the same
//! map. (Persson et al. 2005 describe the method; random phase, not Gaussian
//! amplitudes, so every realisation has exactly the spectrum on the grid.)

use super::Spectrum;
use crate::bem::fft::{signed_index, Fft2};
use crate::error::{Allowed, Result};
use crate::surface::HeightMap;
use rand::rngs::Xoshiro256PlusPlus;
use rand::{Rng, SeedableRng};
use realfft::num_complex::Complex;
use std::f64::consts::PI;

/// A periodic `rows x cols` map (heights in m) of pixel `dx` (m) with
/// spectrum `spectrum`, random phases from `seed`.
///
/// # Errors
/// [`crate::Error::OutOfRange`] naming `rows`/`cols` (4 to 65536) or
/// `pixel_size`.
pub fn random_phase_map(
    spectrum: &Spectrum,
    rows: usize,
    cols: usize,
    pixel_size: f64,
    seed: u64,
) -> Result<HeightMap> {
    let size = Allowed::closed(4.0, 65536.0);
    size.check("rows", rows as f64)?;
    size.check("cols", cols as f64)?;
    crate::error::positive("pixel_size", pixel_size)?;
    let fft = Fft2::new(rows, cols);
    let nh = fft.half_cols();
    let area = (rows * cols) as f64 * pixel_size * pixel_size;
    let (qx0, qy0) = (
        2.0 * PI / (cols as f64 * pixel_size),
        2.0 * PI / (rows as f64 * pixel_size),
    );
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(seed);
    let mut spec = vec![Complex::new(0.0, 0.0); fft.spectrum_len()];
    for kx in 0..nh {
        for ky in 0..rows {
            let q = (kx as f64 * qx0).hypot(signed_index(ky, rows) * qy0);
            let amp = (spectrum.c(q) * 4.0 * PI * PI / area).sqrt();
            let phase = ((rng.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)) * 2.0 * PI;
            spec[kx * rows + ky] = Complex::from_polar(amp, phase);
        }
    }
    spec[0] = Complex::new(0.0, 0.0);
    // Columns kx = 0 and (even cols) kx = cols/2 are their own mirror:
    // make them Hermitian in ky.
    let self_mirrored: Vec<usize> = if cols.is_multiple_of(2) {
        vec![0, nh - 1]
    } else {
        vec![0]
    };
    for kx in self_mirrored {
        let col = &mut spec[kx * rows..(kx + 1) * rows];
        for ky in 1..rows {
            let m = rows - ky;
            if m < ky {
                col[ky] = col[m].conj();
            } else if m == ky {
                col[ky] = Complex::new(col[ky].norm() * col[ky].re.signum(), 0.0);
            }
        }
        col[0].im = 0.0;
    }
    let mut work = spec.clone();
    let mut h = vec![0.0; rows * cols];
    fft.inverse(&mut spec, &mut h, &mut work);
    HeightMap::new(rows, cols, h)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spectrum::Normalisation;

    #[test]
    fn variance_matches_the_grid_sum_of_the_spectrum() {
        let dx = 1e-8;
        let n = 64;
        let q0 = 2.0 * PI / (n as f64 * dx);
        let s = Spectrum::self_affine(
            0.8,
            2.0 * q0,
            4.0 * q0,
            28.0 * q0,
            Normalisation::HRms(1e-9),
        )
        .unwrap();
        let map = random_phase_map(&s, n, n, dx, 3).unwrap();
        let var = map.heights().iter().map(|v| v * v).sum::<f64>() / (n * n) as f64;
        // The grid sum of C (2 pi)^2/A approximates m0 to a few per cent.
        assert!((var / s.m0() - 1.0).abs() < 0.1, "{var} {}", s.m0());
        assert_eq!(map, random_phase_map(&s, n, n, dx, 3).unwrap());
    }
}
