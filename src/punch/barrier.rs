//! Potential energy at fixed depth (paper eq. 4.14) and the energy barriers between
//! neighbouring equilibria.
//!
//! `Pi(a, h) = (pi^2 E*/4) int_0^a psi(t, h)^2 dt - pi w a^2` with
//! `psi(t, h) = (2/pi)(h - t^2/R - pi^2 A t H0(2 pi t/l))` (eq. 4.15), so
//! `dPi/da = E* (h - a^2/R - pi^2 A a H0(2 pi a/l))^2 - 2 pi w a`, zero exactly at the
//! equilibria `h = h(a)`. Equilibria on rising pieces of `h(a)` are minima of `Pi` (stable),
//! on falling pieces maxima (eq. A.1). The barrier from a stable radius to a neighbouring
//! unstable one is `Pi(a_u, h) - Pi(a_s, h) = int_as^au dPi/da da`. At `h = 0` and small `l`
//! (eq. 4.16) `Pi(a, 0) ~ E* a^5/(5R^2) - pi w a^2 + pi^2 E* A^2 a^2 l/4 + 2 E* A a^3 l/(3R)
//! - (E* A/R) a^(5/2) l^(3/2) sin(2 pi a/l + pi/4)`, whence the scale
//! `dPi ~ E* A l^(3/2) a^(5/2)/R` (eq. 4.17; signs re-derived).

use super::landscape::{KnotKind, Landscape};
use super::WavyPunch;
use crate::error::{finite, positive, Result};
use crate::numeric::quadrature::kronrod21;
use crate::numeric::roots::brent;
use crate::special::struve::struve_h0;
use std::f64::consts::PI;

/// One equilibrium at a fixed depth.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Equilibrium {
    /// Contact radius (m).
    pub radius: f64,
    /// Whether it is a local minimum of the potential energy (`dh/da > 0`).
    pub stable: bool,
}

/// The energy barrier between a stable equilibrium and a neighbouring unstable one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Barrier {
    /// Stable radius (m).
    pub stable: f64,
    /// The neighbouring unstable radius (m), smaller or larger.
    pub unstable: f64,
    /// `Pi(unstable) - Pi(stable) >= 0` (J).
    pub energy: f64,
}

impl WavyPunch {
    /// `dPi/da` at fixed depth `h` (N): `E* (h - a^2/R - pi^2 A a H0(2 pi a/l))^2 - 2 pi w a`.
    pub fn potential_slope(&self, a: f64, h: f64) -> f64 {
        let x = 2.0 * PI * a / self.wavelength();
        let g = h - a * a / self.radius() - PI * PI * self.amplitude() * a * struve_h0(x);
        self.estar() * g * g - 2.0 * PI * self.w() * a
    }

    /// Potential energy `Pi(a, h)` (J) of eq. 4.14, by quadrature of `dPi/da` from 0
    /// (panels of at most `l/8`, 21-point Gauss–Kronrod).
    pub fn potential(&self, a: f64, h: f64) -> f64 {
        self.potential_change(0.0, a, h)
    }

    /// `Pi(a1, h) - Pi(a0, h)` (J).
    pub fn potential_change(&self, a0: f64, a1: f64, h: f64) -> f64 {
        let (lo, hi, s) = if a1 >= a0 {
            (a0, a1, 1.0)
        } else {
            (a1, a0, -1.0)
        };
        let mut f = |t: f64| self.potential_slope(t, h);
        let (mut a, mut sum) = (lo, 0.0);
        while a < hi {
            let b = (a + self.wavelength() / 8.0).min(hi);
            sum += kronrod21(&mut f, a, b).0;
            a = b;
        }
        s * sum
    }

    /// Every equilibrium at depth `h` with radius in `(0, a_hi]`, in order of radius.
    ///
    /// # Errors
    /// Non-finite `h` or non-positive `a_hi` (naming `depth`, `radius`); a range too long to
    /// scan (see [`Landscape::scan_to_radius`]).
    pub fn equilibria(&self, h: f64, a_hi: f64) -> Result<Vec<Equilibrium>> {
        finite("depth", h)?;
        positive("radius", a_hi)?;
        let land = Landscape::scan_to_radius(self, a_hi)?;
        let k = land.knots();
        let mut out = Vec::new();
        for w in k.windows(2) {
            let (p, q) = (w[0].state, w[1].state);
            let (lo, hi) = (p.depth.min(q.depth), p.depth.max(q.depth));
            if !(h > lo && h <= hi) || (w[0].kind == KnotKind::Origin && h >= 0.0) {
                continue;
            }
            let f = |a: f64| self.depth(a) - h;
            if let Some(a) = brent(f, p.radius, q.radius, 1e-15 * q.radius) {
                out.push(Equilibrium {
                    radius: a,
                    stable: q.depth > p.depth,
                });
            }
        }
        Ok(out)
    }

    /// The barriers between each stable equilibrium at depth `h` (radius up to `a_hi`) and
    /// its unstable neighbours.
    ///
    /// # Errors
    /// As [`WavyPunch::equilibria`].
    pub fn barriers(&self, h: f64, a_hi: f64) -> Result<Vec<Barrier>> {
        let eq = self.equilibria(h, a_hi)?;
        let mut out = Vec::new();
        for (i, e) in eq.iter().enumerate() {
            if !e.stable {
                continue;
            }
            let left = i.checked_sub(1).map(|j| eq[j]);
            for n in [left, eq.get(i + 1).copied()].into_iter().flatten() {
                if !n.stable {
                    out.push(Barrier {
                        stable: e.radius,
                        unstable: n.radius,
                        energy: self.potential_change(e.radius, n.radius, h),
                    });
                }
            }
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equilibria_are_stationary_points_and_barriers_positive() {
        let p = WavyPunch::new(1.0, 0.05 / (2.0 * PI), 1.0, 0.14, 0.1).unwrap();
        let eq = p.equilibria(0.0, 0.6).unwrap();
        assert!(eq.len() >= 3, "{eq:?}");
        for e in &eq {
            let s = p.potential_slope(e.radius, 0.0);
            assert!(s.abs() < 1e-10, "{e:?}: {s}");
        }
        let b = p.barriers(0.0, 0.6).unwrap();
        assert!(!b.is_empty());
        for x in &b {
            assert!(x.energy > 0.0, "{x:?}");
        }
    }
}
