//! A measured map read for a command (`asperity surface`, `asperity bem`,
//! Python's `read_topography`): any format of [`crate::topography`], its
//! channel, its missing pixels refused or filled, `.npy`/text heights
//! converted from `--height-unit`, and its pixel sizes from the file or the
//! command (`docs/surface.md`, "Measured maps").

use super::{param, CommandResult};
use crate::error::{positive, Error};
use crate::named::Named;
use crate::surface::HeightMap;
use crate::topography::{self, Channel, Format};
use serde::Serialize;
use std::path::Path;

pub use crate::topography::units::HeightUnit;

/// The unit called `s` (`nm`, `um` or `m`; `µm` too).
///
/// # Errors
/// [`Error::Invalid`] naming `{height_unit}` for anything else, with the
/// names allowed.
pub fn height_unit(s: &str) -> CommandResult<HeightUnit> {
    let s = s.trim();
    let s = if s == "µm" || s == "μm" { "um" } else { s };
    HeightUnit::parse(s).map_err(|e| e.renamed(&param("height_unit")))
}

/// How to read a map.
#[derive(Debug, Clone, PartialEq)]
pub struct ReadOptions {
    /// The channel (default: the height channel).
    pub channel: Channel,
    /// Fill missing pixels from their neighbours instead of refusing them.
    pub fill_missing: bool,
    /// The unit of a `.npy` or text map's heights (default m); refused for
    /// the instrument formats, which give their own.
    pub height_unit: Option<HeightUnit>,
    /// A factor on the heights after conversion to m (default 1).
    pub scale: f64,
}

impl Default for ReadOptions {
    fn default() -> Self {
        ReadOptions {
            channel: Channel::Default,
            fill_missing: false,
            height_unit: None,
            scale: 1.0,
        }
    }
}

/// Where a map came from: `"source"` of `asperity surface --json`.
#[derive(Serialize, Debug, Clone, PartialEq)]
pub struct SourceJson {
    /// The format's short name (`x3p`, `sdf`, `gwy`, `sur`, `di`, `ibw`,
    /// `opd`, `opdx`, `nc`, `frt`, `plux`, `npy`, `text`).
    pub format: &'static str,
    /// The channel read.
    pub channel: String,
    /// The unit the instrument wrote the heights in (empty when the file
    /// gives none).
    pub unit: String,
    /// The pixel sizes used, `[dx, dy]` (m) along x (a row) and y.
    pub pixel_size_m: [f64; 2],
    /// Rows of the map (along y).
    pub rows: usize,
    /// Columns (along x).
    pub cols: usize,
    /// Missing pixels in the file (refused, or filled with
    /// `--fill-missing`).
    pub missing: usize,
}

/// A map read for a command.
#[derive(Debug, Clone, PartialEq)]
pub struct MeasuredMap {
    /// The heights (m), complete.
    pub map: HeightMap,
    /// The format.
    pub format: Format,
    /// The channel read.
    pub channel: String,
    /// The instrument's height unit.
    pub unit: String,
    /// The pixel sizes the file gives (m), if any.
    pub file_pixels: Option<(f64, f64)>,
    /// Whether the file says the map is periodic.
    pub periodic: bool,
    /// Missing pixels in the file (filled when asked).
    pub missing: usize,
}

/// Reads the map in `path` (any format by its extension) with `o`.
///
/// # Errors
/// [`Error::Invalid`] naming the file (unreadable, unknown extension, bad
/// content with the format and the reason, missing pixels without
/// `{fill_missing}`), `{channel}` for a channel the file lacks,
/// `{height_unit}` for an instrument file, `{scale}` out of range,
/// [`Error::OutOfMemory`] naming the file.
pub fn read_measured(path: &Path, o: &ReadOptions) -> CommandResult<MeasuredMap> {
    positive(&param("scale"), o.scale)?;
    let shown = path.display().to_string();
    let format = topography::format_of(path)?;
    refuse_unit(o.height_unit, format, &shown)?;
    let to_m = o.height_unit.map_or(1.0, HeightUnit::metres) * o.scale;
    let unit = o.height_unit.map_or("m", Named::name).to_string();
    if format == Format::Npy {
        // The one buffer: the mapped file, validated once, copied only
        // when scaled.
        one_channel(&o.channel, format)?;
        let map = topography::read_npy(path)?;
        return Ok(MeasuredMap {
            map: map.scaled(to_m).map_err(|e| e.renamed(&param("scale")))?,
            format,
            channel: "heights".into(),
            unit,
            file_pixels: None,
            periodic: false,
            missing: 0,
        });
    }
    let mut m = topography::read(path, &o.channel)?;
    let missing = m.missing();
    if missing > 0 && o.fill_missing {
        m.fill_missing().map_err(|e| e.renamed(&shown))?;
    }
    let (format, channel, file_pixels, periodic) =
        (m.format, m.channel.clone(), m.pixel_size, m.periodic);
    let unit = match format {
        Format::Text => unit,
        _ => m.unit.clone(),
    };
    let map = m.into_map().map_err(|e| e.renamed(&shown))?;
    let map = map.scaled(to_m).map_err(|e| e.renamed(&param("scale")))?;
    Ok(MeasuredMap {
        map,
        format,
        channel,
        unit,
        file_pixels,
        periodic,
        missing,
    })
}

