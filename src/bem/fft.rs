//! Two-dimensional real FFT on a `rows x cols` grid (realfft along the
//! rows, rustfft along the columns), parallel over rows and columns.
//!
//! The half spectrum is stored column-major, `spec[kx * rows + ky]` for
//! `kx` in `0..=cols/2` and `ky` in `0..rows`: the column transforms then
//! run on contiguous lines. Unnormalised: `inverse(forward(x)) = rows cols x`.
//!
//! Every transform is made of three passes, each over independent blocks
//! (so the same bits for any number of threads): the rows' real transforms
//! into a row-major half spectrum (`work`); the columns, [`BATCH`] at a
//! time, gathered from `work` into their place in `spec` (128-byte reads
//! per row: a blocked transpose), transformed there and, for a
//! convolution, multiplied by the kernel and transformed back while in
//! cache; the rows' inverse transforms, [`ROWS_PER_TASK`] rows at a time
//! gathered from `spec` (128-byte reads per column). No full-size
//! transpose, kernel product or copy pass. Plans and per-thread scratch
//! are made once per `Fft2` and reused by every call (a small pool).

use rayon::prelude::*;
use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::{Fft, FftPlanner};
use std::sync::{Arc, Mutex};

/// Columns per column task: 8 complex values, 128 bytes, read per row.
const BATCH: usize = 8;
/// Rows per row task: 8 complex values, 128 bytes, read per column.
const ROWS_PER_TASK: usize = 8;
/// Grid points above which the transform runs on several threads.
const PARALLEL_MIN: usize = 1 << 17;

const ZERO: Complex<f64> = Complex { re: 0.0, im: 0.0 };

/// The input of a transform: read as it is, or scaled in place by a
/// factor as it is read (a fused pass: `x *= f`, then transformed).
pub(crate) enum Input<'a> {
    /// Read only.
    Plain(&'a [f64]),
    /// Scaled in place by the factor, then transformed.
    Scaled(&'a mut [f64], f64),
    /// The first field where the second (the mask) is positive, 0
    /// elsewhere: `x (m > 0)`, read without a masked copy.
    Masked(&'a [f64], &'a [f64]),
}

/// One task's scratch: a real row, the transforms' scratch and a block of
/// [`ROWS_PER_TASK`] half-spectrum rows.
struct Scratch {
    re: Vec<f64>,
    cs: Vec<Complex<f64>>,
    block: Vec<Complex<f64>>,
}

/// A scratch taken from the pool, returned to it when dropped.
struct Pooled<'a> {
    pool: &'a Mutex<Vec<Scratch>>,
    s: Option<Scratch>,
}

impl Drop for Pooled<'_> {
    fn drop(&mut self) {
        if let Some(s) = self.s.take() {
            self.pool.lock().unwrap_or_else(|e| e.into_inner()).push(s);
        }
    }
}

/// A planned 2-D real transform.
pub(crate) struct Fft2 {
    rows: usize,
    cols: usize,
    r2c: Arc<dyn RealToComplex<f64>>,
    c2r: Arc<dyn ComplexToReal<f64>>,
    col_fwd: Arc<dyn Fft<f64>>,
    col_inv: Arc<dyn Fft<f64>>,
    pool: Mutex<Vec<Scratch>>,
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
            pool: Mutex::new(Vec::new()),
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

    /// Bytes of the scratch pool per thread (a row, the transforms'
    /// scratch, a block of rows).
    pub(crate) fn scratch_bytes(rows: usize, cols: usize) -> usize {
        8 * cols + 16 * (2 * rows.max(cols) + ROWS_PER_TASK * (cols / 2 + 1))
    }

