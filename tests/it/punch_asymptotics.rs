//! Small-wavelength asymptotics of the wavy punch, measured (run with `--nocapture` for the
//! tables quoted in docs/performance.md):
//! - the exact folds approach the envelopes at the predicted rates
//!   (`h_fold - h_+/- = A l + O(l^(3/2))`, `P_fold - P_+/- = O(l^(3/2))`);
//! - the energy lost per cycle converges to eq. 4.12 as `l -> 0`;
//! - the energy barrier at `h = 0` near the smooth equilibrium approaches the peak-to-peak
//!   amplitude `2 E* A a^(5/2) l^(3/2)/R` of eq. 4.16's oscillating term.
//!
//! Units: the paper's Fig. 8, `E* = R = 1`, `2 pi w/(E* R) = 0.05`, `A = 0.14`.

use asperity::numeric::roots::brent;
use asperity::punch::landscape::{KnotKind, Landscape};
use asperity::punch::{Envelope, Evolution, WavyPunch};
use std::f64::consts::PI;

const A: f64 = 0.14;

fn punch(l: f64) -> WavyPunch {
    WavyPunch::new(1.0, 0.05 / (2.0 * PI), 1.0, A, l).unwrap()
}

/// Least-squares slope of log y against log x.
fn slope(x: &[f64], y: &[f64]) -> f64 {
    let lx: Vec<f64> = x.iter().map(|v| v.ln()).collect();
    let ly: Vec<f64> = y.iter().map(|v| v.ln()).collect();
    let n = lx.len() as f64;
    let (mx, my) = (lx.iter().sum::<f64>() / n, ly.iter().sum::<f64>() / n);
    let sxy: f64 = lx.iter().zip(&ly).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = lx.iter().map(|a| (a - mx) * (a - mx)).sum();
    sxy / sxx
}

/// Extrema of P(a) in [lo, hi]: roots of dP/da = 2 E* (a h' - sqrt(2 pi w a/E*)).
fn load_extrema(p: &WavyPunch, lo: f64, hi: f64) -> Vec<(f64, bool)> {
    let d = |a: f64| a * p.depth_slope(a) - (2.0 * PI * p.w() * a / p.estar()).sqrt();
    let step = p.wavelength() / 64.0;
    let mut out = Vec::new();
    let (mut a0, mut d0) = (lo, d(lo));
    while a0 < hi {
        let a1 = a0 + step;
        let d1 = d(a1);
        if d0.signum() != d1.signum() {
            let r = brent(d, a0, a1, 1e-15).unwrap();
            out.push((r, d0 > 0.0)); // true: a maximum
        }
        (a0, d0) = (a1, d1);
    }
    out
}

#[test]
fn folds_approach_the_envelopes_at_the_predicted_rates() {
    let ls = [0.02, 0.01, 0.005, 0.002, 0.001, 0.0005];
    let (lo, hi) = (0.3, 0.6);
    let (mut eh, mut eh_shift, mut ep) = (vec![], vec![], vec![]);
    println!("| l/R | max abs(h_fold - h_env) | / l | max abs(h_fold - h_env - A l) | / l^1.5 | max abs(P_ext - P_env) | / l^1.5 |");
    println!("|---|---|---|---|---|---|---|");
    for &l in &ls {
        let p = punch(l);
        let land = Landscape::scan_to_radius(&p, hi).unwrap();
        let (mut m1, mut m2) = (0.0_f64, 0.0_f64);
        for k in land.knots() {
            let a = k.state.radius;
            if a < lo || !matches!(k.kind, KnotKind::Minimum | KnotKind::Maximum) {
                continue;
            }
            let which = if k.kind == KnotKind::Maximum {
                Envelope::Loading
            } else {
                Envelope::Unloading
            };
            let d = k.state.depth - p.envelope(a, which).depth;
            m1 = m1.max(d.abs());
            m2 = m2.max((d - A * l).abs());
        }
        let mut m3 = 0.0_f64;
        for (a, is_max) in load_extrema(&p, lo, hi) {
            let which = if is_max {
                Envelope::Loading
            } else {
                Envelope::Unloading
            };
            m3 = m3.max((p.load(a) - p.envelope(a, which).load).abs());
        }
        println!(
            "| {l} | {m1:.3e} | {:.4} | {m2:.3e} | {:.3} | {m3:.3e} | {:.3} |",
            m1 / l,
            m2 / l.powf(1.5),
            m3 / l.powf(1.5)
        );
        eh.push(m1);
        eh_shift.push(m2);
        ep.push(m3);
    }
    let (sh, sh2, sp) = (
        slope(&ls[2..], &eh[2..]),
        slope(&ls[2..], &eh_shift[2..]),
        slope(&ls[2..], &ep[2..]),
    );
    println!("fitted rates (l <= 0.005): h {sh:.3} (predicted 1), h - A l {sh2:.3} (1.5), P {sp:.3} (1.5)");
    assert!((sh - 1.0).abs() < 0.1, "h rate {sh}");
    assert!((sh2 - 1.5).abs() < 0.2, "h - A l rate {sh2}");
    assert!((sp - 1.5).abs() < 0.2, "P rate {sp}");
    // The O(l) coefficient of h is the mean of the roughness, A.
    let last = eh.len() - 1;
    assert!((eh[last] / ls[last] / A - 1.0).abs() < 0.05);
}

