//! Shaped asperities: JKR adhesion of any axisymmetric summit profile
//! (cone, power law, flat punch, true sphere, measured table; see
//! [`crate::axisym`]) as an [`AsperityLaw`], so Greenwood–Williamson
//! integrals and Monte Carlo populations can use non-paraboloidal summits.
//!
//! Same history rules as [`super::Jkr`]: an approaching summit is free for
//! `delta < 0` and jumps onto the stable branch at `delta = 0` (apex
//! contact); a retracting one stays attached down to the jump-out
//! `delta_c` (where `d delta/da = 0`). [`ShapedExact`] solves
//! `delta(a) = delta` by Brent's method at every call (about 1-3 us for the
//! closed-form profiles, far more for a table); [`Shaped`] wraps it in
//! [`InterpolatedLaw`] tables (degree-6 Chebyshev panels) from `delta_c` to
//! the interference of 50 zero-load radii (0.95 R for the sphere), so one
//! evaluation is a binary search and two Clenshaw sums. Beyond a profile
//! that ends (flat punch, a table), the contact radius stays at the end and
//! the load grows with the punch stiffness `2 E* a_max`.
//!
//! [`ShapedMd`] / [`ShapedMdExact`] are the same for Maugis–Dugdale
//! adhesion of the profile ([`crate::axisym::md`], Dugdale stress `sigma0`).

use super::interpolated::InterpolatedLaw;
use super::{AsperityLaw, Branch, ContactState, Control, Instability, LawCursor, LawKernels};
use crate::axisym::{AxisymJkr, AxisymMd, MdPoint, Profile};
use crate::error::Result;
use std::sync::Arc;

/// Default table tolerance of [`Shaped::new`] (relative to the load plus
/// the pull-off scale) for closed-form profiles.
pub const DEFAULT_TOLERANCE: f64 = 1e-11;
/// Default table tolerance of [`Shaped::new`] for a tabulated profile: its
/// PCHIP interpolant is itself only `O(h^3)` accurate, and every exact
/// evaluation costs `O(nodes)` per Brent step (the build takes about 0.1 s
/// for a 41-node table and 2.3 s for 400 nodes at this tolerance;
/// docs/performance.md).
pub const TABLE_TOLERANCE: f64 = 1e-9;

/// The evaluations of a tabulated shaped law, all answered by its
/// [`InterpolatedLaw`] (field `table`); with `table_kernels!` (the GW panel
/// cursor and the Monte Carlo batch) shaped summits take the same fast
/// paths as every other tabulated law.
macro_rules! table_evaluations {
    () => {
        #[inline]
        fn state(&self, delta: f64, branch: Branch) -> ContactState {
            self.table.state(delta, branch)
        }

        #[inline]
        fn load(&self, delta: f64, branch: Branch) -> f64 {
            self.table.load(delta, branch)
        }

        fn state_after(&self, delta: f64, delta_max: f64) -> ContactState {
            self.table.state_after(delta, delta_max)
        }

        fn load_after(&self, delta: f64, delta_max: f64) -> f64 {
            self.table.load_after(delta, delta_max)
        }
    };
}

/// The kernels of a tabulated shaped law: its table's.
macro_rules! table_kernels {
    () => {
        fn state_near(
            &self,
            delta: f64,
            delta_max: Option<f64>,
            cursor: &mut LawCursor,
        ) -> ContactState {
            self.table.state_near(delta, delta_max, cursor)
        }

        fn load_near(&self, delta: f64, delta_max: Option<f64>, cursor: &mut LawCursor) -> f64 {
            self.table.load_near(delta, delta_max, cursor)
        }

        fn state_batch(
            &self,
            delta: &[f64],
            delta_max: Option<&[f64]>,
            load: &mut [f64],
            radius: &mut [f64],
        ) {
            self.table.state_batch(delta, delta_max, load, radius)
        }

        fn load_near_batch(
            &self,
            delta: &[f64],
            delta_max: Option<&[f64]>,
            load: &mut [f64],
            cursor: &mut LawCursor,
        ) {
            self.table.load_near_batch(delta, delta_max, load, cursor)
        }
    };
}

/// JKR for an axisymmetric profile, solved exactly at every call.
#[derive(Debug, Clone, PartialEq)]
pub struct ShapedExact {
    jkr: AxisymJkr,
    zero_load_radius: f64,
}

