//! The stickiness criteria as the commands print them
//! ([`crate::stickiness`]): `asperity bem` on a map with an adhesion,
//! `asperity persson` on a spectrum with an adhesion energy and range.

use super::{param, CommandResult};
use crate::spectrum::Spectrum;
use crate::stickiness::{AdhesiveInteraction, Criteria, Roughness};
use crate::Error;
use serde::Serialize;

/// The stickiness criteria of a map and the scales they use.
#[derive(Serialize, Debug, Clone)]
pub struct CriteriaOutput {
    /// The criteria.
    #[serde(flatten)]
    pub criteria: Criteria,
    /// The map's scales: RMS gradient, RMS curvature (1/m), full-contact
    /// energy (J/m^2), pixel size (m).
    pub roughness: RoughnessOutput,
}

/// The scales of [`CriteriaOutput`], with their units in the keys.
#[derive(Serialize, Debug, Clone, Copy)]
pub struct RoughnessOutput {
    /// RMS gradient `h'`.
    pub slope_rms: f64,
    /// RMS curvature `h''` (half the Laplacian, 1/m).
    pub curvature_rms_per_m: f64,
    /// Full-contact elastic energy per nominal area (J/m^2).
    #[serde(rename = "full_contact_energy_J_per_m2")]
    pub full_contact_energy: f64,
    /// Pixel size `dx` (m).
    pub pixel_size_m: f64,
}

impl From<Roughness> for RoughnessOutput {
    fn from(r: Roughness) -> Self {
        RoughnessOutput {
            slope_rms: r.slope_rms,
            curvature_rms_per_m: r.curvature_rms,
            full_contact_energy: r.full_contact_energy,
            pixel_size_m: r.pixel_size,
        }
    }
}

/// The stickiness criteria of `spectrum` (contact modulus `estar`, Pa)
/// with the adhesion `(adhesion_energy, adhesion_range)` (none without
/// both), their warnings appended to `warnings`.
///
/// # Errors
/// Naming `{adhesion_range}` (out of range) or `{adhesion_energy}` given
/// without it.
pub fn of_spectrum(
    spectrum: &Spectrum,
    estar: f64,
    adhesion: (Option<f64>, Option<f64>),
    warnings: &mut Vec<String>,
) -> CommandResult<Option<CriteriaOutput>> {
    let (w, rho) = match adhesion {
        (Some(w), Some(rho)) => (w, rho),
        (None, Some(_)) => {
            return Err(Error::invalid(
                param("adhesion_range"),
                format!("needs {}", param("adhesion_energy")),
            ))
        }
        _ => return Ok(None),
    };
    let r = Roughness::of_spectrum(spectrum, estar)?;
    let interaction = AdhesiveInteraction {
        contact_modulus: estar,
        energy: w,
        range: rho,
    };
    let c = Criteria::new(&r, &interaction).map_err(|e| match e.field() {
        Some(f @ ("adhesion_energy" | "adhesion_range")) => {
            let f = f.to_string();
            e.renamed(&param(&f))
        }
        _ => e,
    })?;
    warnings.extend(c.warnings(false));
    Ok(Some(CriteriaOutput {
        criteria: c,
        roughness: r.into(),
    }))
}
