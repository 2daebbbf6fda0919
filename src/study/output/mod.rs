//! A run's outputs: the tables (`curve.csv`, `montecarlo.csv`), the JSON
//! summary, the text report and the figures. Columns, summary keys and
//! report lines of the states' quantities follow the plan's
//! [`QuantitySet`](crate::study::quantity::QuantitySet).

mod aliases;
mod feature_figures;
mod figures;
pub mod fixed;
pub mod format;
mod report;
pub mod sci;
mod summary;
mod table;
mod tables;
mod topography;

pub use aliases::Aliases;
pub use feature_figures::{feature_charts, FeatureChart};
pub use figures::{charts, check_outputs, write_outputs, OUTPUT_FILES};
pub use format::{si_prefix, si_prefix_area};
pub use report::text_report;
pub use summary::{
    HeatingSummary, McSummary, PlasticitySummary, SampleSpotsSummary, StictionSummary, Summary,
    DEPRECATED_KEYS,
};
pub use table::{Column, Table, INTEGER_COLUMNS, TEXT_COLUMNS};
pub use tables::{curve_csv, montecarlo_csv};
pub use topography::{HeadlineJson, MeasuredJson, MomentsJson, TopographySummary};
