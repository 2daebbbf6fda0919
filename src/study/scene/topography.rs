//! `[surface] topography = "map.npy"`: scenes from a measured height map.
//!
//! A scene with a topography gives the map (and its `pixel_size`) instead of
//! the summit statistics; [`resolve`] reads the map (path relative to the
//! scene file's directory), characterises it
//! ([`Topography::characterise`]) and turns the scene into an ordinary one
//! whose `[surface]` describes the chosen model of the map
//! ([`SummitSource`]):
//!
//! - `summits = "measured"` (default): `distribution = "empirical"` with the
//!   measured summit heights, `density` = measured summits per candidate
//!   area, `radius` = 1 / mean measured curvature (the radius the law is
//!   built for); the run then sums the law exactly over the measured summits,
//!   each with its own height and radius
//!   ([`crate::montecarlo::MeasuredSummits`]);
//! - `summits = "moments"`: Gaussian heights with McCool's GW parameters from
//!   the measured moments ([`crate::surface::GwParameters`]).
//!
//! `nominal_area` defaults to the map's area (`rows cols dx dy`).
//!
//! The map is any format of [`crate::topography`]: an instrument file gives
//! its heights in m and its pixel sizes (`pixel_size` may then be left out;
//! given, it must agree to [`crate::topography::PIXEL_AGREEMENT`] or it wins
//! with a warning); a `.npy` or text map takes `height_unit` and needs
//! `pixel_size`. Missing pixels are refused unless `fill_missing`.

use super::schema::{Scene, SurfaceSpec};
use crate::error::{positive, Error, Result};
use crate::named::Named;
use crate::study::Warning;
use crate::surface::{Characterisation, HeightMap, Topography};
use crate::topography::units::HeightUnit;
use crate::topography::{self, Channel, Format};
use std::path::{Path, PathBuf};

/// The scene field every error about the map names.
const FIELD: &str = "surface.topography";

pub use super::summit_source::SummitSource;

/// The topography keys of a `[surface]` table, with their defaults.
#[derive(Debug, Clone, PartialEq)]
pub struct TopographySpec {
    /// The map's path as written in the scene.
    pub path: String,
    /// Pixel size (m), when the scene gives one.
    pub pixel_size: Option<f64>,
    /// Unit of a `.npy` or text map's heights (default m).
    pub height_unit: Option<HeightUnit>,
    /// Factor on the heights after their unit (default 1).
    pub height_scale: f64,
    /// Fill missing pixels instead of refusing them (default false).
    pub fill_missing: bool,
    /// Periodic rules (default false).
    pub periodic: bool,
    /// The model the study uses (default measured).
    pub summits: SummitSource,
    /// Whether the other model's headline numbers are reported (default
    /// false).
    pub compare: bool,
}

impl TopographySpec {
    /// The topography keys of `s`, `None` without `topography`.
    ///
    /// # Errors
    /// Missing or forbidden topography keys, naming them.
    pub fn of(s: &SurfaceSpec) -> Result<Option<TopographySpec>> {
        let Some(path) = &s.topography else {
            return Ok(None);
        };
        if let Some(p) = s.pixel_size {
            positive("surface.pixel_size", p)?;
        }
        let height_scale = s.height_scale.unwrap_or(1.0);
        positive("surface.height_scale", height_scale)?;
        Ok(Some(TopographySpec {
            path: path.clone(),
            pixel_size: s.pixel_size,
            height_unit: s.height_unit,
            height_scale,
            fill_missing: s.fill_missing.unwrap_or(false),
            periodic: s.periodic.unwrap_or(false),
            summits: s.summits.unwrap_or(SummitSource::Measured),
            compare: s.compare.unwrap_or(false),
        }))
    }
}

