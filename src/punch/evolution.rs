//! The contact radius under displacement control (paper section 3, eqs. 3.6-3.8) and the
//! energy lost per cycle.
//!
//! Loading: `a_+(h) = min{a > 0 : h(a) = h}` for `h > 0`, detached (`a = 0`, `P = 0`) for
//! `h <= 0`. The radius grows continuously along rising (stable, `dh/da > 0`) pieces and
//! jumps forward at the maxima of `h(a)` whose depth is a new record. Unloading from the
//! deepest depth `h_max` (radius `a_max = a_+(h_max)`):
//! `a_-(h) = max{a <= a_max : h(a) = h}` while `h >= min_[0, a_max] h`, detached below; the
//! radius jumps back at the minima of `h(a)` that are new record lows seen from `a_max`.
//! Both rules pick a root on a rising piece, so every state on either path is stable.
//!
//! The energy lost per cycle between `h_min` and `h_max` is
//! `int_hmin^hmax P_load dh - int_hmin^hmax P_unload dh`, the area between the two paths.
//! On each continuous stretch `a` moves monotonically, so the integral is taken in `a`,
//! `int P(a) h'(a) da`, split at the folds (where the paths jump) and into panels of at most
//! `l/8`, each by 21-point Gauss–Kronrod: relative error near 1e-13.

use super::landscape::{Knot, Landscape};
use super::{PunchState, WavyPunch};
use crate::error::{finite, Result};
use crate::numeric::quadrature::kronrod21;
use crate::numeric::roots::brent;

/// The loading and unloading paths of one displacement-controlled cycle to `h_max`.
#[derive(Debug, Clone)]
pub struct Evolution {
    punch: WavyPunch,
    /// Folds from the origin to `a_max` (the last is the state at `a_max`).
    knots: Vec<PunchState>,
    /// Running maximum of the knots' depths.
    run_max: Vec<f64>,
    /// Minimum of the depths of knots `i..` (knot 0, the origin, excluded: index 0 unused).
    suffix_min: Vec<f64>,
    h_max: f64,
}

/// A stretch of a path along which the radius moves continuously, `a` from `from` to `to`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stretch {
    /// Radius where the stretch starts (m).
    pub from: f64,
    /// Radius where it ends (m).
    pub to: f64,
}

impl Evolution {
    /// The paths of a cycle whose deepest depth is `h_max` (m, any sign; for `h_max <= 0` the
    /// punch never touches).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `depth` when `h_max` is not finite; the
    /// landscape scan's refusals ([`Landscape::scan`]: `depth`, `w`, `wavelength`, `punch`);
    /// [`crate::Error::Invalid`] when it is too deep to scan (see [`Landscape::scan`]).
    pub fn new(punch: &WavyPunch, h_max: f64) -> Result<Self> {
        finite("depth", h_max)?;
        let mut knots = Vec::new();
        if h_max > 0.0 {
            let land = Landscape::scan(punch, h_max)?;
            let k: Vec<PunchState> = land.knots().iter().map(|k: &Knot| k.state).collect();
            // First knot at or above h_max: the root lies on the rising piece before it.
            let j = k
                .iter()
                .position(|s| s.depth >= h_max)
                .unwrap_or(k.len() - 1);
            let a_max = root_between(punch, &k[j - 1], &k[j], h_max);
            knots.extend_from_slice(&k[..j]);
            knots.push(PunchState {
                depth: h_max,
                ..punch.state(a_max)
            });
        }
        let mut run_max = Vec::with_capacity(knots.len());
        let mut m = f64::NEG_INFINITY;
        for s in &knots {
            m = m.max(s.depth);
            run_max.push(m);
        }
        let mut suffix_min = vec![f64::INFINITY; knots.len()];
        let mut m = f64::INFINITY;
        for i in (1..knots.len()).rev() {
            m = m.min(knots[i].depth);
            suffix_min[i] = m;
        }
        Ok(Evolution {
            punch: *punch,
            knots,
            run_max,
            suffix_min,
            h_max,
        })
    }

    /// The deepest depth `h_max` (m).
    pub fn h_max(&self) -> f64 {
        self.h_max
    }

    /// The state at `h_max` (radius `a_max`); detached if `h_max <= 0`.
    pub fn deepest(&self) -> PunchState {
        self.knots
            .last()
            .copied()
            .unwrap_or(self.detached(self.h_max))
    }

    /// The last contact state of unloading: the record-low minimum of `h(a)` below `a_max`
    /// where the contact snaps off (pull-off under displacement control). `None` if the
    /// punch never touched.
    pub fn detach(&self) -> Option<PunchState> {
        let lo = *self.suffix_min.get(1)?;
        self.knots[1..].iter().copied().find(|s| s.depth == lo)
    }

    /// Loading state at depth `h <= h_max` (clamped to `h_max`): the smallest root of
    /// `h(a) = h` for `h > 0`, detached otherwise.
    pub fn loading(&self, h: f64) -> PunchState {
        let h = h.min(self.h_max);
        if !(h > 0.0) || self.knots.is_empty() {
            return self.detached(h);
        }
        let j = self.run_max.partition_point(|&m| m < h).max(1);
        let j = j.min(self.knots.len() - 1);
        let a = root_between(&self.punch, &self.knots[j - 1], &self.knots[j], h);
        self.state_at(a, h)
    }

    /// Unloading state at depth `h <= h_max` (clamped): the largest root of `h(a) = h` not
    /// beyond `a_max`, detached below the pull-off depth.
    pub fn unloading(&self, h: f64) -> PunchState {
        let h = h.min(self.h_max);
        let n = self.knots.len();
        if n < 2 || h < self.suffix_min[1] {
            return self.detached(h);
        }
        let i = self.suffix_min[1..].partition_point(|&m| m <= h); // knots 1..=i have min <= h
        if i >= n - 1 {
            return self.deepest();
        }
        let a = root_between(&self.punch, &self.knots[i], &self.knots[i + 1], h);
        self.state_at(a, h)
    }

