//! The scene file: what a user wants computed, in SI units.
//!
//! Every table rejects unknown keys (a typo must not be silently ignored).
//! Defaults are stated on each field; a scene needs at least `[materials]`,
//! `[surface]`, `[adhesion]` and `[program]`.

use super::law_name::LawName;
use super::topography::SummitSource;
use crate::axisym::ProfileKind;
use crate::electrical::{Interaction, Spreading};
use crate::heights::DistributionKind;
use serde::{Deserialize, Serialize};

/// A whole scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// Optional title, printed in summaries.
    #[serde(default)]
    pub title: Option<String>,
    /// Elastic constants of both bodies.
    pub materials: MaterialsSpec,
    /// Summit statistics of the rough surface.
    pub surface: SurfaceSpec,
    /// Surface interaction.
    pub adhesion: AdhesionSpec,
    /// Asperity law (default `auto`).
    #[serde(default)]
    pub law: LawSpec,
    /// Loading program.
    pub program: ProgramSpec,
    /// Outputs wanted (defaults: load, area, count, pull-off on; hysteresis
    /// energy off).
    #[serde(default)]
    pub outputs: OutputsSpec,
    /// Accuracy target (default `rtol = 1e-6`).
    #[serde(default)]
    pub accuracy: AccuracySpec,
    /// Optional explicit random population, summed exactly beside the
    /// statistical integral (absent: no Monte Carlo).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub montecarlo: Option<MonteCarloSpec>,
    /// Optional electrical contact: spot resistances from the contact
    /// spots (absent: no resistance).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub electrical: Option<ElectricalSpec>,
    /// Optional switch: spring and travel, for the stiction margin.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub switch: Option<SwitchSpec>,
    /// Optional rough sphere: the scene becomes an elastic sphere of this
    /// radius on the surface (Greenwood & Tripp 1967; absent: a nominally
    /// flat contact of area `surface.nominal_area`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sphere: Option<SphereSpec>,
}

/// `[sphere]`: an elastic sphere (or paraboloid) of radius `radius`
/// pressed on the scene's rough surface (Greenwood & Tripp 1967; a switch's
/// contact bump, an AFM colloidal probe). The apparent area is the
/// solution's, so `surface.nominal_area` must not be given; separations are
/// remote (minus the approach of distant points, as a machine controls
/// them); every output is a total over the bump.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SphereSpec {
    /// Sphere radius (m), in `[1e-15, 1]`.
    pub radius: f64,
    /// `"paraboloid"` (default: `r^2/(2R)`, Hertz and Greenwood & Tripp)
    /// or `"sphere"` (`R - sqrt(R^2 - r^2)`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub profile: Option<SphereShape>,
}

/// The undeformed profile of `[sphere]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum SphereShape {
    /// `r^2/(2R)`.
    Paraboloid,
    /// `R - sqrt(R^2 - r^2)`.
    Sphere,
}

/// `[electrical]`: constriction resistance of the contact spots
/// (Maxwell/Holm, Sharvin, Wexler), optionally with Greenwood's interaction
/// and a film. Same metal: `resistivity` (and `mean_free_path`); two
/// metals: `resistivity1`/`resistivity2` (and `mean_free_path1`/`2`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ElectricalSpec {
    /// Resistivity of both bodies (Ohm m), > 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub resistivity: Option<f64>,
    /// Resistivity of body 1 (Ohm m), > 0 (two metals).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub resistivity1: Option<f64>,
    /// Resistivity of body 2 (Ohm m), > 0 (two metals).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub resistivity2: Option<f64>,
    /// Electron mean free path of both bodies (m), > 0; needed by
    /// `sharvin` and `wexler`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mean_free_path: Option<f64>,
    /// Mean free path of body 1 (m), > 0 (two metals).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mean_free_path1: Option<f64>,
    /// Mean free path of body 2 (m), > 0 (two metals).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mean_free_path2: Option<f64>,
    /// `"maxwell"` (diffusive, Holm), `"sharvin"` (ballistic) or
    /// `"wexler"` (Mikrajuddin interpolation); default `"maxwell"`.
    #[serde(default = "default_spreading")]
    pub spreading: Spreading,
    /// `"none"` (independent parallel spots, default) or `"greenwood"`
    /// (mean-field interaction in a square apparent area of side
    /// `sqrt(nominal_area)`).
    #[serde(default = "default_interaction")]
    pub interaction: Interaction,
    /// Film resistance per unit area (Ohm m^2), >= 0; each spot adds
    /// `film_resistance / (pi a^2)`. Default 0.
    #[serde(default)]
    pub film_resistance: f64,
    /// Current through the contact (A), > 0, optional: the summary and the
    /// listed states then give the contact voltage `I R` and the peak
    /// contact temperature (Holm's phi-theta relation with the
    /// Wiedemann–Franz law).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub current: Option<f64>,
    /// Bulk temperature (K), in (0, melting_temperature), for the heating;
    /// default 293.15.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bulk_temperature: Option<f64>,
    /// Softening temperature of the spots' metal (K), > 0; default gold's
    /// 373.15 K (Holm): above it a warning says the spot softens.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub softening_temperature: Option<f64>,
    /// Melting temperature of the spots' metal (K), > softening_temperature;
    /// default gold's 1337.33 K: above it the spot melts, a warning says so
    /// and no peak temperature is reported.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub melting_temperature: Option<f64>,
}

