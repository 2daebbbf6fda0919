//! Single-asperity laws: a sphere of radius `R` against a flat.
//!
//! Every law implements [`AsperityLaw`], its physics, and [`LawKernels`],
//! the speed machinery the rough-surface integrator and the Monte Carlo
//! summation call millions of times (defaults evaluate the physics). A law
//! gives the load `P` (N, > 0 compressive) and contact radius `a` (m) at an
//! interference `delta` (m, > 0 when the undeformed bodies would overlap) on a
//! [`Branch`]: adhesive laws are multi-valued, and which value applies depends
//! on the loading history.
//!
//! Under displacement control (the rough-surface case: a rigid flat at a
//! set separation), an asperity approaching from far away stays detached
//! until the *attach* interference (jump-in), then follows the stable contact
//! branch; on retraction it stays attached down to the *detach* interference
//! (jump-out), below which it is free again. [`AsperityLaw::state_after`]
//! gives the state for any approach-then-retract history.
//!
//! | law | module | attach | detach | pull-off (load control) |
//! |---|---|---|---|---|
//! | Hertz | [`hertz`] | 0 | 0 | 0 |
//! | Bradley (rigid, LJ 9-3) | [`bradley`] | none (rigid) | none | `-2 pi w R` at `delta = 0` |
//! | DMT | [`dmt`] | 0 | 0 | `-2 pi w R` |
//! | JKR | [`jkr`] | 0 | `-(3/4)(pi^2 w^2 R/E*^2)^(1/3)` | `-1.5 pi w R` |
//! | Maugis–Dugdale (exact, with the non-contact branch) | [`maugis`] | `-w/sigma0` | end of the stable branch (non-contact for `lambda < 0.938`) | `-2 .. -1.5 pi w R` |
//! | COS (fit to MD, paired with an interference relation) | [`cos`] | 0 | JKR-like fold (0 at `alpha = 0`) | exact MD value |
//! | shaped (JKR, any axisymmetric summit) | [`shaped`] | 0 | `min delta(a)` of the profile | `min F(a)` of the profile |
//! | tabulated (e.g. LJ sphere solver) | [`tabulated`] | jump-in | jump-out | table's minimum |

/// The critical points of a law that stands in for another one, the
/// field `$inner` (tables of an exact law): detach and cutoff
/// interferences, breakpoints, pull-off and zero-load radius, delegated
/// (a table's are its exact law's, not its own interpolant's).
macro_rules! delegate_critical_points {
    ($inner:ident) => {
        fn detach_interference(&self) -> f64 {
            self.$inner.detach_interference()
        }

        fn cutoff_interference(&self) -> f64 {
            self.$inner.cutoff_interference()
        }

        fn breakpoints(&self, branch: Branch) -> Vec<f64> {
            self.$inner.breakpoints(branch)
        }

        fn pull_off(&self, control: Control) -> Option<Instability> {
            self.$inner.pull_off(control)
        }

        fn zero_load_radius(&self) -> Option<f64> {
            self.$inner.zero_load_radius()
        }
    };
}

/// The history and reach of a law that wraps another one, the field
/// `$inner` (an interpolant of it, or it with a meniscus beside): its
/// history breakpoints, contact-loss peaks, whether it remembers its
/// maximum, its attach and largest interferences, delegated.
macro_rules! delegate_history {
    ($inner:ident) => {
        fn history_breakpoints(&self) -> Vec<f64> {
            self.$inner.history_breakpoints()
        }

        fn contact_loss_peaks(&self, recovery: f64) -> Vec<f64> {
            self.$inner.contact_loss_peaks(recovery)
        }

        fn remembers_maximum(&self) -> bool {
            self.$inner.remembers_maximum()
        }

        fn attach_interference(&self) -> f64 {
            self.$inner.attach_interference()
        }

        fn max_interference(&self) -> f64 {
            self.$inner.max_interference()
        }
    };
}
pub(crate) use delegate_history;

/// The critical interferences of a law with no force out of contact and
/// no jump (Hertz, DMT, the plastic laws): it attaches and detaches at
/// first contact, and the load is zero below it.
macro_rules! critical_at_first_contact {
    () => {
        fn attach_interference(&self) -> f64 {
            0.0
        }

        fn detach_interference(&self) -> f64 {
            0.0
        }

        fn cutoff_interference(&self) -> f64 {
            0.0
        }
    };
}

