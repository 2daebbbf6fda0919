//! Gaussian summit heights truncated at `+-k` standard deviations.

use super::quad::power_moment;
use super::HeightDistribution;
use crate::error::{positive, Result};
use crate::numeric::quadrature::kronrod21;
use crate::special::normal;

/// Smallest truncation `k`: below 0.01 standard deviations every summit
/// sits at one height for any resolved program (`truncation = 1e-300` gave
/// negative areas and a negative hysteresis energy); a single height is the
/// `empirical` distribution of one value.
pub const MIN_TRUNCATION: f64 = 0.01;

/// Standard normal heights truncated to `[-k, k]` and renormalised:
/// `phi_T(s) = phi(s)/Z` on `[-k, k]`, `Z = 1 - 2 Q(k)`.
///
/// `s` is the *untruncated* normal variable: the surface's `sigma` (m) is
/// the standard deviation of the parent Gaussian (the truncated law's own
/// standard deviation is `sqrt(1 - 2 k phi(k)/Z)`, slightly less). Bounded
/// above, so laws that diverge at finite interference (rigid Bradley) can
/// use it.
///
/// `F_0(h) = int_h^k phi / Z` (closed form `Q(h) - Q(k)` when `k - h >= 1`,
/// else fixed 21-point Kronrod rules on `phi(h) int_0^(k-h) exp(-h t - t^2/2) dt`,
/// free of the cancellation); `F_n` for `n > 0` by adaptive
/// quadrature (relative 1e-13).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TruncatedGaussian {
    k: f64,
    z: f64,
}

impl TruncatedGaussian {
    /// Truncation `k` in `[`[`MIN_TRUNCATION`]`, inf)` (in standard
    /// deviations of the parent Gaussian).
    ///
    /// # Errors
    /// [`Error::OutOfRange`](crate::Error::OutOfRange) naming `truncation`.
    pub fn new(k: f64) -> Result<Self> {
        positive("truncation", k)?;
        crate::error::Allowed::closed_open(MIN_TRUNCATION, f64::INFINITY).check("truncation", k)?;
        Ok(TruncatedGaussian {
            k,
            z: 1.0 - 2.0 * normal::tail(k),
        })
    }

    /// Truncation `k`.
    pub fn truncation(&self) -> f64 {
        self.k
    }

    /// `s >= 0` with `int_s^k phi = t` for `0 <= t <= Z/2`: the parent
    /// normal's inverse tail as a first guess, then Newton steps on the
    /// relative-accurate [`mass_above`](Self::mass_above), so the quantile
    /// stays accurate right up to the truncation point.
    fn upper_point(&self, t: f64) -> f64 {
        let k = self.k;
        if !(t > 0.0) {
            return k;
        }
        let mut s = normal::inverse_tail(normal::tail(k) + t).clamp(0.0, k);
        for _ in 0..3 {
            let d = normal::pdf(s);
            s = (s + (self.mass_above(s) - t) / d).clamp(0.0, k);
        }
        s
    }

    /// `int_h^k phi(s) ds` for `-k <= h <= k`, accurate in relative terms.
    fn mass_above(&self, h: f64) -> f64 {
        let k = self.k;
        if k - h >= 1.0 {
            if h >= 0.0 {
                normal::tail(h) - normal::tail(k)
            } else {
                // Q(h) - Q(k) = 1 - Q(-h) - Q(k)
                (1.0 - normal::tail(k)) - normal::tail(-h)
            }
        } else {
            // phi(h) int_0^(k-h) exp(-h t - t^2/2) dt: a smooth integrand on
            // a short interval, summed with fixed 21-point Kronrod rules over
            // pieces on which the exponent changes by at most 4 (degree-31
            // exactness: relative error far below 1e-15). An adaptive rule
            // asked for 1e-14 here can subdivide to its limit on roundoff.
            let g = |t: f64| (-t * (h + 0.5 * t)).exp();
            let len = k - h;
            let pieces = (len * h.abs().max(1.0) / 4.0).ceil().max(1.0) as usize;
            let step = len / pieces as f64;
            let sum: f64 = (0..pieces)
                .map(|i| {
                    let a = i as f64 * step;
                    kronrod21(&mut { g }, a, a + step).0
                })
                .sum();
            normal::pdf(h) * sum
        }
    }
}

impl HeightDistribution for TruncatedGaussian {
    fn name(&self) -> &'static str {
        "truncated-gaussian"
    }

    fn pdf(&self, s: f64) -> f64 {
        if s.is_nan() {
            f64::NAN
        } else if s.abs() <= self.k {
            normal::pdf(s) / self.z
        } else {
            0.0
        }
    }

    fn tail(&self, s: f64) -> f64 {
        if s.is_nan() {
            f64::NAN
        } else if s >= self.k {
            0.0
        } else if s <= -self.k {
            1.0
        } else {
            (self.mass_above(s) / self.z).min(1.0)
        }
    }

    fn support(&self) -> (f64, f64) {
        (-self.k, self.k)
    }

    fn moment_above(&self, n: f64, h: f64) -> f64 {
        if n.is_nan() || h.is_nan() || n < 0.0 {
            return f64::NAN;
        }
        let k = self.k;
        if h >= k {
            return 0.0;
        }
        if n == 0.0 {
            return self.tail(h);
        }
        if h == f64::NEG_INFINITY {
            return f64::INFINITY;
        }
        // int_max(h,-k)^k (s-h)^n phi(s) ds / Z, with t = s - h.
        let t_max = k - h;
        let v = if h >= 0.0 {
            normal::pdf(h) * power_moment(n, |t| (-t * (h + 0.5 * t)).exp(), t_max, &[])
        } else {
            let lo = (-k - h).max(0.0);
            power_moment(
                n,
                |t| {
                    if t < lo {
                        0.0
                    } else {
                        normal::pdf(h + t)
                    }
                },
                t_max,
                &[lo, -h],
            )
        };
        v / self.z
    }

    fn quantile(&self, p: f64) -> f64 {
        if !(0.0..=1.0).contains(&p) {
            return f64::NAN;
        }
        // Solve in the nearer tail: upper mass int_s^k phi = (1-p) Z, or by
        // symmetry the lower one.
        if p < 0.5 {
            -self.upper_point(p * self.z)
        } else {
            self.upper_point((1.0 - p) * self.z)
        }
    }

    fn quantile_upper(&self, q: f64) -> f64 {
        if !(0.0..=1.0).contains(&q) {
            return f64::NAN;
        }
        // The same nearer-tail solve with the upper mass q Z given exactly.
        if q <= 0.5 {
            self.upper_point(q * self.z)
        } else {
            -self.upper_point((1.0 - q) * self.z)
        }
    }

    fn numerical_support(&self, eps: f64) -> (f64, f64) {
        let s = normal::inverse_tail(super::gaussian::clamp_eps(eps));
        (-(s.min(self.k)), s.min(self.k))
    }
}