    /// The stretches of the loading path with depth in `[h_lo, h_hi]` (in order).
    pub fn loading_stretches(&self, h_lo: f64, h_hi: f64) -> Vec<Stretch> {
        let mut out = Vec::new();
        for j in 1..self.knots.len() {
            let top = self.knots[j].depth;
            let prev = self.run_max[j - 1].max(0.0);
            if top <= prev {
                continue;
            }
            let (lo, hi) = (prev.max(h_lo), top.min(h_hi).min(self.h_max));
            if hi > lo {
                let (p, q) = (&self.knots[j - 1], &self.knots[j]);
                out.push(Stretch {
                    from: root_between(&self.punch, p, q, lo),
                    to: root_between(&self.punch, p, q, hi),
                });
            }
        }
        out
    }

    /// The stretches of the unloading path with depth in `[h_lo, h_hi]`, in the order the
    /// path runs (from `a_max` down).
    pub fn unloading_stretches(&self, h_lo: f64, h_hi: f64) -> Vec<Stretch> {
        let mut out = Vec::new();
        let n = self.knots.len();
        for i in (1..n.saturating_sub(1)).rev() {
            let (bottom, top) = (self.knots[i].depth, self.suffix_min[i + 1]);
            if bottom >= top {
                continue;
            }
            let (lo, hi) = (bottom.max(h_lo), top.min(h_hi));
            if hi > lo {
                let (p, q) = (&self.knots[i], &self.knots[i + 1]);
                out.push(Stretch {
                    from: root_between(&self.punch, p, q, hi),
                    to: root_between(&self.punch, p, q, lo),
                });
            }
        }
        out
    }

    /// Energy lost in a displacement-controlled cycle from `h_min` to `h_max` and back (J):
    /// `int P_load dh - int P_unload dh` over `[h_min, h_max]`.
    pub fn energy_loss(&self, h_min: f64) -> f64 {
        let load: f64 = self
            .loading_stretches(h_min, self.h_max)
            .iter()
            .map(|s| self.work(s.from, s.to))
            .sum();
        let unload: f64 = self
            .unloading_stretches(h_min, self.h_max)
            .iter()
            .map(|s| self.work(s.to, s.from))
            .sum();
        load - unload
    }

    /// `int_a0^a1 P(a) h'(a) da` along the equilibrium curve (J), panels of at most `l/8`.
    pub fn work(&self, a0: f64, a1: f64) -> f64 {
        work_between(&self.punch, a0, a1)
    }

    fn detached(&self, h: f64) -> PunchState {
        PunchState {
            radius: 0.0,
            depth: h,
            load: 0.0,
        }
    }

    fn state_at(&self, a: f64, h: f64) -> PunchState {
        PunchState {
            depth: h,
            ..self.punch.state(a)
        }
    }
}

/// `int_a0^a1 P(a) h'(a) da` (J) by 21-point Gauss–Kronrod panels of at most
/// `min(l/8, a/2)` (the integrand has period `l` and a `sqrt(a)` singularity at 0).
pub(crate) fn work_between(punch: &WavyPunch, a0: f64, a1: f64) -> f64 {
    let (lo, hi, sign) = if a1 >= a0 {
        (a0, a1, 1.0)
    } else {
        (a1, a0, -1.0)
    };
    let mut f = |a: f64| punch.load(a) * punch.depth_slope(a);
    let mut sum = 0.0;
    let mut a = lo;
    while a < hi {
        let width = (punch.wavelength() / 8.0).min(0.5 * a.max(hi * 1e-3));
        let b = (a + width).min(hi);
        sum += kronrod21(&mut f, a, b).0;
        a = b;
    }
    sign * sum
}

/// The root of `h(a) = h` between two knots on a monotone piece.
fn root_between(punch: &WavyPunch, p: &PunchState, q: &PunchState, h: f64) -> f64 {
    if h == p.depth {
        return p.radius;
    }
    if h == q.depth {
        return q.radius;
    }
    let f = |a: f64| punch.depth(a) - h;
    brent(f, p.radius, q.radius, 1e-15 * q.radius).unwrap_or_else(|| {
        if (h - p.depth).abs() < (h - q.depth).abs() {
            p.radius
        } else {
            q.radius
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn fig3() -> WavyPunch {
        WavyPunch::new(1.0, 0.05 / (2.0 * PI), 1.0, 0.1, 0.03).unwrap()
    }

    #[test]
    fn paths_are_stable_monotone_and_meet_at_the_ends() {
        let p = fig3();
        let ev = Evolution::new(&p, 0.12).unwrap();
        let mut last = (0.0, 0.0);
        for i in 0..=400 {
            let h = -0.05 + 0.17 * i as f64 / 400.0;
            let (l, u) = (ev.loading(h), ev.unloading(h));
            for s in [l, u] {
                if s.radius > 0.0 {
                    assert!(p.depth_slope(s.radius) >= -1e-9, "unstable at h {h}");
                    assert!((p.depth(s.radius) - h).abs() < 1e-12);
                }
            }
            assert!(
                l.radius >= last.0 && u.radius >= last.1,
                "not monotone at {h}"
            );
            assert!(
                u.radius >= l.radius,
                "unloading radius below loading at {h}"
            );
            last = (l.radius, u.radius);
        }
        assert_eq!(ev.loading(0.12), ev.unloading(0.12));
        assert_eq!(ev.loading(-0.01).radius, 0.0);
        assert!(ev.unloading(-0.01).radius > 0.0);
        assert!(ev.energy_loss(-0.1) > 0.0);
    }
}