/// The name and radius scaling of the law of [`LawKind`] `$kind`: its
/// kind's, written once there.
macro_rules! identity_of_kind {
    ($kind:ident) => {
        fn radius_scaling(&self) -> Option<$crate::law::RadiusScaling> {
            $crate::law::LawKind::$kind.radius_scaling()
        }

        fn name(&self) -> &'static str {
            $crate::law::LawKind::$kind.name()
        }
    };
}

/// The cutoff and breakpoints of an adhesive law whose force acts only in
/// contact (JKR, its shaped form, COS): the load is zero below the jump-out
/// interference `detach_interference`, where the attached branch ends; the
/// approach branch kinks at first contact (0), the retraction branch jumps
/// at detachment.
macro_rules! cutoff_at_detach {
    () => {
        fn cutoff_interference(&self) -> f64 {
            self.detach_interference()
        }

        fn breakpoints(&self, branch: Branch) -> Vec<f64> {
            match branch {
                Branch::Approach => vec![0.0],
                Branch::Retract => vec![self.detach_interference()],
            }
        }
    };
}

pub mod bradley;
pub mod cos;
mod cursor;
pub mod dmt;
pub mod errors;
pub mod hertz;
pub mod interpolated;
pub mod jkr;
mod kernels;
mod kind;
pub mod maugis;
pub mod plastic;
pub mod retraction;
mod scaling;
pub mod shaped;
pub mod tabulated;

pub use bradley::Bradley;
pub use cos::Cos;
pub use cursor::LawCursor;
pub use dmt::Dmt;
pub use hertz::Hertz;
pub use jkr::Jkr;
pub use kernels::{LawKernels, Prepared, TABLE_LOOKUP_NS};
pub use kind::{LawInputs, LawKind, TABULATE_ABOVE_NS};
pub use maugis::{Maugis, MaugisCurve};
pub use retraction::RetractionMinimum;
pub use scaling::RadiusScaling;
pub use shaped::Shaped;
pub use tabulated::Tabulated;

use crate::material::MaugisScales;
use std::f64::consts::PI;
use std::fmt;

/// Which way the interference is moving.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Branch {
    /// Interference increasing from far apart: the asperity is detached until
    /// it jumps in.
    Approach,
    /// Interference decreasing after deep contact: the asperity stays attached
    /// until it jumps out.
    Retract,
}

/// What the experiment holds fixed when the asperity is pulled off.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Control {
    /// Load held, interference free: pull-off at the most tensile load.
    Load,
    /// Interference held (rigid machine): jump-out where the stable branch ends.
    Displacement,
}

/// Load and contact radius of one asperity.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactState {
    /// Load `P` (N): > 0 compressive, < 0 tensile (adhesive pull).
    pub load: f64,
    /// Contact radius `a` (m); 0 when not in contact (an adhesive force may
    /// still act, e.g. the Maugis-Dugdale non-contact branch).
    pub radius: f64,
}

impl ContactState {
    /// The detached state: no load, no contact.
    pub const FREE: ContactState = ContactState {
        load: 0.0,
        radius: 0.0,
    };

    /// Contact area `pi a^2` (m^2).
    pub fn area(&self) -> f64 {
        PI * self.radius * self.radius
    }

    /// Whether the asperity is in contact (`a > 0`).
    pub fn in_contact(&self) -> bool {
        self.radius > 0.0
    }
}

/// A point where the asperity snaps or is pulled off (defined with the
/// axisymmetric contacts the laws are built on).
pub use crate::axisym::Instability;

/// An [`Instability`] in Maugis units ([`MaugisScales`]): load
/// `Pbar = P/(pi w R)`, interference `Dbar`, contact radius `A`. The form
/// tables and the sphere solver keep critical points in.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct InstabilityBar {
    /// `Pbar`.
    pub load_bar: f64,
    /// `Dbar`.
    pub interference_bar: f64,
    /// `A`.
    pub radius_bar: f64,
}

impl InstabilityBar {
    /// The instability in SI units for `scales` (N, m, m).
    pub fn to_si(&self, scales: &MaugisScales) -> Instability {
        Instability {
            load: self.load_bar * scales.load,
            interference: self.interference_bar * scales.interference,
            radius: self.radius_bar * scales.radius,
        }
    }
}

