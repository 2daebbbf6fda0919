//! Values from the library to Python: JSON values to Python objects,
//! tables to NumPy arrays. No physics here.

use asperity::study::{Column, Table};
use numpy::{PyArray1, ToPyArray};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyList};
use serde_json::Value;

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

/// The first row of a table as a dict of Python scalars (float, int, str).
pub fn row_to_py(py: Python<'_>, t: &Table) -> PyResult<Py<PyAny>> {
    let d = PyDict::new(py);
    for (name, col) in &t.columns {
        let v: Py<PyAny> = match col {
            Column::Numbers(v) => v
                .first()
                .copied()
                .unwrap_or(f64::NAN)
                .into_pyobject(py)?
                .into_any()
                .unbind(),
            Column::Integers(v) => v
                .first()
                .copied()
                .unwrap_or_default()
                .into_pyobject(py)?
                .into_any()
                .unbind(),
            Column::Text(v) => v
                .first()
                .cloned()
                .unwrap_or_default()
                .into_pyobject(py)?
                .into_any()
                .unbind(),
        };
        d.set_item(name, v)?;
    }
    Ok(d.into_any().unbind())
}
