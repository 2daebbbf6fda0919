//! The elastic half-space as a convolution, evaluated by FFT.
//!
//! Surface displacement `u` (m, positive away from the rigid body) under a
//! pressure `p` (Pa, positive compressive), contact modulus `E*`:
//! - periodic (Westergaard; Stanley & Kato 1997): `u_q = 2 p_q/(E* |q|)`
//!   for `q != 0`, `q = 2 pi (kx/Lx, ky/Ly)`; the `q = 0` term (the mean
//!   displacement, a rigid shift) is set to 0, so `u` has zero mean. Its
//!   inverse, the stiffness `p_q = E* |q| u_q/2`, is available too;
//! - non-periodic (Liu, Wang & Liu 2000, "DC-FFT"): `u = sum_j G(x_i - x_j) p_j`
//!   with Love's (1929) influence coefficient of a uniformly loaded square
//!   pixel of side `dx`, `G(x, y) = (1/(pi E*)) int_pixel dA'/|x - x'|`
//!   `= (1/(pi E*)) [F(x+a, y+a) - F(x-a, y+a) - F(x+a, y-a) + F(x-a, y-a)]`,
//!   `F(X, Y) = X ln(Y + r) + Y ln(X + r)`, `a = dx/2`; the map is padded
//!   with zeros to `2 rows x 2 cols`, where the circular convolution equals
//!   the linear one on the map.

use super::fft::{signed_index, Fft2, Input};
use rayon::prelude::*;
use realfft::num_complex::Complex;
use std::f64::consts::PI;
use std::sync::Mutex;

/// Scratch buffers of one operator (reused between calls).
struct Buffers {
    spec: Vec<Complex<f64>>,
    work: Vec<Complex<f64>>,
}

/// The compliance (and, periodic, stiffness) of the half-space on a grid.
pub struct HalfSpace {
    rows: usize,
    cols: usize,
    periodic: bool,
    fft: Fft2,
    /// Compliance in Fourier space, normalisation `1/(FFT size)` included.
    compliance: Vec<f64>,
    /// Stiffness in Fourier space (periodic only), normalised likewise.
    stiffness: Vec<f64>,
    buffers: Mutex<Buffers>,
}

impl std::fmt::Debug for HalfSpace {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "HalfSpace({} x {}, periodic {})",
            self.rows, self.cols, self.periodic
        )
    }
}

/// An antiderivative of `1/sqrt(X^2 + Y^2)` in `X` and `Y`:
/// `X ln(Y + r) + Y ln(X + r)`, `r = sqrt(X^2 + Y^2)`, with
/// `ln(s + r) = ln(t^2) - ln(r - s)` for `s < 0` (`t` the other variable),
/// which avoids the cancellation in `s + r`.
fn love_f(x: f64, y: f64) -> f64 {
    let r = x.hypot(y);
    let l = |s: f64, t: f64| {
        if s >= 0.0 {
            (s + r).ln()
        } else {
            2.0 * t.abs().ln() - (r - s).ln()
        }
    };
    let tx = if x == 0.0 { 0.0 } else { x * l(y, x) };
    let ty = if y == 0.0 { 0.0 } else { y * l(x, y) };
    tx + ty
}

/// Love's coefficient `int_pixel dA'/|x - x'|` (m) of a square pixel of
/// side `dx` centred at the origin, at `(x, y)`.
pub fn love_pixel(x: f64, y: f64, dx: f64) -> f64 {
    love_rect(x, y, dx, dx)
}

/// Love's coefficient `int_pixel dA'/|x - x'|` (m) of a rectangular pixel
/// of sides `dx` (along x) and `dy` (along y) centred at the origin, at
/// `(x, y)`: `F(x + a, y + b) - F(x - a, y + b) - F(x + a, y - b) +
/// F(x - a, y - b)`, `a = dx/2`, `b = dy/2` (Love 1929; Johnson, Contact
/// Mechanics, 3.25).
pub fn love_rect(x: f64, y: f64, dx: f64, dy: f64) -> f64 {
    let (a, b) = (dx / 2.0, dy / 2.0);
    love_f(x + a, y + b) - love_f(x - a, y + b) - love_f(x + a, y - b) + love_f(x - a, y - b)
}

