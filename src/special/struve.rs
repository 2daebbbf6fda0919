//! Struve functions `H0(x)`, `H1(x)` of real argument.
//!
//! `H_nu(x) = sum_k (-1)^k (x/2)^(2k+nu+1) / (Gamma(k+3/2) Gamma(k+nu+3/2))`
//! (Abramowitz & Stegun 12.1.3). `H0` is odd, `H1` even. Three regimes:
//! - `|x| < 2`: the power series (terms fall at once, no cancellation; relative
//!   accuracy near 1 ulp, also as `x -> 0` where `H0 ~ 2x/pi`, `H1 ~ 2x^2/(3 pi)`);
//! - `2 <= |x| < 50`: Chebyshev series on unit pieces (`struve_tables.rs`, made by
//!   `tools/gen_struve_tables.py` from mpmath at 40 digits; fit error below 1.2e-16);
//! - `|x| >= 50`: `H_nu = Y_nu + (1/pi) sum_k Gamma(k+1/2)/Gamma(nu+1/2-k) (x/2)^(nu-2k-1)`
//!   (A&S 12.1.29) with Hankel's expansion of `Y_nu` (A&S 9.2.2, 9.2.6, 9.2.10); both
//!   series are summed until their terms fall below 1e-17 of the result, which they do
//!   long before their smallest term (`~ e^-x` and `~ e^-2x`).
//!
//! Measured against mpmath (`tests/it/struve.rs`, 0 <= x <= 1e6): absolute error below
//! 1e-15 everywhere, relative below 1e-14 wherever `|H| > 1e-3`.

use super::struve_tables::{H0_TABLE, H1_TABLE};
use crate::numeric::chebyshev::piecewise;
use std::f64::consts::{FRAC_1_SQRT_2, PI};

/// Below this `|x|` the power series is used.
const SERIES_MAX: f64 = 2.0;
/// From this `|x|` on the asymptotic series are used.
const ASYMPTOTIC_MIN: f64 = 50.0;

/// Struve function `H0(x)` (odd in `x`). Infallible; NaN in, NaN out.
pub fn struve_h0(x: f64) -> f64 {
    let ax = x.abs();
    let v = if ax < SERIES_MAX {
        series(ax, 0)
    } else if ax < ASYMPTOTIC_MIN {
        piecewise(&H0_TABLE, SERIES_MAX, ax)
    } else {
        asymptotic(ax).0
    };
    if x < 0.0 {
        -v
    } else {
        v
    }
}

/// Struve function `H1(x)` (even in `x`). Infallible; NaN in, NaN out.
pub fn struve_h1(x: f64) -> f64 {
    let ax = x.abs();
    if ax < SERIES_MAX {
        series(ax, 1)
    } else if ax < ASYMPTOTIC_MIN {
        piecewise(&H1_TABLE, SERIES_MAX, ax)
    } else {
        asymptotic(ax).1
    }
}

/// `(H0(x), H1(x))` at once (one `sin`/`cos` pair for large `x`).
pub fn struve_h0_h1(x: f64) -> (f64, f64) {
    let ax = x.abs();
    let (h0, h1) = if ax < SERIES_MAX {
        (series(ax, 0), series(ax, 1))
    } else if ax < ASYMPTOTIC_MIN {
        (
            piecewise(&H0_TABLE, SERIES_MAX, ax),
            piecewise(&H1_TABLE, SERIES_MAX, ax),
        )
    } else {
        asymptotic(ax)
    };
    (if x < 0.0 { -h0 } else { h0 }, h1)
}

/// Power series of `H_nu`, `nu` in {0, 1}, for `0 <= x < 2`: first term
/// `(x/2)^(nu+1) / (Gamma(3/2) Gamma(nu+3/2))`, ratio
/// `-(x/2)^2 / ((k+3/2)(k+nu+3/2))`.
fn series(x: f64, nu: u32) -> f64 {
    let z = 0.5 * x;
    let z2 = z * z;
    let n = f64::from(nu);
    // Gamma(3/2)^2 = pi/4; Gamma(3/2) Gamma(5/2) = 3 pi/8.
    let mut term = if nu == 0 {
        z * 4.0 / PI
    } else {
        z2 * 8.0 / (3.0 * PI)
    };
    let mut sum = term;
    let mut k = 0.0;
    while term.abs() > 1e-17 * sum.abs() && k < 40.0 {
        term *= -z2 / ((k + 1.5) * (k + n + 1.5));
        sum += term;
        k += 1.0;
    }
    sum
}

