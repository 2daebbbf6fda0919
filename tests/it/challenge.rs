//! The contact-mechanics challenge at 512^2 (`examples/challenge/`) against
//! ContactMechanics 1.8.3 and Adhesion 0.93 on the same surface
//! (`tests/data/challenge_peers.json`, written by
//! `examples/challenge/peers.py` from `tests/data/challenge_512.npy`).
//!
//! Tolerances: 1e-6 relative, the agreement asked of the two codes where
//! both converge. Both sides solve far tighter than that, so the test fails
//! on any difference of definition or discretisation: the peers' residuals
//! (in the JSON) are a largest penetration of 5e-19 m against a mean gap of
//! 1.6e-6 m (Polonsky & Keer) and a largest projected gradient of 4e-17 N
//! per pixel against a pixel force `P dx^2 = 1e-8 N` (Bugnicourt), asperity's
//! residual 1e-10 of the full-contact pressure. The contact area is a count
//! of pixels (6,506 of 262,144): 1e-6 of it is less than one pixel, so the
//! counts must be equal.

use asperity::bem::challenge::{self, Challenge};
use asperity::bem::{Options, Problem};
use asperity::surface::npy;
use serde_json::Value;

const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/");

fn peers() -> Value {
    let text = std::fs::read_to_string(format!("{DIR}challenge_peers.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

fn close(got: f64, want: &Value, what: &str) {
    let want = want.as_f64().unwrap();
    let rel = (got / want - 1.0).abs();
    assert!(rel < 1e-6, "{what}: asperity {got}, peer {want} ({rel:e})");
}

/// The stored map is the example's surface: the same seed and spectrum give
/// it again (to rounding: the FFT's SIMD path may differ by a few ulps),
/// with RMS gradient 1.
#[test]
fn the_stored_map_is_the_generated_challenge_surface() {
    let c = Challenge::at(512).unwrap();
    let generated = c.surface().unwrap();
    let stored = npy::parse(&std::fs::read(format!("{DIR}challenge_512.npy")).unwrap()).unwrap();
    assert_eq!((stored.rows(), stored.cols()), (512, 512));
    let scale = generated.largest();
    let worst = generated
        .heights()
        .iter()
        .zip(stored.heights())
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(worst <= 1e-12 * scale, "{worst} of {scale}");
    let g = challenge::slope_rms(&stored, c.pixel_size());
    assert!((g - 1.0).abs() < 1e-12, "{g}");
}

/// A/A0, the mean gap and the adhesive mean pressure against the peers.
#[test]
fn the_challenge_agrees_with_contactmechanics_and_adhesion() {
    let want = peers();
    let prov = &want["provenance"]["packages"];
    assert_eq!(prov["contactmechanics"], "1.8.3");
    assert_eq!(prov["Adhesion"], "0.93");
    let (dry_want, wet_want) = (&want["non_adhesive"], &want["adhesive"]);
    assert_eq!(dry_want["converged"], true);
    assert_eq!(wet_want["converged"], true);

    let c = Challenge::at(512).unwrap();
    close(
        c.reference_pressure,
        &want["reference_pressure_pa"],
        "p_ref",
    );
    close(c.adhesion_range(), &want["adhesion_range_m"], "rho");
    let map = npy::parse(&std::fs::read(format!("{DIR}challenge_512.npy")).unwrap()).unwrap();
    let opts = Options {
        tolerance: 1e-10,
        ..Default::default()
    };
    let dry = Problem::new(&map, c.pixel_size(), c.contact_modulus, true, &opts).unwrap();
    let s = dry
        .solve_pressure(c.reference_pressure, &opts, None)
        .unwrap();
    assert_eq!(
        s.contact_pixels as u64,
        dry_want["contact_pixels"].as_u64().unwrap()
    );
    close(s.area_fraction(), &dry_want["area_fraction"], "dry A/A0");
    close(s.mean_gap, &dry_want["mean_gap_m"], "dry mean gap");

    // The adhesive problem at the non-adhesive state's mean gap (the
    // peer's at its own, 1e-11 apart).
    let wet = Problem::new(&map, c.pixel_size(), c.contact_modulus, true, &opts)
        .unwrap()
        .with_adhesion(c.adhesion_energy, c.adhesion_range())
        .unwrap();
    let a = wet.solve_gap(s.mean_gap, &opts, None).unwrap();
    assert_eq!(
        a.contact_pixels as u64,
        wet_want["contact_pixels"].as_u64().unwrap()
    );
    close(
        a.area_fraction(),
        &wet_want["area_fraction"],
        "adhesive A/A0",
    );
    close(a.mean_gap, &wet_want["mean_gap_m"], "adhesive mean gap");
    close(
        a.mean_pressure,
        &wet_want["mean_pressure_pa"],
        "adhesive mean pressure",
    );
    // Adhesion pulls: more contact, less pressure at the same mean gap.
    assert!(a.contact_pixels > s.contact_pixels);
    assert!(a.mean_pressure < s.mean_pressure);
}
