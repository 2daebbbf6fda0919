//! The scene features of the elastic-plastic, electrical and shaped-asperity
//! issues, tested from outside (`asperity run SCENE --json`) with the keys
//! exactly as the issues write them, and against direct library calls.

use crate::common::gw_spots::GwSpots;
use asperity::electrical::{Interaction, SpotResistance, Spreading};
use asperity::heights::Gaussian;
use asperity::law::{Branch, Jkr};
use asperity::named::Named;
use asperity::study::{Plan, PlanMode, Scene, Summary};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::Arc;

fn asperity(args: &[&str], dir: &Path) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("run asperity");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("asperity-features-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn example(name: &str) -> String {
    let path = format!("{}/examples/scenes/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(path).unwrap()
}

/// Runs scene text through the CLI with `--json`; returns the exit code,
/// the parsed summary (when exit 0) and stderr.
fn run_json(name: &str, text: &str) -> (i32, Option<Value>, String) {
    let dir = tmp(name);
    let scene = dir.join("scene.toml");
    std::fs::write(&scene, text).unwrap();
    let out = dir.join("out");
    let (code, stdout, stderr) = asperity(
        &[
            "run",
            scene.to_str().unwrap(),
            "--json",
            "--out",
            out.to_str().unwrap(),
        ],
        &dir,
    );
    let json = (code == 0).then(|| serde_json::from_str(&stdout).expect("JSON on stdout"));
    (code, json, stderr)
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        ((a - b) / b).abs()
    }
}

#[test]
fn listed_separations_give_states_in_order() {
    let (code, json, err) = run_json("plastic", &example("gold-rf-mems-plastic.toml"));
    assert_eq!(code, 0, "{err}");
    let j = json.unwrap();
    assert_eq!(j["points"].as_u64(), Some(200), "the integer points stays");
    let states = j["states"].as_array().unwrap();
    let listed = [10e-9, 5e-9, 0.0, -5e-9];
    assert_eq!(states.len(), listed.len());
    let mut last_load = f64::NEG_INFINITY;
    for (s, d) in states.iter().zip(listed) {
        for key in ["separation_m", "load_N", "real_area_m2", "contacts"] {
            assert!(s[key].is_number(), "{key} in {s}");
        }
        assert_eq!(f(&s["separation_m"]), d);
        // Approach to a closer separation carries more load.
        assert!(f(&s["load_N"]) > last_load);
        last_load = f(&s["load_N"]);
    }
    // Half the summits lie above the mean plane (Gaussian heights).
    assert!(rel(f(&states[2]["contacts"]), 5000.0) < 1e-8);
    let p = &j["plasticity"];
    assert!((f(&p["plasticity_index"]) - 3.0279).abs() < 1e-3);
    let sum = f(&p["elastic_fraction"])
        + f(&p["elastic_plastic_fraction"])
        + f(&p["fully_plastic_fraction"]);
    assert!((sum - 1.0).abs() < 1e-12);
    assert!(j["warnings"].as_array().unwrap().is_empty());
}

