//! Boundary elements: Hertz in a periodic cell and on a padded
//! (non-periodic) map, convergence with the mesh, the rough self-affine
//! map against its stored converged reference, load and gap control
//! agreeing, adhesion, clusters and the memory bound. Small grids only: the
//! converged 512^2 and 256^2 numbers are in `tests/data/bem_reference.json`
//! (`cargo run --release --example bem_reference`).
//!
//! Tolerances: Hertz's contact radius from the pixel count carries an
//! error of about one perimeter pixel's share, `~0.5/(a/dx)` (4 % at
//! `a = 12.8 px`, 2 % at 25.6 px); `p_max` converges faster (< 1 %).

use asperity::bem::{memory_estimate, Options, Problem};
use asperity::surface::{npy, HeightMap};
use serde_json::Value;
use std::f64::consts::PI;

/// The R = 1 paraboloid `-r^2/2` on an `n^2` grid of the unit cell
/// (pixel `dx = 1/n`), its apex at pixel coordinates `(c, c)`.
fn sphere_cell(n: usize, c: f64) -> HeightMap {
    let dx = 1.0 / n as f64;
    let h: Vec<f64> = (0..n * n)
        .map(|k| {
            let (i, j) = ((k / n) as f64 - c, (k % n) as f64 - c);
            -(i * i + j * j) * dx * dx / 2.0
        })
        .collect();
    HeightMap::new(n, n, h).unwrap()
}

/// R = 1 sphere in a unit cell, E* = 1, at the Hertz load of a = 0.1.
fn hertz(n: usize, periodic: bool) -> (f64, f64) {
    let dx = 1.0 / n as f64;
    let map = sphere_cell(n, n as f64 / 2.0 - 0.5);
    let opts = Options::default();
    let prob = Problem::new(&map, dx, 1.0, periodic, &opts).unwrap();
    let s = prob.solve_pressure(4e-3 / 3.0, &opts, None).unwrap();
    assert!(s.residual < opts.tolerance);
    let a = (s.contact_pixels as f64 / PI).sqrt() * dx;
    let pmax = s.pressure.iter().cloned().fold(0.0, f64::max);
    (a / 0.1 - 1.0, pmax / (0.2 / PI) - 1.0)
}

#[test]
fn hertz_periodic_and_padded_converge_with_the_mesh() {
    let (a64, p64) = hertz(64, true);
    let (a128, p128) = hertz(128, true);
    let (a256, p256) = hertz(256, true);
    assert!(a128.abs() < 0.03 && p128.abs() < 0.01, "{a128} {p128}");
    assert!(a256.abs() < 0.015 && p256.abs() < 0.01, "{a256} {p256}");
    assert!(a256.abs() < a64.abs(), "{a64} {a256}");
    let _ = p64;
    let (pa, pp) = hertz(128, false);
    assert!(pa.abs() < 0.03 && pp.abs() < 0.01, "padded: {pa} {pp}");
}

fn reference() -> Value {
    let text = std::fs::read_to_string("tests/data/bem_reference.json").unwrap();
    serde_json::from_str(&text).unwrap()
}

fn selfaffine() -> HeightMap {
    npy::parse(&std::fs::read("examples/data/selfaffine-256.npy").unwrap()).unwrap()
}

/// The shipped map's stored problem and converged answer: pixel size (m),
/// mean pressure (Pa), area fraction and mean gap (m) at tolerance 1e-12.
fn rough_reference() -> (f64, f64, f64, f64) {
    let r = reference();
    let rough = &r["rough"];
    let best = rough["by_tolerance"].as_array().unwrap().last().unwrap();
    let f = |v: &Value, k: &str| v[k].as_f64().unwrap();
    (
        f(rough, "pixel_size_m"),
        f(rough, "pressure_Pa"),
        f(best, "area_fraction"),
        f(best, "mean_gap_m"),
    )
}

