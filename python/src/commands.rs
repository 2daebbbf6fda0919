//! The commands as functions: keyword arguments named as the command
//! line's flags (dashes to underscores, `--lambda` as `lambda_`), arrays
//! for lists, results as the dict `asperity X ... --json` prints (lists of
//! numbers as NumPy arrays). Each converts its arguments into the typed
//! command API (`asperity::commands`) directly, no text in between, and
//! calls it under [`crate::guard`].

use crate::arrays::{self, Dims};
use crate::convert::serialised;
use crate::guard;
use asperity::commands::{self as cmd, Vocabulary};
use asperity::electrical::heating::{
    DEFAULT_BULK_TEMPERATURE, GOLD_MELTING_TEMPERATURE, GOLD_SOFTENING_TEMPERATURE,
};
use numpy::{PyArray, PyArrayMethods};
use pyo3::prelude::*;
use std::path::PathBuf;

/// Python's words for the inputs.
fn words() -> Vocabulary {
    Vocabulary::python()
}

/// A library choice (a law, a profile) by name, as `ValueError` naming
/// the argument.
fn choice<T>(r: asperity::Result<T>) -> PyResult<T> {
    r.map_err(|e| guard::py_err(e, &words()))
}

/// Values with more entries than this run on a worker thread (Ctrl-C
/// honoured); fewer run inline (no thread's start-up cost).
const INLINE_VALUES: usize = 1 << 16;

/// Facts of one single-asperity law in Maugis units.
///
/// Parameters
/// ----------
/// law : str
///     ``"hertz"``, ``"bradley"``, ``"dmt"``, ``"jkr"``, ``"maugis"`` or ``"cos"``.
/// lambda_ : float, optional
///     Maugis parameter lambda > 0 (maugis, cos; default 1).
///
/// Returns
/// -------
/// dict
///     ``law``, ``lambda``, ``pull_off_load_control`` (units of pi w R),
///     ``jump_out_load`` (pi w R; None when nothing snaps),
///     ``jump_out_interference`` ((pi^2 w^2 R / K^2)^(1/3)),
///     ``contact_radius_zero_load`` ((pi w R^2 / K)^(1/3)).
///
/// Examples
/// --------
/// >>> asperity.law("jkr")["pull_off_load_control"]
/// -1.5
#[pyfunction]
#[pyo3(name = "law", signature = (law, lambda_ = None))]
pub fn law_py(py: Python<'_>, law: &str, lambda_: Option<f64>) -> PyResult<Py<PyAny>> {
    use asperity::named::Named;
    let kind =
        choice(asperity::law::LawKind::parse(law).map_err(|e| e.renamed(&cmd::param("law"))))?;
    let input = cmd::law::LawInput {
        law: kind,
        lambda: lambda_,
    };
    let out = guard::quick(py, "law", &words(), || cmd::law::facts(&input))?;
    serialised(py, &out, true)
}

/// Peak contact temperature from the contact voltage, or the reverse
/// (Holm's phi-theta relation with the Wiedemann–Franz law).
///
/// Parameters
/// ----------
/// voltage : float, optional
///     Contact voltage U = I R (V), >= 0: gives the peak temperature.
/// max_temperature : float, optional
///     Peak temperature (K), from the bulk to the melting temperature:
///     gives the voltage. Exactly one of ``voltage``, ``max_temperature``.
/// bulk_temperature : float
///     T0 (K), default 293.15.
/// softening_temperature, melting_temperature : float
///     The metal's (K); default gold's 373.15 and 1337.33.
///
/// Returns
/// -------
/// dict
///     ``max_temperature_K`` (None once the spot melts), ``condition``
///     (solid, softened, molten) and ``warnings``; or ``voltage_V``.
///
/// Examples
/// --------
/// >>> asperity.heating(voltage=0.1)["max_temperature_K"]
#[pyfunction]
#[pyo3(name = "heating", signature = (
    voltage = None,
    max_temperature = None,
    bulk_temperature = DEFAULT_BULK_TEMPERATURE,
    softening_temperature = GOLD_SOFTENING_TEMPERATURE,
    melting_temperature = GOLD_MELTING_TEMPERATURE
))]
pub fn heating_py(
    py: Python<'_>,
    voltage: Option<f64>,
    max_temperature: Option<f64>,
    bulk_temperature: f64,
    softening_temperature: f64,
    melting_temperature: f64,
) -> PyResult<Py<PyAny>> {
    let (out, _) = guard::quick(py, "heating", &words(), || {
        cmd::heating::heating(&cmd::heating::HeatingInput {
            target: cmd::heating::HeatingTarget::from_options(voltage, max_temperature)?,
            bulk_temperature,
            softening_temperature,
            melting_temperature,
        })
    })?;
    serialised(py, &out, true)
}

