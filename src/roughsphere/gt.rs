//! The dimensionless Greenwood–Tripp problem: Hertz summits on Gaussian
//! heights, one parameter `mu` (Greenwood & Tripp 1967, in their units;
//! see [`super::units`]).

use super::local::LocalLaw;
use super::solve::{Core, Estimate, Shape, Solved, SolverOptions};
use crate::error::{Allowed, Result};
use crate::gw::{GwModel, RoughSurface};
use crate::heights::Gaussian;
use crate::law::Hertz;
use serde::Serialize;
use std::sync::Arc;

/// Smallest `mu` accepted (the rigid limit is exact to `~mu` relative there).
pub const MIN_MU: f64 = 1e-12;
/// Largest `mu` accepted.
pub const MAX_MU: f64 = 1e4;

/// The Greenwood–Tripp rough sphere of parameter `mu`.
#[derive(Debug, Clone)]
pub struct GreenwoodTripp {
    mu: f64,
    core: Core,
}

/// The pressure at one radius.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GtPressure {
    /// `rho = r/sqrt(2 R sigma)`.
    pub rho: f64,
    /// `p/(E* sqrt(sigma/(8R)))` with its error estimate.
    pub p: Estimate,
}

/// One state in Greenwood–Tripp units.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GtState {
    /// Separation of the mean planes at the centre, `d/sigma`.
    pub d: f64,
    /// `P* = 2 pi int p rho drho`.
    pub load: Estimate,
    /// Central deflection `u(0) = int_0^inf p drho` (units `sigma`).
    pub central_deflection: Estimate,
    /// Approach of distant points `u(0) - d` (units `sigma`; 0 when the
    /// undeformed sphere's apex touches the mean plane).
    pub approach: Estimate,
    /// Pressures at the requested radii.
    pub pressure: Vec<GtPressure>,
    /// Radius (`rho`) holding 95 % of the load.
    pub radius_95: Option<Estimate>,
    /// Outer mesh radius (`rho`).
    pub outer_radius: f64,
    /// Nodes of the finest mesh.
    pub nodes: usize,
    /// Whether the load met the tolerance before the node limit.
    pub converged: bool,
    /// `(rho, p)` at the finest mesh's nodes.
    pub profile: Vec<(f64, f64)>,
}

impl GreenwoodTripp {
    /// `mu = (8/3) eta sigma sqrt(2 R beta)` in `[1e-12, 1e4]`, default
    /// options.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `mu`.
    pub fn new(mu: f64) -> Result<Self> {
        Self::with_options(mu, SolverOptions::default())
    }

    /// As [`new`](Self::new) with `options`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `mu` or the bad option.
    pub fn with_options(mu: f64, options: SolverOptions) -> Result<Self> {
        Allowed::closed(MIN_MU, MAX_MU).check("mu", mu)?;
        options.validate()?;
        // R = sigma = E* = beta = 1 m / Pa, eta from mu: the local law is
        // then mu F_3/2(H) in units of E* sqrt(sigma/(8R)) = 1/sqrt(8).
        let eta = mu / (8.0 / 3.0 * 2f64.sqrt());
        let surface = RoughSurface::new(eta, 1.0, 1.0, 1.0)?;
        let model = GwModel::new(
            surface,
            Arc::new(Gaussian::new()),
            Arc::new(Hertz::new(1.0, 1.0)?),
        )?;
        let law = LocalLaw::new(&model, (1.0f64 / 8.0).sqrt(), options.tolerance)?;
        Ok(GreenwoodTripp {
            mu,
            core: Core {
                law: Arc::new(law),
                shape: Shape::Paraboloid,
                options,
            },
        })
    }

    /// `mu`.
    pub fn mu(&self) -> f64 {
        self.mu
    }

    fn report(&self, s: &Solved, rhos: &[f64]) -> GtState {
        let load = self.core.load(s);
        let u0 = self.core.central_deflection(s);
        let pressure = rhos
            .iter()
            .map(|&r| GtPressure {
                rho: r,
                p: self.core.pressure_at(s, r),
            })
            .collect();
        let last = s.levels.last().unwrap();
        let (rho, p) = self.core.profile(s);
        GtState {
            d: s.d,
            load,
            central_deflection: u0,
            approach: Estimate {
                value: u0.value - s.d,
                error: u0.error,
            },
            pressure,
            radius_95: self.core.load_radius(s, 0.95),
            outer_radius: last.mesh.rho_max(),
            nodes: last.mesh.len(),
            converged: s.converged,
            profile: rho.into_iter().zip(p).collect(),
        }
    }

    /// The state at central separation `d` (units `sigma`) with the
    /// pressure at radii `rhos`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `d` (not finite) or `rho`
    /// (negative or not finite); [`crate::Error::NoConvergence`].
    pub fn state(&self, d: f64, rhos: &[f64]) -> Result<GtState> {
        Ok(self.states(&[d], rhos)?.remove(0))
    }

    /// The states at separations `ds` (any order; computed by continuation
    /// from the largest down, returned in the order given).
    ///
    /// # Errors
    /// As [`state`](Self::state).
    pub fn states(&self, ds: &[f64], rhos: &[f64]) -> Result<Vec<GtState>> {
        for &d in ds {
            crate::error::finite("d", d)?;
        }
        for &r in rhos {
            Allowed::closed_open(0.0, f64::INFINITY).check("rho", r)?;
        }
        let mut order: Vec<usize> = (0..ds.len()).collect();
        order.sort_by(|&a, &b| ds[b].total_cmp(&ds[a]));
        let mut out: Vec<Option<GtState>> = vec![None; ds.len()];
        let mut prev: Option<Solved> = None;
        for i in order {
            let s = self.core.approach(ds[i], prev.as_ref())?;
            out[i] = Some(self.report(&s, rhos));
            prev = Some(s);
        }
        Ok(out
            .into_iter()
            .map(|s| s.expect("every state solved"))
            .collect())
    }
}