pub use crate::topography::PIXEL_AGREEMENT;

/// The metadata of a map read as it is (Python's `read_topography`).
#[derive(Serialize, Debug, Clone, PartialEq)]
pub struct TopographyMeta {
    /// The format's short name ([`SourceJson::format`]).
    pub format: &'static str,
    /// The channel read.
    pub channel: String,
    /// The unit the instrument wrote the heights in (`m` for `.npy` and
    /// text maps unless `height_unit`; empty when the file gives none).
    pub unit: String,
    /// Pixel sizes `[dx, dy]` (m) along x (a row) and y, when the file
    /// gives them.
    pub pixel_size_m: Option<[f64; 2]>,
    /// Rows (along y).
    pub rows: usize,
    /// Columns (along x).
    pub cols: usize,
    /// Missing pixels in the file (NaN in the heights unless filled).
    pub missing: usize,
    /// Whether the file says the map is periodic.
    pub periodic: bool,
}

/// The map in `path` as the file has it: heights (m, row-major, NaN where
/// a pixel is missing unless `fill_missing`) and their metadata; `.npy`
/// and text heights in `height_unit` (default m).
///
/// # Errors
/// As [`read_measured`], except that missing pixels are not refused.
pub fn read_topography(
    path: &Path,
    channel: &Channel,
    height_unit: Option<HeightUnit>,
    fill_missing: bool,
) -> CommandResult<(Vec<f64>, TopographyMeta)> {
    let shown = path.display().to_string();
    let format = topography::format_of(path)?;
    refuse_unit(height_unit, format, &shown)?;
    let mut m = topography::read(path, channel)?;
    let missing = m.missing();
    if missing > 0 && fill_missing {
        m.fill_missing().map_err(|e| e.renamed(&shown))?;
    }
    let unit = match (height_unit, format) {
        (Some(u), _) => Named::name(u).to_string(),
        _ => m.unit.clone(),
    };
    if let Some(u) = height_unit {
        let f = u.metres();
        m.heights.iter_mut().for_each(|z| *z *= f);
    }
    let meta = TopographyMeta {
        format: m.format.name(),
        channel: m.channel.clone(),
        unit,
        pixel_size_m: m.pixel_size.map(|(dx, dy)| [dx, dy]),
        rows: m.rows,
        cols: m.cols,
        missing,
        periodic: m.periodic,
    };
    Ok((m.heights, meta))
}

/// A one-channel file (`.npy`) takes only the default channel or 0.
fn one_channel(channel: &Channel, format: Format) -> CommandResult<()> {
    if matches!(channel, Channel::Default | Channel::Index(0)) {
        return Ok(());
    }
    Err(Error::invalid(
        param("channel"),
        format!("a {} file has one channel", format.describe()),
    ))
}

/// `{height_unit}` is only for `.npy` and text maps.
fn refuse_unit(unit: Option<HeightUnit>, format: Format, shown: &str) -> CommandResult<()> {
    if unit.is_some() && !matches!(format, Format::Npy | Format::Text) {
        return Err(Error::invalid(
            param("height_unit"),
            format!(
                "only for .npy and text maps: {shown} is a {} file, which gives its own unit",
                format.describe()
            ),
        ));
    }
    Ok(())
}

