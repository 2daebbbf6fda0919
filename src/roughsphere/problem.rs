//! The rough sphere in SI units: an elastic sphere (or paraboloid) of
//! radius `R` pressed on any Greenwood–Williamson surface ([`GwModel`]: any
//! height distribution, any asperity law), controlled by the remote
//! separation as a machine would.
//!
//! Separations: `d` is the separation at the centre between the sphere's
//! surface and the origin of the summit heights (the mean plane for
//! Gaussian heights); the remote separation `s = d - w(0)` subtracts the
//! central elastic deflection, so `-s` is the approach of distant points
//! (0 when the undeformed apex touches the height origin). The solver works
//! at prescribed `d` (`solve.rs`); a state at prescribed `s` is found by a
//! safeguarded secant search on `d` (the first crossing coming from far
//! apart on approach, from the closest state on retraction, as a loading
//! machine would meet it).

use super::local::LocalLaw;
use super::solve::{Core, Estimate, Retraction, Shape, Solved, SolverOptions};
use super::units::GreenwoodTrippUnits;
use crate::error::{positive, Error, Result};
use crate::gw::GwModel;
use crate::loading::Observable;
use std::sync::{Arc, Mutex};

/// Approach states kept for continuation.
const CACHE_STATES: usize = 16;
/// Retractions (per closest separation) kept.
const CACHE_RETRACTIONS: usize = 4;
/// Most solves of one remote-separation search.
const MAX_SEARCH: usize = 80;

/// The sphere's undeformed profile.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SphereProfile {
    /// `r^2/(2R)` (Hertz, Greenwood & Tripp).
    Paraboloid,
    /// `R - sqrt(R^2 - r^2)`, meshes stopping short of the equator.
    Sphere,
}

#[derive(Debug, Default)]
struct Cache {
    /// Approach states, most recent last.
    approach: Vec<Arc<Solved>>,
    /// Retractions with their states, most recent last.
    retractions: Vec<(f64, Arc<Retraction>, Vec<Arc<Solved>>)>,
}

/// An elastic sphere on a rough surface (Greenwood & Tripp 1967).
#[derive(Debug)]
pub struct RoughSphere {
    model: GwModel,
    units: GreenwoodTrippUnits,
    profile: SphereProfile,
    pub(crate) core: Core,
    /// The spot conductance whose spread over the bump its states carry
    /// ([`RoughSphere::with_spot_conductance`]).
    pub(crate) spots: Option<Observable>,
    cache: Mutex<Cache>,
}

impl Clone for RoughSphere {
    fn clone(&self) -> Self {
        RoughSphere {
            model: self.model.clone(),
            units: self.units,
            profile: self.profile,
            core: self.core.clone(),
            spots: self.spots.clone(),
            cache: Mutex::new(Cache::default()),
        }
    }
}

impl RoughSphere {
    /// A sphere of radius `sphere_radius` (m) and contact modulus
    /// `contact_modulus` (Pa, of the sphere against the rough body's bulk)
    /// on the surface of `model` (its nominal area is not used: the
    /// apparent area is the solution's).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `sphere_radius`, `contact_modulus` or an
    /// option; the model's quadrature failures while tabulating its local
    /// law.
    pub fn new(
        model: GwModel,
        sphere_radius: f64,
        contact_modulus: f64,
        profile: SphereProfile,
        options: SolverOptions,
    ) -> Result<Self> {
        positive("sphere_radius", sphere_radius)?;
        positive("contact_modulus", contact_modulus)?;
        options.validate()?;
        let sigma = model.surface().sigma;
        let units = GreenwoodTrippUnits::new(sphere_radius, sigma, contact_modulus)?;
        let law = LocalLaw::new(&model, units.pressure(), options.tolerance)?;
        let shape = match profile {
            SphereProfile::Paraboloid => Shape::Paraboloid,
            SphereProfile::Sphere => Shape::Sphere {
                equator: (sphere_radius / (2.0 * sigma)).sqrt(),
            },
        };
        Ok(RoughSphere {
            model,
            units,
            profile,
            core: Core {
                law: Arc::new(law),
                shape,
                options,
            },
            spots: None,
            cache: Mutex::new(Cache::default()),
        })
    }

    /// This sphere whose states, when their observables include the spot
    /// conductance `conductance` (S, [`crate::electrical::ResistanceObservables::conductance`]),
    /// carry the spots' conductance-weighted mean inverse distance over
    /// the bump ([`Totals::inverse_distance`](crate::loading::Totals::inverse_distance),
    /// 1/m): from it a state's resistance takes Greenwood's interaction over
    /// the bump's own apparent area rather than a nominal one.
    pub fn with_spot_conductance(mut self, conductance: Observable) -> Self {
        self.spots = Some(conductance);
        self
    }

