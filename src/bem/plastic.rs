//! Elastic–perfectly-plastic contact under load control: the pressure
//! capped at the hardness `H` (Almqvist et al. 2007), by a primal–dual
//! active-set method (Hintermüller, Ito & Kunisch 2003) whose linear
//! solves are conjugate gradients on the free set.
//!
//! The pressure minimises `(1/2) p.K p - p.h` over `0 <= p <= H` with
//! `mean p = P`; with the gap `g = K p - h - c` (`c` the approach, the
//! multiplier of the mean) the solution has `g = 0` on the free set
//! `S = {0 < p < H}`, `g >= 0` where `p = 0`, `g <= 0` where `p = H`.
//! One outer step:
//! 1. the sets from the current `(p, g)`: open where `p - k g <= 0`,
//!    plastic where `p - k g >= H`, free otherwise (`k = 1/K_00`, the
//!    inverse self-compliance, which makes `k g` a pressure);
//! 2. `p = 0` on the open set, `H` on the plastic set, and on the free set
//!    the solution of `K_SS p_S - c = h_S - (K p_plastic)_S`,
//!    `sum p = N P`: conjugate gradients in the subspace of free-set moves
//!    of zero sum (the mean held exactly), from the previous `p_S` shifted
//!    to the sum, inexactly: to the residual `max(min(0.1, r) r, tol/10)`
//!    (Eisenstat & Walker's 1996 forcing term, `r` the natural residual
//!    `rms(p - clamp(p - k g, 0, H))/(k h_rms)` of the current `(p, g)`
//!    before the step): loose while the sets still move, a tenth of the
//!    tolerance once they have settled;
//! 3. `g = K p - h - c` with `c` the mean of `K p - h` over `S`.
//!
//! The first step, cold on a periodic map below the hardness, has every
//! pixel free (`g = 0`): its solution, the full-contact pressure
//! `p = K^-1 h + P`, is taken at once by the stiffness (one FFT pair,
//! counted as one application of `K`); padded, warm, or at `P = H` the
//! start is the previous pressure clamped to `[0, H]` or `p = P`.
//! On the 512^2 slope-0.08 map with `H = 0.1 E*` the two together take
//! the iterations from 528-641 to 172-215 (`docs/performance.md`).
//!
//! The iteration stops when the sets' conditions hold
//! (`residual = sqrt((sum_S g^2 + sum_{p=0} min(g, 0)^2 + sum_{p=H}
//! max(g, 0)^2)/N) / h_rms < tolerance` and `0 < p < H` on `S`);
//! `iterations` counts every application of `K` (conjugate-gradient steps
//! and the gap of each outer step) against `options.max_iterations`.

use super::operator::HalfSpace;
use super::{Options, Solution};
use crate::error::Result;

/// A pixel's set.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Set {
    Open,
    Free,
    Plastic,
}

/// The approach `c`: the mean of `u - h` over the free set, or without
/// free pixels the middle of the interval the conditions allow
/// (`max (u - h)` over the plastic pixels to `min (u - h)` over the open
/// ones; either end alone when the other set is empty).
fn approach(u: &[f64], h: &[f64], sets: &[Set]) -> f64 {
    let (mut sum, mut count) = (0.0, 0.0);
    let (mut hi_plastic, mut lo_open) = (f64::NEG_INFINITY, f64::INFINITY);
    for ((ui, hi), s) in u.iter().zip(h).zip(sets) {
        match s {
            Set::Free => {
                sum += ui - hi;
                count += 1.0;
            }
            Set::Plastic => hi_plastic = hi_plastic.max(ui - hi),
            Set::Open => lo_open = lo_open.min(ui - hi),
        }
    }
    if count > 0.0 {
        return sum / count;
    }
    match (hi_plastic.is_finite(), lo_open.is_finite()) {
        (true, true) => 0.5 * (hi_plastic + lo_open),
        (true, false) => hi_plastic,
        (false, true) => lo_open,
        (false, false) => 0.0,
    }
}