/// Checks the summit statistics of `[surface]`: given and positive without
/// a topography; with one, `density`, `radius`, `sigma` and the
/// distribution parameters not given, `nominal_area` positive if given.
/// With `[sphere]` (`sphere`), `nominal_area` must not be given and a
/// topography is refused.
///
/// # Errors
/// [`Error::Invalid`] naming the missing or forbidden key,
/// [`Error::OutOfRange`] naming a bad value.
pub(super) fn validate_surface(s: &SurfaceSpec, sphere: bool) -> Result<()> {
    if sphere {
        if s.topography.is_some() {
            return Err(Error::invalid(
                "surface.topography",
                "not with [sphere]: a rough sphere stands on a statistical surface (density, \
                 radius, sigma); run the map's moments as one (summits = \"moments\" gives them)",
            ));
        }
        if !s.nominal_area.is_nan() {
            return Err(Error::invalid(
                "surface.nominal_area",
                "not with [sphere]: the bump's apparent area is the solution's (Greenwood & \
                 Tripp); remove it",
            ));
        }
    }
    let stats = [
        ("surface.density", s.density),
        ("surface.radius", s.radius),
        ("surface.sigma", s.sigma),
    ];
    if s.topography.is_none() {
        for (name, given) in [
            ("surface.pixel_size", s.pixel_size.is_some()),
            ("surface.height_unit", s.height_unit.is_some()),
            ("surface.height_scale", s.height_scale.is_some()),
            ("surface.fill_missing", s.fill_missing.is_some()),
            ("surface.periodic", s.periodic.is_some()),
            ("surface.summits", s.summits.is_some()),
            ("surface.compare", s.compare.is_some()),
        ] {
            if given {
                return Err(Error::invalid(name, "only with surface.topography"));
            }
        }
        let area = (!sphere).then_some(("surface.nominal_area", s.nominal_area));
        for (name, v) in stats.into_iter().chain(area) {
            if v.is_nan() {
                return Err(Error::invalid(
                    name,
                    "missing or NaN (required without surface.topography)",
                ));
            }
            positive(name, v)?;
        }
        return Ok(());
    }
    for (name, v) in stats {
        if !v.is_nan() {
            return Err(Error::invalid(
                name,
                "comes from surface.topography (the map's summits); remove it",
            ));
        }
    }
    if s.distribution != crate::heights::DistributionKind::Gaussian {
        return Err(Error::invalid(
            "surface.distribution",
            "comes from surface.topography (summits = \"measured\" or \"moments\"); remove it",
        ));
    }
    for (name, given) in [
        ("surface.weibull_shape", s.weibull_shape.is_some()),
        ("surface.truncation", s.truncation.is_some()),
        ("surface.heights", s.heights.is_some()),
    ] {
        if given {
            return Err(Error::invalid(name, "not with surface.topography"));
        }
    }
    if !s.nominal_area.is_nan() {
        positive("surface.nominal_area", s.nominal_area)?;
    }
    TopographySpec::of(s).map(|_| ())
}

/// Reads a height map by its extension (any format of
/// [`crate::topography`]), its default channel; refuses missing pixels.
///
/// # Errors
/// [`Error::Invalid`] naming `surface.topography`, with the file and the
/// reason (unreadable, unknown extension, bad content with the format,
/// missing pixels).
pub fn read_map(path: &Path) -> Result<HeightMap> {
    let spec = TopographySpec {
        path: path.display().to_string(),
        pixel_size: None,
        height_unit: None,
        height_scale: 1.0,
        periodic: false,
        fill_missing: false,
        summits: SummitSource::Measured,
        compare: false,
    };
    read_measured(path, &spec).map(|m| m.map)
}

/// A map read for a scene.
#[derive(Debug, Clone)]
pub struct SceneMap {
    /// The heights (m), complete.
    pub map: HeightMap,
    /// The file's format.
    pub format: Format,
    /// The pixel sizes the file gives (m), if any.
    pub file_pixels: Option<(f64, f64)>,
    /// Whether the file says the map is periodic.
    pub periodic: bool,
}

/// Reads the map at `path` as `spec` says (unit, scale, missing pixels).
///
/// # Errors
/// [`Error::Invalid`] naming `surface.topography` (with the file), or
/// `surface.height_unit` given for an instrument file.
fn read_measured(path: &Path, spec: &TopographySpec) -> Result<SceneMap> {
    let shown = path.display().to_string();
    let format = topography::format_of(path).map_err(|e| Error::invalid(FIELD, e.to_string()))?;
    if spec.height_unit.is_some() && !matches!(format, Format::Npy | Format::Text) {
        return Err(Error::invalid(
            "surface.height_unit",
            format!(
                "only for .npy and text maps: {shown} is a {} file, which gives its own unit",
                format.describe()
            ),
        ));
    }
    let mut m = topography::read(path, &Channel::Default).map_err(|e| match e {
        Error::OutOfMemory { .. } => e.renamed(&format!("{FIELD} = {shown}")),
        _ if e.field() == Some(shown.as_str()) => Error::invalid(FIELD, e.to_string()),
        _ => Error::invalid(FIELD, format!("{shown}: {e}")),
    })?;
    let missing = m.missing();
    if missing > 0 {
        if !spec.fill_missing {
            return Err(Error::invalid(
                FIELD,
                format!(
                    "{shown}: {missing} of {} pixels are missing (NaN or masked in the file): \
                     refused, or filled from their neighbours with surface.fill_missing = true",
                    m.heights.len()
                ),
            ));
        }
        m.fill_missing()
            .map_err(|e| Error::invalid(FIELD, format!("{shown}: {e}")))?;
    }
    let (file_pixels, periodic) = (m.pixel_size, m.periodic);
    let to_m = spec.height_unit.map_or(1.0, HeightUnit::metres);
    let map = m
        .into_map()
        .map_err(|e| Error::invalid(FIELD, format!("{shown}: {e}")))?
        .scaled(to_m * spec.height_scale)
        .map_err(|e| e.renamed("surface.height_scale"))?;
    Ok(SceneMap {
        map,
        format,
        file_pixels,
        periodic,
    })
}