/// Resistance of explicit contact spots: independent parallel spots,
/// Greenwood's (1966) formula and the exact equal-potential solution.
///
/// Parameters
/// ----------
/// x, y : array_like
///     Spot centres (m), finite.
/// radius : array_like
///     Spot radii (m), > 0; as many as ``x``. At most 20,000 spots (the
///     exact solve is O(n^3): about 80 s at 20,000).
/// resistivity : float
///     Resistivity of the metal (Ohm m), > 0.
/// mean_free_path : float, optional
///     Electron mean free path (m), > 0: Wexler's spot resistance instead
///     of Maxwell's.
///
/// Returns
/// -------
/// dict
///     ``parallel_ohm``, ``greenwood_ohm``, ``exact_ohm`` (Ohm).
///
/// Examples
/// --------
/// >>> asperity.spots([0, 1e-6], [0, 0], [1e-7, 1e-7], resistivity=2.44e-8)
#[pyfunction]
#[pyo3(name = "spots", signature = (x, y, radius, resistivity, mean_free_path = None))]
pub fn spots_py(
    py: Python<'_>,
    x: &Bound<'_, PyAny>,
    y: &Bound<'_, PyAny>,
    radius: &Bound<'_, PyAny>,
    resistivity: f64,
    mean_free_path: Option<f64>,
) -> PyResult<Py<PyAny>> {
    let (x, y, r) = (
        arrays::sequence(x, "x")?,
        arrays::sequence(y, "y")?,
        arrays::sequence(radius, "radius")?,
    );
    let out = guard::long(py, "spots", &words(), || {
        cmd::spots::resistances(&cmd::spots::SpotsInput {
            x: &x,
            y: &y,
            radius: &r,
            resistivity,
            mean_free_path,
        })
    })?;
    serialised(py, &out, true)
}

/// Characterise a measured height map: moments, summits, GW parameters
/// from the moments, plasticity index.
///
/// Parameters
/// ----------
/// heights : array_like
///     A real, finite 2-D array (rows along y, columns along x) of heights
///     in m, at least 3 x 3.
/// pixel_size : float
///     Pixel size (m), > 0, along x (a row), and along y unless
///     ``pixel_size_y``.
/// periodic : bool
///     Treat the map as periodic (remove only the mean, wrap neighbours).
/// estar, hardness : float, optional
///     Contact modulus E* and hardness H (Pa), together: the plasticity
///     index (E*/H) sqrt(sigma/R).
/// pixel_size_y : float, optional
///     Pixel size (m), > 0, along y (a column) when it differs from x
///     (``read_topography``'s ``pixel_size_m``).
///
/// Returns
/// -------
/// dict
///     ``rows``, ``cols``, ``rms_height_m``, ``m0`` (m^2), ``m2``, ``m4``
///     (1/m^2), ``rms_slope``, ``rms_gradient``, ``rms_curvature_per_m``,
///     ``bandwidth_alpha``, ``summits`` (``count``, ``density_per_m2``,
///     ``radius_m``, ...), ``gw_from_moments`` (``density_per_m2``,
///     ``radius_m``, ``sigma_m``), ``plasticity_index``.
///
/// Examples
/// --------
/// >>> h = numpy.load("examples/data/measured-topography.npy")
/// >>> asperity.surface(h, pixel_size=50e-9)["rms_height_m"]
#[pyfunction]
#[pyo3(name = "surface", signature = (heights, pixel_size, periodic = false, estar = None, hardness = None, pixel_size_y = None))]
pub fn surface_py(
    py: Python<'_>,
    heights: &Bound<'_, PyAny>,
    pixel_size: f64,
    periodic: bool,
    estar: Option<f64>,
    hardness: Option<f64>,
    pixel_size_y: Option<f64>,
) -> PyResult<Py<PyAny>> {
    let map = arrays::height_map(heights, "heights")?;
    let input = cmd::surface::SurfaceInput {
        pixel_size_y,
        pixel_size,
        periodic,
        estar,
        hardness,
    };
    let out = guard::long(py, "surface", &words(), || {
        asperity::error::positive(&cmd::param("pixel_size"), pixel_size)?;
        // The map's memory: its copy is made; the characterisation's
        // detrended copy and difference grids come on top.
        let map = map?;
        asperity::study::memory::ensure(
            &cmd::param("heights"),
            "characterising a map",
            map.heights().len() as f64 * 8.0 * 2.0,
            "crop or downsample it",
        )?;
        cmd::surface::characterise(map, &input).map(|(out, _)| out)
    })?;
    serialised(py, &out, true)
}

