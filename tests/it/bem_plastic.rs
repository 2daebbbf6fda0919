//! Elastic–perfectly-plastic boundary elements (pressure capped at the
//! hardness): the elastic limit bit for bit, the fully plastic limit, the
//! hard case of a slope-0.08 self-affine map with `H = 0.1 E*` converging
//! up to the fully plastic load, and an independent active-set solution of
//! the same discrete problem (`tests/data/bem_plastic_reference.py`).

use asperity::bem::{Options, Problem, Solution};
use asperity::spectrum::synthesis::random_phase_map;
use asperity::spectrum::{Normalisation, Spectrum};
use asperity::surface::{npy, HeightMap};
use serde_json::Value;
use std::f64::consts::PI;
use std::process::Command;

/// A self-affine periodic map (Hurst 0.8, roll-off at a quarter of the
/// side, cut at Nyquist) of RMS gradient `slope` on `n^2` pixels of 1 um.
fn self_affine(n: usize, slope: f64, seed: u64) -> (HeightMap, f64) {
    let dx = 1e-6;
    let l = n as f64 * dx;
    let s = Spectrum::self_affine(
        0.8,
        2.0 * PI / l,
        8.0 * PI / l,
        PI / dx,
        Normalisation::SlopeRms(slope),
    )
    .unwrap();
    (random_phase_map(&s, n, n, dx, seed).unwrap(), dx)
}

fn solve(prob: &Problem, p: f64, opts: &Options) -> Solution {
    let s = prob.solve_pressure(p, opts, None).unwrap();
    assert!(s.residual < opts.tolerance, "{}", s.residual);
    s
}

/// A hardness above every elastic pressure leaves the elastic solution:
/// the same contact pixels, no plastic one, the same pressures and gaps to
/// the solvers' tolerance (1e-12 of h_rms in the gap: 1e-9 of the largest
/// pressure and of h_rms are far above what either leaves).
#[test]
fn a_hardness_above_every_elastic_pressure_is_the_elastic_solution() {
    let (map, dx) = self_affine(64, 0.08, 3);
    let e = 1e9;
    let opts = Options {
        tolerance: 1e-12,
        ..Options::default()
    };
    for periodic in [true, false] {
        let elastic = Problem::new(&map, dx, e, periodic, &opts).unwrap();
        for p in [1e6, 1e7] {
            let s = solve(&elastic, p, &opts);
            let pmax = s.pressure.iter().cloned().fold(0.0, f64::max);
            let plastic = Problem::new(&map, dx, e, periodic, &opts)
                .unwrap()
                .with_hardness(1.01 * pmax)
                .unwrap();
            let c = solve(&plastic, p, &opts);
            let what = format!("periodic {periodic}, p {p:e}");
            assert_eq!(c.plastic_pixels, 0, "{what}");
            assert_eq!(c.plastic_volume_per_area, 0.0);
            assert_eq!(c.contact(), s.contact(), "{what}");
            for (a, b) in c.pressure.iter().zip(&s.pressure) {
                assert!((a - b).abs() < 1e-9 * pmax, "{what}: {a} {b}");
            }
            assert!(
                (c.mean_gap - s.mean_gap).abs() < 1e-9 * plastic.h_rms(),
                "{what}"
            );
        }
    }
}

/// The exact limits: `P = H` is the fully plastic state (every pixel at
/// `H`, gap 0); the plastic area is `P/H` less the elastic pixels' share,
/// `A_pl/A0 = P/H - sum_{0 < p < H} p/(N H)` (the mean held exactly);
/// `P > H` is refused naming the pressure.
#[test]
fn the_fully_plastic_limits() {
    let (map, dx) = self_affine(64, 0.08, 5);
    let (e, h) = (1e9, 1e8);
    let opts = Options::default();
    for periodic in [true, false] {
        let prob = Problem::new(&map, dx, e, periodic, &opts)
            .unwrap()
            .with_hardness(h)
            .unwrap();
        let n = (64 * 64) as f64;
        for f in [0.3, 0.7, 0.95] {
            let s = solve(&prob, f * h, &opts);
            let elastic: f64 = s
                .pressure
                .iter()
                .cloned()
                .filter(|p| *p > 0.0 && *p < h)
                .sum();
            let exact = f - elastic / (n * h);
            assert!(
                (s.plastic_fraction() - exact).abs() < 1e-12,
                "{} {exact}",
                s.plastic_fraction()
            );
        }
        let s = solve(&prob, h, &opts);
        assert_eq!(s.plastic_pixels, 64 * 64);
        assert_eq!(s.mean_gap, 0.0);
        let err = prob.solve_pressure(1.5 * h, &opts, None).unwrap_err();
        assert!(err.to_string().contains("pressure"), "{err}");
    }
}

