//! Array arguments: any real NumPy array or sequence of numbers, copied
//! once into the numbers the library takes (bit for bit: no text in
//! between), after its type, shape and memory are checked.
//!
//! Refused with `TypeError` naming the argument and the dtype: booleans,
//! complex numbers, objects, strings, dates and masked arrays (a masked
//! pixel has no height). Refused with `ValueError` naming the argument, its
//! shape and the expected shape: the wrong number of dimensions. Refused
//! with `MemoryError`: a copy larger than the memory this process may still
//! use (estimated before anything is allocated). Non-contiguous,
//! Fortran-ordered and big-endian arrays are accepted and give the same
//! numbers as their contiguous native copy.

use asperity::commands::param;
use asperity::surface::HeightMap;
use pyo3::exceptions::{PyMemoryError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyAnyMethods;

/// An array argument's numbers (row-major) and shape.
pub struct Numbers {
    /// The values, C order.
    pub values: Vec<f64>,
    /// The shape (empty for a scalar).
    pub shape: Vec<usize>,
}

/// The dimensions an argument must have.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Dims {
    /// Any shape (the result keeps it).
    Any,
    /// A sequence (a scalar counts as one value).
    One,
    /// A map: rows x columns, at least 3 x 3.
    Map,
}

fn shape_text(shape: &[usize]) -> String {
    match shape {
        [n] => format!("({n},)"),
        _ => format!(
            "({})",
            shape
                .iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// The numbers of argument `name` (`obj`, anything `numpy.asarray` takes)
/// with dimensions `dims`.
///
/// # Errors
/// `TypeError`, `ValueError` or `MemoryError` naming `name` (see the module).
pub fn numbers(obj: &Bound<'_, PyAny>, name: &str, dims: Dims) -> PyResult<Numbers> {
    let py = obj.py();
    let np = py.import("numpy")?;
    let masked = np.getattr("ma")?.getattr("MaskedArray")?;
    if obj.is_instance(&masked)? {
        return Err(PyTypeError::new_err(format!(
            "{name}: a masked array is not accepted (a masked value has no number): fill or drop \
             the masked entries first, e.g. numpy.ma.filled({name}, ...) or {name}.compressed()"
        )));
    }
    let arr = np.call_method1("asarray", (obj,)).map_err(|e| {
        PyTypeError::new_err(format!(
            "{name}: expected an array or a sequence of numbers ({})",
            e.value(py)
        ))
    })?;
    let dtype = arr.getattr("dtype")?;
    let kind: String = dtype.getattr("kind")?.extract()?;
    if !matches!(kind.as_str(), "f" | "i" | "u") {
        let what = match kind.as_str() {
            "b" => "booleans are not numbers here",
            "c" => "complex numbers have no place in a real input: pass .real or abs() explicitly",
            "O" => "objects (None, strings or mixed types in a list?)",
            "M" | "m" => "dates and times are not lengths or pressures",
            "U" | "S" => "strings are not numbers: convert them with float()",
            _ => "not real numbers",
        };
        return Err(PyTypeError::new_err(format!(
            "{name}: expected real numbers (a float or integer array), got dtype {}: {what}",
            dtype.str()?
        )));
    }
    let shape: Vec<usize> = arr.getattr("shape")?.extract()?;
    match dims {
        Dims::One if shape.len() > 1 => {
            return Err(PyValueError::new_err(format!(
                "{name}: expected a 1-D sequence of numbers, got shape {}",
                shape_text(&shape)
            )))
        }
        Dims::Map if shape.len() != 2 || shape[0] < 3 || shape[1] < 3 => {
            return Err(PyValueError::new_err(format!(
                "{name}: expected a 2-D array of heights (rows, columns), at least 3 x 3, got \
                 shape {}",
                shape_text(&shape)
            )))
        }
        _ => {}
    }
    let n: usize = shape.iter().product();
    // The copy (and NumPy's conversion to float64 first, when needed).
    let native_f64 = dtype
        .eq(np.getattr("dtype")?.call1(("float64",))?)
        .unwrap_or(false);
    let bytes = n as f64 * 8.0 * if native_f64 { 1.0 } else { 2.0 };
    asperity::study::memory::ensure(name, &format!("a copy of {n} numbers"), bytes, "")
        .map_err(|e| PyMemoryError::new_err(e.to_string()))?;
    let f64s = np.call_method1("asarray", (&arr, "float64"))?;
    let view: numpy::PyReadonlyArrayDyn<'_, f64> = f64s.extract()?;
    let view = view.as_array();
    let mut values: Vec<f64> = Vec::new();
    values.try_reserve_exact(n).map_err(|_| {
        PyMemoryError::new_err(format!(
            "{name}: a copy of {n} numbers ({:.1} GB) could not be allocated",
            n as f64 * 8e-9
        ))
    })?;
    match view.as_slice() {
        Some(s) => values.extend_from_slice(s),
        None => values.extend(view.iter().copied()),
    }
    let shape = if dims == Dims::One && shape.is_empty() {
        vec![1]
    } else {
        shape
    };
    Ok(Numbers { values, shape })
}

/// A 1-D argument's numbers.
///
/// # Errors
/// As [`numbers`].
pub fn sequence(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<f64>> {
    Ok(numbers(obj, name, Dims::One)?.values)
}

/// An optional 1-D argument's numbers.
///
/// # Errors
/// As [`numbers`].
pub fn opt_sequence(obj: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<Vec<f64>>> {
    obj.filter(|o| !o.is_none())
        .map(|o| sequence(o, name))
        .transpose()
}

/// The height map of argument `name` (a 2-D array in m); its content
/// errors (a NaN height, ...) name `{name}` for the library to word.
///
/// # Errors
/// As [`numbers`]; the map's own check as a library error.
pub fn height_map(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<asperity::Result<HeightMap>> {
    let n = numbers(obj, name, Dims::Map)?;
    Ok(HeightMap::new(n.shape[0], n.shape[1], n.values).map_err(|e| e.renamed(&param(name))))
}