/// A single-asperity contact law: its physics. Object-safe, `Send + Sync`.
///
/// The load and contact radius on each branch and after a maximum
/// interference, the critical points (attach, detach, cutoff, pull-off,
/// breakpoints), the range of validity, and the capabilities that the
/// planner and the integrators ask before choosing a method
/// ([`has_history`](AsperityLaw::has_history),
/// [`remembers_maximum`](AsperityLaw::remembers_maximum),
/// [`reversible`](AsperityLaw::reversible),
/// [`smooth_in_root`](AsperityLaw::smooth_in_root),
/// [`power_form`](AsperityLaw::power_form),
/// [`radius_scaling`](AsperityLaw::radius_scaling),
/// [`interaction_range`](AsperityLaw::interaction_range)). How to evaluate
/// it faster (batches, SIMD lanes, prepared histories, fused sums, pruning
/// bounds, costs) is [`LawKernels`], which every law also implements.
///
/// Evaluation never fails and never returns NaN for finite `delta` below
/// [`max_interference`](AsperityLaw::max_interference): inputs are validated
/// when the law is built.
pub trait AsperityLaw: Send + Sync + fmt::Debug {
    /// Short lower-case name (`"hertz"`, `"jkr"`, ...).
    fn name(&self) -> &'static str;

    /// Load and contact radius at interference `delta` (m) on `branch`.
    fn state(&self, delta: f64, branch: Branch) -> ContactState;

    /// Load `P` (N) at `delta` on `branch`.
    fn load(&self, delta: f64, branch: Branch) -> f64 {
        self.state(delta, branch).load
    }

    /// State at `delta` (m) on retraction after the interference reached
    /// `delta_max` (m) on approach (`delta <= delta_max`). An asperity that
    /// never reached [`attach_interference`](AsperityLaw::attach_interference)
    /// stays on the approach branch.
    fn state_after(&self, delta: f64, delta_max: f64) -> ContactState {
        if delta_max >= self.attach_interference() {
            self.state(delta, Branch::Retract)
        } else {
            self.state(delta, Branch::Approach)
        }
    }

    /// Load only of [`state_after`](AsperityLaw::state_after) (N); laws
    /// that can skip the contact radius override it.
    fn load_after(&self, delta: f64, delta_max: f64) -> f64 {
        self.state_after(delta, delta_max).load
    }

    /// Whether the law has neither hysteresis nor memory:
    /// [`state_after`](AsperityLaw::state_after)`(delta, delta_max)` equals
    /// [`state`](AsperityLaw::state)`(delta, Approach)` bit for bit for every
    /// `delta` and `delta_max` (Hertz, DMT, Bradley). Monte Carlo sums on
    /// retraction then skip the maximum interferences. Default `false`
    /// (always safe).
    fn reversible(&self) -> bool {
        false
    }

    /// Whether the approach state is, between [`breakpoints`](AsperityLaw::breakpoints),
    /// a smooth function of `t = sqrt(delta - cutoff)` (m^(1/2)), with the
    /// contact starting at the [cutoff](AsperityLaw::cutoff_interference):
    /// Hertz (`P ~ t^3`, `a ~ t`) and the elastic-plastic fits (Hertz up to
    /// the first breakpoint, powers of `delta` beyond). Integrators then
    /// integrate in `t` instead of the height, where the contact onset's
    /// square-root singularity is gone and a few fixed high-order panels
    /// meet the tolerance (`GwModel`). Default `false` (always safe).
    fn smooth_in_root(&self) -> bool {
        false
    }

    /// Whether [`state_after`](AsperityLaw::state_after) depends on the
    /// value of `delta_max` beyond crossing the attach interference (plastic
    /// laws: the permanent flattening). Path-following sums
    /// ([`crate::montecarlo::MonteCarlo::sequence`]) then keep each
    /// asperity's maximum interference. Default `false`.
    fn remembers_maximum(&self) -> bool {
        false
    }

    /// Values of `delta_max` at which [`state_after`](AsperityLaw::state_after)
    /// changes character (default: the attach interference). Integrators
    /// split their quadrature there.
    fn history_breakpoints(&self) -> Vec<f64> {
        vec![self.attach_interference()]
    }

    /// History-dependent breakpoints: the maximum interferences
    /// `delta_max` (m, ascending) of the asperities whose retracting branch
    /// loses contact (or otherwise changes character) after the flat has
    /// retracted by `recovery` (m) from its closest approach, i.e. where
    /// `delta_max - delta_loss(delta_max) = recovery`. Integrators
    /// retracting by `recovery` split their quadrature at the summits with
    /// those maximum interferences (the contact count jumps there). Default:
    /// none (laws whose retraction branches end at fixed interferences,
    /// given by [`breakpoints`](AsperityLaw::breakpoints)). Elastic-plastic
    /// laws return the peaks whose residual interference is reached.
    fn contact_loss_peaks(&self, _recovery: f64) -> Vec<f64> {
        Vec::new()
    }