#[test]
fn rough_map_matches_its_converged_reference_and_gap_control_agrees() {
    let (dx, p, a_ref, g_ref) = rough_reference();
    let map = selfaffine();
    let opts = Options {
        tolerance: 1e-8,
        ..Default::default()
    };
    let prob = Problem::new(&map, dx, 1e9, true, &opts).unwrap();
    let s = prob.solve_pressure(p, &opts, None).unwrap();
    // Area stable to 1e-5 between tolerance 1e-8 and the 1e-12 reference.
    assert!(
        (s.area_fraction() - a_ref).abs() < 1e-5,
        "{} {a_ref}",
        s.area_fraction()
    );
    assert!(
        (s.mean_gap / g_ref - 1.0).abs() < 1e-6,
        "{} {g_ref}",
        s.mean_gap
    );
    // Gap control at that mean gap returns the pressure.
    let g = prob.solve_gap(s.mean_gap, &opts, None).unwrap();
    assert!(
        (g.mean_pressure / p - 1.0).abs() < 1e-5,
        "{}",
        g.mean_pressure
    );
    assert!((g.area_fraction() - s.area_fraction()).abs() < 1e-4);
    // Clusters partition the contact pixels.
    let cl = prob.clusters(&s);
    assert_eq!(cl.iter().map(|c| c.pixels).sum::<usize>(), s.contact_pixels);
}

/// The stiffness-preconditioned Polonsky–Keer iteration (periodic maps):
/// 37 iterations at tolerance 1e-8 on the shipped 256^2 map at 0.01 E*,
/// where the plain iteration needed 109 and Tamaas 2.9.0's 117 (both
/// counted by `benches/peers/tamaas_iterations.py` before the change); the
/// bound 45 leaves room for rounding across targets, far below 109. The
/// answer is the converged reference's (same contact pixels, mean gap to
/// 1e-9 at tolerance 1e-12).
#[test]
fn the_preconditioned_iteration_needs_a_third_of_the_plain_iterations() {
    let (dx, p, a_ref, g_ref) = rough_reference();
    let map = selfaffine();
    let solve = |tolerance: f64| {
        let opts = Options {
            tolerance,
            ..Default::default()
        };
        let prob = Problem::new(&map, dx, 1e9, true, &opts).unwrap();
        prob.solve_pressure(p, &opts, None).unwrap()
    };
    let s = solve(1e-8);
    assert!(s.iterations <= 45, "{} iterations", s.iterations);
    let t = solve(1e-12);
    assert!(t.iterations <= 60, "{} iterations", t.iterations);
    assert_eq!(t.area_fraction(), a_ref);
    assert!(
        (t.mean_gap / g_ref - 1.0).abs() < 1e-9,
        "{} {g_ref}",
        t.mean_gap
    );
}

#[test]
fn padded_gap_control_inverts_load_control() {
    let n = 48;
    let dx = 1.0 / n as f64;
    let h: Vec<f64> = (0..n * n)
        .map(|k| {
            let (x, y) = ((k % n) as f64 * dx, (k / n) as f64 * dx);
            1e-3 * ((2.0 * PI * 3.0 * x).cos()
                + (2.0 * PI * 2.0 * y).sin()
                + 0.5 * (2.0 * PI * 5.0 * (x + y)).cos())
        })
        .collect();
    let map = HeightMap::new(n, n, h).unwrap();
    let opts = Options::default();
    let prob = Problem::new(&map, dx, 1.0, false, &opts).unwrap();
    let s = prob.solve_pressure(1e-3, &opts, None).unwrap();
    let g = prob.solve_gap(s.mean_gap, &opts, None).unwrap();
    assert!(
        (g.mean_pressure / 1e-3 - 1.0).abs() < 1e-6,
        "{}",
        g.mean_pressure
    );
}

#[test]
fn adhesion_pulls_more_area_at_the_same_gap_and_vanishes_with_w() {
    let map = selfaffine();
    let dx = 1e-4 / 256.0;
    let opts = Options {
        tolerance: 1e-9,
        ..Default::default()
    };
    let plain = Problem::new(&map, dx, 1e9, true, &opts).unwrap();
    let g = plain.h_rms();
    let s0 = plain.solve_gap(g, &opts, None).unwrap();
    let weak = Problem::new(&map, dx, 1e9, true, &opts)
        .unwrap()
        .with_adhesion(1e-12, 2.0 * dx)
        .unwrap();
    let sw = weak.solve_gap(g, &opts, None).unwrap();
    assert!((sw.mean_pressure / s0.mean_pressure - 1.0).abs() < 1e-6);
    let strong = Problem::new(&map, dx, 1e9, true, &opts)
        .unwrap()
        .with_adhesion(0.02, 2.0 * dx)
        .unwrap();
    let sa = strong.solve_gap(g, &opts, None).unwrap();
    assert!(sa.area_fraction() > s0.area_fraction() && sa.mean_pressure < s0.mean_pressure);
    // The stored reference (tolerance 1e-10) at the same gap.
    let r = reference();
    let st = &r["adhesive"]["states"][0];
    assert!((sa.mean_pressure / st["pressure_Pa"].as_f64().unwrap() - 1.0).abs() < 1e-6);
    assert!((sa.area_fraction() - st["area_fraction"].as_f64().unwrap()).abs() < 1e-4);
    // Adhesion needs a periodic map.
    let padded = Problem::new(&map, dx, 1e9, false, &opts).unwrap();
    assert_eq!(
        padded.with_adhesion(0.02, dx).unwrap_err().field(),
        Some("periodic")
    );
}