impl ShapedExact {
    /// Builds the law of `profile` for contact modulus `E*` (Pa) and work
    /// of adhesion `w` (J/m^2).
    ///
    /// # Errors
    /// As [`AxisymJkr::new`], and [`crate::Error::OutOfRange`] naming
    /// `work_of_adhesion` unless `w > 0` (use [`super::Hertz`]-like Sneddon
    /// contact otherwise).
    pub fn new(profile: Profile, contact_modulus: f64, work: f64) -> Result<Self> {
        crate::error::positive("work_of_adhesion", work)?;
        let jkr = AxisymJkr::new(profile, contact_modulus, work)?;
        let zero_load_radius = jkr.zero_load_radius();
        Ok(ShapedExact {
            jkr,
            zero_load_radius,
        })
    }

    /// The underlying contact.
    pub fn contact(&self) -> &AxisymJkr {
        &self.jkr
    }
}

impl AsperityLaw for ShapedExact {
    fn name(&self) -> &'static str {
        "shaped"
    }

    fn state(&self, delta: f64, branch: Branch) -> ContactState {
        if branch == Branch::Approach && delta < 0.0 {
            return ContactState::FREE;
        }
        match self.jkr.attached(delta) {
            Some((radius, load)) => ContactState { load, radius },
            None => ContactState::FREE,
        }
    }

    fn attach_interference(&self) -> f64 {
        0.0
    }

    fn detach_interference(&self) -> f64 {
        self.jkr.jump_out_displacement_control().interference
    }

    cutoff_at_detach!();

    fn pull_off(&self, control: Control) -> Option<Instability> {
        Some(match control {
            Control::Load => self.jkr.pull_off_load_control(),
            Control::Displacement => self.jkr.jump_out_displacement_control(),
        })
    }

    fn zero_load_radius(&self) -> Option<f64> {
        Some(self.zero_load_radius)
    }
}

impl LawKernels for ShapedExact {}

/// JKR for an axisymmetric profile, tabulated for speed (the law to use).
#[derive(Debug, Clone)]
pub struct Shaped {
    exact: Arc<ShapedExact>,
    table: InterpolatedLaw,
}

impl Shaped {
    /// [`ShapedExact`] tabulated to [`DEFAULT_TOLERANCE`] ([`TABLE_TOLERANCE`]
    /// for a tabulated profile).
    ///
    /// # Errors
    /// As [`AxisymJkr::new`].
    pub fn new(profile: Profile, contact_modulus: f64, work: f64) -> Result<Self> {
        let tol = match profile {
            Profile::Tabulated(_) => TABLE_TOLERANCE,
            _ => DEFAULT_TOLERANCE,
        };
        Shaped::with_tolerance(profile, contact_modulus, work, tol)
    }

    /// [`ShapedExact`] tabulated to relative tolerance `tol` (`[1e-13, 1e-2]`).
    ///
    /// # Errors
    /// As [`AxisymJkr::new`]; [`crate::Error::OutOfRange`] naming `tol`.
    pub fn with_tolerance(
        profile: Profile,
        contact_modulus: f64,
        work: f64,
        tol: f64,
    ) -> Result<Self> {
        let exact = Arc::new(ShapedExact::new(profile, contact_modulus, work)?);
        let jkr = exact.contact();
        let lo = exact.detach_interference();
        let max = jkr.profile().max_radius();
        let a_hi = match jkr.profile() {
            Profile::Sphere { radius } => 0.95 * radius,
            _ => (50.0 * exact.zero_load_radius).min(max),
        };
        let hi = match jkr.profile() {
            // Not past 0.95 R: as a -> R the load loses all its digits
            // (atanh), and the tables would refine on that noise for ever.
            Profile::Sphere { .. } => jkr.interference(a_hi),
            _ => jkr.interference(a_hi).max(lo + 100.0 * lo.abs()),
        };
        if !(hi > lo) {
            return Err(crate::Error::invalid(
                "work_of_adhesion",
                format!(
                    "the jump-out radius {} m of this sphere is beyond 0.95 R: adhesion too \
                     strong for the small-strain exact sphere",
                    jkr.jump_out_displacement_control().radius
                ),
            ));
        }
        let table = InterpolatedLaw::new(exact.clone(), lo, hi, tol)?;
        Ok(Shaped { exact, table })
    }

    /// The exact law the tables stand in for.
    pub fn exact(&self) -> &ShapedExact {
        &self.exact
    }

    /// The tables.
    pub fn table(&self) -> &InterpolatedLaw {
        &self.table
    }
}

impl AsperityLaw for Shaped {
    delegate_critical_points!(exact);
    fn name(&self) -> &'static str {
        "shaped"
    }

    table_evaluations!();

    fn attach_interference(&self) -> f64 {
        0.0
    }
}

impl LawKernels for Shaped {
    table_kernels!();
}