/// Read a measured map from an instrument or exchange file: AFM,
/// profilometer and interferometer formats with their pixel sizes and
/// units (``.x3p``, ``.sdf``, ``.gwy``, ``.sur``, ``.di``/``.spm``,
/// ``.ibw``, ``.opd``, ``.opdx``, ``.nc``, ``.frt``, ``.plux``), ``.npy`` or a text
/// matrix.
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     The file; its format by its extension.
/// channel : str or int, optional
///     The channel of a file with several, by name or index from 0
///     (default: the height channel).
/// height_unit : str, optional
///     ``"nm"``, ``"um"`` or ``"m"``: the unit of a ``.npy`` or text map's
///     heights (default m); not for the instrument formats, which give
///     their own.
/// fill_missing : bool
///     Fill missing pixels (NaN or masked in the file) from their
///     neighbours; by default they stay NaN (counted in ``missing``).
///
/// Returns
/// -------
/// tuple
///     ``(heights, meta)``: a 2-D float64 array of heights in m (rows along
///     y, columns along x) and a dict: ``format``, ``channel``, ``unit``
///     (the instrument's height unit), ``pixel_size_m`` (``(dx, dy)`` in m,
///     or None when the file has none), ``rows``, ``cols``, ``missing``,
///     ``periodic``.
///
/// Examples
/// --------
/// >>> h, meta = asperity.read_topography("tests/data/topography/sdf-1.sdf")
/// >>> meta["pixel_size_m"]
/// (1e-06, 1e-06)
#[pyfunction]
#[pyo3(name = "read_topography", signature = (path, channel = None, height_unit = None, fill_missing = false))]
pub fn read_topography_py(
    py: Python<'_>,
    path: PathBuf,
    channel: Option<&Bound<'_, PyAny>>,
    height_unit: Option<&str>,
    fill_missing: bool,
) -> PyResult<Py<PyAny>> {
    use asperity::topography::Channel;
    let channel = match channel {
        None => Channel::Default,
        Some(c) => match c.extract::<usize>() {
            Ok(i) => Channel::Index(i),
            Err(_) => Channel::Name(c.extract::<String>().map_err(|_| {
                pyo3::exceptions::PyTypeError::new_err(
                    "channel must be a str (a name) or an int (an index from 0)",
                )
            })?),
        },
    };
    let unit = height_unit
        .map(cmd::measured::height_unit)
        .transpose()
        .map_err(|e| guard::py_err(e, &words()))?;
    let (heights, meta) = guard::long(py, "read_topography", &words(), || {
        cmd::measured::read_topography(&path, &channel, unit, fill_missing)
    })?;
    let shape = [meta.rows, meta.cols];
    let array = PyArray::from_vec(py, heights).reshape(shape)?.into_any();
    let d = pyo3::types::PyDict::new(py);
    d.set_item("format", meta.format)?;
    d.set_item("channel", &meta.channel)?;
    d.set_item("unit", &meta.unit)?;
    d.set_item("pixel_size_m", meta.pixel_size_m.map(|[dx, dy]| (dx, dy)))?;
    d.set_item("rows", meta.rows)?;
    d.set_item("cols", meta.cols)?;
    d.set_item("missing", meta.missing)?;
    d.set_item("periodic", meta.periodic)?;
    Ok((array, d).into_pyobject(py)?.into_any().unbind())
}

