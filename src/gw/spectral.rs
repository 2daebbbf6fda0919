//! GW on a surface known by its spectral moments `m0, m2, m4` (an analytic
//! spectrum, or a measured map's finite differences): McCool's summit
//! density `eta`, radius `R` and summit-height deviation `sigma`
//! ([`GwParameters`]), Hertz summits and Gaussian heights, integrated by
//! the one [`GwModel`] (closed-form `F_n`) and solved at a mean pressure by
//! the one [`LoadingModel::separation_at_load`]. No physics of its own
//! beyond the mean gap's definition.
//!
//! With the flat at `d = h sigma` above the mean summit height
//! (Greenwood & Williamson 1966), per nominal area `A_n`:
//! - `p = P/A_n = (4/3) eta E* R^(1/2) sigma^(3/2) F_3/2(h)`,
//! - `A/A0 = pi eta R sigma F_1(h)`,
//! - the mean gap, measured like the boundary-element and Persson ones
//!   between the flat and the mean plane of the heights, with every summit
//!   in contact flattened onto the flat (GW's deformation is local, so the
//!   gap is the rigid one with each summit's cap, of volume `pi R delta^2`
//!   ([`CapVolume`]), removed): `u = d + y_s + V/A_n = sigma h + y_s +
//!   pi eta R sigma^2 F_2(h)`, `y_s = 4 sqrt(m0/(pi alpha))` the mean
//!   summit height above the mean plane (Nayak 1971).

use super::{Accuracy, GwModel, Method, RoughSurface};
use crate::error::{positive, Error, Result};
use crate::heights::Gaussian;
use crate::law::{ContactState, Hertz, PowerForm};
use crate::loading::{History, LoadingModel, Observable, Observables, PerAsperity};
use crate::surface::{GwParameters, Moments, NayakPrediction};
use std::f64::consts::PI;
use std::sync::Arc;

/// GW's local deformation of one summit of radius `R` (m): in contact at
/// interference `delta` it is flattened onto the flat, losing the
/// paraboloidal cap above it, of volume `V = pi R delta^2` (m^3)
/// (Greenwood & Williamson 1966). From the contact state, with Hertz's
/// `a^2 = R delta`: `V = pi a^4/R = (pi a^2)^2/(pi R)` (0 out of contact).
/// For a law whose area is a sum of powers `pi a^2 = sum d_k x^m_k`
/// (`x = delta - onset`) the volume is the square of that sum over `pi R`
/// ([`PerAsperity::power_terms`]), so [`GwModel`] sums it in closed form:
/// for Hertz summits `eta A_n pi R sigma^2 F_2(h)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CapVolume {
    radius: f64,
}

impl CapVolume {
    /// The cap volume of summits of radius `radius` (m).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `radius` unless finite and > 0.
    pub fn new(radius: f64) -> Result<Self> {
        positive("radius", radius)?;
        Ok(CapVolume { radius })
    }
}

impl PerAsperity for CapVolume {
    fn name(&self) -> &str {
        "cap_volume_m3"
    }

    /// `pi a^4 / R` (m^3).
    #[inline]
    fn value(&self, state: &ContactState) -> f64 {
        let a2 = state.radius * state.radius;
        PI * a2 * a2 / self.radius
    }

    /// `(sum d_k x^m_k)^2 / (pi R)`: the terms `d_i d_j/(pi R)` of order
    /// `m_i + m_j` (Hertz: `pi R x^2`).
    fn power_terms(&self, law: &PowerForm) -> Option<Vec<(f64, f64)>> {
        let scale = PI * self.radius;
        Some(
            law.area
                .iter()
                .flat_map(|&(di, mi)| {
                    law.area
                        .iter()
                        .map(move |&(dj, mj)| (di * dj / scale, mi + mj))
                })
                .collect(),
        )
    }
}

/// GW on spectral moments: Hertz summits with McCool's parameters on
/// Gaussian heights (module documentation).
#[derive(Debug, Clone)]
pub struct GwOnMoments {
    /// McCool's parameters.
    pub params: GwParameters,
    /// Summit-height standard deviation `sigma` (m).
    pub sigma: f64,
    /// Mean summit height above the mean plane `y_s` (m).
    pub mean_summit_height: f64,
    model: GwModel,
    observables: Observables,
    /// The slot of the caps' volume in `observables`' totals.
    cap_slot: usize,
}

