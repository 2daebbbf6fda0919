//! `asperity schema`: the JSON Schema of scene files
//! ([`asperity::study::scene::scene_schema_text`]) with `--json`, or one
//! line per key (path, type, unit, default, range, description).

use asperity::study::scene::{scene_keys, scene_schema_text, SchemaKey};
use clap::Args;

#[derive(Args, Debug)]
pub struct SchemaArgs {
    /// Print the JSON Schema itself (draft 2020-12), for editors and
    /// validators, instead of the table.
    #[arg(long)]
    pub json: bool,
}

/// Widest column the table pads to.
const MAX_WIDTH: usize = 32;

pub fn run(args: &SchemaArgs) -> crate::CliResult {
    if args.json {
        crate::out!("{}", scene_schema_text());
        return Ok(());
    }
    let keys = scene_keys();
    let rows: Vec<[String; 5]> = keys.iter().map(columns).collect();
    // A long cell (the names of law.kind) overflows its own line only.
    let width = |i: usize| {
        rows.iter()
            .map(|r| r[i].chars().count())
            .filter(|&n| n <= MAX_WIDTH)
            .max()
            .unwrap_or(0)
    };
    let widths = [width(0), width(1), width(2), width(3), width(4)];
    for (row, key) in rows.iter().zip(&keys) {
        let mut line = String::new();
        for (cell, w) in row.iter().zip(widths) {
            line.push_str(&format!("{cell:<w$}  "));
        }
        let required = if key.required { "required. " } else { "" };
        crate::outln!("{line}{required}{}", key.description.replace("\n\n", " "));
    }
    Ok(())
}

/// Path, type, unit, default and range (or choices) of one key.
fn columns(key: &SchemaKey) -> [String; 5] {
    // A table's default is its keys' defaults, listed on their lines.
    let default = match &key.default {
        Some(_) if key.kind == "table" => "-".to_string(),
        None => "-".to_string(),
        Some(serde_json::Value::String(s)) => format!("\"{s}\""),
        Some(serde_json::Value::Number(n)) => match n.as_f64() {
            // 0.0 -> 0, 1e-6 stays.
            Some(x) if x.fract() == 0.0 && x.abs() < 1e15 => format!("{x}"),
            _ => n.to_string(),
        },
        Some(v) => v.to_string(),
    };
    let range = match (&key.range, key.choices.is_empty()) {
        (_, false) => format!("one of {}", key.choices.join("|")),
        (Some(r), true) => format!("range {r}"),
        (None, true) => "-".to_string(),
    };
    [
        key.path.clone(),
        key.kind.clone(),
        key.unit.clone().unwrap_or_else(|| "-".to_string()),
        format!("default {default}"),
        range,
    ]
}