/// Maugis–Dugdale for an axisymmetric profile ([`crate::axisym::AxisymMd`]),
/// solved exactly at every call (nested root solves: about 0.1-1 ms; use
/// [`ShapedMd`]).
///
/// History as [`super::Maugis`]: an approaching summit is free until the
/// gap at its apex equals the Dugdale range (`delta = -h0`, `h0 = w/sigma0`),
/// then jumps onto the stable branch; a retracting one stays on it down to
/// the displacement-controlled snap.
#[derive(Debug, Clone, PartialEq)]
pub struct ShapedMdExact {
    md: AxisymMd,
}

impl ShapedMdExact {
    /// Builds the law of `profile` for `E*` (Pa), `w` (J/m^2) and Dugdale
    /// stress `sigma0` (Pa).
    ///
    /// # Errors
    /// As [`AxisymMd::new`].
    pub fn new(profile: Profile, contact_modulus: f64, work: f64, stress: f64) -> Result<Self> {
        Ok(ShapedMdExact {
            md: AxisymMd::new(profile, contact_modulus, work, stress)?,
        })
    }

    /// The underlying contact.
    pub fn contact(&self) -> &AxisymMd {
        &self.md
    }

    fn on_disc_snap(&self) -> bool {
        self.md.jump_out_displacement_control().radius == 0.0
    }
}

fn instability(p: MdPoint) -> Instability {
    Instability {
        load: p.load,
        interference: p.interference,
        radius: p.radius,
    }
}

impl AsperityLaw for ShapedMdExact {
    fn name(&self) -> &'static str {
        "shaped_md"
    }

    fn state(&self, delta: f64, branch: Branch) -> ContactState {
        if branch == Branch::Approach && delta < self.attach_interference() {
            return ContactState::FREE;
        }
        match self.md.stable_point(delta) {
            Some(p) => ContactState {
                load: p.load,
                radius: p.radius,
            },
            None => ContactState::FREE,
        }
    }

    /// `-h0`: the gap at the apex equals the Dugdale range.
    fn attach_interference(&self) -> f64 {
        -self.md.range()
    }

    fn detach_interference(&self) -> f64 {
        self.md.jump_out_displacement_control().interference
    }

    fn cutoff_interference(&self) -> f64 {
        self.detach_interference()
    }

    /// The branch threshold, and the junction (contact starts) when the
    /// stable branch passes through the non-contact disc.
    fn breakpoints(&self, branch: Branch) -> Vec<f64> {
        let lo = match branch {
            Branch::Approach => self.attach_interference(),
            Branch::Retract => self.detach_interference(),
        };
        let mut v = vec![lo];
        let j = self.md.junction().interference;
        if self.on_disc_snap() && j > lo {
            v.push(j);
        }
        v
    }

    fn pull_off(&self, control: Control) -> Option<Instability> {
        Some(instability(match control {
            Control::Load => self.md.pull_off_load_control(),
            Control::Displacement => self.md.jump_out_displacement_control(),
        }))
    }

    fn zero_load_radius(&self) -> Option<f64> {
        Some(self.md.zero_load().radius)
    }
}

impl LawKernels for ShapedMdExact {}

/// Maugis–Dugdale for an axisymmetric profile, tabulated for speed by
/// [`InterpolatedLaw`] (degree-6 Chebyshev panels) from the snap to the
/// interference of 50 zero-load radii.
#[derive(Debug, Clone)]
pub struct ShapedMd {
    exact: Arc<ShapedMdExact>,
    table: InterpolatedLaw,
}

impl ShapedMd {
    /// [`ShapedMdExact`] tabulated to [`DEFAULT_TOLERANCE`] (relative to the
    /// load plus the pull-off scale).
    ///
    /// # Errors
    /// As [`AxisymMd::new`].
    pub fn new(profile: Profile, contact_modulus: f64, work: f64, stress: f64) -> Result<Self> {
        ShapedMd::with_tolerance(profile, contact_modulus, work, stress, DEFAULT_TOLERANCE)
    }

    /// [`ShapedMdExact`] tabulated to relative tolerance `tol` (`[1e-13, 1e-2]`).
    ///
    /// # Errors
    /// As [`AxisymMd::new`]; [`crate::Error::OutOfRange`] naming `tol`.
    pub fn with_tolerance(
        profile: Profile,
        contact_modulus: f64,
        work: f64,
        stress: f64,
        tol: f64,
    ) -> Result<Self> {
        let exact = Arc::new(ShapedMdExact::new(profile, contact_modulus, work, stress)?);
        let md = exact.contact();
        let lo = exact.detach_interference();
        let a_hi = (50.0 * md.zero_load().radius).min(0.5 * md.profile().max_radius());
        let hi = md.point(a_hi).interference.max(lo + 100.0 * lo.abs());
        let table = InterpolatedLaw::new(exact.clone(), lo, hi, tol)?;
        Ok(ShapedMd { exact, table })
    }