    /// A scratch from the pool (made on first use by each thread).
    fn scratch(&self) -> Pooled<'_> {
        let s = self
            .pool
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .pop()
            .unwrap_or_else(|| {
                let cs = self
                    .r2c
                    .get_scratch_len()
                    .max(self.c2r.get_scratch_len())
                    .max(self.col_fwd.get_inplace_scratch_len())
                    .max(self.col_inv.get_inplace_scratch_len());
                Scratch {
                    re: vec![0.0; self.cols],
                    cs: vec![ZERO; cs],
                    block: vec![ZERO; ROWS_PER_TASK * self.half_cols()],
                }
            });
        Pooled {
            pool: &self.pool,
            s: Some(s),
        }
    }

    /// `f(index, chunk)` on the chunks of `size` of `data`, in parallel
    /// when the grid is large.
    fn for_chunks<T: Send, F>(&self, data: &mut [T], size: usize, f: F)
    where
        F: Fn(usize, &mut [T]) + Sync,
    {
        if self.parallel() {
            data.par_chunks_mut(size)
                .enumerate()
                .for_each(|(i, c)| f(i, c));
        } else {
            data.chunks_mut(size).enumerate().for_each(|(i, c)| f(i, c));
        }
    }

    /// Forward transforms of the rows into `work` (row-major, `rows x nh`).
    /// `x` is `in_rows x in_cols` (row-major), placed at the top left of
    /// the grid with zeros elsewhere (rows of zeros are not transformed);
    /// with `Input::Scaled` the rows of `x` are scaled in place first.
    fn rows_forward(
        &self,
        x: Input<'_>,
        (in_rows, in_cols): (usize, usize),
        work: &mut [Complex<f64>],
    ) {
        let nh = self.half_cols();
        let (head, tail) = work.split_at_mut(in_rows * nh);
        self.for_chunks(tail, nh * ROWS_PER_TASK, |_, chunk| chunk.fill(ZERO));
        // `ms`: the mask of `Input::Masked` (the same rows as `xs`).
        let transform = |xs: &[f64], ms: Option<&[f64]>, out: &mut [Complex<f64>]| {
            let mut guard = self.scratch();
            let s = guard.s.as_mut().expect("taken from the pool");
            for (i, (xr, o)) in xs.chunks(in_cols).zip(out.chunks_mut(nh)).enumerate() {
                match ms {
                    None => s.re[..in_cols].copy_from_slice(xr),
                    Some(m) => {
                        let mr = &m[i * in_cols..(i + 1) * in_cols];
                        for ((d, x), m) in s.re[..in_cols].iter_mut().zip(xr).zip(mr) {
                            // Branch-free: the contact pattern is random.
                            *d = x * f64::from(u8::from(*m > 0.0));
                        }
                    }
                }
                s.re[in_cols..].fill(0.0);
                // Lengths match by construction.
                let _ = self.r2c.process_with_scratch(&mut s.re, o, &mut s.cs);
            }
        };
        let (xa, wa) = (in_cols * ROWS_PER_TASK, nh * ROWS_PER_TASK);
        match x {
            Input::Plain(x) => {
                if self.parallel() {
                    x.par_chunks(xa)
                        .zip(head.par_chunks_mut(wa))
                        .for_each(|(xs, o)| transform(xs, None, o));
                } else {
                    transform(x, None, head);
                }
            }
            Input::Masked(x, m) => {
                if self.parallel() {
                    x.par_chunks(xa)
                        .zip(m.par_chunks(xa))
                        .zip(head.par_chunks_mut(wa))
                        .for_each(|((xs, ms), o)| transform(xs, Some(ms), o));
                } else {
                    transform(x, Some(m), head);
                }
            }
            Input::Scaled(x, f) => {
                let scaled = |xs: &mut [f64], o: &mut [Complex<f64>]| {
                    xs.iter_mut().for_each(|v| *v *= f);
                    transform(xs, None, o);
                };
                if self.parallel() {
                    x.par_chunks_mut(xa)
                        .zip(head.par_chunks_mut(wa))
                        .for_each(|(xs, o)| scaled(xs, o));
                } else {
                    x.chunks_mut(xa)
                        .zip(head.chunks_mut(wa))
                        .for_each(|(xs, o)| scaled(xs, o));
                }
            }
        }
    }

    /// The columns of `work` (row-major) into `spec` (column-major),
    /// transformed forward there; with a kernel (column-major), multiplied
    /// by it and transformed back.
    fn columns(&self, work: &[Complex<f64>], spec: &mut [Complex<f64>], kernel: Option<&[f64]>) {
        let (rows, nh) = (self.rows, self.half_cols());
        self.for_chunks(spec, rows * BATCH, |b, lines| {
            let kx0 = b * BATCH;
            let nb = lines.len() / rows;
            for ky in 0..rows {
                let row = &work[ky * nh + kx0..ky * nh + kx0 + nb];
                for (j, v) in row.iter().enumerate() {
                    lines[j * rows + ky] = *v;
                }
            }
            let mut guard = self.scratch();
            let s = guard.s.as_mut().expect("taken from the pool");
            self.col_fwd.process_with_scratch(lines, &mut s.cs);
            if let Some(kernel) = kernel {
                for (v, k) in lines.iter_mut().zip(&kernel[kx0 * rows..(kx0 + nb) * rows]) {
                    *v *= *k;
                }
                self.col_inv.process_with_scratch(lines, &mut s.cs);
            }
        });
    }

    /// Inverse transforms of the rows of `spec` (column-major) into `y`:
    /// the top left `out_rows x out_cols` of the grid, row-major.
    fn rows_inverse(
        &self,
        spec: &[Complex<f64>],
        y: &mut [f64],
        (out_rows, out_cols): (usize, usize),
    ) {
        let (rows, cols, nh) = (self.rows, self.cols, self.half_cols());
        debug_assert!(out_rows <= rows && out_cols <= cols && y.len() == out_rows * out_cols);
        self.for_chunks(y, out_cols * ROWS_PER_TASK, |ci, chunk| {
            let r0 = ci * ROWS_PER_TASK;
            let nr = chunk.len() / out_cols;
            let mut guard = self.scratch();
            let s = guard.s.as_mut().expect("taken from the pool");
            for kx in 0..nh {
                let col = &spec[kx * rows + r0..kx * rows + r0 + nr];
                for (k, v) in col.iter().enumerate() {
                    s.block[k * nh + kx] = *v;
                }
            }
            for (k, yr) in chunk.chunks_mut(out_cols).enumerate() {
                let w = &mut s.block[k * nh..(k + 1) * nh];
                // A real signal's DC and Nyquist terms are real.
                w[0].im = 0.0;
                if cols % 2 == 0 {
                    w[nh - 1].im = 0.0;
                }
                if out_cols == cols {
                    let _ = self.c2r.process_with_scratch(w, yr, &mut s.cs);
                } else {
                    let _ = self.c2r.process_with_scratch(w, &mut s.re, &mut s.cs);
                    yr.copy_from_slice(&s.re[..out_cols]);
                }
            }
        });
    }

    /// Forward transform of `x` (row-major, `rows cols`) into `spec`
    /// (column-major half spectrum); `work` is scratch of `spectrum_len()`.
    pub(crate) fn forward(&self, x: &[f64], spec: &mut [Complex<f64>], work: &mut [Complex<f64>]) {
        debug_assert_eq!(x.len(), self.rows * self.cols);
        self.rows_forward(Input::Plain(x), (self.rows, self.cols), work);
        self.columns(work, spec, None);
    }

    /// Inverse transform of `spec` (destroyed) into `x` (row-major),
    /// unnormalised; `work` is unused (kept for the callers' layout).
    pub(crate) fn inverse(
        &self,
        spec: &mut [Complex<f64>],
        x: &mut [f64],
        _work: &mut [Complex<f64>],
    ) {
        let rows = self.rows;
        self.for_chunks(spec, rows * BATCH, |_, lines| {
            let mut guard = self.scratch();
            let s = guard.s.as_mut().expect("taken from the pool");
            self.col_inv.process_with_scratch(lines, &mut s.cs);
        });
        self.rows_inverse(spec, x, (self.rows, self.cols));
    }

    /// `y = IFFT(kernel FFT(x))` with the kernel in the column-major layout
    /// (normalisation included in the kernel), `x` and `y` the whole grid.
    #[cfg(test)]
    pub(crate) fn convolve(
        &self,
        x: &[f64],
        y: &mut [f64],
        kernel: &[f64],
        spec: &mut [Complex<f64>],
        work: &mut [Complex<f64>],
    ) {
        let shape = (self.rows, self.cols);
        self.convolve_corner(Input::Plain(x), shape, y, kernel, spec, work);
    }

    /// `y = IFFT(kernel FFT(x))` (kernel column-major, normalisation
    /// included) for `x` (`rows x cols` of `shape`, row-major)
    /// padded with zeros to the grid, and `y` the same corner of the result
    /// (a padded linear convolution without a padded copy).
    pub(crate) fn convolve_corner(
        &self,
        x: Input<'_>,
        shape: (usize, usize),
        y: &mut [f64],
        kernel: &[f64],
        spec: &mut [Complex<f64>],
        work: &mut [Complex<f64>],
    ) {
        self.rows_forward(x, shape, work);
        self.columns(work, spec, Some(kernel));
        self.rows_inverse(spec, y, shape);
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

    /// A deterministic field of `n` values in `[-0.5, 0.5)` and a kernel
    /// of `f`'s spectrum length in `[1, 2)`: the convolution tests' inputs.
    fn test_field_and_kernel(f: &Fft2, n: usize) -> (Vec<f64>, Vec<f64>) {
        let x = (0..n)
            .map(|k| ((k * 7919) % 97) as f64 / 97.0 - 0.5)
            .collect();
        let kernel = (0..f.spectrum_len())
            .map(|k| 1.0 + ((k * 31) % 13) as f64 / 13.0)
            .collect();
        (x, kernel)
    }

    /// The fused small-grid convolution equals transform, multiply, inverse
    /// on grids narrower than its column batch (a 3 x 3 map panicked).
    #[test]
    fn narrow_grids_convolve_as_the_plain_transforms() {
        for (rows, cols) in [(3, 3), (3, 5), (5, 3), (2, 9), (9, 2), (6, 6), (3, 17)] {
            let f = Fft2::new(rows, cols);
            let (x, kernel) = test_field_and_kernel(&f, rows * cols);
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

    /// Above the parallel threshold the transforms split over threads by
    /// independent lines: the same bits on 1, 2 and 3 threads.
    #[test]
    fn the_same_bits_on_any_number_of_threads() {
        let (rows, cols) = (392, 350);
        assert!(rows * cols > PARALLEL_MIN);
        let f = Fft2::new(rows, cols);
        let (x, kernel) = test_field_and_kernel(&f, rows * cols);
        let run = |threads: usize| {
            crate::test_threads::on_threads(threads, || {
                let mut spec = vec![ZERO; f.spectrum_len()];
                let mut work = spec.clone();
                let mut y = vec![0.0; rows * cols];
                f.convolve(&x, &mut y, &kernel, &mut spec, &mut work);
                f.forward(&x, &mut spec, &mut work);
                let s = spec.clone();
                let mut back = vec![0.0; rows * cols];
                f.inverse(&mut spec, &mut back, &mut work);
                (y, s, back)
            })
        };
        let one = run(1);
        for threads in [2, 3] {
            assert!(one == run(threads), "{threads} threads");
        }
    }
}
