//! Limits with estimates (issue 24, item 10): work beyond a documented
//! bound is refused before it starts, naming the input and giving the
//! estimate; long work says so on stderr. Each case failed on the code
//! before its fix (ran for minutes, or failed after many seconds).
#[path = "common/cli.rs"]
mod cli;
use cli::{bin, example, run, run_within, tmp};

/// A CSV of `n` spots of radius 1 um on a 10 um grid (no overlaps).
fn spots_csv(n: usize) -> String {
    let mut s = String::from("x_m,y_m,radius_m\n");
    for k in 0..n {
        s.push_str(&format!(
            "{:e},{:e},1e-6\n",
            (k % 200) as f64 * 1e-5,
            (k / 200) as f64 * 1e-5
        ));
    }
    s
}

/// 20,001 spots need ~80 s of one core and 6.4 GB for the exact solve:
/// refused at once naming the file, with the estimate and the bound (the
/// old code started the solve).
#[test]
fn spots_beyond_the_bound_are_refused_with_the_estimate() {
    let dir = tmp("spots");
    let file = dir.join("many.csv");
    std::fs::write(&file, spots_csv(20_001)).unwrap();
    let mut cmd = bin();
    cmd.args([
        "spots",
        file.to_str().unwrap(),
        "--resistivity",
        "2.44e-8",
        "--json",
    ]);
    let o = run_within(cmd, 20.0);
    assert!(!o.timed_out, "still running after 20 s");
    assert_eq!(o.code, Some(2), "{}", o.stderr);
    for word in [
        "many.csv",
        "20001 spots",
        "estimated",
        "GB",
        "allowed up to 20000",
    ] {
        assert!(o.stderr.contains(word), "{word}: {}", o.stderr);
    }
    assert!(o.stdout.is_empty(), "{}", o.stdout);
}

/// 4,000 spots (estimated 0.64 s) run quietly; the estimate is printed on
/// stderr only above 2 s, never on stdout (the JSON stays one object).
#[test]
fn spots_below_two_seconds_stay_quiet() {
    let dir = tmp("spots-quiet");
    std::fs::write(dir.join("s.csv"), spots_csv(4_000)).unwrap();
    let (code, out, err) = run(
        &["spots", "s.csv", "--resistivity", "2.44e-8", "--json"],
        &dir,
    );
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert!(v["exact_ohm"].as_f64().unwrap() > 0.0);
    assert!(err.is_empty(), "{err}");
}

/// The estimate itself: 8,000 spots announce ~5 s (measured 4.5 s of one
/// core) on stderr, and finish.
#[test]
#[ignore = "about 5 s of CPU and 1 GB; run with --ignored"]
fn spots_above_two_seconds_print_the_estimate() {
    let dir = tmp("spots-loud");
    std::fs::write(dir.join("s.csv"), spots_csv(8_000)).unwrap();
    let (code, out, err) = run(
        &["spots", "s.csv", "--resistivity", "2.44e-8", "--json"],
        &dir,
    );
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("8000 spots") && err.contains("estimated 5.120 s"),
        "{err}"
    );
    assert!(
        serde_json::from_str::<serde_json::Value>(&out).is_ok(),
        "{out}"
    );
}

/// `calibrated-gold.toml` at rtol = 1e-12 (the scene's documented lower
/// bound) failed with exit 1 after a quadrature stall (5e-12 ran 14 s
/// first); the calibrated law's floor 1e-11 is refused up front, naming
/// accuracy.rtol with the range, before any calibration; `auto` choosing
/// the calibrated law says so. 1e-11 runs.
#[test]
fn a_calibrated_law_below_its_rtol_floor_is_refused_naming_rtol() {
    let dir = tmp("calibrated");
    let cache = dir.join("cache");
    for (scene, rtol, code) in [
        ("calibrated-gold.toml", "1e-12", 2),
        ("calibrated-gold.toml", "5e-12", 2),
        ("mems-gold.toml", "1e-12", 2),
        ("calibrated-gold.toml", "1e-11", 0),
    ] {
        let text: String = example(scene)
            .lines()
            .map(|l| {
                if l.starts_with("rtol") {
                    format!("rtol = {rtol}")
                } else {
                    l.to_string()
                }
            })
            .collect::<Vec<_>>()
            .join("\n");
        assert!(text.contains(&format!("rtol = {rtol}")));
        std::fs::write(dir.join(scene), text).unwrap();
        let mut cmd = bin();
        cmd.args(["run", scene, "--out", &format!("out-{rtol}")])
            .current_dir(&dir)
            .env("ASPERITY_CACHE", &cache);
        let o = run_within(cmd, 60.0);
        assert!(!o.timed_out, "{scene} {rtol}: still running");
        assert_eq!(o.code, Some(code), "{scene} {rtol}: {}", o.stderr);
        if code == 2 {
            assert!(o.stderr.contains("accuracy.rtol"), "{}", o.stderr);
            assert!(o.stderr.contains("allowed [1e-11, 0.1]"), "{}", o.stderr);
            assert!(o.seconds < 10.0, "{scene} {rtol}: {} s", o.seconds);
        }
        if scene == "mems-gold.toml" {
            assert!(o.stderr.contains("\"auto\""), "{}", o.stderr);
        }
    }
}