    /// The Greenwood–Tripp units of this sphere and surface.
    pub fn units(&self) -> GreenwoodTrippUnits {
        self.units
    }

    /// The surface model.
    pub fn model(&self) -> &GwModel {
        &self.model
    }

    /// The profile.
    pub fn profile(&self) -> SphereProfile {
        self.profile
    }

    /// Greenwood–Tripp's `mu = (8/3) eta sigma sqrt(2 R beta)` of this
    /// sphere and surface (the stiffness ratio of the rough layer and the
    /// bulk; the local law need not be Hertz).
    pub fn mu(&self) -> f64 {
        let s = self.model.surface();
        super::units::greenwood_tripp_mu(s.density, s.sigma, self.units.sphere_radius, s.radius)
    }

    /// Central separation `d` (units `sigma`) beyond which no pressure is
    /// felt (`|p| < 1e-16` of its scale everywhere).
    pub(crate) fn top(&self) -> f64 {
        self.core.law.top()
    }

    /// Remote separation `s = d - u(0)` of a solved state (units `sigma`).
    pub(crate) fn remote(&self, s: &Solved) -> Estimate {
        let u0 = self.core.central_deflection(s);
        Estimate {
            value: s.d - u0.value,
            error: u0.error,
        }
    }

    /// `ds/dd` on the coarse level (1 minus the slope of the central
    /// deflection), from the continuation's tangent.
    fn remote_slope(&self, s: &Solved) -> f64 {
        let l = &s.levels[0];
        match &s.tangent {
            Some(t) => {
                let dp: Vec<f64> = l.sol.dp.iter().zip(t).map(|(a, b)| a * b).collect();
                1.0 - l.mesh.central_deflection(&dp)
            }
            None => 1.0,
        }
    }

    fn remember(&self, s: &Arc<Solved>) {
        if let Ok(mut c) = self.cache.lock() {
            c.approach.push(s.clone());
            if c.approach.len() > CACHE_STATES {
                c.approach.remove(0);
            }
        }
    }

    /// The cached approach state nearest above `d` (for continuation).
    fn nearest_above(&self, d: f64) -> Option<Arc<Solved>> {
        let c = self.cache.lock().ok()?;
        c.approach
            .iter()
            .filter(|s| s.d >= d)
            .min_by(|a, b| a.d.total_cmp(&b.d))
            .cloned()
    }

    /// The approach state at central separation `d` (units `sigma`).
    ///
    /// # Errors
    /// As [`Core::approach`].
    pub(crate) fn approach_central(&self, d: f64) -> Result<Arc<Solved>> {
        let start = self.nearest_above(d);
        if let Some(s) = &start {
            if s.d == d {
                return Ok(s.clone());
            }
        }
        let s = Arc::new(self.core.approach(d, start.as_deref())?);
        self.remember(&s);
        Ok(s)
    }

    /// Tolerance of the remote-separation search (units `sigma`): `1e-10`
    /// relative, or the remote separation's own error estimate where that
    /// is larger (the solver's mesh error in the central deflection: below
    /// it the remote separation is not a monotone function of the central
    /// one and a bracket cannot close further).
    fn remote_tolerance(&self, target: f64, s: &Solved) -> f64 {
        let u0 = self.core.central_deflection(s);
        (1e-10 * (1.0 + target.abs() + u0.value.abs())).max(u0.error.abs())
    }

    /// The approach state at remote separation `target` (units `sigma`):
    /// the first crossing coming from far apart.
    ///
    /// # Errors
    /// [`Error::NoConvergence`] when the search or a solve fails.
    pub(crate) fn approach_remote(&self, target: f64) -> Result<Arc<Solved>> {
        crate::error::finite("separation", target)?;
        let top = self.top();
        if target >= top {
            // no pressure anywhere: d = s
            return self.approach_central(target);
        }
        // Start: the cached state with the smallest remote separation
        // still above the target, else from far apart.
        let cached: Option<Arc<Solved>> = self.cache.lock().ok().and_then(|c| {
            c.approach
                .iter()
                .filter(|s| self.remote(s).value >= target)
                .min_by(|a, b| self.remote(a).value.total_cmp(&self.remote(b).value))
                .cloned()
        });
        let mut hi = match cached {
            Some(s) => s,
            None => self.approach_central(top)?,
        };
        let mut lo: Option<Arc<Solved>> = None;
        for _ in 0..MAX_SEARCH {
            let r_hi = self.remote(&hi).value;
            if (r_hi - target).abs() <= self.remote_tolerance(target, &hi) {
                return Ok(hi);
            }
            let d_next = match &lo {
                None => {
                    let slope = self.remote_slope(&hi).max(0.05);
                    hi.d - ((r_hi - target) / slope).min(4.0 + 0.5 * hi.d.abs())
                }
                Some(lo) => {
                    let r_lo = self.remote(lo).value;
                    let t = ((target - r_lo) / (r_hi - r_lo)).clamp(0.02, 0.98);
                    lo.d + t * (hi.d - lo.d)
                }
            };
            let next = self.approach_central(d_next)?;
            let r = self.remote(&next).value;
            if (r - target).abs() <= self.remote_tolerance(target, &next) {
                return Ok(next);
            }
            if r >= target {
                hi = next;
            } else {
                lo = Some(next);
            }
        }
        Err(Error::NoConvergence {
            what: format!("rough sphere: central separation for remote separation {target} sigma"),
            iterations: MAX_SEARCH,
            residual: self.remote(&hi).value - target,
        })
    }

