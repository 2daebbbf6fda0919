//! Non-adhesive contact under load control: constrained conjugate
//! gradients in the pressure (Polonsky & Keer 1999).
//!
//! Unknowns: the pressure `p >= 0` on every pixel and the rigid approach.
//! With the gap `g = K p - h - c` (`h` the rigid surface's heights, `c` the
//! approach, chosen each iteration as the mean of `K p - h` over the
//! contact set `S = {p > 0}`), one iteration is Polonsky & Keer's:
//! 1. `G = sum_S g^2`; search direction `t = g + delta (G/G_old) t` on `S`,
//!    0 elsewhere (`delta = 0` after a step that added contact points);
//! 2. `r = K t` minus its mean over `S`; step `tau = sum_S g t / sum_S r t`;
//! 3. `p -= tau t` on `S`, then `p = max(p, 0)`;
//! 4. pixels outside contact that penetrate (`p = 0`, `g < 0`) enter with
//!    `p = -tau g`;
//! 5. `p` is rescaled to the imposed mean pressure.
//!
//! Convergence criterion (explicit): before each update the contact
//! conditions are measured on the current iterate, whose `p >= 0`, `p g = 0`
//! off `S` and mean pressure hold exactly; what remains is the gap on the
//! contact set and the penetration outside it:
//! `residual = sqrt((sum_S g^2 + sum_{not S} min(g, 0)^2)/N) / h_rms`,
//! `h_rms` the RMS of `h` about its mean. The solve stops when
//! `residual < tolerance` and returns that iterate.

use super::operator::HalfSpace;
use super::passes::{reduce, update};
use super::{Options, Solution};
use crate::error::{Error, Result};

/// Solves for mean pressure `p_mean > 0` starting from `warm` (a previous
/// pressure field, rescaled) or a uniform pressure.
///
/// # Errors
/// [`Error::NoConvergence`] after `options.max_iterations` (unless
/// `options.allow_unconverged`: the last iterate, flagged).
// Over 100 lines, kept whole: one Polonsky–Keer iteration loop whose
// projection, step and convergence tests share the same dozen locals.
pub(crate) fn solve_load(
    op: &HalfSpace,
    h: &[f64],
    h_rms: f64,
    p_mean: f64,
    options: &Options,
    warm: Option<&[f64]>,
) -> Result<Solution> {
    let n = h.len();
    let nf = n as f64;
    let mut p = match warm {
        Some(w) if w.iter().sum::<f64>() > 0.0 => {
            let s = p_mean * nf / w.iter().sum::<f64>();
            w.iter().map(|v| v * s).collect()
        }
        _ => vec![p_mean; n],
    };
    // The gap field first holds the displacement `K p` (no separate field).
    let mut g = vec![0.0; n];
    // The rescaling of step 5, applied as the next displacement reads `p`.
    let mut scale = 1.0;
    let mut t = vec![0.0; n];
    let mut r = vec![0.0; n];
    let (mut g_old, mut delta) = (1.0, false);
    let mut residual = f64::INFINITY;
    for it in 0..=options.max_iterations {
        crate::cancel::check()?;
        op.displacement_scaled(&mut p, scale, &mut g);
        // g = K p - h, then shifted by its mean over S.
        let [sum_s, count_s] = reduce(n, |rg| {
            let mut a = [0.0; 2];
            // Branch-free: the contact pattern is random, branches mispredict.
            for ((gi, hi), pi) in g[rg.clone()].iter().zip(&h[rg.clone()]).zip(&p[rg]) {
                let m = f64::from(u8::from(*pi > 0.0));
                a[0] += m * (gi - hi);
                a[1] += m;
            }
            a
        });
        let c = sum_s / count_s.max(1.0);
        let [big_g, pen] = update(&mut g, |rg, gs| {
            let mut a = [0.0; 2];
            let (hs, ps) = (&h[rg.clone()], &p[rg]);
            for ((gi, hi), pi) in gs.iter_mut().zip(hs).zip(ps) {
                *gi = *gi - hi - c;
                let m = f64::from(u8::from(*pi > 0.0));
                let neg = gi.min(0.0);
                a[0] += m * *gi * *gi;
                a[1] += (1.0 - m) * neg * neg;
            }
            a
        });
        residual = ((big_g + pen) / nf).sqrt() / h_rms;
        if residual < options.tolerance {
            return Ok(Solution::from_fields(p, g, f64::INFINITY, it, residual));
        }
        if it == options.max_iterations {
            let s = Solution::from_fields(p, g, f64::INFINITY, it, residual);
            return super::at_cap(s, options, "boundary elements (Polonsky-Keer)");
        }
        let ratio = if delta { big_g / g_old } else { 0.0 };
        let [num, sum_t] = update(&mut t, |rg, ts| {
            let mut a = [0.0; 2];
            for ((ti, gi), pi) in ts.iter_mut().zip(&g[rg.clone()]).zip(&p[rg]) {
                let m = f64::from(u8::from(*pi > 0.0));
                *ti = m * (gi + ratio * *ti);
                a[0] += gi * *ti;
                a[1] += *ti;
            }
            a
        });
        g_old = big_g;
        op.displacement(&t, &mut r);
        // sum_S (r - rbar) t = sum_S r t - rbar sum_S t.
        let [rs, rt] = reduce(n, |rg| {
            let mut a = [0.0; 2];
            for ((ri, ti), pi) in r[rg.clone()].iter().zip(&t[rg.clone()]).zip(&p[rg]) {
                let m = f64::from(u8::from(*pi > 0.0));
                a[0] += m * ri;
                a[1] += ri * ti; // t = 0 off S
            }
            a
        });
        let den = rt - rs / count_s.max(1.0) * sum_t;
        let tau = if den > 0.0 { num / den } else { 0.0 };
        // Update, clip, let penetrating points in; count them.
        let [entered, total] = update(&mut p, |rg, ps| {
            let mut a = [0.0; 2];
            for ((pi, ti), gi) in ps.iter_mut().zip(&t[rg.clone()]).zip(&g[rg]) {
                // In contact: step and clip; outside: penetrating points enter.
                let m = f64::from(u8::from(*pi > 0.0));
                let enter = (1.0 - m) * f64::from(u8::from(*gi < 0.0));
                *pi = m * (*pi - tau * ti).max(0.0) + enter * (-tau * gi);
                a[0] += enter;
                a[1] += *pi;
            }
            a
        });
        delta = entered == 0.0;
        if !(total > 0.0) {
            return Err(Error::NoConvergence {
                what: "boundary elements (Polonsky-Keer): the pressure vanished".into(),
                iterations: it + 1,
                residual,
            });
        }
        scale = p_mean * nf / total;
    }
    Err(Error::NoConvergence {
        what: "boundary elements (Polonsky-Keer)".into(),
        iterations: options.max_iterations,
        residual,
    })
}
