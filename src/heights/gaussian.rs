//! Standard normal summit heights, `phi(s) = exp(-s^2/2)/sqrt(2 pi)`.

use super::quad::power_moment;
use super::HeightDistribution;
use crate::special::{gaussian_fn, normal};

/// `ln sqrt(2 pi)`.
const LN_SQRT_2PI: f64 = 0.918_938_533_204_672_8;

/// Gaussian summit heights (Greenwood & Williamson 1966): `s` standard
/// normal, so the surface's `sigma` (m) is the summit-height standard
/// deviation and `h = d/sigma` is measured from the mean summit height.
///
/// `F_n` is a closed form ([`gaussian_fn`](crate::special::gaussian_fn),
/// relative error ~1e-15 on `[-5, 10]`, ~1e-14 to `h = 37`) for
/// `n = 0, 1/2, 1, 3/2, 2, 5/2`, and adaptive quadrature (relative 1e-13)
/// of the scaled integral `phi(h) int_0^inf t^n exp(-h t - t^2/2) dt`
/// otherwise.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Gaussian;

impl Gaussian {
    /// The standard normal distribution.
    pub fn new() -> Self {
        Gaussian
    }
}

impl HeightDistribution for Gaussian {
    fn name(&self) -> &'static str {
        "gaussian"
    }

    fn pdf(&self, s: f64) -> f64 {
        normal::pdf(s)
    }

    /// [`normal::pdf_batch`]: within 4e-16 of `pdf`, in vector registers.
    fn pdf_batch(&self, s: &[f64], out: &mut [f64]) {
        normal::pdf_batch(s, out);
    }

    /// `-s^2/2 - ln sqrt(2 pi)`.
    fn log_pdf(&self, s: f64) -> f64 {
        -0.5 * s * s - LN_SQRT_2PI
    }

    /// `exp(-(s - r)(s + r)/2)`: no underflow of either density, and the
    /// difference `s - r` is exact for nearby heights.
    fn pdf_ratio(&self, s: f64, r: f64) -> f64 {
        (-0.5 * (s - r) * (s + r)).exp()
    }

    fn tail(&self, s: f64) -> f64 {
        normal::tail(s)
    }

    /// `sqrt(r^2 + 2 drop)`, `r = max(s, 0)`: where `-s^2/2` has fallen by
    /// `drop` from its value at `r`.
    fn decay_end(&self, s: f64, drop: f64) -> f64 {
        let r = s.max(0.0);
        (r * r + 2.0 * drop).sqrt()
    }

    fn support(&self) -> (f64, f64) {
        (f64::NEG_INFINITY, f64::INFINITY)
    }

    /// `true`: `phi(s) = exp(-s^2/2)/sqrt(2 pi)` itself.
    fn is_standard_normal(&self) -> bool {
        true
    }

    fn moment_above(&self, n: f64, h: f64) -> f64 {
        if n.is_nan() || h.is_nan() || n < 0.0 {
            return f64::NAN;
        }
        if let Some(v) = gaussian_fn::gaussian_fn(n, h) {
            return v;
        }
        gaussian_moment_quadrature(n, h)
    }

    fn quantile(&self, p: f64) -> f64 {
        normal::quantile(p)
    }

    fn quantile_upper(&self, q: f64) -> f64 {
        normal::inverse_tail(q)
    }

    fn numerical_support(&self, eps: f64) -> (f64, f64) {
        let s = normal::inverse_tail(clamp_eps(eps));
        (-s, s)
    }

    fn closed_form_moment(&self, n: f64) -> bool {
        gaussian_fn::has_closed_form(n)
    }
}

/// `eps` clamped to `[1e-307, 0.5]` (NaN -> 1e-307).
pub(crate) fn clamp_eps(eps: f64) -> f64 {
    if eps.is_nan() {
        1e-307
    } else {
        eps.clamp(1e-307, 0.5)
    }
}

/// `F_n(h)` of the standard normal by quadrature, any `n >= 0`.
pub(crate) fn gaussian_moment_quadrature(n: f64, h: f64) -> f64 {
    if h == f64::INFINITY {
        return 0.0;
    }
    if h == f64::NEG_INFINITY {
        return if n == 0.0 { 1.0 } else { f64::INFINITY };
    }
    if h >= 0.0 {
        let p = normal::pdf(h);
        if p == 0.0 {
            return 0.0;
        }
        // exp(-h t - t^2/2) < 1e-330 beyond h t + t^2/2 = 760.
        let t_max = -h + (h * h + 1520.0).sqrt();
        p * power_moment(n, |t| (-t * (h + 0.5 * t)).exp(), t_max, &[])
    } else {
        let t_max = -h + 39.0;
        power_moment(n, |t| normal::pdf(h + t), t_max, &[-h])
    }
}
