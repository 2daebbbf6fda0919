//! Johnson–Kendall–Roberts (1971): short-range adhesion acting as a surface
//! energy inside the contact.
//!
//! In Maugis units (`A = a/(pi w R^2/K)^(1/3)`, `Pbar = P/(pi w R)`,
//! `Dbar = delta/(pi^2 w^2 R/K^2)^(1/3)`, `K = 4E*/3`):
//!
//! ```text
//! Pbar = A^3 - sqrt(6 A^3)            (P = K a^3/R - sqrt(6 pi w K a^3))
//! Dbar = A^2 - sqrt(8 A / 3)          (delta = a^2/R - sqrt(8 pi w a/(3K)))
//! ```
//!
//! Stable under displacement control for `A >= A_c = 6^(-1/3)`
//! (`dDbar/dA = 0`), where `Pbar = -5/6` and `Dbar = -(3/4)(4/3)^(2/3)`.
//! Load-controlled pull-off `Pbar = -3/2` at `A^3 = 3/2`. Zero-load radius
//! `A0 = 6^(1/3)`. Jump-in on approach at `delta = 0` (Johnson, *Contact
//! Mechanics* §5.5; Maugis, *J. Colloid Interface Sci.* 150 (1992)).

use super::{AsperityLaw, Branch, ContactState, Control, Instability, LawKernels};
use crate::error::Result;
use crate::material::MaugisScales;
use crate::numeric::lanes::sqrt_lanes;

/// `sqrt(8/3)`.
const B: f64 = 1.632_993_161_855_452_1;
/// `A_c = 6^(-1/3)`: radius at the displacement-controlled jump-out.
pub const JUMP_OUT_RADIUS: f64 = 0.550_321_208_149_104_4;
/// `Dbar_c = -(3/4)(4/3)^(2/3)`: interference at the jump-out.
pub const JUMP_OUT_INTERFERENCE: f64 = -0.908_560_296_416_069_8;
/// `Pbar = -5/6` at the jump-out.
pub const JUMP_OUT_LOAD: f64 = -5.0 / 6.0;
/// `Pbar = -3/2`: load-controlled pull-off.
pub const PULL_OFF_LOAD: f64 = -1.5;
/// `A^3 = 3/2` at the load-controlled pull-off.
pub const PULL_OFF_RADIUS: f64 = 1.144_714_242_553_331_9;
/// `A0 = 6^(1/3)`: contact radius at zero load.
pub const ZERO_LOAD_RADIUS: f64 = 1.817_120_592_832_139_7;

/// Dimensionless load `Pbar = A^3 - sqrt(6 A^3)`.
#[inline]
pub fn load_bar(a: f64) -> f64 {
    let a3 = a * a * a;
    a3 - (6.0 * a3).sqrt()
}

/// Dimensionless interference `Dbar = A^2 - sqrt(8 A/3)`.
#[inline]
pub fn interference_bar(a: f64) -> f64 {
    a * a - B * a.sqrt()
}

/// Contact radius `A` on the stable branch (`A >= 6^(-1/3)`) at
/// dimensionless interference `Dbar`, or `None` below the jump-out
/// `Dbar_c = -0.9086`.
///
/// Solves `x^4 - sqrt(8/3) x - Dbar = 0` for `x = sqrt(A)` by Newton's
/// method from an upper bound: `f` is convex, so the iterates decrease
/// monotonically to the largest root. The start is the smaller of
/// `Dbar^(1/4) + b^(1/3)` (always an upper bound) and the fold expansion
/// `x_c + sqrt((Dbar - Dbar_c)/(6 x_c^2))` (an upper bound too, since the
/// cubic and quartic terms of `f` about `x_c` are positive), which keeps
/// convergence quadratic near the fold, improved by one fixed-point step
/// `x <- min(x, (Dbar + b x)^(1/4))` (still an upper bound, since
/// `x^4 >= Dbar + b x` above the root; contraction `b/(4 x^3)`, strong in
/// deep contact): 5 Newton steps instead of 7 over a Monte Carlo
/// population. The batch ([`Jkr::state_batch`]) takes the same steps.
#[inline]
pub fn stable_radius_bar(d: f64) -> Option<f64> {
    if !(d >= JUMP_OUT_INTERFERENCE) {
        return None;
    }
    let mut x = newton_start(d);
    for _ in 0..MAX_NEWTON {
        let (next, more) = newton_step(x, d);
        x = next;
        if !more {
            break;
        }
    }
    Some(radius_from_root(x))
}

