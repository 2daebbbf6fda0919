//! Whether a rough surface is sticky: four criteria from the roughness's
//! scales and the adhesive interaction, on a height map or a spectrum.
//!
//! The roughness enters through three numbers ([`Roughness`]): the RMS
//! gradient `h' = sqrt(<|grad h|^2>)`, the RMS curvature `h'' =
//! sqrt(<(lap h / 2)^2>)` (half the Laplacian, the mean curvature) and the
//! elastic energy per nominal area of full contact `U_full/A0` (J/m^2);
//! a map adds its pixel size `dx`. The interaction is the exponential
//! `phi(g) = -w exp(-g/rho)` of the boundary elements ([`AdhesiveInteraction`]:
//! contact modulus `E*`, work of adhesion `w`, range `rho`). With them
//! ([`Criteria::new`]; `docs/physics.md`, "Stickiness criteria"):
//! - Pastewka & Robbins (PNAS 111, 3298, 2014, eq. 10 with `kappa_rep = 2`
//!   and `d_rep = 4 h'/h''`): `h' E* rho/(2 w) (h'^2/(h'' rho))^(2/3)`;
//!   below 1 the surfaces stick. Valid for short-ranged adhesion,
//!   `rho/g0 < 0.1` with `g0 = (16/3) h'^2/h''` (Monti, Sanner & Pastewka,
//!   Tribol. Lett. 69, 80, 2021), and only up to the onset of stickiness
//!   (the DMT-like regime it is derived in);
//! - Persson & Tosatti (J. Chem. Phys. 115, 5597, 2001): `U_full/(A0 w)`;
//!   below 1 the adhesion pays for full contact;
//! - the Tabor parameter at the short-wavelength scale, the summits'
//!   radius `R = 1/h''` (Müser's generalised Tabor parameter, Wang, Zhou &
//!   Müser, Lubricants 9, 17, 2021): `mu_T = R^(1/3) (w/E*)^(2/3)/rho`;
//! - Müser's discretisation number (ibid., eq. 9):
//!   `mu_rho = sqrt(|phi''|_max dx/E*) = sqrt(w dx/(E* rho^2))`, the
//!   interaction's stiffness against a pixel's; below about 0.5 the grid
//!   resolves the interaction.
//!
//! On a spectrum ([`Roughness::of_spectrum`]) the moments are exact
//! integrals and `dx = pi/q_max`, the pixel of the grid whose Nyquist
//! wavevector is the spectrum's largest. On a periodic map
//! ([`crate::bem::Problem::roughness`]) they are finite differences and the
//! discrete elastic energy, the definitions of Adhesion 0.93's example on
//! the contact-mechanics challenge (SurfaceTopography's `rms_gradient`,
//! `rms_curvature_from_area`, the periodic FFT half-space's energy).

use crate::error::{positive, Result};
use crate::spectrum::Spectrum;
use serde::Serialize;
use std::f64::consts::PI;

/// The validity bound of Pastewka & Robbins' criterion: `rho/g0` below it.
pub const PASTEWKA_ROBBINS_RANGE_LIMIT: f64 = 0.1;

/// Müser's bound on `mu_rho`: above it the grid does not resolve the
/// interaction.
pub const MU_RHO_LIMIT: f64 = 0.5;

/// The roughness's scales the criteria need.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Roughness {
    /// RMS gradient `h'` (dimensionless).
    pub slope_rms: f64,
    /// RMS curvature `h''` (1/m): RMS of half the Laplacian.
    pub curvature_rms: f64,
    /// Elastic energy per nominal area of full contact `U_full/A0`
    /// (J/m^2).
    pub full_contact_energy: f64,
    /// The pixel size `dx` (m) of `mu_rho`.
    pub pixel_size: f64,
}

impl Roughness {
    /// The scales of an isotropic spectrum `C(q)` (m^4) with contact
    /// modulus `E*` (Pa): `h'^2 = 2 pi int q^3 C dq`,
    /// `h''^2 = (pi/2) int q^5 C dq` (`<(lap h)^2> = 2 pi int q^5 C dq`),
    /// `U_full/A0 = (pi E*/2) int q^2 C dq` (Persson's), `dx = pi/q_max`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `contact_modulus`.
    pub fn of_spectrum(spectrum: &Spectrum, contact_modulus: f64) -> Result<Self> {
        positive("contact_modulus", contact_modulus)?;
        Ok(Roughness {
            slope_rms: spectrum.slope_rms(),
            curvature_rms: (0.5 * PI * spectrum.integral(5.0)).sqrt(),
            full_contact_energy: 0.5 * PI * contact_modulus * spectrum.integral(2.0),
            pixel_size: PI / spectrum.q_max(),
        })
    }
}

/// The exponential adhesive interaction and the modulus.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdhesiveInteraction {
    /// Contact modulus `E*` (Pa).
    pub contact_modulus: f64,
    /// Work of adhesion `w` (J/m^2).
    pub energy: f64,
    /// Range `rho` (m).
    pub range: f64,
}

