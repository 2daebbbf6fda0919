//! Values between Python and the library: scene dicts to TOML, JSON and
//! TOML values to Python objects, tables to NumPy arrays, errors to
//! exceptions. No physics here.

use asperity::commands::CommandError;
use asperity::study::{Column, Table};
use numpy::{PyArray1, ToPyArray};
use pyo3::exceptions::{PyRuntimeError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use serde_json::Value;

/// Bad input as `ValueError`, every other failure as `RuntimeError`; the
/// message is the command line's.
pub fn lib_err(e: asperity::Error) -> PyErr {
    if e.is_bad_input() {
        PyValueError::new_err(e.to_string())
    } else {
        PyRuntimeError::new_err(e.to_string())
    }
}

/// A command's failure as `ValueError` (bad input) or `RuntimeError`.
pub fn cmd_err(e: CommandError) -> PyErr {
    match e {
        CommandError::Usage(m) => PyValueError::new_err(m),
        CommandError::Failed(m) => PyRuntimeError::new_err(m),
    }
}

/// A Python value (dict, list, tuple, str, bool, int, float or a NumPy
/// scalar or array) as a TOML value; `at` is its dotted path for errors.
pub fn to_toml(obj: &Bound<'_, PyAny>, at: &str) -> PyResult<toml::Value> {
    if let Ok(d) = obj.cast::<PyDict>() {
        let mut table = toml::map::Map::new();
        for (k, v) in d.iter() {
            let key: String = k
                .extract()
                .map_err(|_| PyValueError::new_err(format!("{at}: keys must be str, got {k:?}")))?;
            let path = if at.is_empty() {
                key.clone()
            } else {
                format!("{at}.{key}")
            };
            if v.is_none() {
                continue; // None means "not given", as a missing key.
            }
            table.insert(key, to_toml(&v, &path)?);
        }
        return Ok(toml::Value::Table(table));
    }
    if obj.is_instance_of::<PyBool>() {
        return Ok(toml::Value::Boolean(obj.extract()?));
    }
    if obj.is_instance_of::<PyString>() {
        return Ok(toml::Value::String(obj.extract()?));
    }
    if obj.is_instance_of::<PyInt>() {
        let i: i64 = obj.extract()?;
        return Ok(toml::Value::Integer(i));
    }
    if obj.is_instance_of::<PyFloat>() {
        return Ok(toml::Value::Float(obj.extract()?));
    }
    if obj.is_instance_of::<PyList>() || obj.is_instance_of::<PyTuple>() {
        let items = obj
            .try_iter()?
            .enumerate()
            .map(|(i, v)| to_toml(&v?, &format!("{at}[{i}]")))
            .collect::<PyResult<Vec<_>>>()?;
        return Ok(toml::Value::Array(items));
    }
    // NumPy scalars and arrays, os.PathLike: through their Python value.
    if obj.hasattr("tolist")? {
        return to_toml(&obj.call_method0("tolist")?, at);
    }
    if obj.hasattr("__fspath__")? {
        return to_toml(&obj.call_method0("__fspath__")?, at);
    }
    Err(PyTypeError::new_err(format!(
        "{at}: cannot put a {} into a scene",
        obj.get_type().name()?
    )))
}

/// A JSON value as plain Python objects (dict, list, str, int, float,
/// bool, None).
pub fn json_to_py(py: Python<'_>, v: &Value) -> PyResult<Py<PyAny>> {
    json_to_py_with(py, v, false)
}

fn json_to_py_with(py: Python<'_>, v: &Value, arrays: bool) -> PyResult<Py<PyAny>> {
    Ok(match v {
        Value::Null => py.None(),
        Value::Bool(b) => PyBool::new(py, *b).to_owned().into_any().unbind(),
        Value::Number(n) => {
            if let Some(i) = n.as_i64() {
                i.into_pyobject(py)?.into_any().unbind()
            } else if let Some(u) = n.as_u64() {
                u.into_pyobject(py)?.into_any().unbind()
            } else {
                n.as_f64()
                    .unwrap_or(f64::NAN)
                    .into_pyobject(py)?
                    .into_any()
                    .unbind()
            }
        }
        Value::String(s) => s.into_pyobject(py)?.into_any().unbind(),
        Value::Array(items) => {
            if arrays && !items.is_empty() && items.iter().all(Value::is_number) {
                let xs: Vec<f64> = items
                    .iter()
                    .map(|x| x.as_f64().unwrap_or(f64::NAN))
                    .collect();
                xs.to_pyarray(py).into_any().unbind()
            } else {
                let list = PyList::empty(py);
                for x in items {
                    list.append(json_to_py_with(py, x, arrays)?)?;
                }
                list.into_any().unbind()
            }
        }
        Value::Object(map) => {
            let d = PyDict::new(py);
            for (k, x) in map {
                d.set_item(k, json_to_py_with(py, x, arrays)?)?;
            }
            d.into_any().unbind()
        }
    })
}

/// Anything serialisable as Python objects (lists of numbers as NumPy
/// arrays when `arrays`).
pub fn serialised<T: serde::Serialize>(py: Python<'_>, x: &T, arrays: bool) -> PyResult<Py<PyAny>> {
    let v = serde_json::to_value(x).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    json_to_py_with(py, &v, arrays)
}

/// A table as a dict from column name to a NumPy array (text columns as
/// arrays of str).
pub fn table_to_py(py: Python<'_>, t: &Table) -> PyResult<Py<PyAny>> {
    let numpy = py.import("numpy")?;
    let d = PyDict::new(py);
    for (name, col) in &t.columns {
        let arr: Py<PyAny> = match col {
            Column::Numbers(v) => PyArray1::from_slice(py, v).into_any().unbind(),
            Column::Integers(v) => PyArray1::from_slice(py, v).into_any().unbind(),
            Column::Text(v) => numpy
                .call_method1("asarray", (PyList::new(py, v)?, "str"))?
                .unbind(),
        };
        d.set_item(name, arr)?;
    }
    Ok(d.into_any().unbind())
}
