//! Parameter sweeps over scene fields: grids and Latin-hypercube samples,
//! run in parallel, each finished point appended at once to
//! `DIR/results.csv`, resumable after any interruption, shardable for
//! cluster job arrays and mergeable.
//!
//! Loss-free by construction: a row is written (and flushed to disk) only
//! once its point is finished; on restart the rows already present are
//! kept, a half-written last line is detected and dropped, and only the
//! missing points are computed; at the end the file is rewritten sorted by
//! point index (atomically, via a rename), so an interrupted-and-resumed
//! sweep, an uninterrupted one and a merge of shards all end with the same
//! bytes.

mod edit;
mod humidity;
mod run;
mod spec;
mod store;

pub use edit::set_field;
pub use humidity::{humidity_charts, HUMIDITY_PATH};
pub use run::{run_sweep, sweep_table, PointOutcome, SweepOptions, DEFAULT_MAX_CPU_SECONDS};
pub use spec::{
    Design, Shard, SweepPoint, SweepSpec, Vary, BYTES_PER_POINT, BYTES_PER_VALUE, MAX_POINTS,
};
pub use store::{merge, ResultsFile, SweepMeta};
