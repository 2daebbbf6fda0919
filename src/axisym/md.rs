//! Maugis–Dugdale for any axisymmetric profile: Barthel's general contact
//! solution (Barthel 2008, eqs 3.1, 3.10, 4.8-4.13, 5.2) with a
//! Dugdale cohesive zone, a constant tension `sigma0` on `a < r < c`, of
//! range `h0 = w/sigma0`.
//!
//! # Equations (`calK = E*/2`, `s = sqrt(c^2 - a^2)`, `phi = acos(a/c)`)
//! From (4.10) the zone gives `g(t) = -sigma0 sqrt(c^2 - t^2)` on `a < t < c`, so
//!
//! ```text
//! delta(a) = delta_0(a) - (2 sigma0/E*) s                               (4.12)
//! F(a)     = F_0(a) - 2 sigma0 (a s + c^2 phi)                          (3.10)
//! ```
//!
//! and the zone's extent `c` follows from Barthel's self-consistency (5.2)
//! with a constant stress, `w = sigma0 [u](c)`: the gap at the zone's edge
//! is the range. The gap follows from (3.1) at `r = c`; integrating its
//! slope from `a` to `c` and swapping the integrals removes every
//! cancellation (all terms are >= 0):
//!
//! ```text
//! [u](c) = (2/pi) int_a^c delta_0'(t) acos(t/c) dt + (4 sigma0/(pi E*)) (s phi - c + a) = h0
//! ```
//!
//! (the first term is `h(c) - (2/pi)(phi delta_0(a) + int_0^a delta_0(t) dt/sqrt(c^2-t^2))`).
//! For the paraboloid it is `((c^2 - 2a^2) phi + a s)/(pi R)`, Maugis' (1992)
//! equation with `lambda`; the tests reproduce `law::Maugis` to 1e-10. In
//! `t = c cos v` the integral is `c int_0^phi delta_0'(c cos v) v sin v dv`,
//! smooth, taken by adaptive Gauss–Kronrod.
//!
//! Without contact (`a = 0`, Maugis' non-contact branch) the zone is a disc:
//! `delta = h(c) - h0 - 4 sigma0 c/(pi E*)`, `F = -pi sigma0 c^2`, valid
//! while the centre stays open, up to the junction `c0` with the contact
//! branch: `h(c0) + (2 sigma0/E*)(1 - 2/pi) c0 = h0`.
//!
//! # Instabilities and limits
//! Along the whole curve (non-contact disc, then contact radius growing),
//! the displacement-controlled snap is the first minimum of `delta` met on
//! retraction from deep contact, the load-controlled pull-off the first
//! minimum of `F`; both are found by a scan of the analytic derivatives
//! (`dc/da` by implicit differentiation of the gap equation) and Brent's
//! method. When `delta` has no minimum before `c = 0` (a cone steeper than
//! `4 sigma0/(pi E*)`) contact is lost continuously and nothing snaps:
//! the snap is then reported at `delta = -h0` with zero load.
//!
//! `sigma0 -> inf` (`h0 -> 0`) is JKR for the profile ([`super::AxisymJkr`]);
//! `sigma0 -> 0` (`h0 -> inf`) the rigid (Derjaguin) limit: for the
//! paraboloid DMT, `-2 pi w R`; for the cone the force grows without bound,
//! `-pi w h0/tan^2 beta` (Barthel 5.3: DMT does not exist for a cone).
//! Tested: paraboloid against `law::Maugis`, cone limits both ways.
//!
//! Not supported: the flat punch (its face ends at `a0`, so no zone can
//! form outside it: use JKR, Kendall's result) and tabulated profiles (each
//! `delta_0'` is itself a quadrature; three nested solves are too slow).

use super::jkr::AxisymJkr;
use super::profile::Profile;
use crate::error::{positive, Error, Result};
use crate::numeric::quadrature::{integrate_pieces_n, QuadOptions};
use crate::numeric::roots::brent;
use std::f64::consts::PI;