#[test]
fn memory_is_bounded_with_the_estimate_in_the_message() {
    // 2048^2 fits in 1 GiB both ways.
    assert!(memory_estimate(2048, 2048, true) < 1 << 30);
    assert!(memory_estimate(2048, 2048, false) < 1 << 30);
    assert!(memory_estimate(4096, 4096, false) > 1 << 30);
    let map = HeightMap::new(64, 64, (0..4096).map(|k| (k as f64 * 0.37).sin()).collect()).unwrap();
    let opts = Options {
        memory_limit: 100_000,
        ..Default::default()
    };
    let e = Problem::new(&map, 1e-6, 1e9, true, &opts).unwrap_err();
    assert_eq!(e.field(), Some("topography"));
    assert!(e.to_string().contains("MiB"), "{e}");
    let ok = Options::default();
    assert_eq!(
        Problem::new(&map, 0.0, 1e9, true, &ok).unwrap_err().field(),
        Some("pixel_size")
    );
    assert_eq!(
        Problem::new(&map, 1e-6, -1.0, true, &ok)
            .unwrap_err()
            .field(),
        Some("contact_modulus")
    );
    let prob = Problem::new(&map, 1e-6, 1e9, true, &ok).unwrap();
    assert_eq!(
        prob.solve_pressure(0.0, &ok, None).unwrap_err().field(),
        Some("pressure")
    );
    assert_eq!(
        prob.solve_gap(f64::NAN, &ok, None).unwrap_err().field(),
        Some("gap")
    );
}

#[test]
fn adhesive_sphere_follows_jkr_near_pull_off() {
    // R = 1, E* = 1, w such that a0 = 0.2 (51 pixels), Maugis lambda = 2.5
    // (K = 4E*/3). The pull-off against JKR within 2 % is
    // `adhesive_sphere_pull_off_within_two_percent_of_jkr`; here 256^2 holds
    // the force at the measured radius, P(a), to 5 % of the pull-off force
    // (4 % measured, mostly the finite range: 512^2 gives the same).
    let n = 256;
    let dx = 1.0 / n as f64;
    let map = sphere_cell(n, n as f64 / 2.0);
    let (w, rho) = (5.66e-4, 3.11e-3);
    let opts = Options {
        tolerance: 1e-8,
        ..Default::default()
    };
    let prob = Problem::new(&map, dx, 1.0, true, &opts)
        .unwrap()
        .with_adhesion(w, rho)
        .unwrap();
    let zero = prob.zero_load_gap();
    let pc = 1.5 * PI * w;
    let mut warm = None;
    for k in 0..4 {
        let s = prob
            .solve_gap(zero - 0.004 + 0.001 * k as f64, &opts, warm.as_ref())
            .unwrap();
        let a = (s.contact_pixels as f64 / PI).sqrt() * dx;
        let jkr = 4.0 * a.powi(3) / 3.0 - (8.0 * PI * w * a.powi(3)).sqrt();
        assert!(
            ((s.mean_pressure - jkr) / pc).abs() < 0.05,
            "{k}: {} {jkr}",
            s.mean_pressure
        );
        warm = Some(s);
    }
}

