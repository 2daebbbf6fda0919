//! Greenwood & Williamson's exponential summit heights, `phi(s) = e^-s`, `s >= 0`.

use super::quad::{is_half_integer, is_integer};
use super::HeightDistribution;
use crate::numeric::quadrature::integrate_pieces;
use crate::special::{gamma::gamma, normal};

/// Exponential summit heights (Greenwood & Williamson 1966):
/// `phi(s) = exp(-s)` for `s >= 0`, 0 below. The scale (mean = standard
/// deviation) is 1, so the surface's `sigma` (m) is the decay length, and
/// `h = d/sigma` is measured from the *lowest* summit (`s = 0`), not the mean.
///
/// `F_n(h) = Gamma(n+1) e^-h` for `h >= 0` (any `n >= 0`), which makes load,
/// area and count of Hertz asperities exactly proportional. For `h < 0`,
/// with `a = -h`: `F_n(h) = int_0^inf (s + a)^n e^-s ds = e^a Gamma(n+1, a)`
/// (upper incomplete gamma), evaluated as
/// - integer `n`: `n! sum_(k<=n) a^k/k!`;
/// - half-integer `n`: `G_(1/2) = e^a Gamma(1/2, a) = sqrt(2) R_0(sqrt(2a))`
///   (scaled Mills ratio, no cancellation) and `G_(s+1) = s G_s + a^s`;
/// - other `n`: adaptive quadrature (relative 1e-13).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Exponential;

impl Exponential {
    /// The unit exponential distribution.
    pub fn new() -> Self {
        Exponential
    }
}

impl HeightDistribution for Exponential {
    fn name(&self) -> &'static str {
        "exponential"
    }

    fn pdf(&self, s: f64) -> f64 {
        if s >= 0.0 {
            (-s).exp()
        } else if s.is_nan() {
            f64::NAN
        } else {
            0.0
        }
    }

    fn tail(&self, s: f64) -> f64 {
        if s.is_nan() {
            f64::NAN
        } else {
            (-s.max(0.0)).exp()
        }
    }

    fn support(&self) -> (f64, f64) {
        (0.0, f64::INFINITY)
    }

    fn moment_above(&self, n: f64, h: f64) -> f64 {
        if n.is_nan() || h.is_nan() || n < 0.0 {
            return f64::NAN;
        }
        if h >= 0.0 {
            let e = (-h).exp();
            return if e == 0.0 { 0.0 } else { gamma(n + 1.0) * e };
        }
        exp_moment_below_origin(n, -h)
    }

    fn quantile(&self, p: f64) -> f64 {
        if !(0.0..=1.0).contains(&p) {
            return f64::NAN;
        }
        -(-p).ln_1p()
    }

    fn quantile_upper(&self, q: f64) -> f64 {
        if !(0.0..=1.0).contains(&q) {
            return f64::NAN;
        }
        // P(S > s) = exp(-s)
        -q.ln()
    }

    fn numerical_support(&self, eps: f64) -> (f64, f64) {
        (0.0, -super::gaussian::clamp_eps(eps).ln())
    }

    fn closed_form_moment(&self, n: f64) -> bool {
        is_integer(n) || is_half_integer(n)
    }
}

/// `e^a Gamma(n+1, a) = int_0^inf (s + a)^n e^-s ds` for `a > 0`.
fn exp_moment_below_origin(n: f64, a: f64) -> f64 {
    if a == f64::INFINITY {
        return if n == 0.0 { 1.0 } else { f64::INFINITY };
    }
    if is_integer(n) {
        // n! sum_k a^k / k! = sum_k n!/k! a^k, Horner from the top.
        let m = n as u64;
        let mut v = 1.0;
        for k in (1..=m).rev() {
            v = 1.0 + v * a / k as f64;
        }
        return gamma(n + 1.0) * v;
    }
    if is_half_integer(n) {
        let mut s = 0.5;
        let mut g = std::f64::consts::SQRT_2 * normal::mills_ratio((2.0 * a).sqrt());
        // G_(s+1) = s G_s + a^s, up to s + 1 = n + 1.
        while s < n + 1.0 {
            g = s * g + a.powf(s);
            s += 1.0;
        }
        return g;
    }
    let f = |s: f64| (s + a).powf(n) * (-s).exp();
    let pts = [
        0.0, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0, 128.0, 256.0, 512.0, 800.0,
    ];
    integrate_pieces(f, &pts, &super::quad::FALLBACK).value
}