/// Tolerances of the inner quadratures.
const QUAD: QuadOptions = QuadOptions {
    rel_tol: 1e-13,
    abs_tol: 0.0,
    max_intervals: 64,
    relative_to_magnitude: false,
};

/// Points of the instability scans (log-spaced in the contact radius).
const SCAN: usize = 160;

/// One state on the Maugis–Dugdale curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MdPoint {
    /// Contact radius `a` (m); 0 on the non-contact branch.
    pub radius: f64,
    /// Outer radius `c` of the Dugdale zone (m).
    pub outer_radius: f64,
    /// Interference `delta` (m).
    pub interference: f64,
    /// Load `F` (N, < 0 tensile).
    pub load: f64,
}

/// Maugis–Dugdale contact of a profile: `E*` (Pa), `w` (J/m^2), Dugdale
/// stress `sigma0` (Pa), with its instabilities found once.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisymMd {
    profile: Profile,
    estar: f64,
    work: f64,
    stress: f64,
    range: f64,
    junction: MdPoint,
    pull_off: MdPoint,
    snap: MdPoint,
    zero_load: MdPoint,
    /// Upper end of the scans (m).
    scan_top: f64,
}

/// Where the displacement-controlled snap happened.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Pos {
    Contact(f64),
    Disc(f64),
}

impl AxisymMd {
    /// Builds the contact and finds its instabilities.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `contact_modulus`, `work_of_adhesion`
    /// or `stress` (finite, > 0), or `exponent` (power law: > 1/2);
    /// [`Error::Invalid`] naming `profile` for the flat punch and tables.
    pub fn new(profile: Profile, contact_modulus: f64, work: f64, stress: f64) -> Result<Self> {
        let estar = positive("contact_modulus", contact_modulus)?;
        let work = positive("work_of_adhesion", work)?;
        let stress = positive("stress", stress)?;
        match profile {
            Profile::Flat { .. } => {
                return Err(Error::invalid(
                    "profile",
                    "Maugis-Dugdale needs a surface outside the contact for the cohesive zone; \
                     the flat punch's face ends at its radius: use JKR (Kendall)",
                ))
            }
            Profile::Tabulated(_) => {
                return Err(Error::invalid(
                    "profile",
                    "Maugis-Dugdale is not implemented for a tabulated profile \
                     (nested quadratures); use JKR",
                ))
            }
            _ => {}
        }
        let jkr = AxisymJkr::new(profile.clone(), estar, work)?;
        let a_jkr = jkr.pull_off_load_control().radius;
        let mut md = AxisymMd {
            profile,
            estar,
            work,
            stress,
            range: work / stress,
            junction: MdPoint {
                radius: 0.0,
                outer_radius: 0.0,
                interference: 0.0,
                load: 0.0,
            },
            pull_off: MdPoint {
                radius: 0.0,
                outer_radius: 0.0,
                interference: 0.0,
                load: 0.0,
            },
            snap: MdPoint {
                radius: 0.0,
                outer_radius: 0.0,
                interference: 0.0,
                load: 0.0,
            },
            zero_load: MdPoint {
                radius: 0.0,
                outer_radius: 0.0,
                interference: 0.0,
                load: 0.0,
            },
            scan_top: 0.0,
        };
        let c0 = md.junction_radius()?;
        md.junction = md.disc_point(c0);
        let max = md.profile.max_radius();
        // The zone must stay on the sphere: the scans stop well below R.
        md.scan_top = (1e3 * a_jkr.max(c0)).min(0.5 * max);
        md.pull_off = md.find_pull_off()?;
        md.snap = md.find_snap()?;
        md.zero_load = md.find_zero_load()?;
        Ok(md)
    }

