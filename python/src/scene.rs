//! Scenes from Python: `run`, `run_toml`, `default_scene`, `sweep`. Each
//! call plans and runs exactly as `asperity run` / `asperity sweep` do,
//! with the GIL released while the library computes.

use crate::convert::{json_to_py, lib_err, serialised, table_to_py, to_toml};
use asperity::study::sweep::{sweep_table, SweepOptions};
use asperity::study::{
    check_outputs, curve_csv, montecarlo_csv, write_outputs, Column, Plan, PlanMode, Scene,
    Summary, Table, DEFAULT_STUDY,
};
use numpy::{AllowTypeChange, PyArrayLike1};
use pyo3::exceptions::{PyRuntimeError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use std::path::{Path, PathBuf};

/// Where a scene comes from: TOML text (with the directory its relative
/// paths are read from) or a file.
enum Source {
    Text(String, PathBuf),
    File(PathBuf),
}

impl Source {
    /// A dict (the TOML structure) or a path (`str` or `os.PathLike`).
    fn from_py(scene: &Bound<'_, PyAny>) -> PyResult<Source> {
        if scene.is_instance_of::<PyDict>() {
            let value = to_toml(scene, "")?;
            let text = toml::to_string(&value)
                .map_err(|e| PyValueError::new_err(format!("scene: {e}")))?;
            return Ok(Source::Text(text, PathBuf::from(".")));
        }
        if scene.is_instance_of::<PyString>() || scene.hasattr("__fspath__")? {
            let path: PathBuf = scene.extract()?;
            return Ok(Source::File(path));
        }
        Err(PyTypeError::new_err(
            "scene: expected a dict (the TOML structure) or a path (str or os.PathLike)",
        ))
    }

    /// The scene's text and the directory of its relative paths; errors
    /// as the command line's (`scene: cannot read ...`).
    fn text(&self) -> asperity::Result<(String, PathBuf)> {
        match self {
            Source::Text(t, base) => Ok((t.clone(), base.clone())),
            Source::File(path) => {
                let text = std::fs::read_to_string(path).map_err(|e| {
                    asperity::Error::invalid(
                        "scene",
                        format!("cannot read {}: {e}", path.display()),
                    )
                })?;
                let base = path.parent().unwrap_or(Path::new(".")).to_path_buf();
                Ok((text, base))
            }
        }
    }
}

/// Where a run failed: parsing the scene (a file's bad input then names
/// the file, as `asperity run` and `asperity sweep` do) or anywhere else.
enum Stage {
    Parse(asperity::Error),
    Other(asperity::Error),
}

impl Stage {
    fn into_py(self, source: &Source) -> PyErr {
        match (self, source) {
            (Stage::Parse(e), Source::File(path)) if e.is_bad_input() => {
                PyValueError::new_err(format!("{e} (scene {})", path.display()))
            }
            (Stage::Parse(e) | Stage::Other(e), _) => lib_err(e),
        }
    }
}

/// What a run gives, before it becomes Python objects.
struct Outcome {
    summary: Summary,
    curve: Table,
    montecarlo: Option<Table>,
}

/// Plans and runs a scene as `asperity run` does (the map's path relative
/// to `base`), writing the files only into `out` when given.
fn execute(scene: &Scene, base: &Path, out: Option<&Path>) -> asperity::Result<Outcome> {
    let plan = if scene.surface.topography.is_some() {
        Plan::new_in(scene, PlanMode::Planned, base)?
    } else {
        Plan::new(scene, PlanMode::Planned)?
    };
    let results = plan.run()?;
    let summary = Summary::new(&plan, &results);
    // The CLI always writes its files, refusing non-finite results first;
    // without out= the same refusal.
    match out {
        Some(dir) => {
            write_outputs(&plan, &results, &summary, dir)?;
        }
        None => check_outputs(&plan, &results, &summary)?,
    }
    Ok(Outcome {
        curve: Table::from_csv(&curve_csv(&results, &plan)),
        montecarlo: montecarlo_csv(&results, &plan).map(|t| Table::from_csv(&t)),
        summary,
    })
}

/// The result of a run.
#[pyclass(frozen, module = "asperity", name = "RunResult")]
pub struct RunResult {
    /// The summary: the dict `asperity run SCENE --json` prints.
    #[pyo3(get)]
    summary: Py<PyAny>,
    /// `curve.csv` as a dict from column name to a NumPy array.
    #[pyo3(get)]
    curve: Py<PyAny>,
    /// `montecarlo.csv` likewise, or None.
    #[pyo3(get)]
    montecarlo: Py<PyAny>,
    /// The listed states as a list of dicts, or None.
    #[pyo3(get)]
    states: Py<PyAny>,
    /// The run's warnings.
    #[pyo3(get)]
    warnings: Py<PyAny>,
}

#[pymethods]
impl RunResult {
    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        let title = self.summary.bind(py).get_item("title")?;
        Ok(format!("RunResult(title={})", title.repr()?))
    }
}

