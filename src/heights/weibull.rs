//! Weibull summit heights with unit standard deviation, `s >= 0`.

use super::quad::{binomial, is_integer};
use super::HeightDistribution;
use crate::error::{Allowed, Result};
use crate::numeric::quadrature::integrate_pieces;
use crate::special::gamma::gamma;

/// Allowed shapes: below 0.1 `Gamma(1 + 2/k)` overflows soon after; above
/// 100 the variance `Gamma(1+2/k) - Gamma(1+1/k)^2 ~ 1.6/k^2` loses digits.
pub const SHAPE_RANGE: Allowed = Allowed {
    lo: 0.1,
    lo_inclusive: true,
    hi: 100.0,
    hi_inclusive: true,
};

/// Weibull summit heights of shape `k`, standardised to unit standard
/// deviation and, like GW's exponential, measured from the lowest summit:
///
/// `phi(s) = (k/lambda) (s/lambda)^(k-1) exp(-(s/lambda)^k)`, `s >= 0`,
/// `lambda = 1/sqrt(Gamma(1 + 2/k) - Gamma(1 + 1/k)^2)`.
///
/// So the surface's `sigma` (m) is the summit-height standard deviation, and
/// `k = 1` is exactly [`Exponential`](super::Exponential) (then `lambda = 1`
/// and `sigma` is also the decay length). `h = d/sigma` is measured from
/// `s = 0`, not from the mean `lambda Gamma(1 + 1/k)`.
///
/// `F_0` is closed (`exp(-(h/lambda)^k)`); for `h <= 0` and integer `n`,
/// `F_n(h) = sum_j C(n, j) (-h)^(n-j) lambda^j Gamma(1 + j/k)` (all terms
/// positive); otherwise adaptive quadrature (relative 1e-13) in
/// `y = (s/lambda)^k`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Weibull {
    shape: f64,
    scale: f64,
}

impl Weibull {
    /// Shape `k` in `[0.1, 100]`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`](crate::Error::OutOfRange) naming `weibull_shape`.
    pub fn new(shape: f64) -> Result<Self> {
        SHAPE_RANGE.check("weibull_shape", shape)?;
        let g1 = gamma(1.0 + 1.0 / shape);
        let var = gamma(1.0 + 2.0 / shape) - g1 * g1;
        Ok(Weibull {
            shape,
            scale: 1.0 / var.sqrt(),
        })
    }

    /// Shape `k`.
    pub fn shape(&self) -> f64 {
        self.shape
    }

    /// Scale `lambda` in units of the standard deviation.
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// Mean `lambda Gamma(1 + 1/k)` in units of the standard deviation.
    pub fn mean(&self) -> f64 {
        self.scale * gamma(1.0 + 1.0 / self.shape)
    }

    /// `F_n(h)` by quadrature: with `y0 = (h+/lambda)^k`, `y = y0 + u^2`,
    /// `F_n = e^-y0 int_0^inf 2u (s(y) - h)^n e^-u^2 du`, and for `h > 0`
    /// `s(y) - h = h expm1(ln1p(u^2/y0)/k)` (no cancellation).
    fn quadrature(&self, n: f64, h: f64) -> f64 {
        let (k, lam) = (self.shape, self.scale);
        let y0 = if h > 0.0 { (h / lam).powf(k) } else { 0.0 };
        let pre = (-y0).exp();
        if pre == 0.0 {
            return 0.0;
        }
        let f = |u: f64| {
            let u2 = u * u;
            let gap = if h > 0.0 {
                h * ((u2 / y0).ln_1p() / k).exp_m1()
            } else {
                lam * u2.powf(1.0 / k) - h
            };
            if gap <= 0.0 {
                return 0.0;
            }
            2.0 * u * gap.powf(n) * (-u2).exp()
        };
        let pts = [
            0.0, 0.125, 0.25, 0.5, 1.0, 2.0, 3.0, 4.0, 6.0, 8.0, 16.0, 27.6,
        ];
        pre * integrate_pieces(f, &pts, &super::quad::FALLBACK).value
    }
}

impl HeightDistribution for Weibull {
    fn name(&self) -> &'static str {
        "weibull"
    }

    fn pdf(&self, s: f64) -> f64 {
        if s.is_nan() {
            return f64::NAN;
        }
        if s < 0.0 {
            return 0.0;
        }
        let (k, lam) = (self.shape, self.scale);
        let x = s / lam;
        if x == 0.0 {
            return match k.partial_cmp(&1.0) {
                Some(std::cmp::Ordering::Less) => f64::INFINITY,
                Some(std::cmp::Ordering::Equal) => 1.0 / lam,
                _ => 0.0,
            };
        }
        let xk = x.powf(k);
        if xk == f64::INFINITY {
            return 0.0;
        }
        k / lam * xk / x * (-xk).exp()
    }

    fn tail(&self, s: f64) -> f64 {
        if s.is_nan() {
            return f64::NAN;
        }
        if s <= 0.0 {
            return 1.0;
        }
        (-(s / self.scale).powf(self.shape)).exp()
    }

    fn support(&self) -> (f64, f64) {
        (0.0, f64::INFINITY)
    }

    fn moment_above(&self, n: f64, h: f64) -> f64 {
        if n.is_nan() || h.is_nan() || n < 0.0 {
            return f64::NAN;
        }
        if h == f64::INFINITY {
            return 0.0;
        }
        if n == 0.0 {
            return self.tail(h);
        }
        if h == f64::NEG_INFINITY {
            return f64::INFINITY;
        }
        if h <= 0.0 && is_integer(n) && n <= 64.0 {
            let m = n as u32;
            let a = -h;
            return (0..=m)
                .map(|j| {
                    let jf = f64::from(j);
                    binomial(m, j)
                        * a.powi((m - j) as i32)
                        * self.scale.powf(jf)
                        * gamma(1.0 + jf / self.shape)
                })
                .sum();
        }
        self.quadrature(n, h)
    }

    fn quantile(&self, p: f64) -> f64 {
        if !(0.0..=1.0).contains(&p) {
            return f64::NAN;
        }
        self.scale * (-(-p).ln_1p()).powf(1.0 / self.shape)
    }

    fn quantile_upper(&self, q: f64) -> f64 {
        if !(0.0..=1.0).contains(&q) {
            return f64::NAN;
        }
        // P(S > s) = exp(-(s/scale)^shape)
        self.scale * (-q.ln()).powf(1.0 / self.shape)
    }

    fn numerical_support(&self, eps: f64) -> (f64, f64) {
        let e = super::gaussian::clamp_eps(eps);
        (0.0, self.scale * (-e.ln()).powf(1.0 / self.shape))
    }
}
