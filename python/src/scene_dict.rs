//! Scene dicts to scenes, key by key against the scene schema (the same
//! JSON Schema `asperity schema --json` prints, generated from the Rust
//! scene types): every error names the key path (`surface.sigma`), never a
//! TOML line the user did not write.
//!
//! Refused with `ValueError`: unknown keys (with the nearest known key),
//! keys that are not `str`, a dict or list where the schema has a number or
//! a string (so nesting deeper than the schema, and cycles, end at the
//! first key that does not fit), NaN or infinite numbers, integers beyond
//! 64 bits. Accepted: `bool`, `int`, `float`, `str`, lists, tuples, NumPy
//! arrays and scalars, `os.PathLike`; `None` means "not given".

use asperity::study::scene::{nearest_key, scene_schema};
use asperity::study::Scene;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use serde_json::{Map, Number, Value};

/// Deeper than any scene: a structure nested this far is refused.
const MAX_DEPTH: usize = 16;

/// A scene from a dict with the TOML structure.
///
/// # Errors
/// `ValueError`/`TypeError` naming the key path; the scene's own checks
/// as library errors (`Ok(Err(..))`).
pub fn scene_from_dict(d: &Bound<'_, PyDict>) -> PyResult<asperity::Result<Scene>> {
    let root = scene_schema();
    let value = to_value(d.as_any(), &Path::default(), Some(&root), &root)?;
    let scene: Scene = match serde_path_to_error::deserialize(value) {
        Ok(s) => s,
        Err(e) => {
            let at = e.path().to_string();
            let at = if at == "." { "scene".into() } else { at };
            return Err(PyValueError::new_err(format!("{at}: {}", e.inner())));
        }
    };
    Ok(scene.validate().map(|()| scene))
}

/// A key path, `surface.sigma` or `program.loads[2]`.
#[derive(Default, Clone)]
struct Path {
    text: String,
    keys: Vec<String>,
}

impl Path {
    fn key(&self, k: &str) -> Path {
        let mut keys = self.keys.clone();
        keys.push(k.to_string());
        Path {
            text: if self.text.is_empty() {
                k.to_string()
            } else {
                format!("{}.{k}", self.text)
            },
            keys,
        }
    }

    fn index(&self, i: usize) -> Path {
        Path {
            text: format!("{}[{i}]", self.text),
            keys: self.keys.clone(),
        }
    }

    fn shown(&self) -> &str {
        if self.text.is_empty() {
            "scene"
        } else {
            &self.text
        }
    }
}

/// `node` with its `$ref` followed (into the root's `$defs`) and an
/// optional type (`anyOf`/`oneOf` with `null`) reduced to its other branch.
fn resolve<'a>(node: &'a Value, root: &'a Value) -> &'a Value {
    let mut node = node;
    for _ in 0..8 {
        if let Some(r) = node.get("$ref").and_then(Value::as_str) {
            let name = r.rsplit('/').next().unwrap_or("");
            match root.get("$defs").and_then(|d| d.get(name)) {
                Some(n) => {
                    node = n;
                    continue;
                }
                None => return node,
            }
        }
        let branches = node
            .get("anyOf")
            .or_else(|| node.get("oneOf"))
            .and_then(Value::as_array);
        if let Some(b) = branches {
            let not_null: Vec<&Value> = b
                .iter()
                .filter(|x| x.get("type").and_then(Value::as_str) != Some("null"))
                .collect();
            if let [one] = not_null.as_slice() {
                node = one;
                continue;
            }
        }
        return node;
    }
    node
}

/// The JSON types a schema node allows (empty: any).
fn types(node: &Value) -> Vec<&str> {
    match node.get("type") {
        Some(Value::String(t)) => vec![t.as_str()],
        Some(Value::Array(ts)) => ts.iter().filter_map(Value::as_str).collect(),
        _ => Vec::new(),
    }
}

/// What a schema node wants, in words (`a number (m)`).
fn wanted(node: &Value) -> String {
    let ts: Vec<&str> = types(node).into_iter().filter(|t| *t != "null").collect();
    let what = match ts.as_slice() {
        ["number"] => "a number".to_string(),
        ["integer"] => "an integer".to_string(),
        ["string"] => "a string".to_string(),
        ["boolean"] => "True or False".to_string(),
        ["array"] => "a list".to_string(),
        ["object"] => "a dict".to_string(),
        [] if node.get("enum").is_some() => "one of its names".to_string(),
        [] => "a value".to_string(),
        more => more.join(" or "),
    };
    match node.get("x-unit").and_then(Value::as_str) {
        Some(u) if u != "1" => format!("{what} ({u})"),
        _ => what,
    }
}

/// The Python type's name, for messages.
fn type_name(obj: &Bound<'_, PyAny>) -> String {
    obj.get_type()
        .name()
        .map(|n| n.to_string())
        .unwrap_or_else(|_| "object".into())
}

