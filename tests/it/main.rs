//! The integration tests, one binary (`cargo test --test it`): one module
//! per subject, each formerly its own test binary. Linking one binary
//! instead of 68 is most of what a fresh `cargo test` saved (README, "Two
//! commands"). Test names are `module::test`, so `cargo test --test it
//! cli_sweep::` runs one module. Tests that start the program use
//! `env!("CARGO_BIN_EXE_asperity")`; data paths are built from
//! `env!("CARGO_MANIFEST_DIR")` (`tests/data/`).
//!
//! No test sets process-wide state (environment variables, the global rayon
//! pool, the working directory): subprocesses get their environment through
//! `Command::env`, thread counts through local `rayon::ThreadPool`s, so every
//! module shares this one process safely.

mod common;

mod axisym;
mod bem;
mod bem_full;
mod bem_honest;
mod bem_plastic;
mod bem_plastic_adhesion;
mod bem_plastic_cm;
mod bem_threads;
mod capillary;
mod capillary_maps;
mod challenge;
mod chart_rules;
mod cli_bem;
mod cli_electrical;
mod cli_fn;
mod cli_fuzz;
mod cli_help;
mod cli_law;
mod cli_measured;
mod cli_punch;
mod cli_robustness;
mod cli_rough_sphere;
mod cli_run;
mod cli_shape;
mod cli_sphere;
mod cli_surface;
mod cli_sweep;
mod cos_vs_maugis;
mod doc_reference_tables;
mod docs;
mod docs_figures;
mod docs_tables;
mod electrical;
mod fuller_tabor;
mod gaussian_fn;
mod golden;
mod gw_closed_forms;
mod gw_far_tail;
mod gw_md_accuracy;
mod gw_parallel;
mod heights;
mod hysteresis_energy;
mod law_properties;
mod limits;
mod map_model_error;
mod map_pull_off;
mod maugis;
mod maugis_gw;
mod model_error;
mod never_wrong;
mod observables;
mod performance_tables;
mod persson;
mod persson_gaps;
mod plastic;
mod plastic_history;
mod plastic_properties;
mod plastic_retraction_split;
mod pull_off_population;
mod pull_off_start;
mod pull_off_window;
mod punch;
mod punch_asymptotics;
mod punch_fit;
mod quantile_intervals;
mod quantities;
mod readme_lines;
mod readme_tables;
mod retraction_minimum;
mod rough_sphere;
mod rough_sphere_si;
mod scene_features;
mod scene_fuzz;
mod scenes;
mod shaped_gw;
mod shaped_law;
mod shaped_md;
mod silent_wrong;
mod silent_wrong_two;
mod simd_widths;
mod sphere_calibration;
mod sphere_convergence;
mod sphere_large_mu;
mod sphere_scene;
mod stickiness;
mod struve;
mod surface_reference;
mod surface_scene;
mod surface_synthetic;
mod text_output;
mod theory_differences;
mod topography_deflated;
mod topography_errors;
mod topography_reference;
mod warnings;
mod wet_scenes;
