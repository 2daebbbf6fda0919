//! The Python package `asperity` (module `asperity._asperity`): a thin
//! layer over the library. Scenes run as `asperity run` runs them, the JSON
//! subcommands are functions with their flags as keyword arguments, and
//! every call releases the GIL while the library computes. Bad input raises
//! `ValueError` with the command line's message (naming the field or
//! flag); every other failure `RuntimeError`.

mod commands;
mod convert;
mod scene;

use pyo3::prelude::*;

#[pymodule]
fn _asperity(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", asperity::VERSION)?;
    m.add_class::<scene::RunResult>()?;
    m.add_function(wrap_pyfunction!(scene::run, m)?)?;
    m.add_function(wrap_pyfunction!(scene::run_toml, m)?)?;
    m.add_function(wrap_pyfunction!(scene::default_scene, m)?)?;
    m.add_function(wrap_pyfunction!(scene::sweep, m)?)?;
    m.add_function(wrap_pyfunction!(commands::law_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::heating_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::spots_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::surface_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::fn_values, m)?)?;
    m.add_function(wrap_pyfunction!(commands::shape_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::punch_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::punch_fit_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::persson_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::sphere_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::rough_sphere_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::bem_py, m)?)?;
    Ok(())
}
