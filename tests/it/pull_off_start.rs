//! `LoadingModel::pull_off` with a far start: the issue reported a
//! plausible `start = 1e-2 m` giving -14.3 uN instead of -78.5 uN with no
//! warning. The search samples up to `min(start, interaction onset)` and
//! refines by golden section; for a law felt everywhere (Bradley's
//! Lennard-Jones tail: infinite onset) the samples are 156 um apart and the
//! refinement still finds the minimum. This guards that the pull-off does
//! not depend on how far the start is, for long- and short-range laws.
use asperity::gw::{GwModel, RoughSurface};
use asperity::heights::{Gaussian, HeightDistribution, TruncatedGaussian};
use asperity::law::LawKind;
use asperity::loading::LoadingModel;
use asperity::material::AsperityContact;
use std::sync::Arc;

#[test]
fn a_far_start_finds_the_same_pull_off() {
    let c = AsperityContact::gold_microswitch();
    // The gold switch surface: eta = 1e12 m^-2, R = 1 um, sigma = 5 nm,
    // 100 um x 100 um.
    let surface = RoughSurface::new(1e12, 1e-6, 5e-9, 1e-8).unwrap();
    // Bradley (rigid spheres: the Lennard-Jones tail, felt far out) needs
    // heights bounded above.
    let truncated: Arc<dyn HeightDistribution> = Arc::new(TruncatedGaussian::new(4.0).unwrap());
    for (kind, heights) in [
        (LawKind::Bradley, truncated),
        (
            LawKind::Maugis,
            Arc::new(Gaussian::new()) as Arc<dyn HeightDistribution>,
        ),
        (LawKind::Jkr, Arc::new(Gaussian::new())),
    ] {
        let law = Arc::from(kind.build(&c).unwrap());
        let m = GwModel::new(surface, heights, law).unwrap();
        let closest = 5e-9;
        // The reference: evenly sampled over 60 nm (12 sigma), where the
        // whole adhesive range lies, with 400 samples.
        let near = m.pull_off(closest, 65e-9, 400).unwrap().unwrap();
        for start in [1e-6, 1e-4, 1e-2] {
            let far = m.pull_off(closest, start, 64).unwrap().unwrap();
            // Both refined by golden section to the separation tolerance:
            // the loads agree to the model's tolerance.
            assert!(
                (far.load / near.load - 1.0).abs() < 1e-6,
                "{kind:?} start {start:e}: {:e} vs {:e} N",
                far.load,
                near.load
            );
        }
    }
}

/// A start inside the law's reach, below the separation of the most
/// tensile load, cuts the pull-off off: the search says so
/// (`PullOff::at_start`), and a program's own start is what
/// `pull_off_in` searches up to.
#[test]
fn a_start_that_cuts_the_answer_off_is_flagged() {
    let c = AsperityContact::gold_microswitch();
    let surface = RoughSurface::new(1e12, 1e-6, 5e-9, 1e-8).unwrap();
    let law = Arc::from(LawKind::Jkr.build(&c).unwrap());
    let m = GwModel::new(surface, Arc::new(Gaussian::new()), law).unwrap();
    let closest = 5e-9;
    let full = m.pull_off(closest, f64::INFINITY, 64).unwrap().unwrap();
    assert!(!full.at_start, "{full:?}");
    // Just short of the full search's pull-off separation (the load is
    // tensile there, still falling): cut off, and less tensile.
    let start = full.separation - 0.02 * (full.separation - closest);
    let cut = m.pull_off(closest, start, 64).unwrap().unwrap();
    assert!(cut.at_start, "{cut:?}");
    assert_eq!(cut.separation, start);
    assert!(cut.load > full.load);
    let program = asperity::loading::LoadingProgram::new(start, closest, 50).unwrap();
    assert_eq!(m.pull_off_in(&program, 64).unwrap(), Some(cut));
}

/// Coming down from a start where the load already exceeds the target
/// would miss the crossing above it: refused, naming the start.
#[test]
fn a_start_below_the_target_load_is_refused() {
    let c = AsperityContact::gold_microswitch();
    let surface = RoughSurface::new(1e12, 1e-6, 5e-9, 1e-8).unwrap();
    let law = Arc::from(LawKind::Hertz.build(&c).unwrap());
    let m = GwModel::new(surface, Arc::new(Gaussian::new()), law).unwrap();
    let d = m.separation_at_load(1e-4, 40e-9).unwrap();
    let e = m
        .separation_at_load(1e-4, d - 1e-9)
        .unwrap_err()
        .to_string();
    assert!(e.contains("start_separation"), "{e}");
    assert!((m.separation_at_load(1e-4, d + 1e-9).unwrap() - d).abs() < 1e-15);
}

/// Through a scene: a `start_separation` short of the pull-off separation
/// gives the warning with the start and the load found there.
#[test]
fn a_scene_whose_start_cuts_the_pull_off_warns() {
    let base = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/scenes/mems-gold.toml"
    ))
    .unwrap()
    .replacen("kind = \"auto\"", "kind = \"jkr\"", 1)
    .replacen("points = 200", "points = 60", 1);
    let dir = std::env::temp_dir().join(format!("asperity-cut-start-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let run = |text: &str| -> serde_json::Value {
        let path = dir.join("scene.toml");
        std::fs::write(&path, text).unwrap();
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_asperity"))
            .args(["run", path.to_str().unwrap(), "--json", "--out"])
            .arg(dir.join("out"))
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        serde_json::from_slice(&o.stdout).unwrap()
    };
    let full = run(&base);
    let sep = full["pull_off_separation"].as_f64().unwrap();
    let quiet = full["warnings"].to_string();
    assert!(!quiet.contains("has not pulled off"), "{quiet}");
    let start = sep - 0.02 * (sep - 5e-9);
    let cut = run(&base.replacen(
        "# start_separation = 40e-9",
        &format!("start_separation = {start:e} #"),
        1,
    ));
    let w = cut["warnings"].to_string();
    assert!(w.contains("has not pulled off within the program"), "{w}");
    assert!(w.contains("program.start_separation"), "{w}");
    assert!(cut["pull_off_load"].as_f64().unwrap() > full["pull_off_load"].as_f64().unwrap());
}
