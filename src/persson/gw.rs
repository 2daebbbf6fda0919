//! Greenwood–Williamson on the same spectrum: Gaussian summit heights
//! with McCool's parameters from the spectrum's moments (the rules of
//! `asperity surface`), closed forms in the Gaussian `F_n`.
//!
//! With summit density `eta`, radius `R`, summit-height deviation
//! `sigma` (McCool) and the flat at `d = h sigma` above the mean summit
//! height (Greenwood & Williamson 1966):
//! - `p = (4/3) eta E* R^(1/2) sigma^(3/2) F_3/2(h)`,
//! - `A/A0 = pi eta R sigma F_1(h)`,
//! - the mean gap, measured like the boundary-element and Persson ones
//!   between the flat and the mean plane of the heights, with every summit
//!   in contact flattened onto the flat (GW's deformation is local, so the
//!   gap is the rigid one with each cap of volume `pi R delta^2` removed):
//!   `u = sigma h + y_s + pi eta R sigma^2 F_2(h)`, `y_s = 4 sqrt(m0/(pi alpha))`
//!   the mean summit height above the mean plane (Nayak 1971).

use crate::error::{positive, Error, Result};
use crate::numeric::roots::brent;
use crate::special::gaussian_fn::gaussian_fn;
use crate::spectrum::Spectrum;
use crate::surface::{GwParameters, Moments, NayakPrediction};
use std::f64::consts::PI;

/// GW's model of a surface with given moments.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GwOnSpectrum {
    /// McCool's parameters.
    pub params: GwParameters,
    /// Summit-height standard deviation `sigma` (m).
    pub sigma: f64,
    /// Mean summit height above the mean plane `y_s` (m).
    pub mean_summit_height: f64,
    contact_modulus: f64,
}

/// GW's prediction at one mean pressure (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GwState {
    /// Mean pressure (Pa).
    pub pressure: f64,
    /// Separation of the flat from the mean summit height, over `sigma`.
    pub h: f64,
    /// `A/A0`.
    pub area_fraction: f64,
    /// Mean gap (m), module documentation.
    pub mean_gap: f64,
}

fn f(n: f64, h: f64) -> f64 {
    gaussian_fn(n, h).expect("closed-form order")
}

impl GwOnSpectrum {
    /// GW from moments `m` with contact modulus `E*` (Pa).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `contact_modulus`; [`Error::Invalid`]
    /// named `spectrum` when the bandwidth `alpha <= 0.8968` leaves McCool's
    /// summit heights no variance.
    pub fn from_moments(m: &Moments, contact_modulus: f64) -> Result<Self> {
        positive("contact_modulus", contact_modulus)?;
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
        Ok(GwOnSpectrum {
            params,
            sigma,
            mean_summit_height: NayakPrediction::from_moments(m).mean_height_m,
            contact_modulus,
        })
    }

    /// GW on the moments of `spectrum`.
    ///
    /// # Errors
    /// As [`GwOnSpectrum::from_moments`] and [`Spectrum::moments`].
    pub fn new(spectrum: &Spectrum, contact_modulus: f64) -> Result<Self> {
        Self::from_moments(&spectrum.moments()?, contact_modulus)
    }

    /// `(4/3) eta E* R^(1/2) sigma^(3/2)` (Pa): the pressure at `F_3/2 = 1`.
    fn pressure_scale(&self) -> f64 {
        4.0 / 3.0
            * self.params.density_per_m2
            * self.contact_modulus
            * self.params.radius_m.sqrt()
            * self.sigma.powf(1.5)
    }

    /// The state at separation `h` (in `sigma`, from the mean summit height).
    pub fn state_at(&self, h: f64) -> GwState {
        let (eta, r, s) = (self.params.density_per_m2, self.params.radius_m, self.sigma);
        GwState {
            pressure: self.pressure_scale() * f(1.5, h),
            h,
            area_fraction: PI * eta * r * s * f(1.0, h),
            mean_gap: s * h + self.mean_summit_height + PI * eta * r * s * s * f(2.0, h),
        }
    }

    /// The state at mean pressure `p > 0` (Pa): `h` from
    /// `F_3/2(h) = p/scale` by Brent's method polished by a Newton step
    /// (`F_3/2' = -(3/2) F_1/2`).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `pressure`; [`Error::NoConvergence`] if
    /// no separation in `[-60, 35]` sigma gives it.
    pub fn state(&self, pressure: f64) -> Result<GwState> {
        positive("pressure", pressure)?;
        let target = pressure / self.pressure_scale();
        let lf = |h: f64| f(1.5, h).ln() - target.ln();
        let no = || Error::NoConvergence {
            what: "GW separation at a pressure".into(),
            iterations: 0,
            residual: target,
        };
        let mut h = brent(lf, -60.0, 35.0, 1e-15).ok_or_else(no)?;
        let (v, d) = (f(1.5, h), -1.5 * f(0.5, h));
        if d != 0.0 {
            h -= (v - target) / d;
        }
        Ok(self.state_at(h))
    }
}
