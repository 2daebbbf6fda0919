//! JKR (short-range) adhesion for any axisymmetric profile (Barthel 2008,
//! eqs 5.6-5.7, with `calK = E*/2`):
//!
//! ```text
//! delta(a) = delta_0(a) - sqrt(2 pi w a / E*)
//! F(a)     = F_0(a)     - sqrt(8 pi E* w a^3)
//! ```
//!
//! parametric in the contact radius `a`. With `F_0' = 2 E* a delta_0'`:
//!
//! - load control: pull-off at the local minimum of `F`,
//!   `2 E* a delta_0'(a) = 3 sqrt(2 pi E* w a)`;
//! - displacement control: jump-out at the minimum of `delta`,
//!   `delta_0'(a) = sqrt(pi w / (2 E* a))`.
//!
//! For the power law `f = A r^n` (`delta_0 = k_n A a^n`, paraboloid and cone
//! included) both are closed forms, `a^(n-1/2) = c sqrt(2 pi w/E*) / (2 n k_n A)`
//! with `c = 3` (load) and `c = 1` (displacement); the cone gives
//! `a = 18 w/(pi E* tan^2 beta)` (load) and `2 w/(pi E* tan^2 beta)`
//! (displacement). For the flat punch the contact radius cannot grow past
//! `a0`: both controls give Kendall's pull-off `-sqrt(8 pi E* w a0^3)` at
//! `delta = -sqrt(2 pi w a0/E*)`, and the attached punch has stiffness
//! `2 E* a0`. Otherwise the instabilities are found by scanning for the
//! largest sign change of the derivative (the first instability met on
//! retraction from deep contact) and Brent's method.
//!
//! JKR needs `F` to turn up at large `a`: for `f = A r^n` that means
//! `n > 1/2` (for `n <= 1/2` adhesion wins at every radius and nothing
//! pulls off).

use super::profile::Profile;
use super::Instability;
use crate::error::{positive, Allowed, Error, Result};
use crate::numeric::roots::brent;
use std::f64::consts::PI;

/// JKR contact of one profile: contact modulus `E*` (Pa), work of adhesion
/// `w` (J/m^2), with its two instabilities found once.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisymJkr {
    profile: Profile,
    estar: f64,
    work: f64,
    pull_off: Instability,
    jump_out: Instability,
}

/// Which instability to find.
#[derive(Clone, Copy)]
enum Kind {
    Load,
    Displacement,
}

impl AxisymJkr {
    /// Builds the contact and finds its pull-off and jump-out.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `contact_modulus` (finite, > 0),
    /// `work_of_adhesion` (finite, >= 0; at `w = 0` both instabilities sit
    /// at `a = 0` with zero load: Sneddon's contact) or `exponent` (power
    /// law: > 1/2);
    /// [`Error::Invalid`] naming `profile` when a table ends before its
    /// pull-off.
    pub fn new(profile: Profile, contact_modulus: f64, work: f64) -> Result<Self> {
        let estar = positive("contact_modulus", contact_modulus)?;
        let work = crate::error::non_negative("work_of_adhesion", work)?;
        if let Profile::Power { exponent, .. } = profile {
            Allowed::open(0.5, f64::INFINITY).check("exponent", exponent)?;
        }
        let mut s = AxisymJkr {
            profile,
            estar,
            work,
            pull_off: Instability {
                load: 0.0,
                interference: 0.0,
                radius: 0.0,
            },
            jump_out: Instability {
                load: 0.0,
                interference: 0.0,
                radius: 0.0,
            },
        };
        s.pull_off = s.instability_at(s.critical_radius(Kind::Load)?);
        s.jump_out = s.instability_at(s.critical_radius(Kind::Displacement)?);
        let finite = |i: &Instability| {
            i.radius.is_finite() && i.load.is_finite() && i.interference.is_finite()
        };
        if s.work > 0.0 && finite(&s.pull_off) && !(s.pull_off.load < 0.0) {
            return Err(Error::invalid(
                "work_of_adhesion",
                format!(
                    "w = {:e} J/m^2 is too small for this {} profile in f64: its pull-off \
                     ({:e} N) is lost to underflow",
                    s.work,
                    s.profile.name(),
                    s.pull_off.load
                ),
            ));
        }
        if !(finite(&s.pull_off) && finite(&s.jump_out))
            || (s.work > 0.0 && !(s.pull_off.radius > 0.0))
        {
            // A power law with n just above 1/2 puts its instabilities
            // beyond the floating-point range.
            return Err(Error::invalid(
                "exponent",
                format!(
                    "the JKR instabilities of this {} profile fall outside the floating-point \
                     range (pull-off radius {} m)",
                    s.profile.name(),
                    s.pull_off.radius
                ),
            ));
        }
        Ok(s)
    }

