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
    /// GW's model error on this map ([`SurfaceModelError`]).
    pub model_error: SurfaceModelError,
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

/// The mean pressures over `E*` at which [`characterise`] measures GW's
/// model error.
pub const MODEL_ERROR_LOADS: [f64; 3] = [1e-3, 3e-3, 1e-2];

/// GW's model error on the map: GW on the map's moments (the
/// `gw_from_moments` parameters, Hertz summits, Gaussian heights) and
/// Persson on its radial spectrum against the exact elastic
/// boundary-element solution of the map ([`crate::bem::compare`]) at
/// `p/E*` = [`MODEL_ERROR_LOADS`] (area fractions and gaps at a given
/// `p/E*` do not depend on `E*`), `(model - exact)/exact`; measured when
/// the estimated CPU time is at most 2 s
/// ([`crate::study::map_error::CPU_FLOOR`]).
#[derive(Serialize, Debug, Clone)]
pub struct SurfaceModelError {
    /// What it is measured against, or why it is not.
    pub reference: String,
    /// The states' mean pressures over `E*`.
    pub pressure_over_estar: Vec<f64>,
    /// The exact real-area fractions.
    pub exact_area_fraction: Vec<f64>,
    /// The exact mean gaps (m).
    pub exact_mean_gap_m: Vec<f64>,
    /// GW's area fraction against the exact one at the same pressure.
    pub area: Vec<Option<f64>>,
    /// GW's pressure at the exact mean gap against the exact pressure.
    pub load: Vec<Option<f64>>,
    /// GW's mean gap against the exact one at the same pressure.
    pub mean_gap: Vec<Option<f64>>,
    /// Persson's area fraction against the exact one.
    pub persson_area: Vec<Option<f64>>,
    /// Persson's mean gap against the exact one.
    pub persson_mean_gap: Vec<Option<f64>>,
    /// Estimated CPU time (s) of the exact solution (the output holds no
    /// measured time, so that it is the same bytes run after run).
    pub estimate_s: f64,
}

impl SurfaceModelError {
    fn unmeasured(reference: String, estimate_s: f64) -> Self {
        SurfaceModelError {
            reference,
            pressure_over_estar: Vec::new(),
            exact_area_fraction: Vec::new(),
            exact_mean_gap_m: Vec::new(),
            area: Vec::new(),
            load: Vec::new(),
            mean_gap: Vec::new(),
            persson_area: Vec::new(),
            persson_mean_gap: Vec::new(),
            estimate_s,
        }
    }

    /// A warning per output whose largest difference is above 10 %.
    pub fn warnings(&self) -> Vec<String> {
        [
            ("GW's real contact area", "model_error.area", &self.area),
            (
                "GW's load at the same mean gap",
                "model_error.load",
                &self.load,
            ),
            ("GW's mean gap", "model_error.mean_gap", &self.mean_gap),
            (
                "Persson's real contact area",
                "model_error.persson_area",
                &self.persson_area,
            ),
            (
                "Persson's mean gap",
                "model_error.persson_mean_gap",
                &self.persson_mean_gap,
            ),
        ]
        .into_iter()
        .flat_map(|(name, key, v)| {
            // A difference the model or the exact solution cannot give
            // (no contact, or a value that is not a finite number) is null.
            let nulls = v
                .iter()
                .enumerate()
                .filter(|(_, e)| e.is_none())
                .map(|(k, _)| {
                    format!(
                        "{key}[{k}] at p/E* = {:e} is null: {name} or the exact solution has no \
                     finite nonzero value there",
                        self.pressure_over_estar[k]
                    )
                });
            let largest = v
                .iter()
                .enumerate()
                .filter_map(|(k, e)| e.map(|e| (k, e)))
                .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
                .filter(|(_, e)| e.abs() > crate::study::map_error::WARN_ABOVE)
                .map(|(k, e)| {
                    format!(
                        "model error: {name} on this map differs from the exact elastic solution \
                         by {:+.1} % at p/E* = {:e} ({key})",
                        100.0 * e,
                        self.pressure_over_estar[k]
                    )
                });
            largest.into_iter().chain(nulls).collect::<Vec<_>>()
        })
        .collect()
    }
}