/// The Greenwood–Williamson integrals F_n(h) = int_h^inf (s - h)^n phi(s) ds
/// of a standardised height distribution.
///
/// Parameters
/// ----------
/// dist : str
///     ``"gaussian"`` or ``"exponential"``.
/// n : float
///     Order, in [0, 100].
/// h : array_like
///     Standardised separations h = d / sigma, any shape.
///
/// Returns
/// -------
/// numpy.ndarray
///     F_n at every h, in the shape of ``h`` (dimensionless).
///
/// Examples
/// --------
/// >>> asperity.fn("gaussian", 1.5, numpy.linspace(0, 3, 4))
#[pyfunction]
#[pyo3(name = "fn")]
pub fn fn_values<'py>(
    py: Python<'py>,
    dist: &str,
    n: f64,
    h: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let dist = choice(cmd::fn_::dist_named(dist))?;
    let hs = arrays::numbers(h, "h", Dims::Any)?;
    let work = || cmd::fn_::values(dist, n, &hs.values);
    let values = if hs.values.len() > INLINE_VALUES {
        guard::long(py, "fn", &words(), work)?
    } else {
        guard::quick(py, "fn", &words(), work)?
    };
    let flat = PyArray::from_vec(py, values);
    Ok(flat.reshape(hs.shape)?.into_any())
}

/// JKR adhesion (or Maugis–Dugdale with ``stress``) of an axisymmetric
/// profile: pull-off under load and displacement control and, with
/// ``radii``, the curve. SI units.
///
/// Parameters
/// ----------
/// profile : str
///     ``"paraboloid"``, ``"sphere"``, ``"cone"``, ``"flat"`` or ``"power"``.
/// estar : float
///     Contact modulus E* (Pa), > 0.
/// w : float
///     Work of adhesion (J/m^2), > 0.
/// radius : float, optional
///     Sphere, paraboloid or punch radius (m).
/// tan_angle : float, optional
///     tan(beta) of the cone f(r) = r tan(beta).
/// exponent, coefficient : float, optional
///     n and A (m^(1-n)) of the power law f(r) = A r^n (n > 1/2).
/// radii : array_like, optional
///     Contact radii (m) for the curve.
/// stress : float, optional
///     Dugdale stress sigma0 (Pa): Maugis–Dugdale instead of JKR.
///
/// Returns
/// -------
/// dict
///     ``pull_off_load_control`` and ``jump_out_displacement_control``
///     (``load_N``, ``radius_m``, ``interference_m``), ``curve`` (with
///     ``radii``), ``warnings``.
///
/// Examples
/// --------
/// >>> asperity.shape("cone", estar=1e9, w=0.05, tan_angle=0.2)
#[pyfunction]
#[pyo3(name = "shape", signature = (profile, estar, w, radius = None, tan_angle = None, exponent = None, coefficient = None, radii = None, stress = None))]
#[allow(clippy::too_many_arguments)]
pub fn shape_py(
    py: Python<'_>,
    profile: &str,
    estar: f64,
    w: f64,
    radius: Option<f64>,
    tan_angle: Option<f64>,
    exponent: Option<f64>,
    coefficient: Option<f64>,
    radii: Option<&Bound<'_, PyAny>>,
    stress: Option<f64>,
) -> PyResult<Py<PyAny>> {
    let input = cmd::shape::ShapeInput {
        profile: choice(cmd::shape::profile_named(profile))?,
        radius,
        tan_angle,
        exponent,
        coefficient,
        estar,
        w,
        radii: arrays::opt_sequence(radii, "radii")?,
        stress,
    };
    let out = guard::long(py, "shape", &words(), || cmd::shape::shape(&input))?;
    serialised(py, &out, true)
}