impl HalfSpace {
    /// The half-space on `rows x cols` pixels of side `dx` (m), contact
    /// modulus `estar` (Pa); `periodic` or padded.
    pub fn new(rows: usize, cols: usize, dx: f64, estar: f64, periodic: bool) -> Self {
        HalfSpace::with_pixels(rows, cols, (dx, dx), estar, periodic)
    }

    /// The half-space on `rows x cols` pixels of `dx` (along x, a row) by
    /// `dy` (along y, a column) (m), contact modulus `estar` (Pa);
    /// `periodic` or padded.
    pub fn with_pixels(
        rows: usize,
        cols: usize,
        (dx, dy): (f64, f64),
        estar: f64,
        periodic: bool,
    ) -> Self {
        let (fr, fc) = if periodic {
            (rows, cols)
        } else {
            (2 * rows, 2 * cols)
        };
        let fft = Fft2::new(fr, fc);
        let nh = fft.half_cols();
        let size = (fr * fc) as f64;
        let (mut compliance, mut stiffness) = (vec![0.0; fft.spectrum_len()], Vec::new());
        if periodic {
            stiffness = vec![0.0; fft.spectrum_len()];
            let (lx, ly) = (cols as f64 * dx, rows as f64 * dy);
            for kx in 0..nh {
                for ky in 0..fr {
                    let q = 2.0 * PI * (kx as f64 / lx).hypot(signed_index(ky, fr) / ly);
                    if q > 0.0 {
                        compliance[kx * fr + ky] = 2.0 / (estar * q) / size;
                        stiffness[kx * fr + ky] = estar * q / 2.0 / size;
                    }
                }
            }
        } else {
            let mut g = vec![0.0; fr * fc];
            g.par_chunks_mut(fc).enumerate().for_each(|(i, row)| {
                let y = signed_index(i, fr) * dy;
                for (j, v) in row.iter_mut().enumerate() {
                    let x = signed_index(j, fc) * dx;
                    *v = love_rect(x, y, dx, dy) / (PI * estar);
                }
            });
            let mut spec = vec![Complex::new(0.0, 0.0); fft.spectrum_len()];
            let mut work = spec.clone();
            fft.forward(&g, &mut spec, &mut work);
            // G is even in x and y: its transform is real.
            for (c, s) in compliance.iter_mut().zip(&spec) {
                *c = s.re / size;
            }
        }
        let len = fft.spectrum_len();
        HalfSpace {
            rows,
            cols,
            periodic,
            fft,
            compliance,
            stiffness,
            buffers: Mutex::new(Buffers {
                spec: vec![Complex::new(0.0, 0.0); len],
                work: vec![Complex::new(0.0, 0.0); len],
            }),
        }
    }

    /// Bytes this operator holds: the kernels (`8 len` each, `len = fr
    /// (fc/2 + 1)` on the `fr x fc` transform grid: the map, or twice its
    /// size padded), the two half spectra of the transform (`16 len`
    /// each) and the per-thread scratch of the transform (two threads
    /// counted).
    pub fn bytes(rows: usize, cols: usize, periodic: bool) -> usize {
        let (fr, fc) = if periodic {
            (rows, cols)
        } else {
            (2 * rows, 2 * cols)
        };
        let len = fr * (fc / 2 + 1);
        let kernels = if periodic { 2 } else { 1 } * 8 * len;
        let complex = 2 * 16 * len;
        kernels + complex + 2 * Fft2::scratch_bytes(fr, fc)
    }

    /// Whether the operator is periodic.
    pub fn periodic(&self) -> bool {
        self.periodic
    }

    /// Pixels of the map.
    pub fn len(&self) -> usize {
        self.rows * self.cols
    }

    /// Never empty (at least one pixel).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// `u = K p` (periodic: zero-mean `u`).
    pub fn displacement(&self, p: &[f64], u: &mut [f64]) {
        self.convolve(Input::Plain(p), u, false);
    }

    /// `p *= scale`, then `u = K p`, in one pass over `p` (the same bits as
    /// the two steps).
    pub(crate) fn displacement_scaled(&self, p: &mut [f64], scale: f64, u: &mut [f64]) {
        self.convolve(Input::Scaled(p, scale), u, false);
    }

