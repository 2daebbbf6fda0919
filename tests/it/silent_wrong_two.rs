//! Never silently wrong, round two: messages
//! that name the key the user wrote, plastic fits beyond their range,
//! extreme shaped profiles, the calibration cache, leftovers and strict
//! files. Each case failed on the code before its fix.
use crate::common::cli;
use cli::{bin, example, json, run, tmp};
use std::path::{Path, PathBuf};

/// A scene from an example with each line starting with `key` replaced by
/// `line` (the key must be there).
fn edited(name: &str, edits: &[(&str, &str)]) -> String {
    let mut lines: Vec<String> = example(name).lines().map(String::from).collect();
    for (key, line) in edits {
        let l = lines
            .iter_mut()
            .find(|l| l.starts_with(key))
            .unwrap_or_else(|| panic!("{name} has no line starting with {key}"));
        *l = line.to_string();
    }
    lines.join("\n")
}

/// Runs `scene` (written as `name`) in `dir`; exit code and stderr.
fn run_scene(dir: &Path, name: &str, scene: &str) -> (i32, String) {
    std::fs::write(dir.join(name), scene).unwrap();
    let (code, _, err) = run(&["run", name, "--out", &format!("out-{name}")], dir);
    (code, err)
}

/// Listed states were blamed on `program.max_load` /
/// `program.closest_separation`, keys the scene does not have.
#[test]
fn listed_states_are_blamed_by_their_own_key() {
    let dir = tmp("listed");
    let (code, err) = run_scene(
        &dir,
        "loads.toml",
        &edited(
            "mems-gold.toml",
            &[("closest_separation", "loads = [1e-6, 1e3]")],
        ),
    );
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("error: program.loads:"), "{err}");
    assert!(!err.contains("max_load"), "{err}");
    let (code, err) = run_scene(
        &dir,
        "separations.toml",
        &edited(
            "mems-gold.toml",
            &[("closest_separation", "separations = [5e-9, -1e-3]")],
        ),
    );
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("error: program.separations:"), "{err}");
}

/// `yield_strength = 1e3` was refused blaming
/// `program.closest_separation` (an impossible real area that the elastic
/// law on the same program does not reach).
#[test]
fn an_absurd_yield_strength_is_blamed_on_itself() {
    let dir = tmp("yield");
    let (code, err) = run_scene(
        &dir,
        "ys.toml",
        &edited(
            "gold-rf-mems-plastic.toml",
            &[("yield_strength", "yield_strength = 1e3")],
        ),
    );
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("error: materials.yield_strength:"), "{err}");
    assert!(err.contains("1e7 .. 1e10 Pa"), "{err}");
    // Below any solid's (1e-300 Pa on the default study left a listed load
    // unreachable, blamed on program.loads): refused up front, with the range.
    for (key, line) in [
        ("materials.yield_strength", "yield_strength = 1e-300"),
        ("materials.yield_strength", "yield_strength = 1e300"),
    ] {
        let (code, err) = run_scene(
            &dir,
            "ys-range.toml",
            &edited("rf-mems-switch.toml", &[("yield_strength", line)]),
        );
        assert_eq!(code, 2, "{err}");
        assert!(err.contains(&format!("error: {key} = ")), "{err}");
        assert!(err.contains("[1000, 1e20]"), "{err}");
    }
}

/// `montecarlo-gold.toml` at `rtol = 0.1` (inside the documented
/// `[1e-12, 0.1]`) was refused naming `materials.e2`, then `adhesion.z0`:
/// the law table's tolerance `0.1 x 0.1` rounded to 0.010000000000000002,
/// just above the table's bound 1e-2.
#[test]
fn the_largest_documented_rtol_runs() {
    let dir = tmp("rtol");
    let (code, err) = run_scene(
        &dir,
        "mc.toml",
        &edited("montecarlo-gold.toml", &[("rtol", "rtol = 0.1")]),
    );
    assert_eq!(code, 0, "{err}");
    let s = json(&dir.join("out-mc.toml/summary.json"));
    assert_eq!(s["rtol"].as_f64(), Some(0.1));
}