fn mismatch(path: &Path, node: &Value, obj: &Bound<'_, PyAny>) -> PyErr {
    PyValueError::new_err(format!(
        "{}: expected {}, got {} {}",
        path.shown(),
        wanted(node),
        type_name(obj),
        obj.repr()
            .map(|r| {
                let r = r.to_string();
                if r.len() > 60 {
                    format!("{}...", &r[..r.floor_char_boundary(57)])
                } else {
                    r
                }
            })
            .unwrap_or_default()
    ))
}

/// Whether `node` accepts JSON type `t` (`number` takes integers too).
fn accepts(node: &Value, t: &str) -> bool {
    let ts = types(node);
    ts.is_empty() || ts.contains(&t) || (t == "integer" && ts.contains(&"number"))
}

/// `obj` at `path` as a JSON value, checked against its schema `node`.
fn to_value(
    obj: &Bound<'_, PyAny>,
    path: &Path,
    node: Option<&Value>,
    root: &Value,
) -> PyResult<Value> {
    if path.keys.len() > MAX_DEPTH {
        return Err(PyValueError::new_err(format!(
            "{}: nested deeper than any scene key",
            path.shown()
        )));
    }
    let node = node.map(|n| resolve(n, root));
    let any = Value::Object(Map::new());
    let n = node.unwrap_or(&any);
    if let Ok(d) = obj.cast::<PyDict>() {
        if !accepts(n, "object") {
            return Err(mismatch(path, n, obj));
        }
        let props = n.get("properties").and_then(Value::as_object);
        let mut table = Map::new();
        for (k, v) in d.iter() {
            let Ok(key) = k.extract::<String>() else {
                return Err(PyValueError::new_err(format!(
                    "{}: keys must be str, got {} {}",
                    path.shown(),
                    type_name(&k),
                    k.repr().map(|r| r.to_string()).unwrap_or_default()
                )));
            };
            let at = path.key(&key);
            let child = match props {
                Some(p) => match p.get(&key) {
                    Some(c) => Some(c),
                    None => {
                        let known: Vec<&str> = p.keys().map(String::as_str).collect();
                        let hint = match nearest_key(&key, &known) {
                            Some(near) => format!(" (did you mean {}?)", path.key(&near).text),
                            None => format!("; known keys here: {}", known.join(", ")),
                        };
                        return Err(PyValueError::new_err(format!(
                            "{}: unknown key{hint}",
                            at.text
                        )));
                    }
                },
                None => None,
            };
            if v.is_none() {
                continue; // None means "not given", as a missing key.
            }
            table.insert(key, to_value(&v, &at, child, root)?);
        }
        return Ok(Value::Object(table));
    }
    if obj.is_instance_of::<PyBool>() {
        if !accepts(n, "boolean") {
            return Err(mismatch(path, n, obj));
        }
        return Ok(Value::Bool(obj.extract()?));
    }
    if obj.is_instance_of::<PyInt>() {
        if !accepts(n, "integer") {
            return Err(mismatch(path, n, obj));
        }
        if let Ok(i) = obj.extract::<i64>() {
            return Ok(Value::from(i));
        }
        if let Ok(u) = obj.extract::<u64>() {
            return Ok(Value::from(u));
        }
        return Err(PyValueError::new_err(format!(
            "{}: the integer {} does not fit in 64 bits",
            path.shown(),
            obj.repr()?
        )));
    }
    if obj.is_instance_of::<PyFloat>() {
        if !accepts(n, "number") {
            return Err(mismatch(path, n, obj));
        }
        let x: f64 = obj.extract()?;
        return Number::from_f64(x).map(Value::Number).ok_or_else(|| {
            PyValueError::new_err(format!(
                "{} = {x} is out of range: allowed finite",
                path.shown()
            ))
        });
    }
    if obj.is_instance_of::<PyString>() {
        if !accepts(n, "string") {
            return Err(mismatch(path, n, obj));
        }
        return Ok(Value::String(obj.extract()?));
    }
    if obj.is_instance_of::<PyList>() || obj.is_instance_of::<PyTuple>() {
        if !accepts(n, "array") {
            return Err(mismatch(path, n, obj));
        }
        let items = n.get("items");
        let mut out = Vec::new();
        for (i, v) in obj.try_iter()?.enumerate() {
            out.push(to_value(&v?, &path.index(i), items, root)?);
        }
        return Ok(Value::Array(out));
    }
    // NumPy scalars and arrays: through their Python value.
    if obj.hasattr("dtype")? && obj.hasattr("tolist")? {
        let plain = obj.call_method0("tolist")?;
        if plain.is(obj) {
            return Err(mismatch(path, n, obj));
        }
        return to_value(&plain, path, node, root);
    }
    if obj.hasattr("__fspath__")? {
        let p = obj.call_method0("__fspath__")?;
        if p.is_instance_of::<PyString>() {
            return to_value(&p, path, node, root);
        }
    }
    Err(PyTypeError::new_err(format!(
        "{}: cannot put {} {} into a scene (numbers, strings, booleans, lists and dicts only)",
        path.shown(),
        type_name(obj),
        obj.repr().map(|r| r.to_string()).unwrap_or_default()
    )))
}
