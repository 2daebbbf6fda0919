//! The scaled repeated integrals of the standard normal for `h >= 0`,
//! `R_n(h) = F_n(h) / phi(h) = int_0^inf t^n exp(-h t - t^2/2) dt`: the
//! layer below both the normal tail ([`super::normal`]: `Q = phi R_0`) and
//! the Greenwood–Williamson integrals ([`super::gaussian_fn`]). Chebyshev
//! pieces on `[0, 20)` (fitted at 40 digits by
//! `tools/gen_gaussian_tables.py`, fit error < 2e-16) and, beyond, the
//! asymptotic series `R_n ~ Gamma(n+1) h^-(n+1) sum_k (-1)^k (n+1)_(2k) /
//! (k! (2h^2)^k)`.

use super::gaussian_tables::{POS_R1, POS_R2, POS_R32, POS_R52};
use crate::numeric::chebyshev::piecewise;

/// Upper end of the Chebyshev pieces for `h >= 0`.
pub(crate) const TABLE_HI: f64 = 20.0;
/// `Gamma(5/2)`, `Gamma(7/2)`.
const GAMMA_5_2: f64 = 1.329_340_388_179_137_020_473_625_612_506;
const GAMMA_7_2: f64 = 3.323_350_970_447_842_551_184_064_031_264;

/// `(R_1(h), R_2(h))` from the Chebyshev pieces, `0 <= h < TABLE_HI`.
#[inline]
pub(crate) fn scaled_integer_top(h: f64) -> (f64, f64) {
    (piecewise(&POS_R1, 0.0, h), piecewise(&POS_R2, 0.0, h))
}

/// `(R_1(h), R_2(h))`, `0 <= h < inf`.
#[inline]
pub(crate) fn integer_top(h: f64) -> (f64, f64) {
    if h < TABLE_HI {
        scaled_integer_top(h)
    } else {
        let h2 = h * h;
        (
            r_asymptotic(1.0, 1.0, h, h2),
            r_asymptotic(2.0, 2.0, h, h2 * h),
        )
    }
}

/// `(R_3/2(h), R_5/2(h))`, `0 <= h < inf`.
#[inline]
pub(crate) fn half_top(h: f64) -> (f64, f64) {
    if h < TABLE_HI {
        (piecewise(&POS_R32, 0.0, h), piecewise(&POS_R52, 0.0, h))
    } else {
        let p = h * h * h.sqrt();
        (
            r_asymptotic(1.5, GAMMA_5_2, h, p),
            r_asymptotic(2.5, GAMMA_7_2, h, p * h),
        )
    }
}

/// Asymptotic series of `R_nu(h)` for large `h` (>= 20 here), with
/// `gamma_nu1 = Gamma(nu+1)` and `h_pow = h^(nu+1)`: relative error < 1e-17
/// for `h >= 20`, `nu <= 5/2` (about 11 terms at 20, 6 at 37).
#[inline]
pub(crate) fn r_asymptotic(nu: f64, gamma_nu1: f64, h: f64, h_pow: f64) -> f64 {
    let x = 0.5 / (h * h);
    let (mut term, mut sum) = (1.0_f64, 1.0_f64);
    let mut k = 0.0;
    while k < 40.0 {
        let a = nu + 1.0 + 2.0 * k;
        term *= -a * (a + 1.0) / (k + 1.0) * x;
        sum += term;
        if term.abs() < 1e-17 * sum {
            break;
        }
        k += 1.0;
    }
    gamma_nu1 * sum / h_pow
}