/// A Jackson–Green run whose highest summit's Hertz estimate is
/// a/R = 0.28 (no warning before) reaches a/R = 0.46 by the fit's own
/// contact radius (`a/R = sqrt(delta/R) (w/1.9)^(B/2)`): warned.
#[test]
fn plastic_fits_beyond_their_range_are_warned() {
    let dir = tmp("jg");
    let scene = edited(
        "gold-rf-mems-plastic.toml",
        &[
            ("kind", "kind = \"jackson-green\""),
            ("separations", "separations = [0.0, -30e-9, -60e-9]"),
        ],
    );
    let (code, err) = run_scene(&dir, "jg.toml", &scene);
    assert_eq!(code, 0, "{err}");
    let s = json(&dir.join("out-jg.toml/summary.json"));
    let warnings: Vec<&str> = s["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|w| w.as_str())
        .collect();
    let w = warnings
        .iter()
        .find(|w| w.contains("law's own contact radius"))
        .unwrap_or_else(|| panic!("{warnings:?}"));
    // JG by hand: omega_c = (pi C Y/(2 E*))^2 R = 0.533 nm, w = 78.6/0.533,
    // B = 0.14 exp(23 Y/E) = 0.157: a/R = sqrt(0.0786) (w/1.9)^0.0787 = 0.46.
    assert!(w.contains("a/R = 0.46"), "{w}");
    // The unchanged example stays quiet about it.
    let (code, err) = run_scene(&dir, "ke.toml", &example("gold-rf-mems-plastic.toml"));
    assert_eq!(code, 0, "{err}");
    let s = json(&dir.join("out-ke.toml/summary.json"));
    assert!(
        !s["warnings"].to_string().contains("a/R"),
        "{}",
        s["warnings"]
    );
}

/// Extreme shaped profiles ended in a quadrature failure (exit 1)
/// or ran for minutes (`coefficient = 1e300` on a power law: a contact
/// radius of 1.7e-77 m at one sigma); a 1 nm true sphere under 200 nm
/// roughness ran on past its equator. Now refused up front, naming the key
/// and its range.
#[test]
fn extreme_shaped_profiles_are_refused_naming_the_key() {
    let dir = tmp("shaped");
    let cases = [
        (
            "power.toml",
            vec![
                ("profile =", "profile = \"power\""),
                ("tan_angle", "exponent = 4\ncoefficient = 1e300"),
            ],
            "error: law.coefficient:",
            "allowed 7.500e10 ..= 9.259e30",
        ),
        (
            "sphere.toml",
            vec![
                ("profile =", "profile = \"sphere\""),
                ("tan_angle", "radius = 1e-9"),
            ],
            "error: law.radius:",
            "allowed >= 2e-7 m",
        ),
        (
            "cone.toml",
            vec![("tan_angle", "tan_angle = 1e-300")],
            "error: law.tan_angle:",
            "allowed",
        ),
    ];
    for (name, edits, field, range) in cases {
        let scene = edited("conical-summits.toml", &edits);
        let start = std::time::Instant::now();
        let (code, err) = run_scene(&dir, name, &scene);
        assert_eq!(code, 2, "{name}: {err}");
        assert!(err.contains(field), "{name}: {err}");
        assert!(err.contains(range), "{name}: {err}");
        assert!(start.elapsed().as_secs() < 30, "{name}: refused late");
    }
    // The documented power law (the example's comment) stays accepted.
    let doc = edited(
        "conical-summits.toml",
        &[
            ("profile =", "profile = \"power\""),
            ("tan_angle", "exponent = 4\ncoefficient = 1e15"),
        ],
    );
    std::fs::write(dir.join("doc.toml"), doc).unwrap();
    let (code, _, err) = run(&["run", "doc.toml", "--plan"], &dir);
    assert_eq!(code, 0, "{err}");
}

/// `nominal_area = nan` was taken as "not given" (NaN is the
/// unset mark); a NaN written anywhere is refused naming its key.
#[test]
fn a_written_nan_is_not_an_absent_key() {
    let dir = tmp("nan");
    for (key, line, field) in [
        ("nominal_area", "nominal_area = nan", "surface.nominal_area"),
        ("density", "density = nan", "surface.density"),
    ] {
        let scene = edited("mems-gold.toml", &[(key, line)]);
        std::fs::write(dir.join("s.toml"), scene).unwrap();
        let (code, _, err) = run(&["run", "s.toml", "--plan"], &dir);
        assert_eq!(code, 2, "{err}");
        assert!(err.contains(&format!("error: {field}")), "{err}");
    }
}

/// A UTF-8 byte-order mark was accepted in scenes but refused in
/// CSVs (spots, height maps); now accepted in both, with the same numbers.
#[test]
fn a_byte_order_mark_is_accepted_in_csvs() {
    let dir = tmp("bom");
    let body = "x_m,y_m,radius_m\n0,0,1e-6\n1e-5,0,1e-6\n";
    std::fs::write(dir.join("plain.csv"), body).unwrap();
    std::fs::write(dir.join("bom.csv"), format!("\u{feff}{body}")).unwrap();
    let args = |f: &'static str| ["spots", f, "--resistivity", "2.44e-8", "--json"];
    let (c1, plain, e1) = run(&args("plain.csv"), &dir);
    let (c2, bom, e2) = run(&args("bom.csv"), &dir);
    assert_eq!((c1, c2), (0, 0), "{e1} {e2}");
    assert_eq!(plain, bom);
    let map: String = (0..8)
        .map(|i| {
            (0..8)
                .map(|j| format!("{:e}", 1e-9 * (((i * 7 + j * 3) % 5) as f64)))
                .collect::<Vec<_>>()
                .join(",")
                + "\n"
        })
        .collect();
    std::fs::write(dir.join("m.csv"), &map).unwrap();
    std::fs::write(dir.join("mb.csv"), format!("\u{feff}{map}")).unwrap();
    let args = |f: &'static str| ["surface", f, "--pixel-size", "1e-8", "--json"];
    let (c1, plain, e1) = run(&args("m.csv"), &dir);
    let (c2, bom, e2) = run(&args("mb.csv"), &dir);
    assert_eq!((c1, c2), (0, 0), "{e1} {e2}");
    assert_eq!(plain, bom);
}

/// 24 stray bytes after a `.npy` array were accepted; the file is
/// now refused naming it.
#[test]
fn stray_bytes_after_npy_data_are_refused() {
    let dir = tmp("npy");
    let root = env!("CARGO_MANIFEST_DIR");
    let mut bytes = std::fs::read(format!("{root}/examples/data/selfaffine-256.npy")).unwrap();
    std::fs::write(dir.join("good.npy"), &bytes).unwrap();
    bytes.extend_from_slice(&[0u8; 24]);
    std::fs::write(dir.join("long.npy"), &bytes).unwrap();
    let (code, _, err) = run(&["surface", "good.npy", "--pixel-size", "1e-8"], &dir);
    assert_eq!(code, 0, "{err}");
    let (code, _, err) = run(&["surface", "long.npy", "--pixel-size", "1e-8"], &dir);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("long.npy"), "{err}");
    assert!(err.contains("24 stray bytes"), "{err}");
}

