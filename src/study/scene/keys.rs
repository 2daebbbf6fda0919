//! The keys of scene files, read from their JSON Schema
//! ([`super::scene_schema`]), not from a second list: the tables' keys for
//! "did you mean" messages ([`keys_at`], [`nearest_key`], [`suggest_key`])
//! and one row per key for `asperity schema` ([`scene_keys`]).

use super::json_schema::{cached, UNIT_KEYWORD};
use crate::study::text::edit_distance;
use serde_json::Value;

/// One key of a scene file as the schema states it.
#[derive(Debug, Clone, PartialEq)]
pub struct SchemaKey {
    /// Dotted path (`surface.sigma`; a table is its name, `surface`).
    pub path: String,
    /// `"number"`, `"integer"`, `"string"`, `"boolean"`, `"table"` or
    /// `"array of number"`.
    pub kind: String,
    /// Unit of a number or of a list's numbers (`"m"`; `"1"`:
    /// dimensionless).
    pub unit: Option<String>,
    /// Default value, where there is a fixed one.
    pub default: Option<Value>,
    /// Allowed values of a number (`(0, 0.5]`), or of a list's numbers and
    /// its length (`(0, inf); 1 ..= 10000 items`).
    pub range: Option<String>,
    /// The names a string key accepts (empty otherwise).
    pub choices: Vec<String>,
    /// Whether the schema requires the key (rules across keys, such as
    /// "required unless `topography` is given", are in the description).
    pub required: bool,
    /// What the key means.
    pub description: String,
}

/// The table a `$ref` points to (the schema itself otherwise).
fn resolve(schema: &'static Value) -> &'static Value {
    match schema
        .get("$ref")
        .and_then(Value::as_str)
        .and_then(|r| r.strip_prefix("#/$defs/"))
    {
        Some(name) => &cached()["$defs"][name],
        None => schema,
    }
}

/// The keys a scene allows in the table at `path` (`[]`: the top-level
/// sections and `title`; `["surface"]`: the keys of `[surface]`), sorted;
/// `None` when `path` names no table.
///
/// ```
/// use asperity::study::scene::keys_at;
/// assert!(keys_at(&[]).unwrap().contains(&"surface"));
/// assert!(keys_at(&["surface"]).unwrap().contains(&"sigma"));
/// assert_eq!(keys_at(&["surface", "sigma"]), None);
/// ```
pub fn keys_at(path: &[&str]) -> Option<Vec<&'static str>> {
    let mut node = resolve(cached());
    for key in path {
        node = resolve(node.get("properties")?.get(*key)?);
    }
    let keys = node.get("properties")?.as_object()?;
    Some(keys.keys().map(String::as_str).collect())
}

/// The key of `allowed` that `typed` most likely meant: the closest by
/// edit distance within 2 (within 1 for a `typed` of 2 to 5 characters, 0
/// for one character, so `x` does not suggest `w`), or one that starts
/// with the other, both at least 3 characters (`nominal`: `nominal_area`);
/// case and `-`/`_` are ignored, ties go to the earlier key. `typed`
/// itself when it is allowed; `None` when nothing is close.
///
/// ```
/// use asperity::study::scene::nearest_key;
/// let keys = ["sigma", "radius", "density", "nominal_area"];
/// assert_eq!(nearest_key("sigmaa", &keys).as_deref(), Some("sigma"));
/// assert_eq!(nearest_key("nominal", &keys).as_deref(), Some("nominal_area"));
/// assert_eq!(nearest_key("temperature", &keys), None);
/// ```
pub fn nearest_key(typed: &str, allowed: &[&str]) -> Option<String> {
    let norm = |s: &str| s.to_lowercase().replace('-', "_");
    let t = norm(typed);
    let limit = match t.chars().count() {
        0 | 1 => 0,
        2..=5 => 1,
        _ => 2,
    };
    allowed
        .iter()
        .enumerate()
        .filter_map(|(i, &key)| {
            let k = norm(key);
            let d = edit_distance(&t, &k);
            let shorter = t.chars().count().min(k.chars().count());
            let prefix = shorter >= 3 && (k.starts_with(&t) || t.starts_with(&k));
            (d <= limit || prefix).then_some((d, i, key))
        })
        .min()
        .map(|(_, _, key)| key.to_string())
}

