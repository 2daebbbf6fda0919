//! Measured maps through the commands: `asperity surface FILE` and
//! `asperity bem FILE` on instrument files (the `"source"` record, pixel
//! sizes from the file or `--pixel-size`, channels, missing pixels, units
//! and their warnings, `--export`), scenes with `[surface] topography` on
//! an instrument file, and boundary elements on rectangular pixels.
#![cfg(feature = "study")]

use asperity::bem::{operator::love_rect, Options, Problem};
use asperity::study::{Plan, PlanMode, Scene};
use asperity::surface::HeightMap;
use asperity::topography::{read, Channel};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/topography");

fn data(name: &str) -> String {
    format!("{DIR}/{name}")
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("asperity-measured-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(args)
        .output()
        .expect("run asperity");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn json(args: &[&str]) -> Value {
    let (code, out, err) = run(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(out.trim()).expect("one JSON object")
}

fn error(args: &[&str]) -> String {
    let (code, out, err) = run(args);
    assert_eq!(code, 2, "{args:?}: {out} {err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    err
}

fn reference(name: &str) -> Value {
    let text = std::fs::read_to_string(data("reference.json")).unwrap();
    let v: Value = serde_json::from_str(&text).unwrap();
    v["samples"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["file"] == name)
        .unwrap()
        .clone()
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn source_gives_the_file_its_channel_unit_and_rectangular_pixels() {
    let v = json(&["surface", &data("x3p-2.x3p"), "--json"]);
    let s = &v["source"];
    let mut keys: Vec<&str> = s.as_object().unwrap().keys().map(String::as_str).collect();
    keys.sort_unstable();
    assert_eq!(
        keys,
        [
            "channel",
            "cols",
            "format",
            "missing",
            "pixel_size_m",
            "rows",
            "unit"
        ]
    );
    assert_eq!(s["format"], "x3p");
    assert_eq!(s["unit"], "m");
    assert_eq!(
        (s["rows"].as_u64(), s["cols"].as_u64()),
        (Some(650), Some(650))
    );
    assert_eq!(s["missing"], 0);
    let r = reference("x3p-2.x3p");
    for k in 0..2 {
        let (got, want) = (
            s["pixel_size_m"][k].as_f64().unwrap(),
            r["pixel_size_m"][k].as_f64().unwrap(),
        );
        assert!(rel(got, want) <= 1e-12, "{got} {want}");
    }
    let want = r["plane_rms_m"].as_f64().unwrap();
    assert!(rel(v["rms_height_m"].as_f64().unwrap(), want) <= 1e-12);
    assert_eq!(v["warnings"].as_array().unwrap().len(), 0, "{v}");
    // Nanoscope: nm in the file, the height channel by default.
    let v = json(&["surface", &data("di-3.di"), "--json"]);
    assert_eq!(v["source"]["format"], "di");
    assert_eq!(v["source"]["unit"], "nm");
    assert_eq!(v["source"]["channel"], "ZSensor");
}

#[test]
fn pixel_size_given_must_agree_or_wins_with_a_warning() {
    let f = data("di-3.di");
    let file_px = 3.90625e-08;
    // Agreeing to 1e-9: the file's, no warning.
    let v = json(&["surface", &f, "--json", "--pixel-size", "3.90625000001e-8"]);
    assert!(rel(v["source"]["pixel_size_m"][0].as_f64().unwrap(), file_px) < 1e-15);
    assert!(v["warnings"].as_array().unwrap().is_empty(), "{v}");
    // Disagreeing: --pixel-size wins, the warning names both values.
    let v = json(&["surface", &f, "--json", "--pixel-size", "4e-8"]);
    assert_eq!(v["source"]["pixel_size_m"][0].as_f64(), Some(4e-8));
    assert_eq!(v["source"]["pixel_size_m"][1].as_f64(), Some(4e-8));
    let w = v["warnings"][0].as_str().unwrap();
    assert!(
        w.contains("--pixel-size = 4e-8")
            && w.contains("3.906249")
            && w.contains("using --pixel-size"),
        "{w}"
    );
    // The text report lists it too.
    let (code, out, _) = run(&["surface", &f, "--pixel-size", "4e-8"]);
    assert_eq!(code, 0);
    assert!(out.contains("warning: --pixel-size = 4e-8"), "{out}");
    // A .npy map has none: --pixel-size is required, named.
    let npy = format!(
        "{}/examples/data/measured-topography.npy",
        env!("CARGO_MANIFEST_DIR")
    );
    let err = error(&["surface", &npy]);
    assert!(
        err.contains("--pixel-size") && err.contains("gives no pixel size"),
        "{err}"
    );
}

#[test]
fn channels_by_name_or_index_and_a_missing_one_named() {
    let f = data("di-3.di");
    let by_index = json(&["surface", &f, "--json", "--channel", "3"]);
    assert_eq!(by_index["source"]["channel"], "Height");
    let by_name = json(&["surface", &f, "--json", "--channel", "height"]);
    assert_eq!(by_name["source"]["channel"], "Height");
    assert_eq!(by_index["rms_height_m"], by_name["rms_height_m"]);
    let err = error(&["surface", &f, "--channel", "9"]);
    assert!(
        err.contains("--channel") && err.contains("no channel 9") && err.contains("3 'Height'"),
        "{err}"
    );
    // A channel that holds no heights is refused naming its unit.
    let err = error(&["surface", &f, "--channel", "Phase"]);
    assert!(err.contains("holds no heights"), "{err}");
}

#[test]
fn missing_pixels_are_refused_or_filled_when_asked() {
    let f = data("generated-2.gwy");
    let err = error(&["surface", &f, "--json"]);
    assert!(
        err.contains("generated-2.gwy")
            && err.contains("8 of 561 pixels are missing")
            && err.contains("--fill-missing"),
        "{err}"
    );
    let v = json(&["surface", &f, "--json", "--fill-missing"]);
    assert_eq!(v["source"]["missing"], 8);
    let want = reference("generated-2.gwy")["plane_rms_m"]
        .as_f64()
        .unwrap();
    assert!(rel(v["rms_height_m"].as_f64().unwrap(), want) <= 1e-12);
    // Its pixels of 5.9e-11 m along y are below 0.1 nm: a unit warning.
    let w = v["warnings"].as_array().unwrap();
    assert!(
        w.iter().any(|w| w
            .as_str()
            .unwrap()
            .contains("along y, 5.882e-11 m, is below 0.1 nm")),
        "{w:?}"
    );
}

#[test]
fn height_units_convert_npy_maps_and_wrong_units_warn() {
    // The example map in nm, read as m: an RMS of metres.
    let src = format!(
        "{}/examples/data/measured-topography.npy",
        env!("CARGO_MANIFEST_DIR")
    );
    let m = asperity::surface::npy::parse(&std::fs::read(&src).unwrap()).unwrap();
    let nm = m.scaled(1e9).unwrap();
    let path = scratch("in-nm.npy");
    std::fs::write(&path, asperity::surface::npy::to_bytes(&nm)).unwrap();
    let p = path.to_str().unwrap();
    let as_m = json(&["surface", p, "--pixel-size", "50e-9", "--json"]);
    let rms = as_m["rms_height_m"].as_f64().unwrap();
    assert!(rms > 1.0, "{rms}");
    let w = as_m["warnings"][0].as_str().unwrap();
    assert!(
        w.contains(&format!("the RMS height {rms:.3e} m is above 10 um"))
            && w.contains(&format!("nm ({:.3e} m)", rms * 1e-9))
            && w.contains("--height-unit"),
        "{w}"
    );
    let (_, text, _) = run(&["surface", p, "--pixel-size", "50e-9"]);
    assert!(text.contains("warning: the RMS height"), "{text}");
    let in_nm = json(&[
        "surface",
        p,
        "--pixel-size",
        "50e-9",
        "--height-unit",
        "nm",
        "--json",
    ]);
    let orig = json(&["surface", &src, "--pixel-size", "50e-9", "--json"]);
    assert!(
        rel(
            in_nm["rms_height_m"].as_f64().unwrap(),
            orig["rms_height_m"].as_f64().unwrap()
        ) < 1e-12
    );
    assert_eq!(in_nm["source"]["unit"], "nm");
    // No unit warning (the map's model error has its own).
    assert!(
        in_nm["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .all(|w| w.as_str().unwrap().starts_with("model error:")),
        "{}",
        in_nm["warnings"]
    );
    // A pixel of 50 (um read as m): above 1 mm, with the likely units.
    let v = json(&["surface", &src, "--pixel-size", "50", "--json"]);
    let w = v["warnings"][0].as_str().unwrap();
    assert!(
        w.contains("5.000e1 m, is above 1 mm") && w.contains("um (5.000e-5 m)"),
        "{w}"
    );
    // Instrument files give their own unit; bad units are named.
    let err = error(&["surface", &data("x3p-2.x3p"), "--height-unit", "nm"]);
    assert!(
        err.contains("--height-unit") && err.contains("gives its own unit"),
        "{err}"
    );
    let err = error(&["surface", p, "--pixel-size", "1e-7", "--height-unit", "mm"]);
    assert!(
        err.contains("--height-unit") && err.contains("nm, um, m"),
        "{err}"
    );
    let _ = std::fs::remove_file(&path);
}

#[test]
fn an_exported_x3p_reads_back_bit_for_bit_and_npy_too() {
    for name in ["x3p-2.x3p", "di-2.di", "generated-1.gwy", "opd-1.opd"] {
        let x3p = scratch(&format!("export-{name}.x3p"));
        let npy = scratch(&format!("export-{name}.npy"));
        for out in [&x3p, &npy] {
            let v = json(&[
                "surface",
                &data(name),
                "--fill-missing",
                "--json",
                "--export",
                out.to_str().unwrap(),
            ]);
            assert_eq!(v["source"]["format"], name.rsplit('.').next().unwrap());
        }
        let mut original = read(Path::new(&data(name)), &Channel::Default).unwrap();
        original.fill_missing().unwrap();
        let back = read(&x3p, &Channel::Default).unwrap();
        assert_eq!((back.rows, back.cols), (original.rows, original.cols));
        assert_eq!(back.pixel_size, original.pixel_size, "{name}");
        assert_eq!(back.unit, "m");
        assert!(
            back.heights
                .iter()
                .zip(&original.heights)
                .all(|(a, b)| a.to_bits() == b.to_bits()),
            "{name}: heights differ"
        );
        let n = read(&npy, &Channel::Default).unwrap();
        assert!(n
            .heights
            .iter()
            .zip(&original.heights)
            .all(|(a, b)| a.to_bits() == b.to_bits()));
        // Exporting again from the export gives the same bytes.
        let again = scratch(&format!("again-{name}.x3p"));
        json(&[
            "surface",
            x3p.to_str().unwrap(),
            "--json",
            "--export",
            again.to_str().unwrap(),
        ]);
        assert_eq!(std::fs::read(&again).unwrap(), std::fs::read(&x3p).unwrap());
        for p in [x3p, npy, again] {
            let _ = std::fs::remove_file(p);
        }
    }
    let err = error(&["surface", &data("sdf-1.sdf"), "--export", "out.sdf"]);
    assert!(
        err.contains("--export") && err.contains(".x3p or .npy"),
        "{err}"
    );
}

#[test]
fn bem_reads_instrument_files_with_rectangular_pixels() {
    // generated-1.gwy: 30 x 40 pixels of 100 nm x 200 nm.
    let v = json(&[
        "bem",
        &data("generated-1.gwy"),
        "--estar",
        "1e11",
        "--pressures",
        "1e7",
        "--periodic",
        "--json",
    ]);
    let s = &v["states"][0];
    let area = s["area_fraction"].as_f64().unwrap();
    assert!(area > 0.0 && area < 1.0, "{s}");
    assert_eq!(
        (v["rows"].as_u64(), v["cols"].as_u64()),
        (Some(30), Some(40))
    );
    // The same solve through the library with the file's pixels.
    let m = read(Path::new(&data("generated-1.gwy")), &Channel::Default).unwrap();
    let px = m.pixel_size.unwrap();
    let map = HeightMap::new(m.rows, m.cols, m.heights).unwrap();
    let p = Problem::with_pixels(&map, px, 1e11, true, &Options::default()).unwrap();
    let sol = p.solve_pressure(1e7, &Options::default(), None).unwrap();
    assert!(
        rel(sol.area_fraction(), area) < 1e-12,
        "{} {area}",
        sol.area_fraction()
    );
    let err = error(&[
        "bem",
        &data("generated-2.gwy"),
        "--estar",
        "1e11",
        "--pressures",
        "1e7",
    ]);
    assert!(err.contains("--fill-missing"), "{err}");
}

/// A map on pixels `dx` x `dy` and its transpose on `dy` x `dx` are the
/// same surface turned by 90 degrees: the same contact to roundoff.
#[test]
fn rectangular_pixels_transpose_exactly() {
    let (rows, cols) = (24, 32);
    let (dx, dy) = (1e-7, 1.7e-7);
    let h: Vec<f64> = (0..rows * cols)
        .map(|k| {
            let (i, j) = ((k / cols) as f64, (k % cols) as f64);
            1e-8 * ((0.7 * j).sin() * (0.45 * i).cos() + 0.3 * (1.3 * i + 0.2 * j).sin())
        })
        .collect();
    let t: Vec<f64> = (0..rows * cols)
        .map(|k| {
            let (j, i) = (k / rows, k % rows);
            h[i * cols + j]
        })
        .collect();
    let a = HeightMap::new(rows, cols, h).unwrap();
    let b = HeightMap::new(cols, rows, t).unwrap();
    let o = Options::default();
    for periodic in [true, false] {
        let pa = Problem::with_pixels(&a, (dx, dy), 1e11, periodic, &o).unwrap();
        let pb = Problem::with_pixels(&b, (dy, dx), 1e11, periodic, &o).unwrap();
        assert!(rel(pa.h_rms(), pb.h_rms()) < 1e-13);
        let sa = pa.solve_pressure(3e8, &o, None).unwrap();
        let sb = pb.solve_pressure(3e8, &o, None).unwrap();
        assert_eq!(sa.contact_pixels, sb.contact_pixels, "periodic {periodic}");
        let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
        assert!(
            rel(mean(&sa.gap), mean(&sb.gap)) < 1e-8,
            "periodic {periodic}"
        );
    }
    // Love's rectangle: symmetric in (x, dx) <-> (y, dy); a square's equals
    // the square pixel's.
    assert_eq!(love_rect(3e-7, 5e-7, dx, dy), love_rect(5e-7, 3e-7, dy, dx));
    assert_eq!(
        love_rect(3e-7, 5e-7, dx, dx),
        asperity::bem::operator::love_pixel(3e-7, 5e-7, dx)
    );
}

/// Hertz on rectangular pixels (dy = 2 dx): the contact radius from the
/// contact area (pixels dx dy) and the peak pressure as on square ones.
#[test]
fn hertz_on_rectangular_pixels() {
    let (nx, ny) = (128, 64);
    let (dx, dy) = (1.0 / nx as f64, 1.0 / ny as f64);
    let h: Vec<f64> = (0..nx * ny)
        .map(|k| {
            let x = ((k % nx) as f64 - nx as f64 / 2.0 + 0.5) * dx;
            let y = ((k / nx) as f64 - ny as f64 / 2.0 + 0.5) * dy;
            -(x * x + y * y) / 2.0
        })
        .collect();
    let map = HeightMap::new(ny, nx, h).unwrap();
    let o = Options::default();
    let p = Problem::with_pixels(&map, (dx, dy), 1.0, true, &o).unwrap();
    let s = p.solve_pressure(4e-3 / 3.0, &o, None).unwrap();
    let a = (s.contact_pixels as f64 * dx * dy / std::f64::consts::PI).sqrt();
    let pmax = s.pressure.iter().cloned().fold(0.0, f64::max);
    assert!((a / 0.1 - 1.0).abs() < 0.04, "a = {a}");
    assert!(
        (pmax / (0.2 / std::f64::consts::PI) - 1.0).abs() < 0.02,
        "p = {pmax}"
    );
}

#[test]
fn scenes_read_instrument_files_with_their_pixels() {
    let base = Path::new(DIR);
    let scene = |surface: &str| {
        format!(
            "[materials]\ne1 = 79e9\nnu1 = 0.42\ne2 = 79e9\nnu2 = 0.42\n\n[surface]\n{surface}\n\n\
             [adhesion]\nw = 0.5\nz0 = 0.3e-9\n\n[law]\nkind = \"jkr\"\n\n[program]\n\
             closest_separation = 0.0\npoints = 20\n"
        )
    };
    let plan = |s: &str| {
        Plan::new_in(
            &Scene::from_toml(&scene(s)).unwrap(),
            PlanMode::Planned,
            base,
        )
    };
    // The file's pixels (100 nm x 200 nm), no pixel_size needed.
    let p = plan("topography = \"generated-1.gwy\"").unwrap();
    let c = &p.topography.as_ref().unwrap().characterisation;
    assert_eq!(
        (c.pixel_size_m, c.pixel_size_y_m),
        (1e-7, 2.0000000000000002e-7)
    );
    assert!(
        rel(
            c.moments.rms_height(),
            reference("generated-1.gwy")["plane_rms_m"]
                .as_f64()
                .unwrap()
        ) < 1e-12
    );
    assert!(
        p.warnings.iter().all(|w| !w.to_string().contains("pixel")),
        "{:?}",
        p.warnings
    );
    // A pixel_size that disagrees wins, with a warning naming both.
    let p = plan("topography = \"generated-1.gwy\"\npixel_size = 1e-7").unwrap();
    let c = &p.topography.as_ref().unwrap().characterisation;
    assert_eq!((c.pixel_size_m, c.pixel_size_y_m), (1e-7, 1e-7));
    assert!(
        p.warnings.iter().any(|w| {
            let w = w.to_string();
            w.contains("surface.pixel_size = 1e-7 m disagrees") && w.contains("2e-7")
        }),
        "{:?}",
        p.warnings
    );
    // Missing pixels: refused, or filled with fill_missing.
    let e = plan("topography = \"generated-2.gwy\"").unwrap_err();
    assert_eq!(e.field(), Some("surface.topography"));
    assert!(e.to_string().contains("surface.fill_missing = true"), "{e}");
    let e = plan("topography = \"generated-1.gwy\"\nheight_unit = \"nm\"").unwrap_err();
    assert_eq!(e.field(), Some("surface.height_unit"), "{e}");
    // A .npy map in um read as m warns naming the key; height_unit
    // converts it.
    let npy = format!(
        "{}/examples/data/measured-topography.npy",
        env!("CARGO_MANIFEST_DIR")
    );
    let m = asperity::surface::npy::parse(&std::fs::read(&npy).unwrap()).unwrap();
    let path = scratch("scene-um.npy");
    std::fs::write(
        &path,
        asperity::surface::npy::to_bytes(&m.scaled(1e6).unwrap()),
    )
    .unwrap();
    let s = format!("topography = \"{}\"\npixel_size = 50e-9", path.display());
    // Its summits are then far beyond GW's range: the refusal says why.
    let e = plan(&s).unwrap_err();
    let text = e.to_string();
    assert!(
        text.contains("note: the RMS height") && text.contains("surface.height_unit"),
        "{text}"
    );
    let p = plan(&format!("{s}\nheight_unit = \"um\"")).unwrap();
    assert!(
        p.warnings.iter().all(|w| !w.to_string().contains("10 um")),
        "{:?}",
        p.warnings
    );
    let orig = plan(&format!("topography = \"{npy}\"\npixel_size = 50e-9")).unwrap();
    let (a, b) = (
        &p.topography.as_ref().unwrap().characterisation,
        &orig.topography.as_ref().unwrap().characterisation,
    );
    assert!(rel(a.moments.rms_height(), b.moments.rms_height()) < 1e-12);
    let e = Scene::from_toml(&scene(&format!("{s}\nheight_unit = \"mm\""))).unwrap_err();
    assert!(e.to_string().contains("nm, um, m"), "{e}");
    let _ = std::fs::remove_file(&path);
}
