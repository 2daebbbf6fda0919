//! Setting a numeric scene field by its dotted path (`surface.sigma`).

use crate::error::{Error, Result};

/// Sets the number at dotted `path` in a parsed scene to `value`. The table
/// must exist; the key may be absent (an optional field); the scene's own
/// validation then rejects unknown keys and bad values, naming the field.
///
/// # Errors
/// [`Error::Invalid`] naming the path when a table on the way is missing or
/// the field holds something other than a number.
pub fn set_field(scene: &mut toml::Value, path: &str, value: f64) -> Result<()> {
    let parts: Vec<&str> = path.split('.').collect();
    if parts.iter().any(|p| p.is_empty()) {
        return Err(Error::invalid(
            path,
            "not a dotted field path like surface.sigma",
        ));
    }
    let (key, tables) = parts.split_last().expect("split of a non-empty string");
    let mut node = scene;
    for t in tables {
        node = node
            .get_mut(*t)
            .filter(|v| v.is_table())
            .ok_or_else(|| Error::invalid(path, format!("the scene has no table [{t}]")))?;
    }
    let table = node
        .as_table_mut()
        .ok_or_else(|| Error::invalid(path, "not inside a table"))?;
    match table.get(*key) {
        // An absent key takes a whole value as an integer (a float field
        // reads it too; an integer field reads nothing else).
        None if value.fract() == 0.0 && value.abs() <= 9.0e15 => {
            table.insert((*key).to_string(), toml::Value::Integer(value as i64));
        }
        None | Some(toml::Value::Float(_)) => {
            table.insert((*key).to_string(), toml::Value::Float(value));
        }
        Some(toml::Value::Integer(_)) => {
            if value.fract() != 0.0 || value.abs() > 9.0e15 {
                return Err(Error::invalid(
                    path,
                    format!("is a whole number in the scene; {value} is not"),
                ));
            }
            table.insert((*key).to_string(), toml::Value::Integer(value as i64));
        }
        Some(other) => {
            return Err(Error::invalid(
                path,
                format!("holds a {}, not a number", other.type_str()),
            ))
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sets_floats_integers_and_absent_keys() {
        let mut v: toml::Value =
            toml::from_str("[surface]\nsigma = 5e-9\n[program]\npoints = 10\nname = \"x\"\n")
                .unwrap();
        set_field(&mut v, "surface.sigma", 2e-9).unwrap();
        assert_eq!(v["surface"]["sigma"].as_float(), Some(2e-9));
        set_field(&mut v, "program.points", 20.0).unwrap();
        assert_eq!(v["program"]["points"].as_integer(), Some(20));
        assert!(set_field(&mut v, "program.points", 2.5).is_err());
        set_field(&mut v, "program.start_separation", 1e-8).unwrap();
        assert_eq!(v["program"]["start_separation"].as_float(), Some(1e-8));
        set_field(&mut v, "program.max_load", 2.0).unwrap();
        assert_eq!(v["program"]["max_load"].as_integer(), Some(2));
        let e = set_field(&mut v, "program.name", 1.0).unwrap_err();
        assert_eq!(e.field(), Some("program.name"));
        let e = set_field(&mut v, "nosuch.sigma", 1.0).unwrap_err();
        assert_eq!(e.field(), Some("nosuch.sigma"));
        assert!(set_field(&mut v, "surface..x", 1.0).is_err());
    }
}