/// The dotted key a mistyped dotted key (`surface.sigmaa`) most likely
/// meant (`surface.sigma`), by [`nearest_key`] among the keys of its
/// table; `None` when its table is unknown or no key is close.
///
/// ```
/// use asperity::study::scene::suggest_key;
/// assert_eq!(suggest_key("surface.sigmaa").as_deref(), Some("surface.sigma"));
/// assert_eq!(suggest_key("acuracy").as_deref(), Some("accuracy"));
/// ```
pub fn suggest_key(dotted: &str) -> Option<String> {
    let parts: Vec<&str> = dotted.split('.').collect();
    let (last, table) = parts.split_last()?;
    let near = nearest_key(last, &keys_at(table)?)?;
    Some(match table {
        [] => near,
        t => format!("{}.{near}", t.join(".")),
    })
}

/// Every key of a scene file, depth first with each table's keys sorted:
/// a table (`surface`) comes before its keys (`surface.density`, ...).
pub fn scene_keys() -> Vec<SchemaKey> {
    let mut out = Vec::new();
    walk(resolve(cached()), "", &mut out);
    out
}

fn walk(table: &'static Value, prefix: &str, out: &mut Vec<SchemaKey>) {
    let Some(props) = table.get("properties").and_then(Value::as_object) else {
        return;
    };
    let required: Vec<&str> = table
        .get("required")
        .and_then(Value::as_array)
        .map(|r| r.iter().filter_map(Value::as_str).collect())
        .unwrap_or_default();
    for (name, prop) in props {
        let path = if prefix.is_empty() {
            name.clone()
        } else {
            format!("{prefix}.{name}")
        };
        let def = resolve(prop);
        let text = |key: &str| {
            prop.get(key)
                .or_else(|| def.get(key))
                .and_then(Value::as_str)
                .map(str::to_string)
        };
        let choices = choices(def);
        let ty = def.get("type").and_then(Value::as_str);
        let kind = match ty {
            Some("object") => "table".to_string(),
            Some("array") => format!(
                "array of {}",
                def["items"]["type"].as_str().unwrap_or("values")
            ),
            Some(t) => t.to_string(),
            None if !choices.is_empty() => "string".to_string(),
            None => "value".to_string(),
        };
        out.push(SchemaKey {
            path: path.clone(),
            kind,
            unit: text(UNIT_KEYWORD),
            default: prop.get("default").or_else(|| def.get("default")).cloned(),
            range: range(def),
            choices,
            required: required.contains(&name.as_str()),
            description: text("description").unwrap_or_default(),
        });
        if ty == Some("object") {
            walk(def, &path, out);
        }
    }
}

/// The names of a string enum (`enum`, or `oneOf` of `const`s).
fn choices(schema: &Value) -> Vec<String> {
    let names = |v: &Value| -> Vec<String> {
        v.as_array()
            .map(|a| {
                a.iter()
                    .filter_map(Value::as_str)
                    .map(str::to_string)
                    .collect()
            })
            .unwrap_or_default()
    };
    if let Some(e) = schema.get("enum") {
        return names(e);
    }
    schema
        .get("oneOf")
        .and_then(Value::as_array)
        .map(|alts| {
            alts.iter()
                .flat_map(|a| match a.get("const").and_then(Value::as_str) {
                    Some(c) => vec![c.to_string()],
                    None => a.get("enum").map(&names).unwrap_or_default(),
                })
                .collect()
        })
        .unwrap_or_default()
}

/// `(lo, hi]` from the bound keywords of a number, or of an array's items
/// with its length; `None` without bounds.
fn range(schema: &Value) -> Option<String> {
    if schema.get("type").and_then(Value::as_str) == Some("array") {
        let items = range(&schema["items"]);
        let min = schema.get("minItems").and_then(Value::as_u64);
        let max = schema.get("maxItems").and_then(Value::as_u64);
        let count = match (min, max) {
            (Some(lo), Some(hi)) => Some(format!("{lo} ..= {hi} items")),
            (Some(lo), None) => Some(format!("at least {lo} items")),
            (None, Some(hi)) => Some(format!("at most {hi} items")),
            (None, None) => None,
        };
        let parts: Vec<String> = items.into_iter().chain(count).collect();
        return (!parts.is_empty()).then(|| parts.join("; "));
    }
    let num = |k: &str| schema.get(k).and_then(Value::as_f64);
    let (lo, lo_open) = match (num("exclusiveMinimum"), num("minimum")) {
        (Some(x), _) => (Some(x), true),
        (None, Some(x)) => (Some(x), false),
        (None, None) => (None, true),
    };
    let (hi, hi_open) = match (num("exclusiveMaximum"), num("maximum")) {
        (Some(x), _) => (Some(x), true),
        (None, Some(x)) => (Some(x), false),
        (None, None) => (None, true),
    };
    if lo.is_none() && hi.is_none() {
        return None;
    }
    Some(format!(
        "{}{}, {}{}",
        if lo_open { '(' } else { '[' },
        lo.map_or("-inf".to_string(), short),
        hi.map_or("inf".to_string(), short),
        if hi_open { ')' } else { ']' },
    ))
}

