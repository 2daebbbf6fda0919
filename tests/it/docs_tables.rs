//! The result tables of `docs/` are what their commands print: each test
//! runs the code of the command the text names and compares the rows it
//! prints with the quoted ones (timing columns aside).

use std::path::PathBuf;

#[path = "../../tools/reports/model_error_maps.rs"]
mod model_error_maps;
#[path = "../../tools/reports/rough_sphere_regimes.rs"]
mod rough_sphere_regimes;
#[path = "../../tools/reports/surface_bias.rs"]
mod surface_bias;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A Markdown row without its last cell (a timing).
fn without_last_cell(row: &str) -> String {
    let cells: Vec<&str> = row.trim().trim_matches('|').split('|').collect();
    cells[..cells.len() - 1].join("|")
}

/// docs/physics.md's "GW and Persson against the exact solution":
/// `cargo run --release --example model_error_maps`.
#[test]
fn the_model_error_table_of_the_maps_is_what_its_example_prints() {
    let physics = std::fs::read_to_string(root().join("docs/physics.md")).unwrap();
    assert!(
        physics.contains("cargo run --release --example model_error_maps"),
        "the table's command changed"
    );
    let at = physics
        .find(model_error_maps::HEADER)
        .expect("the table's header changed");
    let quoted: Vec<String> = physics[at..]
        .lines()
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .map(without_last_cell)
        .collect();
    let printed = model_error_maps::rows(&root());
    let printed_cut: Vec<String> = printed.iter().map(|r| without_last_cell(r)).collect();
    assert_eq!(
        quoted,
        printed_cut,
        "docs/physics.md's model-error table differs from what the example prints now:\n{}",
        printed.join("\n")
    );
}

/// docs/physics.md's regime map of the rough sphere:
/// `cargo run --release --example rough_sphere_regimes`.
#[test]
fn the_rough_sphere_regime_map_is_what_its_example_prints() {
    let physics = std::fs::read_to_string(root().join("docs/physics.md")).unwrap();
    assert!(
        physics.contains("cargo run --release --example rough_sphere_regimes"),
        "the table's command changed"
    );
    let at = physics
        .find(rough_sphere_regimes::HEADER)
        .expect("the table's header changed");
    let quoted: Vec<&str> = physics[at..]
        .lines()
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .collect();
    let printed = rough_sphere_regimes::rows();
    assert_eq!(
        quoted,
        printed,
        "docs/physics.md's regime map differs from what the example prints now:\n{}",
        printed.join("\n")
    );
}

/// docs/surface.md's grid bias on synthetic Gaussian surfaces:
/// `cargo run --release --example surface_bias` (about 1.5 min for the
/// eight rows). The test reruns the rows of the two shortest correlation
/// lengths (8 maps of 1024^2 each, a few seconds), which the text quotes
/// ("density -9 %, curvature -11 % at l = 2"), and checks that the other
/// rows are those lengths, on the example's grids.
#[test]
fn the_grid_bias_table_is_what_its_example_prints() {
    let surface = std::fs::read_to_string(root().join("docs/surface.md")).unwrap();
    assert!(
        surface.contains("`cargo run --release --example surface_bias`"),
        "the table's command changed"
    );
    let at = surface
        .find(surface_bias::HEADER)
        .expect("the table's header changed");
    let quoted: Vec<&str> = surface[at..]
        .lines()
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .collect();
    assert_eq!(quoted.len(), surface_bias::LENGTHS.len());
    for (row, l) in quoted.iter().zip(surface_bias::LENGTHS) {
        let n = ((256.0 * l) as usize).clamp(1024, 4096);
        assert!(
            row.starts_with(&format!("| {l} | {n}² | ")),
            "docs/surface.md: the row of l = {l}: {row}"
        );
    }
    for (k, l) in surface_bias::LENGTHS[..2].iter().enumerate() {
        let printed = surface_bias::row(*l).unwrap();
        assert_eq!(
            quoted[k], printed,
            "docs/surface.md's grid-bias row l = {l} differs from what the example prints now"
        );
    }
}