fn default_spreading() -> Spreading {
    Spreading::Maxwell
}

fn default_interaction() -> Interaction {
    Interaction::None
}

/// `[switch]`: the spring that reopens the contact.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SwitchSpec {
    /// Spring constant `k` (N/m), > 0.
    pub spring_constant: f64,
    /// Travel (m), > 0: the restoring force is `k x travel`.
    pub travel: f64,
    /// Confidence of the stiction margin, in (0, 1); default 0.95: the
    /// margin uses the pull-off that only the 5 % most tensile
    /// populations exceed (with the population basis).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub confidence: Option<f64>,
}

/// `[montecarlo]`: an explicit random population of summits drawn from the
/// surface's height distribution and summed exactly over the same program.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MonteCarloSpec {
    /// Summits drawn, >= 1; default `eta A_n` (rounded). Fewer than that
    /// draws a sub-area and scales the totals up (their standard errors
    /// then measure the distance to the expectation).
    #[serde(default)]
    pub summits: Option<usize>,
    /// Seed of the population (default 1); sweeps set it per point. The
    /// pull-off populations use seeds `seed, seed + 1, ...`.
    #[serde(default = "default_seed")]
    pub seed: u64,
    /// Number of populations of `eta A_n` summits whose pull-offs give the
    /// pull-off distribution (`pull_off_population` in the summary),
    /// >= 1; default [`DEFAULT_POPULATIONS`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seeds: Option<usize>,
    /// Standard deviation of `ln R` (lognormal radii with median
    /// `surface.radius`), >= 0; default 0 (every summit of radius R, as in
    /// GW). Not available for Maugis–Dugdale or calibrated laws.
    #[serde(default)]
    pub radius_log_std: f64,
}

/// Default `montecarlo.seed`.
pub const DEFAULT_SEED: u64 = 1;

/// Default number of pull-off populations (`montecarlo.seeds`).
pub const DEFAULT_POPULATIONS: usize = 100;

/// Most pull-off populations a scene may ask for.
pub const MAX_POPULATIONS: usize = 100_000;

fn default_seed() -> u64 {
    DEFAULT_SEED
}

/// `[materials]`: Young's moduli (Pa) and Poisson ratios of body 1 (the
/// rough one) and body 2 (the flat).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialsSpec {
    /// Young's modulus of body 1 (Pa), > 0.
    pub e1: f64,
    /// Poisson ratio of body 1, in [0, 0.5).
    pub nu1: f64,
    /// Young's modulus of body 2 (Pa), > 0.
    pub e2: f64,
    /// Poisson ratio of body 2, in [0, 0.5).
    pub nu2: f64,
    /// Yield strength of the body that yields (Pa), > 0; required by the
    /// elastic-plastic laws, optional otherwise (it feeds the plasticity
    /// diagnostics). Its Poisson ratio is taken as that of the softer body
    /// (the lower Young's modulus; body 1 on a tie). Allowed `[1e3, 1e20]`
    /// Pa.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yield_strength: Option<f64>,
    /// Hardness of the body that yields (Pa), >= `yield_strength`, at most
    /// 1e20 Pa; default `2.8 x yield_strength` (Tabor).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub hardness: Option<f64>,
}

