//! The contact-mechanics challenge (Müser et al., Tribol. Lett. 65, 118,
//! 2017) on asperity's boundary elements: the challenge's surface generated
//! from its published spectrum with a fixed seed, the non-adhesive and the
//! adhesive problem at the reference pressure, with CPU times.
//!
//! ```text
//! cargo run --release --example challenge                  # 512^2
//! cargo run --release --example challenge -- 2048          # 2048^2 (minutes)
//! cargo run --release --example challenge -- 512 --write tests/data/challenge_512.npy
//! cargo run --release --example challenge -- 512 --map tests/data/challenge_512.npy
//! ```
//!
//! The surface, the problems and their definitions are those of
//! `examples/challenge/README.md`; the numbers are printed as one JSON
//! object. CPU times are this process's user + system time (Linux
//! `/proc/self/stat`; run with `RAYON_NUM_THREADS=1` for one thread).

use asperity::bem::challenge::{self, Challenge};
use asperity::bem::{Options, Problem, Solution};
use asperity::surface::{npy, HeightMap};
use serde_json::{json, Value};

/// The solvers' tolerance on their residual (dimensionless, see
/// `asperity::bem`).
const TOLERANCE: f64 = 1e-10;

/// This process's CPU time (s): user + system from `/proc/self/stat`.
fn cpu_s() -> f64 {
    asperity::study::cpu_time::process_cpu_seconds().unwrap_or(f64::NAN)
}

/// Exit 2 with the usage and `what` was wrong.
fn usage(what: &str) -> ! {
    eprintln!(
        "challenge: expected [N] (grid size, 512 default) [--write PATH] [--map PATH]: {what}"
    );
    std::process::exit(2)
}

/// The path after the flag at `args[k]`, or exit 2 naming the flag.
fn path_after(args: &[String], k: usize) -> String {
    args.get(k + 1)
        .cloned()
        .unwrap_or_else(|| usage(&format!("{} needs a path", args[k])))
}

/// A solution's numbers: A/A0, mean gap, mean pressure, iterations,
/// residual, converged, CPU time.
fn state(s: &Solution, cpu: f64) -> Value {
    json!({
        "area_fraction": s.area_fraction(),
        "contact_pixels": s.contact_pixels,
        "mean_gap_m": s.mean_gap,
        "mean_pressure_pa": s.mean_pressure,
        "iterations": s.iterations,
        "residual": s.residual,
        "converged": s.converged,
        "cpu_s": cpu,
    })
}

fn main() {
    if let Err(e) = run() {
        eprintln!("challenge: {e}");
        // Bad input (a grid size out of range, an unreadable map) exits 2,
        // a failed solve 1.
        let input = matches!(
            e,
            asperity::Error::OutOfRange { .. } | asperity::Error::Invalid { .. }
        );
        std::process::exit(if input { 2 } else { 1 });
    }
}

fn run() -> asperity::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut n = 512;
    let (mut write, mut read) = (None, None);
    let mut k = 0;
    while k < args.len() {
        match args[k].as_str() {
            "--write" => {
                write = Some(path_after(&args, k));
                k += 1;
            }
            "--map" => {
                read = Some(path_after(&args, k));
                k += 1;
            }
            v => n = v.parse().unwrap_or_else(|_| usage(&format!("got '{v}'"))),
        }
        k += 1;
    }
    let t0 = cpu_s();
    let map: Option<HeightMap> = match &read {
        Some(path) => Some(npy::parse(&std::fs::read(path).map_err(|e| {
            asperity::Error::invalid("map", format!("cannot read {path}: {e}"))
        })?)?),
        None => None,
    };
    // A map read sets the grid (square, side 0.1 mm).
    if let Some(m) = &map {
        if m.rows() != m.cols() {
            usage(&format!("--map is {} x {}, not square", m.rows(), m.cols()));
        }
        n = m.rows();
    }
    let c = Challenge::at(n)?;
    let map = match map {
        Some(m) => m,
        None => c.surface()?,
    };
    let t_surface = cpu_s() - t0;
    if let Some(path) = &write {
        std::fs::write(path, npy::to_bytes(&map))
            .map_err(|e| asperity::Error::invalid("write", format!("cannot write {path}: {e}")))?;
    }
    let opts = Options {
        tolerance: TOLERANCE,
        ..Default::default()
    };
    let t1 = cpu_s();
    let dry = Problem::new(&map, c.pixel_size(), c.contact_modulus, true, &opts)?;
    let s_dry = dry.solve_pressure(c.reference_pressure, &opts, None)?;
    let t_dry = cpu_s() - t1;
    let t2 = cpu_s();
    let wet = Problem::new(&map, c.pixel_size(), c.contact_modulus, true, &opts)?
        .with_adhesion(c.adhesion_energy, c.adhesion_range())?;
    let s_wet = wet.solve_gap(s_dry.mean_gap, &opts, None)?;
    let t_wet = cpu_s() - t2;
    let out = json!({
        "n": n,
        "pixel_size_m": c.pixel_size(),
        "seed": challenge::SEED,
        "map": read.unwrap_or_else(|| "generated".into()),
        "slope_rms": challenge::slope_rms(&map, c.pixel_size()),
        "contact_modulus_pa": c.contact_modulus,
        "reference_pressure_pa": c.reference_pressure,
        "adhesion_energy_j_m2": c.adhesion_energy,
        "adhesion_range_m": c.adhesion_range(),
        "tolerance": TOLERANCE,
        "threads": rayon::current_num_threads(),
        "surface_cpu_s": t_surface,
        "non_adhesive": state(&s_dry, t_dry),
        "adhesive": state(&s_wet, t_wet),
    });
    println!("{}", serde_json::to_string_pretty(&out).unwrap_or_default());
    Ok(())
}