/// Outputs are written whole or not at all (temporary file and
/// rename): a run leaves no `*.tmp` beside its outputs, and a run whose
/// `summary.json` cannot be written exits 1 leaving no temporary file.
#[test]
fn outputs_leave_no_temporary_files() {
    let dir = tmp("atomic");
    std::fs::write(dir.join("s.toml"), example("mems-gold.toml")).unwrap();
    std::fs::create_dir_all(dir.join("o/summary.json/x")).unwrap();
    let (code, _, err) = run(&["run", "s.toml", "--out", "o"], &dir);
    assert_eq!(code, 1, "{err}");
    let names: Vec<String> = std::fs::read_dir(dir.join("o"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert!(!names.iter().any(|n| n.contains("tmp")), "{names:?}");
}

/// Every array under a key `load_bar` in `v`, times `k`.
fn scale_load_bars(v: &mut serde_json::Value, k: f64) {
    match v {
        serde_json::Value::Object(m) => {
            for (key, x) in m.iter_mut() {
                if key == "load_bar" {
                    if let Some(xs) = x.as_array_mut() {
                        for y in xs {
                            *y = serde_json::json!(y.as_f64().unwrap() * k);
                        }
                    }
                } else {
                    scale_load_bars(x, k);
                }
            }
        }
        serde_json::Value::Array(xs) => xs.iter_mut().for_each(|x| scale_load_bars(x, k)),
        _ => {}
    }
}

/// A parseable but altered calibration cache entry (loads x1.5)
/// was trusted silently (+50 % on the maximum load). Entries now carry a
/// checksum; a bad one is recomputed, with a warning naming the file.
#[test]
fn an_altered_calibration_cache_entry_is_recomputed_with_a_note() {
    let dir = tmp("cache");
    let cache = dir.join("cache");
    let scene = edited(
        "calibrated-gold.toml",
        &[("rtol", "rtol = 1e-3"), ("points", "points = 40")],
    );
    std::fs::write(dir.join("s.toml"), scene).unwrap();
    let go = |out: &str| {
        let o = bin()
            .args(["run", "s.toml", "--out", out])
            .env("ASPERITY_CACHE", &cache)
            .current_dir(&dir)
            .output()
            .unwrap();
        assert_eq!(
            o.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
        json(&dir.join(out).join("summary.json"))
    };
    let first = go("a");
    let entries: Vec<PathBuf> = std::fs::read_dir(&cache)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    assert_eq!(entries.len(), 1, "{entries:?}");
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&entries[0]).unwrap()).unwrap();
    scale_load_bars(&mut v, 1.5);
    std::fs::write(&entries[0], v.to_string()).unwrap();
    let second = go("b");
    let max = |s: &serde_json::Value| s["max_load"].as_f64().unwrap();
    assert_eq!(max(&second), max(&first), "the altered entry was used");
    let w = second["warnings"].to_string();
    assert!(w.contains("fails its checksum"), "{w}");
    assert!(w.contains(&entries[0].display().to_string()), "{w}");
    // Stored again intact: the third run uses it quietly.
    let third = go("c");
    assert_eq!(max(&third), max(&first));
    assert!(!third["warnings"].to_string().contains("checksum"));
}

/// A map far beyond the memory (a 20000 x 20000 `.npy` aborted on
/// allocation under an 8 GB limit) is refused before it is read, with the
/// estimate. Here a sparse 80 GB file (100000 x 100000 doubles, no disk
/// blocks): about 160 GB to characterise from the command line (16 bytes a
/// pixel for a mapped `.npy`), 240 GB in a scene, more than any test
/// machine has.
#[test]
fn a_map_beyond_the_memory_is_refused_with_an_estimate() {
    let dir = tmp("huge");
    let mut header =
        b"{'descr': '<f8', 'fortran_order': False, 'shape': (100000, 100000), }".to_vec();
    let pad = 64 - (10 + header.len() + 1) % 64;
    header.extend(std::iter::repeat_n(b' ', pad));
    header.push(b'\n');
    let mut bytes = b"\x93NUMPY\x01\x00".to_vec();
    bytes.extend((header.len() as u16).to_le_bytes());
    bytes.extend(&header);
    let path = dir.join("huge.npy");
    std::fs::write(&path, &bytes).unwrap();
    let f = std::fs::OpenOptions::new().write(true).open(&path).unwrap();
    f.set_len(bytes.len() as u64 + 8 * 100_000 * 100_000)
        .unwrap();
    drop(f);
    // Refused from the header, no page of the 80 GB touched (it was paged
    // in first: 16 s of system time, 22 GB resident).
    let started = std::time::Instant::now();
    let (code, _, err) = run(&["surface", "huge.npy", "--pixel-size", "1e-8"], &dir);
    let took = started.elapsed().as_secs_f64();
    assert!(took < 5.0, "{took} s");
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("huge.npy"), "{err}");
    assert!(err.contains("160.0 GB"), "{err}");
    assert!(err.contains("of memory available"), "{err}");
    // The same map as a scene's topography.
    let scene = edited(
        "measured-topography.toml",
        &[("topography", "topography = \"huge.npy\"")],
    );
    std::fs::write(dir.join("s.toml"), scene).unwrap();
    let (code, _, err) = run(&["run", "s.toml", "--out", "o"], &dir);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("surface.topography"), "{err}");
    assert!(err.contains("240.0 GB"), "{err}");
    // Under a 4 GB address-space limit the file cannot be mapped: it is
    // refused with its size, not read whole (it was: an abort on allocation).
    let out = std::process::Command::new("sh")
        .arg("-c")
        .arg(format!(
            "ulimit -v 4000000 && exec '{}' surface huge.npy --pixel-size 1e-8",
            env!("CARGO_BIN_EXE_asperity")
        ))
        .current_dir(&dir)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("huge.npy"), "{err}");
    assert!(err.contains("cannot be memory-mapped"), "{err}");
    assert!(err.contains("80.0 GB"), "{err}");
    std::fs::remove_file(&path).unwrap();
}