/// Iteration cap of [`stable_radius_bar`] (quadratic convergence from the
/// start takes at most ~6).
const MAX_NEWTON: usize = 60;
/// `x_c = 6^(-1/6) = sqrt(A_c)`.
const XC: f64 = 0.741_836_375_590_402_3;

/// Start of the Newton iteration for `x = sqrt(A)` at `Dbar = d`: the
/// smaller of `Dbar^(1/4) + b^(1/3)` and `x_c + sqrt((Dbar - Dbar_c)/(6 x_c^2))`,
/// both upper bounds of the largest root, then one fixed-point step
/// `min(x, (Dbar + b x)^(1/4))`.
#[inline(always)]
fn newton_start(d: f64) -> f64 {
    let (bound, fold) = start_radicands(d);
    let x = start_from_roots(bound.sqrt().sqrt(), fold.sqrt());
    x.min((d + B * x).sqrt().sqrt())
}

/// The radicands of [`newton_start`]: `max(Dbar, 0)` (fourth root) and
/// `(Dbar - Dbar_c)/(6 x_c^2)` (square root).
#[inline(always)]
fn start_radicands(d: f64) -> (f64, f64) {
    (d.max(0.0), (d - JUMP_OUT_INTERFERENCE) / (6.0 * XC * XC))
}

/// [`newton_start`] from the roots of its radicands (taken in SIMD lanes
/// by the batch).
#[inline(always)]
fn start_from_roots(fourth_root: f64, fold_root: f64) -> f64 {
    // B^(1/3) = (8/3)^(1/6) (mpmath), a constant rather than a cbrt per call.
    const B_CBRT: f64 = 1.177_591_843_000_480_9;
    (fourth_root + B_CBRT).min(XC + fold_root)
}

/// One branch-free Newton step on `f(x) = x^4 - b x - Dbar`: the new
/// iterate (unchanged where `f'(x) <= 0`) and whether to go on (the step
/// exceeded `4 eps x`). Shared by the scalar and the batch solve, which are
/// therefore equal bit for bit.
#[inline(always)]
fn newton_step(x: f64, d: f64) -> (f64, bool) {
    let x2 = x * x;
    let f = x2 * x2 - B * x - d;
    let fp = 4.0 * x2 * x - B;
    let descends = !(fp <= 0.0);
    let step = f / fp;
    let next = x - step;
    let more = !(step.abs() <= 4.0 * f64::EPSILON * next);
    if descends {
        (next, descends && more)
    } else {
        (x, false)
    }
}

/// `A = max(x, x_c)^2` from the root `x = sqrt(A)`.
#[inline(always)]
fn radius_from_root(x: f64) -> f64 {
    x.max(XC) * x.max(XC)
}

/// Lanes solved together by [`Jkr::state_batch`]: four AVX-512 vectors, so
/// the divisions of one hide the latency of the others (measured: 16 lanes
/// 10.0, 32 lanes 7.4, 64 lanes 7.5-8.0 ns per summit).
const GROUP: usize = 32;

