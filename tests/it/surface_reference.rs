//! `asperity::surface` against the independent numpy implementation of the
//! same rules (`tests/data/surface_ref.py`, stored maps), the two readers
//! against each other, and the Nayak closed forms against mpmath quadrature
//! of Rice's integrals (`tests/data/nayak_summits.py`).

use crate::common::{local, num, rel};
use asperity::surface::{
    npy, text, Characterisation, HeightMap, Moments, NayakPrediction, Topography,
};
use serde_json::Value;

fn read(name: &str) -> Vec<u8> {
    std::fs::read(format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"))).unwrap()
}

fn npy_map(name: &str) -> HeightMap {
    npy::parse(&read(&format!("{name}.npy"))).unwrap()
}

fn text_map(file: &str) -> HeightMap {
    text::parse(std::str::from_utf8(&read(file)).unwrap()).unwrap()
}

/// Every number of the contract plus the summit positions, to `tol`.
fn assert_matches(c: &Characterisation, r: &Value, tol: f64, what: &str) {
    assert_eq!(c.rows as u64, r["rows"].as_u64().unwrap());
    assert_eq!(c.cols as u64, r["cols"].as_u64().unwrap());
    let close = |a: f64, key: &str, v: &Value| {
        let b = num(&v[key]);
        assert!(
            rel(a, b) <= tol,
            "{what} {key}: {a} vs {b} (rel {:e})",
            rel(a, b)
        );
    };
    close(c.moments.rms_height(), "rms_height_m", r);
    close(c.moments.m0, "m0", r);
    close(c.moments.m2, "m2", r);
    close(c.moments.m4, "m4", r);
    close(c.bandwidth_alpha(), "bandwidth_alpha", r);
    let s = &r["summits"];
    assert_eq!(
        c.stats.count as u64,
        s["count"].as_u64().unwrap(),
        "{what} count"
    );
    let pos: Vec<[u64; 2]> = serde_json::from_value(r["positions"].clone()).unwrap();
    let ours: Vec<[u64; 2]> = c
        .summits
        .iter()
        .map(|s| [s.row as u64, s.col as u64])
        .collect();
    assert_eq!(ours, pos, "{what} positions");
    close(c.stats.density_per_m2, "density_per_m2", s);
    close(
        c.stats.mean_curvature_per_m.unwrap(),
        "mean_curvature_per_m",
        s,
    );
    close(c.stats.radius_m.unwrap(), "radius_m", s);
    close(c.stats.height_std_m.unwrap(), "height_std_m", s);
    // The mean height is a mean of residuals about 0: compare absolutely
    // on the scale of the RMS height.
    let mh = c.stats.mean_height_m.unwrap();
    let mh_ref = num(&s["mean_height_m"]);
    assert!(
        (mh - mh_ref).abs() <= tol * c.moments.rms_height(),
        "{what} mean_height_m: {mh} vs {mh_ref}"
    );
    let g = &r["gw_from_moments"];
    let gw = c.gw_from_moments();
    close(gw.density_per_m2, "density_per_m2", g);
    close(gw.radius_m, "radius_m", g);
    close(gw.sigma_m.unwrap(), "sigma_m", g);
}

#[test]
fn agrees_with_the_numpy_reference_to_1e_12() {
    let refs = local("surface_ref.json");
    for (name, r) in refs["maps"].as_object().unwrap() {
        let map = npy_map(name).scaled(num(&r["scale"])).unwrap();
        let topo = Topography::new(map, num(&r["pixel_size"])).unwrap();
        for (mode, periodic) in [("interior", false), ("periodic", true)] {
            let c = topo.characterise(periodic).unwrap();
            assert!(c.stats.count > 40, "{name} {mode}: {}", c.stats.count);
            assert_matches(&c, &r[mode], 1e-12, &format!("{name} {mode}"));
        }
    }
}

#[test]
fn the_two_readers_give_identical_maps_and_results() {
    for (name, twin, scale, dx) in [
        ("surface_a", "surface_a.txt", 1.0, 1e-7),
        ("surface_b", "surface_b.csv", 1e-9, 5e-8),
    ] {
        let a = npy_map(name);
        let b = text_map(twin);
        assert_eq!(a, b, "{name}");
        for periodic in [false, true] {
            let ca = Topography::new(a.clone().scaled(scale).unwrap(), dx)
                .unwrap()
                .characterise(periodic)
                .unwrap();
            let cb = Topography::new(b.clone().scaled(scale).unwrap(), dx)
                .unwrap()
                .characterise(periodic)
                .unwrap();
            assert_eq!(ca, cb, "{name} periodic {periodic}");
        }
    }
}

#[test]
fn nayak_closed_forms_match_rice_quadrature() {
    let refs = local("nayak_summits.json");
    for row in refs["rows"].as_array().unwrap() {
        let alpha = num(&row["alpha"]);
        let p = NayakPrediction::from_moments(&Moments::new(1.0, 1.0, alpha).unwrap());
        let checks = [
            (p.density_per_m2 / alpha, "density_over_m4_per_m2"),
            (
                p.mean_curvature_per_m / alpha.sqrt(),
                "mean_curvature_over_sqrt_m4",
            ),
            (p.mean_height_m, "mean_height_over_sqrt_m0"),
            (p.height_std_m, "height_std_over_sqrt_m0"),
        ];
        for (ours, key) in checks {
            let r = num(&row[key]);
            assert!(rel(ours, r) < 1e-13, "alpha {alpha} {key}: {ours} vs {r}");
        }
    }
}