    /// The retraction after the approach came to remote separation
    /// `closest` (units `sigma`), cached.
    fn retraction(&self, closest: f64) -> Result<Arc<Retraction>> {
        if let Ok(c) = self.cache.lock() {
            if let Some((_, r, _)) = c.retractions.iter().find(|(k, _, _)| *k == closest) {
                return Ok(r.clone());
            }
        }
        let deepest = self.approach_remote(closest)?;
        let r = Arc::new(self.core.retraction(deepest)?);
        if let Ok(mut c) = self.cache.lock() {
            c.retractions.push((closest, r.clone(), Vec::new()));
            if c.retractions.len() > CACHE_RETRACTIONS {
                c.retractions.remove(0);
            }
        }
        Ok(r)
    }

    fn retract_central(&self, d: f64, r: &Arc<Retraction>) -> Result<Arc<Solved>> {
        let start: Option<Arc<Solved>> = self.cache.lock().ok().and_then(|c| {
            c.retractions
                .iter()
                .find(|(_, x, _)| Arc::ptr_eq(x, r))
                .and_then(|(_, _, states)| {
                    states
                        .iter()
                        .filter(|s| s.d <= d)
                        .max_by(|a, b| a.d.total_cmp(&b.d))
                        .cloned()
                })
        });
        if let Some(s) = &start {
            if s.d == d {
                return Ok(s.clone());
            }
        }
        let s = Arc::new(self.core.retract(d, r, start.as_deref())?);
        if let Ok(mut c) = self.cache.lock() {
            if let Some((_, _, states)) =
                c.retractions.iter_mut().find(|(_, x, _)| Arc::ptr_eq(x, r))
            {
                states.push(s.clone());
                if states.len() > CACHE_STATES {
                    states.remove(0);
                }
            }
        }
        Ok(s)
    }

    /// The retraction state at remote separation `target >= closest`
    /// (units `sigma`): the first crossing coming up from the closest state.
    ///
    /// # Errors
    /// As [`approach_remote`](Self::approach_remote).
    pub(crate) fn retract_remote(&self, target: f64, closest: f64) -> Result<Arc<Solved>> {
        crate::error::finite("separation", target)?;
        let r = self.retraction(closest)?;
        let mut lo = r.deepest.clone();
        if target <= closest {
            return Ok(lo);
        }
        let mut hi: Option<Arc<Solved>> = None;
        for _ in 0..MAX_SEARCH {
            let r_lo = self.remote(&lo).value;
            if (r_lo - target).abs() <= self.remote_tolerance(target, &lo) {
                return Ok(lo);
            }
            let d_next = match &hi {
                None => {
                    let slope = self.remote_slope(&lo).max(0.05);
                    lo.d + ((target - r_lo) / slope).min(4.0 + 0.5 * lo.d.abs())
                }
                Some(hi) => {
                    let r_hi = self.remote(hi).value;
                    let t = ((target - r_lo) / (r_hi - r_lo)).clamp(0.02, 0.98);
                    lo.d + t * (hi.d - lo.d)
                }
            };
            let next = self.retract_central(d_next, &r)?;
            let rn = self.remote(&next).value;
            if (rn - target).abs() <= self.remote_tolerance(target, &next) {
                return Ok(next);
            }
            if rn <= target {
                lo = next;
            } else {
                hi = Some(next);
            }
        }
        Err(Error::NoConvergence {
            what: format!(
                "rough sphere: central separation for remote separation {target} sigma on retraction"
            ),
            iterations: MAX_SEARCH,
            residual: self.remote(&lo).value - target,
        })
    }
}
