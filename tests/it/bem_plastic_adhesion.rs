//! Adhesion with an elastic–perfectly-plastic cap (the gap solver with the
//! interaction extended below `g = 0` by `phi(0) - H g`): the elastic
//! adhesive limit bit for bit, the non-adhesive plastic limit, and an
//! independent dense solution of the same discrete problem
//! (`tests/data/bem_plastic_adhesion_reference.py`).

use asperity::bem::{Options, Problem, Solution};
use asperity::surface::{npy, HeightMap};
use serde_json::Value;
use std::process::Command;

fn data(name: &str) -> String {
    format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn reference() -> (Value, HeightMap) {
    let text = std::fs::read_to_string(data("bem_plastic_adhesion_reference.json")).unwrap();
    let map = npy::parse(&std::fs::read(data("bem_plastic_map32.npy")).unwrap()).unwrap();
    (serde_json::from_str(&text).unwrap(), map)
}

const E: f64 = 1e9;
const DX: f64 = 1e-6;
const H: f64 = 1e8;
const W: f64 = 0.2;
const RHO: f64 = 5e-8;

fn opts() -> Options {
    Options {
        tolerance: 1e-12,
        ..Options::default()
    }
}

fn problem(map: &HeightMap, adhesion: Option<f64>, hardness: Option<f64>) -> Problem {
    let mut p = Problem::new(map, DX, E, true, &opts()).unwrap();
    if let Some(w) = adhesion {
        p = p.with_adhesion(w, RHO).unwrap();
    }
    if let Some(h) = hardness {
        p = p.with_hardness(h).unwrap();
    }
    p
}

fn same_bits(a: &Solution, b: &Solution, what: &str) {
    assert_eq!(a.pressure, b.pressure, "{what}: pressure");
    assert_eq!(a.gap, b.gap, "{what}: gap");
    assert_eq!(a.mean_pressure, b.mean_pressure, "{what}");
    assert_eq!(a.mean_gap, b.mean_gap, "{what}");
    assert_eq!(a.contact_pixels, b.contact_pixels, "{what}");
    assert_eq!(a.iterations, b.iterations, "{what}");
    assert_eq!(b.plastic_pixels, 0, "{what}");
}

/// A hardness above every reaction of the adhesive elastic solution leaves
/// it bit for bit, under mean-gap and load control: no pixel goes below
/// `g = 0`, so the iterates are those of the elastic solver (the extra
/// terms add exact zeros).
#[test]
fn a_hardness_above_every_pressure_is_the_adhesive_elastic_solution_bit_for_bit() {
    let (_, map) = reference();
    let elastic = problem(&map, Some(W), None);
    for gap in [3e-8, 6e-8] {
        let s = elastic.solve_gap(gap, &opts(), None).unwrap();
        let pmax = s.pressure.iter().cloned().fold(0.0, f64::max);
        let plastic = problem(&map, Some(W), Some(1.5 * pmax));
        let c = plastic.solve_gap(gap, &opts(), None).unwrap();
        same_bits(&s, &c, &format!("gap {gap:e}"));
    }
    // Load control's root-find visits smaller gaps (larger pressures) than
    // the answer's: a hardness far above.
    let s = elastic.solve_pressure(1e7, &opts(), None).unwrap();
    let pmax = s.pressure.iter().cloned().fold(0.0, f64::max);
    let c = problem(&map, Some(W), Some(1e3 * pmax))
        .solve_pressure(1e7, &opts(), None)
        .unwrap();
    same_bits(&s, &c, "pressure 1e7");
}

/// A vanishing work of adhesion (`w = 1e-9 J/m^2`: a tension `w/rho` of
/// 0.02 Pa, 2e-10 of the hardness) gives the non-adhesive plastic solution
/// (`plastic`, another algorithm in the pressure): the same contact and
/// plastic pixels, pressures to 1e-6 H (both solvers stop at 1e-12 of their
/// residual scales).
#[test]
fn a_vanishing_adhesion_is_the_plastic_solution() {
    let (_, map) = reference();
    let adhesive = Problem::new(&map, DX, E, true, &opts())
        .unwrap()
        .with_adhesion(1e-9, RHO)
        .unwrap()
        .with_hardness(H)
        .unwrap();
    let plastic = problem(&map, None, Some(H));
    for p in [1e7, 5e7, 9e7] {
        let a = adhesive.solve_pressure(p, &opts(), None).unwrap();
        let b = plastic.solve_pressure(p, &opts(), None).unwrap();
        assert_eq!(a.contact_pixels, b.contact_pixels, "{p:e}");
        assert_eq!(a.plastic_pixels, b.plastic_pixels, "{p:e}");
        assert!(b.plastic_pixels > 0);
        for (x, y) in a.pressure.iter().zip(&b.pressure) {
            assert!((x - y).abs() < 1e-6 * H, "{p:e}: {x} {y}");
        }
        let rel = |x: f64, y: f64| (x / y - 1.0).abs();
        assert!(rel(a.mean_gap, b.mean_gap) < 1e-6, "{p:e}");
        assert!(
            rel(a.plastic_volume_per_area, b.plastic_volume_per_area) < 1e-6,
            "{p:e}"
        );
    }
}

/// Against the independent dense solution (L-BFGS-B on the potential in
/// split variables, polished by Newton's method on fixed sets, its KKT
/// conditions verified to 1e-10): the same contact and plastic pixels
/// (fractions to 1e-6, i.e. exactly on 1024 pixels), mean gap and displaced
/// volume to 1e-6 relative, under load control; under mean-gap control at
/// the reference's mean gap, its mean pressure to 1e-6 relative. The
/// reference's `w = 0` cases against the non-adhesive plastic solver check
/// that both formulations are one problem.
#[test]
fn against_the_independent_dense_solution() {
    let (r, map) = reference();
    let adhesive = problem(&map, Some(W), Some(H));
    let plastic = problem(&map, None, Some(H));
    let rel = |x: f64, y: f64| (x / y - 1.0).abs();
    for case in r["cases"].as_array().unwrap() {
        let get = |k: &str| case[k].as_f64().unwrap();
        let p = get("pressure_Pa");
        let w = get("adhesion_energy_J_m2");
        let prob = if w > 0.0 { &adhesive } else { &plastic };
        let what = format!("w {w}, p {p:e}");
        let check = |s: &Solution, how: &str| {
            assert!(
                (s.area_fraction() - get("area_fraction")).abs() < 1e-6,
                "{what} {how}: A/A0 {} {}",
                s.area_fraction(),
                get("area_fraction")
            );
            assert!(
                (s.plastic_fraction() - get("plastic_fraction")).abs() < 1e-6,
                "{what} {how}: A_pl/A0 {} {}",
                s.plastic_fraction(),
                get("plastic_fraction")
            );
            assert!(
                rel(s.plastic_volume_per_area, get("plastic_volume_per_area_m")) < 1e-6,
                "{what} {how}: V {} {}",
                s.plastic_volume_per_area,
                get("plastic_volume_per_area_m")
            );
        };
        let s = prob.solve_pressure(p, &opts(), None).unwrap();
        check(&s, "load");
        assert!(
            rel(s.mean_gap, get("mean_gap_m")) < 1e-6,
            "{what}: gap {} {}",
            s.mean_gap,
            get("mean_gap_m")
        );
        if w > 0.0 {
            let s = prob.solve_gap(get("mean_gap_m"), &opts(), None).unwrap();
            check(&s, "gap");
            assert!(
                rel(s.mean_pressure, p) < 1e-6,
                "{what}: pressure {}",
                s.mean_pressure
            );
        }
    }
}

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("run asperity");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// `asperity bem` on the 32^2 map (1 um pixels, E* = 1 GPa) with `more`.
fn bem_map32<'a>(more: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec![
        "bem",
        "tests/data/bem_plastic_map32.npy",
        "--pixel-size",
        "1e-6",
        "--estar",
        "1e9",
    ];
    args.extend_from_slice(more);
    args
}