/// The four criteria (module documentation), with Pastewka & Robbins'
/// validity.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Criteria {
    /// Pastewka & Robbins' number `h' E* rho/(2 w) (h'^2/(h'' rho))^(2/3)`:
    /// sticky below 1.
    pub pastewka_robbins: f64,
    /// Its gap scale `g0 = (16/3) h'^2/h''` (m).
    #[serde(rename = "pastewka_robbins_g0_m")]
    pub g0: f64,
    /// `rho/g0`: the criterion holds below
    /// [`PASTEWKA_ROBBINS_RANGE_LIMIT`].
    pub range_over_g0: f64,
    /// Whether `rho/g0 < 0.1`.
    pub pastewka_robbins_valid: bool,
    /// Persson & Tosatti's `U_full/(A0 w)`: full contact pays below 1.
    pub persson_tosatti: f64,
    /// The Tabor parameter `R^(1/3) (w/E*)^(2/3)/rho` at `R = 1/h''`.
    pub tabor: f64,
    /// Müser's `mu_rho = sqrt(w dx/(E* rho^2))`: the grid resolves the
    /// interaction below [`MU_RHO_LIMIT`].
    pub mu_rho: f64,
}

impl Criteria {
    /// The criteria of `roughness` with `interaction`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `contact_modulus`,
    /// `adhesion_energy`, `adhesion_range`, `slope_rms`, `curvature_rms`,
    /// `full_contact_energy` or `pixel_size` unless finite and > 0.
    pub fn new(roughness: &Roughness, interaction: &AdhesiveInteraction) -> Result<Self> {
        let e = positive("contact_modulus", interaction.contact_modulus)?;
        let w = positive("adhesion_energy", interaction.energy)?;
        let rho = positive("adhesion_range", interaction.range)?;
        let g = positive("slope_rms", roughness.slope_rms)?;
        let k = positive("curvature_rms", roughness.curvature_rms)?;
        let u = positive("full_contact_energy", roughness.full_contact_energy)?;
        let dx = positive("pixel_size", roughness.pixel_size)?;
        let g0 = 16.0 / 3.0 * g * g / k;
        Ok(Criteria {
            pastewka_robbins: g * e * rho / (2.0 * w) * (g * g / (k * rho)).powf(2.0 / 3.0),
            g0,
            range_over_g0: rho / g0,
            pastewka_robbins_valid: rho / g0 < PASTEWKA_ROBBINS_RANGE_LIMIT,
            persson_tosatti: u / w,
            tabor: (1.0 / k).cbrt() * (w / e).powf(2.0 / 3.0) / rho,
            mu_rho: (w * dx / (e * rho * rho)).sqrt(),
        })
    }

    /// Sentences for what lies outside a criterion's validity: Pastewka &
    /// Robbins' range condition, Müser's grid bound (`grid`: whether a
    /// computation runs on that grid).
    pub fn warnings(&self, grid: bool) -> Vec<String> {
        let mut w = Vec::new();
        if !self.pastewka_robbins_valid {
            w.push(format!(
                "Pastewka-Robbins stickiness criterion outside its validity: it assumes a \
                 short-ranged interaction, rho/g0 < {PASTEWKA_ROBBINS_RANGE_LIMIT} (g0 = 16 h'^2/(3 \
                 h'') = {:.4e} m), here rho/g0 = {:.4}",
                self.g0, self.range_over_g0
            ));
        }
        if grid && self.mu_rho > MU_RHO_LIMIT {
            w.push(format!(
                "mu_rho = {:.4} > {MU_RHO_LIMIT}: the pixels are too coarse to resolve the \
                 interaction's range (Wang, Zhou & Muser 2021); refine the map or widen the range",
                self.mu_rho
            ));
        }
        w
    }

    /// The criteria in words, one per line.
    pub fn text(&self) -> String {
        let verdict = |x: f64| {
            if x < 1.0 {
                "sticky: below 1"
            } else {
                "not sticky: sticky below 1"
            }
        };
        format!(
            "adhesion criteria:\n  Pastewka-Robbins h' E* rho/(2w) (h'^2/(h'' rho))^(2/3) = {:.5} \
             ({}; valid for rho/g0 < {PASTEWKA_ROBBINS_RANGE_LIMIT}: rho/g0 = {:.4}, {})\n  \
             Persson-Tosatti U_full/(A0 w) = {:.5} ({})\n  Tabor parameter at R = 1/h'': \
             R^(1/3) (w/E*)^(2/3)/rho = {:.5}\n  Muser's mu_rho = sqrt(w dx/(E* rho^2)) = {:.5} \
             (grid resolves the interaction below {MU_RHO_LIMIT})\n",
            self.pastewka_robbins,
            verdict(self.pastewka_robbins),
            self.range_over_g0,
            if self.pastewka_robbins_valid {
                "valid"
            } else {
                "NOT valid"
            },
            self.persson_tosatti,
            verdict(self.persson_tosatti),
            self.tabor,
            self.mu_rho
        )
    }
}
