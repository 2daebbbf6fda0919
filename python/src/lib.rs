//! The Python package `asperity` (module `asperity._asperity`): a thin
//! layer over the library's typed command API (`asperity::commands`) and
//! its scenes. Arguments become typed inputs directly (arrays as slices, no
//! text in between); every call runs under `guard` (the GIL released,
//! Ctrl-C honoured, no panic crossing into Python, errors in Python's
//! words); arrays are checked and copied once (`arrays`); scene dicts are
//! checked key by key against the scene schema (`scene_dict`).

mod arrays;
mod commands;
mod convert;
mod guard;
mod scene;
mod scene_dict;

use pyo3::prelude::*;

#[pymodule]
fn _asperity(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", asperity::VERSION)?;
    m.add_class::<scene::RunResult>()?;
    m.add_function(wrap_pyfunction!(scene::run, m)?)?;
    m.add_function(wrap_pyfunction!(scene::run_toml, m)?)?;
    m.add_function(wrap_pyfunction!(scene::default_scene, m)?)?;
    m.add_function(wrap_pyfunction!(scene::scene_schema, m)?)?;
    m.add_function(wrap_pyfunction!(scene::sweep, m)?)?;
    m.add_function(wrap_pyfunction!(commands::law_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::heating_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::spots_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::surface_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::read_topography_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::fn_values, m)?)?;
    m.add_function(wrap_pyfunction!(commands::shape_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::punch_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::punch_fit_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::persson_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::sphere_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::rough_sphere_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::bem_py, m)?)?;
    m.add_function(wrap_pyfunction!(commands::_heights_as_received, m)?)?;
    Ok(())
}
