//! The mean plane: the least-squares plane `z = c0 + c1 x + c2 y` over all
//! pixels (x = j dx along a row, y = i dy down the columns).
//!
//! On a complete regular grid the normal equations decouple about the
//! centre `(x_c, y_c) = ((cols-1)/2, (rows-1)/2) dx`:
//! `c1 = sum (x - x_c) z / sum (x - x_c)^2` with
//! `sum_j (j - j_c)^2 = cols (cols^2 - 1)/12` (and likewise `c2`), and the
//! plane passes through the mean height at the centre. A periodic map has
//! no tilt: only the mean is removed.

use rayon::prelude::*;

/// A fitted plane, SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plane {
    /// Height of the plane at pixel (0, 0) (m).
    pub c0: f64,
    /// Slope along x, i.e. along a row (m/m).
    pub slope_x: f64,
    /// Slope along y, i.e. down a column (m/m).
    pub slope_y: f64,
    /// Mean height of the map (m): the plane's height at the centre.
    mean: f64,
    /// Slopes per pixel (m/pixel), used to evaluate the plane.
    per_px: (f64, f64),
    centre: (f64, f64),
}

impl Plane {
    /// Fits the plane to a row-major map of pixels `dx` x `dy` (`periodic`:
    /// the mean only).
    pub(crate) fn fit_xy(
        z: &[f64],
        rows: usize,
        cols: usize,
        (dx, dy): (f64, f64),
        periodic: bool,
    ) -> Plane {
        let jc = (cols as f64 - 1.0) / 2.0;
        let ic = (rows as f64 - 1.0) / 2.0;
        // Per row: sum z and sum (j - jc) z in LANES interleaved
        // accumulators, rows added in row order (the same on any number of
        // threads).
        let xs: Vec<f64> = (0..cols).map(|j| j as f64 - jc).collect();
        let sums: Vec<(f64, f64)> = z.par_chunks(cols).map(|row| row_sums(row, &xs)).collect();
        let n = (rows * cols) as f64;
        let (mut s, mut sx, mut sy) = (0.0, 0.0, 0.0);
        for (i, (rs, rsx)) in sums.iter().enumerate() {
            s += rs;
            sx += rsx;
            sy += (i as f64 - ic) * rs;
        }
        let mean = s / n;
        let (cx, cy) = if periodic {
            (0.0, 0.0)
        } else {
            let sxx = rows as f64 * cols as f64 * ((cols * cols) as f64 - 1.0) / 12.0;
            let syy = cols as f64 * rows as f64 * ((rows * rows) as f64 - 1.0) / 12.0;
            (sx / sxx, sy / syy)
        };
        Plane {
            c0: mean - cx * jc - cy * ic,
            slope_x: cx / dx,
            slope_y: cy / dy,
            mean,
            per_px: (cx, cy),
            centre: (jc, ic),
        }
    }

    /// Height of the plane at pixel `(i, j)` (m).
    pub fn at(&self, i: usize, j: usize) -> f64 {
        self.mean
            + self.per_px.0 * (j as f64 - self.centre.0)
            + self.per_px.1 * (i as f64 - self.centre.1)
    }

    /// The residual heights `z - plane`, row-major.
    pub(crate) fn residual(&self, z: &[f64], cols: usize) -> Vec<f64> {
        let columns = self.columns(cols);
        let mut r = vec![0.0; z.len()];
        r.par_chunks_mut(cols)
            .zip(z.par_chunks(cols))
            .enumerate()
            .for_each(|(i, (out, row))| self.residual_row(i, row, &columns, out));
        r
    }

    /// The column part of the plane, `mean + slope_x_px (j - j_c)` for
    /// `j < cols` (m): with [`Plane::residual_row`], the height of
    /// [`Plane::at`] to the bit.
    pub(crate) fn columns(&self, cols: usize) -> Vec<f64> {
        (0..cols)
            .map(|j| self.mean + self.per_px.0 * (j as f64 - self.centre.0))
            .collect()
    }

    /// Row `i` of the residual heights, `row - plane`, into `out`;
    /// `columns` from [`Plane::columns`].
    pub(crate) fn residual_row(&self, i: usize, row: &[f64], columns: &[f64], out: &mut [f64]) {
        let y = self.per_px.1 * (i as f64 - self.centre.1);
        for ((o, &v), &c) in out.iter_mut().zip(row).zip(columns) {
            *o = v - (c + y);
        }
    }
}

/// Interleaved accumulators of [`row_sums`].
const LANES: usize = 4;

/// `(sum z, sum x z)` over a row `z` with centred column positions `xs`
/// (pixels), in [`LANES`] interleaved accumulators added in lane order.
fn row_sums(z: &[f64], xs: &[f64]) -> (f64, f64) {
    let (mut s, mut sx) = ([0.0; LANES], [0.0; LANES]);
    let (zc, xc) = (z.chunks_exact(LANES), xs.chunks_exact(LANES));
    let (zr, xr) = (zc.remainder(), xc.remainder());
    for (zk, xk) in zc.zip(xc) {
        for l in 0..LANES {
            s[l] += zk[l];
            sx[l] += xk[l] * zk[l];
        }
    }
    let (mut t, mut tx) = (0.0, 0.0);
    for (&v, &x) in zr.iter().zip(xr) {
        t += v;
        tx += x * v;
    }
    (t + s.iter().sum::<f64>(), tx + sx.iter().sum::<f64>())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn removes_an_exact_plane_and_only_the_mean_when_periodic() {
        let (rows, cols, dx) = (5, 7, 2e-6);
        let z: Vec<f64> = (0..rows * cols)
            .map(|k| 3e-6 + 1e-3 * (k % cols) as f64 * dx - 2e-3 * (k / cols) as f64 * dx)
            .collect();
        let p = Plane::fit_xy(&z, rows, cols, (dx, dx), false);
        assert!((p.slope_x - 1e-3).abs() < 1e-15 && (p.slope_y + 2e-3).abs() < 1e-15);
        assert!((p.c0 - 3e-6).abs() < 1e-18);
        assert!(p.residual(&z, cols).iter().all(|r| r.abs() < 1e-18));
        let q = Plane::fit_xy(&z, rows, cols, (dx, dx), true);
        assert_eq!((q.slope_x, q.slope_y), (0.0, 0.0));
        let r = q.residual(&z, cols);
        assert!(r.iter().sum::<f64>().abs() < 1e-18);
        assert!(r[cols - 1] > 0.0);
    }
}
