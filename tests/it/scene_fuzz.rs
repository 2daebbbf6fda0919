//! Scene fuzz test: every field of every example scene is set to
//! 0, a negative value, NaN, inf, a huge and a tiny value, a value of the
//! wrong type, removed, and duplicated. Each mutated scene is parsed, planned
//! and run in-process (the library path of `asperity run`) on its own thread
//! with a time budget, and must either
//! - be refused as bad input (`exit 2`) with a message naming the mutated
//!   field, or
//! - run (`exit 0`) with finite outputs, and with warnings when the real
//!   area is outside GW's validity range;
//!
//! never panic, abort or hang. Variants add the keys no example sets
//! (`montecarlo.summits`, `program.start_separation`, `weibull_shape`,
//! `truncation`; the shaped power, sphere and tabulated profiles' keys;
//! two metals' resistivities and mean free paths, `hardness`). To keep every run cheap in a debug build the
//! base scenes use at most [`POINTS`] points per leg (the `points` field
//! itself is mutated from its original value), and the calibrated scene and
//! the plastic switch bump are only planned (`Plan::preview`: the sphere
//! solver for every mutated Tabor parameter would take seconds each, the
//! plastic bump's retraction about half a minute).

use asperity::study::{curve_csv, montecarlo_csv, Plan, PlanMode, Scene, Summary};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::mpsc;
use std::time::{Duration, Instant};
use toml::Value;

/// Where the example scenes live (relative paths in them, such as a
/// `topography` map, resolve against it).
const SCENE_DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/scenes");

/// Points per leg of the base scenes.
const POINTS: i64 = 12;

/// Time budget of one case (s): a case that takes longer counts as a hang.
/// Generous against a loaded CI machine; cases take milliseconds.
const BUDGET_S: u64 = 20;

const MUTATIONS: [&str; 9] = [
    "zero",
    "negative",
    "nan",
    "inf",
    "huge",
    "tiny",
    "wrong-type",
    "missing",
    "duplicated",
];

/// Outcome of one case, for the assertions and the tally.
enum Outcome {
    Refused(String),
    Ran { warnings: usize },
}

fn scenes() -> Vec<(String, String)> {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/scenes");
    let mut v: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .map(|p| {
            (
                p.file_name().unwrap().to_string_lossy().into_owned(),
                std::fs::read_to_string(&p).unwrap(),
            )
        })
        .collect();
    v.sort();
    // Keys no example scene sets, so that every schema key is mutated.
    let find = |n: &str| v.iter().find(|x| x.0 == n).unwrap().1.clone();
    let mc = find("montecarlo-gold.toml")
        .replacen("# summits = 10000", "summits = 500", 1)
        .replacen("points = 60", "points = 60\nstart_separation = 40e-9", 1);
    let gold = find("mems-gold.toml");
    let weibull = gold.replacen(
        "distribution = \"gaussian\"",
        "distribution = \"weibull\"\nweibull_shape = 2.0",
        1,
    );
    let truncated = gold.replacen(
        "distribution = \"gaussian\"",
        "distribution = \"truncated-gaussian\"\ntruncation = 3.0",
        1,
    );
    // The shaped profiles and electrical keys no example sets (found by the fuzz:
    // the newer keys are fuzzed too): a power law, a true sphere and a
    // tabulated profile on the conical example; two metals and a hardness
    // on the switch example.
    let cone = find("conical-summits.toml");
    let shaped = |profile: &str| {
        cone.replacen("profile = \"cone\"", profile, 1).replacen(
            "tan_angle = 0.3 ",
            "# tan_angle ",
            1,
        )
    };
    let power = shaped("profile = \"power\"\nexponent = 4.0\ncoefficient = 1e15");
    let sphere = shaped("profile = \"sphere\"\nradius = 10e-6");
    let tabulated = shaped(
        "profile = \"tabulated\"\nprofile_r = [0.0, 1e-6, 2e-6, 4e-6]\n\
         profile_f = [0.0, 5e-8, 2e-7, 8e-7]",
    );
    let switch = find("rf-mems-switch.toml");
    let metals = switch
        .replacen(
            "resistivity = 2.44e-8 ",
            "resistivity1 = 2.44e-8\nresistivity2 = 1.0e-7 ",
            1,
        )
        .replacen(
            "mean_free_path = 3.46e-8 ",
            "mean_free_path1 = 3.46e-8\nmean_free_path2 = 1e-8 ",
            1,
        )
        .replacen(
            "yield_strength = 0.4e9 ",
            "yield_strength = 0.4e9\nhardness = 1.2e9 ",
            1,
        );
    for (n, t) in [
        ("extra-montecarlo", mc),
        ("extra-weibull", weibull),
        ("extra-truncated", truncated),
        ("extra-power", power),
        ("extra-sphere-profile", sphere),
        ("extra-tabulated", tabulated),
        ("extra-two-metals", metals),
    ] {
        assert!(Scene::from_toml(&t).is_ok(), "{n}");
        v.push((n.to_string(), t));
    }
    v
}