    /// `sigma0` (Pa) giving Maugis' parameter `lambda = 2 sigma0 (R/(pi w K^2))^(1/3)`,
    /// `K = 4E*/3`, for a paraboloid of radius `R` (m).
    pub fn stress_from_lambda(lambda: f64, radius: f64, contact_modulus: f64, work: f64) -> f64 {
        let k = 4.0 * contact_modulus / 3.0;
        0.5 * lambda * (PI * work * k * k / radius).cbrt()
    }

    adhesive_profile_accessors!();

    /// Dugdale stress `sigma0` (Pa).
    pub fn stress(&self) -> f64 {
        self.stress
    }

    /// Dugdale range `h0 = w/sigma0` (m).
    pub fn range(&self) -> f64 {
        self.range
    }

    /// `4 sigma0/(pi E*)`: the zone's own opening per unit radius.
    fn k(&self) -> f64 {
        4.0 * self.stress / (PI * self.estar)
    }

    /// `[G, dG/dc]` with `G(a, c) = (2/pi) int_a^c delta_0'(t) acos(t/c) dt` (m).
    fn shape_gap(&self, a: f64, c: f64) -> [f64; 2] {
        let phi = phi_of(a, c);
        if !(phi > 0.0) {
            return [0.0, 0.0];
        }
        let q = integrate_pieces_n(
            |v| {
                let (sv, cv) = v.sin_cos();
                let d = self.profile.delta0_slope(c * cv);
                [d * v * sv, d * cv]
            },
            &[0.0, phi],
            &QUAD,
        );
        [2.0 / PI * c * q.value[0], 2.0 / PI * q.value[1]]
    }

    /// The gap at the zone's edge `[u](c)` minus the range (m) for contact
    /// radius `a` (> 0).
    fn gap_excess(&self, a: f64, c: f64) -> f64 {
        let s = ((c - a) * (c + a)).max(0.0).sqrt();
        let phi = phi_of(a, c);
        self.shape_gap(a, c)[0] + self.k() * (s * phi - (c - a)) - self.range
    }

    /// Outer radius `c` (m) of the zone at contact radius `a` (m, > 0).
    fn outer_radius(&self, a: f64) -> f64 {
        if !(a > 0.0) {
            return self.junction.outer_radius;
        }
        let mut d = a;
        let cap = self.profile.max_radius();
        let mut hi = a + d;
        while self.gap_excess(a, hi) < 0.0 {
            d *= 2.0;
            hi = a + d;
            if hi >= cap {
                // The sphere: the zone would pass the equator.
                return f64::NAN;
            }
        }
        brent(|c| self.gap_excess(a, c), a, hi, 4.0 * f64::EPSILON * hi).unwrap_or(f64::NAN)
    }

    /// Junction radius `c0`: `h(c0) + (2 sigma0/E*)(1 - 2/pi) c0 = h0`.
    fn junction_radius(&self) -> Result<f64> {
        let e = 2.0 * self.stress / self.estar * (1.0 - 2.0 / PI);
        let f = |c: f64| self.profile.height(c) + e * c - self.range;
        let cap = self.profile.max_radius();
        let mut hi = self.range / e;
        if hi >= cap {
            hi = 0.5 * cap;
        }
        if f(hi) < 0.0 {
            return Err(Error::invalid(
                "stress",
                format!(
                    "the Dugdale range {} m reaches beyond the {} profile",
                    self.range,
                    self.profile.name()
                ),
            ));
        }
        // `range/e` can be decades above the root (at sigma0 = 1e-3 Pa on a
        // 1 um paraboloid, 7e13 m against c0 = 1 cm), and Brent's absolute
        // tolerance is relative to the bracket: halve down to the root's
        // decade first (f(0) = -h0 < 0, so the root stays bracketed).
        let mut lo = 0.0;
        for _ in 0..2200 {
            let half = 0.5 * hi;
            if !(half > 0.0) || f(half) < 0.0 {
                lo = half.max(0.0);
                break;
            }
            hi = half;
        }
        brent(f, lo, hi, 4.0 * f64::EPSILON * hi).ok_or(Error::NoConvergence {
            what: "Maugis-Dugdale junction radius".into(),
            iterations: 200,
            residual: f64::NAN,
        })
    }

