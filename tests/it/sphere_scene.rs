//! Scenes with `[sphere]`: a rough sphere (Greenwood & Tripp 1967) on the
//! scene's surface, run by `asperity run` and checked against the library's
//! `RoughSphere` called directly, against Hertz at heavy load, and for bad
//! input naming the field.
use asperity::gw::{Accuracy, GwModel, RoughSurface};
use asperity::heights::Gaussian;
use asperity::law::{Dmt, Hertz, LawKernels};
use asperity::loading::{History, LoadingModel, Observables};
use asperity::material::{contact_modulus, Material};
use asperity::roughsphere::{RoughSphere, SolverOptions, SphereProfile};
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
    let d = std::env::temp_dir().join(format!(
        "asperity-sphere-scene-{name}-{}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

const EXAMPLE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/examples/scenes/switch-bump.toml"
);

/// Gold on gold, Hertz summits (eta = 5e14 /m^2, beta = 50 nm, sigma =
/// 2 nm) under a 5 um paraboloid; `program` and `extra` complete it.
fn scene(program: &str, extra: &str) -> String {
    format!(
        "title = \"sphere test\"\n\
         [materials]\ne1 = 79e9\nnu1 = 0.42\ne2 = 79e9\nnu2 = 0.42\n\
         [surface]\ndensity = 5e14\nradius = 50e-9\nsigma = 2e-9\n\
         [sphere]\nradius = 5e-6\n\
         [adhesion]\nw = 0.0\nz0 = 0.3e-9\n\
         [law]\nkind = \"hertz\"\n\
         [program]\n{program}\n\
         {extra}"
    )
}

/// Runs `text` with `--json`: exit code, summary, stderr.
fn run(name: &str, text: &str) -> (i32, Option<Value>, String) {
    let dir = tmp(name);
    let path = dir.join("scene.toml");
    std::fs::write(&path, text).unwrap();
    let (code, out, err) = asperity(&["run", path.to_str().unwrap(), "--json"], &dir);
    (code, serde_json::from_str(&out).ok(), err)
}

fn estar() -> f64 {
    let m = Material::new(79e9, 0.42).unwrap();
    contact_modulus(&m, &m)
}

/// The library's rough sphere of the test scene with `law`, built as the
/// plan builds it (unit reference area, the scene's rtol).
fn direct(
    law: Arc<dyn LawKernels>,
    radius: f64,
    density: f64,
    beta: f64,
    sigma: f64,
) -> RoughSphere {
    let model = GwModel::new(
        RoughSurface::new(density, beta, sigma, 1.0).unwrap(),
        Arc::new(Gaussian::new()),
        law,
    )
    .unwrap()
    .with_accuracy(Accuracy::new(1e-6).unwrap());
    RoughSphere::new(
        model,
        radius,
        estar(),
        SphereProfile::Paraboloid,
        SolverOptions::default(),
    )
    .unwrap()
}

fn states(summary: &Value) -> Vec<(f64, f64)> {
    summary["states"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| {
            (
                s["separation_m"].as_f64().unwrap(),
                s["load_N"].as_f64().unwrap(),
            )
        })
        .collect()
}

/// The listed states of a `[sphere]` scene carry the loads of the library's
/// `RoughSphere` at the same remote separations (the same solver on the
/// same surface: agreement to 1e-9, far below the solver's own 1e-6).
#[test]
fn listed_loads_equal_the_library_sphere() {
    let text = scene("separations = [4e-9, 0.0, -2e-9, -6e-9]\npoints = 12", "");
    let (code, summary, err) = run("listed", &text);
    assert_eq!(code, 0, "{err}");
    let summary = summary.unwrap();
    assert!(summary["summits"].is_null(), "{}", summary["summits"]);
    assert!(
        summary["rough_sphere"]["radius_95"]["value"]
            .as_f64()
            .unwrap()
            > 0.0
    );
    let hertz = Arc::new(Hertz::new(50e-9, estar()).unwrap());
    let sphere = direct(hertz, 5e-6, 5e14, 50e-9, 2e-9);
    let got = states(&summary);
    assert_eq!(got.len(), 4);
    for (s, load) in got {
        let st = sphere
            .state(s, History::Approach, &Observables::LOAD)
            .unwrap();
        let want = st.load().unwrap();
        assert!(
            (load - want).abs() <= 1e-9 * want.abs(),
            "s = {s:e}: scene {load:e} N, library {want:e} N"
        );
    }
}

/// The example switch bump (DMT summits with adhesion): exit 0 within a
/// few seconds, resistance and stiction reported, its listed loads those of
/// the library's sphere at the solved separations.
#[test]
fn switch_bump_example_reports_resistance_and_stiction() {
    let dir = tmp("bump");
    let t0 = std::time::Instant::now();
    let (code, out, err) = asperity(&["run", EXAMPLE, "--json"], &dir);
    let seconds = t0.elapsed().as_secs_f64();
    assert_eq!(code, 0, "{err}");
    let s: Value = serde_json::from_str(&out).unwrap();
    let r = s["resistance_ohm"].as_f64().unwrap();
    assert!(r > 0.0 && r.is_finite(), "{r}");
    let st = &s["stiction"];
    assert!(st["sticks"].is_boolean(), "{st}");
    assert_eq!(st["pull_off_basis"], "integral");
    assert!(s["pull_off_population"].is_null());
    // Greenwood's interaction over the bump: the square it equals is
    // smaller than the bump's reach and positive.
    let side = s["rough_sphere"]["resistance"]["equivalent_square_side"]
        .as_f64()
        .unwrap();
    let outer = s["rough_sphere"]["outer_radius"].as_f64().unwrap();
    assert!(side > 0.0 && side < 2.0 * outer, "{side} {outer}");
    // resistance falls with force
    let rs: Vec<f64> = s["states"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x["resistance_ohm"].as_f64().unwrap())
        .collect();
    assert!(rs.windows(2).all(|w| w[1] < w[0]), "{rs:?}");
    // the loads at the solved separations are the library sphere's
    let dmt = Arc::new(Dmt::new(50e-9, estar(), 0.5).unwrap());
    let sphere = direct(dmt, 5e-6, 5e14, 50e-9, 2e-9);
    for (sep, load) in states(&s) {
        let want = sphere
            .state(sep, History::Approach, &Observables::LOAD)
            .unwrap()
            .load()
            .unwrap();
        assert!(
            (load - want).abs() <= 1e-9 * want.abs(),
            "s = {sep:e}: {load:e} vs {want:e}"
        );
    }
    // generous against a loaded machine: about 1.5 s of CPU in release
    assert!(seconds < 60.0, "{seconds} s");
}

/// The switch bump with Kogut–Etsion summits and JKR adhesion on the
/// flattened shape (`examples/scenes/switch-bump-plastic.toml`): a finite
/// tensile pull-off, the stiction margin its sum with the spring's force,
/// the resistance the sphere's, and the approach loads the library
/// sphere's with the same law. Run with 3 points per leg instead of the
/// example's 10 (the retraction tables, not the points, set the cost):
/// there the search for the central separation of a remote one once
/// failed ("no convergence after 80 iterations", residual 8e-10 sigma)
/// because it asked for 1e-10 sigma, below the mesh error of the central
/// deflection.
#[test]
fn plastic_switch_bump_example_pulls_off_and_reports_stiction() {
    let example = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/scenes/switch-bump-plastic.toml"
    );
    let dir = tmp("bump-plastic");
    let scene =
        std::fs::read_to_string(example)
            .unwrap()
            .replacen("points = 10 ", "points = 3 ", 1);
    assert!(scene.contains("points = 3 "));
    std::fs::write(dir.join("bump3.toml"), scene).unwrap();
    let (code, out, err) = asperity(&["run", "bump3.toml", "--json"], &dir);
    assert_eq!(code, 0, "{err}");
    let s: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(s["law"], "kogut-etsion", "{}", s["law"]);
    // tensile and finite, and smaller than the force pressed with (12 uN)
    let pull = s["pull_off_load"].as_f64().unwrap();
    assert!(pull < 0.0 && pull > -12e-6, "{pull:e}");
    // at 12 uN the centre holds 0.92 of the nominal area: a real area, below
    // the apparent area pi a95^2, and no above-1 warning (at 20 uN it was
    // 1.13: `never_wrong.rs`)
    assert!(
        !s["warnings"].to_string().contains("above 1"),
        "{}",
        s["warnings"]
    );
    let area = s["rough_sphere"]["real_area"]["value"]
        .as_f64()
        .unwrap_or_else(|| panic!("no real area: {}", s["rough_sphere"]));
    let r95 = s["rough_sphere"]["radius_95"]["value"].as_f64().unwrap();
    assert!(
        area > 0.0 && area < std::f64::consts::PI * r95 * r95,
        "{area:e}, a95 {r95:e}"
    );
    let st = &s["stiction"];
    assert_eq!(st["pull_off_N"].as_f64().unwrap(), pull);
    let spring = st["restoring_force_N"].as_f64().unwrap();
    assert!((spring - 20e-6).abs() <= 1e-15, "{spring:e}");
    let margin = st["margin_N"].as_f64().unwrap();
    assert!(
        (margin - (spring + pull)).abs() <= 1e-12 * spring,
        "{margin:e}"
    );
    assert_eq!(st["sticks"].as_bool().unwrap(), margin < 0.0);
    let r = s["resistance_ohm"].as_f64().unwrap();
    let rs = s["rough_sphere"]["resistance"]["resistance"]["value"]
        .as_f64()
        .unwrap();
    assert!(r > 0.0 && r.is_finite(), "{r}");
    assert!((r - rs).abs() <= 1e-6 * r, "{r} {rs}");
    // the loads at the solved separations are the library sphere's
    let ke = asperity::law::plastic::build(
        asperity::material::plastic::Variant::KogutEtsion,
        50e-9,
        estar(),
        asperity::material::plastic::Plasticity::gold(),
    )
    .unwrap();
    let law = asperity::law::plastic::AdhesivePlastic::new(ke.as_loading(), 0.5).unwrap();
    let sphere = direct(Arc::new(law), 5e-6, 5e14, 50e-9, 2e-9);
    // The listed state is solved for its load: its separation comes from a
    // root-find to the scene's rtol (1e-6), so the library's load at that
    // separation agrees to rtol, not to the last digits (3e-8 relative at
    // 12 uN; 1e-9 happened to hold at the former 20 uN).
    for (sep, load) in states(&s) {
        let want = sphere
            .state(sep, History::Approach, &Observables::LOAD)
            .unwrap()
            .load()
            .unwrap();
        assert!(
            (load - want).abs() <= 1e-6 * want.abs(),
            "s = {sep:e}: {load:e} vs {want:e}"
        );
    }
}