/// GW's prediction at one mean pressure (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GwPressureState {
    /// Mean pressure `P/A_n` (Pa).
    pub pressure: f64,
    /// Separation `d` of the flat from the mean summit height (m).
    pub separation: f64,
    /// `h = d/sigma`.
    pub h: f64,
    /// `A/A0`.
    pub area_fraction: f64,
    /// Mean gap `u` (m), module documentation.
    pub mean_gap: f64,
}

/// Relative tolerance of [`GwOnMoments`]'s model: closed forms only, and
/// the loads met to 1e-12 ([`LoadingModel::load_tolerance`]; the
/// separation itself is found to a few ulps).
const MOMENTS_RTOL: f64 = 1e-12;
/// Stride (in `sigma`) of the search start below the interaction onset:
/// the separation solver looks 50 `sigma` below its start.
const START_STRIDE: f64 = 40.0;
/// Most strides below the onset: separations down to about `-170 sigma`
/// (the solver's 50 `sigma` below the lowest start).
const START_STRIDES: usize = 4;
/// How far below its start [`LoadingModel::separation_at_load`] looks,
/// in `sigma` (for the message).
const LOAD_SEARCH_SIGMAS: f64 = 50.0;

impl GwOnMoments {
    /// GW from moments `m` with contact modulus `E*` (Pa) on a nominal
    /// area `A_n` (m^2). Pressures, fractions and gaps do not depend on
    /// `A_n`; totals such as a resistance do.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `contact_modulus` or `nominal_area`;
    /// [`Error::Invalid`] named `spectrum` when the bandwidth
    /// `alpha <= 0.8968` leaves McCool's summit heights no variance.
    pub fn new(m: &Moments, contact_modulus: f64, nominal_area: f64) -> Result<Self> {
        positive("contact_modulus", contact_modulus)?;
        positive("nominal_area", nominal_area)?;
        let params = GwParameters::from_moments(m);
        let sigma = params.sigma_m.ok_or_else(|| {
            Error::invalid(
                "spectrum",
                format!(
                    "bandwidth alpha = {} <= 0.8968: no summit-height variance",
                    m.alpha()
                ),
            )
        })?;
        let r = params.radius_m;
        let surface = RoughSurface::new(params.density_per_m2, r, sigma, nominal_area)?;
        let law = Arc::new(Hertz::new(r, contact_modulus)?);
        let accuracy = Accuracy::new(MOMENTS_RTOL)?.with_method(Method::ClosedForm);
        let model = GwModel::new(surface, Arc::new(Gaussian::new()), law)?.with_accuracy(accuracy);
        let cap = Observable::Custom(Arc::new(CapVolume::new(r)?));
        let observables = Observables::standard(true, true, false).with(cap.clone())?;
        let cap_slot = observables.slot(&cap).expect("just added");
        Ok(GwOnMoments {
            params,
            sigma,
            mean_summit_height: NayakPrediction::from_moments(m).mean_height_m,
            model,
            observables,
            cap_slot,
        })
    }

    /// The model: Hertz summits on Gaussian heights, closed forms only
    /// ([`Method::ClosedForm`]) to a relative tolerance of 1e-12. Other
    /// observables (a spot conductance) need
    /// [`GwModel::with_accuracy`] with quadrature allowed.
    pub fn model(&self) -> &GwModel {
        &self.model
    }

    /// The nominal area `A_n` (m^2).
    pub fn nominal_area(&self) -> f64 {
        self.model.surface().nominal_area
    }

    /// The state with the flat at separation `d` (m) above the mean summit
    /// height: `p = P/A_n`, `A/A0 = A/A_n`, `u = d + y_s + V/A_n`.
    ///
    /// # Errors
    /// As [`LoadingModel::state`] (a non-finite separation).
    pub fn state_at(&self, separation: f64) -> Result<GwPressureState> {
        let s = self
            .model
            .state(separation, History::Approach, &self.observables)?;
        let a_n = self.nominal_area();
        let total = |slot: usize| s.totals.get(slot).unwrap_or(0.0) / a_n;
        Ok(GwPressureState {
            pressure: total(0),
            separation,
            h: separation / self.sigma,
            area_fraction: total(1),
            mean_gap: separation + self.mean_summit_height + total(self.cap_slot),
        })
    }

