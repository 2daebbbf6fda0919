//! The converged boundary-element reference numbers kept in
//! `tests/data/bem_reference.json` (too slow for `cargo test`), and the
//! shared 256^2 self-affine map `examples/data/selfaffine-256.npy` that
//! `benches/peers/tamaas_bem.py` solves with Tamaas.
//!
//! ```text
//! cargo run --release --example bem_reference -- map      # writes the map
//! cargo run --release --example bem_reference > tests/data/bem_reference.json
//! ```
//!
//! CPU times are this process's user + system time (Linux `/proc/self/stat`).

use asperity::bem::{Options, Problem};
use asperity::spectrum::{synthesis::random_phase_map, Normalisation, Spectrum};
use asperity::surface::{npy, HeightMap};
use serde_json::{json, Value};
use std::f64::consts::PI;

/// The reference map: H = 0.8, wavevectors 4 to 64 (2 pi/L), RMS gradient
/// 0.1, L = 100 um, 256^2, seed 1.
pub fn selfaffine_map() -> (HeightMap, f64) {
    let (n, l) = (256, 1e-4);
    let q0 = 2.0 * PI / l;
    let s = Spectrum::self_affine(
        0.8,
        4.0 * q0,
        4.0 * q0,
        64.0 * q0,
        Normalisation::SlopeRms(0.1),
    )
    .unwrap();
    (
        random_phase_map(&s, n, n, l / n as f64, 1).unwrap(),
        l / n as f64,
    )
}

fn cpu_s() -> f64 {
    asperity::study::cpu_time::process_cpu_seconds().unwrap_or(f64::NAN)
}

/// A sphere of radius 1 in a cell of side 1 on `n x n` pixels (centred on a
/// pixel corner), E* = 1, at the Hertz load of a = 0.1: (a/a_H, p_max/p_H).
fn hertz(n: usize, periodic: bool) -> Value {
    let dx = 1.0 / n as f64;
    let c = n as f64 / 2.0 - 0.5;
    let h: Vec<f64> = (0..n * n)
        .map(|k| {
            let (i, j) = ((k / n) as f64 - c, (k % n) as f64 - c);
            -(i * i + j * j) * dx * dx / 2.0
        })
        .collect();
    let map = HeightMap::new(n, n, h).unwrap();
    let opts = Options {
        tolerance: 1e-10,
        ..Default::default()
    };
    let t = cpu_s();
    let prob = Problem::new(&map, dx, 1.0, periodic, &opts).unwrap();
    let a_h = 0.1;
    let load = 4.0 * a_h * a_h * a_h / 3.0;
    let s = prob.solve_pressure(load, &opts, None).unwrap();
    let a = (s.contact_pixels as f64 / PI).sqrt() * dx;
    let pmax = s.pressure.iter().cloned().fold(0.0, f64::max);
    json!({
        "n": n, "periodic": periodic,
        "a_over_a_hertz": a / a_h,
        "pmax_over_p_hertz": pmax / (2.0 * a_h / PI),
        "iterations": s.iterations, "residual": s.residual, "cpu_s": cpu_s() - t,
    })
}

fn rough() -> Value {
    let (map, dx) = selfaffine_map();
    let estar = 1e9;
    let mut rows = Vec::new();
    for tol in [1e-6, 1e-8, 1e-10, 1e-12] {
        let opts = Options {
            tolerance: tol,
            ..Default::default()
        };
        let t = cpu_s();
        let prob = Problem::new(&map, dx, estar, true, &opts).unwrap();
        let s = prob.solve_pressure(0.01 * estar, &opts, None).unwrap();
        let cpu = cpu_s() - t;
        let t = cpu_s();
        let g = prob.solve_gap(s.mean_gap, &opts, None).unwrap();
        rows.push(json!({
            "tolerance": tol,
            "area_fraction": s.area_fraction(),
            "mean_gap_m": s.mean_gap,
            "clusters": prob.clusters(&s).len(),
            "iterations": s.iterations, "residual": s.residual, "cpu_s": cpu,
            "gap_control": {"pressure_Pa": g.mean_pressure, "area_fraction": g.area_fraction(),
                            "iterations": g.iterations, "residual": g.residual, "cpu_s": cpu_s() - t},
        }));
    }
    json!({"map": "examples/data/selfaffine-256.npy", "pixel_size_m": dx, "estar_Pa": estar,
           "pressure_Pa": 0.01 * estar, "by_tolerance": rows})
}

/// Adhesion on the same map under mean-gap control.
fn adhesive() -> Value {
    let (map, dx) = selfaffine_map();
    let estar = 1e9;
    let (w, rho) = (0.02, 2.0 * dx);
    let opts = Options {
        tolerance: 1e-10,
        ..Default::default()
    };
    let prob = Problem::new(&map, dx, estar, true, &opts).unwrap();
    let plain = Problem::new(&map, dx, estar, true, &opts).unwrap();
    let prob = prob.with_adhesion(w, rho).unwrap();
    let h_rms = plain.h_rms();
    let mut rows = Vec::new();
    let mut warm = None;
    for f in [1.0, 0.5, 0.25] {
        let g = f * h_rms;
        let t = cpu_s();
        let s = prob.solve_gap(g, &opts, warm.as_ref()).unwrap();
        let cpu = cpu_s() - t;
        let n = plain.solve_gap(g, &opts, None).unwrap();
        rows.push(json!({
            "mean_gap_m": g, "pressure_Pa": s.mean_pressure, "area_fraction": s.area_fraction(),
            "iterations": s.iterations, "residual": s.residual, "cpu_s": cpu,
            "without_adhesion": {"pressure_Pa": n.mean_pressure, "area_fraction": n.area_fraction()},
        }));
        warm = Some(s);
    }
    json!({"adhesion_energy_J_per_m2": w, "adhesion_range_m": rho, "states": rows})
}

fn main() {
    if std::env::args().nth(1).as_deref() == Some("hertz") {
        println!("{}", hertz(128, std::env::args().nth(2).is_none()));
        return;
    }
    if std::env::args().nth(1).as_deref() == Some("map") {
        let (map, _) = selfaffine_map();
        std::fs::write("examples/data/selfaffine-256.npy", npy::to_bytes(&map)).unwrap();
        eprintln!("wrote examples/data/selfaffine-256.npy");
        return;
    }
    let hertz: Vec<Value> = [
        (128, true),
        (256, true),
        (512, true),
        (128, false),
        (256, false),
    ]
    .iter()
    .map(|&(n, p)| hertz(n, p))
    .collect();
    let out = json!({
        "provenance": "cargo run --release --example bem_reference (asperity boundary elements)",
        "hertz": hertz,
        "rough": rough(),
        "adhesive": adhesive(),
    });
    println!("{}", serde_json::to_string_pretty(&out).unwrap());
}