/// `(H0(x), H1(x))` for `x >= 50` from `H_nu - Y_nu` (A&S 12.1.29) and Hankel's
/// expansion `Y_nu = sqrt(2/(pi x)) (P sin chi + Q cos chi)`, `chi = x - (nu/2 + 1/4) pi`.
/// Multiplications only in the loops (divisions cost ~20 cycles each).
fn asymptotic(x: f64) -> (f64, f64) {
    let (s, c) = x.sin_cos();
    let inv = 1.0 / x;
    let ((p0, q0), (p1, q1)) = hankel_pq(inv);
    let amp = (2.0 / PI * inv).sqrt();
    // chi_0 = x - pi/4, chi_1 = x - 3 pi/4.
    let (s0, c0) = (FRAC_1_SQRT_2 * (s - c), FRAC_1_SQRT_2 * (s + c));
    let (s1, c1) = (-FRAC_1_SQRT_2 * (s + c), FRAC_1_SQRT_2 * (s - c));
    let y0 = amp * (p0 * s0 + q0 * c0);
    let y1 = amp * (p1 * s1 + q1 * c1);
    let (d0, d1) = struve_minus_y(inv);
    (y0 + d0, y1 + d1)
}

/// `1/(8k)` for `k = 1..=24`.
const INV_8K: [f64; 24] = {
    let mut t = [0.0; 24];
    let mut k = 0;
    while k < 24 {
        t[k] = 1.0 / (8.0 * (k + 1) as f64);
        k += 1;
    }
    t
};

/// Hankel's `(P_0, Q_0)`, `(P_1, Q_1)` at `1/x` (`x >= 50`):
/// `a_k = a_(k-1) (4 nu^2 - (2k-1)^2)/(8k x)`, `P = sum (-1)^k a_2k`, `Q = sum (-1)^k a_(2k+1)`
/// (terms fall below 1e-17 by k = 14 at x = 50).
fn hankel_pq(inv: f64) -> ((f64, f64), (f64, f64)) {
    let (mut p0, mut q0, mut p1, mut q1) = (1.0, 0.0, 1.0, 0.0);
    let (mut a0, mut a1) = (1.0, 1.0);
    for (k, &i8k) in INV_8K.iter().enumerate() {
        let k = k + 1;
        let odd = (2 * k - 1) as f64;
        let f = i8k * inv;
        a0 *= -odd * odd * f;
        a1 *= (4.0 - odd * odd) * f;
        // sign (-1)^floor(k/2) for both series
        let (t0, t1) = if (k / 2) % 2 == 0 {
            (a0, a1)
        } else {
            (-a0, -a1)
        };
        if k % 2 == 1 {
            q0 += t0;
            q1 += t1;
        } else {
            p0 += t0;
            p1 += t1;
        }
        if a0.abs().max(a1.abs()) < 1e-17 {
            break;
        }
    }
    ((p0, q0), (p1, q1))
}

/// `(H0 - Y0, H1 - Y1)` at `1/x` for large `x` (A&S 12.1.29): for `nu = 0` terms from
/// `2/(pi x)`, ratio `-(2k+1)^2/x^2`; for `nu = 1` from `2/pi`, ratio `(1 - 4k^2)/x^2`.
fn struve_minus_y(inv: f64) -> (f64, f64) {
    let i2 = inv * inv;
    let (mut t0, mut t1) = (2.0 / PI * inv, 2.0 / PI);
    let (mut s0, mut s1) = (t0, t1);
    for k in 0..30 {
        let kf = f64::from(k);
        t0 *= -(2.0 * kf + 1.0) * (2.0 * kf + 1.0) * i2;
        t1 *= (1.0 - 4.0 * kf * kf) * i2;
        s0 += t0;
        s1 += t1;
        if t0.abs() < 1e-17 * s0.abs() && t1.abs() < 1e-17 * s1.abs() {
            break;
        }
    }
    (s0, s1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn symmetry_and_small_argument_limits() {
        for x in [0.3, 1.9, 7.5, 49.9, 60.0, 1e4] {
            assert_eq!(struve_h0(-x), -struve_h0(x));
            assert_eq!(struve_h1(-x), struve_h1(x));
            let (a, b) = struve_h0_h1(-x);
            assert_eq!((a, b), (struve_h0(-x), struve_h1(-x)));
        }
        let x = 1e-8;
        assert!((struve_h0(x) / (2.0 * x / PI) - 1.0).abs() < 1e-15);
        assert!((struve_h1(x) / (2.0 * x * x / (3.0 * PI)) - 1.0).abs() < 1e-15);
        assert_eq!(struve_h0(0.0), 0.0);
        assert_eq!(struve_h1(0.0), 0.0);
        assert!(struve_h0(f64::NAN).is_nan());
    }

    #[test]
    fn regimes_join_continuously() {
        for edge in [SERIES_MAX, ASYMPTOTIC_MIN] {
            let (lo, hi) = (edge * (1.0 - 1e-15), edge);
            assert!((struve_h0(lo) - struve_h0(hi)).abs() < 5e-15);
            assert!((struve_h1(lo) - struve_h1(hi)).abs() < 5e-15);
        }
    }
}
