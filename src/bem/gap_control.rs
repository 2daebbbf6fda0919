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
//! 1. `q -= mean_F q`; `G = sum_F q^2`; `t = q + delta (G/G_old) t` on `F`
//!    (Fletcher–Reeves; with plastic pixels, below, Polak–Ribière+'s
//!    `max(0, (G - sum_F q q_old)/G_old)`);
//! 2. `r = K^-1 t` minus its mean over `F`; the step `tau = sum_F q t /
//!    (sum_F r t + sum_F phi''(g) t^2)` (the curvature of the adhesion
//!    included while the total stays positive, the elastic part alone
//!    otherwise);
//! 3. `g -= tau t` on `F`, `g = max(g, 0)`; pixels in contact whose
//!    reaction is negative (`g = 0`, `q < 0`) are freed with `g = -tau q`;
//! 4. `g` is rescaled to the imposed mean.
//!
//! With a hardness `H` (elastic–perfectly-plastic, [`solve_gap_capped`]) the
//! interaction is extended below `g = 0` by the linear, convex
//! `phi(g) = phi(0) - H g` (`phi'(g) = -H`, `phi'' = 0`): a pixel may pass
//! through the rigid surface (`g < 0`, plastic) where its reaction
//! `p = K^-1 u + p_mean` would exceed `H`, and there `p = H`. The free set
//! is `F = {g != 0}`; at `g = 0` the reaction lies in `[-phi'(0+), H]`,
//! i.e. `0 <= q <= H + phi'(0+)`. In step 3 the plastic pixels stay at or
//! below 0 (`g = min(g - tau t, 0)`), contact pixels with `q > H +
//! phi'(0+)` move to `g = -tau (q - H - phi'(0+)) < 0`, and step 4 scales
//! the open part (`g > 0`) only (every `g < 0` shifted when that cannot
//! reach the mean). `g_mean` is then the mean of the signed gap (the
//! approach: the mean of the clipped gap, the mean separation, is
//! `g_mean` plus the displaced volume per area). The criterion adds
//! `sum_{g = 0} max(q - H - phi'(0+), 0)^2`. While the last update left a
//! plastic pixel the conjugacy ratio is Polak–Ribière+'s (Gilbert & Nocedal
//! 1992), which restarts by itself where Fletcher–Reeves' jams: with a
//! strong short-range adhesion (`w = 0.5 J/m^2`, `rho = 20 nm` on the 32^2
//! map of `tests/it/bem_plastic_adhesion.rs`, from the rigid start) the
//! sets stayed fixed and the residual fell by a factor 12 from step 200 to
//! 3000 (mean gaps `7e-9` and `8.5e-9` m: 7e-6 and 1.6e-6 after 3000),
//! where Polak–Ribière+ reaches 1e-12 in 423 and 481 steps. With `H` above every reaction no pixel
//! goes below 0 and the ratio stays Fletcher–Reeves'. With `w = 0` the minimiser is
//! that of the complementary energy of `plastic` (the same KKT
//! conditions); with `H` above every reaction no pixel goes below 0 and
//! the iterates are those without a hardness, bit for bit.
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
pub(crate) fn solve_gap(
    op: &HalfSpace,
    h: &[f64],
    p_ref: f64,
    g_mean: f64,
    adhesion: Option<Exponential>,
    options: &Options,
    warm: Option<&[f64]>,
) -> Result<Solution> {
    solve_gap_capped(op, h, p_ref, g_mean, (adhesion, None), options, warm).map(|(s, _)| s)
}