/// Smallest force (most tensile mean pressure; the load-control pull-off)
/// of the R = 1 sphere in a periodic unit cell, `n^2` pixels, E* = 1,
/// exponential adhesion `w exp(-g/rho)`, stepped in mean gap by `step`
/// from `zero-load gap + start` (`count` states, warm-started), refined by a
/// parabola through the smallest sample and its neighbours.
fn sphere_pull_off(n: usize, w: f64, rho: f64, start: f64, step: f64, count: usize) -> f64 {
    let dx = 1.0 / n as f64;
    let map = sphere_cell(n, n as f64 / 2.0);
    let opts = Options {
        tolerance: 1e-8,
        ..Default::default()
    };
    let prob = Problem::new(&map, dx, 1.0, true, &opts)
        .unwrap()
        .with_adhesion(w, rho)
        .unwrap();
    let zero = prob.zero_load_gap();
    let mut warm = None;
    let mut p = Vec::with_capacity(count);
    for k in 0..count {
        let s = prob
            .solve_gap(zero + start + step * k as f64, &opts, warm.as_ref())
            .unwrap();
        p.push(s.mean_pressure);
        warm = Some(s);
    }
    let k = (0..count).min_by(|&i, &j| p[i].total_cmp(&p[j])).unwrap();
    assert!(
        k > 0 && k + 1 < count,
        "pull-off not bracketed (rho {rho}): {p:?}"
    );
    let (a, b, c) = (p[k - 1], p[k], p[k + 1]);
    b - (c - a) * (c - a) / (8.0 * (a - 2.0 * b + c))
}

#[test]
fn adhesive_sphere_pull_off_within_two_percent_of_jkr() {
    // R = 1, E* = 1, w = 5.66e-4 (JKR a0 = 0.2, pull-off 1.5 pi w R at
    // a = 0.126), 512^2. The JKR limit is rho -> 0: the exponential law's
    // pull-off exceeds JKR's by an amount first order in rho (measured at
    // 512^2: +4.76 %, +3.04 %, +1.93 % at rho = 3.11e-3, 2.2e-3, 1.55e-3,
    // differences in ratio 1.44 for rho in ratio 1.42; the mesh is not the
    // cause: 256^2 gives +4.86 %, +3.26 % at the first two). At rho =
    // 1.55e-3 (Maugis lambda = 2 (w/rho)(R/(pi w K^2))^(1/3) = 5.0,
    // K = 4E*/3) the pull-off is within 2 % of JKR; the first-order
    // extrapolation rho -> 0 of the last two lands within 2 % too
    // (-0.7 % measured; Maugis-Dugdale at lambda = 5 is +0.42 %). Measured:
    // 1.0304 and 1.0193, so the direct bound has a margin of 0.07 %; the
    // lattice pins the contact line below rho ~ 0.8 dx, so a smaller rho
    // needs a finer mesh (docs/performance.md).
    let w = 5.66e-4;
    let jkr = -1.5 * PI * w;
    let coarse = sphere_pull_off(512, w, 2.2e-3, 0.0015, 0.00025, 5) / jkr;
    let fine = sphere_pull_off(512, w, 1.55e-3, 0.0015, 0.00025, 5) / jkr;
    println!("pull-off / JKR: rho 2.2e-3 {coarse}, rho 1.55e-3 {fine}");
    assert!(fine > 1.0 && fine < 1.02, "{fine}");
    assert!(coarse > fine + 0.005, "{coarse} {fine}");
    let r = 2.2 / 1.55;
    let limit = fine - (coarse - fine) / (r - 1.0);
    assert!((limit - 1.0).abs() < 0.02, "{limit}");
}

/// A contact modulus whose Fourier kernels would leave f64's normal range
/// (here the compliance `~ dx/(E* N)` below 1e-290) is refused naming
/// `contact_modulus`, instead of iterating to the cap on subnormal
/// kernels (E* = 1e300 on a 64^2 map of 1.56 um pixels ran 10,000
/// iterations, 22 s); 1e200 Pa still solves.
#[test]
fn a_modulus_beyond_what_the_kernels_hold_is_refused() {
    let map = sphere_cell(64, 31.5);
    let opts = Options::default();
    let e = Problem::new(&map, 1.5625e-6, 1e300, false, &opts).unwrap_err();
    assert!(e.to_string().contains("contact_modulus"), "{e}");
    let ok = Problem::new(&map, 1.5625e-6, 1e200, false, &opts).unwrap();
    assert!(ok.solve_pressure(1e197, &opts, None).unwrap().converged);
}