/// `--plan` states the sphere decision and why no pull-off spread.
#[test]
fn plan_prints_the_sphere_decision() {
    let dir = tmp("plan");
    let (code, out, err) = asperity(&["run", EXAMPLE, "--plan"], &dir);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("rough sphere") && out.contains("R = 5e-6 m"),
        "{out}"
    );
    assert!(out.contains("Greenwood & Tripp"), "{out}");
    assert!(out.contains("a rough sphere: its summits"), "{out}");
    assert!(out.contains("over the bump's apparent area"), "{out}");
}

/// Heavy load with a stiff rough layer (Greenwood–Tripp mu = 10): the
/// radius holding 95 % of the load tends to Hertz's at the same load as the
/// approach grows (as the library's limit, tests/it/rough_sphere.rs), and the
/// approach to Hertz's `a^2/R`. Measured at remote separations -10, -40,
/// -200 nm (central gap -1.7 sigma at the last): radius off by 4.2 % at
/// -40 nm and 1.07 % at -200 nm, approach by 0.36 %.
#[test]
fn heavy_load_tends_to_hertz() {
    // mu = (8/3) eta sigma sqrt(2 R beta) = (8/3) 3.75e15 1e-9 1e-6 = 10
    let mut prev = f64::INFINITY;
    for closest in ["-10e-9", "-40e-9", "-200e-9"] {
        let text = format!(
            "title = \"hertz limit\"\n\
             [materials]\ne1 = 79e9\nnu1 = 0.42\ne2 = 79e9\nnu2 = 0.42\n\
             [surface]\ndensity = 3.75e15\nradius = 100e-9\nsigma = 1e-9\n\
             [sphere]\nradius = 5e-6\n\
             [adhesion]\nw = 0.0\nz0 = 0.3e-9\n\
             [law]\nkind = \"hertz\"\n\
             [program]\nclosest_separation = {closest}\npoints = 12\n"
        );
        let (code, s, err) = run("hertz", &text);
        assert_eq!(code, 0, "{err}");
        let b = &s.unwrap()["rough_sphere"];
        let a95 = b["radius_95"]["value"].as_f64().unwrap();
        let h95 = b["hertz_radius_95"].as_f64().unwrap();
        let a = b["hertz_radius"].as_f64().unwrap();
        let approach = b["approach"]["value"].as_f64().unwrap();
        let radius = (a95 / h95 - 1.0).abs();
        let alpha = (approach / (a * a / 5e-6) - 1.0).abs();
        assert!(radius < prev, "{closest}: {radius} after {prev}");
        prev = radius;
        if closest == "-200e-9" {
            assert!(radius < 0.015 && alpha < 0.005, "{radius} {alpha}");
        }
    }
}

