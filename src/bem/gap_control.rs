//! Mean-gap control on a periodic map, with or without adhesion:
//! constrained conjugate gradients in the gap (Rey, Anciaux & Molinari
//! 2017).
//!
//! Unknown: the gap `g >= 0` with imposed mean `g_mean`; the displacement
//! is `u = g + h`. The energy per pixel area is
//! `E(g) = (1/2) u . K^-1 u + sum_i phi(g_i)` with the exponential
//! interaction `phi(g) = -w exp(-g/rho)` (`w` the work of adhesion, J/m^2,
//! `rho` its range, m; `phi = 0` without adhesion). Its gradient is
//! `q = K^-1 u + phi'(g)`, `phi'(g) = (w/rho) exp(-g/rho)`; at the minimum
//! `q` equals the same constant `-p_mean` on the free set `F = {g > 0}`
//! (the mean pressure, the multiplier of the mean-gap constraint), and
//! `q + p_mean >= 0` (the contact reaction) where `g = 0`. One iteration
//! mirrors Polonsky & Keer's with the roles of gap and pressure swapped:
//! 1. `q -= mean_F q`; `G = sum_F q^2`; `t = q + delta (G/G_old) t` on `F`;
//! 2. `r = K^-1 t` minus its mean over `F`; the step `tau = sum_F q t /
//!    (sum_F r t + sum_F phi''(g) t^2)` (the curvature of the adhesion
//!    included while the total stays positive, the elastic part alone
//!    otherwise);
//! 3. `g -= tau t` on `F`, `g = max(g, 0)`; pixels in contact whose
//!    reaction is negative (`g = 0`, `q < 0`) are freed with `g = -tau q`;
//! 4. `g` is rescaled to the imposed mean.
//!
//! Convergence criterion (explicit), on the iterate before its update:
//! `residual = sqrt((sum_F q^2 + sum_{not F} min(q, 0)^2)/N) / p_ref`,
//! `p_ref = rms(K^-1 h)` the RMS pressure of full contact (`E* g_rms/2`).

use super::operator::HalfSpace;
use super::{Options, Solution};
use crate::error::{Error, Result};
use crate::numeric::roots::brent;
use rayon::prelude::*;

/// The exponential interaction of Rey, Anciaux & Molinari (2017).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Exponential {
    /// Work of adhesion `w` (J/m^2).
    pub energy: f64,
    /// Range `rho` (m).
    pub range: f64,
}

fn sums<F: Fn(usize) -> [f64; 4] + Sync>(n: usize, f: F) -> [f64; 4] {
    (0..n)
        .into_par_iter()
        .with_min_len(4096)
        .fold(
            || [0.0; 4],
            |mut a, i| {
                let v = f(i);
                for k in 0..4 {
                    a[k] += v[k];
                }
                a
            },
        )
        .reduce(
            || [0.0; 4],
            |a, b| [a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]],
        )
}

/// The rigid-body start: `g = max(c - h, 0)` with `c` such that the mean is
/// `g_mean`, by Brent's method ([`brent`]) to a few ulps of `c`. The mean
/// `m(c) = mean max(c - h, 0)` increases with `c` and lies between
/// `c - min h` (capped below by 0) and `c - mean h`, so
/// `m(min h + g_mean) <= g_mean <= m(mean h + g_mean)` brackets `c`.
pub(crate) fn rigid_gap(h: &[f64], g_mean: f64) -> Vec<f64> {
    let n = h.len() as f64;
    let mean_at = |c: f64| h.iter().map(|v| (c - v).max(0.0)).sum::<f64>() / n;
    let hmin = h.iter().cloned().fold(f64::INFINITY, f64::min);
    let hmax = h.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    let hmean = h.iter().sum::<f64>() / n;
    let (lo, hi) = (hmin + g_mean, hmean + g_mean);
    let xtol = 4.0 * f64::EPSILON * (hmax - hmin + g_mean);
    // Without a sign change (no pixel clipped: m(hi) = g_mean to rounding)
    // the upper end is the answer.
    let c = brent(|c| mean_at(c) - g_mean, lo, hi, xtol).unwrap_or(hi);
    h.iter().map(|v| (c - v).max(0.0)).collect()
}

