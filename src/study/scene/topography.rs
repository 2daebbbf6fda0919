//! `[surface] topography = "map.npy"`: scenes from a measured height map.
//!
//! A scene with a topography gives the map and its `pixel_size` instead of
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
//! `nominal_area` defaults to the map's area (`rows cols pixel_size^2`).

use super::schema::{Scene, SurfaceSpec};
use crate::error::{positive, Error, Result};
use crate::surface::{npy, text, Characterisation, HeightMap, Topography};
use std::path::{Path, PathBuf};

/// The scene field every error about the map names.
const FIELD: &str = "surface.topography";

pub use super::summit_source::SummitSource;

/// The topography keys of a `[surface]` table, with their defaults.
#[derive(Debug, Clone, PartialEq)]
pub struct TopographySpec {
    /// The map's path as written in the scene.
    pub path: String,
    /// Pixel size (m).
    pub pixel_size: f64,
    /// Factor from the map's unit to metres (default 1).
    pub height_scale: f64,
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
        let pixel_size = s.pixel_size.ok_or_else(|| {
            Error::invalid("surface.pixel_size", "required with surface.topography")
        })?;
        positive("surface.pixel_size", pixel_size)?;
        let height_scale = s.height_scale.unwrap_or(1.0);
        positive("surface.height_scale", height_scale)?;
        Ok(Some(TopographySpec {
            path: path.clone(),
            pixel_size,
            height_scale,
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
            ("surface.height_scale", s.height_scale.is_some()),
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

/// Reads a height map by its extension: `.npy`, or a text matrix (`.txt`,
/// `.csv`, `.asc`).
///
/// # Errors
/// [`Error::Invalid`] naming `surface.topography`, with the file and the
/// reason (unreadable, unknown extension, bad content).
pub fn read_map(path: &Path) -> Result<HeightMap> {
    let shown = path.display();
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .unwrap_or_default();
    crate::study::memory::check_map(path).map_err(|e| e.renamed(&format!("{FIELD} = {shown}")))?;
    let bytes = std::fs::read(path)
        .map_err(|e| Error::invalid(FIELD, format!("{shown}: cannot read: {e}")))?;
    let map = match ext.as_str() {
        "npy" => npy::parse(&bytes),
        "txt" | "csv" | "asc" => match std::str::from_utf8(&bytes) {
            Ok(t) => text::parse(t),
            Err(_) => Err(Error::invalid(FIELD, "not UTF-8 text")),
        },
        _ => Err(Error::invalid(
            FIELD,
            format!("unknown extension '{ext}': expected .npy, .txt, .csv or .asc"),
        )),
    };
    map.map_err(|e| Error::invalid(FIELD, format!("{shown}: {e}")))
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
    let map = read_map(&file)?
        .scaled(spec.height_scale)
        .map_err(|e| e.renamed("surface.height_scale"))?;
    let topo = Topography::new(map, spec.pixel_size).map_err(|e| match e.field() {
        Some("heights") => e.renamed("surface.height_scale"),
        _ => e.renamed("surface.pixel_size"),
    })?;
    let c = topo
        .characterise(spec.periodic)
        .map_err(|e| Error::invalid(FIELD, format!("{}: {e}", file.display())))?;
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
    s.height_scale = None;
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
    }))
}
