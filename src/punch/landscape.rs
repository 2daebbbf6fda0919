//! The folds of the exact curve `h(a)`: its local minima and maxima, in order of radius.
//!
//! Between consecutive folds `h(a)` is monotone, so every question the evolution asks
//! ("the smallest root of `h(a) = h`", "the largest root below `a_max`") becomes a search
//! over the fold values plus one bracketed root. Folds are found by scanning `dh/da` on a
//! grid of step `min(l/48, a_J/16)` (`a_J` the JKR jump-out radius) and refining each sign
//! change by Brent's method to `1e-15 a`. Two folds closer than one step (a near-tangency,
//! where the curve barely folds) can be missed; the jump they would make changes the depth by
//! less than `max |h''| step^2`, a few 1e-4 of the oscillation amplitude.

use super::{PunchState, WavyPunch};
use crate::error::{Error, Result};
use crate::numeric::roots::brent;

/// Most grid points one scan may take (about 1.5 s of work).
const MAX_STEPS: usize = 20_000_000;

/// The grid the scan to depth `h_stop` takes, estimated before it
/// starts: `(steps, step, a_end)`, with the step `min(l/48, a_J/16)` and
/// the end radius `a_end = sqrt(R h_stop) + (2 pi w R^2/E*)^(1/3)` (past
/// both the smooth punch's zero-depth radius and the Hertz radius of
/// `h_stop`, ignoring the roughness, so a lower estimate).
pub fn scan_estimate(punch: &WavyPunch, h_stop: f64) -> (f64, f64, f64) {
    let step = (punch.wavelength() / 48.0).min(punch.jkr_detach_radius() / 16.0);
    let r = punch.radius();
    let zero_depth = (2.0 * std::f64::consts::PI * punch.w() * r * r / punch.estar()).cbrt();
    let a_end = (r * h_stop.max(0.0)).sqrt() + zero_depth;
    (a_end / step, step, a_end)
}

/// Refuses a scan estimated beyond [`MAX_STEPS`] before it starts, naming
/// what sets the count: `w` when the step is the JKR jump-out radius's
/// (adhesion too weak: a tiny `a_J`) or the end is adhesion's zero-depth
/// radius (adhesion too strong), `depth` for a depth beyond the radius of
/// curvature, `punch` when its scales overflow, else `wavelength` (too
/// short for the contact's size).
fn check_scan(punch: &WavyPunch, h_stop: f64) -> Result<()> {
    let (steps, step, a_end) = scan_estimate(punch, h_stop);
    if !steps.is_nan() && steps <= MAX_STEPS as f64 {
        return Ok(());
    }
    let r = punch.radius();
    let a_j = punch.jkr_detach_radius();
    let hertz = (r * h_stop.max(0.0)).sqrt();
    let (name, why) = if !(a_end.is_finite() && step > 0.0) {
        ("punch", "the punch's scales overflow")
    } else if a_j / 16.0 < punch.wavelength() / 48.0 {
        (
            "w",
            "the JKR jump-out radius a_J sets the step (a_J/16): adhesion too weak",
        )
    } else if hertz < a_end - hertz {
        (
            "w",
            "the contact radius is set by adhesion: adhesion too strong",
        )
    } else if h_stop > r {
        ("depth", "the depth is beyond the radius of curvature")
    } else {
        (
            "wavelength",
            "the wavelength sets the step (l/48): too short for the contact",
        )
    };
    Err(Error::invalid(
        name,
        format!(
            "the scan of the wavy curve to depth {h_stop:e} m (contact radius ~{a_end:.3e} m, \
             step {step:.3e} m) needs an estimated {steps:.3e} grid points, allowed up to \
             {MAX_STEPS}: {why} (adhesion number 2 pi w/(E* R) = {:.3e}, a_J = {a_j:.3e} m, \
             l = {:e} m, R = {r:e} m)",
            punch.adhesion_number(),
            punch.wavelength()
        ),
    ))
}

/// What a knot of the landscape is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KnotKind {
    /// `a = 0`, `h = 0`, `P = 0`.
    Origin,
    /// A local minimum of `h(a)` (a fold where unloading jumps).
    Minimum,
    /// A local maximum of `h(a)` (a fold where loading jumps).
    Maximum,
    /// The end of the scan (`h` there is at least the depth asked for).
    End,
}

/// One knot: a fold of `h(a)` or an end of the scanned range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Knot {
    /// Kind of point.
    pub kind: KnotKind,
    /// The exact state there.
    pub state: PunchState,
}