    adhesive_profile_accessors!();

    /// Interference `delta(a) = delta_0(a) - sqrt(2 pi w a/E*)` (m).
    pub fn interference(&self, a: f64) -> f64 {
        // Square roots taken apart: `w a` and `E* w a^3` underflow for tiny
        // `w` (1e-200 J/m^2 gave a positive pull-off).
        self.profile.delta0(a) - (2.0 * PI * self.work / self.estar).sqrt() * a.sqrt()
    }

    /// Load `F(a) = F_0(a) - sqrt(8 pi E* w a^3)` (N).
    pub fn load(&self, a: f64) -> f64 {
        self.profile.load0(a, self.estar)
            - (8.0 * PI * self.estar * self.work).sqrt() * a * a.sqrt()
    }

    /// Load (N) and interference (m) at contact radius `a` (m), checked:
    /// `a` within the profile ([`Profile::check_radius`]) and both values
    /// finite (a paraboloid's load grows like `a^3` and overflows f64 past
    /// ~1e100 m).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `a` outside the profile or where a value
    /// overflows.
    pub fn point(&self, a: f64) -> Result<(f64, f64)> {
        let a = self.profile.check_radius("a", a)?;
        let (load, interference) = (self.load(a), self.interference(a));
        if load.is_finite() && interference.is_finite() {
            Ok((load, interference))
        } else {
            Err(Error::invalid(
                "a",
                format!(
                    "at a = {a:e} m the {} profile's load or interference overflows f64",
                    self.profile.name()
                ),
            ))
        }
    }

    /// `d delta/da` (dimensionless).
    pub fn interference_slope(&self, a: f64) -> f64 {
        self.profile.delta0_slope(a) - (0.5 * PI * self.work / (self.estar * a)).sqrt()
    }

    /// Energy release rate `G = (F_0(a) - F)^2 / (8 pi E* a^3)` at radius `a`
    /// under load `F` (J/m^2); equilibrium is `G = w` (Barthel section 5.1.3; Maugis & Barquins).
    pub fn release_rate(&self, a: f64, load: f64) -> f64 {
        let df = self.profile.load0(a, self.estar) - load;
        df * df / (8.0 * PI * self.estar * a * a * a)
    }

    /// Load-controlled pull-off: the most tensile load met on retraction.
    pub fn pull_off_load_control(&self) -> Instability {
        self.pull_off
    }

    /// Displacement-controlled jump-out: where the attached branch ends.
    pub fn jump_out_displacement_control(&self) -> Instability {
        self.jump_out
    }

    /// Radius, load and interference at contact radius `a`.
    pub fn instability_at(&self, a: f64) -> Instability {
        Instability {
            load: self.load(a),
            interference: self.interference(a),
            radius: a,
        }
    }

    /// Contact radius (m) on the attached (stable) branch at interference
    /// `delta` (m), or `None` below the jump-out. For the flat punch the
    /// radius is `a0`. For the sphere `delta -> inf` as `a -> R`; for a
    /// table the radius is capped at its last node.
    pub fn stable_radius(&self, delta: f64) -> Option<f64> {
        let j = self.jump_out;
        if !(delta >= j.interference) {
            return None;
        }
        if let Profile::Flat { radius } = self.profile {
            return Some(radius);
        }
        let max = self.profile.max_radius();
        let hi = if max.is_finite() {
            // The sphere's delta grows without bound as a -> R; a table is capped.
            let top = match self.profile {
                Profile::Sphere { .. } => max * (1.0 - 1e-15),
                _ => max,
            };
            if self.interference(top) <= delta {
                return Some(top);
            }
            top
        } else {
            let mut hi = if j.radius > 0.0 {
                2.0 * j.radius
            } else {
                1e-12
            };
            while self.interference(hi) < delta {
                hi *= 2.0;
            }
            hi
        };
        Some(self.solve_branch(delta, j.radius, hi))
    }

    /// Root of `delta(a) = target` in `[lo, hi]` (`delta(lo) <= target <=
    /// delta(hi)`): Newton with the analytic slope, kept inside a shrinking
    /// bracket by bisection (few evaluations, which matters for tables).
    fn solve_branch(&self, target: f64, lo: f64, hi: f64) -> f64 {
        if self.interference(lo) >= target {
            // At the fold itself (delta(a) - delta_c ~ (a - a_c)^2 there).
            return lo;
        }
        let (mut lo, mut hi) = (lo, hi);
        let mut x = 0.5 * (lo + hi);
        for _ in 0..200 {
            let r = self.interference(x) - target;
            if r == 0.0 {
                return x;
            }
            if r < 0.0 {
                lo = x;
            } else {
                hi = x;
            }
            let slope = self.interference_slope(x);
            let mut next = x - r / slope;
            if !(slope > 0.0 && next > lo && next < hi) {
                next = 0.5 * (lo + hi);
            }
            if (next - x).abs() <= 2.0 * f64::EPSILON * x || hi - lo <= 2.0 * f64::EPSILON * hi {
                return next;
            }
            x = next;
        }
        x
    }