/// Every leaf key as (table, key); `table` is empty for top-level keys.
fn fields(v: &Value) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for (k, x) in v.as_table().unwrap() {
        match x {
            Value::Table(t) => {
                for kk in t.keys() {
                    out.push((k.clone(), kk.clone()));
                }
            }
            _ => out.push((String::new(), k.clone())),
        }
    }
    out
}

fn mutated_value(old: &Value, mutation: &str) -> Option<Value> {
    Some(match (old, mutation) {
        (Value::Integer(i), m) => match m {
            "zero" => Value::Integer(0),
            "negative" => Value::Integer(-(i.abs().max(1))),
            "nan" => Value::Float(f64::NAN),
            "inf" => Value::Float(f64::INFINITY),
            "huge" => Value::Integer(i64::MAX),
            "tiny" => Value::Integer(1),
            _ => Value::String("oops".into()),
        },
        (Value::Float(x), m) => Value::Float(match m {
            "zero" => 0.0,
            "negative" => -(x.abs().max(1e-9)),
            "nan" => f64::NAN,
            "inf" => f64::INFINITY,
            "huge" => 1e300,
            "tiny" => 1e-300,
            _ => return Some(Value::String("oops".into())),
        }),
        (Value::Array(a), m) if m != "wrong-type" => {
            let mut a = a.clone();
            let first = a.first().cloned().unwrap_or(Value::Float(0.0));
            a[0] = mutated_value(&first, m)?;
            Value::Array(a)
        }
        (Value::String(_), "zero") => Value::String(String::new()),
        (Value::String(_), "negative") => Value::String("-".into()),
        (Value::String(_), _) => Value::Float(if mutation == "nan" { f64::NAN } else { 1e300 }),
        (Value::Boolean(_), "zero") => Value::Boolean(false),
        (Value::Boolean(b), "negative") => Value::Boolean(!b),
        (Value::Boolean(_), _) => Value::Float(f64::NAN),
        _ => Value::String("oops".into()),
    })
}

/// The scene text with `table.key` mutated.
fn mutate(base: &Value, table: &str, key: &str, mutation: &str) -> String {
    let mut v = base.clone();
    let t = if table.is_empty() {
        v.as_table_mut().unwrap()
    } else {
        v.get_mut(table).unwrap().as_table_mut().unwrap()
    };
    match mutation {
        "missing" => {
            t.remove(key);
        }
        "duplicated" => {
            let text = toml::to_string(&v).unwrap();
            let header = format!("[{table}]");
            let mut in_table = table.is_empty();
            let mut out = String::new();
            let mut done = false;
            for line in text.lines() {
                out.push_str(line);
                out.push('\n');
                if line.starts_with('[') {
                    in_table = line.trim() == header;
                }
                if in_table && !done && line.starts_with(&format!("{key} =")) {
                    out.push_str(line);
                    out.push('\n');
                    done = true;
                }
            }
            assert!(done, "{table}.{key} not found in\n{text}");
            return out;
        }
        m => {
            let new = mutated_value(&t[key], m).unwrap();
            t.insert(key.to_string(), new);
        }
    }
    toml::to_string(&v).unwrap()
}

fn finite(x: Option<f64>) -> bool {
    x.is_none_or(f64::is_finite)
}

