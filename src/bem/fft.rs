//! Two-dimensional real FFT on a `rows x cols` grid (realfft along the
//! rows, rustfft along the columns), parallel over rows and columns.
//!
//! The half spectrum is stored column-major, `spec[kx * rows + ky]` for
//! `kx` in `0..=cols/2` and `ky` in `0..rows`: the column transforms then
//! run on contiguous lines. Unnormalised: `inverse(forward(x)) = rows cols x`.

use rayon::prelude::*;
use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

/// Rows per parallel task (keeps tasks a few hundred microseconds long).
const ROWS_PER_TASK: usize = 16;
/// Grid points above which the transform runs on several threads.
const PARALLEL_MIN: usize = 1 << 17;

/// A planned 2-D real transform.
pub(crate) struct Fft2 {
    rows: usize,
    cols: usize,
    r2c: Arc<dyn RealToComplex<f64>>,
    c2r: Arc<dyn ComplexToReal<f64>>,
    col_fwd: Arc<dyn Fft<f64>>,
    col_inv: Arc<dyn Fft<f64>>,
}

impl std::fmt::Debug for Fft2 {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Fft2({} x {})", self.rows, self.cols)
    }
}

impl Fft2 {
    /// Plans a `rows x cols` transform (both >= 1).
    pub(crate) fn new(rows: usize, cols: usize) -> Self {
        let mut rp = RealFftPlanner::<f64>::new();
        let mut cp = FftPlanner::<f64>::new();
        Fft2 {
            rows,
            cols,
            r2c: rp.plan_fft_forward(cols),
            c2r: rp.plan_fft_inverse(cols),
            col_fwd: cp.plan_fft_forward(rows),
            col_inv: cp.plan_fft_inverse(rows),
        }
    }

    /// Whether the transform is large enough to split over threads (below
    /// that, thread hand-offs cost more than they save).
    fn parallel(&self) -> bool {
        self.rows * self.cols > PARALLEL_MIN
    }

    /// Number of half-spectrum columns, `cols/2 + 1`.
    pub(crate) fn half_cols(&self) -> usize {
        self.cols / 2 + 1
    }

    /// Length of the half spectrum, `rows (cols/2 + 1)`.
    pub(crate) fn spectrum_len(&self) -> usize {
        self.rows * self.half_cols()
    }

    /// Forward transform of `x` (row-major, `rows cols`) into `spec`
    /// (column-major half spectrum); `work` is scratch of `spectrum_len()`.
    pub(crate) fn forward(&self, x: &[f64], spec: &mut [Complex<f64>], work: &mut [Complex<f64>]) {
        let (rows, cols, nh) = (self.rows, self.cols, self.half_cols());
        debug_assert_eq!(x.len(), rows * cols);
        // Rows: real to complex into `work`, row-major rows x nh.
        let rows_fwd = |(inp, scratch): &mut (Vec<f64>, Vec<Complex<f64>>),
                        (out, xin): (&mut [Complex<f64>], &[f64])| {
            for (o, xr) in out.chunks_mut(nh).zip(xin.chunks(cols)) {
                inp.copy_from_slice(xr);
                // Lengths match by construction.
                let _ = self.r2c.process_with_scratch(inp, o, scratch);
            }
        };
        let init = || (self.r2c.make_input_vec(), self.r2c.make_scratch_vec());
        if self.parallel() {
            work.par_chunks_mut(nh * ROWS_PER_TASK)
                .zip(x.par_chunks(cols * ROWS_PER_TASK))
                .for_each_init(init, rows_fwd);
        } else {
            let mut state = init();
            rows_fwd(&mut state, (&mut work[..], x));
        }
        transpose(work, spec, rows, nh, self.parallel());
        self.columns(spec, &self.col_fwd);
    }

