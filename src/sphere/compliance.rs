//! Axisymmetric compliance matrix of an elastic half-space for a
//! piecewise-linear pressure on a non-uniform radial mesh ("overlapping
//! triangles", Johnson, *Contact Mechanics* §3.9; Greenwood 2009, appendix 1).
//!
//! Units: lengths in any unit, pressure `p`, displacement `u E* `, i.e. the
//! entries are `E* u_i / p_j` (a length). With the sphere scaling the
//! dimensionless displacement is `U = mu^2 C sigma_hat` (see `newton.rs`).
//!
//! A uniform pressure `p` on a disc of radius `s` displaces the surface at
//! radius `r` by `u = p D(r, s) / E*` (Johnson eq. 3.25), with
//!
//! ```text
//! D(r, s) = (4/pi) s E(r^2/s^2)                              r <= s
//! D(r, s) = (4/pi) r [E(s^2/r^2) - (1 - s^2/r^2) K(s^2/r^2)]  r >  s
//! ```
//!
//! (`K`, `E` in the parameter convention). `dD/ds` is the ring Green's
//! function, so for a pressure `p(s) = sum_j p_j phi_j(s)` (hat functions)
//! integration by parts gives `u(r_i) = sum_j C_ij p_j / E*` with
//! `C_ij = mean of D(r_i, .) over [s_j, s_j+1] - mean over [s_j-1, s_j]`. The
//! last node carries a half hat whose pressure drops to zero at the outer
//! radius: its right-hand mean is replaced by `D(r_i, s_last)`.
//!
//! `D(r, .)` has a logarithmically infinite slope at `s = r` (always a mesh
//! node). It is split exactly as `D = A(s) + B(s) ln|s - r|` with `A`, `B`
//! analytic, using the connection formulas of `K` and `E` at `m = 1`
//! (DLMF 19.12.1-2): with `q = 1 - m`,
//! `K(m) = analytic - K(q) ln(q)/pi`, `E(m) = analytic - (K(q) - E(q)) ln(q)/pi`.
//! Hence `B = -(4/pi^2) s (K(q) - E(q))` for `r < s` (`q = 1 - r^2/s^2`) and
//! `B = (4/pi^2) r (E(q) - (1-q) K(q))` for `r > s` (`q = 1 - s^2/r^2`);
//! `A` is integrated by Gauss–Legendre and `B ln|s - r|` by Gauss–Legendre
//! plus the Gauss rule for the weight `-ln t`. No offset, no truncation.

use super::quadrature::{gauss_legendre, gauss_log, Rule};
use crate::special::elliptic::{ellip_ke_comp, ellip_ke_comp_lanes};
use std::f64::consts::PI;

const FOUR_OVER_PI: f64 = 4.0 / PI;
const FOUR_OVER_PI2: f64 = 4.0 / (PI * PI);

/// `D(r, s)`: `E* u(r) / p` for a uniform pressure `p` on a disc of radius `s`.
pub fn disc(r: f64, s: f64) -> f64 {
    if s <= 0.0 {
        return 0.0;
    }
    if r <= s {
        // m = r^2/s^2, m1 = (s-r)(s+r)/s^2 (no cancellation)
        let m1 = (s - r) * (s + r) / (s * s);
        FOUR_OVER_PI * s * ellip_ke_comp(m1).1
    } else {
        let m1 = (r - s) * (r + s) / (r * r);
        let (k, e) = ellip_ke_comp(m1);
        FOUR_OVER_PI * r * (e - m1 * k)
    }
}

/// [`disc`] at four radii `s` (the elliptic integrals in lanes): the same
/// operations per radius, so the same bits.
fn disc_lanes(r: f64, s: &[f64; 4]) -> [f64; 4] {
    let m1 = s.map(|s| {
        if s <= 0.0 {
            1.0
        } else if r <= s {
            (s - r) * (s + r) / (s * s)
        } else {
            (r - s) * (r + s) / (r * r)
        }
    });
    let ke = ellip_ke_comp_lanes(&m1);
    std::array::from_fn(|l| {
        let (s, (k, e)) = (s[l], ke[l]);
        if s <= 0.0 {
            0.0
        } else if r <= s {
            FOUR_OVER_PI * s * e
        } else {
            FOUR_OVER_PI * r * (e - m1[l] * k)
        }
    })
}

/// `(A(s), B(s))` with `D(r, s) = A + B ln|s - r|`, for `s != r`, `r > 0`.
fn split(r: f64, s: f64) -> (f64, f64) {
    let d = disc(r, s);
    let b = if r < s {
        // (K(q), E(q)) with q = 1 - r^2/s^2: complementary parameter r^2/s^2.
        let (kq, eq) = ellip_ke_comp(r * r / (s * s));
        -FOUR_OVER_PI2 * s * (kq - eq)
    } else {
        let c = s * s / (r * r);
        let (kq, eq) = ellip_ke_comp(c);
        FOUR_OVER_PI2 * r * (eq - c * kq)
    };
    (d - b * (s - r).abs().ln(), b)
}