#[test]
fn listed_loads_are_reached_and_resistance_and_stiction_reported() {
    let (code, json, err) = run_json("switch", &example("rf-mems-switch.toml"));
    assert_eq!(code, 0, "{err}");
    let j = json.unwrap();
    let states = j["states"].as_array().unwrap();
    let loads = [10e-6, 20e-6, 50e-6, 100e-6, 200e-6, 500e-6];
    assert_eq!(states.len(), loads.len());
    let mut last_r = f64::INFINITY;
    for (s, p) in states.iter().zip(loads) {
        // The separation is solved to rtol * sigma: the load to ~rtol.
        assert!(rel(f(&s["load_N"]), p) < 1e-5, "{s}");
        let r = f(&s["resistance_ohm"]);
        assert!(r > 0.0 && r < last_r, "resistance falls with force: {s}");
        last_r = r;
    }
    // R falls faster than one spot's F^-1/2 and slower than F^-1 here
    // (the number of spots grows with the force).
    let r0 = f(&states[0]["resistance_ohm"]);
    let exponent = (last_r / r0).ln() / (loads[5] / loads[0]).ln();
    assert!(exponent < -0.5 && exponent > -1.0, "exponent {exponent}");
    assert!(rel(f(&j["resistance_ohm"]), last_r) < 1e-12);
    // Holm's phi-theta with Wiedemann–Franz: T = sqrt(T0^2 + U^2/(4L)),
    // L = (pi^2/3)(k_B/e)^2 (exact SI constants), U = I R.
    let kb_e = 1.380_649e-23 / 1.602_176_634e-19;
    let lorenz = std::f64::consts::PI.powi(2) / 3.0 * kb_e * kb_e;
    let h = &j["heating"];
    let u = 0.1 * last_r;
    assert!(rel(f(&h["contact_voltage_V"]), u) < 1e-12);
    let t = (293.15f64.powi(2) + u * u / (4.0 * lorenz)).sqrt();
    assert!(rel(f(&h["max_temperature_K"]), t) < 1e-12);
    for st in states {
        let u = 0.1 * f(&st["resistance_ohm"]);
        assert!(rel(f(&st["contact_voltage_V"]), u) < 1e-12);
        let t = (293.15f64.powi(2) + u * u / (4.0 * lorenz)).sqrt();
        assert!(rel(f(&st["max_temperature_K"]), t) < 1e-12);
    }
    let s = &j["stiction"];
    let (pull, restoring, margin) = (
        f(&s["pull_off_N"]),
        f(&s["restoring_force_N"]),
        f(&s["margin_N"]),
    );
    assert!(pull < 0.0);
    // One switch of 100 summits: the stiction margin is taken at the 5 %
    // most tensile population (switch.confidence = 0.95), beyond the
    // integral's pull-off.
    assert_eq!(s["pull_off_basis"], "population");
    assert_eq!(pull, f(&j["pull_off_population"]["p05_N"]));
    assert!(pull < f(&j["pull_off_load"]));
    assert!(rel(restoring, 10.0 * 2e-6) < 1e-15);
    assert!((margin - (restoring - pull.abs())).abs() < 1e-18);
    assert_eq!(s["sticks"].as_bool(), Some(margin < 0.0));
    // Fewer than 2 expected contacts at the start of the curve: the
    // Greenwood term is left out there, with a warning.
    let warnings = j["warnings"].as_array().unwrap();
    assert!(warnings
        .iter()
        .any(|w| w.as_str().unwrap().contains("greenwood")));
    let csv = std::fs::read_to_string(
        std::env::temp_dir()
            .join(format!("asperity-features-switch-{}", std::process::id()))
            .join("out/curve.csv"),
    )
    .unwrap();
    // With a current the curve also gives the contact voltage and the peak
    // temperature of every state.
    assert!(
        csv.starts_with(
            "leg,separation_m,load_N,area_m2,count,resistance_ohm,contact_voltage_V,max_temperature_K\n"
        ),
        "{}",
        csv.lines().next().unwrap_or("")
    );
}

/// A scene with Hertz (w = 0) or JKR summits, Maxwell or Wexler spots, at
/// listed separations.
fn electrical_scene(w: f64, spreading: &str, interaction: &str) -> String {
    format!(
        r#"
[materials]
e1 = 79e9
nu1 = 0.42
e2 = 79e9
nu2 = 0.42
[surface]
density = 1e12
radius = 1e-6
sigma = 5e-9
nominal_area = 1e-8
[adhesion]
w = {w}
z0 = 0.3e-9
[law]
kind = "{law}"
[program]
separations = [1e-8, 5e-9, 0.0]
[outputs]
resistance = true
[electrical]
resistivity = 2.44e-8
mean_free_path = 3.46e-8
spreading = "{spreading}"
interaction = "{interaction}"
[accuracy]
rtol = 1e-10
"#,
        law = if w == 0.0 { "hertz" } else { "jkr" }
    )
}

