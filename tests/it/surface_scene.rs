//! Scenes from measurements: `[surface] topography` keys, the
//! exact sum over the measured summits against an independent numpy direct
//! sum (`tests/data/measured_summits.py`), and the moments model.

use asperity::loading::{History, LoadingModel, Observables};
use asperity::study::measured::measured_model;
use asperity::study::{Plan, PlanMode, Scene};
use serde_json::Value;
use std::path::PathBuf;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn scenes() -> PathBuf {
    root().join("examples/scenes")
}

fn example() -> String {
    std::fs::read_to_string(scenes().join("measured-topography.toml")).unwrap()
}

fn with(old: &str, new: &str) -> String {
    let text = example();
    assert!(text.contains(old), "{old}");
    text.replacen(old, new, 1)
}

fn plan(text: &str) -> asperity::Result<Plan> {
    Plan::new_in(&Scene::from_toml(text)?, PlanMode::Planned, &scenes())
}

fn field(text: &str) -> String {
    let e = plan(text).unwrap_err();
    format!("{} | {e}", e.field().unwrap_or(""))
}

fn reference() -> Value {
    let text = std::fs::read_to_string(root().join("tests/data/measured_summits.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

/// The measured-summit sum equals the numpy direct sum (math.fsum) to
/// 1e-12: each summit's terms agree to a few ulps (the radius scaling of
/// the law from the mean radius to R_i costs ~3 roundings), and the block
/// sums of ~500 positive terms add at most ~1e-13 relative. The DMT load
/// mixes signs, so its error is measured against sum |terms|.
#[test]
fn measured_sum_equals_the_numpy_direct_sum() {
    let r = reference();
    for (law, w) in [("hertz", "0.0"), ("dmt", "0.5")] {
        let text = with("kind = \"jkr\"", &format!("kind = \"{law}\""))
            .replacen("w = 0.5", &format!("w = {w}"), 1)
            .replacen("compare = true", "compare = false", 1);
        let p = plan(&text).unwrap();
        let t = p.topography.as_ref().unwrap();
        assert_eq!(
            t.characterisation.stats.count as u64,
            r["summit_count"].as_u64().unwrap()
        );
        let m = measured_model(&p, t).unwrap().unwrap();
        assert!((m.factor() / r["factor"].as_f64().unwrap() - 1.0).abs() < 1e-14);
        let origin = r["mean_summit_height_m"].as_f64().unwrap();
        assert!((m.origin_m() / origin - 1.0).abs() < 1e-13);
        for case in r["cases"].as_array().unwrap() {
            let d = case["separation_m"].as_f64().unwrap();
            let s = m.state(d, History::Approach, &Observables::ALL).unwrap();
            let get = |k: &str| case[k].as_f64().unwrap();
            let close = |got: f64, want: f64, scale: f64, what: &str| {
                assert!(
                    (got - want).abs() <= 1e-12 * scale,
                    "{law} {what} at d = {d:e}: {got:e} vs {want:e}"
                );
            };
            if law == "hertz" {
                let p = get("hertz_load_N");
                close(s.load().unwrap(), p, p, "load");
            } else {
                close(
                    s.load().unwrap(),
                    get("dmt_load_N"),
                    get("dmt_abs_sum_N"),
                    "load",
                );
            }
            close(s.area().unwrap(), get("area_m2"), get("area_m2"), "area");
            close(s.count().unwrap(), get("count"), get("count"), "count");
        }
    }
}

#[test]
fn measured_scene_resolves_to_the_map_statistics() {
    let p = plan(&example()).unwrap();
    let c = &p.topography.as_ref().unwrap().characterisation;
    // nominal_area defaults to the map's area: 160 x 160 pixels of 50 nm.
    assert!((p.surface.nominal_area / (160.0 * 160.0 * 2.5e-15) - 1.0).abs() < 1e-14);
    assert_eq!(p.surface.density, c.stats.density_per_m2);
    assert_eq!(p.surface.radius, c.stats.radius_m.unwrap());
    assert_eq!(p.distribution.name(), "empirical");
    assert!(p
        .to_string()
        .contains("exact sum over the 525 measured summits"));
    // The curve is the measured sum: at the closest separation (0, the mean
    // summit height) about half the summits touch.
    let results = p.run().unwrap();
    let n = results.curve.approach[0].count().unwrap();
    assert!(
        n > 0.3 * p.surface.summits() && n < 0.7 * p.surface.summits(),
        "{n}"
    );
    let other = results.topography.clone().unwrap().other.unwrap();
    assert_eq!(other.model, "moments");
    // Same surface, two models: headline loads within a factor 1.5.
    let ratio = other.headlines.get("max_load").flatten().unwrap() / results.max_load().unwrap();
    assert!(ratio > 0.67 && ratio < 1.5, "{ratio}");
}

#[test]
fn moments_scene_uses_mccool_parameters() {
    let text = with("summits = \"measured\"", "summits = \"moments\"").replacen(
        "# nominal_area = 1e-8",
        "nominal_area = 1e-8",
        1,
    );
    let p = plan(&text).unwrap();
    let gw = p
        .topography
        .as_ref()
        .unwrap()
        .characterisation
        .gw_from_moments();
    assert_eq!(p.surface.density, gw.density_per_m2);
    assert_eq!(p.surface.radius, gw.radius_m);
    assert_eq!(p.surface.sigma, gw.sigma_m.unwrap());
    assert_eq!(p.surface.nominal_area, 1e-8);
    assert_eq!(p.distribution.name(), "gaussian");
    let results = p.run().unwrap();
    assert_eq!(results.topography.unwrap().other.unwrap().model, "measured");
}

#[test]
fn topography_keys_are_validated_by_name() {
    for (text, want) in [
        (
            with("pixel_size = 50e-9", "pixel_size = 50e-9\ndensity = 1e12"),
            "surface.density",
        ),
        (
            with("pixel_size = 50e-9", "pixel_size = 50e-9\nsigma = 5e-9"),
            "surface.sigma",
        ),
        (
            with("pixel_size = 50e-9", "pixel_size = 50e-9\nradius = 1e-6"),
            "surface.radius",
        ),
        (
            with(
                "pixel_size = 50e-9",
                "pixel_size = 50e-9\ndistribution = \"exponential\"",
            ),
            "surface.distribution",
        ),
        (
            with("pixel_size = 50e-9", "pixel_size = -1.0"),
            "surface.pixel_size",
        ),
        (with("pixel_size = 50e-9", ""), "surface.pixel_size"),
        (
            with("summits = \"measured\"", "summits = \"nayak\""),
            "surface.summits",
        ),
        (
            with("# height_scale = 1.0", "height_scale = 0.0"),
            "surface.height_scale",
        ),
        (
            with("measured-topography.npy", "missing.npy"),
            "surface.topography",
        ),
        (
            with("measured-topography.npy", "map.gwy"),
            "surface.topography",
        ),
        // Summits of different radii need a law that scales with R.
        (
            with("kind = \"jkr\"", "kind = \"maugis\""),
            "surface.summits",
        ),
    ] {
        let got = field(&text);
        assert!(got.starts_with(&format!("{want} |")), "{want}: {got}");
    }
    // Topography keys without a topography, and a missing statistic without one.
    let default = asperity::study::DEFAULT_SCENE;
    let e = Scene::from_toml(&default.replacen(
        "nominal_area = 1e-8",
        "nominal_area = 1e-8\npixel_size = 1e-7",
        1,
    ))
    .unwrap_err();
    assert_eq!(e.field(), Some("surface.pixel_size"), "{e}");
    let e = Scene::from_toml(&default.replacen("density = 1e12", "", 1)).unwrap_err();
    assert_eq!(e.field(), Some("surface.density"), "{e}");
    // A scene without topography round-trips unchanged.
    let s = Scene::from_toml(default).unwrap();
    assert_eq!(Scene::from_toml(&s.to_toml()).unwrap(), s);
    // (Absent statistics read as NaN, so compare the text.)
    let s = Scene::from_toml(&example()).unwrap();
    let back = Scene::from_toml(&s.to_toml()).unwrap();
    assert_eq!(back.to_toml(), s.to_toml());
    assert!(!s.to_toml().contains("density"));
}