/// Parses, plans and runs one scene (only plans a calibrated law).
fn case(text: &str, preview_only: bool) -> Result<Outcome, String> {
    let scene = match Scene::from_toml(text) {
        Ok(s) => s,
        Err(e) if e.is_bad_input() => return Ok(Outcome::Refused(e.to_string())),
        Err(e) => return Err(format!("parse failed without bad input (exit 1): {e}")),
    };
    if preview_only {
        return match Plan::preview_in(&scene, PlanMode::Planned, std::path::Path::new(SCENE_DIR)) {
            Ok(p) => Ok(Outcome::Ran {
                warnings: p.warnings().len(),
            }),
            Err(e) if e.is_bad_input() => Ok(Outcome::Refused(e.to_string())),
            Err(e) => Err(format!("plan failed (exit 1): {e}")),
        };
    }
    let plan = match Plan::new_in(&scene, PlanMode::Planned, std::path::Path::new(SCENE_DIR)) {
        Ok(p) => p,
        Err(e) if e.is_bad_input() => return Ok(Outcome::Refused(e.to_string())),
        Err(e) => return Err(format!("plan failed (exit 1): {e}")),
    };
    let results = match plan.run() {
        Ok(r) => r,
        Err(e) if e.is_bad_input() => return Ok(Outcome::Refused(e.to_string())),
        Err(e) => return Err(format!("run failed (exit 1): {e}")),
    };
    let s = Summary::new(&plan, &results);
    let headline = |k: &str| s.headlines.get(k).flatten();
    for (name, x) in [
        ("max_load", headline("max_load")),
        ("max_area", headline("max_area")),
        ("max_count", headline("max_count")),
        ("pull_off_load", s.pull_off_load),
        ("pull_off_separation", s.pull_off_separation),
        ("hysteresis_energy", s.hysteresis_energy),
        ("start_separation", Some(s.start_separation)),
        ("closest_separation", Some(s.closest_separation)),
    ] {
        if !finite(x) {
            return Err(format!("{name} = {x:?} is not finite"));
        }
    }
    if s.hysteresis_energy.is_some_and(|e| e < 0.0) {
        return Err(format!(
            "negative hysteresis energy {:?}",
            s.hysteresis_energy
        ));
    }
    if let Some(m) = &s.montecarlo {
        for (name, x) in [
            ("mc max_load", m.max_load),
            ("mc max_load_standard_error", m.max_load_standard_error),
            ("mc pull_off_load", m.pull_off_load),
            ("mc max_abs_z", m.max_abs_z),
            ("mc pull_off_seed_std", m.pull_off_seed_std),
        ] {
            if !finite(x) {
                return Err(format!("{name} = {x:?} is not finite"));
            }
        }
    }
    let csv = curve_csv(&results, &plan) + &montecarlo_csv(&results, &plan).unwrap_or_default();
    let lower = csv.to_lowercase();
    if lower.contains("nan") || lower.contains("inf") {
        return Err("a CSV cell is not finite".into());
    }
    // Outside GW's validity range (real area above 10 % of the nominal):
    // the run must say so.
    if let Some(a) = headline("max_area") {
        if a > 0.1 * plan.surface.nominal_area && s.warnings.is_empty() {
            return Err(format!(
                "A_r/A_n = {} without a warning",
                a / plan.surface.nominal_area
            ));
        }
    }
    Ok(Outcome::Ran {
        warnings: s.warnings.len(),
    })
}

/// Runs `case` on its own thread within [`BUDGET_S`], catching panics.
fn guarded(text: String, preview_only: bool) -> Result<Outcome, String> {
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let r = catch_unwind(AssertUnwindSafe(|| case(&text, preview_only)));
        let _ = tx.send(r);
    });
    match rx.recv_timeout(Duration::from_secs(BUDGET_S)) {
        Ok(Ok(r)) => r,
        Ok(Err(p)) => Err(format!(
            "panicked: {}",
            p.downcast_ref::<String>()
                .cloned()
                .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default()
        )),
        Err(_) => Err(format!("no answer within {BUDGET_S} s (hang)")),
    }
}

