//! Measured summit heights: the empirical distribution of a sample.

use super::quad::binomial;
use super::HeightDistribution;
use crate::error::{finite, Error, Result};
use crate::special::normal;

/// Highest integer order with the `O(log N)` closed form.
const MAX_POW: usize = 3;

/// The empirical distribution of measured summit heights `z_i` (m),
/// standardised by the sample mean and the sample standard deviation with
/// divisor `N` (so the standardised sample has mean 0 and variance exactly 1):
/// `s_i = (z_i - mean)/std`. The surface's `sigma` should be
/// [`std_m`](Empirical::std_m) and `h = d/sigma` is measured from the sample
/// mean.
///
/// `F_n(h) = (1/N) sum_(s_i > h) (s_i - h)^n`, the exact sample average:
/// - integer `n <= 3`: `O(log N)`. The sorted sample is stored with, for every
///   `m`, `T_j(m) = sum_(i >= m) (s_i - s_m)^j`, `j <= 3`, built from the top
///   by `T_j(m) = [j = 0] + sum_l C(j, l) (s_(m+1) - s_m)^(j-l) T_l(m+1)`;
///   then with `m` the first index above `h` (binary search) and
///   `g = s_m - h > 0`, `N F_n = sum_j C(n, j) g^(n-j) T_j(m)`. Every term is
///   positive, so nothing cancels (relative error ~`sqrt(N)` ulp typical,
///   `N` ulp worst case).
/// - other `n`: the direct sum over the `N - m` points above `h`.
///
/// The sample has no density: [`pdf`](HeightDistribution::pdf) is a Gaussian
/// kernel density estimate (Silverman's bandwidth `1.06 N^(-1/5)`), used only
/// by integrators that need a density (quadrature of non-power laws); it is
/// *not* consistent with `F_n` and `tail`, which are the exact sample
/// averages. Closed-form integrators (Hertz, DMT) therefore reproduce the
/// exact sum over the measured summits.
#[derive(Debug, Clone, PartialEq)]
pub struct Empirical {
    /// Sorted standardised heights.
    s: Vec<f64>,
    /// `t[m][j] = T_j(m)`; `t[N] = 0`.
    t: Vec<[f64; MAX_POW + 1]>,
    mean_m: f64,
    std_m: f64,
    bandwidth: f64,
}

impl Empirical {
    /// From measured summit heights (m; any common origin).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `heights` for fewer than 2 values or zero
    /// spread; [`Error::OutOfRange`] naming `heights[i]` for a non-finite value.
    pub fn new(heights_m: &[f64]) -> Result<Self> {
        if heights_m.len() < 2 {
            return Err(Error::invalid(
                "heights",
                format!("needs at least 2 measured heights, got {}", heights_m.len()),
            ));
        }
        for (i, &z) in heights_m.iter().enumerate() {
            finite(&format!("heights[{i}]"), z)?;
        }
        let n = heights_m.len() as f64;
        let mean = heights_m.iter().sum::<f64>() / n;
        let var = heights_m.iter().map(|z| (z - mean).powi(2)).sum::<f64>() / n;
        let std = var.sqrt();
        if !(std > 1e-12 * mean.abs()) || !std.is_finite() {
            return Err(Error::invalid(
                "heights",
                format!("no spread: standard deviation {std:e} m about mean {mean:e} m"),
            ));
        }
        let mut s: Vec<f64> = heights_m.iter().map(|z| (z - mean) / std).collect();
        s.sort_by(f64::total_cmp);
        let len = s.len();
        let mut t = vec![[0.0; MAX_POW + 1]; len + 1];
        t[len - 1][0] = 1.0;
        for m in (0..len - 1).rev() {
            let g = s[m + 1] - s[m];
            let up = t[m + 1];
            let mut row = [0.0; MAX_POW + 1];
            for (j, r) in row.iter_mut().enumerate() {
                let mut v = if j == 0 { 1.0 } else { 0.0 };
                for (l, &ul) in up.iter().enumerate().take(j + 1) {
                    v += binomial(j as u32, l as u32) * g.powi((j - l) as i32) * ul;
                }
                *r = v;
            }
            t[m] = row;
        }
        Ok(Empirical {
            s,
            t,
            mean_m: mean,
            std_m: std,
            bandwidth: 1.06 * n.powf(-0.2),
        })
    }

    /// Sample mean of the measured heights (m).
    pub fn mean_m(&self) -> f64 {
        self.mean_m
    }

    /// Sample standard deviation (divisor `N`) of the measured heights (m):
    /// the surface's `sigma`.
    pub fn std_m(&self) -> f64 {
        self.std_m
    }

    /// The sorted standardised heights.
    pub fn standardised(&self) -> &[f64] {
        &self.s
    }

    /// Index of the first height strictly above `h`.
    fn first_above(&self, h: f64) -> usize {
        self.s.partition_point(|&x| x <= h)
    }
}

impl HeightDistribution for Empirical {
    fn name(&self) -> &'static str {
        "empirical"
    }

    fn sample_points(&self) -> Option<&[f64]> {
        Some(&self.s)
    }

    fn pdf(&self, s: f64) -> f64 {
        if s.is_nan() {
            return f64::NAN;
        }
        let bw = self.bandwidth;
        let lo = self.s.partition_point(|&x| x < s - 9.0 * bw);
        let hi = self.s.partition_point(|&x| x <= s + 9.0 * bw);
        let sum: f64 = self.s[lo..hi]
            .iter()
            .map(|&x| normal::pdf((s - x) / bw))
            .sum();
        sum / (bw * self.s.len() as f64)
    }

    fn tail(&self, s: f64) -> f64 {
        if s.is_nan() {
            return f64::NAN;
        }
        (self.s.len() - self.first_above(s)) as f64 / self.s.len() as f64
    }

    fn support(&self) -> (f64, f64) {
        (self.s[0], self.s[self.s.len() - 1])
    }

    fn moment_above(&self, n: f64, h: f64) -> f64 {
        if n.is_nan() || h.is_nan() || n < 0.0 {
            return f64::NAN;
        }
        let len = self.s.len();
        let m = self.first_above(h);
        if m == len {
            return 0.0;
        }
        if h == f64::NEG_INFINITY {
            return if n == 0.0 { 1.0 } else { f64::INFINITY };
        }
        let total = if n == n.floor() && n <= MAX_POW as f64 {
            let k = n as usize;
            let g = self.s[m] - h;
            let row = &self.t[m];
            (0..=k)
                .map(|j| binomial(k as u32, j as u32) * g.powi((k - j) as i32) * row[j])
                .sum::<f64>()
        } else {
            self.s[m..].iter().map(|&x| (x - h).powf(n)).sum::<f64>()
        };
        total / len as f64
    }

    fn quantile(&self, p: f64) -> f64 {
        if !(0.0..=1.0).contains(&p) {
            return f64::NAN;
        }
        let len = self.s.len();
        let i = ((p * len as f64).ceil() as usize).clamp(1, len) - 1;
        self.s[i]
    }

    fn numerical_support(&self, eps: f64) -> (f64, f64) {
        // The kernel density reaches c bandwidths beyond the extreme points.
        let c = normal::inverse_tail(super::gaussian::clamp_eps(eps));
        let (lo, hi) = self.support();
        (lo - c * self.bandwidth, hi + c * self.bandwidth)
    }

    fn closed_form_moment(&self, n: f64) -> bool {
        n >= 0.0 && n.is_finite()
    }
}