/// `asperity bem --hardness --adhesion-energy --adhesion-range` on a
/// periodic map: the reference's adhesive state at 0.03 E*; padded, refused
/// naming `--periodic` (exit 2).
#[test]
fn cli_hardness_with_adhesion() {
    let (r, _) = reference();
    let case = &r["cases"][2];
    assert_eq!(case["pressure_Pa"].as_f64(), Some(3e7));
    let mut args = bem_map32(&[
        "--pressures",
        "3e7",
        "--hardness",
        "1e8",
        "--adhesion-energy",
        "0.2",
        "--adhesion-range",
        "5e-8",
        "--tolerance",
        "1e-12",
        "--json",
    ]);
    let (code, _, err) = run(&args);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--periodic"), "{err}");
    args.push("--periodic");
    let (code, out, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(out.trim()).unwrap();
    let st = &v["states"][0];
    let pa = st["plastic_area_fraction"].as_f64().unwrap();
    assert!(
        (pa - case["plastic_fraction"].as_f64().unwrap()).abs() < 1e-6,
        "{st}"
    );
    let per = st["plastic_volume_per_area_m"].as_f64().unwrap();
    let want = case["plastic_volume_per_area_m"].as_f64().unwrap();
    assert!((per / want - 1.0).abs() < 1e-6, "{per} {want}");
}

/// Strong short-range adhesion (w = 0.05 J/m^2, rho = 1 nm on 1 um
/// pixels) makes the mean pressure jump with the mean gap: 5 MPa lies in
/// a jump, so no state on the mean-gap path has it. The run said 1.30 MPa
/// (tolerance 1e-8) or 5.07 MPa as if they were 5 MPa; now it is refused
/// naming the pressure, the jump's gap and the state it reached, and a
/// pressure below the first jump (1 MPa) still runs. (On this map with
/// 1 um pixels each pixel snaps on its own: 2, 10, 20 and 30 MPa all lie in
/// jumps.)
#[test]
fn a_pressure_inside_an_adhesive_jump_is_refused_not_misreported() {
    let map = npy::parse(&std::fs::read(data("bem_plastic_map32.npy")).unwrap()).unwrap();
    let p = Problem::new(&map, DX, E, true, &opts())
        .unwrap()
        .with_adhesion(0.05, 1e-9)
        .unwrap()
        .with_hardness(H)
        .unwrap();
    let o = Options {
        tolerance: 1e-8,
        ..Options::default()
    };
    let err = p.solve_pressure(5e6, &o, None).unwrap_err();
    assert_eq!(err.field(), Some("pressure"), "{err}");
    let text = err.to_string();
    assert!(
        text.contains("jumps across it") && text.contains("mean gap"),
        "{text}"
    );
    let mut args = bem_map32(&[
        "--periodic",
        "--hardness",
        "1e8",
        "--adhesion-energy",
        "0.05",
        "--adhesion-range",
        "1e-9",
        "--tolerance",
        "1e-8",
        "--pressures",
        "5e6",
    ]);
    let (code, _, err) = run(&args);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("--pressures") && err.contains("5e6 Pa"),
        "{err}"
    );
    // Below the first jump the state exists and has the asked mean pressure.
    args.pop();
    args.extend(["1e6", "--json"]);
    let (code, out, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(out.trim()).unwrap();
    let got = v["states"][0]["pressure_Pa"].as_f64().unwrap();
    assert!((got / 1e6 - 1.0).abs() < 1e-8, "{got}");
}