/// The wavy punch of Kesari & Lew (2011): a paraboloid with sinusoidal
/// roughness under JKR adhesion: exact curve, envelopes, loading and
/// unloading paths, energy loss per cycle.
///
/// Parameters
/// ----------
/// estar : float
///     Contact modulus E* (Pa).
/// w : float
///     Work of adhesion (J/m^2).
/// radius : float
///     Radius of curvature R (m).
/// amplitude : float
///     Dimensionless roughness amplitude A.
/// wavelength : float
///     Roughness wavelength l (m), < ``radius``.
/// radii : array_like, optional
///     Contact radii (m) of the curve and envelopes.
/// depths : array_like, optional
///     Depths (m) of the paths.
/// cycle : (float, float), optional
///     ``(hmin, hmax)`` (m): the energy lost per displacement-controlled
///     cycle.
///
/// Returns
/// -------
/// dict
///     ``curve``, ``envelope_loading``, ``envelope_unloading`` (lists of
///     ``radius``, ``depth``, ``load``), ``loading``, ``unloading``
///     (``depth_m``, ``radius_m``, ``load_N``), ``energy_loss_per_cycle_J``.
///
/// Examples
/// --------
/// >>> asperity.punch(17.08e3, 0.0804, 0.25, 0.0156, 5e-5, cycle=(-1e-3, 1.5e-3))
#[pyfunction]
#[pyo3(name = "punch", signature = (estar, w, radius, amplitude, wavelength, radii = None, depths = None, cycle = None))]
#[allow(clippy::too_many_arguments)]
pub fn punch_py(
    py: Python<'_>,
    estar: f64,
    w: f64,
    radius: f64,
    amplitude: f64,
    wavelength: f64,
    radii: Option<&Bound<'_, PyAny>>,
    depths: Option<&Bound<'_, PyAny>>,
    cycle: Option<&Bound<'_, PyAny>>,
) -> PyResult<Py<PyAny>> {
    let cycle = match arrays::opt_sequence(cycle, "cycle")? {
        Some(c) if c.len() == 2 => Some((c[0], c[1])),
        Some(c) => {
            return Err(pyo3::exceptions::PyValueError::new_err(format!(
                "cycle: expected (hmin, hmax), got {} values",
                c.len()
            )))
        }
        None => None,
    };
    let input = cmd::punch::PunchInput {
        estar,
        w,
        radius,
        amplitude,
        wavelength,
        radii: arrays::opt_sequence(radii, "radii")?,
        depths: arrays::opt_sequence(depths, "depths")?,
        cycle,
    };
    let out = guard::long(py, "punch", &words(), || cmd::punch::punch(&input))?;
    serialised(py, &out, true)
}

/// Fit E*, w and A sqrt(l) of the Kesari–Lew envelopes to measured
/// (contact radius, load) pairs on loading and unloading.
///
/// Parameters
/// ----------
/// phase : sequence of str
///     ``"loading"`` or ``"unloading"`` per point.
/// radius : array_like
///     Contact radii (m).
/// load : array_like
///     Loads (N).
/// punch_radius : float
///     The punch's radius of curvature (m).
///
/// Returns
/// -------
/// dict
///     ``estar_Pa``, ``w_J_per_m2``, ``amplitude_sqrt_wavelength_m_half``,
///     each with ``_stderr``, ``residual_rms_N``, ``points``.
#[pyfunction]
#[pyo3(name = "punch_fit", signature = (phase, radius, load, punch_radius))]
pub fn punch_fit_py(
    py: Python<'_>,
    phase: Vec<String>,
    radius: &Bound<'_, PyAny>,
    load: &Bound<'_, PyAny>,
    punch_radius: f64,
) -> PyResult<Py<PyAny>> {
    let (radius, load) = (
        arrays::sequence(radius, "radius")?,
        arrays::sequence(load, "load")?,
    );
    let out = guard::long(py, "punch_fit", &words(), || {
        let phases: Vec<&str> = phase.iter().map(String::as_str).collect();
        let data = cmd::punch::fit_points(&phases, &radius, &load)?;
        cmd::punch::fit(&data, punch_radius, &cmd::param("radius"))
    })?;
    serialised(py, &out, true)
}