    /// Contact radius (m) and load (N) on the attached branch at
    /// interference `delta` (m), or `None` below the jump-out. Where the
    /// contact radius reaches the end of a profile that ends in a wall (flat
    /// punch, a table: a tip on a cylinder of that radius) the contact
    /// stiffens as a punch: `F = F(a_max) + 2 E* a_max (delta - delta(a_max))`
    /// (the flat punch's `F = 2 E* a0 delta`).
    pub fn attached(&self, delta: f64) -> Option<(f64, f64)> {
        let a = self.stable_radius(delta)?;
        let max = self.profile.max_radius();
        if a == max && !matches!(self.profile, Profile::Sphere { .. }) {
            let f = self.load(max) + 2.0 * self.estar * max * (delta - self.interference(max));
            Some((a, f))
        } else {
            Some((a, self.load(a)))
        }
    }

    /// Contact radius at zero load (m) on the attached branch.
    pub fn zero_load_radius(&self) -> f64 {
        let lo = self.pull_off.radius;
        let max = self.profile.max_radius();
        if let Profile::Flat { radius } = self.profile {
            return radius;
        }
        let mut hi = 2.0 * lo;
        while self.load(hi.min(max)) < 0.0 && hi < max {
            hi = if max.is_finite() {
                0.5 * (hi + max)
            } else {
                2.0 * hi
            };
            if max.is_finite() && max - hi < 1e-15 * max {
                break;
            }
        }
        let hi = hi.min(max);
        if self.load(hi) < 0.0 {
            return max;
        }
        brent(|a| self.load(a), lo, hi, 4.0 * f64::EPSILON * hi).unwrap_or(hi)
    }

    /// The contact radius of an instability: closed form for the power laws
    /// and the flat punch, otherwise the largest sign change of the slope.
    fn critical_radius(&self, kind: Kind) -> Result<f64> {
        let c = match kind {
            Kind::Load => 3.0,
            Kind::Displacement => 1.0,
        };
        let g = (2.0 * PI * self.work / self.estar).sqrt();
        let power = |k_a: f64, n: f64| (c * g / (2.0 * n * k_a)).powf(1.0 / (n - 0.5));
        match &self.profile {
            Profile::Flat { radius } => return Ok(*radius),
            _ if self.work == 0.0 => return Ok(0.0),
            Profile::Paraboloid { radius } => return Ok(power(1.0 / radius, 2.0)),
            Profile::Cone { tan_angle } => return Ok(power(0.5 * PI * tan_angle, 1.0)),
            Profile::Power {
                exponent,
                k_coefficient,
                ..
            } => return Ok(power(*k_coefficient, *exponent)),
            _ => {}
        }
        // slope(a) < 0 below the instability, > 0 above it.
        let slope = |a: f64| match kind {
            Kind::Load => {
                2.0 * self.estar * a * self.profile.delta0_slope(a)
                    - 3.0 * (2.0 * PI * self.estar * self.work * a).sqrt()
            }
            Kind::Displacement => self.interference_slope(a),
        };
        let max = self.profile.max_radius();
        let top = match self.profile {
            Profile::Sphere { .. } => max * (1.0 - 1e-12),
            _ => max,
        };
        const SCAN: usize = 400;
        let lo = top * 1e-12;
        let ratio = (top / lo).powf(1.0 / SCAN as f64);
        let mut hi_a = top;
        let mut hi_s = slope(top);
        for i in (0..SCAN).rev() {
            let a = lo * ratio.powi(i as i32);
            let s = slope(a);
            if s < 0.0 && hi_s >= 0.0 {
                let tol = 2.0 * f64::EPSILON * hi_a;
                return brent(slope, a, hi_a, tol).ok_or(Error::NoConvergence {
                    what: "JKR instability of the profile".into(),
                    iterations: 200,
                    residual: f64::NAN,
                });
            }
            hi_a = a;
            hi_s = s;
        }
        Err(Error::invalid(
            "profile",
            format!(
                "no JKR {} instability of the {} profile at contact radii {lo:e} to {top:e} m{}",
                match kind {
                    Kind::Load => "pull-off",
                    Kind::Displacement => "jump-out",
                },
                self.profile.name(),
                match self.profile {
                    Profile::Tabulated(_) => ": the table ends before it",
                    _ => "",
                }
            ),
        ))
    }
}