/// `[surface]`: the summits.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SurfaceSpec {
    /// Summit areal density `eta` (1/m^2), > 0. Required unless
    /// `topography` is given (then it comes from the map and must not be
    /// given); absent reads as NaN.
    #[serde(default = "unset", skip_serializing_if = "is_unset")]
    pub density: f64,
    /// Summit radius `R` (m), > 0. Required unless `topography` is given.
    #[serde(default = "unset", skip_serializing_if = "is_unset")]
    pub radius: f64,
    /// Summit-height standard deviation `sigma` (m), > 0 (the decay length
    /// for the exponential distribution). Required unless `topography` is
    /// given.
    #[serde(default = "unset", skip_serializing_if = "is_unset")]
    pub sigma: f64,
    /// Height distribution: `"gaussian"` (default), `"exponential"`,
    /// `"weibull"`, `"truncated-gaussian"`, `"empirical"`.
    #[serde(default = "default_distribution")]
    pub distribution: DistributionKind,
    /// Nominal area `A_n` (m^2), > 0. Required unless `topography` is
    /// given (default then: the map's area, rows x cols x pixel_size^2) or
    /// the scene has `[sphere]` (then it must not be given: the bump's
    /// apparent area is the solution's).
    #[serde(default = "unset", skip_serializing_if = "is_unset")]
    pub nominal_area: f64,
    /// Weibull shape `k` (> 0), for `distribution = "weibull"`.
    #[serde(default)]
    pub weibull_shape: Option<f64>,
    /// Truncation at `k sigma` (> 0), for `"truncated-gaussian"`.
    #[serde(default)]
    pub truncation: Option<f64>,
    /// Measured summit heights (m), for `"empirical"`.
    #[serde(default)]
    pub heights: Option<Vec<f64>>,
    /// A measured height map (`.npy`, or a text matrix `.txt`/`.csv`/`.asc`),
    /// path relative to the scene file's directory. The summits come from
    /// the map (`docs/surface.md`, "Scenes from measurements"): `density`,
    /// `radius` and `sigma` must then not be given, and `distribution`
    /// must stay `"gaussian"`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub topography: Option<String>,
    /// Pixel size of the map (m), > 0; required with `topography`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pixel_size: Option<f64>,
    /// Factor from the map's height unit to metres (e.g. `1e-9` for nm),
    /// > 0; default 1. Only with `topography`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub height_scale: Option<f64>,
    /// Treat the map as periodic (remove only the mean, wrap neighbours);
    /// default false. Only with `topography`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub periodic: Option<bool>,
    /// Which model of the map the study uses: `"measured"` (default: an
    /// exact sum over the measured summits, each with its own height and
    /// radius) or `"moments"` (Gaussian GW with the parameters McCool's
    /// relations give from the measured moments). Only with `topography`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub summits: Option<SummitSource>,
    /// Also run the other model of the map and report its headline numbers
    /// in the summary's `topography` object; default false. Only with
    /// `topography`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub compare: Option<bool>,
}

/// The value of a summit statistic not given in the scene.
fn unset() -> f64 {
    f64::NAN
}

fn is_unset(x: &f64) -> bool {
    x.is_nan()
}

fn default_distribution() -> DistributionKind {
    DistributionKind::Gaussian
}

/// `[adhesion]`: work of adhesion and force range.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AdhesionSpec {
    /// Work of adhesion `w` (J/m^2), >= 0; 0 switches adhesion off.
    pub w: f64,
    /// Equilibrium separation `z0` of the Lennard-Jones law (m), > 0.
    pub z0: f64,
}

/// `[law]`: the single-asperity law.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LawSpec {
    /// `"auto"` (default: the planner picks the cheapest law that meets the
    /// tolerance for this Tabor parameter), `"hertz"`, `"dmt"`, `"jkr"`,
    /// `"maugis"`, `"cos"`, `"calibrated"`, the elastic-plastic
    /// `"kogut-etsion"`, `"jackson-green"`, `"chang-etsion-bogy"`,
    /// `"zhao-maietta-chang"` (need `materials.yield_strength`), or
    /// `"shaped"` (JKR on the axisymmetric `profile`).
    #[serde(default)]
    pub kind: LawName,
    /// For `kind = "shaped"`: `"paraboloid"`, `"sphere"` (exact sphere),
    /// `"cone"`, `"flat"`, `"power"` or `"tabulated"`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub profile: Option<ProfileKind>,
    /// Shaped: sphere/paraboloid radius or flat-punch radius (m), > 0;
    /// default `surface.radius`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    /// Shaped cone: `tan(beta)` of `f(r) = r tan(beta)`, > 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tan_angle: Option<f64>,
    /// Shaped power law `f(r) = A r^n`: the exponent `n`, > 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub exponent: Option<f64>,
    /// Shaped power law: the coefficient `A` (m^(1-n)), > 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub coefficient: Option<f64>,
    /// Shaped tabulated profile: radii `r` (m), ascending from 0; 3 ..=
    /// 2000 points (`MAX_TABULATED_POINTS`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub profile_r: Option<Vec<f64>>,
    /// Shaped tabulated profile: heights `f(r)` (m) at `profile_r`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub profile_f: Option<Vec<f64>>,
}