/// Bad `[sphere]` input exits 2 naming the field.
#[test]
fn bad_sphere_input_exits_2_naming_the_field() {
    let base = scene("closest_separation = 0.0\npoints = 12", "");
    let cases = [
        (
            base.replace("radius = 5e-6", "radius = 0.0"),
            "sphere.radius",
        ),
        (
            base.replace("radius = 5e-6", "radius = -5e-6"),
            "sphere.radius",
        ),
        (
            base.replace("radius = 5e-6", "radius = nan"),
            "sphere.radius",
        ),
        (
            base.replace("radius = 5e-6", "radius = inf"),
            "sphere.radius",
        ),
        (base.replace("radius = 5e-6\n", ""), "sphere.radius"),
        (
            base.replace("radius = 5e-6", "radius = 5e-6\nprofile = \"cone\""),
            "sphere.profile",
        ),
        (format!("{base}[montecarlo]\nseed = 2\n"), "montecarlo"),
        (
            base.replace("sigma = 2e-9", "sigma = 2e-9\nnominal_area = 1e-10"),
            "surface.nominal_area",
        ),
    ];
    for (i, (text, field)) in cases.iter().enumerate() {
        let (code, _, err) = run(&format!("bad{i}"), text);
        assert_eq!(code, 2, "{field}: {err}");
        assert!(err.contains(field), "{field}: {err}");
    }
}