#[test]
fn energy_loss_converges_to_eq_4_12() {
    let (h_min, h_max) = (-0.3, 0.3);
    let ls = [0.02, 0.01, 0.005, 0.002, 0.001, 0.0005];
    let mut diffs = vec![];
    println!("| l/R | exact loss | eq. 4.12 | JKR term | rel. diff | diff / l |");
    println!("|---|---|---|---|---|---|");
    for &l in &ls {
        let p = punch(l);
        let ev = Evolution::new(&p, h_max).unwrap();
        let exact = ev.energy_loss(h_min);
        let asy = p.loss_asymptotic(h_max).unwrap();
        let d = exact - asy.total();
        println!(
            "| {l} | {exact:.6e} | {:.6e} | {:.6e} | {:+.2e} | {:+.4} |",
            asy.total(),
            asy.jkr,
            d / exact,
            d / l
        );
        diffs.push(d.abs());
    }
    let s = slope(&ls[2..], &diffs[2..]);
    println!("fitted rate of |exact - eq 4.12| (l <= 0.005): {s:.3} (eq 4.12 drops O(l))");
    assert!(s > 0.8, "rate {s}");
    assert!(diffs[diffs.len() - 1] / ls[ls.len() - 1] < 1.0);
}

#[test]
fn barrier_at_zero_depth_scales_as_eq_4_17() {
    let ls = [0.01, 0.005, 0.002, 0.001, 0.0005];
    let a_s = (2.0 * PI * (0.05 / (2.0 * PI))).cbrt(); // smooth equilibrium at h = 0
    println!("| l/R | stable a | barrier (min of both sides) | 2 E* A a^2.5 l^1.5 / R | ratio |");
    println!("|---|---|---|---|---|");
    let mut ratios = vec![];
    for &l in &ls {
        let p = punch(l);
        let bars = p.barriers(0.0, 0.6).unwrap();
        // The stable equilibrium nearest the smooth one.
        let best = bars
            .iter()
            .map(|b| b.stable)
            .min_by(|x, y| (x - a_s).abs().total_cmp(&(y - a_s).abs()))
            .unwrap();
        let e = bars
            .iter()
            .filter(|b| b.stable == best)
            .map(|b| b.energy)
            .fold(f64::INFINITY, f64::min);
        let scale = 2.0 * A * best.powf(2.5) * l.powf(1.5);
        println!(
            "| {l} | {best:.5} | {e:.4e} | {scale:.4e} | {:.4} |",
            e / scale
        );
        ratios.push(e / scale);
    }
    // The ratio oscillates (the stable radius moves within a period); at small l it stays
    // within 10 % of 1.
    for r in &ratios[2..] {
        assert!((r - 1.0).abs() < 0.1, "ratio {r}");
    }
}