    /// Inverse transform of `spec` (destroyed) into `x` (row-major),
    /// unnormalised; `work` is scratch of `spectrum_len()`.
    pub(crate) fn inverse(
        &self,
        spec: &mut [Complex<f64>],
        x: &mut [f64],
        work: &mut [Complex<f64>],
    ) {
        let (rows, cols, nh) = (self.rows, self.cols, self.half_cols());
        self.columns(spec, &self.col_inv);
        transpose(spec, work, nh, rows, self.parallel());
        let rows_inv = |scratch: &mut Vec<Complex<f64>>,
                        (xout, win): (&mut [f64], &mut [Complex<f64>])| {
            for (xr, w) in xout.chunks_mut(cols).zip(win.chunks_mut(nh)) {
                // A real signal's DC and Nyquist terms are real.
                w[0].im = 0.0;
                if cols % 2 == 0 {
                    w[nh - 1].im = 0.0;
                }
                let _ = self.c2r.process_with_scratch(w, xr, scratch);
            }
        };
        if self.parallel() {
            x.par_chunks_mut(cols * ROWS_PER_TASK)
                .zip(work.par_chunks_mut(nh * ROWS_PER_TASK))
                .for_each_init(|| self.c2r.make_scratch_vec(), rows_inv);
        } else {
            rows_inv(&mut self.c2r.make_scratch_vec(), (x, work));
        }
    }

    /// `y = IFFT(kernel FFT(x))` with the kernel in the column-major layout
    /// (normalisation included in the kernel). Small grids run one thread
    /// and fuse the column passes: batches of 8 columns are gathered,
    /// transformed, multiplied and transformed back while in cache, with
    /// no full-size transposes. Large grids use the parallel transposed path.
    pub(crate) fn convolve(
        &self,
        x: &[f64],
        y: &mut [f64],
        kernel: &[f64],
        spec: &mut [Complex<f64>],
        work: &mut [Complex<f64>],
    ) {
        if self.parallel() {
            self.forward(x, spec, work);
            spec.par_chunks_mut(4096)
                .zip(kernel.par_chunks(4096))
                .for_each(|(s, k)| s.iter_mut().zip(k).for_each(|(a, b)| *a *= *b));
            self.inverse(spec, y, work);
            return;
        }
        let (rows, cols, nh) = (self.rows, self.cols, self.half_cols());
        let mut inp = self.r2c.make_input_vec();
        let mut rs = self.r2c.make_scratch_vec();
        for (o, xr) in work.chunks_mut(nh).zip(x.chunks(cols)) {
            inp.copy_from_slice(xr);
            let _ = self.r2c.process_with_scratch(&mut inp, o, &mut rs);
        }
        const BATCH: usize = 8;
        // At most `nh` columns per batch: a grid narrower than a batch has
        // a spectrum shorter than BATCH * rows.
        let buf = &mut spec[..BATCH.min(nh) * rows];
        let mut cs = vec![
            Complex::new(0.0, 0.0);
            self.col_fwd
                .get_inplace_scratch_len()
                .max(self.col_inv.get_inplace_scratch_len())
        ];
        for kx0 in (0..nh).step_by(BATCH) {
            let nb = BATCH.min(nh - kx0);
            for ky in 0..rows {
                let row = &work[ky * nh + kx0..ky * nh + kx0 + nb];
                for (b, v) in row.iter().enumerate() {
                    buf[b * rows + ky] = *v;
                }
            }
            let lines = &mut buf[..nb * rows];
            self.col_fwd.process_with_scratch(lines, &mut cs);
            for (v, k) in lines.iter_mut().zip(&kernel[kx0 * rows..(kx0 + nb) * rows]) {
                *v *= *k;
            }
            self.col_inv.process_with_scratch(lines, &mut cs);
            for ky in 0..rows {
                let row = &mut work[ky * nh + kx0..ky * nh + kx0 + nb];
                for (b, v) in row.iter_mut().enumerate() {
                    *v = lines[b * rows + ky];
                }
            }
        }
        let mut cs = self.c2r.make_scratch_vec();
        for (yr, w) in y.chunks_mut(cols).zip(work.chunks_mut(nh)) {
            w[0].im = 0.0;
            if cols % 2 == 0 {
                w[nh - 1].im = 0.0;
            }
            let _ = self.c2r.process_with_scratch(w, yr, &mut cs);
        }
    }

    /// The column transforms, in place, on the column-major spectrum.
    fn columns(&self, spec: &mut [Complex<f64>], fft: &Arc<dyn Fft<f64>>) {
        let per_task = self.rows * ROWS_PER_TASK;
        let scratch = || vec![Complex::new(0.0, 0.0); fft.get_inplace_scratch_len()];
        if self.parallel() {
            spec.par_chunks_mut(per_task)
                .for_each_init(scratch, |s, lines| fft.process_with_scratch(lines, s));
        } else {
            fft.process_with_scratch(spec, &mut scratch());
        }
    }
}