/// The stable JKR roots of a group in SIMD lanes: for each lane with
/// `live` set, `(A, Pbar)` of [`stable_radius_bar`]`(d)` and [`load_bar`]
/// bit for bit (the same start, the same Newton steps); other lanes hold
/// no meaning.
#[inline(always)]
fn group_roots<S: pulp::Simd>(
    simd: S,
    d: &[f64; GROUP],
    mut live: [bool; GROUP],
) -> ([f64; GROUP], [f64; GROUP]) {
    // newton_start, with its square roots in SIMD lanes.
    let (mut bound, mut fold) = ([0.0; GROUP], [0.0; GROUP]);
    for j in 0..GROUP {
        (bound[j], fold[j]) = start_radicands(d[j]);
    }
    sqrt_lanes(simd, &mut bound);
    sqrt_lanes(simd, &mut bound);
    sqrt_lanes(simd, &mut fold);
    let mut x = [0.0; GROUP];
    for j in 0..GROUP {
        x[j] = start_from_roots(bound[j], fold[j]);
        bound[j] = d[j] + B * x[j];
    }
    sqrt_lanes(simd, &mut bound);
    sqrt_lanes(simd, &mut bound);
    for j in 0..GROUP {
        x[j] = x[j].min(bound[j]);
    }
    for _ in 0..MAX_NEWTON {
        let mut any = false;
        for j in 0..GROUP {
            let (next, more) = newton_step(x[j], d[j]);
            x[j] = if live[j] { next } else { x[j] };
            live[j] &= more;
            any |= live[j];
        }
        if !any {
            break;
        }
    }
    // load_bar(A) = A^3 - sqrt(6 A^3), the root in SIMD lanes.
    let (mut a, mut a3, mut root) = ([0.0; GROUP], [0.0; GROUP], [0.0; GROUP]);
    for j in 0..GROUP {
        a[j] = radius_from_root(x[j]);
        a3[j] = a[j] * a[j] * a[j];
        root[j] = 6.0 * a3[j];
    }
    sqrt_lanes(simd, &mut root);
    for j in 0..GROUP {
        a3[j] -= root[j];
    }
    (a, a3)
}

/// JKR states of asperities with their own scales (a plastic summit's
/// flattened shape): state `i` is `(Pbar(A) * words[i][2], A * words[i][3])`
/// with `A` = [`stable_radius_bar`]`((delta[i] - words[i][0]) / words[i][1])`,
/// free where that has no root (NaN words included); in SIMD lanes, bit
/// for bit the scalar formulas. Words as
/// [`AdhesivePlastic::prepare_after`](crate::law::LawKernels::prepare_after).
pub(crate) struct JkrShapesBatch<'a> {
    pub delta: &'a [f64],
    pub words: &'a [crate::law::Prepared],
    pub load: &'a mut [f64],
    pub radius: &'a mut [f64],
}

impl pulp::WithSimd for JkrShapesBatch<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, simd: S) {
        let n = self
            .delta
            .len()
            .min(self.words.len())
            .min(self.load.len())
            .min(self.radius.len());
        let mut start = 0;
        while start < n {
            let len = GROUP.min(n - start);
            let (mut d, mut live) = ([0.0; GROUP], [false; GROUP]);
            for j in 0..len {
                let w = &self.words[start + j];
                let dbar = (self.delta[start + j] - w[0]) / w[1];
                live[j] = dbar >= JUMP_OUT_INTERFERENCE;
                d[j] = if live[j] { dbar } else { 0.0 };
            }
            let (a, pbar) = group_roots(simd, &d, live);
            for j in 0..len {
                let w = &self.words[start + j];
                (self.load[start + j], self.radius[start + j]) = if live[j] {
                    (pbar[j] * w[2], a[j] * w[3])
                } else {
                    (0.0, 0.0)
                };
            }
            start += len;
        }
    }
}

/// [`Jkr::state_batch`] as a [`pulp::WithSimd`] operation (compiled for the
/// widest SIMD the CPU has): per group of [`GROUP`] asperities, masked
/// Newton iterations until every lane has stopped; each lane takes exactly
/// the steps of [`stable_radius_bar`].
struct JkrBatch<'a> {
    scales: MaugisScales,
    delta: &'a [f64],
    delta_max: Option<&'a [f64]>,
    load: &'a mut [f64],
    radius: &'a mut [f64],
}