#[test]
fn scene_resistance_equals_the_direct_spot_sums() {
    let gw = GwSpots::new(1e4, 1e-6, 5e-9, 1e-8, Arc::new(Gaussian)).unwrap();
    for (w, spreading, interaction) in [
        (0.0, "maxwell", "none"),
        (0.0, "wexler", "greenwood"),
        (0.5, "wexler", "greenwood"),
    ] {
        let scene = Scene::from_toml(&electrical_scene(w, spreading, interaction)).unwrap();
        let plan = Plan::new(&scene, PlanMode::Planned).unwrap();
        let results = plan.run().unwrap();
        let summary = Summary::new(&plan, &results);
        let spot = SpotResistance::same_metal(
            Spreading::parse(spreading).unwrap(),
            2.44e-8,
            Some(3.46e-8),
        )
        .unwrap();
        let inter = Interaction::parse(interaction).unwrap();
        let estar = 79e9 / (2.0 * (1.0 - 0.42f64 * 0.42));
        let jkr = Jkr::new(1e-6, estar, 0.5).unwrap();
        for st in summary.states.unwrap() {
            let h = st.separation_m / 5e-9;
            let direct = if w == 0.0 {
                gw.hertz_resistance(&spot, inter, h)
            } else {
                let sums = gw.law_sums(&jkr, Branch::Approach, &spot, h);
                asperity::electrical::ContactResistance::from_sums(&sums, &spot, inter, gw.side())
            };
            let got = st.get("resistance_ohm").flatten().unwrap();
            assert!(
                rel(got, direct.resistance) < 1e-8,
                "{spreading}/{interaction} w = {w} at h = {h}: {got} vs {}",
                direct.resistance
            );
        }
    }
}

fn with(text: &str, old: &str, new: &str) -> String {
    assert!(text.contains(old), "{old}");
    text.replacen(old, new, 1)
}

#[test]
fn vanishing_plasticity_recovers_the_elastic_scene() {
    // psi -> 0 (a huge yield strength): Kogut–Etsion is Hertz, and with
    // adhesion the flattened-shape JKR is JKR.
    let base = example("gold-rf-mems-plastic.toml");
    for (w, elastic) in [("0.0", "hertz"), ("0.5", "jkr")] {
        let plastic = with(
            &with(&base, "yield_strength = 0.4e9", "yield_strength = 1e16"),
            "w = 0.5",
            &format!("w = {w}"),
        );
        let hertz = with(
            &plastic,
            "kind = \"kogut-etsion\"",
            &format!("kind = \"{elastic}\""),
        );
        let run = |t: &str| {
            let s = Scene::from_toml(t).unwrap();
            let p = Plan::new(&s, PlanMode::Planned).unwrap();
            let r = p.run().unwrap();
            (Summary::new(&p, &r), r)
        };
        let (a, ra) = run(&plastic);
        let (b, rb) = run(&hertz);
        for (x, y) in a.states.unwrap().iter().zip(b.states.unwrap().iter()) {
            assert!(
                rel(
                    x.get("load_N").flatten().unwrap(),
                    y.get("load_N").flatten().unwrap()
                ) < 1e-7,
                "w = {w}"
            );
            assert!(
                rel(
                    x.get("real_area_m2").flatten().unwrap(),
                    y.get("real_area_m2").flatten().unwrap()
                ) < 1e-7
            );
        }
        assert_eq!(ra.curve.approach.len(), rb.curve.approach.len());
        if w != "0.0" {
            assert!(rel(a.pull_off_load.unwrap(), b.pull_off_load.unwrap()) < 1e-6);
        }
    }
}