/// A bound as people write it, the shorter of the plain and the exponent
/// forms: `0.5`, `200`, `1e-15`, `1e6`.
fn short(x: f64) -> String {
    let (plain, exp) = (format!("{x}"), format!("{x:e}"));
    if exp.len() < plain.len() {
        exp
    } else {
        plain
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_come_from_the_schema() {
        let top = keys_at(&[]).unwrap();
        for section in [
            "materials",
            "surface",
            "adhesion",
            "law",
            "program",
            "outputs",
            "accuracy",
            "montecarlo",
            "electrical",
            "switch",
            "sphere",
            "title",
        ] {
            assert!(top.contains(&section), "{section}: {top:?}");
        }
        assert_eq!(top.len(), 12, "{top:?}");
        let surface = keys_at(&["surface"]).unwrap();
        assert!(surface.contains(&"sigma") && surface.contains(&"topography"));
        assert_eq!(
            keys_at(&["materials"]).unwrap(),
            ["e1", "e2", "hardness", "nu1", "nu2", "yield_strength"]
        );
        assert_eq!(keys_at(&["nowhere"]), None);
        assert_eq!(keys_at(&["surface", "sigma"]), None);
        assert_eq!(keys_at(&["title"]), None);
    }

    #[test]
    fn nearest_key_suggests_close_keys_only() {
        let surface = keys_at(&["surface"]).unwrap();
        let near = |t: &str| nearest_key(t, &surface);
        assert_eq!(near("sigmaa").as_deref(), Some("sigma"));
        assert_eq!(near("Sigma").as_deref(), Some("sigma"));
        assert_eq!(near("densty").as_deref(), Some("density"));
        assert_eq!(near("nominal").as_deref(), Some("nominal_area"));
        assert_eq!(near("pixel-size").as_deref(), Some("pixel_size"));
        assert_eq!(near("weibull").as_deref(), Some("weibull_shape"));
        assert_eq!(near("sigma").as_deref(), Some("sigma"));
        assert_eq!(near("temperature"), None);
        assert_eq!(near("xy"), None);
        assert_eq!(nearest_key("x", &["w", "z0"]), None);
        assert_eq!(nearest_key("ww", &["w", "z0"]).as_deref(), Some("w"));
        assert_eq!(nearest_key("anything", &[]), None);
        let electrical = keys_at(&["electrical"]).unwrap();
        assert_eq!(
            nearest_key("resistivity_1", &electrical).as_deref(),
            Some("resistivity1")
        );
    }

    #[test]
    fn suggest_key_completes_the_dotted_path() {
        assert_eq!(
            suggest_key("surface.sigmaa").as_deref(),
            Some("surface.sigma")
        );
        assert_eq!(
            suggest_key("program.point").as_deref(),
            Some("program.points")
        );
        assert_eq!(suggest_key("electrcal").as_deref(), Some("electrical"));
        assert_eq!(suggest_key("nowhere.sigma"), None);
    }

    #[test]
    fn every_key_has_a_row_with_its_facts() {
        let keys = scene_keys();
        let row = |p: &str| keys.iter().find(|k| k.path == p).unwrap().clone();
        let sigma = row("surface.sigma");
        assert_eq!(sigma.kind, "number");
        assert_eq!(sigma.unit.as_deref(), Some("m"));
        assert_eq!(sigma.range.as_deref(), Some("[1e-15, 1]"));
        assert_eq!(sigma.default, None, "no NaN default");
        assert!(!sigma.required);
        let nu1 = row("materials.nu1");
        assert_eq!(nu1.range.as_deref(), Some("[0, 0.5)"));
        assert!(nu1.required);
        assert_eq!(row("program.points").default, Some(200.into()));
        assert_eq!(row("program.points").range.as_deref(), Some("[2, 1e6]"));
        assert_eq!(
            row("program.loads").range.as_deref(),
            Some("(0, inf); 1 ..= 10000 items")
        );
        assert_eq!(row("surface").kind, "table");
        assert!(row("surface").required);
        assert_eq!(row("sphere.profile").choices, ["paraboloid", "sphere"]);
        assert!(row("law.kind")
            .choices
            .contains(&"kogut-etsion".to_string()));
        assert_eq!(row("surface.heights").kind, "array of number");
        // Every table's keys, and nothing else, have rows.
        for k in &keys {
            let (table, last) = match k.path.rsplit_once('.') {
                Some((t, l)) => (t.split('.').collect::<Vec<_>>(), l),
                None => (vec![], k.path.as_str()),
            };
            assert!(keys_at(&table).unwrap().contains(&last), "{}", k.path);
        }
    }
}