impl pulp::WithSimd for JkrBatch<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, simd: S) {
        let s = self.scales;
        let n = self.delta.len().min(self.load.len()).min(self.radius.len());
        let n = self.delta_max.map_or(n, |m| n.min(m.len()));
        let mut start = 0;
        while start < n {
            let len = GROUP.min(n - start);
            // Padded to a whole group (free lanes), so every loop below
            // runs over GROUP lanes and vectorises.
            let mut delta = [-1.0; GROUP];
            let mut maximum = [-1.0; GROUP];
            delta[..len].copy_from_slice(&self.delta[start..start + len]);
            if let Some(m) = self.delta_max {
                maximum[..len].copy_from_slice(&m[start..start + len]);
            }
            let mut d = [0.0; GROUP];
            let mut live = [false; GROUP];
            for j in 0..GROUP {
                // Approach: free below touching; retraction from a
                // touching maximum follows the attached branch.
                let attached = !(delta[j] < 0.0) || maximum[j] >= 0.0;
                let dbar = delta[j] / s.interference;
                live[j] = attached && dbar >= JUMP_OUT_INTERFERENCE;
                d[j] = if live[j] { dbar } else { 0.0 };
            }
            let ok = live;
            let (a, pbar) = group_roots(simd, &d, live);
            let (mut p, mut r) = ([0.0; GROUP], [0.0; GROUP]);
            for j in 0..GROUP {
                p[j] = if ok[j] { pbar[j] * s.load } else { 0.0 };
                r[j] = if ok[j] { a[j] * s.radius } else { 0.0 };
            }
            self.load[start..start + len].copy_from_slice(&p[..len]);
            self.radius[start..start + len].copy_from_slice(&r[..len]);
            start += len;
        }
    }
}

/// JKR law for a sphere of radius `R` (m), contact modulus `E*` (Pa) and
/// work of adhesion `w` (J/m^2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jkr {
    scales: MaugisScales,
}

impl Jkr {
    /// All arguments finite and > 0 (use [`super::Hertz`] when `w = 0`).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `radius`, `contact_modulus` or
    /// `work_of_adhesion`.
    pub fn new(radius: f64, contact_modulus: f64, work: f64) -> Result<Self> {
        Ok(Jkr {
            scales: MaugisScales::new(radius, contact_modulus, work)?,
        })
    }

    /// The Maugis scales of this contact.
    pub fn scales(&self) -> MaugisScales {
        self.scales
    }

    #[inline]
    fn attached(&self, delta: f64) -> ContactState {
        match stable_radius_bar(delta / self.scales.interference) {
            Some(a) => ContactState {
                load: load_bar(a) * self.scales.load,
                radius: a * self.scales.radius,
            },
            None => ContactState::FREE,
        }
    }
}

impl AsperityLaw for Jkr {
    identity_of_kind!(Jkr);

    #[inline]
    fn state(&self, delta: f64, branch: Branch) -> ContactState {
        match branch {
            Branch::Approach if delta < 0.0 => ContactState::FREE,
            _ => self.attached(delta),
        }
    }

    fn attach_interference(&self) -> f64 {
        0.0
    }

    fn detach_interference(&self) -> f64 {
        JUMP_OUT_INTERFERENCE * self.scales.interference
    }

    cutoff_at_detach!();

    fn pull_off(&self, control: Control) -> Option<Instability> {
        let s = self.scales;
        let (a, p) = match control {
            Control::Load => (PULL_OFF_RADIUS, PULL_OFF_LOAD),
            Control::Displacement => (JUMP_OUT_RADIUS, JUMP_OUT_LOAD),
        };
        Some(Instability {
            load: p * s.load,
            interference: interference_bar(a) * s.interference,
            radius: a * s.radius,
        })
    }

    fn zero_load_radius(&self) -> Option<f64> {
        Some(ZERO_LOAD_RADIUS * self.scales.radius)
    }
}

impl LawKernels for Jkr {
    fn cost_ns(&self) -> f64 {
        super::LawKind::Jkr.cost_ns()
    }

    /// Newton in SIMD lanes: 14.7 ns per evaluation on the `soft-jkr`
    /// populations (`examples/population_cost.rs`).
    fn batch_cost_ns(&self) -> f64 {
        15.0
    }

    /// The stable branch's load falls to `-(3/2) pi w R` (load-controlled
    /// pull-off), then rises to the jump-out; a summit that never touched
    /// stays free.
    fn retraction_minimum(&self, delta_max: f64) -> Option<super::RetractionMinimum> {
        if delta_max < self.attach_interference() {
            return Some(super::RetractionMinimum::MONOTONE);
        }
        self.pull_off(Control::Load).map(Into::into)
    }