#[test]
fn an_elastic_law_on_a_yielding_surface_is_warned_about() {
    let text = with(
        &example("gold-rf-mems-plastic.toml"),
        "kind = \"kogut-etsion\"",
        "kind = \"jkr\"",
    );
    let (code, json, err) = run_json("elastic-warning", &text);
    assert_eq!(code, 0, "{err}");
    let j = json.unwrap();
    let w = j["warnings"].as_array().unwrap();
    assert!(
        w.iter()
            .any(|w| w.as_str().unwrap().contains("plasticity index")),
        "{w:?}"
    );
    assert!(
        err.contains("plasticity index"),
        "warnings go to stderr too"
    );
    // The diagnostics are there with an elastic law as well.
    assert!(j["plasticity"]["plasticity_index"].as_f64().unwrap() > 3.0);
}

#[test]
fn shaped_summits_run_from_a_scene() {
    let (code, json, err) = run_json("cone", &example("conical-summits.toml"));
    assert_eq!(code, 0, "{err}");
    let j = json.unwrap();
    assert_eq!(j["law"].as_str(), Some("shaped (cone)"));
    assert!(f(&j["pull_off_load"]) < 0.0);
    // A paraboloid profile of the summit radius is the JKR law.
    let base = with(
        &example("conical-summits.toml"),
        "profile = \"cone\"",
        "profile = \"paraboloid\"",
    );
    let para = with(&base, "tan_angle = 0.3", "");
    let jkr = with(
        &with(&para, "kind = \"shaped\"", "kind = \"jkr\""),
        "profile = \"paraboloid\"",
        "",
    );
    let run = |t: &str| {
        let s = Scene::from_toml(t).unwrap();
        let p = Plan::new(&s, PlanMode::Planned).unwrap();
        let r = p.run().unwrap();
        r.max_load().unwrap()
    };
    let (a, b) = (run(&para), run(&jkr));
    // Both at the scene's rtol 1e-2 (the shaped law is tabulated).
    assert!(rel(a, b) < 1e-2, "{a} vs {b}");
}

#[test]
fn bad_feature_values_exit_2_naming_the_field() {
    let plastic = example("gold-rf-mems-plastic.toml");
    let switch = example("rf-mems-switch.toml");
    let cone = example("conical-summits.toml");
    let cases: Vec<(String, &str)> = vec![
        (
            with(&plastic, "yield_strength = 0.4e9", "yield_strength = 0.0"),
            "materials.yield_strength",
        ),
        (
            with(&plastic, "yield_strength = 0.4e9", "yield_strength = -1e9"),
            "materials.yield_strength",
        ),
        (
            with(&plastic, "yield_strength = 0.4e9", "yield_strength = nan"),
            "materials.yield_strength",
        ),
        (
            with(&plastic, "yield_strength = 0.4e9", ""),
            "materials.yield_strength",
        ),
        (
            with(&plastic, "# hardness = 1.12e9", "hardness = 0.2e9"),
            "materials.hardness",
        ),
        (
            with(
                &with(&plastic, "yield_strength = 0.4e9", ""),
                "# hardness = 1.12e9",
                "hardness = 1e9",
            ),
            "materials.yield_strength",
        ),
        (
            with(&switch, "resistivity = 2.44e-8", "resistivity = -2.44e-8"),
            "electrical.resistivity",
        ),
        (
            with(&switch, "resistivity = 2.44e-8", "resistivity = nan"),
            "electrical.resistivity",
        ),
        (
            with(&switch, "mean_free_path = 3.46e-8", ""),
            "electrical.mean_free_path",
        ),
        (
            with(&switch, "spreading = \"wexler\"", "spreading = \"holm\""),
            "electrical.spreading",
        ),
        (
            with(
                &switch,
                "interaction = \"greenwood\"",
                "interaction = \"mean\"",
            ),
            "electrical.interaction",
        ),
        (
            with(&switch, "film_resistance = 0.0", "film_resistance = -1.0"),
            "electrical.film_resistance",
        ),
        (
            with(&switch, "spring_constant = 10.0", "spring_constant = 0.0"),
            "switch.spring_constant",
        ),
        (
            with(&switch, "travel = 2e-6", "travel = inf"),
            "switch.travel",
        ),
        (
            with(&switch, "loads = [", "loads = [-1e-6, "),
            "program.loads",
        ),
        (
            with(
                &switch,
                "loads = [10e-6, 20e-6, 50e-6, 100e-6, 200e-6, 500e-6]",
                "loads = []",
            ),
            "program.loads",
        ),
        (
            with(&plastic, "separations = [10e-9,", "separations = [nan,"),
            "program.separations",
        ),
        (
            with(
                &plastic,
                "separations = [",
                "closest_separation = 0.0\nseparations = [",
            ),
            "program",
        ),
        (
            with(&switch, "[electrical]", "[electrical_]"),
            "outputs.resistance",
        ),
        (with(&cone, "profile = \"cone\"", ""), "law.profile"),
        (
            with(&cone, "tan_angle = 0.3", "tan_angle = -0.3"),
            "law.tan_angle",
        ),
        (
            with(&cone, "tan_angle = 0.3", "tan_angle = 0.3\nexponent = 2.0"),
            "law.exponent",
        ),
        (
            with(&cone, "profile = \"cone\"", "profile = \"pyramid\""),
            "law.profile",
        ),
        (
            with(
                &plastic,
                "kind = \"kogut-etsion\"",
                "kind = \"jkr\"\ntan_angle = 0.1",
            ),
            "law.tan_angle",
        ),
        (
            with(
                &plastic,
                "kind = \"kogut-etsion\"",
                "kind = \"kogut-etsionn\"",
            ),
            "law.kind",
        ),
    ];
    for (i, (text, field)) in cases.iter().enumerate() {
        // `[electrical_]` is an unknown table: the scene must still name a
        // field; drop its keys so that the missing section is the error.
        let text = if text.contains("[electrical_]") {
            let cut = text.find("[electrical_]").unwrap();
            let end = text[cut..].find("[switch]").unwrap() + cut;
            format!("{}{}", &text[..cut], &text[end..])
        } else {
            text.clone()
        };
        let (code, _, err) = run_json(&format!("bad{i}"), &text);
        assert_eq!(code, 2, "case {i} ({field}): {err}");
        assert!(err.contains(field), "case {i}: expected {field} in: {err}");
        assert_eq!(err.trim().lines().count(), 1, "one line: {err}");
    }
}

