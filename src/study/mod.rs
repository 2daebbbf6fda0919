//! The study layer: scenes (what to compute), the planner (how), runs,
//! outputs (tables, JSON, charts) and sweeps. It only assembles pieces of the
//! physics core; it owns the file formats (TOML scenes, CSV, JSON, SVG) and
//! maps core errors onto scene fields.
//!
//! Compiled with the default feature `study`; the physics core builds without
//! it (`cargo build --lib --no-default-features`).

pub mod cache;
pub mod measured;
pub mod output;
pub mod plan;
pub mod plot;
pub mod quantity;
pub mod run;
pub mod scene;
pub mod sweep;
pub mod validity;

pub use output::{
    charts, curve_csv, montecarlo_csv, text_report, write_outputs, McSummary, PlasticitySummary,
    StictionSummary, Summary,
};
pub use plan::{Plan, PlanMode};
pub use quantity::{Quantity, QuantitySet, Record, StateRow};
pub use run::{McResults, Results};
pub use scene::{Scene, DEFAULT_SCENE};