    /// Masked Newton iterations on groups of asperities in SIMD lanes
    /// (`JkrBatch`), bit for bit [`state`](AsperityLaw::state) /
    /// [`state_after`](AsperityLaw::state_after).
    fn state_batch(
        &self,
        delta: &[f64],
        delta_max: Option<&[f64]>,
        load: &mut [f64],
        radius: &mut [f64],
    ) {
        crate::numeric::simd::arch().dispatch(JkrBatch {
            scales: self.scales,
            delta,
            delta_max,
            load,
            radius,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants_match_their_formulas() {
        assert!((B - (8.0f64 / 3.0).sqrt()).abs() < 1e-16);
        assert!(((8.0f64 / 3.0).powf(1.0 / 6.0) - 1.177_591_843_000_480_9).abs() < 3e-16);
        // powf is good to ~1 ulp (1.1e-16 here).
        assert!((JUMP_OUT_RADIUS - 6f64.powf(-1.0 / 3.0)).abs() < 3e-16);
        assert!((ZERO_LOAD_RADIUS - 6f64.cbrt()).abs() < 1e-15);
        assert!((PULL_OFF_RADIUS - 1.5f64.cbrt()).abs() < 1e-15);
        assert!((JUMP_OUT_RADIUS.sqrt() - 6f64.powf(-1.0 / 6.0)).abs() < 3e-16);
        let dc = -0.75 * (4.0f64 / 3.0).powf(2.0 / 3.0);
        assert!((JUMP_OUT_INTERFERENCE - dc).abs() < 1e-15);
        assert!((interference_bar(JUMP_OUT_RADIUS) - dc).abs() < 1e-15);
        assert!((load_bar(JUMP_OUT_RADIUS) - JUMP_OUT_LOAD).abs() < 1e-15);
        assert!((load_bar(PULL_OFF_RADIUS) - PULL_OFF_LOAD).abs() < 1e-15);
        assert!(load_bar(ZERO_LOAD_RADIUS).abs() < 1e-14);
    }

    #[test]
    fn radius_inverts_interference_on_stable_branch() {
        // A from just above the fold to deep contact; round trip to ~1e-15
        // except near the fold, where the root is ill-conditioned:
        // dA ~ dD / (dD/dA) and dD/dA -> 0.
        let mut a = JUMP_OUT_RADIUS * (1.0 + 1e-6);
        while a < 1e4 {
            let d = interference_bar(a);
            let back = stable_radius_bar(d).unwrap();
            let slope = 2.0 * a - 0.5 * B / a.sqrt();
            let tol = 4e-16 * (1.0 + d.abs()) / slope + 1e-15 * a;
            assert!((back - a).abs() <= tol, "A {a}: got {back}, tol {tol}");
            a *= 1.07;
        }
        assert!(stable_radius_bar(JUMP_OUT_INTERFERENCE - 1e-12).is_none());
        assert!(stable_radius_bar(f64::NAN).is_none());
        let at_fold = stable_radius_bar(JUMP_OUT_INTERFERENCE).unwrap();
        assert!((at_fold - JUMP_OUT_RADIUS).abs() < 1e-7);
    }

    #[test]
    fn dimensional_law_matches_textbook_formulas() {
        let (r, e, w) = (1e-6, 5e10, 0.5);
        let jkr = Jkr::new(r, e, w).unwrap();
        let k = 4.0 * e / 3.0;
        for a in [2e-8, 5e-8, 1e-7, 3e-7] {
            let delta = a * a / r - (8.0 * std::f64::consts::PI * w * a / (3.0 * k)).sqrt();
            let p = k * a.powi(3) / r - (6.0 * std::f64::consts::PI * w * k * a.powi(3)).sqrt();
            let s = jkr.state(delta, Branch::Retract);
            if a >= JUMP_OUT_RADIUS * jkr.scales().radius {
                assert!((s.radius / a - 1.0).abs() < 1e-10, "{a}");
                assert!((s.load - p).abs() < 1e-10 * p.abs().max(jkr.scales().load));
            }
        }
        let pull = jkr.pull_off(Control::Displacement).unwrap();
        let dc = -0.75 * (std::f64::consts::PI.powi(2) * w * w * r / (e * e)).cbrt();
        assert!((pull.interference / dc - 1.0).abs() < 1e-14);
    }
}