    /// `p = K^-1 u` (periodic only; zero-mean `p`).
    ///
    /// # Panics
    /// On a padded operator (an internal misuse).
    pub fn pressure(&self, u: &[f64], p: &mut [f64]) {
        assert!(self.periodic, "stiffness of a padded half-space");
        self.convolve(Input::Plain(u), p, true);
    }

    /// `p = K^-1 (u (mask > 0))`: the stiffness applied to `u` where
    /// `mask` is positive and to 0 elsewhere (periodic only; zero-mean
    /// `p`), without a masked copy of `u`.
    ///
    /// # Panics
    /// On a padded operator (an internal misuse).
    pub(crate) fn pressure_masked(&self, u: &[f64], mask: &[f64], p: &mut [f64]) {
        assert!(self.periodic, "stiffness of a padded half-space");
        self.convolve(Input::Masked(u, mask), p, true);
    }

    fn convolve(&self, x: Input<'_>, y: &mut [f64], stiff: bool) {
        let mut guard = self.buffers.lock().unwrap_or_else(|e| e.into_inner());
        let b = &mut *guard;
        let kernel = if stiff {
            &self.stiffness
        } else {
            &self.compliance
        };
        // Padded: the map in the top-left corner of the doubled grid, zeros
        // elsewhere (never stored), and the same corner of the result.
        self.fft.convolve_corner(
            x,
            (self.rows, self.cols),
            y,
            kernel,
            &mut b.spec,
            &mut b.work,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn vec_cos(n: usize, q: f64, dx: f64) -> Vec<f64> {
        (0..n * n)
            .map(|k| (q * (k % n) as f64 * dx).cos())
            .collect()
    }

    #[test]
    fn love_coefficient_and_a_periodic_mode() {
        // Centre of a uniformly loaded square: 4 dx asinh(1).
        assert!((love_pixel(0.0, 0.0, 2.0) / (8.0 * 1f64.asinh()) - 1.0).abs() < 1e-15);
        // Far away: dx^2 / r.
        let far = love_pixel(300.0, 400.0, 1.0);
        assert!((far * 500.0 - 1.0).abs() < 1e-6, "{far}");
        // A cosine pressure gives u = 2 p/(E* q).
        let (n, dx, e) = (32, 1e-6, 1e9);
        let hs = HalfSpace::new(n, n, dx, e, true);
        let q = 2.0 * PI * 3.0 / (n as f64 * dx);
        let p: Vec<f64> = (0..n * n)
            .map(|k| (q * (k % n) as f64 * dx).cos())
            .collect();
        let mut u = vec![0.0; n * n];
        hs.displacement(&p, &mut u);
        for (a, b) in u.iter().zip(&p) {
            assert!((a - 2.0 * b / (e * q)).abs() < 1e-12 * 2.0 / (e * q));
        }
        // Padded: a unit pressure on pixel (3, 4) gives Love's coefficient.
        let (r, c) = (12, 10);
        let hs = HalfSpace::new(r, c, dx, e, false);
        let mut p = vec![0.0; r * c];
        p[3 * c + 4] = 1.0;
        let mut u = vec![0.0; r * c];
        for _ in 0..2 {
            hs.displacement(&p, &mut u);
            for i in 0..r {
                for j in 0..c {
                    let want =
                        love_pixel((j as f64 - 4.0) * dx, (i as f64 - 3.0) * dx, dx) / (PI * e);
                    assert!(
                        (u[i * c + j] - want).abs() < 1e-12 * want,
                        "({i}, {j}) {} {want}",
                        u[i * c + j]
                    );
                }
            }
        }
        let hs = HalfSpace::new(n, n, dx, e, true);
        let mut u = vec![0.0; n * n];
        hs.displacement(&vec_cos(n, q, dx), &mut u);
        let mut back = vec![0.0; n * n];
        hs.pressure(&u, &mut back);
        for (a, b) in back.iter().zip(&vec_cos(n, q, dx)) {
            assert!((a - b).abs() < 1e-12);
        }
    }
}
