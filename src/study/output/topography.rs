//! The summary's `topography` object and the charts of a measured map.

use super::aliases::Aliases;
use crate::error::Result;
use crate::study::measured::Headline;
use crate::study::plan::Plan;
use crate::study::plot::surface::{write_summit_heights, write_summit_map};
use crate::study::quantity::Headlines;
use crate::study::run::Results;
use crate::surface::{GwParameters, SummitStats};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// The measured map in a run's summary (SI units).
#[derive(Debug, Clone, Serialize)]
pub struct TopographySummary {
    /// The map file read.
    pub file: String,
    /// Rows and columns of the map.
    pub rows: usize,
    /// Columns.
    pub cols: usize,
    /// Pixel size (m) along x (a row).
    pub pixel_size_m: f64,
    /// Pixel size (m) along y (a column; equal to `pixel_size_m` for
    /// square pixels).
    pub pixel_size_y_m: f64,
    /// Whether periodic rules were used.
    pub periodic: bool,
    /// RMS height after the mean plane is removed (m).
    pub rms_height_m: f64,
    /// Profile moments (m^2, 1, 1/m^2) and Nayak's bandwidth.
    pub m0: f64,
    /// `m2`.
    pub m2: f64,
    /// `m4` (1/m^2).
    pub m4: f64,
    /// `alpha = m0 m4 / m2^2`.
    pub bandwidth_alpha: f64,
    /// The model the curve used: `"measured"` or `"moments"`.
    pub model: &'static str,
    /// The measured summits.
    pub summits: MeasuredJson,
    /// McCool's GW parameters from the moments.
    pub gw_from_moments: MomentsJson,
    /// The other model's headline numbers (`surface.compare = true`), else
    /// `null`.
    pub other: Option<HeadlineJson>,
}

/// The measured summits' statistics (as `asperity surface --json`).
#[derive(Debug, Clone, Serialize)]
pub struct MeasuredJson {
    /// Number of summits on the map.
    pub count: usize,
    /// Summits per candidate area (1/m^2).
    pub density_per_m2: f64,
    /// Mean curvature (1/m).
    pub mean_curvature_per_m: Option<f64>,
    /// `1 / mean curvature` (m).
    pub radius_m: Option<f64>,
    /// Summit-height standard deviation (m).
    pub height_std_m: Option<f64>,
    /// Mean summit height above the mean plane (m).
    pub mean_height_m: Option<f64>,
}

impl MeasuredJson {
    /// The statistics of a map's measured summits.
    pub fn of(s: &SummitStats) -> Self {
        MeasuredJson {
            count: s.count,
            density_per_m2: s.density_per_m2,
            mean_curvature_per_m: s.mean_curvature_per_m,
            radius_m: s.radius_m,
            height_std_m: s.height_std_m,
            mean_height_m: s.mean_height_m,
        }
    }
}

/// McCool's GW parameters.
#[derive(Debug, Clone, Serialize)]
pub struct MomentsJson {
    /// `eta` (1/m^2).
    pub density_per_m2: f64,
    /// `R` (m).
    pub radius_m: f64,
    /// `sigma_s` (m).
    pub sigma_m: Option<f64>,
}

impl MomentsJson {
    /// McCool's parameters from a map's spectral moments.
    pub fn of(gw: &GwParameters) -> Self {
        MomentsJson {
            density_per_m2: gw.density_per_m2,
            radius_m: gw.radius_m,
            sigma_m: gw.sigma_m,
        }
    }
}

/// Another model's headline numbers.
#[derive(Debug, Clone, Serialize)]
pub struct HeadlineJson {
    /// `"measured"` or `"moments"`.
    pub model: &'static str,
    /// `eta A_n`.
    pub summits: f64,
    /// Summit density (1/m^2).
    pub density_per_m2: f64,
    /// Summit radius (m).
    pub radius_m: f64,
    /// Summit-height standard deviation (m).
    pub sigma_m: f64,
    /// Start of its program (m).
    pub start_separation: f64,
    /// Closest separation (m).
    pub closest_separation: f64,
    /// The quantities' headline numbers (`max_load`, `max_area`,
    /// `max_count`, ...).
    #[serde(flatten)]
    pub headlines: Headlines,
    /// Pull-off force (N).
    pub pull_off_load: Option<f64>,
    /// Its separation (m).
    pub pull_off_separation: Option<f64>,
    /// Wall-clock time (s).
    pub seconds: f64,
    /// The headlines' previous keys without a unit (`max_load`,
    /// `max_area`), the same values, for one release: deprecated.
    #[serde(flatten)]
    pub deprecated: Aliases,
}

impl From<&Headline> for HeadlineJson {
    fn from(h: &Headline) -> Self {
        HeadlineJson {
            model: h.model,
            summits: h.summits,
            density_per_m2: h.density,
            radius_m: h.radius,
            sigma_m: h.sigma,
            start_separation: h.start_separation,
            closest_separation: h.closest_separation,
            headlines: h.headlines.clone(),
            pull_off_load: h.pull_off_load,
            pull_off_separation: h.pull_off_separation,
            seconds: h.seconds,
            deprecated: Aliases::of(
                h.headlines
                    .0
                    .iter()
                    .filter(|(q, _)| q.key != q.sweep)
                    .map(|(q, v)| (q.key.as_str(), serde_json::json!(v))),
            ),
        }
    }
}

/// The `topography` object of a run's summary (`None` without a map).
pub fn summary(plan: &Plan, results: &Results) -> Option<TopographySummary> {
    let t = plan.topography.as_ref()?;
    let c = &t.characterisation;
    let (s, gw) = (&c.stats, c.gw_from_moments());
    Some(TopographySummary {
        file: t.file.display().to_string(),
        rows: c.rows,
        cols: c.cols,
        pixel_size_m: c.pixel_size_m,
        pixel_size_y_m: c.pixel_size_y_m,
        periodic: c.periodic,
        rms_height_m: c.moments.rms_height(),
        m0: c.moments.m0,
        m2: c.moments.m2,
        m4: c.moments.m4,
        bandwidth_alpha: c.bandwidth_alpha(),
        model: t.spec.summits.name(),
        summits: MeasuredJson::of(s),
        gw_from_moments: MomentsJson::of(&gw),
        other: results
            .topography
            .as_ref()
            .and_then(|r| r.other.as_ref())
            .map(HeadlineJson::from),
    })
}

/// Writes `summit_heights.svg` (histogram against the Gaussian of the
/// moments) and `summit_map.svg` into `dir` when the plan has a map.
///
/// # Errors
/// As [`write_summit_heights`] and [`write_summit_map`].
pub fn write_charts(plan: &Plan, dir: &Path) -> Result<Vec<PathBuf>> {
    let Some(t) = &plan.topography else {
        return Ok(Vec::new());
    };
    let heights = dir.join("summit_heights.svg");
    write_summit_heights(&heights, &t.characterisation)?;
    let map = dir.join("summit_map.svg");
    write_summit_map(&map, &t.characterisation)?;
    Ok(vec![heights, map])
}