    /// Interference (m) at which an approaching asperity jumps onto the
    /// contact branch. `-inf` for laws with no hysteresis (Bradley).
    fn attach_interference(&self) -> f64;

    /// Interference (m) at which a retracting asperity jumps off (the end
    /// of the attached branch). `-inf` for laws with no hysteresis.
    fn detach_interference(&self) -> f64;

    /// Interference (m) below which the load is exactly zero on every branch.
    /// `-inf` for laws whose force never vanishes (Bradley).
    fn cutoff_interference(&self) -> f64;

    /// Interference (m) below which an asperity's load is negligible for
    /// placing the default start of a loading program, never for
    /// truncating a load: the [cutoff](AsperityLaw::cutoff_interference)
    /// (the default) for laws whose load vanishes exactly; finite for
    /// long-range laws whose load never vanishes but falls below a stated
    /// fraction of the pull-off (the calibrated Lennard-Jones law:
    /// [`crate::law::tabulated::RANGE_GAP`]). `-inf` for laws with no such
    /// range (rigid Bradley).
    fn interaction_range(&self) -> f64 {
        self.cutoff_interference()
    }

    /// Largest admissible interference (m); `+inf` except for rigid laws
    /// (Bradley: `z0`, where the gap closes and the load diverges).
    fn max_interference(&self) -> f64 {
        f64::INFINITY
    }

    /// Interferences (m) where the load on `branch` is discontinuous or has a
    /// discontinuous slope, ascending. Quadrature splits there.
    fn breakpoints(&self, branch: Branch) -> Vec<f64>;

    /// Pull-off: under [`Control::Load`] the most tensile load on the curve;
    /// under [`Control::Displacement`] the point where the attached branch
    /// ends and the asperity snaps off. `None` when nothing snaps (Hertz,
    /// rigid Bradley under displacement control): the load then follows the
    /// curve continuously back to zero.
    fn pull_off(&self, control: Control) -> Option<Instability>;

    /// Contact radius (m) at zero load on the attached branch; `None` for laws
    /// with no adhesion (Hertz) or no contact radius (rigid Bradley).
    fn zero_load_radius(&self) -> Option<f64>;

    /// The law as a sum of powers, when it is one on both branches (no
    /// hysteresis): statistical integration then uses closed forms `F_n`.
    /// `None` (the default) means "integrate numerically".
    fn power_form(&self) -> Option<PowerForm> {
        None
    }

    /// Whether a retracting asperity can differ from an approaching one at
    /// the same interference: adhesive hysteresis (attach and detach
    /// interferences differ) or memory of the maximum interference (the
    /// permanent flattening of plastic laws). Without history the
    /// retraction leg of a program equals its approach leg.
    fn has_history(&self) -> bool {
        self.remembers_maximum() || self.attach_interference() != self.detach_interference()
    }

    /// How the law scales with the asperity radius ([`RadiusScaling`]): the
    /// law at radius `k R` is this one with interference, load and area
    /// multiplied by the scaling's factors. `None` (the default) for laws
    /// that depend on `R` otherwise (Maugis–Dugdale: `lambda ~ R^(1/3)`),
    /// or are tables of one radius.
    fn radius_scaling(&self) -> Option<RadiusScaling> {
        None
    }
}

/// A law that is zero for `delta < onset` and, for `delta >= onset` on both
/// branches, `P = sum c_k (delta - onset)^n_k`, `pi a^2 = sum d_k (delta -
/// onset)^m_k`; every asperity past `onset` counts as a contact. Over heights
/// `z = sigma s` at separation `d`, each term integrates to
/// `c sigma^n F_n((d + onset)/sigma)` (Greenwood & Williamson 1966).
#[derive(Debug, Clone, PartialEq)]
pub struct PowerForm {
    /// Interference (m) where the terms start.
    pub onset: f64,
    /// Load terms `(c, n)`: `c (delta - onset)^n` in N, `c` in N/m^n.
    pub load: Vec<(f64, f64)>,
    /// Area terms `(d, m)`: `d (delta - onset)^m` in m^2.
    pub area: Vec<(f64, f64)>,
}
