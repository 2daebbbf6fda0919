//! Scenes from Python: `run`, `run_toml`, `default_scene`, `sweep`,
//! `scene_schema`. Each call plans and runs exactly as `asperity run` /
//! `asperity sweep` do, under [`crate::guard`] (GIL released, Ctrl-C
//! honoured, no panic crossing into Python).

use crate::arrays;
use crate::convert::{json_to_py, serialised, table_to_py};
use crate::guard;
use crate::scene_dict::scene_from_dict;
use asperity::commands::Vocabulary;
use asperity::study::sweep::{sweep_table, SweepOptions, DEFAULT_MAX_CPU_SECONDS};
use asperity::study::{
    check_outputs, curve_csv, montecarlo_csv, write_outputs, Column, Plan, PlanMode, Scene,
    Summary, Table, DEFAULT_STUDY,
};
use pyo3::exceptions::{PyRuntimeError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;

/// A scene and the directory its relative paths (a map) are read from.
struct Source {
    scene: Scene,
    base: PathBuf,
}

impl Source {
    /// A dict (the TOML structure, checked key by key) or a path to a TOML
    /// file (`str` or `os.PathLike`).
    fn from_py(scene: &Bound<'_, PyAny>) -> PyResult<Source> {
        let words = Vocabulary::python();
        if let Ok(d) = scene.cast::<PyDict>() {
            let scene = scene_from_dict(d)?.map_err(|e| guard::py_err(e, &words))?;
            return Ok(Source {
                scene,
                base: PathBuf::from("."),
            });
        }
        if scene.is_instance_of::<PyString>() || scene.hasattr("__fspath__")? {
            let path: PathBuf = scene.extract()?;
            // Without the GIL: the file may be a pipe another thread writes.
            let text = scene
                .py()
                .detach(|| std::fs::read_to_string(&path))
                .map_err(|e| {
                    PyValueError::new_err(format!("scene: cannot read {}: {e}", path.display()))
                })?;
            // A file's errors name its key and line, and the file.
            let scene = Scene::from_toml(&text).map_err(|e| {
                if e.is_bad_input() {
                    let text = format!("{} (scene {})", words.render(&e), path.display());
                    PyValueError::new_err(text)
                } else {
                    guard::py_err(e, &words)
                }
            })?;
            let base = path.parent().unwrap_or(Path::new(".")).to_path_buf();
            return Ok(Source { scene, base });
        }
        Err(PyTypeError::new_err(format!(
            "scene: expected a dict (the TOML structure) or a path (str or os.PathLike), got {}",
            scene.get_type().name()?
        )))
    }

    /// TOML text (relative paths from the current directory).
    fn from_toml(text: &str) -> PyResult<Source> {
        let scene = Scene::from_toml(text).map_err(|e| guard::py_err(e, &Vocabulary::python()))?;
        Ok(Source {
            scene,
            base: PathBuf::from("."),
        })
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
    let plan = results.plan(&plan).clone();
    let summary = Summary::new(&plan, &results);
    // Nothing half-written: an interrupted run stops before its files.
    asperity::cancel::check()?;
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

/// The result of a run: `summary`, `curve`, `montecarlo`, `states`,
/// `warnings` (see the attributes).
#[pyclass(frozen, module = "asperity", name = "RunResult")]
pub struct RunResult {
    /// The summary: the dict `asperity run SCENE --json` prints.
    #[pyo3(get)]
    summary: Py<PyAny>,
    /// `curve.csv` as a dict from column name to a NumPy array (SI units as
    /// in the names, e.g. `separation_m`, `load_N`; `leg` as str; NaN
    /// where a value is not computed).
    #[pyo3(get)]
    curve: Py<PyAny>,
    /// `montecarlo.csv` likewise, or None.
    #[pyo3(get)]
    montecarlo: Py<PyAny>,
    /// The scene's listed states (`[program] separations` or `loads`) as a
    /// list of dicts, or None.
    #[pyo3(get)]
    states: Py<PyAny>,
    /// The run's warnings (results outside a model's validity).
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

fn run_source(
    py: Python<'_>,
    name: &str,
    source: Source,
    out: Option<PathBuf>,
) -> PyResult<RunResult> {
    let outcome = guard::long(py, name, &Vocabulary::python(), || {
        execute(&source.scene, &source.base, out.as_deref())
    })?;
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

/// Run a scene as ``asperity run`` does: plan (law, methods, what is
/// skipped), compute the load–separation curve, pull-off, hysteresis,
/// populations, resistance and stiction the scene asks for.
///
/// Parameters
/// ----------
/// scene : dict or str or os.PathLike
///     A dict with the TOML structure of a scene file, or the path of a
///     TOML file (a map's path is then relative to the file's directory).
///     Sections: ``materials`` (e1, nu1, e2, nu2 in Pa and 1; yield_strength,
///     hardness in Pa), ``surface`` (density 1/m^2, radius m, sigma m,
///     distribution, nominal_area m^2, or topography = a map file),
///     ``adhesion`` (w J/m^2, z0 m), ``law`` (kind: auto, hertz, dmt, jkr,
///     maugis, cos, calibrated, kogut-etsion, ...), ``program``
///     (closest_separation m or max_load N or separations / loads, points),
///     ``outputs``, ``accuracy`` (rtol), and optionally ``montecarlo``,
///     ``electrical``, ``switch``, ``sphere``. Every key with its type,
///     unit, default and range: ``asperity.scene_schema()``; commented
///     examples: ``examples/scenes/*.toml``; the default study:
///     ``asperity.default_scene()``.
/// out : str or os.PathLike, optional
///     A directory for ``curve.csv``, ``summary.json`` and the SVG charts;
///     nothing is written without it.
///
/// Returns
/// -------
/// RunResult
///     ``.summary`` (the dict ``asperity run SCENE --json`` prints: e.g.
///     ``max_load`` N, ``pull_off_load`` N, ``warnings``, ``model_error``),
///     ``.curve`` (each ``curve.csv`` column as an array: ``separation_m``,
///     ``load_N``, ``area_m2``, ``contacts``, ``leg``), ``.montecarlo``,
///     ``.states``, ``.warnings``.
///
/// Raises
/// ------
/// ValueError
///     Bad input, naming the key path (``surface.sigma = -1e-09 is out of
///     range: ...``, ``surface.sigmaa: unknown key (did you mean
///     surface.sigma?)``).
/// MemoryError
///     A map or population beyond the memory available, with the estimate.
/// RuntimeError
///     A computation that failed (no convergence), a file not written.
/// KeyboardInterrupt
///     Ctrl-C: the run stops within a step; nothing is half-written.
///
/// Examples
/// --------
/// >>> scene = asperity.default_scene()
/// >>> scene["surface"]["sigma"] = 4e-9
/// >>> r = asperity.run(scene)
/// >>> r.summary["max_load"]          # N
#[pyfunction]
#[pyo3(signature = (scene, *, out = None))]
pub fn run(py: Python<'_>, scene: &Bound<'_, PyAny>, out: Option<PathBuf>) -> PyResult<RunResult> {
    let source = Source::from_py(scene)?;
    run_source(py, "run", source, out)
}

/// Run a scene given as TOML text (the text of a scene file; see
/// ``run``).
///
/// Parameters
/// ----------
/// text : str
///     The TOML text of a scene (sections and keys as in ``run``; every
///     key in ``asperity.scene_schema()``). Errors name the key and its
///     line in ``text``.
/// out : str or os.PathLike, optional
///     A directory for ``curve.csv``, ``summary.json`` and the charts.
///
/// Returns
/// -------
/// RunResult
///     As ``run``.
///
/// Examples
/// --------
/// >>> r = asperity.run_toml(open("examples/scenes/soft-jkr.toml").read())
#[pyfunction]
#[pyo3(signature = (text, *, out = None))]
pub fn run_toml(py: Python<'_>, text: String, out: Option<PathBuf>) -> PyResult<RunResult> {
    let source = Source::from_toml(&text)?;
    run_source(py, "run_toml", source, out)
}

/// The default study (``examples/scenes/rf-mems-switch.toml``, what a bare
/// ``asperity`` runs: a gold RF-MEMS switch) as a dict to edit and pass to
/// ``run`` or ``sweep``.
#[pyfunction]
pub fn default_scene(py: Python<'_>) -> PyResult<Py<PyAny>> {
    let value: toml::Value =
        toml::from_str(DEFAULT_STUDY).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    let json = serde_json::to_value(&value).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    json_to_py(py, &json)
}

/// The JSON Schema (draft 2020-12) of scene files and scene dicts: every
/// section and key with its type, unit (``x-unit``), default, range and
/// description, generated from the Rust scene types (the same as
/// ``asperity schema --json``).
///
/// Examples
/// --------
/// >>> s = asperity.scene_schema()
/// >>> s["$defs"]["SurfaceSpec"]["properties"]["sigma"]["x-unit"]
/// 'm'
/// >>> import jsonschema, tomllib
/// >>> jsonschema.validate(tomllib.load(open("examples/scenes/mems-gold.toml", "rb")), s)
#[pyfunction]
pub fn scene_schema(py: Python<'_>) -> PyResult<Py<PyAny>> {
    json_to_py(py, &asperity::study::scene::scene_schema())
}

/// Progress of a sweep on `sys.stderr`: a line rewritten in place on a
/// terminal (or notebook), otherwise a line every 10 % or 10 s.
struct Progress {
    start: Instant,
    last: f64,
    last_done: usize,
    terminal: bool,
    estimate_said: bool,
}

impl Progress {
    fn new(py: Python<'_>) -> Progress {
        let terminal = py
            .import("sys")
            .and_then(|sys| sys.getattr("stderr"))
            .and_then(|e| e.call_method0("isatty"))
            .and_then(|t| t.extract::<bool>())
            .unwrap_or_else(|_| std::io::stderr().is_terminal());
        Progress {
            start: Instant::now(),
            last: 0.0,
            last_done: 0,
            terminal,
            estimate_said: false,
        }
    }

    fn write(py: Python<'_>, text: &str) -> PyResult<()> {
        let err = py.import("sys")?.getattr("stderr")?;
        err.call_method1("write", (text,))?;
        err.call_method0("flush")?;
        Ok(())
    }

    fn show(&mut self, py: Python<'_>, done: usize, total: usize, end: bool) -> PyResult<()> {
        let t = self.start.elapsed().as_secs_f64();
        if done >= 1 && !self.estimate_said && total > 1 {
            self.estimate_said = true;
            let rest = (total - done) as f64;
            Self::write(
                py,
                &format!(
                    "sweep: {total} points; the first took {t:.3} s, the {} others an estimated \
                     {:.3e} s of CPU\n",
                    total - done,
                    t / done as f64 * rest
                ),
            )?;
        }
        let every = if self.terminal { 0.2 } else { 10.0 };
        let step = (total / 10).max(1);
        let due =
            end || t - self.last >= every || (!self.terminal && done >= self.last_done + step);
        if !due || done == self.last_done && !end {
            return Ok(());
        }
        self.last = t;
        self.last_done = done;
        let rate = done as f64 / t.max(1e-9);
        let eta = if done > 0 {
            format!("{:.0} s", (total - done) as f64 / rate)
        } else {
            "-".into()
        };
        let line = format!(
            "sweep: {done}/{total} points ({:.0} %), {rate:.3} points/s, ETA {eta}",
            100.0 * done as f64 / total.max(1) as f64
        );
        if self.terminal {
            Self::write(py, &format!("\r{line}   {}", if end { "\n" } else { "" }))
        } else {
            Self::write(py, &format!("{line}\n"))
        }
    }
}

/// The rows finished since the last tick, for `callback=`.
#[derive(Default)]
struct Finished {
    header: String,
    rows: Vec<String>,
}

/// A grid over every combination of the given values of scene fields (the
/// first varies slowest), run in parallel as ``asperity sweep`` runs its
/// points: each point's numbers equal ``run`` on the same scene.
///
/// Parameters
/// ----------
/// scene : dict or str or os.PathLike
///     The base scene (see ``run``).
/// vary : dict
///     ``{"dotted.scene.path": values}``, e.g. ``{"surface.sigma":
///     numpy.linspace(2e-9, 8e-9, 6)}`` (each value in the field's unit).
/// threads : int, optional
///     Worker threads, >= 1 (default: one per core).
/// seed : int
///     Base seed of the points' Monte Carlo populations.
/// max_cpu_seconds : float
///     Most CPU time (s) the sweep may take, estimated from its first
///     point's time (the first point runs alone); beyond it ``ValueError``
///     names the estimate. Default one CPU-day.
/// progress : bool
///     Show progress on ``sys.stderr``: the estimate after the first
///     point, then points done, rate and ETA.
/// callback : callable, optional
///     Called with each finished row as a dict (the keys of the result
///     table), in the order the points finish; an exception it raises
///     stops the sweep and is raised.
///
/// Returns
/// -------
/// dict
///     ``results.csv``'s columns as arrays: ``index``, the varied paths,
///     ``seed``, ``status`` ("ok" or the error), and the result columns
///     (``max_load_N``, ``pull_off_N``, ...; NaN where a point failed).
///
/// Raises
/// ------
/// ValueError
///     A bad path or value (naming it), an estimate beyond
///     ``max_cpu_seconds``.
/// RuntimeError
///     Every point failed.
/// KeyboardInterrupt
///     Ctrl-C: the sweep stops within a point.
///
/// Examples
/// --------
/// >>> t = asperity.sweep("examples/scenes/mems-gold.toml",
/// ...                    {"surface.sigma": [2e-9, 4e-9, 8e-9]}, progress=True)
/// >>> t["pull_off_N"]                # N, one per point
#[pyfunction]
#[pyo3(signature = (scene, vary, threads = None, *, seed = 0, max_cpu_seconds = DEFAULT_MAX_CPU_SECONDS, progress = false, callback = None))]
#[allow(clippy::too_many_arguments)]
pub fn sweep(
    py: Python<'_>,
    scene: &Bound<'_, PyAny>,
    vary: &Bound<'_, PyDict>,
    threads: Option<usize>,
    seed: u64,
    max_cpu_seconds: f64,
    progress: bool,
    callback: Option<Py<PyAny>>,
) -> PyResult<Py<PyAny>> {
    let source = Source::from_py(scene)?;
    let mut fields: Vec<(String, Vec<f64>)> = Vec::new();
    for (k, v) in vary.iter() {
        let path: String = k
            .extract()
            .map_err(|_| PyValueError::new_err("vary: keys must be dotted scene paths (str)"))?;
        let values = arrays::sequence(&v, &format!("vary[{path:?}]"))?;
        fields.push((path, values));
    }
    if threads == Some(0) {
        return Err(PyValueError::new_err("threads = 0: give at least 1"));
    }
    asperity::error::positive(
        &asperity::commands::param("max_cpu_seconds"),
        max_cpu_seconds,
    )
    .map_err(|e| guard::py_err(e, &Vocabulary::python()))?;
    if let Some(c) = &callback {
        if !c.bind(py).is_callable() {
            return Err(PyTypeError::new_err(
                "callback: expected a callable taking a dict",
            ));
        }
    }
    let done = AtomicUsize::new(0);
    let total = AtomicUsize::new(0);
    let finished = Mutex::new(Finished::default());
    let want_rows = callback.is_some();
    let mut shown = progress.then(|| Progress::new(py));
    let table = guard::watched(
        py,
        "sweep",
        &Vocabulary::python(),
        || {
            let mut options = SweepOptions::default();
            options.threads = threads;
            options.max_cpu_seconds = Some(max_cpu_seconds);
            sweep_table(
                &source.scene,
                &fields,
                seed,
                &options,
                &|d, t, header, row| {
                    done.store(d, Ordering::Relaxed);
                    total.store(t, Ordering::Relaxed);
                    if want_rows {
                        if let Ok(mut f) = finished.lock() {
                            if f.header.is_empty() {
                                f.header = header.to_string();
                            }
                            f.rows.push(row.to_string());
                        }
                    }
                },
            )
        },
        |py| {
            let (d, t) = (done.load(Ordering::Relaxed), total.load(Ordering::Relaxed));
            if let Some(p) = shown.as_mut() {
                if t > 0 {
                    p.show(py, d, t, d == t)?;
                }
            }
            if let Some(c) = &callback {
                let batch = match finished.lock() {
                    Ok(mut f) => {
                        let rows = std::mem::take(&mut f.rows);
                        (f.header.clone(), rows)
                    }
                    Err(_) => (String::new(), Vec::new()),
                };
                for row in batch.1 {
                    let one = Table::from_csv(&format!("{}\n{row}\n", batch.0));
                    let d = crate::convert::row_to_py(py, &one)?;
                    c.bind(py).call1((d,))?;
                }
            }
            Ok(())
        },
    )?;
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
