//! `asperity surface`: characterise a measured height map (moments,
//! summits, GW parameters from the moments, plasticity index;
//! [`crate::surface::Topography`], `docs/surface.md`).

use super::{param, CommandResult};
use crate::error::positive;
use crate::surface::{npy, text, Characterisation, HeightMap, Topography};
use crate::Error;
use serde::Serialize;
use std::path::Path;

/// The input of [`characterise`] besides the map.
#[derive(Debug, Clone, Copy, Default)]
pub struct SurfaceInput {
    /// Pixel size (m) along x (a row), and along y unless `pixel_size_y`.
    pub pixel_size: f64,
    /// Pixel size (m) along y (a column) when it differs from x.
    pub pixel_size_y: Option<f64>,
    /// Treat the map as periodic: remove only the mean, wrap differences and
    /// summit neighbours around every edge.
    pub periodic: bool,
    /// Contact modulus E* (Pa), with `hardness` for the plasticity index.
    pub estar: Option<f64>,
    /// Hardness H (Pa), with `estar` for the plasticity index.
    pub hardness: Option<f64>,
}

/// The summits of `asperity surface --json` (the run summary's
/// measured-summit statistics).
pub use crate::study::output::MeasuredJson as SummitsJson;

/// GW parameters from the spectral moments (McCool), as in a run's
/// summary.
pub use crate::study::output::MomentsJson as GwJson;

/// What `asperity surface --json` prints.
#[derive(Serialize, Debug, Clone)]
pub struct SurfaceJson {
    /// Rows of the map.
    pub rows: usize,
    /// Columns of the map.
    pub cols: usize,
    /// Rms height (m).
    pub rms_height_m: f64,
    /// Spectral moment m0 (m^2).
    pub m0: f64,
    /// Spectral moment m2 (dimensionless).
    pub m2: f64,
    /// Spectral moment m4 (1/m^2).
    pub m4: f64,
    /// `sqrt(m2)`: a profile's rms slope.
    pub rms_slope: f64,
    /// `sqrt(2 m2)`: the surface's rms gradient.
    pub rms_gradient: f64,
    /// `sqrt(m4)` (1/m): a profile's rms curvature.
    pub rms_curvature_per_m: f64,
    /// Nayak's bandwidth parameter `m0 m4 / m2^2`.
    pub bandwidth_alpha: f64,
    /// The summits found.
    pub summits: SummitsJson,
    /// GW parameters from the moments.
    pub gw_from_moments: GwJson,
    /// Plasticity index with `--estar` and `--hardness`.
    pub plasticity_index: Option<f64>,
    /// Where the map came from (a map read from a file).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub source: Option<super::measured::SourceJson>,
    /// Warnings about the map: a `--pixel-size` that disagrees with the
    /// file's, units that are probably wrong
    /// ([`super::measured::unit_warnings`]).
    pub warnings: Vec<String>,
}

/// Reads the height map in `path` by its extension (`.npy`, or a text
/// matrix `.txt`/`.csv`/`.asc`) and multiplies its heights by `scale` (the
/// file's height unit in metres); every content error names the file.
///
/// # Errors
/// [`Error::Invalid`] naming the file (unreadable, unknown extension, bad
/// content), [`Error::OutOfMemory`] naming it beyond the memory available,
/// `{scale}` out of range.
pub fn read_map(path: &Path, scale: f64) -> CommandResult<HeightMap> {
    positive(&param("scale"), scale)?;
    let shown = path.display().to_string();
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .unwrap_or_default();
    crate::study::memory::check_map(path)?;
    let bytes =
        std::fs::read(path).map_err(|e| Error::invalid(&shown, format!("cannot read: {e}")))?;
    let map = match ext.as_str() {
        "npy" => npy::parse(&bytes),
        "txt" | "csv" | "asc" => match std::str::from_utf8(&bytes) {
            Ok(t) => text::parse(t),
            Err(_) => Err(Error::invalid("topography", "not UTF-8 text")),
        },
        _ => Err(Error::invalid(
            "topography",
            format!("unknown extension '{ext}': expected .npy, .txt, .csv or .asc"),
        )),
    };
    map.map_err(|e| e.renamed(&shown))?
        .scaled(scale)
        .map_err(|e| e.renamed(&param("scale")))
}