impl Default for LawSpec {
    fn default() -> Self {
        LawSpec {
            kind: LawName::Auto,
            profile: None,
            radius: None,
            tan_angle: None,
            exponent: None,
            coefficient: None,
            profile_r: None,
            profile_f: None,
        }
    }
}

/// `[program]`: approach to a closest separation or to a maximum load, then
/// retract back out through the same separations. Instead of a closest
/// separation or a maximum load, `separations` or `loads` list states of
/// interest: the curve then runs to the closest (most loaded) of them and
/// each listed state is reported on approach, in the listed order.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProgramSpec {
    /// Closest separation of the flat from the mean summit plane (m).
    /// Exactly one of `closest_separation` and `max_load` must be given.
    #[serde(default)]
    pub closest_separation: Option<f64>,
    /// Maximum compressive load on approach (N, > 0).
    #[serde(default)]
    pub max_load: Option<f64>,
    /// Separations (m, from the mean summit height) at which to report the
    /// approach state, in this order; at most [`MAX_LISTED_STATES`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub separations: Option<Vec<f64>>,
    /// Compressive loads (N, > 0) at which to report the approach state
    /// (the separation is solved for each), in this order; at most
    /// [`MAX_LISTED_STATES`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub loads: Option<Vec<f64>>,
    /// Separation where the program starts and ends (m); default: where
    /// the first asperity comes within range of the flat.
    #[serde(default)]
    pub start_separation: Option<f64>,
    /// Points per leg (approach, retraction), >= 2; default 200.
    #[serde(default = "default_points")]
    pub points: usize,
}

/// Most listed states a program may ask for.
pub const MAX_LISTED_STATES: usize = 10_000;

fn default_points() -> usize {
    200
}

/// `[outputs]`: what to compute; everything not asked for is skipped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OutputsSpec {
    /// Total load against separation (default true).
    #[serde(default = "yes")]
    pub load: bool,
    /// Real contact area (default true).
    #[serde(default = "yes")]
    pub area: bool,
    /// Number of contacts (default true).
    #[serde(default = "yes")]
    pub count: bool,
    /// Pull-off force of the rough surface (default true).
    #[serde(default = "yes")]
    pub pull_off: bool,
    /// Energy lost per approach–retract cycle (default false).
    #[serde(default)]
    pub hysteresis_energy: bool,
    /// Contact resistance (default false; needs `[electrical]`): the curve
    /// gains `resistance_ohm`, the summary the resistance at the closest
    /// approach.
    #[serde(default)]
    pub resistance: bool,
    /// The pull-off distribution of one switch over populations of the
    /// surface's `eta A_n` summits (`pull_off_population` in the summary;
    /// default true, only when the pull-off is searched on a finite
    /// surface). `false` skips the populations (a sweep that needs only the
    /// integral); `[switch]` then uses the integral's pull-off.
    #[serde(default = "yes")]
    pub pull_off_population: bool,
}

fn yes() -> bool {
    true
}

impl Default for OutputsSpec {
    fn default() -> Self {
        OutputsSpec {
            load: true,
            area: true,
            count: true,
            pull_off: true,
            hysteresis_energy: false,
            resistance: false,
            pull_off_population: true,
        }
    }
}

/// `[accuracy]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AccuracySpec {
    /// Relative tolerance of every output, in [1e-12, 0.1] (at least 1e-11
    /// with the calibrated law, whose table stalls below); default 1e-6.
    #[serde(default = "default_rtol")]
    pub rtol: f64,
    /// Measure the model error of an adhesive law on this surface against
    /// the full Lennard-Jones solver's law (`model_error` in the summary;
    /// the calibration is computed once per Tabor parameter and cached),
    /// and let `law.kind = "auto"` fall back to the full-solver law when no
    /// analytic law meets `rtol`; default true. `false` skips the
    /// full-solver run (the planner then picks by one summit's error).
    #[serde(default = "yes_model_error")]
    pub model_error: bool,
}

fn yes_model_error() -> bool {
    true
}

fn default_rtol() -> f64 {
    1e-6
}

impl Default for AccuracySpec {
    fn default() -> Self {
        AccuracySpec {
            rtol: default_rtol(),
            model_error: true,
        }
    }
}
