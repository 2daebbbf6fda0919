//! The JSON subcommands as functions: keyword arguments named as the flags
//! (dashes to underscores, `--lambda` as `lambda_`), list flags as
//! sequences or arrays, results as the dict `asperity X ... --json` prints
//! with lists of numbers as NumPy arrays. Each calls
//! `asperity::commands::X` with the GIL released.

use crate::convert::{cmd_err, serialised};
use asperity::commands::{self as cmd, CommandResult};
use asperity::surface::HeightMap;
use numpy::{AllowTypeChange, PyArray, PyArrayLike1, PyArrayLike2, PyArrayLikeDyn, PyArrayMethods};
use pyo3::prelude::*;
use std::path::PathBuf;

/// A sequence or array of numbers as the comma-separated text of a list
/// flag (each number in Rust's shortest round-trip form, so the command
/// reads back the same doubles).
pub fn list_text(values: &PyArrayLike1<'_, f64, AllowTypeChange>) -> String {
    values
        .as_array()
        .iter()
        .map(|x| format!("{x:?}"))
        .collect::<Vec<_>>()
        .join(",")
}

/// Runs a command without the GIL and converts its output.
pub fn call<T, F>(py: Python<'_>, f: F) -> PyResult<Py<PyAny>>
where
    T: serde::Serialize + Send,
    F: FnOnce() -> CommandResult<T> + Send,
{
    let out = py.detach(f).map_err(cmd_err)?;
    serialised(py, &out, true)
}

/// `asperity law --law LAW [--lambda L] --json`.
#[pyfunction]
#[pyo3(name = "law", signature = (law, lambda_ = None))]
pub fn law_py(py: Python<'_>, law: String, lambda_: Option<f64>) -> PyResult<Py<PyAny>> {
    let args = cmd::law::LawArgs {
        law,
        lambda: lambda_,
        json: true,
    };
    call(py, || cmd::law::run(&args))
}

/// `asperity heating --voltage U | --max-temperature T [--bulk-temperature T0]
/// [--softening-temperature Ts] [--melting-temperature Tm] --json`.
#[pyfunction]
#[pyo3(name = "heating", signature = (
    voltage = None,
    max_temperature = None,
    bulk_temperature = asperity::electrical::heating::DEFAULT_BULK_TEMPERATURE,
    softening_temperature = asperity::electrical::heating::GOLD_SOFTENING_TEMPERATURE,
    melting_temperature = asperity::electrical::heating::GOLD_MELTING_TEMPERATURE
))]
pub fn heating_py(
    py: Python<'_>,
    voltage: Option<f64>,
    max_temperature: Option<f64>,
    bulk_temperature: f64,
    softening_temperature: f64,
    melting_temperature: f64,
) -> PyResult<Py<PyAny>> {
    let args = cmd::heating::HeatingArgs {
        voltage,
        max_temperature,
        bulk_temperature,
        softening_temperature,
        melting_temperature,
        json: true,
    };
    call(py, || cmd::heating::run(&args).map(|(out, _)| out))
}

/// `asperity spots` on spots given as arrays (m).
#[pyfunction]
#[pyo3(name = "spots", signature = (x, y, radius, resistivity, mean_free_path = None))]
pub fn spots_py(
    py: Python<'_>,
    x: PyArrayLike1<'_, f64, AllowTypeChange>,
    y: PyArrayLike1<'_, f64, AllowTypeChange>,
    radius: PyArrayLike1<'_, f64, AllowTypeChange>,
    resistivity: f64,
    mean_free_path: Option<f64>,
) -> PyResult<Py<PyAny>> {
    let (x, y, r) = (
        x.as_array().to_vec(),
        y.as_array().to_vec(),
        radius.as_array().to_vec(),
    );
    call(py, move || {
        let spot = cmd::spots::spot_resistance(resistivity, mean_free_path)?;
        let s = cmd::spots::from_columns(x, y, r)?;
        cmd::spots::resistances(&s, &spot)
    })
}

/// `asperity surface` on a height map given as a 2-D array (m).
#[pyfunction]
#[pyo3(name = "surface", signature = (heights, pixel_size, periodic = false, estar = None, hardness = None))]
pub fn surface_py(
    py: Python<'_>,
    heights: PyArrayLike2<'_, f64, AllowTypeChange>,
    pixel_size: f64,
    periodic: bool,
    estar: Option<f64>,
    hardness: Option<f64>,
) -> PyResult<Py<PyAny>> {
    let view = heights.as_array();
    let (rows, cols) = view.dim();
    let values: Vec<f64> = view.iter().copied().collect();
    call(py, move || {
        asperity::error::positive("--pixel-size", pixel_size)?;
        let map = HeightMap::new(rows, cols, values).map_err(|e| e.renamed("heights"))?;
        cmd::surface::characterise(map, "heights", pixel_size, periodic, estar, hardness)
            .map(|(out, _)| out)
    })
}