    /// The state at mean pressure `p > 0` (Pa): the separation where the
    /// load reaches `p A_n` ([`LoadingModel::separation_at_load`], to a
    /// few ulps of the separation, the load met to 1e-12), searched from
    /// the interaction onset or up to `START_STRIDES` (4) strides of
    /// `START_STRIDE` (40) `sigma` lower where the load there is still below
    /// the target.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `pressure`; [`Error::Invalid`] naming
    /// `pressure` when no separation gives it (below what the Gaussian
    /// tail resolves at the interaction onset, or beyond the deepest
    /// separation searched).
    pub fn state(&self, pressure: f64) -> Result<GwPressureState> {
        positive("pressure", pressure)?;
        let target = pressure * self.nominal_area();
        let start = self.search_start(target)?;
        let d = self
            .model
            .separation_at_load(target, start)
            .map_err(|e| match e.field() {
                Some("start_separation") => Error::invalid(
                    "pressure",
                    format!(
                        "{pressure:e} Pa is below GW's resolution: the summits' load at the \
                         interaction onset, {:.1} sigma above the mean summit height, already \
                         reaches it",
                        start / self.sigma
                    ),
                ),
                Some("max_load") => Error::invalid(
                    "pressure",
                    format!(
                        "{pressure:e} Pa is not met by GW's load at separations above {:.1} \
                         sigma below the mean summit height",
                        -(start / self.sigma - LOAD_SEARCH_SIGMAS)
                    ),
                ),
                _ => e,
            })?;
        self.state_at(d)
    }

    /// The start of the separation search for a load `target` (N).
    fn search_start(&self, target: f64) -> Result<f64> {
        let mut start = self.model.interaction_onset();
        for _ in 0..START_STRIDES {
            let next = start - START_STRIDE * self.sigma;
            let load = self
                .model
                .state(next, History::Approach, &Observables::LOAD)?
                .load()
                .unwrap_or(0.0);
            if !(load < target) {
                break;
            }
            start = next;
        }
        Ok(start)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::special::gaussian_fn::gaussian_fn;

    /// The closed-form totals are GW's formulas in `F_n`, and the cap
    /// volume's closed form is its quadrature.
    #[test]
    fn totals_are_the_closed_forms() {
        let m = Moments::new(1e-16, 2.7e-4, 5.8e12).unwrap();
        let gw = GwOnMoments::new(&m, 1e9, 1e-8).unwrap();
        let (eta, r, s) = (gw.params.density_per_m2, gw.params.radius_m, gw.sigma);
        let f = |n: f64, h: f64| gaussian_fn(n, h).unwrap();
        for h in [-1.0, 0.5, 2.0, 4.0] {
            let st = gw.state_at(h * s).unwrap();
            let p = 4.0 / 3.0 * eta * 1e9 * r.sqrt() * s.powf(1.5) * f(1.5, h);
            let a = PI * eta * r * s * f(1.0, h);
            let u = s * h + gw.mean_summit_height + PI * eta * r * s * s * f(2.0, h);
            assert!((st.pressure / p - 1.0).abs() < 1e-14, "{h}");
            assert!((st.area_fraction / a - 1.0).abs() < 1e-14, "{h}");
            assert!((st.mean_gap / u - 1.0).abs() < 1e-14, "{h}");
            let back = gw.state(st.pressure).unwrap();
            assert!((back.h - h).abs() < 1e-13, "{h}: {}", back.h);
        }
        let quad = gw.model().clone().with_accuracy(
            Accuracy::new(1e-12)
                .unwrap()
                .with_method(Method::Quadrature),
        );
        let obs = &gw.observables;
        for h in [0.0, 2.5] {
            let c = gw.model().state(h * s, History::Approach, obs).unwrap();
            let q = quad.state(h * s, History::Approach, obs).unwrap();
            let (vc, vq) = (
                c.totals.get(gw.cap_slot).unwrap(),
                q.totals.get(gw.cap_slot).unwrap(),
            );
            assert!((vc / vq - 1.0).abs() < 1e-10, "{h}: {vc} {vq}");
        }
        assert_eq!(
            GwOnMoments::new(&m, 0.0, 1.0).unwrap_err().field(),
            Some("contact_modulus")
        );
        assert_eq!(gw.state(-1.0).unwrap_err().field(), Some("pressure"));
    }
}
