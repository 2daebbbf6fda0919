//! The JSON Schema (draft 2020-12) of scene files, generated from the scene
//! types: [`Scene`] and its tables derive [`JsonSchema`], so the schema
//! cannot drift from what [`Scene::from_toml`] reads. Every key states its
//! type, its unit (the keyword [`UNIT_KEYWORD`], `"1"` for dimensionless
//! numbers), its default, its range (the bounds the validation checks, from
//! the same constants) and its description (the field's doc comment).
//!
//! The named choices of the physics core (`DistributionKind`,
//! `ProfileKind`, `Spreading`, `Interaction`) get their schemas here, as
//! string enums of [`Named::names`]: the core builds without `schemars`.
//!
//! Rules across keys (exactly one program target; keys that apply to one
//! distribution, one profile or only with `topography`; `hardness >=
//! yield_strength`; `eta A_n` within bounds) stay in the Rust validation;
//! the descriptions state them.

use super::law_name::LawName;
use super::schema::Scene;
use super::topography::SummitSource;
use crate::axisym::ProfileKind;
use crate::electrical::{Interaction, Spreading};
use crate::heights::DistributionKind;
use crate::named::Named;
use crate::topography::units::HeightUnit;
use schemars::generate::SchemaSettings;
use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};
use serde_json::Value;
use std::borrow::Cow;
use std::sync::OnceLock;

/// The dialect the schema declares in `$schema`.
pub const SCHEMA_DIALECT: &str = "https://json-schema.org/draft/2020-12/schema";

/// The custom keyword stating a number's unit (`"m"`, `"Pa"`, `"1"` for a
/// dimensionless number); absent on booleans and strings.
pub const UNIT_KEYWORD: &str = "x-unit";

/// The JSON Schema of scene files, for editors (TOML language servers take
/// JSON Schemas), other languages and documentation: a scene's TOML,
/// converted to JSON, validates against it. Draft 2020-12; tables are
/// `$defs` referenced by `$ref`, every table has `additionalProperties:
/// false`.
pub fn scene_schema() -> Value {
    cached().clone()
}

/// [`scene_schema`] as pretty-printed JSON with a trailing newline, the same
/// bytes on every call and every machine (keys sorted): what `asperity
/// schema --json` prints.
pub fn scene_schema_text() -> String {
    let mut text = serde_json::to_string_pretty(cached()).unwrap_or_default();
    text.push('\n');
    text
}

/// The schema, generated once.
pub(super) fn cached() -> &'static Value {
    static SCHEMA: OnceLock<Value> = OnceLock::new();
    SCHEMA.get_or_init(generate)
}

fn generate() -> Value {
    let root = SchemaSettings::draft2020_12()
        .into_generator()
        .into_root_schema_for::<Scene>();
    let mut value = root.to_value();
    tidy(&mut value);
    if let Value::Object(obj) = &mut value {
        obj.insert("$schema".into(), SCHEMA_DIALECT.into());
        obj.insert("title".into(), "asperity scene".into());
        obj.insert(
            "description".into(),
            "A scene file of asperity (TOML): what to compute for an adhesive contact \
             between rough surfaces, in SI units. Examples with every key commented: \
             examples/scenes/*.toml. TOML has no null: an optional key is left out. Rules \
             across keys (one program target; keys that apply to one distribution, profile \
             or topography) are checked by `asperity run` and stated in the descriptions."
                .into(),
        );
    }
    value
}

