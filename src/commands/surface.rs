//! `asperity surface`: characterise a measured height map (moments,
//! summits, GW parameters from the moments, plasticity index;
//! [`crate::surface::Topography`], `docs/surface.md`).

use super::{CommandError, CommandResult};
use crate::error::positive;
use crate::surface::{npy, text, Characterisation, HeightMap, Topography};
use crate::Error;
use serde::Serialize;
use std::path::{Path, PathBuf};

/// Arguments of `asperity surface`.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "cli", derive(clap::Args))]
pub struct SurfaceArgs {
    /// The height map: NumPy `.npy` (2-D float64/float32, C order) or a text
    /// matrix (`.txt`, `.csv`, `.asc`; whitespace or comma separated).
    pub file: PathBuf,
    /// Pixel size (m), the same along x and y.
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub pixel_size: f64,
    /// Factor from the file's height unit to metres (e.g. 1e-9 for nm).
    #[cfg_attr(
        feature = "cli",
        arg(long, allow_negative_numbers = true, default_value_t = 1.0)
    )]
    pub scale: f64,
    /// Treat the map as periodic: remove only the mean, wrap differences and
    /// summit neighbours around every edge.
    #[cfg_attr(feature = "cli", arg(long))]
    pub periodic: bool,
    /// Contact modulus E* (Pa), with --hardness for the plasticity index.
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub estar: Option<f64>,
    /// Hardness H (Pa), with --estar for the plasticity index.
    #[cfg_attr(feature = "cli", arg(long, allow_negative_numbers = true))]
    pub hardness: Option<f64>,
    /// Print one JSON object instead of a table.
    #[cfg_attr(feature = "cli", arg(long))]
    pub json: bool,
    /// Also write `surface.json`, `summit_heights.svg` and `summit_map.svg`
    /// into this directory.
    #[cfg_attr(feature = "cli", arg(long))]
    pub out: Option<PathBuf>,
}

/// The summits of `asperity surface --json`.
#[derive(Serialize, Debug, Clone)]
pub struct SummitsJson {
    /// Strict 8-neighbour summits.
    pub count: usize,
    /// Summits per area (1/m^2).
    pub density_per_m2: f64,
    /// Mean summit curvature (1/m).
    pub mean_curvature_per_m: Option<f64>,
    /// Mean summit radius (m).
    pub radius_m: Option<f64>,
    /// Summit-height standard deviation (m).
    pub height_std_m: Option<f64>,
    /// Mean summit height above the mean plane (m).
    pub mean_height_m: Option<f64>,
}

/// GW parameters from the spectral moments (McCool).
#[derive(Serialize, Debug, Clone)]
pub struct GwJson {
    /// Summit density (1/m^2).
    pub density_per_m2: f64,
    /// Summit radius (m).
    pub radius_m: f64,
    /// Summit-height standard deviation (m).
    pub sigma_m: Option<f64>,
}

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
}

/// Reads the map by extension; every content error names the file.
pub fn read_map(path: &Path) -> CommandResult<HeightMap> {
    let shown = path.display().to_string();
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .unwrap_or_default();
    crate::study::memory::check_map(path).map_err(CommandError::Usage)?;
    let bytes = std::fs::read(path)
        .map_err(|e| CommandError::Usage(format!("{shown}: cannot read: {e}")))?;
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
    Ok(map.map_err(|e| e.renamed(&shown))?)
}

fn plasticity(
    estar: Option<f64>,
    hardness: Option<f64>,
    c: &Characterisation,
) -> CommandResult<Option<f64>> {
    match (estar, hardness) {
        (None, None) => Ok(None),
        (Some(_), None) => Err(CommandError::Usage(
            "--hardness: needed with --estar".into(),
        )),
        (None, Some(_)) => Err(CommandError::Usage(
            "--estar: needed with --hardness".into(),
        )),
        (Some(e), Some(h)) => {
            positive("--estar", e)?;
            positive("--hardness", h)?;
            let psi = c.gw_from_moments().plasticity_index(e, h)?;
            if psi.is_some_and(|p| !p.is_finite()) {
                return Err(CommandError::Usage(format!(
                    "--estar = {e:e} Pa and --hardness = {h:e} Pa: the plasticity index \
                     (E*/H) sqrt(sigma/R) overflows"
                )));
            }
            Ok(psi)
        }
    }
}

/// How a map is named in messages: its path, and `--scale` when it is not
/// 1 (a flat map may be a tiny scale's doing).
pub(crate) fn scaled_name(path: &std::path::Path, scale: f64) -> String {
    if scale == 1.0 {
        path.display().to_string()
    } else {
        format!("{} (heights x --scale {scale:e})", path.display())
    }
}

/// Characterises `map` (heights in m) with pixels of `pixel_size` (m);
/// errors name `--pixel-size`, `--estar`, `--hardness` or `map_name`.
pub fn characterise(
    map: HeightMap,
    map_name: &str,
    pixel_size: f64,
    periodic: bool,
    estar: Option<f64>,
    hardness: Option<f64>,
) -> CommandResult<(SurfaceJson, Characterisation)> {
    let topo = Topography::new(map, pixel_size).map_err(|e| match e.field() {
        Some("heights") => e.renamed("--scale"),
        _ => e.renamed("--pixel-size"),
    })?;
    let c = topo
        .characterise(periodic)
        .map_err(|e| e.renamed(map_name))?;
    let psi = plasticity(estar, hardness, &c)?;
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
        summits: SummitsJson {
            count: s.count,
            density_per_m2: s.density_per_m2,
            mean_curvature_per_m: s.mean_curvature_per_m,
            radius_m: s.radius_m,
            height_std_m: s.height_std_m,
            mean_height_m: s.mean_height_m,
        },
        gw_from_moments: GwJson {
            density_per_m2: gw.density_per_m2,
            radius_m: gw.radius_m,
            sigma_m: gw.sigma_m,
        },
        plasticity_index: psi,
    };
    Ok((out, c))
}

/// Runs `asperity surface` (and writes `--out`).
pub fn run(args: &SurfaceArgs) -> CommandResult<SurfaceJson> {
    positive("--pixel-size", args.pixel_size)?;
    positive("--scale", args.scale)?;
    let map = read_map(&args.file)?
        .scaled(args.scale)
        .map_err(|e| e.renamed("--scale"))?;
    let (out, c) = characterise(
        map,
        &scaled_name(&args.file, args.scale),
        args.pixel_size,
        args.periodic,
        args.estar,
        args.hardness,
    )?;
    if let Some(dir) = &args.out {
        let json = serde_json::to_string(&out).map_err(|e| CommandError::Failed(e.to_string()))?;
        write_outputs(dir, &json, &c)?;
    }
    Ok(out)
}

fn write_outputs(dir: &Path, json: &str, c: &Characterisation) -> CommandResult<()> {
    let io = |p: &Path, e: std::io::Error| CommandError::from(Error::io(p.display(), e));
    std::fs::create_dir_all(dir).map_err(|e| io(dir, e))?;
    let p = dir.join("surface.json");
    crate::study::atomic::write(&p, format!("{json}\n")).map_err(|e| io(&p, e))?;
    if c.summits.len() < 2 {
        eprintln!("note: fewer than 2 summits, no charts written");
        return Ok(());
    }
    let chart = |e: Error| CommandError::Failed(e.to_string());
    crate::study::plot::surface::write_summit_heights(&dir.join("summit_heights.svg"), c)
        .map_err(chart)?;
    crate::study::plot::surface::write_summit_map(&dir.join("summit_map.svg"), c).map_err(chart)
}