/// GW's mean pressure (Pa) where its mean gap is `u` (m), searched from
/// its state at `p` (Pa) in steps of a tenth of `sigma`.
fn gw_pressure_at_gap(gw: &crate::gw::GwOnMoments, u: f64, p: f64) -> Option<f64> {
    let g0 = gw.state(p).ok()?;
    let f = |x: f64| gw.state_at(x).map_or(f64::NAN, |g| g.mean_gap - u);
    let (mut lo, mut hi) = (g0.separation, g0.separation);
    for _ in 0..400 {
        if f(lo) <= 0.0 {
            break;
        }
        lo -= 0.1 * gw.sigma;
    }
    for _ in 0..400 {
        if f(hi) >= 0.0 {
            break;
        }
        hi += 0.1 * gw.sigma;
    }
    let x = crate::numeric::roots::brent(f, lo, hi, 1e-12 * gw.sigma)?;
    gw.state_at(x).ok().map(|g| g.pressure)
}

/// [`SurfaceModelError`] of `map` with `c` its characterisation.
fn model_error(
    map: &HeightMap,
    input: &SurfaceInput,
    c: &Characterisation,
) -> CommandResult<SurfaceModelError> {
    use crate::bem::compare::{compare, CompareInput, Control};
    use crate::study::map_error::{estimate_seconds, CPU_FLOOR, EXACT_TOLERANCE};
    let (rows, cols) = (map.rows(), map.cols());
    let estimate = estimate_seconds(rows, cols, input.periodic, MODEL_ERROR_LOADS.len());
    let options = crate::bem::Options {
        tolerance: EXACT_TOLERANCE,
        ..Default::default()
    };
    let memory = crate::bem::memory_estimate(rows, cols, input.periodic);
    if estimate > CPU_FLOOR || memory > options.memory_limit {
        return Ok(SurfaceModelError::unmeasured(
            format!(
                "not measured: the exact elastic solution of this {rows} x {cols} map at {} loads \
                 would cost an estimated {estimate:.1} s of CPU ({:.0} MiB), above {CPU_FLOOR} s \
                 (or 1 GiB); `asperity bem` measures it at the pressures you give",
                MODEL_ERROR_LOADS.len(),
                memory as f64 / 1048576.0
            ),
            estimate,
        ));
    }
    let estar = input.estar.unwrap_or(1e9);
    let cmp = compare(
        map,
        &CompareInput {
            pixel_size: input.pixel_size,
            pixel_size_y: input.pixel_size_y,
            contact_modulus: estar,
            periodic: input.periodic,
            control: Control::Pressure,
            targets: MODEL_ERROR_LOADS.iter().map(|l| l * estar).collect(),
            adhesion: None,
            hardness: None,
            gamma: 1.0,
            resistivity: None,
            options,
        },
    );
    let cmp = match cmp {
        Ok(c) => c,
        Err(e) if matches!(e.error, Error::Cancelled) => return Err(e.error),
        Err(e) => {
            return Ok(SurfaceModelError::unmeasured(
                format!(
                    "not measured: the exact elastic solution failed ({})",
                    e.error
                ),
                estimate,
            ))
        }
    };
    let gw = crate::gw::GwOnMoments::new(&c.moments, estar, c.nominal_area_m2()).ok();
    let states = &cmp.states;
    Ok(SurfaceModelError {
        reference: format!(
            "exact elastic half-space, FFT boundary elements, tolerance {EXACT_TOLERANCE:e}, on \
             the same map{}; GW on the map's moments (Hertz summits), Persson (gamma = 1) on its \
             radial spectrum; area and mean gap at the same pressure, load at the same mean gap",
            if input.periodic {
                " (periodic)"
            } else {
                " (padded to twice its size)"
            }
        ),
        pressure_over_estar: MODEL_ERROR_LOADS.to_vec(),
        exact_area_fraction: states.iter().map(|s| s.solution.area_fraction()).collect(),
        exact_mean_gap_m: states.iter().map(|s| s.solution.mean_gap).collect(),
        area: cmp.differences.iter().map(|d| d.gw_area).collect(),
        load: states
            .iter()
            .map(|s| {
                let (p, u) = (s.solution.mean_pressure, s.solution.mean_gap);
                gw.as_ref()
                    .and_then(|g| gw_pressure_at_gap(g, u, p))
                    .map(|q| q / p - 1.0)
            })
            .collect(),
        mean_gap: cmp.differences.iter().map(|d| d.gw_mean_gap).collect(),
        persson_area: cmp.differences.iter().map(|d| d.persson_area).collect(),
        persson_mean_gap: cmp.differences.iter().map(|d| d.persson_mean_gap).collect(),
        estimate_s: estimate,
    })
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
        model_error: SurfaceModelError::unmeasured(String::new(), 0.0),
    };
    let mut out = out;
    out.model_error = model_error(topo.map(), input, &c)?;
    out.warnings.extend(out.model_error.warnings());
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