/// Solves at mean gap `g_mean > 0` from `warm` (a previous gap field,
/// rescaled) or the rigid-body gap.
///
/// # Errors
/// [`Error::NoConvergence`] after `options.max_iterations` (unless
/// `options.allow_unconverged`: the last iterate, flagged).
// Over 100 lines, kept whole: one conjugate-gradient loop on the gap whose
// projection, step and convergence tests share the same dozen locals.
pub(crate) fn solve_gap(
    op: &HalfSpace,
    h: &[f64],
    p_ref: f64,
    g_mean: f64,
    adhesion: Option<Exponential>,
    options: &Options,
    warm: Option<&[f64]>,
) -> Result<Solution> {
    let n = h.len();
    let nf = n as f64;
    let mut g: Vec<f64> = match warm {
        Some(w) if w.iter().sum::<f64>() > 0.0 => {
            let s = g_mean * nf / w.iter().sum::<f64>();
            w.iter().map(|v| v * s).collect()
        }
        _ => rigid_gap(h, g_mean),
    };
    let (w, rho) = adhesion.map_or((0.0, 1.0), |a| (a.energy, a.range));
    let dphi = |g: f64| {
        if w > 0.0 {
            w / rho * (-g / rho).exp()
        } else {
            0.0
        }
    };
    let mut u = vec![0.0; n];
    let mut q = vec![0.0; n];
    let mut t = vec![0.0; n];
    let mut r = vec![0.0; n];
    let (mut g_old, mut delta) = (1.0, false);
    let mut residual = f64::INFINITY;
    for it in 0..=options.max_iterations {
        crate::cancel::check()?;
        u.par_iter_mut()
            .zip(&g)
            .zip(h)
            .for_each(|((ui, gi), hi)| *ui = gi + hi);
        op.pressure(&u, &mut q);
        let [qs, nfree, _, _] = sums(n, |i| {
            if g[i] > 0.0 {
                [q[i] + dphi(g[i]), 1.0, 0.0, 0.0]
            } else {
                [0.0; 4]
            }
        });
        let qbar = qs / nfree.max(1.0);
        q.par_iter_mut()
            .zip(&g)
            .for_each(|(qi, gi)| *qi += dphi(*gi) - qbar);
        let [big_g, viol, _, _] = sums(n, |i| {
            if g[i] > 0.0 {
                [q[i] * q[i], 0.0, 0.0, 0.0]
            } else {
                [0.0, q[i].min(0.0).powi(2), 0.0, 0.0]
            }
        });
        residual = ((big_g + viol) / nf).sqrt() / p_ref;
        if residual < options.tolerance || it == options.max_iterations {
            // Pressure field: K^-1 u plus the mean pressure -qbar.
            let mut p = vec![0.0; n];
            op.pressure(&u, &mut p);
            p.par_iter_mut().for_each(|v| *v -= qbar);
            let s = Solution::from_gap_fields(p, g, -qbar, it, residual);
            if residual < options.tolerance {
                return Ok(s);
            }
            return super::at_cap(s, options, "boundary elements (gap control)");
        }
        let ratio = if delta { big_g / g_old } else { 0.0 };
        t.par_iter_mut()
            .zip(&q)
            .zip(&g)
            .for_each(|((ti, qi), gi)| *ti = if *gi > 0.0 { qi + ratio * *ti } else { 0.0 });
        g_old = big_g;
        op.pressure(&t, &mut r);
        let [rs, _, _, _] = sums(n, |i| {
            if g[i] > 0.0 {
                [r[i], 0.0, 0.0, 0.0]
            } else {
                [0.0; 4]
            }
        });
        let rbar = rs / nfree.max(1.0);
        let [num, den_el, den_adh, _] = sums(n, |i| {
            if g[i] > 0.0 {
                let d2 = if w > 0.0 { -dphi(g[i]) / rho } else { 0.0 };
                [q[i] * t[i], (r[i] - rbar) * t[i], d2 * t[i] * t[i], 0.0]
            } else {
                [0.0; 4]
            }
        });
        let den = if den_el + den_adh > 0.0 {
            den_el + den_adh
        } else {
            den_el
        };
        let tau = if den > 0.0 { num / den } else { 0.0 };
        let [freed, total, _, _] = g
            .par_iter_mut()
            .zip(&t)
            .zip(&q)
            .with_min_len(4096)
            .fold(
                || [0.0; 4],
                |mut a, ((gi, ti), qi)| {
                    if *gi > 0.0 {
                        *gi = (*gi - tau * ti).max(0.0);
                    } else if *qi < 0.0 {
                        *gi = -tau * qi;
                        a[0] += 1.0;
                    }
                    a[1] += *gi;
                    a
                },
            )
            .reduce(|| [0.0; 4], |a, b| [a[0] + b[0], a[1] + b[1], 0.0, 0.0]);
        delta = freed == 0.0;
        if !(total > 0.0) {
            return Err(Error::NoConvergence {
                what: "boundary elements (gap control): the gap vanished".into(),
                iterations: it + 1,
                residual,
            });
        }
        let s = g_mean * nf / total;
        g.par_iter_mut().for_each(|v| *v *= s);
    }
    Err(Error::NoConvergence {
        what: "boundary elements (gap control)".into(),
        iterations: options.max_iterations,
        residual,
    })
}