/// Quadrature rules, built once per assembly.
pub(crate) struct Rules {
    gl: [Rule; 4],
    log: Rule,
}

impl Rules {
    pub(crate) fn new() -> Self {
        Rules {
            gl: [
                gauss_legendre(4),
                gauss_legendre(6),
                gauss_legendre(10),
                gauss_legendre(16),
            ],
            log: gauss_log(),
        }
    }
}

/// `int_sa^sb D(r, s) ds` for a mesh node `r` (`r` is an endpoint or lies
/// outside `[sa, sb]`).
pub(crate) fn interval_integral(rules: &Rules, r: f64, sa: f64, sb: f64) -> f64 {
    let len = sb - sa;
    if r == 0.0 {
        // D(0, s) = 2 s
        return sb * sb - sa * sa;
    }
    if sa == 0.0 && r == sb {
        // D(r, .) is analytic at s = 0 but the split A, B is not (s^2 ln s):
        // plain Gauss on [0, r/2], the log split on [r/2, r].
        let half = 0.5 * sb;
        return interval_integral(rules, r, 0.0, half) + interval_integral(rules, r, half, sb);
    }
    if r == sa || r == sb {
        // Log-singular end: A by Gauss–Legendre; B ln|s-r| = B ln L + B ln t.
        let from_left = r == sa;
        let at = |t: f64| if from_left { r + len * t } else { r - len * t };
        let gl = &rules.gl[3];
        let (mut ia, mut ib) = (0.0, 0.0);
        for (x, w) in gl.x.iter().zip(&gl.w) {
            let (a, b) = split(r, at(*x));
            ia += w * a;
            ib += w * b;
        }
        let mut ilog = 0.0;
        for (x, w) in rules.log.x.iter().zip(&rules.log.w) {
            ilog += w * split(r, at(*x)).1;
        }
        return len * (ia + len.ln() * ib - ilog);
    }
    let dist = if r < sa { sa - r } else { r - sb };
    let ratio = dist / len;
    let rule = if ratio < 1.0 {
        &rules.gl[3]
    } else if ratio < 4.0 {
        &rules.gl[2]
    } else if ratio < 16.0 {
        &rules.gl[1]
    } else {
        &rules.gl[0]
    };
    // four nodes at a time (the rules' last group padded with its first
    // node), summed in the rule's order as one by one
    let mut sum = 0.0;
    for (xs, ws) in rule.x.chunks(4).zip(rule.w.chunks(4)) {
        let s: [f64; 4] = std::array::from_fn(|l| sa + len * xs[l.min(xs.len() - 1)]);
        let d = disc_lanes(r, &s);
        for (w, d) in ws.iter().zip(d) {
            sum += w * d;
        }
    }
    len * sum
}

/// The compliance matrix `C` (row-major, `n x n`) for nodes `r` (ascending,
/// `r[0] = 0`): `E* u(r_i) = sum_j C_ij p_j` for the piecewise-linear pressure
/// through `p_j` that drops to zero at `r[n-1]`. Rows are assembled in
/// parallel (rayon), each exactly as serially.
pub fn compliance_matrix(r: &[f64]) -> Vec<f64> {
    use rayon::prelude::*;
    let n = r.len();
    let rules = Rules::new();
    let mut c = vec![0.0; n * n];
    // rows are independent (bit-identical for any thread count)
    c.par_chunks_mut(n.max(1)).enumerate().for_each(|(i, row)| {
        let means: Vec<f64> = (0..n.saturating_sub(1))
            .map(|k| interval_integral(&rules, r[i], r[k], r[k + 1]) / (r[k + 1] - r[k]))
            .collect();
        for j in 0..n {
            let right = if j + 1 < n {
                means[j]
            } else {
                disc(r[i], r[j])
            };
            let left = if j > 0 { means[j - 1] } else { 0.0 };
            row[j] = right - left;
        }
    });
    c
}

/// `int phi_j(r) r dr` for the hat functions (the last a half hat): the load
/// of a piecewise-linear pressure is `2 pi sum_j W_j p_j`.
pub fn load_weights(r: &[f64]) -> Vec<f64> {
    let n = r.len();
    let mut w = vec![0.0; n];
    for k in 0..n.saturating_sub(1) {
        let len = r[k + 1] - r[k];
        // falling part of hat k, rising part of hat k+1
        w[k] += len * (2.0 * r[k] + r[k + 1]) / 6.0;
        w[k + 1] += len * (r[k] + 2.0 * r[k + 1]) / 6.0;
    }
    w
}

#[cfg(test)]
mod tests;
