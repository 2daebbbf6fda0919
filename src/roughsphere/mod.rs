//! The rough sphere: an elastic sphere (or paraboloid) of radius `R`
//! pressed on a Greenwood–Williamson surface (Greenwood & Tripp 1967, J.
//! Appl. Mech. 34, 153; Johnson, *Contact Mechanics*, sec. 13.4), with any
//! height distribution and any asperity law (Hertz, elastic-plastic with
//! history, JKR, DMT, Maugis–Dugdale, calibrated).
//!
//! The pressure at radius `r` is the GW pressure of the local gap, and the
//! gap contains the elastic displacement that pressure causes:
//!
//! ```text
//! p(r) = p_GW(h(r)),   h(r) = d + f(r) + w(r) - w(0),   E* w = C p
//! ```
//!
//! with `d` the separation at the centre between the sphere's surface and
//! the height origin (the mean plane for Gaussian heights), `f` the
//! undeformed profile (`r^2/(2R)`), `w` the half-space displacement (the
//! axisymmetric compliance `C` of [`crate::sphere::compliance`]) and `p_GW`
//! the local law of a [`crate::gw::GwModel`]: closed forms where they
//! exist, else Chebyshev tables of the model's own states; on retraction
//! each radius remembers its closest gap. In Greenwood–Tripp units
//! ([`units`]) with Hertz summits on Gaussian heights,
//! `p = mu F_3/2(d + rho^2 + u(rho) - u(0))`.
//!
//! Method: Newton on the nodal gaps at prescribed `d` (`newton.rs`),
//! continuation in `d`; the outer radius from the pressure's decay (where
//! the gap reaches the law's negligible-pressure gap), meshes uniform or
//! graded towards the contact edge; four or more nested meshes and
//! Richardson extrapolation with an error estimate for every output
//! (`solve.rs`). A state at a prescribed remote separation (the approach
//! of distant points, as a machine controls it) is found by a safeguarded
//! secant search on `d` (`problem.rs`).
//!
//! - [`GreenwoodTripp`]: the dimensionless problem of parameter `mu`
//!   (Hertz summits, Gaussian heights), states at central separations.
//! - [`RoughSphere`]: SI, any [`crate::gw::GwModel`]; per-state reports
//!   ([`SphereState`]: load, `p(r)`, the radius holding 95 % of the load,
//!   the Hertz radius at the same load, contacts, real area, the bump's
//!   resistance with Greenwood's interaction over its apparent area) and a
//!   [`crate::loading::LoadingModel`] over the remote separation (curves,
//!   pull-off, hysteresis energy, separation at a load).
//!
//! ```
//! use asperity::roughsphere::GreenwoodTripp;
//! let s = GreenwoodTripp::new(1.0)?.state(0.0, &[0.5])?;
//! // P* = 0.906501119 (independent solver, tests/data/rough_sphere.py)
//! assert!((s.load.value - 0.906_501_119_4).abs() < 1e-6 * 0.9065);
//! assert!(s.load.error < 1e-6 * s.load.value);
//! # Ok::<(), asperity::Error>(())
//! ```

mod converge;
mod gt;
mod loading_model;
mod local;
mod mesh;
mod newton;
mod observe;
mod problem;
mod report;
mod retract_table;
mod shared_heights;
mod shifted_density;
mod solve;
mod table;
pub mod units;
mod warning;

pub use gt::{GreenwoodTripp, GtPressure, GtState, MAX_MU, MIN_MU};
pub use problem::{RoughSphere, SphereProfile};
pub use report::{
    BumpElectrics, BumpResistance, PressureAt, SphereQuery, SphereState, AREA_FRACTION_WARNING,
    RADIUS_RATIO_WARNING,
};
pub use solve::{Estimate, Shape, SolverOptions};
pub use warning::SphereWarning;