/// How the command line names a map read from `path` with heights times
/// `scale`: its path, and the scale when it is not 1 (a flat map may be a
/// tiny scale's doing).
pub fn map_name(path: &Path, scale: f64) -> String {
    if scale == 1.0 {
        path.display().to_string()
    } else {
        format!("{} (heights x --scale {scale:e})", path.display())
    }
}

fn plasticity(
    estar: Option<f64>,
    hardness: Option<f64>,
    c: &Characterisation,
) -> CommandResult<Option<f64>> {
    match (estar, hardness) {
        (None, None) => Ok(None),
        (Some(_), None) => Err(Error::invalid(
            param("hardness"),
            format!("needed with {}", param("estar")),
        )),
        (None, Some(_)) => Err(Error::invalid(
            param("estar"),
            format!("needed with {}", param("hardness")),
        )),
        (Some(e), Some(h)) => {
            positive(&param("estar"), e)?;
            positive(&param("hardness"), h)?;
            let psi = c.gw_from_moments().plasticity_index(e, h)?;
            if psi.is_some_and(|p| !p.is_finite()) {
                return Err(Error::invalid(
                    param("estar"),
                    format!(
                        "{e:e} Pa with {} = {h:e} Pa: the plasticity index (E*/H) \
                         sqrt(sigma/R) overflows",
                        param("hardness")
                    ),
                ));
            }
            Ok(psi)
        }
    }
}

/// Characterises `map` (heights in m; `asperity surface`).
///
/// # Errors
/// Naming `{pixel_size}`, `{estar}`, `{hardness}`, `{heights}` (the map:
/// too small, flat, ...), or `{scale}` when the heights underflow.
pub fn characterise(
    map: HeightMap,
    input: &SurfaceInput,
) -> CommandResult<(SurfaceJson, Characterisation)> {
    let dy = input.pixel_size_y.unwrap_or(input.pixel_size);
    let topo = Topography::with_pixels(map, input.pixel_size, dy).map_err(|e| match e.field() {
        Some("heights") => e.renamed(&param("scale")),
        Some("pixel_size_y") => e.renamed(&param("pixel_size_y")),
        _ => e.renamed(&param("pixel_size")),
    })?;
    let c = topo
        .characterise(input.periodic)
        .map_err(|e| e.renamed(&param("heights")))?;
    let psi = plasticity(input.estar, input.hardness, &c)?;
    let (s, gw) = (&c.stats, c.gw_from_moments());
    let out = SurfaceJson {
        rows: c.rows,
        cols: c.cols,
        rms_height_m: c.moments.rms_height(),
        m0: c.moments.m0,
        m2: c.moments.m2,
        m4: c.moments.m4,
        rms_slope: c.moments.rms_slope(),
        rms_gradient: c.moments.rms_gradient(),
        rms_curvature_per_m: c.moments.rms_curvature(),
        bandwidth_alpha: c.bandwidth_alpha(),
        summits: SummitsJson::of(s),
        gw_from_moments: GwJson::of(&gw),
        plasticity_index: psi,
        source: None,
        warnings: Vec::new(),
    };
    Ok((out, c))
}

/// Writes `surface.json` (the output `out` as `--json` prints it),
/// `summit_heights.svg` and `summit_map.svg` into `dir`.
///
/// # Errors
/// [`Error::Io`] naming the file that could not be written.
pub fn write_outputs(dir: &Path, out: &SurfaceJson, c: &Characterisation) -> CommandResult<()> {
    super::create_dir(dir)?;
    super::write_file(
        &dir.join("surface.json"),
        format!("{}\n", super::json_line(out)?),
    )?;
    if c.summits.len() < 2 {
        eprintln!("note: fewer than 2 summits, no charts written");
        return Ok(());
    }
    crate::study::plot::surface::write_summit_heights(&dir.join("summit_heights.svg"), c)?;
    crate::study::plot::surface::write_summit_map(&dir.join("summit_map.svg"), c)
}
