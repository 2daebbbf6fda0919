//! Quadrature fallback for `F_n` where no closed form exists.

use crate::numeric::quadrature::{integrate_pieces, QuadOptions};

/// Relative tolerance of the fallback quadrature.
pub(crate) const FALLBACK_REL_TOL: f64 = 1e-13;

/// The fallback quadrature's options: [`FALLBACK_REL_TOL`] relative to
/// `|int f|`, no absolute tolerance, at most 1000 panels.
pub(crate) const FALLBACK: QuadOptions = QuadOptions {
    rel_tol: FALLBACK_REL_TOL,
    abs_tol: 0.0,
    max_intervals: 1000,
    relative_to_magnitude: false,
};

/// `int_0^t_max t^n g(t) dt` for `n >= 0` by adaptive Gauss–Kronrod in
/// `u = sqrt(t)` (`dt = 2u du`, integrand `2 u^(2n+1) g(u^2)`), which removes
/// the `t^n` endpoint singularity for half-integer `n` and softens it
/// otherwise. `g` must be smooth on `(0, t_max)` apart from the listed
/// `breaks` (values of `t`). Panels: a geometric ladder towards 0.
pub(crate) fn power_moment<G: Fn(f64) -> f64>(n: f64, g: G, t_max: f64, breaks: &[f64]) -> f64 {
    if !(t_max > 0.0) {
        return 0.0;
    }
    let u_max = t_max.sqrt();
    let f = |u: f64| {
        if u <= 0.0 {
            return 0.0;
        }
        2.0 * u.powf(2.0 * n + 1.0) * g(u * u)
    };
    let mut pts = vec![0.0, u_max];
    for frac in [1.0 / 64.0, 1.0 / 16.0, 0.125, 0.25, 0.5] {
        pts.push(u_max * frac);
    }
    for &b in breaks {
        if b > 0.0 && b < t_max {
            pts.push(b.sqrt());
        }
    }
    pts.sort_by(f64::total_cmp);
    pts.dedup();
    integrate_pieces(f, &pts, &FALLBACK).value
}

/// Whether `n` is a non-negative integer.
pub(crate) fn is_integer(n: f64) -> bool {
    n >= 0.0 && n == n.floor() && n < 1e9
}

/// Whether `n` is a non-negative half-integer (`k + 1/2`).
pub(crate) fn is_half_integer(n: f64) -> bool {
    n > 0.0 && is_integer(n - 0.5)
}

/// Binomial coefficient `C(n, j)` for integer `n >= j >= 0` (as f64).
pub(crate) fn binomial(n: u32, j: u32) -> f64 {
    let mut c = 1.0;
    for i in 0..j {
        c = c * f64::from(n - i) / f64::from(i + 1);
    }
    c
}
