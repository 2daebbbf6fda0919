//! the hysteresis energy follows the tolerance. JKR
//! asperities on Gaussian heights (Fuller & Tabor), against the mpmath
//! reference of tests/data/hysteresis_energy.py (30 digits; the energy
//! computed per asperity and then over heights, not over separation).
use asperity::gw::{Accuracy, GwModel, RoughSurface};
use asperity::heights::Gaussian;
use asperity::law::Jkr;
use asperity::loading::{hysteresis_energy_to, LoadingModel, LoadingProgram, Observables};
use std::f64::consts::PI;
use std::sync::Arc;

/// Units R = 1, K = 1 (E* = 3/4), pi w R = 1, N = 1: the interference unit
/// is 1, so sigma = k and energies are in N pi w R delta_unit.
fn model(k: f64, rtol: f64) -> GwModel {
    let (r, e, w) = (1.0, 0.75, 1.0 / PI);
    let surface = RoughSurface::new(1.0, r, k, 1.0).unwrap();
    GwModel::new(
        surface,
        Arc::new(Gaussian::new()),
        Arc::new(Jkr::new(r, e, w).unwrap()),
    )
    .unwrap()
    .with_accuracy(Accuracy::new(rtol).unwrap())
}

#[test]
fn hysteresis_energy_meets_the_tolerance() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/hysteresis_energy.json"
    ))
    .unwrap();
    let doc: serde_json::Value = serde_json::from_str(&text).unwrap();
    for case in doc["cases"].as_array().unwrap() {
        let k = case["k_sigma_over_maugis_delta"].as_f64().unwrap();
        let (h_min, h_start) = (
            case["h_min"].as_f64().unwrap(),
            case["h_start"].as_f64().unwrap(),
        );
        let want = case["energy_over_N_pi_w_R_delta"].as_f64().unwrap();
        let program = LoadingProgram::new(h_start * k, h_min * k, 200).unwrap();
        for rtol in [1e-6, 1e-9] {
            let m = model(k, rtol);
            let got = hysteresis_energy_to(&m, &program, rtol).unwrap();
            let rel = (got / want - 1.0).abs();
            // The states are accurate to rtol against int |integrand|,
            // which here is within a factor of a few of the energy.
            assert!(
                rel < 10.0 * rtol,
                "k {k} rtol {rtol}: {got} vs {want} ({rel:e})"
            );
            if rtol == 1e-9 {
                let trapezoid = m
                    .curve(&program, &Observables::LOAD)
                    .unwrap()
                    .hysteresis_energy()
                    .unwrap();
                eprintln!(
                    "k {k}: adaptive {rel:.1e}, trapezoid on 200 points {:.1e}",
                    (trapezoid / want - 1.0).abs()
                );
            }
        }
    }
}

#[test]
fn no_hysteresis_without_adhesion_and_bad_rtol_is_refused() {
    let s = RoughSurface::gold_microswitch();
    let hertz = asperity::law::Hertz::new(s.radius, 5e10).unwrap();
    let m = GwModel::new(s, Arc::new(Gaussian::new()), Arc::new(hertz)).unwrap();
    let program = LoadingProgram::new(4.0 * s.sigma, 0.0, 50).unwrap();
    assert_eq!(hysteresis_energy_to(&m, &program, 1e-8).unwrap(), 0.0);
    let e = hysteresis_energy_to(&m, &program, 0.0).unwrap_err();
    assert_eq!(e.field(), Some("rtol"));
}

/// Gauss–Legendre nodes and weights on [-1, 1] (Newton on P_n), written
/// here so that the reference shares no quadrature code with the library.
fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (1..=n)
        .map(|i| {
            let mut x = (PI * (i as f64 - 0.25) / (n as f64 + 0.5)).cos();
            let mut dp = 0.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                    (p0, p1) = (p1, p2);
                }
                dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                let dx = p1 / dp;
                x -= dx;
                if dx.abs() < 1e-16 {
                    break;
                }
            }
            (x, 2.0 / ((1.0 - x * x) * dp * dp))
        })
        .collect()
}