/// A tabulated profile of 100,000 points ran for many minutes
/// without a word (22 s of CPU at 1,000 points); beyond the documented
/// 2,000 points it is refused up front with the cost estimate.
#[test]
fn a_huge_tabulated_profile_is_refused_with_its_cost() {
    let dir = tmp("tabulated");
    let n = 100_000;
    let r: Vec<String> = (0..n)
        .map(|i| format!("{:e}", 4e-6 * i as f64 / (n - 1) as f64))
        .collect();
    let f: Vec<String> = (0..n)
        .map(|i| {
            let x = 4e-6 * i as f64 / (n - 1) as f64;
            format!("{:e}", x * x / 2e-5)
        })
        .collect();
    let profile = format!(
        "profile = \"tabulated\"\nprofile_r = [{}]\nprofile_f = [{}]",
        r.join(","),
        f.join(",")
    );
    let scene = edited(
        "conical-summits.toml",
        &[("profile =", &profile), ("tan_angle", "")],
    );
    let start = std::time::Instant::now();
    let (code, err) = run_scene(&dir, "t.toml", &scene);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("error: law.profile_r: 100000 points"), "{err}");
    assert!(err.contains("760 s of CPU"), "{err}");
    assert!(err.contains("allowed 3 ..= 2000 points"), "{err}");
    assert!(start.elapsed().as_secs() < 30);
}