/// Persson's contact theory on a self-affine spectrum, with GW on the same
/// spectrum beside it.
///
/// Parameters
/// ----------
/// hurst : float
///     Hurst exponent H, in (0, 1].
/// q_long, q_roll, q_short : float
///     Wavevectors (rad/m): the spectrum is zero below q_long, flat up to
///     q_roll, C ~ q^-2(1+H) up to q_short.
/// estar : float
///     Contact modulus E* (Pa).
/// pressures : array_like
///     Mean pressures (Pa), each > 0.
/// h_rms : float, optional
///     RMS height (m) of the spectrum (or ``slope_rms``: exactly one).
/// slope_rms : float, optional
///     RMS gradient of the spectrum.
/// gamma : float
///     Yang–Persson factor in [0, 1] of the mean gap (default 1).
/// adhesion_energy : float, optional
///     w (J/m^2): adds the Persson–Tosatti number.
/// adhesion_range : float, optional
///     rho (m) of the interaction -w exp(-g/rho): with ``adhesion_energy``
///     adds ``adhesion_criteria`` (Pastewka–Robbins with its validity
///     rho/g0 < 0.1, Persson–Tosatti, the Tabor parameter at R = 1/h'',
///     Müser's mu_rho).
/// relative_humidity : float, optional
///     In (0, 1): adds ``capillary``, the flooded capillary attraction at
///     every pressure from Persson's gap distribution (Laplace pressure
///     where the gap is below the meniscus height) beside per-summit
///     menisci on GW's summits, and the regime h_m/u_rms.
/// surface_tension, contact_angle_1, contact_angle_2, temperature, molar_volume : float
///     The liquid (N/m, degrees, degrees, K, m^3/mol); default water at
///     293.15 K wetting both surfaces.
///
/// Returns
/// -------
/// dict
///     ``states`` (``pressure_Pa``, ``area_fraction``, ``mean_gap_m``,
///     ``gw_area_fraction``, ``gw_mean_gap_m``), the spectrum's moments,
///     ``full_contact_energy_J_per_m2``, ``gw``, ``numerical_error``,
///     ``model_error``, ``warnings``, ``adhesion_criteria`` (with an
///     adhesion range), ``capillary`` (with a relative humidity).
///
/// Examples
/// --------
/// >>> asperity.persson(0.8, 1e5, 4e5, 4e8, 1e9, [1e4, 1e5], h_rms=1e-8)
#[pyfunction]
#[pyo3(name = "persson", signature = (hurst, q_long, q_roll, q_short, estar, pressures, h_rms = None, slope_rms = None, gamma = 1.0, adhesion_energy = None, adhesion_range = None, relative_humidity = None, surface_tension = 0.0728, contact_angle_1 = 0.0, contact_angle_2 = 0.0, temperature = 293.15, molar_volume = 1.8e-5))]
#[allow(clippy::too_many_arguments)]
pub fn persson_py(
    py: Python<'_>,
    hurst: f64,
    q_long: f64,
    q_roll: f64,
    q_short: f64,
    estar: f64,
    pressures: &Bound<'_, PyAny>,
    h_rms: Option<f64>,
    slope_rms: Option<f64>,
    gamma: f64,
    adhesion_energy: Option<f64>,
    adhesion_range: Option<f64>,
    relative_humidity: Option<f64>,
    surface_tension: f64,
    contact_angle_1: f64,
    contact_angle_2: f64,
    temperature: f64,
    molar_volume: f64,
) -> PyResult<Py<PyAny>> {
    let pressures = arrays::sequence(pressures, "pressures")?;
    let liquid = relative_humidity.map(|rh| cmd::wet_map::Liquid {
        relative_humidity: rh,
        surface_tension,
        contact_angle_1,
        contact_angle_2,
        temperature,
        molar_volume,
    });
    let out = guard::long(py, "persson", &words(), || {
        cmd::persson::persson(&cmd::persson::PerssonInput {
            hurst,
            q_long,
            q_roll,
            q_short,
            normalisation: cmd::persson::normalisation(h_rms, slope_rms)?,
            estar,
            pressures,
            gamma,
            adhesion_energy,
            adhesion_range,
            liquid,
        })
    })?;
    serialised(py, &out, true)
}

/// The full Lennard-Jones sphere solver: pull-off facts in Maugis units.
///
/// Parameters
/// ----------
/// mu : float
///     Tabor parameter (R w^2 / (E*^2 z0^3))^(1/3), in [0.005, 100].
/// rho : float, optional
///     Size ratio R/z0 of a true sphere (paraboloid if absent).
/// resolution : float, optional
///     Mesh resolution multiplier in [0.5, 64] (default 1).
/// curve : str or os.PathLike, optional
///     Write the traced curve (CSV) to this file.
///
/// Returns
/// -------
/// dict
///     ``pull_off_load_control`` (pi w R), ``jump_out_load``,
///     ``jump_out_interference``, ``jump_in_interference``,
///     ``contact_radius_zero_load``, ``nodes``.
#[pyfunction]
#[pyo3(name = "sphere", signature = (mu, rho = None, resolution = None, curve = None))]
pub fn sphere_py(
    py: Python<'_>,
    mu: f64,
    rho: Option<f64>,
    resolution: Option<f64>,
    curve: Option<PathBuf>,
) -> PyResult<Py<PyAny>> {
    let input = cmd::sphere::SphereInput {
        mu,
        rho,
        resolution,
        curve,
    };
    let out = guard::long(py, "sphere", &words(), || cmd::sphere::sphere(&input))?;
    serialised(py, &out, true)
}