/// `mems-gold.toml` with sigma = 1 nm, w = 0.033 J/m^2
/// (lambda 0.301: jump-in onto the non-contact branch), Maugis–Dugdale,
/// closest separation 0.5 nm, start 6 nm, rtol 1e-6 reported 1.69725e-16 J
/// against the exact 1.69423e-16 J (1.8e-3 off): the retracting summits'
/// edge (attach interference reached at `z = closest + delta_att`) and
/// their detach edge (`z = d + delta_det`) cross at `d = closest +
/// delta_att - delta_det`, a kink of the gap inside one panel that fooled
/// the adaptive rule. Reference: 40-point Gauss–Legendre on 64 panels per
/// piece, split at that kink, the states at rtol 1e-10.
#[test]
fn hysteresis_energy_meets_rtol_across_the_attach_detach_kink() {
    use asperity::law::{AsperityLaw, Maugis};
    use asperity::loading::History;
    let (e, nu, r, w, z0) = (79e9, 0.42, 1e-6, 0.033, 0.3e-9);
    let estar = e / (2.0 * (1.0 - nu * nu));
    // The scene's lambda: the Dugdale stress matched to the Lennard-Jones
    // maximum tension (lambda = 1.1570 mu).
    let contact = asperity::material::AsperityContact::new(
        r,
        estar,
        asperity::material::Adhesion::new(w, z0).unwrap(),
    )
    .unwrap();
    let lambda = contact.lambda();
    assert!((lambda - 0.3006).abs() < 1e-4, "lambda {lambda}");
    let law = Arc::new(Maugis::new(r, estar, w, lambda).unwrap());
    let (att, det) = (law.attach_interference(), law.detach_interference());
    let surface = RoughSurface::new(1e12, r, 1e-9, 1e-8).unwrap();
    let make = |rtol: f64| {
        GwModel::new(surface, Arc::new(Gaussian::new()), law.clone())
            .unwrap()
            .with_accuracy(asperity::gw::Accuracy::new(rtol).unwrap())
    };
    let (closest, start) = (0.5e-9, 6e-9);
    let exact = make(1e-10);
    let gap = |d: f64| {
        let a = exact
            .state(d, History::Approach, &Observables::LOAD)
            .unwrap();
        let b = exact
            .state(d, History::Retract { closest }, &Observables::LOAD)
            .unwrap();
        a.load().unwrap() - b.load().unwrap()
    };
    let kink = closest + att - det;
    assert!(kink > closest && kink < start, "kink {kink:e}");
    let gl = gauss_legendre(40);
    let (mut reference, mut magnitude) = (0.0, 0.0);
    for (lo, hi) in [(closest, kink), (kink, start)] {
        let panels = 64;
        let h = (hi - lo) / panels as f64;
        for p in 0..panels {
            let mid = lo + (p as f64 + 0.5) * h;
            for &(x, wt) in &gl {
                let g = gap(mid + 0.5 * h * x);
                reference += 0.5 * h * wt * g;
                magnitude += 0.5 * h * wt * g.abs();
            }
        }
    }
    // The independent value (split quadrature and a converged
    // 4000-point trapezoid): 1.69423e-16 J.
    assert!(
        (reference / 1.69423e-16 - 1.0).abs() < 5e-6,
        "reference {reference:e}"
    );
    let program = LoadingProgram::new(start, closest, 120).unwrap();
    // States to 1e-8, so that the cycle integral's own rtol is what is
    // tested (with states to 1e-6 the loads' own errors, ~1e-6 of loads far
    // larger than the gap, are the floor).
    let got = hysteresis_energy_to(&make(1e-8), &program, 1e-6).unwrap();
    assert!(
        (got - reference).abs() <= 1e-6 * magnitude,
        "{got:e} vs {reference:e}: {:.2e} of the magnitude",
        (got - reference).abs() / magnitude
    );
    // The scene, as asperity run computes it (rtol 1e-6 for the
    // states and the energy): within rtol of the reference (1.69725e-16 J
    // before, 1.8e-3 off).
    let dir = std::env::temp_dir().join(format!("asperity-hyst-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let root = env!("CARGO_MANIFEST_DIR");
    let scene: String = std::fs::read_to_string(format!("{root}/examples/scenes/mems-gold.toml"))
        .unwrap()
        .lines()
        .map(|l| match l.split(' ').next().unwrap_or("") {
            "sigma" => "sigma = 1e-9".to_string(),
            "w" => "w = 0.033".to_string(),
            "kind" => "kind = \"maugis\"".to_string(),
            "closest_separation" => {
                "closest_separation = 0.5e-9\nstart_separation = 6e-9".to_string()
            }
            "points" => "points = 120".to_string(),
            _ => l.to_string(),
        })
        .collect::<Vec<_>>()
        .join("\n");
    std::fs::write(dir.join("s.toml"), scene).unwrap();
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(["run", "s.toml", "--out", "o"])
        .env("ASPERITY_CACHE", dir.join("cache"))
        .current_dir(&dir)
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("o/summary.json")).unwrap())
            .unwrap();
    let scene_energy = summary["hysteresis_energy"].as_f64().unwrap();
    assert!(
        (scene_energy - reference).abs() <= 1e-6 * magnitude,
        "scene: {scene_energy:e} vs {reference:e}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
