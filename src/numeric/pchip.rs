//! Shape-preserving piecewise cubic Hermite interpolation (PCHIP; Fritsch &
//! Carlson 1980, with the Fritsch–Butland harmonic-mean slopes used by
//! Matlab's `pchip` and scipy's `PchipInterpolator`): monotone data give a
//! monotone interpolant, no overshoot at steep steps.

use serde::{Deserialize, Serialize};

/// A PCHIP interpolant through `(x_i, y_i)`, `x` strictly increasing.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Pchip {
    x: Vec<f64>,
    y: Vec<f64>,
    d: Vec<f64>,
}

impl Pchip {
    /// Builds the interpolant; `None` unless `x` is strictly increasing, all
    /// values finite and there are at least 2 points.
    pub fn new(x: Vec<f64>, y: Vec<f64>) -> Option<Self> {
        let n = x.len();
        if n < 2 || y.len() != n || x.iter().chain(&y).any(|v| !v.is_finite()) {
            return None;
        }
        if x.windows(2).any(|w| !(w[1] > w[0])) {
            return None;
        }
        let h: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
        let del: Vec<f64> = (0..n - 1).map(|k| (y[k + 1] - y[k]) / h[k]).collect();
        let d = if n == 2 {
            vec![del[0]; 2]
        } else {
            slopes(&h, &del)
        };
        Some(Pchip { x, y, d })
    }

    /// Abscissae.
    pub fn x(&self) -> &[f64] {
        &self.x
    }

    /// Ordinates.
    pub fn y(&self) -> &[f64] {
        &self.y
    }

    /// Value at `t`, clamped to the end values outside `[x_0, x_n-1]`.
    #[inline]
    pub fn eval(&self, t: f64) -> f64 {
        let n = self.x.len();
        if !(t > self.x[0]) {
            return self.y[0];
        }
        if t >= self.x[n - 1] {
            return self.y[n - 1];
        }
        self.eval_piece(self.x.partition_point(|&v| v <= t) - 1, t)
    }
}

impl Pchip {
    /// The piece `k` with `x_k <= t < x_k+1` for `x_0 < t < x_n-1` (the
    /// piece [`eval`](Pchip::eval) finds), walking from `*hint` (updated)
    /// when it is a valid piece and the walk is short, bisecting otherwise:
    /// nearby arguments (a sorted population) then cost a comparison or two.
    #[inline]
    pub fn piece_near(&self, t: f64, hint: &mut usize) -> usize {
        let x = &self.x;
        let last = x.len() - 2;
        let mut k = *hint;
        if k <= last {
            for _ in 0..4 {
                if x[k] > t {
                    if k == 0 {
                        break;
                    }
                    k -= 1;
                } else if k < last && x[k + 1] <= t {
                    k += 1;
                } else {
                    *hint = k;
                    return k;
                }
            }
        }
        k = (x.partition_point(|&v| v <= t) - 1).min(last);
        *hint = k;
        k
    }

    /// The value at `t` on piece `k` (as [`eval`](Pchip::eval) for
    /// `x_0 < t < x_n-1` and `k` from [`piece_near`](Pchip::piece_near)).
    #[inline]
    pub fn eval_piece(&self, k: usize, t: f64) -> f64 {
        let h = self.x[k + 1] - self.x[k];
        let s = (t - self.x[k]) / h;
        let (y0, y1) = (self.y[k], self.y[k + 1]);
        let (d0, d1) = (self.d[k] * h, self.d[k + 1] * h);
        hermite(s, y0, y1, d0, d1)
    }
}

/// The cubic Hermite interpolant on the unit interval: value at `s` in
/// `[0, 1]` of the cubic with end values `y0`, `y1` and end slopes `d0`,
/// `d1` (per unit `s`), `h00 y0 + h10 d0 + h01 y1 + h11 d1` with
/// `h00 = 2s^3 - 3s^2 + 1`, `h10 = s^3 - 2s^2 + s`, `h01 = -2s^3 + 3s^2`,
/// `h11 = s^3 - s^2`.
#[inline]
pub fn hermite(s: f64, y0: f64, y1: f64, d0: f64, d1: f64) -> f64 {
    let s2 = s * s;
    let s3 = s2 * s;
    (2.0 * s3 - 3.0 * s2 + 1.0) * y0
        + (s3 - 2.0 * s2 + s) * d0
        + (-2.0 * s3 + 3.0 * s2) * y1
        + (s3 - s2) * d1
}