/// The hard case ContactMechanics' users reported, on an `n`^2 map: the slope-0.08
/// self-affine map, `E* = 1 GPa`, `H = 0.1 E*`, tolerance 1e-8 within 500
/// applications of `K`.
fn hard_case(n: usize) -> (Problem, Options, f64) {
    let (map, dx) = self_affine(n, 0.08, 7);
    let e = 1e9;
    let opts = Options {
        tolerance: 1e-8,
        max_iterations: 500,
        ..Options::default()
    };
    let prob = Problem::new(&map, dx, e, true, &opts)
        .unwrap()
        .with_hardness(0.1 * e)
        .unwrap();
    (prob, opts, e)
}

/// The slope-0.08 self-affine map with `H = 0.1 E*` at 128^2: every load
/// up to the fully plastic one converges to 1e-8 within 500 iterations.
#[test]
fn the_hard_plastic_case_converges_up_to_the_fully_plastic_load() {
    let (prob, opts, e) = hard_case(128);
    let mut last = (0.0, 0.0);
    for f in [
        0.01, 0.03, 0.05, 0.07, 0.08, 0.09, 0.095, 0.099, 0.0999, 0.1,
    ] {
        let s = prob
            .solve_pressure(f * e, &opts, None)
            .unwrap_or_else(|err| panic!("P = {f} E*: {err}"));
        assert!(s.residual < 1e-8 && s.iterations <= 500);
        // Area and plastic area grow with the load.
        assert!(s.area_fraction() >= last.0 && s.plastic_fraction() >= last.1);
        last = (s.area_fraction(), s.plastic_fraction());
    }
    assert_eq!(last, (1.0, 1.0));
    // A mean pressure above the hardness (0.3 E* > H = 0.1 E*) has none.
    assert!(prob.solve_pressure(0.3 * e, &opts, None).is_err());
}

/// The same kind of map at 512^2, where the solver with every inner solve
/// to a tenth of the tolerance from `p = P` needed 528-641 iterations
/// (`docs/performance.md`): the load that costs most here (measured at
/// 0.01-0.099 E*: 169-217, the most at 0.07 E*; about 4 s a load in the
/// test build, so one load) converges to 1e-8 within 500.
#[test]
fn the_hard_plastic_case_at_512_converges_within_500_iterations() {
    let (prob, opts, e) = hard_case(512);
    let s = prob
        .solve_pressure(0.07 * e, &opts, None)
        .unwrap_or_else(|err| panic!("P = 0.07 E*: {err}"));
    assert!(
        s.residual < 1e-8 && s.iterations <= 500,
        "{} iterations, residual {}",
        s.iterations,
        s.residual
    );
}