    /// State on the non-contact branch with a zone of radius `c` (m).
    pub fn disc_point(&self, c: f64) -> MdPoint {
        MdPoint {
            radius: 0.0,
            outer_radius: c,
            interference: self.profile.height(c) - self.range - self.k() * c,
            load: -PI * self.stress * c * c,
        }
    }

    /// State on the contact branch at contact radius `a` (m; `a = 0` is the
    /// junction with the non-contact branch).
    pub fn point(&self, a: f64) -> MdPoint {
        if !(a > 0.0) {
            return self.junction;
        }
        let c = self.outer_radius(a);
        self.point_with(a, c)
    }

    fn point_with(&self, a: f64, c: f64) -> MdPoint {
        let s = ((c - a) * (c + a)).max(0.0).sqrt();
        let phi = phi_of(a, c);
        MdPoint {
            radius: a,
            outer_radius: c,
            interference: self.profile.delta0(a) - 2.0 * self.stress / self.estar * s,
            load: self.profile.load0(a, self.estar) - 2.0 * self.stress * (a * s + c * c * phi),
        }
    }

    /// `(d delta/da, dF/da)` along the contact branch at radius `a` (m).
    pub fn slopes(&self, a: f64) -> (f64, f64) {
        let c = self.outer_radius(a);
        let s = ((c - a) * (c + a)).max(0.0).sqrt();
        let phi = phi_of(a, c);
        let k = self.k();
        let d0 = self.profile.delta0_slope(a);
        let g_c = self.shape_gap(a, c)[1];
        // phi/s -> 1/a as c -> a.
        let phi_s = if s > 0.0 { phi / s } else { 1.0 / a };
        let gap_a = -2.0 / PI * d0 * phi - k * a * phi_s;
        let gap_c = g_c + k * (c * phi_s + a / c - 1.0);
        let cp = -gap_a / gap_c;
        let dd = d0 - 2.0 * self.stress / self.estar * (c * cp - a) / s;
        let df = 2.0 * self.estar * a * d0
            - 2.0 * self.stress * (-2.0 * a * a / s + (2.0 * a * c / s + 2.0 * c * phi) * cp);
        (dd, df)
    }

    /// Load-controlled pull-off: the first minimum of `F` met from deep
    /// contact (the junction when `F` only falls towards it).
    pub fn pull_off_load_control(&self) -> MdPoint {
        self.pull_off
    }

    /// Displacement-controlled snap: the first minimum of `delta` met on
    /// retraction (radius 0 when it is on the non-contact branch; zero load
    /// at `delta = -h0` when contact and zone fade continuously).
    pub fn jump_out_displacement_control(&self) -> MdPoint {
        self.snap
    }

    /// The junction of the two branches (`a -> 0`).
    pub fn junction(&self) -> MdPoint {
        self.junction
    }

    /// The zero-load state on the stable contact branch.
    pub fn zero_load(&self) -> MdPoint {
        self.zero_load
    }