fn run_source(py: Python<'_>, source: Source, out: Option<PathBuf>) -> PyResult<RunResult> {
    let outcome = py
        .detach(|| {
            let (text, base) = source.text().map_err(Stage::Other)?;
            let scene = Scene::from_toml(&text).map_err(Stage::Parse)?;
            execute(&scene, &base, out.as_deref()).map_err(Stage::Other)
        })
        .map_err(|e| e.into_py(&source))?;
    let summary = serialised(py, &outcome.summary, false)?;
    Ok(RunResult {
        states: serialised(py, &outcome.summary.states, false)?,
        warnings: serialised(py, &outcome.summary.warnings, false)?,
        summary,
        curve: table_to_py(py, &outcome.curve)?,
        montecarlo: match &outcome.montecarlo {
            Some(t) => table_to_py(py, t)?,
            None => py.None(),
        },
    })
}

/// Runs a scene: a dict with the TOML structure or a path to a TOML file.
#[pyfunction]
#[pyo3(signature = (scene, *, out = None))]
pub fn run(py: Python<'_>, scene: &Bound<'_, PyAny>, out: Option<PathBuf>) -> PyResult<RunResult> {
    let source = Source::from_py(scene)?;
    run_source(py, source, out)
}

/// Runs a scene given as TOML text.
#[pyfunction]
#[pyo3(signature = (text, *, out = None))]
pub fn run_toml(py: Python<'_>, text: String, out: Option<PathBuf>) -> PyResult<RunResult> {
    run_source(py, Source::Text(text, PathBuf::from(".")), out)
}

/// The default study (`examples/scenes/rf-mems-switch.toml`, what a bare
/// `asperity` runs) as a dict.
#[pyfunction]
pub fn default_scene(py: Python<'_>) -> PyResult<Py<PyAny>> {
    let value: toml::Value =
        toml::from_str(DEFAULT_STUDY).map_err(|e| PyValueError::new_err(e.to_string()))?;
    let json = serde_json::to_value(&value).map_err(|e| PyValueError::new_err(e.to_string()))?;
    json_to_py(py, &json)
}

/// A grid sweep over the given values of dotted scene paths.
#[pyfunction]
#[pyo3(signature = (scene, vary, threads = None, *, seed = 0))]
pub fn sweep(
    py: Python<'_>,
    scene: &Bound<'_, PyAny>,
    vary: &Bound<'_, PyDict>,
    threads: Option<usize>,
    seed: u64,
) -> PyResult<Py<PyAny>> {
    let source = Source::from_py(scene)?;
    let mut fields: Vec<(String, Vec<f64>)> = Vec::new();
    for (k, v) in vary.iter() {
        let path: String = k
            .extract()
            .map_err(|_| PyValueError::new_err("vary: keys must be dotted scene paths (str)"))?;
        let values: PyArrayLike1<'_, f64, AllowTypeChange> = v.extract().map_err(|_| {
            PyValueError::new_err(format!("vary: {path}: expected a sequence of numbers"))
        })?;
        fields.push((path, values.as_array().to_vec()));
    }
    if threads == Some(0) {
        return Err(PyValueError::new_err("threads = 0: give at least 1"));
    }
    let table = py
        .detach(|| {
            let (text, _) = source.text().map_err(Stage::Other)?;
            let scene = Scene::from_toml(&text).map_err(Stage::Parse)?;
            let mut options = SweepOptions::default();
            options.threads = threads;
            sweep_table(&scene, &fields, seed, &options).map_err(Stage::Other)
        })
        .map_err(|e| e.into_py(&source))?;
    // As `asperity sweep`: a sweep that produced no result at all is a
    // failure (exit 1 there), naming the first point's error.
    if let Some(Column::Text(status)) = table.get("status") {
        if !status.is_empty() && status.iter().all(|s| s != "ok") {
            return Err(PyRuntimeError::new_err(format!(
                "every one of the {} points failed (first, point 0: {})",
                status.len(),
                status[0]
            )));
        }
    }
    table_to_py(py, &table)
}