/// The Greenwood–Tripp rough sphere (Hertz summits on Gaussian heights)
/// in Greenwood–Tripp units.
///
/// Parameters
/// ----------
/// mu : float
///     (8/3) eta sigma sqrt(2 R beta), > 0.
/// d : array_like
///     Central separations of the mean planes (units of sigma).
/// rho : array_like, optional
///     Radii r / sqrt(2 R sigma) >= 0 where the pressure is given.
/// tolerance : float, optional
///     Relative error of the load, in [1e-10, 1e-2] (default 1e-6).
/// errors : bool
///     Add each value's error estimate (keys ``*_error``).
/// out : str or os.PathLike, optional
///     Write charts (SVG) here.
///
/// Returns
/// -------
/// dict
///     ``states``: ``d``, ``load`` (E* sqrt(sigma/(8R)) 2R sigma),
///     ``central_deflection`` (sigma), ``pressure`` (``rho``, ``p``).
///
/// Examples
/// --------
/// >>> asperity.rough_sphere(10, [1, 0, -1], rho=[0, 0.5])
#[pyfunction]
#[pyo3(name = "rough_sphere", signature = (mu, d, rho = None, tolerance = None, errors = false, out = None))]
pub fn rough_sphere_py(
    py: Python<'_>,
    mu: f64,
    d: &Bound<'_, PyAny>,
    rho: Option<&Bound<'_, PyAny>>,
    tolerance: Option<f64>,
    errors: bool,
    out: Option<PathBuf>,
) -> PyResult<Py<PyAny>> {
    let input = cmd::rough_sphere::RoughSphereInput {
        mu,
        d: arrays::sequence(d, "d")?,
        rho: arrays::opt_sequence(rho, "rho")?.unwrap_or_default(),
        tolerance,
        errors,
        out,
    };
    let out = guard::long(py, "rough_sphere", &words(), || {
        cmd::rough_sphere::rough_sphere(&input)
    })?;
    serialised(py, &out, true)
}