/// `dst[j * n_rows + i] = src[i * n_cols + j]` for an `n_rows x n_cols`
/// row-major `src`, in cache blocks, parallel over blocks of `dst` rows.
fn transpose(
    src: &[Complex<f64>],
    dst: &mut [Complex<f64>],
    n_rows: usize,
    n_cols: usize,
    par: bool,
) {
    const B: usize = 32;
    let one = |(jb, block): (usize, &mut [Complex<f64>])| {
        let j0 = jb * B;
        let jn = block.len() / n_rows;
        for i0 in (0..n_rows).step_by(B) {
            for i in i0..(i0 + B).min(n_rows) {
                let row = &src[i * n_cols + j0..i * n_cols + j0 + jn];
                for (dj, v) in row.iter().enumerate() {
                    block[dj * n_rows + i] = *v;
                }
            }
        }
    };
    if par {
        dst.par_chunks_mut(n_rows * B).enumerate().for_each(one);
    } else {
        dst.chunks_mut(n_rows * B).enumerate().for_each(one);
    }
}

/// Signed frequency index of position `k` in a transform of length `n`.
#[inline]
pub(crate) fn signed_index(k: usize, n: usize) -> f64 {
    if k <= n / 2 {
        k as f64
    } else {
        k as f64 - n as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_and_a_single_mode() {
        for (rows, cols) in [(8, 8), (6, 10), (33, 17), (64, 48)] {
            let f = Fft2::new(rows, cols);
            let x: Vec<f64> = (0..rows * cols)
                .map(|k| ((k * 7919) % 97) as f64 / 97.0 - 0.5)
                .collect();
            let mut spec = vec![Complex::new(0.0, 0.0); f.spectrum_len()];
            let mut work = spec.clone();
            f.forward(&x, &mut spec, &mut work);
            let mut y = vec![0.0; rows * cols];
            f.inverse(&mut spec, &mut y, &mut work);
            let n = (rows * cols) as f64;
            for (a, b) in x.iter().zip(&y) {
                assert!((a - b / n).abs() < 1e-13, "{rows}x{cols}");
            }
            // cos(2 pi (2 j / cols + 1 i / rows)): amplitude n/2 at (kx 2, ky 1).
            let x: Vec<f64> = (0..rows * cols)
                .map(|k| {
                    let (i, j) = ((k / cols) as f64, (k % cols) as f64);
                    (2.0 * std::f64::consts::PI * (2.0 * j / cols as f64 + i / rows as f64)).cos()
                })
                .collect();
            f.forward(&x, &mut spec, &mut work);
            let v = spec[2 * rows + 1];
            assert!((v.re - n / 2.0).abs() < 1e-9 && v.im.abs() < 1e-9);
            let total: f64 = spec.iter().map(|c| c.norm()).sum();
            assert!((total - n / 2.0).abs() < 1e-8, "{total}");
        }
    }

    /// The fused small-grid convolution equals transform, multiply, inverse
    /// on grids narrower than its column batch (a 3 x 3 map panicked).
    #[test]
    fn narrow_grids_convolve_as_the_plain_transforms() {
        for (rows, cols) in [(3, 3), (3, 5), (5, 3), (2, 9), (9, 2), (6, 6), (3, 17)] {
            let f = Fft2::new(rows, cols);
            let x: Vec<f64> = (0..rows * cols)
                .map(|k| ((k * 7919) % 97) as f64 / 97.0 - 0.5)
                .collect();
            let kernel: Vec<f64> = (0..f.spectrum_len())
                .map(|k| 1.0 + ((k * 31) % 13) as f64 / 13.0)
                .collect();
            let mut spec = vec![Complex::new(0.0, 0.0); f.spectrum_len()];
            let mut work = spec.clone();
            let mut fused = vec![0.0; rows * cols];
            f.convolve(&x, &mut fused, &kernel, &mut spec, &mut work);
            f.forward(&x, &mut spec, &mut work);
            for (s, k) in spec.iter_mut().zip(&kernel) {
                *s *= *k;
            }
            let mut plain = vec![0.0; rows * cols];
            f.inverse(&mut spec, &mut plain, &mut work);
            for (a, b) in fused.iter().zip(&plain) {
                assert!(
                    (a - b).abs() < 1e-12 * (1.0 + b.abs()),
                    "{rows}x{cols}: {a} {b}"
                );
            }
        }
    }
}