/// Conjugate gradients for the free pixels of `p` (the others fixed at 0
/// or `H`), the sum of `p` held at `target`: minimises the complementary
/// energy over zero-sum moves of the free pixels. Returns the steps taken.
#[allow(clippy::too_many_arguments)]
fn free_set_cg(
    op: &HalfSpace,
    h: &[f64],
    sets: &[Set],
    p: &mut [f64],
    target: f64,
    (tol, h_rms): (f64, f64),
    budget: usize,
    scratch: &mut [Vec<f64>; 3],
) -> Result<usize> {
    let n = p.len();
    let nf = n as f64;
    let free = sets.iter().filter(|s| **s == Set::Free).count();
    if free == 0 {
        return Ok(0);
    }
    let fixed: f64 = p
        .iter()
        .zip(sets)
        .filter(|(_, s)| **s != Set::Free)
        .map(|(v, _)| v)
        .sum();
    let have: f64 = p
        .iter()
        .zip(sets)
        .filter(|(_, s)| **s == Set::Free)
        .map(|(v, _)| v)
        .sum();
    let shift = (target - fixed - have) / free as f64;
    p.iter_mut()
        .zip(sets)
        .filter(|(_, s)| **s == Set::Free)
        .for_each(|(v, _)| *v += shift);
    let [u, r, d] = scratch;
    // The residual -g on S, projected to zero sum (the approach absorbs
    // its mean).
    let project = |x: &mut [f64]| {
        let mean = x
            .iter()
            .zip(sets)
            .filter(|(_, s)| **s == Set::Free)
            .map(|(v, _)| v)
            .sum::<f64>()
            / free as f64;
        x.iter_mut().zip(sets).for_each(|(v, s)| {
            *v = if *s == Set::Free { *v - mean } else { 0.0 };
        });
    };
    op.displacement(p, u);
    r.iter_mut()
        .zip(u.iter())
        .zip(h)
        .for_each(|((ri, ui), hi)| *ri = hi - ui);
    project(r);
    d.copy_from_slice(r);
    let mut rr: f64 = r.iter().map(|v| v * v).sum();
    let mut steps = 0;
    while (rr / nf).sqrt() / h_rms >= tol {
        if steps >= budget {
            return Ok(steps);
        }
        crate::cancel::check()?;
        op.displacement(d, u);
        project(u);
        let dkd: f64 = d.iter().zip(u.iter()).map(|(a, b)| a * b).sum();
        if !(dkd > 0.0) {
            break;
        }
        let a = rr / dkd;
        p.iter_mut()
            .zip(d.iter())
            .for_each(|(pi, di)| *pi += a * di);
        r.iter_mut()
            .zip(u.iter())
            .for_each(|(ri, ui)| *ri -= a * ui);
        let rn: f64 = r.iter().map(|v| v * v).sum();
        let beta = rn / rr;
        d.iter_mut()
            .zip(r.iter())
            .zip(sets)
            .for_each(|((di, ri), s)| {
                *di = if *s == Set::Free {
                    ri + beta * *di
                } else {
                    0.0
                }
            });
        rr = rn;
        steps += 1;
    }
    Ok(steps)
}

/// Frees pixels when the fixed ones cannot carry `target` alone and no
/// free pixel can make up the difference: the `ceil(|miss|/H) + 1` fixed
/// pixels whose `y = p - k g` lies nearest the free interval `(0, H)` on the
/// side that must give (plastic ones when the fixed sum is too large, open
/// ones when too small).
fn free_enough(sets: &mut [Set], p: &mut [f64], g: &[f64], k: f64, target: f64, hardness: f64) {
    if sets.contains(&Set::Free) {
        return;
    }
    let miss = target - p.iter().sum::<f64>();
    if miss.abs() <= 1e-14 * target {
        return;
    }
    let side = if miss < 0.0 { Set::Plastic } else { Set::Open };
    let mut cand: Vec<usize> = (0..p.len()).filter(|&i| sets[i] == side).collect();
    // Nearest the interval first: plastic by the smallest y, open by the largest.
    let y = |i: usize| p[i] - k * g[i];
    if side == Set::Plastic {
        cand.sort_by(|&a, &b| y(a).total_cmp(&y(b)));
    } else {
        cand.sort_by(|&a, &b| y(b).total_cmp(&y(a)));
    }
    let m = (miss.abs() / hardness).ceil() as usize + 1;
    for &i in cand.iter().take(m) {
        sets[i] = Set::Free;
    }
}