/// The folds of `h(a)` from `a = 0` until `h(a)` first reaches a given depth.
#[derive(Debug, Clone)]
pub struct Landscape {
    knots: Vec<Knot>,
}

impl Landscape {
    /// Scans `h(a)` from 0 until the first radius where `h(a) >= h_stop` is certain (a grid
    /// point or a maximum at or above `h_stop`); the last knot is that point.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `depth` when `h_stop` needs more than 2e7 grid points
    /// (a depth far beyond the punch's scale); estimated before the scan
    /// ([`scan_estimate`]), naming `w` (adhesion too weak or too strong for
    /// the grid), `wavelength` or `depth`, whichever sets the count.
    pub fn scan(punch: &WavyPunch, h_stop: f64) -> Result<Self> {
        check_scan(punch, h_stop)?;
        Self::scan_until(punch, |s: &PunchState, rising| rising && s.depth >= h_stop).map_err(|n| {
            Error::invalid(
                "depth",
                format!("{h_stop:e} m needs more than {n} grid points of the wavy curve"),
            )
        })
    }

    /// Scans `h(a)` from 0 to radius `a_stop` (the last knot is at `a_stop`).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `radius` when `a_stop` needs more than 2e7 grid points.
    pub fn scan_to_radius(punch: &WavyPunch, a_stop: f64) -> Result<Self> {
        Self::scan_until(punch, |s: &PunchState, _| s.radius >= a_stop).map_err(|n| {
            Error::invalid(
                "radius",
                format!("{a_stop:e} m needs more than {n} grid points of the wavy curve"),
            )
        })
    }

    /// The scan: `stop(state, rising)` is asked at every maximum (`rising = true`, as the
    /// piece before it rises) and at every grid point (`rising` = `dh/da > 0` there).
    fn scan_until<F: FnMut(&PunchState, bool) -> bool>(
        punch: &WavyPunch,
        mut stop: F,
    ) -> std::result::Result<Self, usize> {
        let step = (punch.wavelength() / 48.0).min(punch.jkr_detach_radius() / 16.0);
        let origin = PunchState {
            radius: 0.0,
            depth: 0.0,
            load: 0.0,
        };
        let mut knots = vec![Knot {
            kind: KnotKind::Origin,
            state: origin,
        }];
        let slope = |a: f64| punch.depth_slope(a);
        // h' -> -inf as a -> 0: the first piece falls.
        let (mut a0, mut s0) = (step * 1e-6, slope(step * 1e-6));
        for i in 1..=MAX_STEPS {
            let a1 = step * i as f64;
            let s1 = slope(a1);
            if s0.signum() != s1.signum() && s1 != 0.0 {
                let a = brent(slope, a0, a1, 1e-15 * a1).unwrap_or(a1);
                let kind = if s1 > 0.0 {
                    KnotKind::Minimum
                } else {
                    KnotKind::Maximum
                };
                let state = punch.state(a);
                knots.push(Knot { kind, state });
                if kind == KnotKind::Maximum && stop(&state, true) {
                    return Ok(Landscape { knots });
                }
            }
            let state = punch.state(a1);
            if stop(&state, s1 > 0.0) {
                knots.push(Knot {
                    kind: KnotKind::End,
                    state,
                });
                return Ok(Landscape { knots });
            }
            (a0, s0) = (a1, s1);
        }
        Err(MAX_STEPS)
    }

    /// The knots in order of radius: the origin, alternating minima and maxima, the end
    /// (which may be a maximum).
    pub fn knots(&self) -> &[Knot] {
        &self.knots
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn knots_alternate_and_are_folds() {
        let p = WavyPunch::new(1.0, 0.05 / (2.0 * PI), 1.0, 0.1, 0.03).unwrap();
        let l = Landscape::scan(&p, 0.3).unwrap();
        let k = l.knots();
        assert_eq!(k[0].kind, KnotKind::Origin);
        assert_eq!(k[1].kind, KnotKind::Minimum);
        assert!(k.len() > 20, "{}", k.len());
        for w in k[1..k.len() - 1].windows(2) {
            assert_ne!(w[0].kind, w[1].kind);
            assert!(w[1].state.radius > w[0].state.radius);
        }
        for kn in &k[1..k.len() - 1] {
            assert!(p.depth_slope(kn.state.radius).abs() < 1e-9);
        }
        assert!(k.last().unwrap().state.depth >= 0.3);
    }
}