/// The exact sphere profile is accepted and, at a contact radius far below
/// R, gives the paraboloid's load.
#[test]
fn sphere_profile_matches_the_paraboloid_at_small_contact() {
    let program = "separations = [0.0]\npoints = 12";
    let (c1, s1, e1) = run("para", &scene(program, ""));
    let text = scene(program, "").replace("radius = 5e-6", "radius = 5e-6\nprofile = \"sphere\"");
    let (c2, s2, e2) = run("sph", &text);
    assert_eq!((c1, c2), (0, 0), "{e1}{e2}");
    let (p1, p2) = (states(&s1.unwrap())[0].1, states(&s2.unwrap())[0].1);
    assert!((p1 - p2).abs() < 1e-3 * p1, "{p1} {p2}");
}

/// The bump's temperatures come from its per-state resistances (set after
/// the run over the bump's apparent area): a current that melts the spots
/// says so, with no temperature.
#[test]
fn a_melting_current_on_the_bump_is_a_warning() {
    let text = std::fs::read_to_string(EXAMPLE).unwrap().replacen(
        "[electrical]",
        "[electrical]\ncurrent = 10.0",
        1,
    );
    assert!(text.contains("current = 10.0"));
    let (code, s, err) = run("melting", &text);
    assert_eq!(code, 0, "{err}");
    let s = s.unwrap();
    let warnings = s["warnings"].to_string();
    assert!(
        warnings.contains("electrical.current = 1e1 A") && warnings.contains("melt"),
        "{warnings}"
    );
    // 10 A through ~0.1 Ohm is ~1 V, beyond gold's melting voltage 0.43 V.
    assert!(
        s["heating"]["max_temperature_K"].is_null(),
        "{}",
        s["heating"]
    );
}