/// `x` as Python's `%.{p}g` prints it (the table's digits).
fn g(x: f64, p: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let sci = format!("{:.*e}", p - 1, x);
    let (mantissa, exp) = sci.split_once('e').unwrap();
    let exp: i32 = exp.parse().unwrap();
    let trim = |s: &str| -> String {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s.to_string()
        }
    };
    if exp < -4 || exp >= p as i32 {
        let sign = if exp < 0 { '-' } else { '+' };
        format!("{}e{sign}{:02}", trim(mantissa), exp.abs())
    } else {
        let decimals = (p as i32 - 1 - exp).max(0) as usize;
        trim(&format!("{x:.decimals$}"))
    }
}

/// docs/physics.md's "Model error on a rough surface": `mems-gold.toml` at
/// five `sigma/z0` with each law, as the table's caption says (its
/// regenerating command is this test: on a difference it prints the rows).
#[test]
fn the_pull_off_table_of_the_laws_is_what_the_scenes_give() {
    use crate::common::cli::{example, run_scene_json, tmp};
    let physics = std::fs::read_to_string(root().join("docs/physics.md")).unwrap();
    let header = "| sigma/z0 | calibrated (LJ) P_c [uN] |";
    let at = physics.find(header).expect("the table's header changed");
    let quoted: Vec<&str> = physics[at..]
        .lines()
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .collect();
    let base = example("mems-gold.toml");
    for key in [
        "kind = \"auto\"",
        "sigma = 5e-9 ",
        "closest_separation = 5e-9 ",
    ] {
        assert!(base.contains(key), "mems-gold.toml changed: {key}");
    }
    let dir = tmp("pull-off-laws");
    let scene = |sigma: f64, law: &str, seeds: u32| -> serde_json::Value {
        let text = base
            .replacen("kind = \"auto\"", &format!("kind = \"{law}\""), 1)
            .replacen("sigma = 5e-9 ", &format!("sigma = {sigma:e} "), 1)
            .replacen(
                "closest_separation = 5e-9 ",
                &format!("closest_separation = {sigma:e} "),
                1,
            )
            + &format!("\n[montecarlo]\nseeds = {seeds}\n");
        run_scene_json(&dir, &format!("{law}-{sigma:e}"), &text)
    };
    let z0 = 0.3e-9;
    let mut printed = Vec::new();
    for sigma in [0.3e-9, 1e-9, 3e-9, 5e-9, 10e-9] {
        let cal = scene(sigma, "calibrated", 100);
        let mut row = vec![
            g(sigma / z0, 3),
            g(cal["pull_off_load_N"].as_f64().unwrap() * 1e6, 4),
        ];
        for law in ["maugis", "jkr", "dmt"] {
            let v = scene(sigma, law, 2);
            let shown = v["pull_off_load_N"]
                .as_f64()
                .map_or("none".to_string(), |p| g(p * 1e6, 4));
            row.push(match v["model_error"]["pull_off"].as_f64() {
                Some(e) => format!("{shown} ({:+.0} %)", 100.0 * e),
                None => shown,
            });
        }
        let pop = &cal["pull_off_population"];
        let f = |k: &str| pop[k].as_f64().unwrap_or(f64::NAN);
        row.push(format!(
            "{} +- {}",
            g(f("mean_N") * 1e6, 4),
            g(f("mean_se_N") * 1e6, 2)
        ));
        row.push(g(f("p05_N") * 1e6, 4));
        row.push(g(f("carriers"), 3));
        printed.push(format!("| {} |", row.join(" | ")));
    }
    assert_eq!(
        quoted,
        printed,
        "docs/physics.md's pull-off table differs from the runs; paste:\n{}",
        printed.join("\n")
    );
}

#[test]
fn python_g_formatting() {
    assert_eq!(g(-21540.4, 4), "-2.154e+04");
    assert_eq!(g(-7989.2, 4), "-7989");
    assert_eq!(g(-0.02143, 4), "-0.02143");
    assert_eq!(g(1.0, 3), "1");
    assert_eq!(g(10.0 / 0.3, 3), "33.3");
    assert_eq!(g(6.4, 2), "6.4");
    assert_eq!(g(8890.0, 3), "8.89e+03");
    assert_eq!(g(0.0799, 3), "0.0799");
}