fn reference() -> Value {
    let text = std::fs::read_to_string(data("bem_plastic_reference.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

fn data(name: &str) -> String {
    format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// Against the independent active-set solution of the same discrete
/// problem (`tests/data/bem_plastic_reference.py`): the same contact and
/// plastic pixels (area fractions to 1e-6, i.e. exactly on 1024 pixels);
/// mean gap and displaced volume to 1e-6 relative (the solver stops at a
/// residual of 1e-12 h_rms; the reference is exact to rounding).
#[test]
fn against_the_independent_active_set_solution() {
    let r = reference();
    let map = npy::parse(&std::fs::read(data("bem_plastic_map32.npy")).unwrap()).unwrap();
    let dx = r["pixel_size_m"].as_f64().unwrap();
    let e = r["contact_modulus_Pa"].as_f64().unwrap();
    let h = r["hardness_Pa"].as_f64().unwrap();
    let opts = Options {
        tolerance: 1e-12,
        ..Options::default()
    };
    for case in r["cases"].as_array().unwrap() {
        let periodic = case["periodic"].as_bool().unwrap();
        let prob = Problem::new(&map, dx, e, periodic, &opts)
            .unwrap()
            .with_hardness(h)
            .unwrap();
        let get = |k: &str| case[k].as_f64().unwrap();
        let p = get("pressure_Pa");
        let s = solve(&prob, p, &opts);
        let what = format!("periodic {periodic}, p {p:e}");
        assert!(
            (s.area_fraction() - get("area_fraction")).abs() < 1e-6,
            "{what}: {}",
            s.area_fraction()
        );
        assert!(
            (s.plastic_fraction() - get("plastic_fraction")).abs() < 1e-6,
            "{what}: {}",
            s.plastic_fraction()
        );
        let rel = |a: f64, b: f64| (a / b - 1.0).abs();
        assert!(
            rel(s.mean_gap, get("mean_gap_m")) < 1e-6,
            "{what}: gap {} {}",
            s.mean_gap,
            get("mean_gap_m")
        );
        assert!(
            rel(s.plastic_volume_per_area, get("plastic_volume_per_area_m")) < 1e-6,
            "{what}: volume {} {}",
            s.plastic_volume_per_area,
            get("plastic_volume_per_area_m")
        );
    }
}

/// A bad hardness is named with its range; hardness and adhesion combine
/// in either order (`tests/it/bem_plastic_adhesion.rs`), and a padded map
/// with adhesion is refused naming `periodic`, hardness or not.
#[test]
fn bad_hardness_is_named_and_adhesion_combines_with_it() {
    let (map, dx) = self_affine(16, 0.08, 1);
    let opts = Options::default();
    let prob = |periodic| Problem::new(&map, dx, 1e9, periodic, &opts).unwrap();
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let e = prob(true).with_hardness(bad).unwrap_err().to_string();
        assert!(e.contains("hardness") && e.contains("(0, inf)"), "{e}");
    }
    let a = prob(true)
        .with_hardness(1e8)
        .unwrap()
        .with_adhesion(0.2, 5e-8)
        .unwrap();
    let b = prob(true)
        .with_adhesion(0.2, 5e-8)
        .unwrap()
        .with_hardness(1e8)
        .unwrap();
    assert_eq!(a.hardness(), b.hardness());
    let e = prob(false)
        .with_hardness(1e8)
        .unwrap()
        .with_adhesion(0.2, 5e-8)
        .unwrap_err();
    assert!(e.to_string().contains("periodic"), "{e}");
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

const MAP: [&str; 7] = [
    "bem",
    "tests/data/bem_plastic_map32.npy",
    "--pixel-size",
    "1e-6",
    "--estar",
    "1e9",
    "--periodic",
];

#[test]
fn cli_hardness_prints_the_plastic_outputs_and_names_bad_values() {
    let mut args = MAP.to_vec();
    args.extend(["--pressures", "5e6,5e7", "--hardness", "1e8", "--json"]);
    let (code, out, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(out.trim()).unwrap();
    assert_eq!(v["hardness_Pa"].as_f64(), Some(1e8));
    let r = reference();
    for (k, st) in v["states"].as_array().unwrap().iter().enumerate() {
        for key in [
            "plastic_area_fraction",
            "plastic_volume_m3",
            "plastic_volume_per_area_m",
            "iterations",
            "residual",
        ] {
            assert!(st.get(key).is_some(), "{key} in {st}");
        }
        // The reference's periodic cases 0.005 E* and 0.05 E*.
        let case = &r["cases"][[0, 2][k]];
        let pa = st["plastic_area_fraction"].as_f64().unwrap();
        assert!((pa - case["plastic_fraction"].as_f64().unwrap()).abs() < 1e-6);
        let vol = st["plastic_volume_m3"].as_f64().unwrap();
        let per = case["plastic_volume_per_area_m"].as_f64().unwrap();
        assert!((vol / (per * 1024e-12) - 1.0).abs() < 1e-6, "{vol}");
    }
    assert!(v["warnings"]
        .to_string()
        .contains("elastic-perfectly-plastic"));
    // Without a hardness the keys are absent (the elastic JSON unchanged).
    let mut args = MAP.to_vec();
    args.extend(["--pressures", "5e6", "--json"]);
    let (code, out, _) = run(&args);
    assert_eq!(code, 0);
    assert!(!out.contains("plastic") && !out.contains("hardness"));
    let bad: [(&[&str], &str); 3] = [
        (&["--pressures", "5e6", "--hardness", "-1"], "--hardness"),
        (&["--pressures", "5e6", "--hardness", "inf"], "--hardness"),
        (
            &["--pressures", "5e6,2e8", "--hardness", "1e8"],
            "--pressures",
        ),
    ];
    for (extra, name) in bad {
        let mut args = MAP.to_vec();
        args.extend(extra);
        let (code, _, err) = run(&args);
        assert_eq!(code, 2, "{extra:?}: {err}");
        assert!(err.contains(name), "{extra:?}: {err}");
    }
    let (_, help, _) = run(&["bem", "--help"]);
    assert!(help.contains("--hardness"));
}

/// A plastic solve at its iteration cap is the program's failure (exit 1
/// with the residual), or with `--allow-unconverged` its last iterate
/// flagged `converged: false`: as every other solver (it was exit 2,
/// "outside what the solver reaches").
#[test]
fn a_plastic_solve_at_the_cap_is_exit_one_or_flagged() {
    let mut args = MAP.to_vec();
    args.extend([
        "--pressures",
        "5e7",
        "--hardness",
        "1e8",
        "--max-iterations",
        "3",
        "--json",
    ]);
    let (code, _, err) = run(&args);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("iteration cap") && err.contains("residual"),
        "{err}"
    );
    args.push("--allow-unconverged");
    let (code, out, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(out.trim()).unwrap();
    let st = &v["states"][0];
    assert_eq!(st["converged"], Value::Bool(false), "{st}");
    assert!(st["residual"].as_f64().unwrap() > 1e-10, "{st}");
}