    /// The log-spaced contact radii of the scans, descending.
    fn grid(&self) -> impl Iterator<Item = f64> + '_ {
        let lo = self.scan_top * 1e-12;
        let ratio = (self.scan_top / lo).powf(1.0 / SCAN as f64);
        (0..=SCAN).rev().map(move |i| lo * ratio.powi(i as i32))
    }

    /// The first contact radius of the descending scan ([`Self::grid`])
    /// where slope `k` of [`Self::slopes`] (0: `d delta/da`, 1: `dF/da`)
    /// turns negative, refined by Brent; `None` when it never does. `what`
    /// names the instability in the errors.
    fn first_negative_slope(&self, k: usize, what: &str) -> Result<Option<MdPoint>> {
        let slope = |a: f64| {
            let s = self.slopes(a);
            [s.0, s.1][k]
        };
        let mut prev: Option<(f64, f64)> = None;
        for a in self.grid() {
            let d = slope(a);
            if let Some((a_hi, d_hi)) = prev {
                if d < 0.0 && d_hi >= 0.0 {
                    let r = brent(slope, a, a_hi, 4.0 * f64::EPSILON * a_hi)
                        .ok_or_else(|| no_convergence(&format!("Maugis-Dugdale {what}")))?;
                    return Ok(Some(self.point(r)));
                }
            } else if d < 0.0 {
                return Err(too_deep(what));
            }
            prev = Some((a, d));
        }
        Ok(None)
    }

    fn find_pull_off(&self) -> Result<MdPoint> {
        Ok(self
            .first_negative_slope(1, "pull-off")?
            .unwrap_or(self.junction))
    }

    fn find_snap(&self) -> Result<MdPoint> {
        if let Some(p) = self.first_negative_slope(0, "jump-out")? {
            return Ok(p);
        }
        // On the disc: d delta/dc = h'(c) - 4 sigma0/(pi E*).
        let c0 = self.junction.outer_radius;
        let k = self.k();
        let slope = |c: f64| self.profile.slope(c) - k;
        if slope(c0) < 0.0 {
            // The minimum is at the junction itself.
            return Ok(self.junction);
        }
        let mut hi = c0;
        for i in (0..SCAN).rev() {
            let c = c0 * i as f64 / SCAN as f64;
            if slope(c) < 0.0 {
                let r = brent(slope, c, hi, 4.0 * f64::EPSILON * c0)
                    .ok_or_else(|| no_convergence("Maugis-Dugdale disc snap"))?;
                return Ok(self.disc_point(r));
            }
            hi = c;
        }
        // delta rises from c = 0: nothing snaps.
        Ok(self.disc_point(0.0))
    }

    /// Smallest `hi = lo0 * 1.5^k` (from `start`) with `value(hi) >= target`,
    /// or `None` when the zone reaches the end of the profile first.
    fn bracket_up(&self, start: f64, target: f64, value: impl Fn(&MdPoint) -> f64) -> Option<f64> {
        let mut hi = start;
        for _ in 0..400 {
            let v = value(&self.point(hi));
            if !v.is_finite() || hi >= self.profile.max_radius() {
                return None;
            }
            if v >= target {
                return Some(hi);
            }
            hi *= 1.5;
        }
        None
    }

    /// A starting radius above `lo` (m) for the upward brackets.
    fn start_above(&self, lo: f64) -> f64 {
        if lo > 0.0 {
            1.5 * lo
        } else {
            1e-3 * self.junction.outer_radius
        }
    }

    fn find_zero_load(&self) -> Result<MdPoint> {
        let lo = self.pull_off.radius;
        let hi = self
            .bracket_up(self.start_above(lo), 0.0, |p| p.load)
            .ok_or_else(|| {
                Error::invalid(
                    "stress",
                    format!(
                        "the Dugdale zone reaches the end of the {} profile before zero \
                         load (range w/sigma0 = {:e} m too long for it)",
                        self.profile.name(),
                        self.range
                    ),
                )
            })?;
        let r = brent(|a| self.point(a).load, lo, hi, 4.0 * f64::EPSILON * hi)
            .ok_or_else(|| no_convergence("Maugis-Dugdale zero-load radius"))?;
        Ok(self.point(r))
    }

    fn snap_position(&self) -> Pos {
        if self.snap.radius > 0.0 {
            Pos::Contact(self.snap.radius)
        } else {
            Pos::Disc(self.snap.outer_radius)
        }
    }

    /// The stable state at interference `delta` (m), or `None` below the
    /// snap (and for a sphere beyond where the zone reaches its equator).
    /// Displacement control: past the snap `delta` rises along the curve.
    pub fn stable_point(&self, delta: f64) -> Option<MdPoint> {
        if !(delta >= self.snap.interference) {
            return None;
        }
        let lo_a = match self.snap_position() {
            Pos::Contact(a) => a,
            Pos::Disc(c) => {
                if delta <= self.junction.interference {
                    let c0 = self.junction.outer_radius;
                    let r = brent(
                        |x| self.disc_point(x).interference - delta,
                        c,
                        c0,
                        4.0 * f64::EPSILON * c0,
                    )
                    .unwrap_or(c0);
                    return Some(self.disc_point(r));
                }
                0.0
            }
        };
        let hi = self.bracket_up(self.start_above(lo_a), delta, |p| p.interference)?;
        let a = brent(
            |x| self.point(x).interference - delta,
            lo_a,
            hi,
            4.0 * f64::EPSILON * hi,
        )?;
        Some(self.point(a))
    }
}