    /// The exact law the tables stand in for.
    pub fn exact(&self) -> &ShapedMdExact {
        &self.exact
    }

    /// The tables.
    pub fn table(&self) -> &InterpolatedLaw {
        &self.table
    }
}

impl AsperityLaw for ShapedMd {
    delegate_critical_points!(exact);
    fn name(&self) -> &'static str {
        "shaped_md"
    }

    table_evaluations!();

    fn attach_interference(&self) -> f64 {
        self.exact.attach_interference()
    }
}

impl LawKernels for ShapedMd {
    table_kernels!();
}

/// The shaped law of a profile for scenes and populations: JKR
/// ([`Shaped`]) when `stress` is `None`, Maugis–Dugdale ([`ShapedMd`]) with
/// Dugdale stress `sigma0 = stress` (Pa) otherwise; `E*` (Pa), `w` (J/m^2).
///
/// # Errors
/// As [`Shaped::new`] or [`ShapedMd::new`] (fields `contact_modulus`,
/// `work_of_adhesion`, `stress`, `exponent`, `profile`).
pub fn build(
    profile: Profile,
    contact_modulus: f64,
    work: f64,
    stress: Option<f64>,
) -> Result<Arc<dyn LawKernels>> {
    Ok(match stress {
        None => Arc::new(Shaped::new(profile, contact_modulus, work)?),
        Some(s) => Arc::new(ShapedMd::new(profile, contact_modulus, work, s)?),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::law::Jkr;

    #[test]
    fn a_paraboloid_reproduces_the_jkr_law() {
        let (r, e, w) = (1e-6, 5e10, 0.5);
        let s = Shaped::new(Profile::paraboloid(r).unwrap(), e, w).unwrap();
        let j = Jkr::new(r, e, w).unwrap();
        let ps = j.pull_off(Control::Load).unwrap().load.abs();
        let dc = j.detach_interference();
        for i in 0..400 {
            let d = dc + (i as f64 / 40.0).powi(2) * dc.abs();
            for b in [Branch::Approach, Branch::Retract] {
                let (x, y) = (s.state(d, b), j.state(d, b));
                assert!(
                    (x.load - y.load).abs() <= 1e-10 * (y.load.abs() + ps),
                    "{d} {b:?}"
                );
                assert!(
                    (x.radius - y.radius).abs() <= 1e-9 * y.radius.max(1e-9),
                    "{d}"
                );
            }
        }
        assert!((s.detach_interference() / dc - 1.0).abs() < 1e-14);
        let z = j.zero_load_radius().unwrap();
        assert!((s.zero_load_radius().unwrap() / z - 1.0).abs() < 1e-14);
    }

    #[test]
    fn build_picks_jkr_or_maugis_dugdale() {
        let p = Profile::cone(0.2).unwrap();
        let j = build(p.clone(), 1e9, 0.05, None).unwrap();
        assert_eq!(j.attach_interference(), 0.0);
        let m = build(p.clone(), 1e9, 0.05, Some(6e8)).unwrap();
        assert!((m.attach_interference() + 0.05 / 6e8).abs() < 1e-24);
        let e = build(p, 1e9, 0.05, Some(-1.0)).unwrap_err();
        assert_eq!(e.field(), Some("stress"));
    }

    #[test]
    fn the_flat_punch_is_linear_with_kendall_pull_off() {
        let (a0, e, w) = (1e-6, 1e9, 0.05);
        let s = Shaped::new(Profile::flat(a0).unwrap(), e, w).unwrap();
        let kendall = -(8.0 * std::f64::consts::PI * e * w * a0.powi(3)).sqrt();
        let p = s.pull_off(Control::Displacement).unwrap();
        assert!((p.load / kendall - 1.0).abs() < 1e-14);
        for d in [p.interference, 0.0, 1e-9, 1e-7] {
            let st = s.state(d, Branch::Retract);
            assert!(
                (st.load - 2.0 * e * a0 * d).abs() <= 1e-12 * kendall.abs(),
                "{d}"
            );
            assert!((st.radius / a0 - 1.0).abs() < 1e-13);
        }
        assert_eq!(
            s.state(p.interference * 1.001, Branch::Retract),
            ContactState::FREE
        );
    }
}
