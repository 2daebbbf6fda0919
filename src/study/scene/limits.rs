//! The scene's documented bounds and defaults, in one place: the
//! validation (`parse.rs`, `features.rs`), the schema (`schema.rs`) and the
//! messages read them from here.

/// Largest `program.points` (per leg).
pub const MAX_POINTS: usize = 1_000_000;

/// Smallest summit radius, height scale and interaction range (m): below a
/// femtometre no length of a contact means anything.
pub const MIN_LENGTH: f64 = 1e-15;

/// Largest summit radius, height scale and interaction range (m).
pub const MAX_LENGTH: f64 = 1.0;

/// Largest number of summits `eta A_n` on the nominal area (totals stay
/// far from overflow).
pub const MAX_SURFACE_SUMMITS: f64 = 1e24;

/// Largest memory (bytes) a Monte Carlo population may take (heights, radii
/// and the sorted suffix), so that a scene never aborts on allocation.
pub const MAX_POPULATION_BYTES: f64 = 2.0 * (1u64 << 30) as f64;

/// Largest estimated single-core time (s) of summing a population over the
/// program.
pub const MAX_POPULATION_SECONDS: f64 = 3600.0;

/// Most points of a tabulated profile (`law.profile_r`): the shaped law's
/// cost grows with the table (about [`TABULATED_CPU_S_PER_POINT`] each: a
/// 100,000-point profile ran for many minutes without a word).
pub const MAX_TABULATED_POINTS: usize = 2000;

/// CPU seconds per point of a tabulated profile's shaped-law run, measured
/// on `conical-summits.toml` with a 400-point paraboloid table (3.05 s, a
/// release build; 0.55 s at 100 points).
pub const TABULATED_CPU_S_PER_POINT: f64 = 7.6e-3;

/// Allowed yield strengths and hardnesses in scenes (Pa): from the softest
/// gels (~1e3 Pa) to far beyond diamond (~1e11 Pa), so a vanishing
/// plasticity (1e16 Pa) stays expressible.
pub const YIELD_STRENGTH_RANGE: (f64, f64) = (1e3, 1e20);

/// Largest `electrical.current` (A).
pub const MAX_CURRENT: f64 = 1e6;

/// Default `montecarlo.seed`.
pub const DEFAULT_SEED: u64 = 1;

/// Default number of pull-off populations (`montecarlo.seeds`).
pub const DEFAULT_POPULATIONS: usize = 100;

/// Most pull-off populations a scene may ask for.
pub const MAX_POPULATIONS: usize = 100_000;

/// Most listed states a program may ask for.
pub const MAX_LISTED_STATES: usize = 10_000;