/// A scene's topography, read and characterised.
#[derive(Debug, Clone)]
pub struct Resolved {
    /// The scene with `[surface]` describing the chosen model of the map
    /// (no topography keys left).
    pub scene: Scene,
    /// The topography keys.
    pub spec: TopographySpec,
    /// The map file read.
    pub file: PathBuf,
    /// What the map gave.
    pub characterisation: Characterisation,
    /// The map's heights (m), as read.
    pub map: crate::surface::HeightMap,
    /// Warnings about the map: a `pixel_size` that disagrees with the
    /// file's, units that are probably wrong.
    pub warnings: Vec<Warning>,
}

/// Reads and characterises the scene's map (its path relative to
/// `base_dir`, the scene file's directory) and returns the scene with the
/// chosen model's summit statistics; `None` for a scene without topography.
///
/// # Errors
/// As [`read_map`]; [`Error::Invalid`] naming `surface.topography` when the
/// map is flat or has fewer than 2 summits, or (for `moments`) when its
/// bandwidth gives no summit-height spread; naming `surface.height_scale`
/// or `surface.pixel_size` for values the map cannot take.
pub fn resolve(scene: &Scene, base_dir: &Path) -> Result<Option<Resolved>> {
    let Some(spec) = TopographySpec::of(&scene.surface)? else {
        return Ok(None);
    };
    let file = base_dir.join(&spec.path);
    let read = read_measured(&file, &spec)?;
    let ((dx, dy), mismatch) = topography::pixel_sizes(
        read.file_pixels,
        spec.pixel_size,
        "surface.pixel_size",
        read.format,
    )?;
    let mut warnings: Vec<Warning> = mismatch.into_iter().map(Warning::MapPixelSize).collect();
    let periodic = spec.periodic || read.periodic;
    let topo = Topography::with_pixels(read.map, dx, dy).map_err(|e| match e.field() {
        Some("heights") => e.renamed("surface.height_scale"),
        _ => e.renamed("surface.pixel_size"),
    })?;
    let c = topo
        .characterise(periodic)
        .map_err(|e| Error::invalid(FIELD, format!("{}: {e}", file.display())))?;
    warnings.extend(
        topography::unit_warnings(
            c.moments.rms_height(),
            (dx, dy),
            &format!(
                "surface.height_unit = \"{}\"",
                HeightUnit::names().join("\" | \"")
            ),
            "surface.height_scale",
        )
        .into_iter()
        .map(Warning::MapUnits),
    );
    if c.stats.count < 2 {
        return Err(Error::invalid(
            FIELD,
            format!(
                "{}: {} summits; at least 2 are needed",
                file.display(),
                c.stats.count
            ),
        ));
    }
    let mut s = scene.surface.clone();
    if s.nominal_area.is_nan() {
        s.nominal_area = c.nominal_area_m2();
    }
    match spec.summits {
        SummitSource::Measured => {
            let heights: Vec<f64> = c.summits.iter().map(|x| x.height_m).collect();
            s.density = c.stats.density_per_m2;
            // count >= 2, so the statistics exist.
            s.radius = c.stats.radius_m.unwrap_or(f64::NAN);
            s.sigma = c.stats.height_std_m.unwrap_or(f64::NAN);
            s.distribution = crate::heights::DistributionKind::Empirical;
            s.heights = Some(heights);
        }
        SummitSource::Moments => {
            let gw = c.gw_from_moments();
            s.density = gw.density_per_m2;
            s.radius = gw.radius_m;
            s.sigma = gw.sigma_m.ok_or_else(|| {
                Error::invalid(
                    FIELD,
                    format!(
                        "bandwidth alpha = {:.4} <= 0.8968: the moments give no summit-height \
                         spread; use summits = \"measured\"",
                        c.bandwidth_alpha()
                    ),
                )
            })?;
        }
    }
    s.topography = None;
    s.pixel_size = None;
    s.height_unit = None;
    s.height_scale = None;
    s.fill_missing = None;
    s.periodic = None;
    s.summits = None;
    s.compare = None;
    let mut resolved = scene.clone();
    resolved.surface = s;
    resolved.validate()?;
    Ok(Some(Resolved {
        scene: resolved,
        spec,
        file,
        characterisation: c,
        map: topo.into_map(),
        warnings,
    }))
}