impl MeasuredMap {
    /// The pixel sizes `(dx, dy)` (m) to use and the warning on the way
    /// ([`topography::pixel_sizes`] with `{pixel_size}`): the file's, or
    /// `given` (square) when the file has none; given anyway, it must agree
    /// with the file's to [`PIXEL_AGREEMENT`] relative, else it wins with a
    /// warning naming both ([`topography::PixelSizeMismatch`]).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `{pixel_size}` when neither gives one;
    /// out of range when given non-positive.
    pub fn pixels(
        &self,
        given: Option<f64>,
    ) -> CommandResult<((f64, f64), Option<topography::PixelSizeMismatch>)> {
        topography::pixel_sizes(self.file_pixels, given, &param("pixel_size"), self.format)
    }

    /// The `"source"` record with the pixel sizes used.
    pub fn source(&self, (dx, dy): (f64, f64)) -> SourceJson {
        SourceJson {
            format: self.format.name(),
            channel: self.channel.clone(),
            unit: self.unit.clone(),
            pixel_size_m: [dx, dy],
            rows: self.map.rows(),
            cols: self.map.cols(),
            missing: self.missing,
        }
    }
}

/// The RMS height (m) of `map` after the least-squares mean plane in
/// physical coordinates (pixels `(dx, dy)` m; only the mean when
/// `periodic`), as `rms_height_m` of `asperity surface`.
pub fn plane_rms(map: &HeightMap, pixels: (f64, f64), periodic: bool) -> f64 {
    let (rows, cols) = (map.rows(), map.cols());
    let plane = crate::surface::Plane::fit_xy(map.heights(), rows, cols, pixels, periodic);
    let r = plane.residual(map.heights(), cols);
    (r.iter().map(|v| v * v).sum::<f64>() / r.len() as f64).sqrt()
}

/// Warnings that a unit is probably wrong ([`topography::unit_warnings`],
/// pointing at `{height_unit}` and `{scale}`).
pub fn unit_warnings(rms_height: f64, pixels: (f64, f64)) -> Vec<topography::UnitWarning> {
    topography::unit_warnings(rms_height, pixels, &param("height_unit"), &param("scale"))
}

/// Writes `map` (m) with pixels `(dx, dy)` (m) to `path` by its extension:
/// `.x3p` (float64 heights, the pixel sizes; reads back bit for bit) or
/// `.npy` (float64 heights only).
///
/// # Errors
/// [`Error::Invalid`] naming `{export}` for another extension,
/// [`Error::Io`] when the file (or its missing directory) cannot be
/// written.
pub fn export(path: &Path, map: &HeightMap, (dx, dy): (f64, f64)) -> CommandResult<()> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .unwrap_or_default();
    let bytes = match ext.as_str() {
        "x3p" => topography::to_x3p(map.heights(), map.rows(), map.cols(), dx, dy, "asperity")?,
        "npy" => crate::surface::npy::to_bytes(map),
        _ => {
            return Err(Error::invalid(
                param("export"),
                format!("{}: expected a .x3p or .npy file", path.display()),
            ))
        }
    };
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        super::create_dir(dir)?;
    }
    super::write_file(path, bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pixel_sizes_from_the_file_or_the_command() {
        let map = HeightMap::new(3, 3, vec![0.0, 1.0, 0.0, 1.0, 2.0, 1.0, 0.0, 1.0, 0.0]).unwrap();
        let mut m = MeasuredMap {
            map,
            format: Format::X3p,
            channel: "Default".into(),
            unit: "m".into(),
            file_pixels: Some((1e-7, 2e-7)),
            periodic: false,
            missing: 0,
        };
        assert_eq!(m.pixels(None).unwrap(), ((1e-7, 2e-7), None));
        let (p, w) = m.pixels(Some(1e-7)).unwrap();
        assert_eq!(p, (1e-7, 1e-7));
        let w = w.unwrap();
        assert_eq!((w.given, w.file), (1e-7, (1e-7, 2e-7)));
        assert!(w.to_string().contains("disagrees"), "{w:?}");
        m.file_pixels = Some((1e-7, 1e-7));
        assert_eq!(m.pixels(Some(1e-7 * (1.0 + 1e-10))).unwrap().1, None);
        m.file_pixels = None;
        let e = m.pixels(None).unwrap_err();
        assert_eq!(e.field(), Some("{pixel_size}"));
        let first = |h, p| unit_warnings(h, p)[0].to_string();
        assert!(first(2e-5, (1e-7, 1e-7)).contains("um"));
        assert!(first(1e-8, (5e-3, 5e-3)).contains("above 1 mm"));
        assert!(first(1e-8, (1e-11, 1e-7)).contains("below 0.1 nm"));
        assert!(unit_warnings(1e-8, (1e-7, 1e-7)).is_empty());
    }
}
