//! Tables of docs/performance.md (`## Full sphere solver`):
//! `cargo run --release --example sphere_tables`.
//!
//! Includes a small Maugis–Dugdale pull-off (physics.md equations 1-2,
//! checked against physics.md's values) for the comparison at
//! `lambda = 1.1570 mu`; the library's own MD law is written elsewhere.
use asperity::material::LAMBDA_PER_TABOR;
use asperity::numeric::roots::{brent, golden_min};
use asperity::sphere::{Shape, SolverOptions, SphereProblem};
use std::time::Instant;

/// MD load at contact radius `a` (Maugis units): solve eq. 1 for `m > 1`.
fn md_load(lambda: f64, a: f64) -> f64 {
    let eq1 = |m: f64| {
        let s = (m * m - 1.0).sqrt();
        let t = s.atan();
        0.5 * lambda * a * a * (s + (m * m - 2.0) * t)
            + (4.0 * lambda * lambda * a / 3.0) * (s * t - m + 1.0)
            - 1.0
    };
    let mut hi = 2.0;
    while eq1(hi) < 0.0 {
        hi *= 2.0;
    }
    let m = brent(eq1, 1.0, hi, 1e-14).unwrap();
    let s = (m * m - 1.0).sqrt();
    a * a * a - lambda * a * a * (s + m * m * s.atan())
}

/// Load-controlled MD pull-off: the minimum of `Pbar(A)`.
fn md_pull_off(lambda: f64) -> f64 {
    golden_min(|a| md_load(lambda, a), 1e-4, 3.0, 1e-10).1
}

fn facts(mu: f64, shape: Shape, res: f64) -> (asperity::sphere::SphereFacts, f64) {
    let o = {
        let mut o = SolverOptions::default();
        o.resolution = res;
        o
    };
    let t = Instant::now();
    let f = SphereProblem::new(mu, shape, o).unwrap().facts().unwrap();
    (f, t.elapsed().as_secs_f64())
}

fn main() {
    for (l, v) in [(0.1, -1.9506), (1.0, -1.6007), (5.0, -1.5063)] {
        let p = md_pull_off(l);
        assert!((p - v).abs() < 1e-4, "MD check lambda {l}: {p} vs {v}");
    }
    println!("### Mesh convergence (paraboloid, load-controlled pull-off P/(pi w R))\n");
    println!("| mu | resolution | nodes | pull-off | rel. change vs previous | time (s) |");
    println!("|---|---|---|---|---|---|");
    for mu in [0.1, 1.0, 5.0] {
        let mut prev: Option<f64> = None;
        for res in [0.5, 1.0, 2.0, 4.0] {
            let (f, t) = facts(mu, Shape::Paraboloid, res);
            let p = f.pull_off.load_bar;
            let ch = prev.map_or("".to_string(), |q| format!("{:.1e}", ((p - q) / q).abs()));
            println!("| {mu} | {res} | {} | {p:.6} | {ch} | {t:.3} |", f.nodes);
            prev = Some(p);
        }
    }
    println!(
        "\n### Solver vs Maugis–Dugdale (lambda = 1.1570 mu), paraboloid, default resolution\n"
    );
    println!("| mu | lambda = 1.157 mu | pull-off (solver) | pull-off (MD) | MD lambda with the solver's pull-off | jump-out load | jump-out Dbar | jump-in Dbar | A at zero load | time (s) |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for mu in [
        0.01, 0.03, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 1.5, 2.0, 3.0, 5.0, 7.0, 10.0,
    ] {
        let (f, t) = facts(mu, Shape::Paraboloid, 1.0);
        let lambda = LAMBDA_PER_TABOR * mu;
        let show = |x: Option<f64>| x.map_or("–".to_string(), |v| format!("{v:.4}"));
        // the lambda whose MD pull-off equals the solver's (MD is monotone in lambda)
        let p = f.pull_off.load_bar;
        let fit = if p > -1.9999 && p < -1.5001 {
            brent(|l| md_pull_off(l) - p, 1e-3, 200.0, 1e-10)
                .map_or("–".to_string(), |l| format!("{l:.4}"))
        } else {
            "–".to_string()
        };
        println!(
            "| {mu} | {lambda:.4} | {:.4} | {:.4} | {fit} | {} | {} | {} | {} | {t:.3} |",
            f.pull_off.load_bar,
            md_pull_off(lambda),
            show(f.jump_out.map(|j| j.load_bar)),
            show(f.jump_out.map(|j| j.interference_bar)),
            show(f.jump_in.map(|j| j.interference_bar)),
            show(f.zero_load_radius_bar),
        );
    }
    println!("\n### True sphere (size ratio rho = R/z0) vs paraboloid, pull-off P/(pi w R)\n");
    println!("| mu | rho = 10 | rho = 30 | rho = 100 | rho = 1000 | rho = 1e5 | paraboloid |");
    println!("|---|---|---|---|---|---|---|");
    for mu in [0.01, 0.1, 1.0, 3.0] {
        let mut row = format!("| {mu} |");
        for rho in [10.0, 30.0, 100.0, 1000.0, 1e5] {
            let (f, _) = facts(mu, Shape::Sphere { rho }, 1.0);
            row.push_str(&format!(" {:.4} |", f.pull_off.load_bar));
        }
        let (f, _) = facts(mu, Shape::Paraboloid, 1.0);
        row.push_str(&format!(" {:.4} |", f.pull_off.load_bar));
        println!("{row}");
    }
    println!("\n### Far-field truncation (mu = 1, default resolution)\n");
    println!("| far_gap (rigid gap at the last node, z0) | pull-off |");
    println!("|---|---|");
    for far in [15.0, 30.0, 60.0, 240.0, 1000.0] {
        let o = {
            let mut o = SolverOptions::default();
            o.far_gap = far;
            o
        };
        let f = SphereProblem::new(1.0, Shape::Paraboloid, o)
            .unwrap()
            .facts()
            .unwrap();
        println!("| {far} | {:.7} |", f.pull_off.load_bar);
    }
}