#[test]
fn a_population_places_its_own_spots() {
    // 10 000 summits over 100 um x 100 um, 936 spots at the closest
    // approach (seed 7): the sample's explicit-position Greenwood resistance
    // agrees with the integral's mean field within its sampling scatter
    // (the conductance sum scatters by ~1/sqrt(936) = 3.3 %; measured
    // 1.7 %, 8 % allowed), and the exact solution never exceeds Greenwood's
    // formula.
    let text = with(
        &with(
            &example("rf-mems-switch.toml"),
            "nominal_area = 1e-10",
            "nominal_area = 1e-8",
        ),
        "loads = [10e-6, 20e-6, 50e-6, 100e-6, 200e-6, 500e-6]",
        "loads = [5e-3]",
    ) + "\n[montecarlo]\nseed = 7\n";
    let scene = Scene::from_toml(&text).unwrap();
    let plan = Plan::new(&scene, PlanMode::Planned).unwrap();
    let results = plan.run().unwrap();
    let summary = Summary::new(&plan, &results);
    let gw = summary.headlines.get("resistance_ohm").flatten().unwrap();
    let spots = summary.montecarlo.unwrap().spots.unwrap();
    assert!(spots.count > 500, "{}", spots.count);
    assert!(
        rel(spots.greenwood_ohm, gw) < 0.08,
        "{} vs {gw}",
        spots.greenwood_ohm
    );
    assert!(spots.greenwood_ohm > spots.parallel_ohm);
    if let Some(exact) = spots.exact_ohm {
        assert!(exact <= spots.greenwood_ohm * (1.0 + 1e-12));
        assert!(exact > spots.parallel_ohm);
    }
    assert!((spots.side_m - 1e-4).abs() < 1e-18);
}

