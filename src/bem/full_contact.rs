//! Load control at and near full contact on a periodic map, without
//! adhesion or hardness: the exact full-contact state at once, and near it
//! the complementary problem, conjugate gradients in the gap on the small
//! non-contact set.
//!
//! Full contact. With every pixel in contact the gap is 0, so the
//! displacement is the surface itself, `u = h + c`, and the periodic
//! stiffness gives the pressure in one step,
//! `p_full = K^-1 h + P` (`(K^-1 h)_q = E* |q| h_q/2`, zero mean; `P` the
//! imposed mean pressure). That is the solution exactly when
//! `min p_full > 0` (every pixel pressed): `P > P_full = max(-(K^-1 h))`.
//! Its elastic energy per nominal area is `(1/2) mean(h K^-1 h)
//! = (E*/4) sum_q |q| |h_q|^2`, Persson's `U_full/A0` of the map
//! (`docs/physics.md`).
//!
//! Near full contact (a few pixels of `p_full` not positive) the unknown is
//! the gap `g >= 0`, nonzero only on the small non-contact set, with
//! `u = g + h`: `g` minimises `Pi(g) = (1/2) u . K^-1 u + P sum g`
//! (elastic energy plus the work of the imposed load), whose gradient is
//! the contact pressure `r = K^-1 u + P`; at the minimum `r = 0` where
//! `g > 0` and `r >= 0` where `g = 0` (Rey, Anciaux & Molinari 2017 with
//! the mean gap free and the load imposed through `P sum g`; the mean
//! pressure is `P` exactly because `K^-1 u` has zero mean). One iteration,
//! Polonsky & Keer's with gap and pressure swapped and no constraint on the
//! mean:
//! 1. `r = K^-1 (g + h) + P`; `G = sum_F r^2` on the free set
//!    `F = {g > 0}`; `t = r + delta (G/G_old) t` on `F`, 0 elsewhere;
//! 2. `tau = sum_F r t / sum_F t K^-1 t`;
//! 3. `g -= tau t` on `F`, `g = max(g, 0)`; pixels in contact with a
//!    tensile reaction (`g = 0`, `r < 0`) open with `g = -tau r`
//!    (`delta = 0` after a step that opened pixels).
//!
//! The start is one Jacobi step from full contact, `g = max(-p_full, 0)/k`
//! with `k` the self-stiffness `(K^-1)_00`. Each iterate is judged by
//! Polonsky & Keer's own criterion (so `residual` means the same under
//! load control whichever method ran): its pressure
//! `p = max(r, 0)` on the contact set (0 on `F`), `g' = K p - h - c` with
//! `c` the mean of `K p - h` over `S = {p > 0}`, and
//! `residual = sqrt((sum_S g'^2 + sum_{not S} min(g', 0)^2)/N) / h_rms`.
//! That costs one more product with `K`, so it is measured only when the
//! gap iteration's own residual, `sqrt((sum_F r^2 + sum_{not F}
//! min(r, 0)^2)/N)/p_ref` (`p_ref = rms(K^-1 h)`), falls below a target
//! that starts at the tolerance and drops tenfold whenever the measured
//! criterion is not met yet.

use super::operator::HalfSpace;
use super::passes::{reduce, update};
use super::{Options, Solution};
use crate::error::Result;

/// Below this fraction of non-positive pixels in `p_full` (the
/// non-contact set the smaller one), the gap iteration runs instead of
/// Polonsky & Keer's: on the shipped 256^2 self-affine map it needs fewer
/// products with the operator from a fraction of about 0.36 down against
/// plain Polonsky & Keer, and 5-15 % fewer from 0.27 down against the
/// preconditioned one (three products an iteration; `docs/performance.md`).
pub(crate) const NEAR_FULL: f64 = 0.3;

/// `p_full = K^-1 h + P`: the pressure of full contact at mean `P` (Pa).
pub(crate) fn full_pressure(op: &HalfSpace, h: &[f64], p_mean: f64) -> Vec<f64> {
    let mut p = vec![0.0; h.len()];
    op.pressure(h, &mut p);
    p.iter_mut().for_each(|v| *v += p_mean);
    p
}

/// Fraction of the pixels of `p_full` that are not pressed (`<= 0`).
pub(crate) fn open_fraction(p_full: &[f64]) -> f64 {
    p_full.iter().filter(|v| **v <= 0.0).count() as f64 / p_full.len() as f64
}

/// The state of pressure `p` judged by Polonsky & Keer's criterion (module
/// documentation): the gap `K p - h - c` and its residual.
fn judged(op: &HalfSpace, h: &[f64], h_rms: f64, p: Vec<f64>, it: usize) -> Solution {
    let n = h.len();
    let mut u = vec![0.0; n];
    op.displacement(&p, &mut u);
    let [sum_s, count_s] = reduce(n, |rg| {
        let mut a = [0.0; 2];
        for ((ui, hi), pi) in u[rg.clone()].iter().zip(&h[rg.clone()]).zip(&p[rg]) {
            if *pi > 0.0 {
                a[0] += ui - hi;
                a[1] += 1.0;
            }
        }
        a
    });
    let c = sum_s / count_s.max(1.0);
    let mut sq = 0.0;
    for ((ui, hi), pi) in u.iter_mut().zip(h).zip(&p) {
        *ui = *ui - hi - c;
        sq += if *pi > 0.0 {
            *ui * *ui
        } else {
            ui.min(0.0).powi(2)
        };
    }
    let residual = (sq / n as f64).sqrt() / h_rms;
    Solution::from_fields(p, u, f64::INFINITY, it, residual)
}

