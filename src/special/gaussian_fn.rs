//! Greenwood–Williamson integrals of the standard normal,
//! `F_n(h) = int_h^inf (s-h)^n phi(s) ds`, for `n = 0, 1/2, 1, 3/2, 2, 5/2`.
//!
//! Method (relative error <= ~1e-15 for `h` in `[-5, 10]`, ~1e-14 out to
//! `h = 37`; see `tests/gaussian_fn.rs`):
//!
//! - `h >= 0`: `F_n = phi(h) R_n(h)` with the scaled integral
//!   `R_n(h) = int_0^inf t^n exp(-h t - t^2/2) dt
//!           = Gamma(n+1) exp(h^2/4) D_(-n-1)(h)` (parabolic cylinder `D`).
//!   The top two members of each family (`R_1, R_2` and `R_3/2, R_5/2`) are
//!   Chebyshev series on unit pieces of `[0, 12)` fitted at 40 digits by
//!   `tools/gen_gaussian_tables.py` (fit error < 2e-16); beyond 12 the
//!   asymptotic series `R_n ~ Gamma(n+1) h^-(n+1) sum_k (-1)^k (n+1)_(2k) /
//!   (k! (2h^2)^k)` (converged to 1e-17 in <= 25 terms). The lower members
//!   follow from the recurrence `F_(n+1) = n F_(n-1) - h F_n` run *downwards*,
//!   `R_(n-1) = (R_(n+1) + h R_n)/n`, a sum of positive terms: no
//!   cancellation (the upward direction loses `~h^2` digits).
//! - `h < 0`: integer family from `F_0 = 1 - Q(-h)` and the upward
//!   recurrence (all terms positive); half-integer family from Chebyshev
//!   pieces of `F_1/2, F_3/2` on `[-9, 0)` and, below `-9`, the asymptotic
//!   series `F_n(h) ~ sum_j C(n, 2j) (2j-1)!! |h|^(n-2j)` (error
//!   `~exp(-h^2/2)`, below 1e-17).
//! - `phi(h)` with an exact exponent ([`normal::pdf`]); past its underflow
//!   (`h ~ 38.6`) every `F_n` is 0. `h = -inf` gives `F_0 = 1`, others `inf`.

use super::chebyshev::piecewise;
use super::gaussian_tables::{NEG_F12, NEG_F32, POS_R1, POS_R2, POS_R32, POS_R52};
use super::normal;

/// Upper end of the Chebyshev pieces for `h >= 0`.
pub(crate) const TABLE_HI: f64 = 12.0;
/// Lower end of the Chebyshev pieces for `h < 0`.
const TABLE_LO: f64 = -9.0;
/// `Gamma(5/2)`, `Gamma(7/2)`.
const GAMMA_5_2: f64 = 1.329_340_388_179_137_020_473_625_612_506;
const GAMMA_7_2: f64 = 3.323_350_970_447_842_551_184_064_031_264;

/// The orders with closed forms here.
pub const CLOSED_ORDERS: [f64; 6] = [0.0, 0.5, 1.0, 1.5, 2.0, 2.5];

/// Whether [`gaussian_fn`] has a closed form for order `n`.
pub fn has_closed_form(n: f64) -> bool {
    CLOSED_ORDERS.contains(&n)
}

/// `F_n(h)` for `n` in [`CLOSED_ORDERS`], `None` for other `n`. NaN only for
/// NaN `h`.
pub fn gaussian_fn(n: f64, h: f64) -> Option<f64> {
    let i = CLOSED_ORDERS.iter().position(|&c| c == n)?;
    Some(if i % 2 == 0 {
        integer_family(h)[i / 2]
    } else {
        half_family(h)[i / 2]
    })
}

/// `(R_1(h), R_2(h))` from the Chebyshev pieces, `0 <= h < 12`.
#[inline]
pub(crate) fn scaled_integer_top(h: f64) -> (f64, f64) {
    (piecewise(&POS_R1, 0.0, h), piecewise(&POS_R2, 0.0, h))
}

/// Asymptotic series of `R_nu(h)` for large `h` (>= 12 here), with
/// `gamma_nu1 = Gamma(nu+1)`: relative error < 1e-16 for `h >= 12`,
/// `nu <= 5/2`.
#[inline]
pub(crate) fn r_asymptotic(nu: f64, gamma_nu1: f64, h: f64) -> f64 {
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
    gamma_nu1 * sum / h.powf(nu + 1.0)
}

/// `[F_0, F_1, F_2](h)`.
#[inline]
pub fn integer_family(h: f64) -> [f64; 3] {
    if h.is_nan() {
        return [f64::NAN; 3];
    }
    if h >= 0.0 {
        if h == f64::INFINITY {
            return [0.0; 3];
        }
        let (r1, r2) = if h < TABLE_HI {
            scaled_integer_top(h)
        } else {
            (r_asymptotic(1.0, 1.0, h), r_asymptotic(2.0, 2.0, h))
        };
        let r0 = h.mul_add(r1, r2);
        let p = normal::pdf(h);
        [p * r0, p * r1, p * r2]
    } else {
        if h == f64::NEG_INFINITY {
            return [1.0, f64::INFINITY, f64::INFINITY];
        }
        let a = -h;
        let p = normal::pdf(h);
        let f0 = 1.0 - normal::tail(a);
        let f1 = a.mul_add(f0, p);
        let f2 = a.mul_add(f1, f0);
        [f0, f1, f2]
    }
}

/// `[F_1/2, F_3/2, F_5/2](h)`.
#[inline]
pub fn half_family(h: f64) -> [f64; 3] {
    if h.is_nan() {
        return [f64::NAN; 3];
    }
    if h >= 0.0 {
        if h == f64::INFINITY {
            return [0.0; 3];
        }
        let (r32, r52) = if h < TABLE_HI {
            (piecewise(&POS_R32, 0.0, h), piecewise(&POS_R52, 0.0, h))
        } else {
            (
                r_asymptotic(1.5, GAMMA_5_2, h),
                r_asymptotic(2.5, GAMMA_7_2, h),
            )
        };
        let r12 = h.mul_add(r32, r52) / 1.5;
        let p = normal::pdf(h);
        [p * r12, p * r32, p * r52]
    } else if h >= TABLE_LO {
        let f12 = piecewise(&NEG_F12, TABLE_LO, h);
        let f32 = piecewise(&NEG_F32, TABLE_LO, h);
        [f12, f32, (-h).mul_add(f32, 1.5 * f12)]
    } else {
        let a = -h;
        [
            neg_asymptotic(0.5, a),
            neg_asymptotic(1.5, a),
            neg_asymptotic(2.5, a),
        ]
    }
}

/// `F_nu(-a) ~ sum_j C(nu, 2j) (2j-1)!! a^(nu-2j)` for `a >= 9`: the
/// moments of `(a + S)^nu`; the neglected part is `O(exp(-a^2/2))`.
fn neg_asymptotic(nu: f64, a: f64) -> f64 {
    let lead = a.powf(nu);
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
        for edge in 1..12 {
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
