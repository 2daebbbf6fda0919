//! The study layer: scenes (what to compute), the planner (how), runs,
//! outputs (tables, JSON, charts) and sweeps. It only assembles pieces of the
//! physics core; it owns the file formats (TOML scenes, CSV, JSON, SVG) and
//! maps core errors onto scene fields.
//!
//! Compiled with the default feature `study`; the physics core builds without
//! it (`cargo build --lib --no-default-features`).
//!
//! ```
//! use asperity::study::{Plan, PlanMode, Scene, Summary, DEFAULT_SCENE};
//!
//! // The default gold switch without adhesion, pressed to the mean summit
//! // plane: Hertz summits on Gaussian heights in closed form,
//! // (4/3) E* sqrt(R) N sigma^(3/2) F_3/2(0) = 97.22 mN (mpmath).
//! let text = DEFAULT_SCENE
//!     .replacen("w = 0.5", "w = 0.0", 1)
//!     .replacen("closest_separation = 5e-9", "closest_separation = 0.0", 1);
//! let scene = Scene::from_toml(&text)?;
//! let plan = Plan::new(&scene, PlanMode::Planned)?;
//! let summary = Summary::new(&plan, &plan.run()?);
//! let max_load = summary.headlines.get("max_load").flatten().unwrap();
//! assert!((max_load / 0.0972216862214102 - 1.0).abs() < 1e-12);
//! # Ok::<(), asperity::Error>(())
//! ```

pub mod atomic;
pub mod cache;
pub mod cpu_time;
pub mod map_error;
pub mod map_pull_off;
pub mod measured;
pub mod memory;
pub mod model_error;
pub mod output;
pub mod plan;
pub mod plot;
pub mod population;
pub mod quantity;
pub mod run;
pub mod scene;

pub mod sweep;
pub mod text;
pub mod warning;

pub use output::{
    charts, check_outputs, curve_csv, montecarlo_csv, text_report, write_outputs, Column,
    McSummary, PlasticitySummary, StictionSummary, Summary, Table,
};
pub use plan::{Plan, PlanMode};
pub use quantity::{Quantity, QuantitySet, Record, StateRow};
pub use run::{McResults, Results};
pub use scene::{Scene, DEFAULT_SCENE, DEFAULT_STUDY};
pub use warning::Warning;
