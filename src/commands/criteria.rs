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

/// What `asperity bem` and `asperity persson` give after their numbers: the
/// outputs' numerical and model errors in words, the warnings, and, when
/// asked, the stickiness criteria and the capillary attraction (`C`: on the
/// map's exact gap fields for `bem`, [`super::wet_map::WetOutput`]; on
/// Persson's gap distribution for `persson`,
/// [`super::wet_persson::PerssonWetOutput`]). Its keys stand inline in the
/// output, in this order.
#[derive(Serialize, Debug, Clone)]
pub struct Assessment<C> {
    /// The numerical error of the outputs, in words.
    pub numerical_error: String,
    /// The model error of the outputs, in words.
    pub model_error: String,
    /// Results outside a model's validity.
    pub warnings: Vec<String>,
    /// With an adhesion energy and range: the stickiness criteria
    /// ([`crate::stickiness`]: Pastewka–Robbins with its validity,
    /// Persson–Tosatti, the Tabor parameter at `R = 1/h''`, Müser's
    /// `mu_rho`) and the scales they use.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub adhesion_criteria: Option<CriteriaOutput>,
    /// With a liquid: the flooded capillary attraction, per-summit menisci
    /// beside it, and the regime.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub capillary: Option<C>,
}

impl<C> Assessment<C> {
    /// The text's last lines: each warning, then the numerical and the
    /// model error.
    pub fn closing_lines(&self, t: &mut String) {
        use std::fmt::Write as _;
        for w in &self.warnings {
            let _ = writeln!(t, "warning: {w}");
        }
        let _ = writeln!(t, "numerical error: {}", self.numerical_error);
        let _ = writeln!(t, "model error: {}", self.model_error);
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
