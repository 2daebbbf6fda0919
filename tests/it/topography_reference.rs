//! Every instrument sample in `tests/data/topography/` against
//! SurfaceTopography 1.27.1 (`reference.json`, made by `reference.py` there):
//! shape, pixel sizes to 1e-12 relative, missing pixels in the same places,
//! heights to 1e-12 of the map's RMS (64 sampled pixels, the extrema, the
//! mean and 4 weighted sums over every pixel), and the RMS height after the
//! least-squares mean plane (`asperity surface`'s `rms_height_m`, through
//! the command's reader and characterisation).
#![cfg(feature = "study")]

use asperity::commands::measured::{read_measured, ReadOptions};
use asperity::commands::surface::{characterise, SurfaceInput};
use asperity::topography::{read, Channel, Measured};
use serde_json::Value;
use std::path::Path;

const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/topography");

fn reference() -> Value {
    let text = std::fs::read_to_string(format!("{DIR}/reference.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap()
}

/// A compensated (Neumaier) sum: numpy's pairwise sums and a plain loop
/// differ by more than 1e-12 of the RMS on maps far from zero.
fn fsum(v: impl Iterator<Item = f64>) -> f64 {
    let (mut s, mut c) = (0.0f64, 0.0f64);
    for x in v {
        let t = s + x;
        c += if s.abs() >= x.abs() {
            (s - t) + x
        } else {
            (x - t) + s
        };
        s = t;
    }
    s + c
}

/// The worst height error of `m` against the record `r`, in units of the
/// map's standard deviation; panics on any structural difference.
fn compare(m: &Measured, r: &Value) -> f64 {
    let name = r["file"].as_str().unwrap();
    assert_eq!(m.format.name(), r["format"].as_str().unwrap(), "{name}");
    assert_eq!(
        (m.rows, m.cols),
        (
            r["rows"].as_u64().unwrap() as usize,
            r["cols"].as_u64().unwrap() as usize
        ),
        "{name}: shape"
    );
    assert_eq!(m.periodic, r["periodic"].as_bool().unwrap(), "{name}");
    if r["unit"].is_null() {
        assert_eq!(m.unit, "", "{name}: a file without a unit");
        assert_eq!(m.pixel_size, None, "{name}");
    } else {
        let (dx, dy) = m
            .pixel_size
            .unwrap_or_else(|| panic!("{name}: no pixel size"));
        let want = r["pixel_size_m"].as_array().unwrap();
        let rel = |a: f64, b: &Value| (a - f(b)).abs() / f(b);
        assert!(
            rel(dx, &want[0]) <= 1e-12,
            "{name}: dx {dx:e} vs {}",
            want[0]
        );
        if !want[1].is_null() {
            assert!(
                rel(dy, &want[1]) <= 1e-12,
                "{name}: dy {dy:e} vs {}",
                want[1]
            );
        }
    }
    // Missing pixels in the same places.
    let missing: Vec<u128> = (0..m.heights.len())
        .filter(|&k| m.heights[k].is_nan())
        .map(|k| k as u128)
        .collect();
    assert_eq!(
        missing.len() as u64,
        r["missing"].as_u64().unwrap(),
        "{name}: missing"
    );
    if !missing.is_empty() {
        assert_eq!(
            missing[0] as u64,
            r["missing_first"].as_u64().unwrap(),
            "{name}"
        );
        let sum: u128 = missing.iter().sum();
        let sq: u128 = missing.iter().map(|k| k * k).sum();
        assert_eq!(
            sum.to_string(),
            r["missing_index_sum"].to_string(),
            "{name}"
        );
        assert_eq!(
            sq.to_string(),
            r["missing_index_square_sum"].to_string(),
            "{name}"
        );
    }
    let std = f(&r["std_m"]);
    let mut worst: f64 = 0.0;
    let err = |worst: &mut f64, a: f64, b: f64| {
        if (a - b).abs() / std > 1e-12 {
            eprintln!("{name}: {a:e} vs {b:e}");
        }
        *worst = worst.max((a - b).abs() / std)
    };
    let idx = r["sample_index"].as_array().unwrap();
    let want = r["sample_m"].as_array().unwrap();
    for (k, w) in idx.iter().zip(want) {
        let z = m.heights[k.as_u64().unwrap() as usize];
        if w.is_null() {
            assert!(z.is_nan(), "{name}: pixel {k} should be missing");
        } else {
            err(&mut worst, z, f(w));
        }
    }
    let known: Vec<f64> = m.heights.iter().copied().filter(|z| !z.is_nan()).collect();
    let min = known.iter().copied().fold(f64::INFINITY, f64::min);
    let max = known.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    err(&mut worst, min, f(&r["min_m"]));
    err(&mut worst, max, f(&r["max_m"]));
    let n = m.heights.len() as f64;
    let mean = fsum(known.iter().copied()) / known.len() as f64;
    err(&mut worst, mean, f(&r["mean_m"]));
    // The weighted sums add n terms: their error is n times a pixel's at
    // most (weights below 0.5), plus the roundoff of the sum itself.
    let big = known.iter().fold(0.0f64, |a, z| a.max(z.abs()));
    for (k, w) in r["weighted_sums_m"].as_array().unwrap().iter().enumerate() {
        let s = fsum(m.heights.iter().enumerate().map(|(i, z)| {
            let wi = ((i as f64) * (0.618_033_988_749_894_9 + 0.1 * k as f64) + 0.5 * k as f64)
                .rem_euclid(1.0)
                - 0.5;
            if z.is_nan() {
                0.0
            } else {
                z * wi
            }
        }));
        let roundoff = n * 1e-15 * big;
        let per_pixel = ((s - f(w)).abs() - roundoff).max(0.0) / (0.5 * n);
        if per_pixel / std > 1e-12 {
            eprintln!("{name}: weighted sum {k}: {s:e} vs {w}");
        }
        worst = worst.max(per_pixel / std);
    }
    worst
}

#[test]
fn every_sample_reads_as_surface_topography_reads_it() {
    let r = reference();
    assert_eq!(r["surface_topography"], "1.27.1");
    let mut report = Vec::new();
    for s in r["samples"].as_array().unwrap() {
        let name = s["file"].as_str().unwrap();
        let m = read(Path::new(&format!("{DIR}/{name}")), &Channel::Default)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let worst = compare(&m, s);
        assert!(
            worst <= 1e-12,
            "{name}: heights differ by {worst:e} x the RMS"
        );
        report.push(format!("{name}: {worst:.1e}"));
    }
    eprintln!("worst height error / RMS: {}", report.join(", "));
}

/// `rms_height_m` of `asperity surface FILE` (missing pixels filled, the
/// file's pixel sizes, 1e-7 m for the one file without) against the RMS
/// after the least-squares plane that `reference.py` computes with numpy.
#[test]
fn surface_rms_height_is_the_rms_after_the_mean_plane() {
    let r = reference();
    let mut checked = 0;
    for s in r["samples"].as_array().unwrap() {
        let name = s["file"].as_str().unwrap();
        let Some(want) = s["plane_rms_m"].as_f64() else {
            continue; // a single profile: no plane
        };
        let options = ReadOptions {
            fill_missing: true,
            ..ReadOptions::default()
        };
        let m = read_measured(Path::new(&format!("{DIR}/{name}")), &options)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let (pixels, _) = m.pixels(m.file_pixels.is_none().then_some(1e-7)).unwrap();
        let input = SurfaceInput {
            pixel_size: pixels.0,
            pixel_size_y: Some(pixels.1),
            ..SurfaceInput::default()
        };
        let std = f(&s["std_m"]);
        let out = match characterise(m.map, &input) {
            Ok((out, _)) => out,
            // A plane (nc-1.nc): numpy's residual is roundoff too.
            Err(e) if e.to_string().contains("flat") && want < 1e-12 * std => {
                checked += 1;
                continue;
            }
            Err(e) => panic!("{name}: {e}"),
        };
        let err = (out.rms_height_m - want).abs();
        assert!(
            err <= 1e-12 * std.max(want),
            "{name}: rms {:e} vs {want:e} (std {std:e})",
            out.rms_height_m
        );
        checked += 1;
    }
    assert_eq!(checked, 23);
}