#[test]
fn plastic_laws_scale_with_the_radius_as_documented() {
    // RadiusScaling::PLASTIC = (1, 2, 1): delta ~ R, P ~ R^2, a ~ R at
    // fixed E*, Y, H; checked for every variant across its breakpoints.
    use asperity::law::plastic::build;
    use asperity::law::RadiusScaling;
    use asperity::material::plastic::{Plasticity, Variant};
    let s = RadiusScaling::PLASTIC;
    let estar = 47.96e9;
    for v in Variant::ALL {
        for rho in [0.3, 2.0, 7.0] {
            let a = build(v, 1e-6, estar, Plasticity::gold()).unwrap();
            let b = build(v, rho * 1e-6, estar, Plasticity::gold()).unwrap();
            let wc = a.critical_interference();
            for m in [0.5, 1.5, 3.0, 20.0, 80.0, 150.0] {
                let d = m * wc;
                let sa = a.state(d, Branch::Approach);
                let sb = b.state(d * rho.powf(s.interference), Branch::Approach);
                assert!(
                    rel(sb.load, sa.load * rho.powf(s.load)) < 1e-12,
                    "{v:?} {rho} {m}"
                );
                assert!(rel(sb.radius, sa.radius * rho.powf(s.contact_radius)) < 1e-12);
            }
        }
    }
    // A population with lognormal radii runs with a non-adhesive plastic law.
    let text = with(&example("gold-rf-mems-plastic.toml"), "w = 0.5", "w = 0.0")
        + "\n[montecarlo]\nsummits = 2000\nradius_log_std = 0.3\n";
    let scene = Scene::from_toml(&text).unwrap();
    let plan = Plan::new(&scene, PlanMode::Planned).unwrap();
    let r = plan.run().unwrap();
    assert!(r.montecarlo.unwrap().curve.approach[0].load().unwrap() > 0.0);
}

#[test]
fn a_tabulated_profile_from_a_scene_follows_its_analytic_shape() {
    // profile_r/profile_f sampled from the cone r tan(beta), tan(beta) =
    // 0.3, out to 40 um: PCHIP reproduces linear data exactly, so the
    // scene's curve is the cone's to the scene's rtol 1e-2 (both laws are
    // Chebyshev tables to that tolerance).
    let r: Vec<f64> = (0..=20).map(|i| i as f64 * 2e-6).collect();
    let f: Vec<f64> = r.iter().map(|x| 0.3 * x).collect();
    let list = |v: &[f64]| {
        v.iter()
            .map(|x| format!("{x:e}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let cone = example("conical-summits.toml");
    let tab = with(
        &with(&cone, "profile = \"cone\"", "profile = \"tabulated\""),
        "tan_angle = 0.3",
        &format!("profile_r = [{}]\nprofile_f = [{}]", list(&r), list(&f)),
    );
    let run = |t: &str| {
        let s = Scene::from_toml(t).unwrap();
        let p = Plan::new(&s, PlanMode::Planned).unwrap();
        let r = p.run().unwrap();
        (
            r.max_load().unwrap(),
            r.pull_off.unwrap().load,
            p.law.name.clone(),
        )
    };
    let (a, pa, name) = run(&tab);
    let (b, pb, _) = run(&cone);
    assert_eq!(name, "shaped (tabulated)");
    assert!(rel(a, b) < 1e-2, "max load {a} vs {b}");
    assert!(rel(pa, pb) < 1e-2, "pull-off {pa} vs {pb}");
    // A non-monotone table is refused, naming the field.
    let mut bad = f.clone();
    bad[10] = bad[12];
    let text = with(
        &with(&cone, "profile = \"cone\"", "profile = \"tabulated\""),
        "tan_angle = 0.3",
        &format!("profile_r = [{}]\nprofile_f = [{}]", list(&r), list(&bad)),
    );
    let e = Scene::from_toml(&text).unwrap_err();
    assert!(e.field().unwrap_or("").starts_with("law.profile"), "{e}");
}
