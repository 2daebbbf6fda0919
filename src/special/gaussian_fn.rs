//! Greenwood–Williamson integrals of the standard normal,
//! `F_n(h) = int_h^inf (s-h)^n phi(s) ds`, for `n = 0, 1/2, 1, 3/2, 2, 5/2`.
//!
//! Method (relative error <= ~1e-15 for `h` in `[-5, 10]`, ~1e-14 out to
//! `h = 37`; see `tests/it/gaussian_fn.rs`):
//!
//! - `h >= 0`: `F_n = phi(h) R_n(h)` with the scaled integral
//!   `R_n(h) = int_0^inf t^n exp(-h t - t^2/2) dt
//!           = Gamma(n+1) exp(h^2/4) D_(-n-1)(h)` (parabolic cylinder `D`).
//!   The top two members of each family (`R_1, R_2` and `R_3/2, R_5/2`) are
//!   Chebyshev series on unit pieces of `[0, 20)` fitted at 40 digits by
//!   `tools/gen_gaussian_tables.py` (fit error < 2e-16); beyond 20 the
//!   asymptotic series `R_n ~ Gamma(n+1) h^-(n+1) sum_k (-1)^k (n+1)_(2k) /
//!   (k! (2h^2)^k)` (converged to 1e-17 in <= 12 terms). The lower members
//!   follow from the recurrence `F_(n+1) = n F_(n-1) - h F_n` run *downwards*,
//!   `R_(n-1) = (R_(n+1) + h R_n)/n`, a sum of positive terms: no
//!   cancellation (the upward direction loses `~h^2` digits).
//! - `h < 0`: integer family from `F_0 = 1 - Q(-h)` and the upward
//!   recurrence (all terms positive); half-integer family from Chebyshev
//!   pieces of `F_1/2, F_3/2` on `[-20, 0)` and, below `-20`, the asymptotic
//!   series `F_n(h) ~ sum_j C(n, 2j) (2j-1)!! |h|^(n-2j)` (error
//!   `~exp(-h^2/2)`, below 1e-17).
//! - `phi(h)` with an exact exponent ([`normal::pdf`]); past its underflow
//!   (`h ~ 38.6`) every `F_n` is 0. `h = -inf` gives `F_0 = 1`, others `inf`.

use super::gaussian_tables::{NEG_F12, NEG_F32};
use super::normal;
#[cfg(test)]
use super::scaled::TABLE_HI;
use super::scaled::{half_top, integer_top};
use crate::numeric::chebyshev::piecewise;

/// Lower end of the Chebyshev pieces for `h < 0`.
const TABLE_LO: f64 = -20.0;

/// The orders with closed forms here.
pub const CLOSED_ORDERS: [f64; 6] = [0.0, 0.5, 1.0, 1.5, 2.0, 2.5];

/// Whether [`gaussian_fn`] has a closed form for order `n`.
pub fn has_closed_form(n: f64) -> bool {
    CLOSED_ORDERS.contains(&n)
}

/// `F_n(h)` for `n` in [`CLOSED_ORDERS`], `None` for other `n`. NaN only for
/// NaN `h`; 0 where `phi(h)` underflows; `F_0(-inf) = 1`, other orders `inf`
/// there.
#[inline]
pub fn gaussian_fn(n: f64, h: f64) -> Option<f64> {
    if h.is_nan() {
        return has_closed_form(n).then_some(f64::NAN);
    }
    let v = if n == 0.0 {
        f0(h)
    } else if n == 1.0 {
        f1(h)
    } else if n == 1.5 {
        f3half(h)
    } else if n == 0.5 {
        f_half(h)
    } else if n == 2.0 {
        f2(h)
    } else if n == 2.5 {
        f5half(h)
    } else {
        return None;
    };
    Some(v)
}

/// For `h < 0`: `(phi(h), F_0(h))` with `F_0 = 1 - phi(a) R_0(a)`, `a = -h`.
#[inline]
fn neg_integer_base(h: f64) -> (f64, f64) {
    let a = -h;
    let p = normal::pdf(h);
    if p == 0.0 {
        return (0.0, 1.0);
    }
    let (r1, r2) = integer_top(a);
    (p, 1.0 - p * (a * r1 + r2))
}

/// `F_0(h) = Q(h)`.
fn f0(h: f64) -> f64 {
    normal::tail(h)
}

/// `F_1(h) = phi(h) R_1(h)`; for `h < 0`, `phi + |h| F_0`.
fn f1(h: f64) -> f64 {
    if h >= 0.0 {
        if h == f64::INFINITY {
            return 0.0;
        }
        normal::pdf(h) * integer_top(h).0
    } else {
        let (p, q) = neg_integer_base(h);
        p - h * q
    }
}

/// `F_2(h) = phi(h) R_2(h)`; for `h < 0`, `F_0 + |h| F_1`.
fn f2(h: f64) -> f64 {
    if h >= 0.0 {
        if h == f64::INFINITY {
            return 0.0;
        }
        normal::pdf(h) * integer_top(h).1
    } else {
        let (p, q) = neg_integer_base(h);
        q - h * (p - h * q)
    }
}

