//! The result tables of `docs/` are what their commands print: each test
//! runs the code of the command the text names and compares the rows it
//! prints with the quoted ones (timing columns aside).

use std::path::PathBuf;

#[path = "../../tools/reports/model_error_maps.rs"]
mod model_error_maps;
#[path = "../../tools/reports/rough_sphere_regimes.rs"]
mod rough_sphere_regimes;

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
