//! Non-adhesive contact under load control: constrained conjugate
//! gradients in the pressure (Polonsky & Keer 1999).
//!
//! Unknowns: the pressure `p >= 0` on every pixel and the rigid approach.
//! With the gap `g = K p - h - c` (`h` the rigid surface's heights, `c` the
//! approach, chosen each iteration as the mean of `K p - h` over the
//! contact set `S = {p > 0}`), one iteration is Polonsky & Keer's:
//! 1. `G = sum_S g z`; search direction `t = z + delta (G/G_old) t` on `S`,
//!    0 elsewhere (`delta = 0` after a step that added contact points),
//!    with `z = g` (non-periodic maps) or, periodic, the preconditioned
//!    gap `z = K^-1 (g on S, 0 elsewhere)` on `S` minus its mean over `S`;
//! 2. `r = K t` minus its mean over `S`; step `tau = sum_S g t / sum_S r t`;
//! 3. `p -= tau t` on `S`, then `p = max(p, 0)`;
//! 4. pixels outside contact that penetrate (`p = 0`, `g < 0`) enter with
//!    `p = -tau g`;
//! 5. `p` is rescaled to the imposed mean pressure.
//!
//! The preconditioner (periodic maps): the stiffness `K^-1` (`E* |q|/2` in
//! Fourier space) is the exact inverse of the full operator, an
//! approximate inverse of its restriction to `S`: the FFT-based
//! approximate inverse of Zhao, Vollebregt & Oosterlee (2014, Numer.
//! Linear Algebra Appl. 21, 256) used as the preconditioner of the
//! bound-constrained conjugate gradients (Vollebregt 2014, J. Optim.
//! Theory Appl. 162, 931). One more convolution an iteration, about 3x
//! fewer iterations at 256^2 and 5x fewer at 1024^2 (docs/performance.md).
//! Non-periodic maps keep plain conjugate gradients: their padded
//! operator has no exact inverse on the map.
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
        let ([num, sum_t], big_g_new) = direction(
            op,
            (&g, &p),
            (&mut t, &mut r),
            count_s,
            big_g,
            delta.then_some(g_old),
        );
        g_old = big_g_new;
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

/// Step 1, the search direction `t` (in place) on the contact set
/// `S = {p > 0}` of `count_s` pixels, from the gap `g` (zero mean over
/// `S`) and `G = sum_S g z`: `t = S (z + beta t)` with `beta = G/G_old`
/// (`previous` = `G_old`; `None` restarts, `beta = 0`). `z = g` on a
/// padded operator; periodic, `z = K^-1 (S g) - zbar` on `S` (`zbar` its
/// mean over `S`), computed in `r` (free until `r = K t`). Returns
/// `[sum g t, sum t]` and this iteration's `G` (`big_g = sum_S g^2` when
/// unpreconditioned).
fn direction(
    op: &HalfSpace,
    (g, p): (&[f64], &[f64]),
    (t, r): (&mut [f64], &mut [f64]),
    count_s: f64,
    big_g: f64,
    previous: Option<f64>,
) -> ([f64; 2], f64) {
    let n = g.len();
    if !op.periodic() {
        let ratio = previous.map_or(0.0, |old| big_g / old);
        let sums = update(t, |rg, ts| {
            let mut a = [0.0; 2];
            for ((ti, gi), pi) in ts.iter_mut().zip(&g[rg.clone()]).zip(&p[rg]) {
                let m = f64::from(u8::from(*pi > 0.0));
                *ti = m * (gi + ratio * *ti);
                a[0] += gi * *ti;
                a[1] += *ti;
            }
            a
        });
        return (sums, big_g);
    }
    op.pressure_masked(g, p, r);
    let [sz, sgz, sg] = reduce(n, |rg| {
        let mut a = [0.0; 3];
        let (gs, ps) = (&g[rg.clone()], &p[rg.clone()]);
        for ((zi, gi), pi) in r[rg].iter().zip(gs).zip(ps) {
            let m = f64::from(u8::from(*pi > 0.0));
            a[0] += m * zi;
            a[1] += m * gi * zi;
            a[2] += m * gi;
        }
        a
    });
    let zbar = sz / count_s.max(1.0);
    // sum_S g (z - zbar); sum_S g is 0 but for rounding.
    let gz = sgz - zbar * sg;
    let ratio = previous.map_or(0.0, |old| gz / old);
    let r = &*r;
    let sums = update(t, |rg, ts| {
        let mut a = [0.0; 2];
        let (gs, ps) = (&g[rg.clone()], &p[rg.clone()]);
        for (((ti, zi), gi), pi) in ts.iter_mut().zip(&r[rg]).zip(gs).zip(ps) {
            let m = f64::from(u8::from(*pi > 0.0));
            *ti = m * (zi - zbar + ratio * *ti);
            a[0] += gi * *ti;
            a[1] += *ti;
        }
        a
    });
    (sums, gz)
}
