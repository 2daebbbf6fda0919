//! GW (on the map's moments) and Persson (on its radial spectrum) against
//! the exact elastic boundary-element solution of the same map, at three
//! mean pressures: the real-area fraction and the mean gap at the same
//! pressure, and the pressure at the same mean gap; with the cost of the
//! exact solves. The maps: the shipped measured map
//! (`examples/data/measured-topography.npy`, 160^2 of 50 nm, padded), the
//! shipped 256^2 self-affine map (`examples/data/selfaffine-256.npy`,
//! periodic) and a periodic 512^2 random-phase self-affine map (H = 0.8,
//! roll-off at 4 q_l, q_s at a 4-pixel wavelength, slope 0.1, seed 1).
//!
//! `cargo run --release --example model_error_maps` (prints a Markdown
//! table; docs/physics.md quotes it, and `tests/it/docs_tables.rs` runs
//! [`rows`] to hold the quote to it, the CPU column aside).
use asperity::bem::compare::{compare, CompareInput, Control};
use asperity::bem::Options;
use asperity::gw::GwOnMoments;
use asperity::numeric::roots::brent;
use asperity::persson::Persson;
use asperity::spectrum::radial::radial_psd_xy;
use asperity::spectrum::synthesis::random_phase_map;
use asperity::spectrum::{Normalisation, Spectrum};
use asperity::surface::{npy, HeightMap, Topography};
use std::f64::consts::PI;

fn cpu_s() -> f64 {
    asperity::study::cpu_time::process_cpu_seconds().unwrap_or(f64::NAN)
}

/// `x` with `f(x) = target` for `f` increasing in `ln x`, from `x0`.
fn invert(f: impl Fn(f64) -> f64, target: f64, x0: f64) -> Option<f64> {
    let g = |lx: f64| f(lx.exp()) - target;
    let (mut lo, mut hi) = (x0.ln() - 1.0, x0.ln() + 1.0);
    for _ in 0..60 {
        if g(lo) < 0.0 {
            break;
        }
        lo -= 1.0;
    }
    for _ in 0..60 {
        if g(hi) > 0.0 {
            break;
        }
        hi += 1.0;
    }
    brent(g, lo, hi, 1e-13).map(f64::exp)
}

fn pct(x: f64) -> String {
    format!("{:+.1} %", 100.0 * x)
}

/// The table's rows for one map, each state's row a Markdown line.
fn report(
    name: &str,
    map: &HeightMap,
    dx: f64,
    periodic: bool,
    estar: f64,
    loads: &[f64],
) -> Vec<String> {
    let mut rows = Vec::new();
    let input = CompareInput {
        pixel_size: dx,
        pixel_size_y: None,
        contact_modulus: estar,
        periodic,
        control: Control::Pressure,
        targets: loads.iter().map(|l| l * estar).collect(),
        adhesion: None,
        hardness: None,
        gamma: 1.0,
        resistivity: None,
        options: Options::default(),
    };
    let t = cpu_s();
    let cmp = compare(map, &input).expect("compare");
    let cpu = cpu_s() - t;
    // The same theories, for the pressures at the exact gaps.
    let topo = Topography::new(map.clone(), dx).unwrap();
    let c = topo.characterise(periodic).unwrap();
    let gw = GwOnMoments::new(&c.moments, estar, c.nominal_area_m2()).unwrap();
    let psd = radial_psd_xy(map, (dx, dx), periodic).unwrap();
    let persson = Persson::new(psd, estar, 1.0).unwrap();
    for (k, s) in cmp.states.iter().enumerate() {
        let (p, u) = (s.solution.mean_pressure, s.solution.mean_gap);
        let d = &cmp.differences[k];
        // GW: the separation whose mean gap is u; Persson: the pressure.
        let gw_p = gw.state(p).ok().and_then(|g0| {
            let f = |x: f64| gw.state_at(x).map_or(f64::NAN, |g| g.mean_gap - u);
            let (mut lo, mut hi) = (g0.separation, g0.separation);
            for _ in 0..200 {
                if f(lo) <= 0.0 {
                    break;
                }
                lo -= 0.1 * gw.sigma;
            }
            for _ in 0..200 {
                if f(hi) >= 0.0 {
                    break;
                }
                hi += 0.1 * gw.sigma;
            }
            let x = brent(f, lo, hi, 1e-12 * gw.sigma)?;
            gw.state_at(x).ok().map(|g| g.pressure)
        });
        let pe_p = invert(
            |x| -persson.state(x).map_or(f64::NAN, |s| s.mean_gap),
            -u,
            p,
        );
        let o = |x: Option<f64>| x.map_or("-".into(), pct);
        rows.push(format!(
            "| {name} | {:.0e} | {:.4} | {} | {} | {} | {} | {} | {} | {} |",
            p / estar,
            s.solution.area_fraction(),
            o(d.gw_area),
            o(gw_p.map(|g| g / p - 1.0)),
            o(d.gw_mean_gap),
            o(d.persson_area),
            o(pe_p.map(|x| x / p - 1.0)),
            o(d.persson_mean_gap),
            if k == 0 {
                format!("{cpu:.2} s CPU ({:.2} s wall)", cmp.solve_wall_s)
            } else {
                String::new()
            }
        ));
    }
    for w in &cmp.warnings {
        eprintln!("{name}: {w}");
    }
    rows
}

/// The table's header and separator lines.
pub const HEADER: &str =
    "| map | p/E* | exact A/A0 | GW area | GW load at the same gap | GW gap | \
     Persson area | Persson load at the same gap | Persson gap | exact solves |\n\
     |---|---|---|---|---|---|---|---|---|---|";

/// Every row of the table, map by map (paths from the repository root).
pub fn rows(root: &std::path::Path) -> Vec<String> {
    let mut rows = Vec::new();
    let measured =
        npy::parse(&std::fs::read(root.join("examples/data/measured-topography.npy")).unwrap())
            .unwrap();
    // gold on gold, as examples/scenes/measured-topography.toml
    let estar = 79e9 / (2.0 * (1.0 - 0.42 * 0.42));
    rows.extend(report(
        "measured 160^2 (padded)",
        &measured,
        50e-9,
        false,
        estar,
        &[1e-4, 3e-4, 1e-3],
    ));
    let loads = [1e-3, 3e-3, 1e-2];
    let sa256 =
        npy::parse(&std::fs::read(root.join("examples/data/selfaffine-256.npy")).unwrap()).unwrap();
    rows.extend(report(
        "self-affine 256^2",
        &sa256,
        1e-4 / 256.0,
        true,
        1e9,
        &loads,
    ));
    let n = 512;
    let dx = 1e-8;
    let ql = 2.0 * PI / (n as f64 * dx);
    let spectrum = Spectrum::self_affine(
        0.8,
        ql,
        4.0 * ql,
        2.0 * PI / (4.0 * dx),
        Normalisation::SlopeRms(0.1),
    )
    .unwrap();
    let sa512 = random_phase_map(&spectrum, n, n, dx, 1).unwrap();
    rows.extend(report("self-affine 512^2", &sa512, dx, true, 1e9, &loads));
    rows
}

#[allow(dead_code)] // the tests use `rows` alone
fn main() {
    println!("{HEADER}");
    for row in rows(std::path::Path::new(".")) {
        println!("{row}");
    }
}
