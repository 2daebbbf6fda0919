//! Honest convergence of the boundary elements: every state reports its
//! iterations, final residual and whether it converged; a solve stopped at
//! the iteration cap fails (exit 1 naming the residual) unless allowed,
//! then it is flagged `converged: false` with a warning; a mean gap beyond
//! the surface's highest point answers "no contact" at once (it used to
//! iterate to the cap: `u = g + h` loses the heights' digits when the gap
//! is 1 m and the heights 1e-7 m).

use asperity::bem::{Options, Problem, AT_CAP};
use asperity::surface::{npy, HeightMap};
use asperity::Error;
use serde_json::Value;
use std::process::Command;
use std::time::Instant;

const MAP: &str = "examples/data/selfaffine-256.npy";
const DX: &str = "3.90625e-7";

fn map() -> HeightMap {
    npy::parse(&std::fs::read(MAP).unwrap()).unwrap()
}

fn run(extra: &[&str]) -> (i32, String, String) {
    let mut args = vec![
        "bem",
        MAP,
        "--pixel-size",
        DX,
        "--estar",
        "1e9",
        "--periodic",
    ];
    args.extend_from_slice(extra);
    let out = Command::new(env!("CARGO_BIN_EXE_asperity"))
        .args(&args)
        .output()
        .expect("run asperity");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn cap_is_an_error_with_the_residual_unless_allowed() {
    let m = map();
    let capped = Options {
        max_iterations: 5,
        ..Options::default()
    };
    let prob = Problem::new(&m, 3.90625e-7, 1e9, true, &capped).unwrap();
    for gap_control in [false, true] {
        let solve = |o: &Options| {
            if gap_control {
                prob.solve_gap(1e-7, o, None)
            } else {
                prob.solve_pressure(1e6, o, None)
            }
        };
        match solve(&capped) {
            Err(Error::NoConvergence {
                what,
                iterations,
                residual,
            }) => {
                assert!(what.ends_with(AT_CAP), "{what}");
                assert_eq!(iterations, 5);
                assert!(residual > capped.tolerance && residual.is_finite());
            }
            r => panic!("expected no convergence, got {r:?}"),
        }
        let allowed = Options {
            allow_unconverged: true,
            ..capped
        };
        let s = solve(&allowed).unwrap();
        assert!(!s.converged);
        assert_eq!(s.iterations, 5);
        assert!(s.residual > capped.tolerance);
        // The same iterate as the failure reported.
        let Err(Error::NoConvergence { residual, .. }) = solve(&capped) else {
            unreachable!()
        };
        assert_eq!(s.residual, residual);
        // Converged solves say so.
        let full = solve(&Options::default()).unwrap();
        assert!(full.converged && full.residual < 1e-10, "{}", full.residual);
    }
}

#[test]
fn cli_cap_exits_1_and_allowed_is_flagged() {
    for target in [["--pressures", "1e6"], ["--gaps", "1e-7"]] {
        let mut a = target.to_vec();
        a.extend(["--max-iterations", "5"]);
        let (code, _, err) = run(&a);
        assert_eq!(code, 1, "{err}");
        for needle in [
            target[0],
            "iteration cap",
            "residual",
            "--allow-unconverged",
            "--max-iterations 5",
        ] {
            assert!(err.contains(needle), "{needle} not in {err}");
        }
        a.extend(["--allow-unconverged", "--json"]);
        let (code, out, err) = run(&a);
        assert_eq!(code, 0, "{err}");
        let v: Value = serde_json::from_str(out.trim()).unwrap();
        let s = &v["states"][0];
        assert_eq!(s["converged"], Value::Bool(false));
        assert_eq!(s["iterations"], 5);
        assert!(s["residual"].as_f64().unwrap() > 1e-10);
        let w = v["warnings"].to_string();
        assert!(w.contains("not converged"), "{w}");
        assert!(v["numerical_error"]
            .as_str()
            .unwrap()
            .contains("NOT converged"));
    }
    // The table shows the flag.
    let (code, out, _) = run(&[
        "--pressures",
        "1e6",
        "--max-iterations",
        "5",
        "--allow-unconverged",
    ]);
    assert_eq!(code, 0);
    assert!(out.contains("conv") && out.contains(" NO |"), "{out}");
    // Every state of a converged run has the three keys.
    let (code, out, err) = run(&["--pressures", "1e6,1e7", "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(out.trim()).unwrap();
    for s in v["states"].as_array().unwrap() {
        assert!(s["iterations"].as_u64().unwrap() > 0);
        assert!(s["residual"].as_f64().unwrap() < 1e-10);
        assert_eq!(s["converged"], Value::Bool(true));
    }
}

#[test]
fn far_gap_is_no_contact_at_once() {
    let m = map();
    let opts = Options::default();
    for periodic in [true, false] {
        let prob = Problem::new(&m, 3.90625e-7, 1e9, periodic, &opts).unwrap();
        let t = Instant::now();
        let s = prob.solve_gap(1.0, &opts, None).unwrap();
        assert!(t.elapsed().as_secs_f64() < 1.0);
        assert_eq!((s.iterations, s.contact_pixels), (0, 0));
        assert_eq!((s.mean_pressure, s.residual), (0.0, 0.0));
        assert!(s.converged && (s.mean_gap - 1.0).abs() < 1e-15);
    }
    // With adhesion: the tension -(w/rho) exp(-g/rho) is below every
    // double's resolution of the residual there; the rigid state is the
    // answer, its residual measured.
    let prob = Problem::new(&m, 3.90625e-7, 1e9, true, &opts)
        .unwrap()
        .with_adhesion(0.05, 2e-9)
        .unwrap();
    let s = prob.solve_gap(1.0, &opts, None).unwrap();
    assert_eq!((s.iterations, s.contact_pixels), (0, 0));
    assert!(s.residual < opts.tolerance && s.mean_pressure <= 0.0);
    // Just above the highest point the adhesion pulls: the solver runs.
    let near = prob.zero_load_gap() * 1.01;
    let s = prob.solve_gap(near, &opts, None).unwrap();
    assert!(s.iterations > 0 && s.converged);
    // The command: at once, with its warning (it took the 10,000-iteration
    // cap before, over 2 minutes, then exit 2).
    let t = Instant::now();
    let (code, out, err) = run(&["--gaps", "1", "--json"]);
    assert_eq!(code, 0, "{err}");
    assert!(t.elapsed().as_secs_f64() < 20.0);
    let v: Value = serde_json::from_str(out.trim()).unwrap();
    assert_eq!(v["states"][0]["area_fraction"], 0.0);
    assert_eq!(v["states"][0]["iterations"], 0);
    assert!(v["warnings"].to_string().contains("no contact"));
}
