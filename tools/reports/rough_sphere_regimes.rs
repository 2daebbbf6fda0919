//! The regime map of docs/physics.md ("Rough sphere"): Greenwood–Tripp
//! with Hertz summits on Gaussian heights, at `mu` 0.01 .. 100 and central
//! separations `d` 2 .. -2 (units of sigma); each cell
//! `P*: a95/a95_rigid / a95/a95_Hertz`, the radius holding 95 % of the
//! load against that of GW without bulk deformation at the same load and
//! against Hertz's at the same load.
//!
//! Rigid: `p = mu F_3/2(d_r + rho^2)`, load `pi mu F_5/2(d_r)/(5/2)`
//! (`rigid_load_gt`); the load within `rho` is the same expression minus
//! `F_5/2(d_r + rho^2)`, so `a95_rigid^2 = t` with
//! `F_5/2(d_r + t) = 0.05 F_5/2(d_r)`.
//!
//! `cargo run --release --example rough_sphere_regimes` (prints the
//! Markdown table; `tests/it/docs_tables.rs` runs [`rows`] against the
//! quote).
use asperity::numeric::roots::brent;
use asperity::roughsphere::units::{hertz_load_fraction_radius, hertz_radius_gt, rigid_load_gt};
use asperity::roughsphere::GreenwoodTripp;
use asperity::special::gaussian_fn::gaussian_fn;

/// Tabor-like stiffness ratios (rows) and separations (columns).
pub const MUS: [f64; 5] = [0.01, 0.1, 1.0, 10.0, 100.0];
/// Central separations `d` (units of sigma).
pub const DS: [f64; 5] = [2.0, 0.5, 0.0, -1.0, -2.0];

/// Three significant digits; scientific below 0.1 and from 1000.
fn three(x: f64) -> String {
    if (0.1..1000.0).contains(&x.abs()) {
        let decimals = (2 - x.abs().log10().floor() as i32).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        let s = format!("{x:.2e}");
        s.replace("e0", "")
    }
}

/// `x` with `f(x) = 0` for `f` monotone, the bracket `[lo, hi]` widened
/// on both sides until it holds a sign change.
fn root(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    for _ in 0..200 {
        if f(lo) * f(hi) <= 0.0 {
            break;
        }
        let w = hi - lo;
        (lo, hi) = (lo - w, hi + w);
    }
    brent(&f, lo, hi, 1e-14 * (1.0 + hi.abs())).expect("a bracketed root")
}

/// One cell: `(P*, a95/a95_rigid, a95/a95_Hertz)`.
pub fn cell(mu: f64, d: f64) -> (f64, f64, f64) {
    let s = GreenwoodTripp::new(mu).unwrap().state(d, &[]).unwrap();
    let load = s.load.value;
    let a95 = s.radius_95.expect("a loaded state").value;
    let f52 = |h: f64| gaussian_fn(2.5, h).unwrap();
    // The rigid separation at the same load (the load falls with d_r).
    let d_r = root(|x| rigid_load_gt(mu, x) - load, d - 0.5, d + 0.5);
    let t = root(|t| f52(d_r + t) - 0.05 * f52(d_r), 0.5, 1.0).max(0.0);
    let hertz = hertz_radius_gt(load) * hertz_load_fraction_radius(0.95);
    (load, a95 / t.sqrt(), a95 / hertz)
}

/// The table's header and separator lines.
pub const HEADER: &str = "| mu \\ d | 2 | 0.5 | 0 | -1 | -2 |\n|---|---|---|---|---|---|";

/// The table's rows, one per `mu`.
pub fn rows() -> Vec<String> {
    MUS.iter()
        .map(|&mu| {
            let cells: Vec<String> = DS
                .iter()
                .map(|&d| {
                    let (p, rigid, hertz) = cell(mu, d);
                    format!("{}: {} / {}", three(p), three(rigid), three(hertz))
                })
                .collect();
            format!("| {} | {} |", mu, cells.join(" | "))
        })
        .collect()
}

#[allow(dead_code)] // the tests use `rows` alone
fn main() {
    println!("{HEADER}");
    for row in rows() {
        println!("{row}");
    }
}