/// The inner solve's residual target for the natural residual `r` of the
/// current `(p, g)` (relative to `h_rms`): Eisenstat & Walker's (1996)
/// forcing term `min(0.1, r) r`, loose while the sets still move, and not
/// below a tenth of the tolerance `tol` (the last solves).
fn forcing(r: f64, tol: f64) -> f64 {
    (r.min(0.1) * r).max(0.1 * tol)
}

/// Solves for mean pressure `0 < p_mean <= hardness` starting from `warm`
/// (a previous pressure field), cold on a periodic map below the hardness
/// from the full-contact pressure `K^-1 h + P`, else a uniform pressure.
///
/// # Errors
/// [`Error::NoConvergence`](crate::Error::NoConvergence) when `options.max_iterations` applications of
/// the operator did not reach the tolerance.
pub(crate) fn solve_load(
    op: &HalfSpace,
    h: &[f64],
    h_rms: f64,
    p_mean: f64,
    hardness: f64,
    options: &Options,
    warm: Option<&[f64]>,
) -> Result<Solution> {
    let n = h.len();
    let nf = n as f64;
    let target = p_mean * nf;
    let mut used = 0;
    let mut p: Vec<f64> = match warm {
        Some(w) if w.iter().sum::<f64>() > 0.0 => {
            w.iter().map(|v| v.clamp(0.0, hardness)).collect()
        }
        // Cold and periodic below the hardness: the first outer step with
        // every pixel free, `p = K^-1 h + P` at once (one application of
        // the stiffness, an FFT pair as `K` is: counted as one).
        _ if op.periodic() && p_mean < hardness => {
            used = 1;
            super::full_contact::full_pressure(op, h, p_mean)
        }
        _ => vec![p_mean; n],
    };
    let mut g = vec![0.0; n];
    let mut u = vec![0.0; n];
    let mut sets = vec![Set::Free; n];
    let mut scratch = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
    let k = {
        let mut e = vec![0.0; n];
        e[0] = 1.0;
        op.displacement(&e, &mut u);
        1.0 / u[0]
    };
    let mut residual = f64::INFINITY;
    // Outer steps are bounded by the operator applications they cost.
    while used < options.max_iterations {
        crate::cancel::check()?;
        // The natural residual of the conditions at the current `(p, g)`,
        // in gap units: `|p - clamp(p - k g, 0, H)|/k`.
        let mut natural = 0.0;
        for ((s, pi), gi) in sets.iter_mut().zip(p.iter_mut()).zip(&g) {
            let y = *pi - k * gi;
            natural += ((*pi - y.clamp(0.0, hardness)) / k).powi(2);
            *s = if y <= 0.0 {
                *pi = 0.0;
                Set::Open
            } else if y >= hardness {
                *pi = hardness;
                Set::Plastic
            } else {
                Set::Free
            };
        }
        free_enough(&mut sets, &mut p, &g, k, target, hardness);
        let inner = forcing((natural / nf).sqrt() / h_rms, options.tolerance);
        let budget = options.max_iterations - used;
        used += free_set_cg(
            op,
            h,
            &sets,
            &mut p,
            target,
            (inner, h_rms),
            budget,
            &mut scratch,
        )?;
        op.displacement(&p, &mut u);
        used += 1;
        let c = approach(&u, h, &sets);
        let (mut sq, mut inside) = (0.0, true);
        for (((gi, ui), hi), (s, pi)) in g.iter_mut().zip(&u).zip(h).zip(sets.iter().zip(&p)) {
            *gi = ui - hi - c;
            sq += match s {
                Set::Free => {
                    inside &= *pi > 0.0 && *pi < hardness;
                    *gi * *gi
                }
                Set::Open => gi.min(0.0).powi(2),
                Set::Plastic => gi.max(0.0).powi(2),
            };
        }
        residual = (sq / nf).sqrt() / h_rms;
        let mean_held = (p.iter().sum::<f64>() - target).abs() <= 1e-12 * target;
        if residual < options.tolerance && inside && mean_held {
            return Ok(Solution::from_fields(p, g, hardness, used, residual));
        }
    }
    // At the cap: the last iterate, flagged or refused as every solver's.
    super::at_cap(
        Solution::from_fields(p, g, hardness, used, residual),
        options,
        "boundary elements (elastic-perfectly-plastic, active set)",
    )
}