/// The derivative of the cubic Hermite interpolant on a piece of width `h`
/// with end values `y0`, `y1` and end slopes `d0`, `d1` (per unit of the
/// abscissa), as `p0 + p1 t + p2 t^2` in `t = (x - x0)/h`: `p0 = d0`,
/// `p1 = 6 c - 4 d0 - 2 d1`, `p2 = -6 c + 3 d0 + 3 d1` with the chord
/// `c = (y1 - y0)/h`.
#[inline]
pub fn hermite_derivative(h: f64, y0: f64, y1: f64, d0: f64, d1: f64) -> [f64; 3] {
    let chord = (y1 - y0) / h;
    [
        d0,
        6.0 * chord - 4.0 * d0 - 2.0 * d1,
        -6.0 * chord + 3.0 * d0 + 3.0 * d1,
    ]
}

/// PCHIP node slopes from the interval widths `h` and secants `del` (at
/// least two intervals): Fritsch–Butland weighted harmonic means inside
/// (zero at a local extremum), Moler's shape-preserving end rule.
pub fn slopes(h: &[f64], del: &[f64]) -> Vec<f64> {
    let n = h.len() + 1;
    let mut d = vec![0.0; n];
    for k in 1..n - 1 {
        if del[k - 1] * del[k] > 0.0 {
            let w1 = 2.0 * h[k] + h[k - 1];
            let w2 = h[k] + 2.0 * h[k - 1];
            d[k] = (w1 + w2) / (w1 / del[k - 1] + w2 / del[k]);
        }
    }
    d[0] = end_slope(h[0], h[1], del[0], del[1]);
    d[n - 1] = end_slope(h[n - 2], h[n - 3], del[n - 2], del[n - 3]);
    d
}

/// Three-point end slope, kept shape-preserving (Moler, *Numerical Computing
/// with MATLAB*, `pchipend`).
fn end_slope(h0: f64, h1: f64, del0: f64, del1: f64) -> f64 {
    let d = ((2.0 * h0 + h1) * del0 - h0 * del1) / (h0 + h1);
    if d * del0 <= 0.0 {
        0.0
    } else if del0 * del1 <= 0.0 && d.abs() > 3.0 * del0.abs() {
        3.0 * del0
    } else {
        d
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The walk from any hint finds the piece of the bisection, and
    /// `eval_piece` on it is `eval`, bit for bit.
    #[test]
    fn piece_near_is_the_bisections_piece_from_any_hint() {
        let x: Vec<f64> = (0..40).map(|k| (k as f64).powf(1.3)).collect();
        let y: Vec<f64> = x.iter().map(|v| v.sin()).collect();
        let p = Pchip::new(x.clone(), y).unwrap();
        let last = x[x.len() - 1];
        for i in 1..2000 {
            let t = last * i as f64 / 2000.0;
            let want = x.partition_point(|&v| v <= t) - 1;
            for hint in [0, 1, 5, 20, 37, 38, 39, 100, usize::MAX] {
                let mut h = hint;
                let k = p.piece_near(t, &mut h);
                assert_eq!(k, want, "{t} {hint}");
                assert_eq!(h, k);
                assert_eq!(p.eval_piece(k, t).to_bits(), p.eval(t).to_bits());
            }
        }
    }

    #[test]
    fn reproduces_nodes_and_cubics_with_matching_slopes() {
        let x = vec![0.0, 0.5, 1.3, 2.0, 3.1];
        let y: Vec<f64> = x.iter().map(|v| 2.0 * v + 1.0).collect();
        let p = Pchip::new(x.clone(), y.clone()).unwrap();
        for (a, b) in x.iter().zip(&y) {
            assert_eq!(p.eval(*a), *b);
        }
        // linear data are reproduced exactly in between
        assert!((p.eval(1.7) - 4.4).abs() < 1e-14);
        assert_eq!(p.eval(-5.0), 1.0);
        assert_eq!(p.eval(10.0), y[4]);
        assert!(Pchip::new(vec![0.0, 0.0], vec![1.0, 2.0]).is_none());
        assert!(Pchip::new(vec![0.0], vec![1.0]).is_none());
        assert!(Pchip::new(vec![0.0, 1.0], vec![f64::NAN, 2.0]).is_none());
    }

    proptest! {
        /// Monotone data give a monotone interpolant within the data range.
        #[test]
        fn monotone_data_stay_monotone(steps in proptest::collection::vec((0.01f64..2.0, 0.0f64..5.0), 3..20)) {
            let mut x = vec![0.0];
            let mut y = vec![0.0];
            for (dx, dy) in &steps {
                x.push(x.last().unwrap() + dx);
                y.push(y.last().unwrap() + dy);
            }
            let p = Pchip::new(x.clone(), y.clone()).unwrap();
            let mut prev = f64::NEG_INFINITY;
            let xmax = *x.last().unwrap();
            for i in 0..=400 {
                let v = p.eval(xmax * i as f64 / 400.0);
                prop_assert!(v >= prev - 1e-12);
                prop_assert!(v >= -1e-12 && v <= y.last().unwrap() + 1e-12);
                prev = v;
            }
        }
    }
}