/// `F_1/2 = phi (R_5/2 + h R_3/2)/(3/2)` for `h >= 0`; Chebyshev pieces or
/// the asymptotic series below 0.
fn f_half(h: f64) -> f64 {
    if h >= 0.0 {
        if h == f64::INFINITY {
            return 0.0;
        }
        let (r32, r52) = half_top(h);
        normal::pdf(h) * (h * r32 + r52) / 1.5
    } else if h >= TABLE_LO {
        piecewise(&NEG_F12, TABLE_LO, h)
    } else {
        let a = -h;
        neg_asymptotic(0.5, a, a.sqrt())
    }
}

/// `F_3/2 = phi R_3/2`.
fn f3half(h: f64) -> f64 {
    if h >= 0.0 {
        if h == f64::INFINITY {
            return 0.0;
        }
        normal::pdf(h) * half_top(h).0
    } else if h >= TABLE_LO {
        piecewise(&NEG_F32, TABLE_LO, h)
    } else {
        let a = -h;
        neg_asymptotic(1.5, a, a * a.sqrt())
    }
}

/// `F_5/2 = phi R_5/2`; for `h < 0`, `1.5 F_1/2 + |h| F_3/2`.
fn f5half(h: f64) -> f64 {
    if h >= 0.0 {
        if h == f64::INFINITY {
            return 0.0;
        }
        normal::pdf(h) * half_top(h).1
    } else if h >= TABLE_LO {
        let f12 = piecewise(&NEG_F12, TABLE_LO, h);
        let f32 = piecewise(&NEG_F32, TABLE_LO, h);
        1.5 * f12 - h * f32
    } else {
        let a = -h;
        neg_asymptotic(2.5, a, a * a * a.sqrt())
    }
}

/// `F_nu(-a) ~ sum_j C(nu, 2j) (2j-1)!! a^(nu-2j)` for `a >= 20` with
/// `lead = a^nu`: the moments of `(a + S)^nu`; the neglected part is
/// `O(exp(-a^2/2))`.
fn neg_asymptotic(nu: f64, a: f64, lead: f64) -> f64 {
    if a > 1e100 || !lead.is_finite() {
        return lead;
    }
    let x = 1.0 / (a * a);
    let (mut term, mut sum) = (1.0_f64, 1.0_f64);
    let mut j = 0.0;
    while j < 60.0 {
        // t_(j+1)/t_j = (nu-2j)(nu-2j-1) / (2j+2) / a^2
        let next = term * (nu - 2.0 * j) * (nu - 2.0 * j - 1.0) / (2.0 * j + 2.0) * x;
        if next.abs() >= term.abs() {
            break;
        }
        term = next;
        sum += term;
        if term.abs() < 1e-17 * sum {
            break;
        }
        j += 1.0;
    }
    lead * sum
}

/// Reference values `F_n(0) = 2^((n-1)/2) Gamma((n+1)/2) / sqrt(2 pi)`.
pub fn gaussian_fn_at_zero(n: f64) -> f64 {
    2f64.powf(0.5 * (n - 1.0)) * super::gamma::gamma(0.5 * (n + 1.0)) * normal::FRAC_1_SQRT_2PI
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pieces_join_continuously() {
        for edge in 1..20 {
            let h = edge as f64;
            for n in CLOSED_ORDERS {
                let below = gaussian_fn(n, h - 1e-12).unwrap();
                let at = gaussian_fn(n, h).unwrap();
                let slope = n.max(1.0) * 1e-12 * (1.0 + h) * below;
                assert!(
                    (below - at).abs() <= 4.0 * slope + 1e-15 * at,
                    "n {n} h {h}"
                );
            }
        }
    }

    #[test]
    fn values_at_zero_match_gamma_formula() {
        for n in CLOSED_ORDERS {
            let v = gaussian_fn(n, 0.0).unwrap();
            let z = gaussian_fn_at_zero(n);
            assert!((v / z - 1.0).abs() < 1e-14, "n {n}: {v} vs {z}");
        }
    }

    #[test]
    fn asymptotic_regions_join() {
        for n in CLOSED_ORDERS {
            for h in [TABLE_HI, TABLE_LO] {
                let lo = gaussian_fn(n, h - 1e-9).unwrap();
                let hi = gaussian_fn(n, h + 1e-9).unwrap();
                assert!(
                    (lo / hi - 1.0).abs() < 1e-7 * (1.0 + h.abs()),
                    "n {n} h {h}"
                );
            }
        }
    }

    #[test]
    fn infinities_and_nan() {
        for n in CLOSED_ORDERS {
            assert_eq!(gaussian_fn(n, f64::INFINITY), Some(0.0));
            assert_eq!(gaussian_fn(n, 40.0), Some(0.0));
            assert!(gaussian_fn(n, f64::NAN).unwrap().is_nan());
            let v = gaussian_fn(n, f64::NEG_INFINITY).unwrap();
            assert!(v == 1.0 || v == f64::INFINITY, "n {n}: {v}");
            assert!(!gaussian_fn(n, -1e200).unwrap().is_nan());
        }
        assert_eq!(gaussian_fn(3.0, 1.0), None);
    }
}