/// `acos(a/c)` without the loss near `c = a`.
fn phi_of(a: f64, c: f64) -> f64 {
    ((c - a) * (c + a)).max(0.0).sqrt().atan2(a)
}

fn no_convergence(what: &str) -> Error {
    Error::NoConvergence {
        what: what.into(),
        iterations: 200,
        residual: f64::NAN,
    }
}

fn too_deep(what: &str) -> Error {
    Error::invalid(
        "stress",
        format!("the Maugis-Dugdale {what} lies outside the scanned range of contact radii"),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shape_gap_matches_its_closed_forms() {
        // Cone: G = tan(beta) (s - a phi); paraboloid: ((c^2 - 2a^2) phi + a s)/(pi R).
        let (t, r) = (0.3, 2e-6);
        let cone = AxisymMd::new(Profile::cone(t).unwrap(), 1e9, 0.05, 1e7).unwrap();
        let par = AxisymMd::new(Profile::paraboloid(r).unwrap(), 1e9, 0.05, 1e7).unwrap();
        for (a, c) in [(1e-8f64, 1.5e-8f64), (1e-8, 1e-6), (3e-7, 3.1e-7)] {
            let s = ((c - a) * (c + a)).sqrt();
            let phi = (a / c).acos();
            let want = t * (s - a * phi);
            assert!(
                (cone.shape_gap(a, c)[0] / want - 1.0).abs() < 1e-12,
                "{a} {c}"
            );
            let want = ((c * c - 2.0 * a * a) * phi + a * s) / (PI * r);
            assert!(
                (par.shape_gap(a, c)[0] / want - 1.0).abs() < 1e-9,
                "{a} {c}"
            );
            // dG/dc by central differences.
            let h = 1e-6 * (c - a);
            let num = (cone.shape_gap(a, c + h)[0] - cone.shape_gap(a, c - h)[0]) / (2.0 * h);
            assert!(
                (cone.shape_gap(a, c)[1] / num - 1.0).abs() < 1e-6,
                "{a} {c}"
            );
        }
    }

    #[test]
    fn the_slopes_are_the_derivatives_of_the_curve() {
        let md = AxisymMd::new(Profile::power(1e4, 1.5).unwrap(), 1e9, 0.05, 3e7).unwrap();
        for a in [1e-9, 1e-8, 1e-7] {
            let h = 1e-5 * a;
            let (p, m) = (md.point(a + h), md.point(a - h));
            let (dd, df) = md.slopes(a);
            let nd = (p.interference - m.interference) / (2.0 * h);
            let nf = (p.load - m.load) / (2.0 * h);
            assert!(
                (dd - nd).abs() < 1e-6 * nd.abs().max(dd.abs()),
                "{a} {dd} {nd}"
            );
            assert!(
                (df - nf).abs() < 1e-6 * nf.abs().max(df.abs()),
                "{a} {df} {nf}"
            );
        }
        assert_eq!(
            AxisymMd::new(Profile::flat(1e-6).unwrap(), 1e9, 0.05, 1e7)
                .unwrap_err()
                .field(),
            Some("profile")
        );
    }
}