/// `F_n(h)` of a distribution at every `h`, in the shape of `h`.
#[pyfunction]
#[pyo3(name = "fn")]
pub fn fn_values<'py>(
    py: Python<'py>,
    dist: String,
    n: f64,
    h: PyArrayLikeDyn<'py, f64, AllowTypeChange>,
) -> PyResult<Bound<'py, PyAny>> {
    let view = h.as_array();
    let shape: Vec<usize> = view.shape().to_vec();
    // A copy (memcpy when contiguous), so no Python thread can change the
    // values while the GIL is released.
    let hs: Vec<f64> = match view.as_slice() {
        Some(s) => s.to_vec(),
        None => view.iter().copied().collect(),
    };
    let values = py
        .detach(|| cmd::fn_::values(&dist, n, &hs))
        .map_err(cmd_err)?;
    let flat = PyArray::from_vec(py, values);
    Ok(flat.reshape(shape)?.into_any())
}

/// A list flag given as a sequence or array, as its text (None stays None).
fn opt_list(values: Option<PyArrayLike1<'_, f64, AllowTypeChange>>) -> Option<String> {
    values.as_ref().map(list_text)
}

/// Runs a command that reports (`asperity::commands::Report`) without the
/// GIL; its JSON as Python objects (lists of numbers as NumPy arrays).
fn report<F>(py: Python<'_>, f: F) -> PyResult<Py<PyAny>>
where
    F: FnOnce() -> CommandResult<cmd::Report> + Send,
{
    let r = py.detach(f).map_err(cmd_err)?;
    serialised(py, &r.json, true)
}

/// `asperity shape ... --json`.
#[pyfunction]
#[pyo3(name = "shape", signature = (profile, estar, w, radius = None, tan_angle = None, exponent = None, coefficient = None, radii = None, stress = None))]
#[allow(clippy::too_many_arguments)]
pub fn shape_py(
    py: Python<'_>,
    profile: String,
    estar: f64,
    w: f64,
    radius: Option<f64>,
    tan_angle: Option<f64>,
    exponent: Option<f64>,
    coefficient: Option<f64>,
    radii: Option<PyArrayLike1<'_, f64, AllowTypeChange>>,
    stress: Option<f64>,
) -> PyResult<Py<PyAny>> {
    let args = cmd::shape::ShapeArgs {
        profile,
        radius,
        tan_angle,
        exponent,
        coefficient,
        estar,
        w,
        radii: opt_list(radii),
        stress,
        json: true,
    };
    report(py, || cmd::shape::run(&args))
}

/// `asperity punch ... --json`; `cycle` is `(hmin, hmax)` in m.
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
    radii: Option<PyArrayLike1<'_, f64, AllowTypeChange>>,
    depths: Option<PyArrayLike1<'_, f64, AllowTypeChange>>,
    cycle: Option<PyArrayLike1<'_, f64, AllowTypeChange>>,
) -> PyResult<Py<PyAny>> {
    let cycle = cycle.map(|c| {
        c.as_array()
            .iter()
            .map(|x| format!("{x:?}"))
            .collect::<Vec<_>>()
            .join(":")
    });
    let args = cmd::punch::PunchArgs {
        estar,
        w,
        radius,
        amplitude,
        wavelength,
        radii: opt_list(radii),
        depths: opt_list(depths),
        cycle,
        json: true,
    };
    report(py, || cmd::punch::run(&args))
}

/// `asperity punch-fit DATA.csv --radius R --json` on columns: `phase`
/// (`"loading"`/`"unloading"`), contact radii `radius` (m), loads `load`
/// (N); `punch_radius` is the punch's radius of curvature (m).
#[pyfunction]
#[pyo3(name = "punch_fit", signature = (phase, radius, load, punch_radius))]
pub fn punch_fit_py(
    py: Python<'_>,
    phase: Vec<String>,
    radius: PyArrayLike1<'_, f64, AllowTypeChange>,
    load: PyArrayLike1<'_, f64, AllowTypeChange>,
    punch_radius: f64,
) -> PyResult<Py<PyAny>> {
    let (radius, load) = (radius.as_array().to_vec(), load.as_array().to_vec());
    report(py, move || {
        let data = cmd::punch::fit_points(&phase, &radius, &load)?;
        cmd::punch::fit(&data, punch_radius, "punch_radius", "data")
    })
}