/// [`solve_gap`] with an optional hardness `H` (Pa): the interaction
/// extended below `g = 0` by `phi(g) = phi(0) - H g` (module docs), `g_mean`
/// the mean of the signed gap (the approach). Returns the solution (gap
/// clipped at 0, plastic pixels at `p = H` counted, see
/// [`Solution::plastic_volume_per_area`]) and the signed gap (a warm start).
///
/// # Errors
/// As [`solve_gap`].
// Over 100 lines, kept whole: one conjugate-gradient loop on the gap whose
// projection, step and convergence tests share the same dozen locals.
pub(crate) fn solve_gap_capped(
    op: &HalfSpace,
    h: &[f64],
    p_ref: f64,
    g_mean: f64,
    (adhesion, hardness): (Option<Exponential>, Option<f64>),
    options: &Options,
    warm: Option<&[f64]>,
) -> Result<(Solution, Vec<f64>)> {
    let n = h.len();
    let nf = n as f64;
    let mut g: Vec<f64> = match warm {
        // Scaled to the mean (without a hardness always, as before it had
        // one: the retraction paths depend on the start).
        Some(w)
            if w.iter().sum::<f64>() > 0.0
                && (hardness.is_none() || (g_mean > 0.0 && w.iter().all(|v| *v >= 0.0))) =>
        {
            let s = g_mean * nf / w.iter().sum::<f64>();
            w.iter().map(|v| v * s).collect()
        }
        Some(w) if hardness.is_some() && w.iter().any(|v| *v != 0.0) => {
            // A signed gap shifted to the mean (scaling would flip signs).
            let d = g_mean - w.iter().sum::<f64>() / nf;
            w.iter().map(|v| v + d).collect()
        }
        // A mean at or below 0 only with a hardness: the rigid
        // interpenetration.
        _ if g_mean <= 0.0 => h.iter().map(|v| g_mean - v).collect(),
        _ => rigid_gap(h, g_mean),
    };
    let (w, rho) = adhesion.map_or((0.0, 1.0), |a| (a.energy, a.range));
    let hard = hardness.unwrap_or(f64::INFINITY);
    let plastic = hardness.is_some();
    // The free set: open, or (with a hardness) plastic.
    let free = |g: f64| g > 0.0 || (plastic && g < 0.0);
    let dphi = |g: f64| {
        if plastic && g < 0.0 {
            -hard
        } else if w > 0.0 {
            w / rho * (-g / rho).exp()
        } else {
            0.0
        }
    };
    // The reaction's upper bound at g = 0 in units of q: H + phi'(0+).
    let cap = hard + dphi(0.0);
    let mut u = vec![0.0; n];
    let mut q = vec![0.0; n];
    let mut t = vec![0.0; n];
    let mut r = vec![0.0; n];
    let (mut g_old, mut delta) = (1.0, false);
    // Whether the last update left plastic pixels (`g < 0`): then the
    // Polak–Ribière+ ratio (module docs).
    let mut below_zero = false;
    let mut residual = f64::INFINITY;
    for it in 0..=options.max_iterations {
        crate::cancel::check()?;
        u.par_iter_mut()
            .zip(&g)
            .zip(h)
            .for_each(|((ui, gi), hi)| *ui = gi + hi);
        // The last gradient kept in `r` (its scratch until `K^-1 t`).
        std::mem::swap(&mut q, &mut r);
        op.pressure(&u, &mut q);
        let [qs, nfree, _, _] = sums(n, |i| {
            if free(g[i]) {
                [q[i] + dphi(g[i]), 1.0, 0.0, 0.0]
            } else {
                [0.0; 4]
            }
        });
        let qbar = qs / nfree.max(1.0);
        q.par_iter_mut()
            .zip(&g)
            .for_each(|(qi, gi)| *qi += dphi(*gi) - qbar);
        let [big_g, viol, cross, _] = sums(n, |i| {
            if free(g[i]) {
                [q[i] * q[i], 0.0, q[i] * r[i], 0.0]
            } else {
                let over = (q[i] - cap).max(0.0);
                [0.0, q[i].min(0.0).powi(2) + over * over, 0.0, 0.0]
            }
        });
        residual = ((big_g + viol) / nf).sqrt() / p_ref;
        if residual < options.tolerance || it == options.max_iterations {
            // Pressure field: K^-1 u plus the mean pressure -qbar.
            let mut p = vec![0.0; n];
            op.pressure(&u, &mut p);
            p.par_iter_mut().for_each(|v| *v -= qbar);
            let s = match hardness {
                None => Solution::from_gap_fields(p, g.clone(), -qbar, it, residual),
                Some(hard) => Solution::from_capped_gap_fields(p, &g, (hard, -qbar), it, residual),
            };
            if residual < options.tolerance {
                return Ok((s, g));
            }
            return super::at_cap(s, options, "boundary elements (gap control)").map(|s| (s, g));
        }
        let ratio = match (delta, below_zero) {
            (false, _) => 0.0,
            (true, false) => big_g / g_old,
            (true, true) => ((big_g - cross) / g_old).max(0.0),
        };
        t.par_iter_mut()
            .zip(&q)
            .zip(&g)
            .for_each(|((ti, qi), gi)| *ti = if free(*gi) { qi + ratio * *ti } else { 0.0 });
        g_old = big_g;
        op.pressure(&t, &mut r);
        let [rs, _, _, _] = sums(n, |i| {
            if free(g[i]) {
                [r[i], 0.0, 0.0, 0.0]
            } else {
                [0.0; 4]
            }
        });
        let rbar = rs / nfree.max(1.0);
        let [num, den_el, den_adh, _] = sums(n, |i| {
            if free(g[i]) {
                let d2 = if w > 0.0 && g[i] > 0.0 {
                    -dphi(g[i]) / rho
                } else {
                    0.0
                };
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
        let [freed, total, below, nbelow] = g
            .par_iter_mut()
            .zip(&t)
            .zip(&q)
            .with_min_len(4096)
            .fold(
                || [0.0; 4],
                |mut a, ((gi, ti), qi)| {
                    if *gi > 0.0 {
                        *gi = (*gi - tau * ti).max(0.0);
                    } else if plastic && *gi < 0.0 {
                        // Plastic: stays at or below 0.
                        *gi = (*gi - tau * ti).min(0.0);
                    } else if *qi < 0.0 {
                        *gi = -tau * qi;
                        a[0] += 1.0;
                    } else if plastic && *qi > cap {
                        // The reaction above H: into the plastic set.
                        *gi = -tau * (qi - cap);
                        a[0] += 1.0;
                    }
                    if plastic && *gi < 0.0 {
                        a[2] += *gi;
                        a[3] += 1.0;
                    } else {
                        a[1] += *gi;
                    }
                    a
                },
            )
            .reduce(
                || [0.0; 4],
                |a, b| [a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]],
            );
        delta = freed == 0.0;
        below_zero = nbelow > 0.0;
        // The open part scaled to the mean (the plastic part, g < 0, kept);
        // when that cannot reach the mean, every non-contact pixel shifted.
        let s = (g_mean * nf - below) / total;
        if total > 0.0 && s > 0.0 {
            g.par_iter_mut().for_each(|v| {
                if !(plastic && *v < 0.0) {
                    *v *= s
                }
            });
        } else if hardness.is_some() && nbelow > 0.0 {
            let d = (g_mean * nf - below - total) / nbelow;
            g.par_iter_mut().for_each(|v| {
                if *v < 0.0 {
                    *v += d
                }
            });
        } else {
            return Err(Error::NoConvergence {
                what: "boundary elements (gap control): the gap vanished".into(),
                iterations: it + 1,
                residual,
            });
        }
    }
    Err(Error::NoConvergence {
        what: "boundary elements (gap control)".into(),
        iterations: options.max_iterations,
        residual,
    })
}