#[test]
fn every_field_of_every_example_scene_survives_every_mutation() {
    let t0 = Instant::now();
    let mut failures = Vec::new();
    let (mut refused, mut ran, mut warned) = (0, 0, 0);
    for (name, text) in scenes() {
        let mut base: Value = toml::from_str(&text).unwrap();
        let program = base.get_mut("program").unwrap().as_table_mut().unwrap();
        // `points` defaults to 200 where a scene does not give it.
        let points = program
            .get("points")
            .and_then(|p| p.as_integer())
            .unwrap_or(200)
            .min(POINTS);
        program.insert("points".into(), Value::Integer(points));
        // The full solver is not run for every mutated Tabor parameter: the
        // model error against it has its own tests (tests/it/model_error.rs).
        if let Some(t) = base.as_table_mut() {
            let acc = t
                .entry("accuracy")
                .or_insert_with(|| Value::Table(Default::default()));
            if let Some(a) = acc.as_table_mut() {
                a.insert("model_error".into(), Value::Boolean(false));
            }
            // Nor are the pull-off populations drawn (seconds each in a
            // debug build; tests/it/pull_off_population.rs tests them).
            let outputs = t
                .entry("outputs")
                .or_insert_with(|| Value::Table(Default::default()));
            if let Some(o) = outputs.as_table_mut() {
                o.insert("pull_off_population".into(), Value::Boolean(false));
            }
        }
        // (a rough sphere with plastic summits retracts in about half a minute)
        let preview_only = text.contains("\"calibrated\"")
            || (text.contains("[sphere]") && text.contains("kind = \"kogut-etsion\""));
        for (table, key) in fields(&base)
            .into_iter()
            .filter(|(_, k)| k != "model_error" && k != "pull_off_population")
        {
            let path = if table.is_empty() {
                key.clone()
            } else {
                format!("{table}.{key}")
            };
            for m in MUTATIONS {
                let mut v = base.clone();
                if key == "points" {
                    // Mutate the scene's own value, not the reduced one.
                    let original: Value = toml::from_str(&text).unwrap();
                    let own = original["program"]
                        .get("points")
                        .cloned()
                        .unwrap_or(Value::Integer(200));
                    v["program"]
                        .as_table_mut()
                        .unwrap()
                        .insert("points".into(), own);
                }
                let mutated = mutate(&v, &table, &key, m);
                match guarded(mutated.clone(), preview_only) {
                    Ok(Outcome::Refused(msg)) => {
                        refused += 1;
                        let named = msg.contains(&path)
                            || (!table.is_empty() && msg.contains(&table) && msg.contains(&key))
                            || msg.starts_with(&format!("{table}:"))
                            || msg.starts_with(&format!("{table}."));
                        if !named {
                            failures.push(format!(
                                "{name} {path} {m}: message does not name the field: {msg}"
                            ));
                        }
                    }
                    Ok(Outcome::Ran { warnings }) => {
                        ran += 1;
                        warned += usize::from(warnings > 0);
                    }
                    Err(e) => failures.push(format!("{name} {path} {m}: {e}")),
                }
            }
        }
    }
    eprintln!(
        "scene fuzz: {refused} refused, {ran} ran ({warned} with warnings) in {:.1} s",
        t0.elapsed().as_secs_f64()
    );
    assert!(refused > 0 && ran > 0);
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// The cases of the issue, one by one, through the same path.
#[test]
fn the_issue_cases_are_refused_or_warned() {
    // As the fuzz's base scenes: no full-solver reference, no populations.
    let gold = &asperity::study::DEFAULT_SCENE
        .replacen("[accuracy]", "[accuracy]\nmodel_error = false", 1)
        .replacen("[outputs]", "[outputs]\npull_off_population = false", 1);
    assert!(gold.contains("model_error = false") && gold.contains("pull_off_population = false"));
    let with = |old: &str, new: &str| {
        assert!(gold.contains(old), "{old}");
        gold.replacen(old, new, 1)
    };
    for (text, field) in [
        (
            with("points = 200", "points = 1000000000"),
            "program.points",
        ),
        (with("e1 = 79e9", "e1 = 1e-300"), "materials.e1"),
        (with("sigma = 5e-9 ", "sigma = 1e300 "), "surface.sigma"),
        (with("sigma = 5e-9 ", "sigma = 1e-3 "), "surface.sigma"),
        (
            with("closest_separation = 5e-9", "closest_separation = -1e-6"),
            "program.closest_separation",
        ),
        (
            with("nominal_area = 1e-8", "nominal_area = 1e2") + "\n[montecarlo]\n",
            "surface.nominal_area",
        ),
        (
            format!("{gold}\n[montecarlo]\nsummits = 1000000000\n"),
            "montecarlo.summits",
        ),
        (
            with(
                "nominal_area = 1e-8",
                "nominal_area = 1e-8\nheights = [1e-9, 2e-9]",
            ),
            "surface.heights",
        ),
        (
            with(
                "nominal_area = 1e-8",
                "nominal_area = 1e-8\nweibull_shape = 2.0",
            ),
            "surface.weibull_shape",
        ),
    ] {
        match guarded(text, false) {
            Ok(Outcome::Refused(msg)) => assert!(msg.starts_with(field), "{field}: {msg}"),
            Ok(Outcome::Ran { .. }) => panic!("{field}: accepted"),
            Err(e) => panic!("{field}: {e}"),
        }
    }
    // Outside the model but possible: a run with warnings.
    for text in [
        with("sigma = 5e-9 ", "sigma = 1e-7 "),
        with("# start_separation = 40e-9", "start_separation = 1.0"),
    ] {
        match guarded(text, false) {
            Ok(Outcome::Ran { warnings }) => assert!(warnings > 0),
            Ok(Outcome::Refused(msg)) => panic!("refused: {msg}"),
            Err(e) => panic!("{e}"),
        }
    }
}
