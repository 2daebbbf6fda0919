//! The two-zone (meniscus + solid) law where a scene may put it: the rough
//! sphere (Greenwood–Tripp over the two-zone summits) runs with it, dry at
//! `relative_humidity = 0` bit for bit, and its pull-off is more tensile
//! than the dry one but within the bump's rigid two-zone bound; lognormal
//! summit radii (a radius spread) are refused naming the key, because
//! neither wet law scales with the radius.

use serde_json::Value;
use std::process::Command;

fn run(scene: &str) -> (Option<i32>, Value, String) {
    let dir = std::env::temp_dir().join(format!(
        "asperity-wet-scenes-{}-{}",
        std::process::id(),
        scene.len()
    ));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("scene.toml");
    std::fs::write(&path, scene).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .arg("run")
        .arg(&path)
        .arg("--json")
        .output()
        .unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    let v = serde_json::from_str(String::from_utf8_lossy(&o.stdout).trim()).unwrap_or(Value::Null);
    (
        o.status.code(),
        v,
        String::from_utf8_lossy(&o.stderr).into(),
    )
}

fn humid() -> String {
    let root = env!("CARGO_MANIFEST_DIR");
    std::fs::read_to_string(format!("{root}/examples/scenes/rf-mems-switch-humid.toml")).unwrap()
}

#[test]
fn rough_sphere_with_the_two_zone_law() {
    // The humid switch on a 5 um bump with DMT summits: the planner makes
    // them two-zone summits (gold's lambda 1.8: Derjaguin's meniscus is not
    // within rtol).
    let bump = |rh: &str| {
        humid()
            .replace("[adhesion]", "[sphere]\nradius = 5e-6\n\n[adhesion]")
            .replace("nominal_area = 1e-10", "")
            .replace("kind = \"kogut-etsion\"", "kind = \"dmt\"")
            .replace(
                "relative_humidity = 0.5",
                &format!("relative_humidity = {rh}"),
            )
    };
    let (code, wet, err) = run(&bump("0.5"));
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(wet["law"], "two-zone (meniscus + solid)");
    let (code, dry0, err) = run(&bump("0.0"));
    assert_eq!(code, Some(0), "{err}");
    let (_, dry, _) = run(&bump("0.0").replace("relative_humidity = 0.0", ""));
    // RH = 0: the dry run, bit for bit.
    assert_eq!(dry0["pull_off_load_N"], dry["pull_off_load_N"]);
    assert_eq!(dry0["law"], dry["law"]);
    let (pw, pd) = (
        wet["pull_off_load_N"].as_f64().unwrap(),
        dry["pull_off_load_N"].as_f64().unwrap(),
    );
    // Menisci add attraction; neither adhesion can pull harder than on a
    // smooth rigid bump, 2 pi R (w + w_m), w_m = 2 gamma for water wetting
    // both sides.
    let bound = 2.0 * std::f64::consts::PI * 5e-6 * (0.5 + 2.0 * 0.0728);
    assert!(pw < pd && pd <= 0.0, "wet {pw} dry {pd}");
    assert!(-pw < bound, "{pw} beyond {bound}");
}

#[test]
fn lognormal_radii_are_refused_with_either_wet_law() {
    for kind in ["kogut-etsion", "maugis"] {
        let scene = humid().replace("kind = \"kogut-etsion\"", &format!("kind = \"{kind}\""))
            + "\n[montecarlo]\nsummits = 1000\nradius_log_std = 0.3\n";
        let (code, _, err) = run(&scene);
        assert_eq!(code, Some(2), "{kind}: {err}");
        assert!(err.contains("montecarlo.radius_log_std"), "{kind}: {err}");
        assert!(err.contains("meniscus"), "{kind}: {err}");
    }
}