/// `asperity persson ... --json`.
#[pyfunction]
#[pyo3(name = "persson", signature = (hurst, q_long, q_roll, q_short, estar, pressures, h_rms = None, slope_rms = None, gamma = 1.0, adhesion_energy = None))]
#[allow(clippy::too_many_arguments)]
pub fn persson_py(
    py: Python<'_>,
    hurst: f64,
    q_long: f64,
    q_roll: f64,
    q_short: f64,
    estar: f64,
    pressures: PyArrayLike1<'_, f64, AllowTypeChange>,
    h_rms: Option<f64>,
    slope_rms: Option<f64>,
    gamma: f64,
    adhesion_energy: Option<f64>,
) -> PyResult<Py<PyAny>> {
    let args = cmd::persson::PerssonArgs {
        hurst,
        q_long,
        q_roll,
        q_short,
        h_rms,
        slope_rms,
        estar,
        pressures: list_text(&pressures),
        gamma,
        adhesion_energy,
        json: true,
    };
    report(py, || cmd::persson::run(&args))
}

/// `asperity sphere --mu MU [--rho RHO] [--resolution X] [--curve FILE] --json`.
#[pyfunction]
#[pyo3(name = "sphere", signature = (mu, rho = None, resolution = None, curve = None))]
pub fn sphere_py(
    py: Python<'_>,
    mu: f64,
    rho: Option<f64>,
    resolution: Option<f64>,
    curve: Option<PathBuf>,
) -> PyResult<Py<PyAny>> {
    let args = cmd::sphere::SphereArgs {
        mu,
        rho,
        resolution,
        json: true,
        curve,
    };
    report(py, || cmd::sphere::run(&args))
}

/// `asperity rough-sphere --mu MU --d D,.. [--rho R,..] [--tolerance T] [--errors] [--out DIR] --json`.
#[pyfunction]
#[pyo3(name = "rough_sphere", signature = (mu, d, rho = None, tolerance = None, errors = false, out = None))]
pub fn rough_sphere_py(
    py: Python<'_>,
    mu: f64,
    d: PyArrayLike1<'_, f64, AllowTypeChange>,
    rho: Option<PyArrayLike1<'_, f64, AllowTypeChange>>,
    tolerance: Option<f64>,
    errors: bool,
    out: Option<PathBuf>,
) -> PyResult<Py<PyAny>> {
    let args = cmd::rough_sphere::RoughSphereArgs {
        mu,
        d: list_text(&d),
        rho: opt_list(rho),
        tolerance,
        json: true,
        errors,
        out,
    };
    report(py, || cmd::rough_sphere::run(&args))
}

/// `asperity bem MAP ... --json` on a height map given as a 2-D array (m).
#[pyfunction]
#[pyo3(name = "bem", signature = (heights, pixel_size, estar, pressures = None, gaps = None, periodic = false, adhesion_energy = None, adhesion_range = None, gamma = 1.0, resistivity = None, tolerance = 1e-10, max_iterations = 10_000, memory_limit_mib = 1024.0, out = None))]
#[allow(clippy::too_many_arguments)]
pub fn bem_py(
    py: Python<'_>,
    heights: PyArrayLike2<'_, f64, AllowTypeChange>,
    pixel_size: f64,
    estar: f64,
    pressures: Option<PyArrayLike1<'_, f64, AllowTypeChange>>,
    gaps: Option<PyArrayLike1<'_, f64, AllowTypeChange>>,
    periodic: bool,
    adhesion_energy: Option<f64>,
    adhesion_range: Option<f64>,
    gamma: f64,
    resistivity: Option<f64>,
    tolerance: f64,
    max_iterations: usize,
    memory_limit_mib: f64,
    out: Option<PathBuf>,
) -> PyResult<Py<PyAny>> {
    let view = heights.as_array();
    let (rows, cols) = view.dim();
    let values: Vec<f64> = view.iter().copied().collect();
    let args = cmd::bem::BemArgs {
        map: PathBuf::from("heights"),
        pixel_size,
        scale: 1.0,
        estar,
        pressures: opt_list(pressures),
        gaps: opt_list(gaps),
        periodic,
        adhesion_energy,
        adhesion_range,
        gamma,
        resistivity,
        tolerance,
        max_iterations,
        memory_limit_mib,
        out,
        json: true,
    };
    report(py, move || {
        let map = HeightMap::new(rows, cols, values).map_err(|e| e.renamed("heights"))?;
        cmd::bem::run_map(&args, Some((map, "heights")))
    })
}