/// Exact elastic contact of a height map by FFT boundary elements, beside
/// GW (from the map's moments) and Persson (from its radial spectrum) at
/// the same mean pressures.
///
/// Parameters
/// ----------
/// heights : array_like
///     A real, finite 2-D array of heights (m), at least 3 x 3: the rigid
///     rough surface.
/// pixel_size : float
///     Pixel size (m), the same along x and y.
/// estar : float
///     Contact modulus E* (Pa).
/// pressures : array_like, optional
///     Mean pressures (Pa), each > 0: load control.
/// gaps : array_like, optional
///     Mean gaps (m), each > 0: gap control (exactly one of the two).
/// periodic : bool
///     Treat the map as periodic (otherwise padded to twice its size).
/// adhesion_energy, adhesion_range : float, optional
///     w (J/m^2) and rho (m) of the interaction -w exp(-g/rho), together.
/// hardness : float, optional
///     Hardness H (Pa, > 0): the contact pressure is capped at H
///     (elastic-perfectly-plastic); each state then has
///     ``plastic_area_fraction``, ``plastic_volume_m3`` and
///     ``plastic_volume_per_area_m``. Mean pressures up to H; with an
///     adhesion (periodic maps) the compressive pressure capped at H.
/// gamma : float
///     Yang–Persson factor for Persson's mean gap, in [0, 1].
/// resistivity : float, optional
///     Ohm m: adds the contact resistance of the clusters and GW's.
/// tolerance : float
///     Solver residual, in [1e-15, 1e-2] (default 1e-10).
/// max_iterations : int
///     Most iterations per solve (default 10,000).
/// memory_limit_mib : float
///     Memory the solver may use (MiB, default 1024).
/// allow_unconverged : bool
///     A solve stopped at ``max_iterations`` gives its last iterate flagged
///     ``converged: False`` with a warning; otherwise it raises
///     ``RuntimeError`` with its residual (default False).
/// relative_humidity : float, optional
///     In (0, 1): adds ``capillary``, the flooded capillary attraction of
///     every state beside per-summit menisci on GW's summits, and the
///     regime h_m/u_rms.
/// surface_tension, contact_angle_1, contact_angle_2, temperature, molar_volume : float
///     The liquid (N/m, degrees, degrees, K, m^3/mol); default water at
///     293.15 K wetting both surfaces.
/// out : str or os.PathLike, optional
///     Write per-state .npy fields, bem.json and charts here.
///
/// Returns
/// -------
/// dict
///     ``states`` (``pressure_Pa``, ``mean_gap_m``, ``area_fraction``,
///     ``clusters``, ``iterations``, ``residual``, ``converged``, ...), ``gw`` and
///     ``persson`` at the same pressures, ``relative_differences``,
///     ``numerical_error``, ``model_error``, ``warnings``; with an adhesion
///     ``adhesion_criteria`` (Pastewka–Robbins with its validity,
///     Persson–Tosatti, the Tabor parameter at R = 1/h'', Müser's mu_rho).
///
/// Examples
/// --------
/// >>> h = numpy.load("examples/data/selfaffine-256.npy")
/// >>> asperity.bem(h, 3.90625e-7, 1e9, pressures=[1e6, 1e7], periodic=True)
#[pyfunction]
#[pyo3(name = "bem", signature = (heights, pixel_size, estar, pressures = None, gaps = None, periodic = false, adhesion_energy = None, adhesion_range = None, gamma = 1.0, resistivity = None, tolerance = 1e-10, max_iterations = 10_000, memory_limit_mib = 1024.0, out = None, allow_unconverged = false, relative_humidity = None, surface_tension = 0.0728, contact_angle_1 = 0.0, contact_angle_2 = 0.0, temperature = 293.15, molar_volume = 1.8e-5, hardness = None))]
#[allow(clippy::too_many_arguments)]
pub fn bem_py(
    py: Python<'_>,
    heights: &Bound<'_, PyAny>,
    pixel_size: f64,
    estar: f64,
    pressures: Option<&Bound<'_, PyAny>>,
    gaps: Option<&Bound<'_, PyAny>>,
    periodic: bool,
    adhesion_energy: Option<f64>,
    adhesion_range: Option<f64>,
    gamma: f64,
    resistivity: Option<f64>,
    tolerance: f64,
    max_iterations: usize,
    memory_limit_mib: f64,
    out: Option<PathBuf>,
    allow_unconverged: bool,
    relative_humidity: Option<f64>,
    surface_tension: f64,
    contact_angle_1: f64,
    contact_angle_2: f64,
    temperature: f64,
    molar_volume: f64,
    hardness: Option<f64>,
) -> PyResult<Py<PyAny>> {
    let targets = cmd::bem::BemTargets::from_options(
        arrays::opt_sequence(pressures, "pressures")?,
        arrays::opt_sequence(gaps, "gaps")?,
    );
    let mut input = cmd::bem::BemInput::new(pixel_size, estar, choice(targets)?);
    input.periodic = periodic;
    input.adhesion = choice(cmd::bem::BemAdhesion::from_options(
        adhesion_energy,
        adhesion_range,
    ))?;
    input.hardness = hardness;
    input.gamma = gamma;
    input.resistivity = resistivity;
    input.tolerance = tolerance;
    input.max_iterations = max_iterations;
    input.memory_limit_mib = memory_limit_mib;
    input.allow_unconverged = allow_unconverged;
    input.liquid = relative_humidity.map(|rh| cmd::wet_map::Liquid {
        relative_humidity: rh,
        surface_tension,
        contact_angle_1,
        contact_angle_2,
        temperature,
        molar_volume,
    });
    input.out = out;
    choice(input.validate())?;
    let map = arrays::height_map(heights, "heights")?;
    let out = guard::long(py, "bem", &words(), || cmd::bem::bem(&map?, &input))?;
    serialised(py, &out, true)
}

/// The heights of a map as the library receives them (row-major, the
/// array's shape): for the tests, which check that numbers arrive bit for
/// bit (no text in between).
#[pyfunction]
pub fn _heights_as_received<'py>(
    py: Python<'py>,
    heights: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let map = choice(arrays::height_map(heights, "heights")?)?;
    let shape = vec![map.rows(), map.cols()];
    let flat = PyArray::from_vec(py, map.heights().to_vec());
    Ok(flat.reshape(shape)?.into_any())
}