/// The exact full-contact state at mean pressure `p_mean` from its
/// pressure `p_full` (all positive), with its residual measured; `None`
/// when a pixel of `p_full` is not pressed or the residual misses the
/// tolerance (rounding on an extreme map: the iterations decide then).
pub(crate) fn exact(
    op: &HalfSpace,
    h: &[f64],
    h_rms: f64,
    p_full: &[f64],
    options: &Options,
) -> Option<Solution> {
    if p_full.iter().any(|v| !(*v > 0.0)) {
        return None;
    }
    let s = judged(op, h, h_rms, p_full.to_vec(), 0);
    (s.residual < options.tolerance).then_some(s)
}

/// Solves at mean pressure `p_mean` by the gap iteration (module
/// documentation), starting from `warm` (a previous gap field) or one
/// Jacobi step from `p_full`.
///
/// # Errors
/// [`crate::Error::NoConvergence`] after `options.max_iterations` (unless
/// `options.allow_unconverged`: the last iterate, flagged), or
/// [`crate::Error::Cancelled`].
pub(crate) fn solve_load(
    op: &HalfSpace,
    (h, h_rms, p_ref): (&[f64], f64, f64),
    p_mean: f64,
    p_full: &[f64],
    options: &Options,
    warm: Option<&[f64]>,
) -> Result<Solution> {
    let n = h.len();
    let nf = n as f64;
    let k = {
        let mut e = vec![0.0; n];
        e[0] = 1.0;
        let mut s = vec![0.0; n];
        op.pressure(&e, &mut s);
        s[0]
    };
    let mut g: Vec<f64> = match warm {
        Some(w) if w.len() == n && w.iter().all(|v| *v >= 0.0) => w.to_vec(),
        _ => p_full.iter().map(|p| (-p).max(0.0) / k).collect(),
    };
    let mut u = vec![0.0; n];
    let mut r = vec![0.0; n];
    let mut t = vec![0.0; n];
    let mut z = vec![0.0; n];
    let (mut g_old, mut delta) = (1.0, false);
    let mut target = options.tolerance;
    let mut last: Option<Solution> = None;
    for it in 0..=options.max_iterations {
        crate::cancel::check()?;
        update::<0, _>(&mut u, |rg, us| {
            for ((ui, gi), hi) in us.iter_mut().zip(&g[rg.clone()]).zip(&h[rg]) {
                *ui = gi + hi;
            }
            []
        });
        op.pressure(&u, &mut r);
        let [big_g, viol] = update(&mut r, |rg, rs| {
            let mut a = [0.0; 2];
            for (ri, gi) in rs.iter_mut().zip(&g[rg]) {
                *ri += p_mean;
                if *gi > 0.0 {
                    a[0] += *ri * *ri;
                } else {
                    a[1] += ri.min(0.0).powi(2);
                }
            }
            a
        });
        let own = ((big_g + viol) / nf).sqrt() / p_ref;
        if own < target || it == options.max_iterations {
            let mut p: Vec<f64> = r
                .iter()
                .zip(&g)
                .map(|(ri, gi)| if *gi > 0.0 { 0.0 } else { ri.max(0.0) })
                .collect();
            // The clipped residual moved the mean: back to `P` exactly.
            let scale = p_mean * nf / p.iter().sum::<f64>();
            p.iter_mut().for_each(|v| *v *= scale);
            let s = judged(op, h, h_rms, p, it);
            if s.residual < options.tolerance {
                return Ok(s);
            }
            if it == options.max_iterations {
                // The better of this iterate and the last one judged.
                let best = match last {
                    Some(l) if l.residual < s.residual => l,
                    _ => s,
                };
                return super::at_cap(best, options, "boundary elements (full-contact gap)");
            }
            target *= 0.1;
            last = Some(s);
        }
        let ratio = if delta { big_g / g_old } else { 0.0 };
        g_old = big_g;
        let opened = descend(op, &r, &mut g, [&mut t, &mut z], ratio, k);
        delta = opened == 0.0;
    }
    // The loop returns at the iteration cap; this is its bound.
    Err(crate::error::Error::NoConvergence {
        what: format!("boundary elements (full-contact gap): {}", super::AT_CAP),
        iterations: options.max_iterations,
        residual: f64::INFINITY,
    })
}

/// One conjugate-gradient step of the gap iteration (steps 1-3 of the
/// module documentation) from the contact pressure `r`: the direction `t`
/// (its image `z = K^-1 t`), the step, the update of `g`. Returns the
/// pixels opened.
fn descend(
    op: &HalfSpace,
    r: &[f64],
    g: &mut [f64],
    [t, z]: [&mut Vec<f64>; 2],
    ratio: f64,
    k: f64,
) -> f64 {
    let n = g.len();
    update::<0, _>(t, |rg, ts| {
        for ((ti, ri), gi) in ts.iter_mut().zip(&r[rg.clone()]).zip(&g[rg]) {
            *ti = if *gi > 0.0 { ri + ratio * *ti } else { 0.0 };
        }
        []
    });
    op.pressure(t, z);
    let [num, den] = reduce(n, |rg| {
        let mut a = [0.0; 2];
        for ((ri, ti), zi) in r[rg.clone()].iter().zip(&t[rg.clone()]).zip(&z[rg]) {
            a[0] += ri * ti; // t = 0 off F
            a[1] += zi * ti;
        }
        a
    });
    let tau = if den > 0.0 { num / den } else { 1.0 / k };
    let [opened] = update(g, |rg, gs| {
        let mut a = [0.0];
        for ((gi, ti), ri) in gs.iter_mut().zip(&t[rg.clone()]).zip(&r[rg]) {
            if *gi > 0.0 {
                *gi = (*gi - tau * ti).max(0.0);
            } else if *ri < 0.0 {
                *gi = -tau * ri;
                a[0] += 1.0;
            }
        }
        a
    });
    opened
}