/// Fits the generated schema to TOML: no `null` (an optional key is left
/// out, not null), and descriptions as paragraphs (the doc comments' line
/// breaks joined).
fn tidy(value: &mut Value) {
    match value {
        Value::Object(obj) => {
            // `Option<T>`: `{"anyOf": [T, {"type": "null"}], ...}` -> `T, ...`.
            if let Some(Value::Array(any)) = obj.get("anyOf") {
                let is_null = |v: &Value| v.get("type").and_then(Value::as_str) == Some("null");
                if any.len() == 2 && any.iter().any(is_null) {
                    let inner = any.iter().find(|v| !is_null(v)).cloned();
                    obj.remove("anyOf");
                    if let Some(Value::Object(inner)) = inner {
                        for (k, v) in inner {
                            obj.entry(k).or_insert(v);
                        }
                    }
                }
            }
            // `["number", "null"]` -> `"number"`.
            if let Some(Value::Array(types)) = obj.get_mut("type") {
                types.retain(|t| t != "null");
                if types.len() == 1 {
                    let only = types.remove(0);
                    obj.insert("type".into(), only);
                }
            }
            if let Some(Value::String(d)) = obj.get_mut("description") {
                *d = paragraphs(d);
            }
            for v in obj.values_mut() {
                tidy(v);
            }
        }
        Value::Array(items) => items.iter_mut().for_each(tidy),
        _ => {}
    }
}

/// Joins the lines of each paragraph with spaces; paragraphs stay apart.
fn paragraphs(text: &str) -> String {
    text.split("\n\n")
        .map(|p| p.split_whitespace().collect::<Vec<_>>().join(" "))
        .filter(|p| !p.is_empty())
        .collect::<Vec<_>>()
        .join("\n\n")
}

/// A string enum of `names` with a description.
fn choice(names: Vec<&'static str>, description: &str) -> Schema {
    json_schema!({
        "type": "string",
        "enum": names,
        "description": description,
    })
}

/// `JsonSchema` for a [`Named`] enum of the core: the string enum of its
/// names.
macro_rules! named_schema {
    ($t:ty, $description:expr) => {
        impl JsonSchema for $t {
            fn schema_name() -> Cow<'static, str> {
                stringify!($t).into()
            }

            fn json_schema(_: &mut SchemaGenerator) -> Schema {
                choice(<$t as Named>::names(), $description)
            }
        }
    };
}

named_schema!(DistributionKind, "A summit-height distribution, by name.");
named_schema!(ProfileKind, "An axisymmetric summit profile, by name.");
named_schema!(
    Spreading,
    "The spreading resistance of one spot: diffusive (Maxwell/Holm), ballistic (Sharvin) or \
     Wexler's interpolation."
);
named_schema!(
    Interaction,
    "The interaction between contact spots: none (parallel) or Greenwood's mean field."
);
named_schema!(
    SummitSource,
    "Which model of a measured map the study uses."
);
named_schema!(
    HeightUnit,
    "The unit of a .npy or text map's heights, which the file does not give."
);

impl JsonSchema for LawName {
    fn schema_name() -> Cow<'static, str> {
        "LawName".into()
    }

    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        choice(
            LawName::names(),
            "A single-asperity law, by name: auto, an analytic law, the calibrated \
             full-solver law, an elastic-plastic law or a shaped (profile) law.",
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_text_is_deterministic_and_declares_draft_2020_12() {
        let text = scene_schema_text();
        assert_eq!(text, scene_schema_text());
        assert!(text.ends_with("}\n"), "{text}");
        let v: Value = serde_json::from_str(&text).unwrap();
        assert_eq!(v, scene_schema());
        assert_eq!(v["$schema"], SCHEMA_DIALECT);
        assert!(v["description"]
            .as_str()
            .unwrap()
            .contains("examples/scenes"));
        fn has_null(v: &Value) -> bool {
            match v {
                Value::Null => true,
                Value::String(s) => s == "null",
                Value::Array(xs) => xs.iter().any(has_null),
                Value::Object(o) => o.values().any(has_null),
                _ => false,
            }
        }
        assert!(!has_null(&v), "TOML has no null");
    }

    #[test]
    fn core_choices_list_their_names() {
        let v = scene_schema();
        let defs = &v["$defs"];
        assert_eq!(
            defs["DistributionKind"]["enum"],
            serde_json::json!(DistributionKind::names())
        );
        assert_eq!(defs["LawName"]["enum"], serde_json::json!(LawName::names()));
        assert_eq!(
            defs["Spreading"]["enum"],
            serde_json::json!(["maxwell", "sharvin", "wexler"])
        );
    }
}
