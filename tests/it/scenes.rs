//! Scenes end to end: every example scene parses, runs and matches direct
//! library calls; the planner's skips pay and cost nothing.

use asperity::gw::{Accuracy, GwModel, Method};
use asperity::law::LawKind;
use asperity::loading::{History, LoadingModel, Observables};
use asperity::study::scene::{build_contact, build_distribution, build_surface, LawName};
use asperity::study::{Plan, PlanMode, Scene};
use std::sync::Arc;

fn example(name: &str) -> Scene {
    let path = format!("{}/examples/scenes/{name}", env!("CARGO_MANIFEST_DIR"));
    Scene::from_toml(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn all_examples() -> Vec<String> {
    let dir = format!("{}/examples/scenes", env!("CARGO_MANIFEST_DIR"));
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|n| n.ends_with(".toml"))
        .collect();
    v.sort();
    v
}

#[test]
fn every_example_scene_runs_and_matches_library_calls() {
    let names = all_examples();
    assert!(names.len() >= 5, "{names:?}");
    for name in names {
        let scene = example(&name);
        if scene.surface.topography.is_some() {
            // A measured map: tests/it/surface_scene.rs checks it against a
            // direct sum over its summits.
            continue;
        }
        if scene.sphere.is_some() {
            // A rough sphere: tests/it/sphere_scene.rs checks it against the
            // library's RoughSphere (to 1e-9).
            continue;
        }
        let plan = Plan::new(&scene, PlanMode::Planned).unwrap();
        let res = plan.run().unwrap();
        // The same numbers straight from the library.
        let contact = build_contact(&scene).unwrap();
        // The calibrated law is tested against the solver in src/sphere.
        let law: Arc<dyn asperity::law::LawKernels> = match plan.law.source {
            LawName::Analytic(kind) => Arc::from(kind.build(&contact).unwrap()),
            _ => plan.law.law.clone(),
        };
        let model = GwModel::new(
            build_surface(&scene).unwrap(),
            build_distribution(&scene.surface).unwrap(),
            law,
        )
        .unwrap();
        let acc = Accuracy::new(scene.accuracy.rtol).unwrap();
        let closest = res.curve.program.closest;
        for k in [
            0,
            res.curve.approach.len() / 3,
            res.curve.approach.len() - 1,
        ] {
            for (leg, history) in [
                (&res.curve.approach, History::Approach),
                (&res.curve.retract, History::Retract { closest }),
            ] {
                let got = leg[k];
                let want = model
                    .clone()
                    .with_accuracy(acc)
                    .state(got.separation, history, &Observables::ALL)
                    .unwrap();
                for (g, w, asked, e) in [
                    (
                        got.load(),
                        want.load(),
                        scene.outputs.load,
                        want.totals.error(0).unwrap(),
                    ),
                    (
                        got.area(),
                        want.area(),
                        scene.outputs.area,
                        want.totals.error(1).unwrap(),
                    ),
                    (
                        got.count(),
                        want.count(),
                        scene.outputs.count,
                        want.totals.error(2).unwrap(),
                    ),
                ] {
                    if asked {
                        let (g, w) = (g.unwrap(), w.unwrap());
                        // The exact law, not the plan's table (if it made one):
                        // equal to the scene's rtol plus the error estimates.
                        let rtol = scene.accuracy.rtol;
                        let tol = 2.0 * e
                            + (0..3).filter_map(|i| got.totals.error(i)).sum::<f64>()
                            + rtol * w.abs();
                        assert!((g - w).abs() <= tol, "{name} {k}: {g} vs {w} (tol {tol})");
                    }
                }
            }
        }
        if scene.outputs.pull_off && scene.adhesion.w > 0.0 {
            // A stiff, rough surface may never go tensile: both say so.
            let direct = model
                .clone()
                .with_accuracy(acc)
                .pull_off(closest, res.curve.program.start, 64)
                .unwrap();
            match (res.pull_off, direct) {
                (Some(p), Some(d)) => {
                    let tol = scene.accuracy.rtol * d.load.abs();
                    assert!((p.load - d.load).abs() <= tol, "{name}: {p:?} vs {d:?}")
                }
                (None, None) => {}
                other => panic!("{name}: {other:?}"),
            }
        } else {
            assert!(res.pull_off.is_none(), "{name}");
        }
        if !scene.outputs.count {
            assert!(
                res.curve.approach.iter().all(|s| s.count().is_none()),
                "{name}"
            );
        }
    }
}

/// Relative difference of two optional outputs, against the larger
/// magnitude of the curve (adhesive loads cross zero).
fn worst_gap(a: &[Option<f64>], b: &[Option<f64>]) -> f64 {
    let scale = a
        .iter()
        .chain(b)
        .flatten()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    a.iter()
        .zip(b)
        .filter_map(|(x, y)| Some((x.as_ref()? - y.as_ref()?).abs() / scale))
        .fold(0.0, f64::max)
}

#[test]
fn planned_runs_do_less_work_and_agree_within_tolerance() {
    let (mut planned_evals, mut full_evals) = (0, 0);
    for name in ["hertz-exponential.toml", "soft-jkr.toml", "mems-gold.toml"] {
        let mut scene = example(name);
        // The planner's choice by one summit's error: with the surface-level
        // model error on, `auto` takes the full-solver law on mems-gold,
        // more work for a far more accurate pull-off (tests/it/model_error.rs).
        scene.accuracy.model_error = false;
        // Same separations for both runs.
        if scene.program.start_separation.is_none() {
            let p = Plan::new(&scene, PlanMode::Planned).unwrap();
            scene.program.start_separation = Some(p.start);
        }
        let planned = Plan::new(&scene, PlanMode::Planned).unwrap();
        let full = Plan::new(&scene, PlanMode::EverythingOn).unwrap();
        let (rp, rf) = (planned.run().unwrap(), full.run().unwrap());
        // Closed forms and cheaper laws: no more work, counted in law
        // evaluations (wall-clock seconds reversed on a loaded CI machine;
        // soft-jkr keeps its law and only drops observables).
        planned_evals += rp.evaluations;
        full_evals += rf.evaluations;
        assert!(
            rp.evaluations <= rf.evaluations,
            "{name}: planned {} evals vs everything-on {} evals",
            rp.evaluations,
            rf.evaluations
        );
        let rtol = scene.accuracy.rtol;
        for (pa, fa) in [
            (&rp.curve.approach, &rf.curve.approach),
            (&rp.curve.retract, &rf.curve.retract),
        ] {
            let loads =
                |v: &Vec<asperity::loading::State>| v.iter().map(|s| s.load()).collect::<Vec<_>>();
            let areas =
                |v: &Vec<asperity::loading::State>| v.iter().map(|s| s.area()).collect::<Vec<_>>();
            let gap = worst_gap(&loads(pa), &loads(fa)).max(worst_gap(&areas(pa), &areas(fa)));
            assert!(
                gap <= rtol,
                "{name}: planned and everything-on differ by {gap:e} > {rtol:e}"
            );
        }
        eprintln!(
            "{name}: planned {:.4} s / {} evals, everything-on {:.4} s / {} evals",
            rp.seconds, rp.evaluations, rf.seconds, rf.evaluations
        );
    }
    assert!(
        planned_evals < full_evals,
        "{planned_evals} vs {full_evals}"
    );
}

#[test]
fn plans_say_what_they_skip() {
    let plan = Plan::new(&example("hertz-exponential.toml"), PlanMode::Planned).unwrap();
    let text = plan.to_string();
    assert!(text.contains("closed form"), "{text}");
    assert!(text.contains("copied from approach"), "{text}");
    assert!(text.contains("w = 0"), "{text}");
    assert!(!plan.pull_off && !plan.compute_retraction);
    assert_eq!(plan.accuracy.method, Method::Auto);
    let plan = Plan::new(&example("max-load.toml"), PlanMode::Planned).unwrap();
    assert!(!plan.quantities.observables().count);
    assert!(plan.to_string().contains("not asked for"));
}

#[test]
fn maugis_population_agrees_with_the_integral_within_its_statistical_error() {
    let base = example("montecarlo-gold.toml");
    for seed in 1..=4 {
        let mut scene = base.clone();
        scene.montecarlo.as_mut().unwrap().seed = seed;
        let plan = Plan::new(&scene, PlanMode::Planned).unwrap();
        let res = plan.run().unwrap();
        let mc = res.montecarlo.unwrap();
        let z = mc.max_abs_z.unwrap();
        assert!(z < 5.0, "seed {seed}: worst |z| = {z}");
        // Every state with enough summits in range is compared.
        let compared = mc.z.iter().filter(|z| z[0].is_some()).count();
        assert!(compared > mc.z.len() / 3, "{compared} of {}", mc.z.len());
    }
    // Power: an integral for a 10% rougher surface is rejected.
    let plan = Plan::new(&base, PlanMode::Planned).unwrap();
    let mc = plan.run().unwrap().montecarlo.unwrap();
    let mut rough = base.clone();
    rough.surface.sigma *= 1.1;
    rough.montecarlo = None;
    rough.program.start_separation = Some(plan.start);
    let wrong = Plan::new(&rough, PlanMode::Planned).unwrap().run().unwrap();
    let worst = mc
        .curve
        .approach
        .iter()
        .zip(&wrong.curve.approach)
        .filter(|(m, _)| m.evaluations >= 20)
        .filter_map(|(m, g)| m.deviation_from(g)[0])
        .fold(0.0f64, |a, z| a.max(z.abs()));
    assert!(
        worst > 5.0,
        "a 10% sigma error went unnoticed: |z| = {worst}"
    );
}

#[test]
fn radius_spread_needs_a_law_that_scales_with_the_radius() {
    let mut scene = example("montecarlo-gold.toml");
    scene.montecarlo.as_mut().unwrap().radius_log_std = 0.2;
    let e = Plan::new(&scene, PlanMode::Planned).unwrap_err();
    assert_eq!(e.field(), Some("montecarlo.radius_log_std"), "{e}");
    scene.law.kind = LawName::Analytic(LawKind::Jkr);
    let res = Plan::new(&scene, PlanMode::Planned).unwrap().run().unwrap();
    assert!(res.montecarlo.unwrap().max_abs_z.is_some());
}

// The scene files' JSON Schema (`asperity schema --json`) against the
// scenes: a small validator for the subset of draft 2020-12 the generated
// schema uses (a keyword outside it fails the test, so the validator
// cannot silently skip one).

use asperity::study::scene::{
    scene_schema, scene_schema_text, DEFAULT_SCENE, DEFAULT_STUDY, UNIT_KEYWORD,
};
use serde_json::{json, Value};

/// Keywords that only annotate.
const ANNOTATIONS: &[&str] = &[
    "$schema",
    "$defs",
    "$id",
    "title",
    "description",
    "default",
    "format",
    UNIT_KEYWORD,
];

/// Keywords [`violations`] checks.
const ASSERTIONS: &[&str] = &[
    "$ref",
    "type",
    "enum",
    "const",
    "properties",
    "additionalProperties",
    "required",
    "items",
    "minItems",
    "maxItems",
    "minimum",
    "maximum",
    "exclusiveMinimum",
    "exclusiveMaximum",
    "anyOf",
    "oneOf",
];

fn join(path: &str, key: &str) -> String {
    if path.is_empty() {
        key.to_string()
    } else {
        format!("{path}.{key}")
    }
}

/// What is wrong with `value` against `schema` (a part of `root`), each
/// message starting with the dotted path of the value.
fn violations(root: &Value, schema: &Value, value: &Value, path: &str) -> Vec<String> {
    let mut out = Vec::new();
    macro_rules! bad {
        ($($arg:tt)*) => { out.push(format!("{path}: {}", format!($($arg)*))) };
    }
    let num = |k: &str| schema.get(k).and_then(Value::as_f64);
    if let Some(r) = schema.get("$ref").and_then(Value::as_str) {
        let name = r.strip_prefix("#/$defs/").expect("a local $ref");
        let def = &root["$defs"][name];
        assert!(def.is_object(), "{r} is defined");
        out.extend(violations(root, def, value, path));
    }
    if let Some(t) = schema.get("type") {
        let types: Vec<&str> = match t {
            Value::String(s) => vec![s.as_str()],
            Value::Array(a) => a.iter().filter_map(Value::as_str).collect(),
            _ => panic!("type {t}"),
        };
        let is = |t: &str| match t {
            "object" => value.is_object(),
            "array" => value.is_array(),
            "string" => value.is_string(),
            "boolean" => value.is_boolean(),
            "number" => value.is_number(),
            "integer" => value.is_i64() || value.is_u64(),
            "null" => value.is_null(),
            other => panic!("type {other}"),
        };
        if !types.iter().any(|t| is(t)) {
            bad!("{value} is not of type {t}");
            return out;
        }
    }
    if let Some(e) = schema.get("enum").and_then(Value::as_array) {
        if !e.contains(value) {
            bad!("{value} is not one of {}", Value::from(e.clone()));
        }
    }
    if let Some(c) = schema.get("const") {
        if c != value {
            bad!("{value} is not {c}");
        }
    }
    if let Some(x) = value.as_f64() {
        if num("minimum").is_some_and(|lo| x < lo) {
            bad!("{x} < minimum {}", schema["minimum"]);
        }
        if num("maximum").is_some_and(|hi| x > hi) {
            bad!("{x} > maximum {}", schema["maximum"]);
        }
        if num("exclusiveMinimum").is_some_and(|lo| x <= lo) {
            bad!("{x} <= exclusiveMinimum {}", schema["exclusiveMinimum"]);
        }
        if num("exclusiveMaximum").is_some_and(|hi| x >= hi) {
            bad!("{x} >= exclusiveMaximum {}", schema["exclusiveMaximum"]);
        }
    }
    if let Some(obj) = value.as_object() {
        let required = schema.get("required").and_then(Value::as_array);
        for key in required.into_iter().flatten().filter_map(Value::as_str) {
            if !obj.contains_key(key) {
                bad!("missing required key {key:?}");
            }
        }
        let props = schema.get("properties").and_then(Value::as_object);
        let closed = schema.get("additionalProperties") == Some(&json!(false));
        for (key, v) in obj {
            match props.and_then(|p| p.get(key)) {
                Some(sub) => out.extend(violations(root, sub, v, &join(path, key))),
                None if closed => out.push(format!("{}: unknown key", join(path, key))),
                None => {}
            }
        }
    }
    if let Some(items) = value.as_array() {
        let n = items.len() as u64;
        if let Some(lo) = schema.get("minItems").and_then(Value::as_u64) {
            if n < lo {
                bad!("{n} items < minItems {lo}");
            }
        }
        if let Some(hi) = schema.get("maxItems").and_then(Value::as_u64) {
            if n > hi {
                bad!("{n} items > maxItems {hi}");
            }
        }
        if let Some(item) = schema.get("items") {
            for (i, v) in items.iter().enumerate() {
                out.extend(violations(root, item, v, &format!("{path}[{i}]")));
            }
        }
    }
    let passing = |alternatives: &Value| {
        alternatives
            .as_array()
            .unwrap()
            .iter()
            .filter(|s| violations(root, s, value, path).is_empty())
            .count()
    };
    if let Some(alternatives) = schema.get("anyOf") {
        if passing(alternatives) == 0 {
            bad!("{value} matches no anyOf alternative");
        }
    }
    if let Some(alternatives) = schema.get("oneOf") {
        let n = passing(alternatives);
        if n != 1 {
            bad!("{value} matches {n} oneOf alternatives, not 1");
        }
    }
    out
}

/// A scene's TOML as the JSON the schema describes.
fn scene_json(text: &str) -> Value {
    let table: toml::Table = toml::from_str(text).unwrap();
    serde_json::to_value(table).unwrap()
}

fn check(text: &str) -> Vec<String> {
    let schema = scene_schema();
    violations(&schema, &schema, &scene_json(text), "")
}

/// Every keyword of `schema` (recursively, in its schema positions).
fn keywords(schema: &Value, out: &mut std::collections::BTreeSet<String>) {
    let Some(obj) = schema.as_object() else {
        return;
    };
    for (k, v) in obj {
        out.insert(k.clone());
        match k.as_str() {
            "properties" | "$defs" => v
                .as_object()
                .unwrap()
                .values()
                .for_each(|s| keywords(s, out)),
            "items" => keywords(v, out),
            "anyOf" | "oneOf" => v.as_array().unwrap().iter().for_each(|s| keywords(s, out)),
            _ => {}
        }
    }
}

/// Every property schema: (dotted path, property schema, its target after
/// `$ref`).
fn properties(root: &Value) -> Vec<(String, Value, Value)> {
    fn walk(root: &Value, table: &Value, prefix: &str, out: &mut Vec<(String, Value, Value)>) {
        for (key, prop) in table["properties"].as_object().unwrap() {
            let path = join(prefix, key);
            let target = match prop.get("$ref").and_then(Value::as_str) {
                Some(r) => root["$defs"][r.strip_prefix("#/$defs/").unwrap()].clone(),
                None => prop.clone(),
            };
            out.push((path.clone(), prop.clone(), target.clone()));
            if target.get("properties").is_some() {
                walk(root, &target, &path, out);
            }
        }
    }
    let mut out = Vec::new();
    walk(root, root, "", &mut out);
    out
}

/// Every example scene, the embedded scenes, and variants that give the
/// keys no example gives.
fn example_texts() -> Vec<(String, String)> {
    let mut v: Vec<(String, String)> = all_examples()
        .into_iter()
        .map(|n| {
            let text = example_text(&n);
            (n, text)
        })
        .collect();
    v.push(("DEFAULT_STUDY".into(), DEFAULT_STUDY.into()));
    v.push(("DEFAULT_SCENE".into(), DEFAULT_SCENE.into()));
    // Variants giving the keys no example gives.
    let edit = |base: &str, edits: &[(&str, &str)]| {
        edits.iter().fold(base.to_string(), |text, (old, new)| {
            assert!(text.contains(old), "{old}");
            text.replacen(old, new, 1)
        })
    };
    let switch = example_text("rf-mems-switch.toml");
    let conical = example_text("conical-summits.toml");
    let gaussian = "distribution = \"gaussian\"";
    for (name, text) in [
        (
            "heated switch",
            edit(
                &switch,
                &[
                    ("# hardness = 1.12e9", "hardness = 1.12e9"),
                    (
                        "# bulk_temperature = 293.15",
                        "bulk_temperature = 293.15\nsoftening_temperature = 373.15\n\
                         melting_temperature = 1337.33",
                    ),
                    ("travel = 2e-6", "travel = 2e-6\nconfidence = 0.9"),
                ],
            ),
        ),
        (
            "two metals",
            edit(
                &switch,
                &[
                    (
                        "resistivity = 2.44e-8",
                        "resistivity1 = 2.44e-8\nresistivity2 = 1e-7",
                    ),
                    (
                        "mean_free_path = 3.46e-8",
                        "mean_free_path1 = 3.46e-8\nmean_free_path2 = 1e-8",
                    ),
                ],
            ),
        ),
        (
            "power-law summits",
            edit(
                &conical,
                &[
                    ("profile = \"cone\"", "profile = \"power\""),
                    ("tan_angle = 0.3", "exponent = 2.0\ncoefficient = 5e4"),
                ],
            ),
        ),
        (
            "paraboloidal summits",
            edit(
                &conical,
                &[
                    ("profile = \"cone\"", "profile = \"paraboloid\""),
                    ("tan_angle = 0.3", "radius = 10e-6"),
                ],
            ),
        ),
        (
            "weibull",
            edit(
                DEFAULT_SCENE,
                &[(gaussian, "distribution = \"weibull\"\nweibull_shape = 2.0")],
            ),
        ),
        (
            "truncated",
            edit(
                DEFAULT_SCENE,
                &[(
                    gaussian,
                    "distribution = \"truncated-gaussian\"\ntruncation = 3.0",
                )],
            ),
        ),
        (
            "scaled map",
            edit(
                &example_text("measured-topography.toml"),
                &[(
                    "pixel_size = 50e-9",
                    "pixel_size = 50e-9\nheight_scale = 1.0",
                )],
            ),
        ),
        (
            "populations",
            format!("{DEFAULT_SCENE}\n[montecarlo]\nsummits = 1000\nseeds = 10\n"),
        ),
    ] {
        v.push((name.to_string(), text));
    }
    v
}

fn example_text(name: &str) -> String {
    let path = format!("{}/examples/scenes/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(path).unwrap()
}

#[test]
fn schema_uses_only_keywords_the_test_validator_checks() {
    let mut used = std::collections::BTreeSet::new();
    keywords(&scene_schema(), &mut used);
    for k in &used {
        assert!(
            ANNOTATIONS.contains(&k.as_str()) || ASSERTIONS.contains(&k.as_str()),
            "keyword {k} is neither checked by the test validator nor an annotation"
        );
    }
    for k in [
        "$ref",
        "additionalProperties",
        "required",
        "enum",
        "exclusiveMaximum",
    ] {
        assert!(used.contains(k), "{k} unused: {used:?}");
    }
}

#[test]
fn every_example_scene_validates_against_the_schema() {
    let texts = example_texts();
    assert!(texts.len() >= 10, "{}", texts.len());
    for (name, text) in texts {
        let errors = check(&text);
        assert!(errors.is_empty(), "{name}: {errors:#?}");
        // And the Rust validation agrees the scene is good.
        Scene::from_toml(&text).unwrap();
    }
}

#[test]
fn schema_rejects_what_the_validation_rejects_naming_the_same_key() {
    let with = |old: &str, new: &str| {
        assert!(DEFAULT_SCENE.contains(old), "{old}");
        DEFAULT_SCENE.replacen(old, new, 1)
    };
    let cases = [
        // A misspelled key, a string for a number, out-of-range values.
        (with("sigma = 5e-9", "sigmaa = 5e-9"), "surface.sigmaa"),
        (with("e2 = 79e9", "e2 = \"stiff\""), "materials.e2"),
        (with("rtol = 1e-6", "rtol = 0.5"), "accuracy.rtol"),
        (with("nu1 = 0.42", "nu1 = 0.5"), "materials.nu1"),
        (with("sigma = 5e-9", "sigma = -5e-9"), "surface.sigma"),
        (with("sigma = 5e-9", "sigma = 2.0"), "surface.sigma"),
        (with("points = 200", "points = 1"), "program.points"),
        (with("points = 200", "points = 2.5"), "program.points"),
        (with("w = 0.5", "w = -0.5"), "adhesion.w"),
        (with("kind = \"auto\"", "kind = \"hertzz\""), "law.kind"),
        (
            with("distribution = \"gaussian\"", "distribution = \"lorentz\""),
            "surface.distribution",
        ),
        (with("[accuracy]", "[accuracyy]"), "accuracyy"),
        (
            format!("{DEFAULT_SCENE}\n[montecarlo]\nseeds = 0\n"),
            "montecarlo.seeds",
        ),
        (
            format!(
                "{DEFAULT_SCENE}\n[switch]\nspring_constant = 10.0\ntravel = 2e-6\n\
                 confidence = 1.0\n"
            ),
            "switch.confidence",
        ),
    ];
    for (text, field) in cases {
        let errors = check(&text);
        assert!(
            errors.iter().any(|e| e.starts_with(&format!("{field}:"))),
            "{field}: {errors:#?}"
        );
        let e = Scene::from_toml(&text).unwrap_err();
        assert_eq!(e.field(), Some(field), "{e}");
    }
    // A required key left out.
    let errors = check(&with("e1 = 79e9", ""));
    assert!(
        errors
            .iter()
            .any(|e| e.contains("missing required key \"e1\"")),
        "{errors:#?}"
    );
}

#[test]
fn every_key_states_its_description_and_every_number_its_unit() {
    let schema = scene_schema();
    let props = properties(&schema);
    assert!(props.len() >= 75, "{}", props.len());
    for (path, prop, target) in &props {
        let description = prop["description"].as_str().unwrap_or("");
        assert!(description.len() > 10, "{path}: no description");
        let ty = |s: &Value| s.get("type").and_then(Value::as_str).map(str::to_string);
        let numeric = |t: Option<String>| matches!(t.as_deref(), Some("number" | "integer"));
        let is_numeric = numeric(ty(target)) || numeric(ty(&target["items"]));
        let unit = prop.get(UNIT_KEYWORD).and_then(Value::as_str);
        if is_numeric {
            assert!(unit.is_some_and(|u| !u.is_empty()), "{path}: no x-unit");
        } else {
            assert_eq!(unit, None, "{path}: a unit on a non-number");
        }
        assert!(
            ty(target).is_some() || target.get("oneOf").is_some(),
            "{path}: no type"
        );
        if let Some(d) = prop.get("default") {
            // A default is a valid value (no NaN turned null, in range).
            let errors = violations(&schema, prop, d, path);
            assert!(errors.is_empty(), "{path}: default {d}: {errors:?}");
        }
    }
    // Tables refuse unknown keys.
    for (name, def) in schema["$defs"].as_object().unwrap() {
        if def.get("properties").is_some() {
            assert_eq!(def["additionalProperties"], json!(false), "{name}");
        }
    }
    assert_eq!(schema["additionalProperties"], json!(false));
    // The NaN placeholders of unset summit statistics are no defaults.
    let surface = &schema["$defs"]["SurfaceSpec"]["properties"];
    for key in ["density", "radius", "sigma", "nominal_area"] {
        assert!(surface[key].get("default").is_none(), "surface.{key}");
    }
}

/// Rules across keys that narrow a key's range: (words of their message,
/// words of the schema's descriptions that state the rule).
const CROSS_KEY_RULES: &[(&str, &str)] = &[
    ("calibrated law", "at least 1e-11 with the calibrated law"),
    ("Greenwood-Tripp mu", "Greenwood-Tripp mu"),
    ("materials.hardness = ", ">= `yield_strength`"),
    ("GB of memory", "within 2 GB of memory"),
    (
        "the profile's contact radius is",
        "an exponent that leaves no representable coefficient",
    ),
];

/// Numbers just outside and just inside a bound (`None` for an unbounded
/// side; no inside number for an exclusive bound at 0, whose neighbours
/// leave other ranges: `eta A_n` below one summit).
fn around(schema: &Value, keyword: &str, integer: bool) -> Option<(f64, Option<f64>)> {
    let b = schema.get(keyword)?.as_f64()?;
    let step = if integer { 1.0 } else { b.abs() * 1e-3 };
    Some(match keyword {
        "minimum" => (b - step.max(1e-300), Some(b)),
        "maximum" => (b + step, Some(b)),
        "exclusiveMinimum" => (b, (b != 0.0).then_some(b + step)),
        _ => (b, (b != 0.0).then_some(b - step)),
    })
}

#[test]
fn every_bound_in_the_schema_is_the_validations() {
    // Each number an example scene gives, set just outside each of its
    // schema bounds: the Rust validation refuses it, naming the key (the
    // schema is no looser there); set on the bound (inside an exclusive
    // one), the key's own check passes (the schema is no stricter).
    let schema = scene_schema();
    let props = properties(&schema);
    let all_text = scene_schema_text();
    let mut checked = Vec::new();
    let mut failures = Vec::new();
    for (name, text) in example_texts() {
        let table: toml::Table = toml::from_str(&text).unwrap();
        for (path, _, target) in &props {
            let Some((section, key)) = path.split_once('.') else {
                continue;
            };
            let integer = target["type"] == "integer";
            if !(integer || target["type"] == "number") {
                continue;
            }
            let Some(toml::Value::Table(t)) = table.get(section) else {
                continue;
            };
            if !t.contains_key(key) {
                continue;
            }
            for keyword in ["minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum"] {
                let Some((x, inside)) = around(target, keyword, integer) else {
                    continue;
                };
                let with_value = |x: f64| {
                    let mut edited = table.clone();
                    edited[section].as_table_mut().unwrap()[key] = if integer {
                        toml::Value::Integer(x as i64)
                    } else {
                        toml::Value::Float(x)
                    };
                    toml::to_string(&edited).unwrap()
                };
                if let Some(y) = inside {
                    // Just inside, the key's own range check passes (a rule
                    // across keys may still refuse the scene: one the
                    // schema's descriptions state).
                    let text = with_value(y);
                    if !check(&text).is_empty() {
                        failures.push(format!("{name}: {path} = {y} fails the schema"));
                    }
                    if let Err(e) = Scene::from_toml(&text) {
                        let stated = CROSS_KEY_RULES.iter().any(|(message, rule)| {
                            e.to_string().contains(message) && all_text.contains(rule)
                        });
                        if e.field() == Some(path.as_str()) && !stated {
                            failures.push(format!("{name}: {path} = {y} is refused: {e}"));
                        }
                    }
                }
                let text = with_value(x);
                if check(&text).is_empty() {
                    failures.push(format!("{name}: {path} = {x} passes the schema"));
                }
                // Refused, named as the field or in the message of a rule
                // across keys that fires first (a shaped law's contact
                // radius against adhesion.z0).
                match Scene::from_toml(&text) {
                    Ok(_) => failures.push(format!("{name}: {path} = {x} is accepted")),
                    Err(e) => {
                        if e.field() != Some(path.as_str())
                            && !e.to_string().contains(path.as_str())
                        {
                            failures.push(format!("{name}: {path} = {x}: {e}"));
                        }
                    }
                }
                checked.push(format!("{path} {keyword}"));
            }
        }
    }
    checked.sort();
    checked.dedup();
    // Every bounded number of the schema is checked.
    let mut bounds: Vec<String> = props
        .iter()
        .flat_map(|(path, _, target)| {
            ["minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum"]
                .into_iter()
                .filter(|k| {
                    target.get(*k).is_some()
                        && matches!(target["type"].as_str(), Some("number" | "integer"))
                })
                .map(move |k| format!("{path} {k}"))
        })
        .collect();
    bounds.sort();
    assert_eq!(checked, bounds);
    assert!(failures.is_empty(), "{failures:#?}");
}
