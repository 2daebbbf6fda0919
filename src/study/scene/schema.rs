//! The scene file: what a user wants computed, in SI units.
//!
//! Every table rejects unknown keys (a typo must not be silently ignored).
//! Defaults are stated on each field; a scene needs at least `[materials]`,
//! `[surface]`, `[adhesion]` and `[program]`.
//!
//! Each type derives [`JsonSchema`]: the doc comments become the
//! descriptions of the scene files' JSON Schema
//! ([`super::scene_schema`]), and each number states its unit (`x-unit`)
//! and the range the validation enforces (`parse.rs`, `features.rs`; the
//! bounds are the same constants).

use super::law_name::LawName;
use super::limits::{
    DEFAULT_POPULATIONS, DEFAULT_SEED, MAX_CURRENT, MAX_LENGTH, MAX_LISTED_STATES, MAX_POINTS,
    MAX_POPULATIONS, MAX_TABULATED_POINTS, MIN_LENGTH, YIELD_STRENGTH_RANGE,
};
use super::summit_source::SummitSource;
use crate::axisym::ProfileKind;
use crate::electrical::heating::{
    DEFAULT_BULK_TEMPERATURE, GOLD_MELTING_TEMPERATURE, GOLD_SOFTENING_TEMPERATURE,
};
use crate::electrical::{Conductor, Interaction, Spreading};
use crate::heights::DistributionKind;
use crate::montecarlo::MAX_SUMMITS;
use crate::topography::units::HeightUnit;
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// A whole scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// Optional title, printed in summaries.
    #[serde(default, skip_serializing_if = "Option::is_none")]
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
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SphereSpec {
    /// Sphere radius (m), in `[1e-15, 1]`. With the surface, the rough
    /// sphere's Greenwood-Tripp mu = (8/3) eta sigma sqrt(2 R beta)
    /// (`R` this radius, `beta` the summit radius) must lie in
    /// `[1e-12, 1e4]`.
    #[schemars(extend("x-unit" = "m"), range(min = MIN_LENGTH, max = MAX_LENGTH))]
    pub radius: f64,
    /// `"paraboloid"` (default: `r^2/(2R)`, Hertz and Greenwood & Tripp)
    /// or `"sphere"` (`R - sqrt(R^2 - r^2)`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("default" = "paraboloid"))]
    pub profile: Option<SphereShape>,
}

/// The undeformed profile of `[sphere]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
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
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ElectricalSpec {
    /// Resistivity of both bodies (Ohm m), in `[1e-12, 1e6]`. Give it, or
    /// both `resistivity1` and `resistivity2`, not both forms.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(
        extend("x-unit" = "Ohm m"),
        range(min = Conductor::RESISTIVITY.lo, max = Conductor::RESISTIVITY.hi)
    )]
    pub resistivity: Option<f64>,
    /// Resistivity of body 1 (Ohm m), in `[1e-12, 1e6]` (two metals: with
    /// `resistivity2`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(
        extend("x-unit" = "Ohm m"),
        range(min = Conductor::RESISTIVITY.lo, max = Conductor::RESISTIVITY.hi)
    )]
    pub resistivity1: Option<f64>,
    /// Resistivity of body 2 (Ohm m), in `[1e-12, 1e6]` (two metals: with
    /// `resistivity1`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(
        extend("x-unit" = "Ohm m"),
        range(min = Conductor::RESISTIVITY.lo, max = Conductor::RESISTIVITY.hi)
    )]
    pub resistivity2: Option<f64>,
    /// Electron mean free path of both bodies (m), in `[1e-15, 1e-2]`;
    /// needed by `sharvin` and `wexler`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(
        extend("x-unit" = "m"),
        range(min = Conductor::MEAN_FREE_PATH.lo, max = Conductor::MEAN_FREE_PATH.hi)
    )]
    pub mean_free_path: Option<f64>,
    /// Mean free path of body 1 (m), in `[1e-15, 1e-2]` (two metals: with
    /// `mean_free_path2`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(
        extend("x-unit" = "m"),
        range(min = Conductor::MEAN_FREE_PATH.lo, max = Conductor::MEAN_FREE_PATH.hi)
    )]
    pub mean_free_path1: Option<f64>,
    /// Mean free path of body 2 (m), in `[1e-15, 1e-2]` (two metals: with
    /// `mean_free_path1`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(
        extend("x-unit" = "m"),
        range(min = Conductor::MEAN_FREE_PATH.lo, max = Conductor::MEAN_FREE_PATH.hi)
    )]
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
    /// Film resistance per unit area (Ohm m^2), in `[0, 1e3]`; each spot
    /// adds `film_resistance / (pi a^2)`. Default 0.
    #[serde(default)]
    #[schemars(extend("x-unit" = "Ohm m^2"), range(min = 0.0, max = 1e3))]
    pub film_resistance: f64,
    /// Current through the contact (A), in `(0, 1e6]`, optional: the
    /// summary and the listed states then give the contact voltage `I R`
    /// and the peak contact temperature (Holm's phi-theta relation with the
    /// Wiedemann–Franz law).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "A", "exclusiveMinimum" = 0.0), range(max = MAX_CURRENT))]
    pub current: Option<f64>,
    /// Bulk temperature (K), in (0, melting_temperature), for the heating;
    /// default 293.15. Only with `current`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(
        extend("x-unit" = "K", "exclusiveMinimum" = 0.0, "default" = DEFAULT_BULK_TEMPERATURE)
    )]
    pub bulk_temperature: Option<f64>,
    /// Softening temperature of the spots' metal (K), > 0; default gold's
    /// 373.15 K (Holm): above it a warning says the spot softens. Only
    /// with `current`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(
        extend("x-unit" = "K", "exclusiveMinimum" = 0.0, "default" = GOLD_SOFTENING_TEMPERATURE)
    )]
    pub softening_temperature: Option<f64>,
    /// Melting temperature of the spots' metal (K), > softening_temperature;
    /// default gold's 1337.33 K: above it the spot melts, a warning says so
    /// and no peak temperature is reported. Only with `current`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(
        extend("x-unit" = "K", "exclusiveMinimum" = 0.0, "default" = GOLD_MELTING_TEMPERATURE)
    )]
    pub melting_temperature: Option<f64>,
}

fn default_spreading() -> Spreading {
    Spreading::Maxwell
}

fn default_interaction() -> Interaction {
    Interaction::None
}

/// `[switch]`: the spring that reopens the contact.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SwitchSpec {
    /// Spring constant `k` (N/m), > 0.
    #[schemars(extend("x-unit" = "N/m", "exclusiveMinimum" = 0.0))]
    pub spring_constant: f64,
    /// Travel (m), > 0: the restoring force is `k x travel`.
    #[schemars(extend("x-unit" = "m", "exclusiveMinimum" = 0.0))]
    pub travel: f64,
    /// Confidence of the stiction margin, in (0, 1); default 0.95: the
    /// margin uses the pull-off that only the 5 % most tensile
    /// populations exceed (with the population basis).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend(
        "x-unit" = "1",
        "exclusiveMinimum" = 0.0,
        "exclusiveMaximum" = 1.0,
        "default" = crate::study::run::DEFAULT_CONFIDENCE
    ))]
    pub confidence: Option<f64>,
}

/// `[montecarlo]`: an explicit random population of summits drawn from the
/// surface's height distribution and summed exactly over the same program.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MonteCarloSpec {
    /// Summits drawn, in `[1, 2^30]`; default `eta A_n` (rounded). Fewer
    /// than that draws a sub-area and scales the totals up (their standard
    /// errors then measure the distance to the expectation). The
    /// population must also stay within 2 GB of memory and an estimated
    /// hour of one core.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "1"), range(min = 1, max = MAX_SUMMITS))]
    pub summits: Option<usize>,
    /// Seed of the population (default 1); sweeps set it per point. The
    /// pull-off populations use seeds `seed, seed + 1, ...`.
    #[serde(default = "default_seed")]
    #[schemars(extend("x-unit" = "1"))]
    pub seed: u64,
    /// Number of populations of `eta A_n` summits whose pull-offs give the
    /// pull-off distribution (`pull_off_population` in the summary), in
    /// `[1, 1e5]`; default 100 ([`DEFAULT_POPULATIONS`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(
        extend("x-unit" = "1", "default" = DEFAULT_POPULATIONS),
        range(min = 1, max = MAX_POPULATIONS)
    )]
    pub seeds: Option<usize>,
    /// Standard deviation of `ln R` (lognormal radii with median
    /// `surface.radius`), >= 0; default 0 (every summit of radius R, as in
    /// GW). Not available for Maugis–Dugdale or calibrated laws.
    #[serde(default)]
    #[schemars(extend("x-unit" = "1"), range(min = 0.0))]
    pub radius_log_std: f64,
}

fn default_seed() -> u64 {
    DEFAULT_SEED
}

/// `[materials]`: Young's moduli (Pa) and Poisson ratios of body 1 (the
/// rough one) and body 2 (the flat).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MaterialsSpec {
    /// Young's modulus of body 1 (Pa), > 0.
    #[schemars(extend("x-unit" = "Pa", "exclusiveMinimum" = 0.0))]
    pub e1: f64,
    /// Poisson ratio of body 1, in [0, 0.5).
    #[schemars(extend("x-unit" = "1", "exclusiveMaximum" = 0.5), range(min = 0.0))]
    pub nu1: f64,
    /// Young's modulus of body 2 (Pa), > 0.
    #[schemars(extend("x-unit" = "Pa", "exclusiveMinimum" = 0.0))]
    pub e2: f64,
    /// Poisson ratio of body 2, in [0, 0.5).
    #[schemars(extend("x-unit" = "1", "exclusiveMaximum" = 0.5), range(min = 0.0))]
    pub nu2: f64,
    /// Yield strength of the body that yields (Pa), > 0; required by the
    /// elastic-plastic laws, optional otherwise (it feeds the plasticity
    /// diagnostics). Its Poisson ratio is taken as that of the softer body
    /// (the lower Young's modulus; body 1 on a tie). Allowed `[1e3, 1e20]`
    /// Pa.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(
        extend("x-unit" = "Pa"),
        range(min = YIELD_STRENGTH_RANGE.0, max = YIELD_STRENGTH_RANGE.1)
    )]
    pub yield_strength: Option<f64>,
    /// Hardness of the body that yields (Pa), >= `yield_strength`, in
    /// `[1e3, 1e20]` Pa; default `2.8 x yield_strength` (Tabor). Only with
    /// `yield_strength`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(
        extend("x-unit" = "Pa"),
        range(min = YIELD_STRENGTH_RANGE.0, max = YIELD_STRENGTH_RANGE.1)
    )]
    pub hardness: Option<f64>,
}

/// `[surface]`: the summits.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SurfaceSpec {
    /// Summit areal density `eta` (1/m^2), > 0. Required unless
    /// `topography` is given (then it comes from the map and must not be
    /// given); absent reads as NaN. The summits on the nominal area,
    /// `eta A_n`, must number 1 to 1e24.
    #[serde(default = "unset", skip_serializing_if = "is_unset")]
    #[schemars(extend("x-unit" = "1/m^2", "exclusiveMinimum" = 0.0))]
    pub density: f64,
    /// Summit radius `R` (m), in `[1e-15, 1]`. Required unless
    /// `topography` is given (then it must not be given).
    #[serde(default = "unset", skip_serializing_if = "is_unset")]
    #[schemars(extend("x-unit" = "m"), range(min = MIN_LENGTH, max = MAX_LENGTH))]
    pub radius: f64,
    /// Summit-height standard deviation `sigma` (m), in `[1e-15, 1]` (the
    /// decay length for the exponential distribution). Required unless
    /// `topography` is given (then it must not be given).
    #[serde(default = "unset", skip_serializing_if = "is_unset")]
    #[schemars(extend("x-unit" = "m"), range(min = MIN_LENGTH, max = MAX_LENGTH))]
    pub sigma: f64,
    /// Height distribution: `"gaussian"` (default), `"exponential"`,
    /// `"weibull"` (needs `weibull_shape`), `"truncated-gaussian"` (needs
    /// `truncation`), `"empirical"` (needs `heights`). With `topography`
    /// it must stay `"gaussian"`.
    #[serde(default = "default_distribution")]
    pub distribution: DistributionKind,
    /// Nominal area `A_n` (m^2), > 0. Required unless `topography` is
    /// given (default then: the map's area, rows x cols x pixel_size^2) or
    /// the scene has `[sphere]` (then it must not be given: the bump's
    /// apparent area is the solution's).
    #[serde(default = "unset", skip_serializing_if = "is_unset")]
    #[schemars(extend("x-unit" = "m^2", "exclusiveMinimum" = 0.0))]
    pub nominal_area: f64,
    /// Weibull shape `k` (> 0), for `distribution = "weibull"` only (and
    /// required there).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "1", "exclusiveMinimum" = 0.0))]
    pub weibull_shape: Option<f64>,
    /// Truncation at `k sigma` (> 0), for `"truncated-gaussian"` only (and
    /// required there).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "1", "exclusiveMinimum" = 0.0))]
    pub truncation: Option<f64>,
    /// Measured summit heights (m), at least 2, for `"empirical"` only (and
    /// required there).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "m"), length(min = 2))]
    pub heights: Option<Vec<f64>>,
    /// A measured height map, path relative to the scene file's directory:
    /// an instrument file (`.x3p`, `.sdf`, `.gwy`, `.sur`, `.di`/`.spm`,
    /// `.ibw`, `.opd`, `.opdx`, `.nc`, `.frt`, `.plux`: heights, pixel sizes and unit
    /// from the file, its height channel), `.npy` or a text matrix
    /// (`.txt`/`.csv`/`.asc`). The summits come from the map
    /// (`docs/surface.md`, "Scenes from measurements"): `density`, `radius`
    /// and `sigma` must then not be given, and `distribution` must stay
    /// `"gaussian"`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub topography: Option<String>,
    /// Pixel size of the map (m), > 0, the same along x and y; required
    /// with a `.npy` or text `topography`, only with `topography`. For a
    /// file that gives its own it may be left out; given anyway, it must
    /// agree with the file's to 1e-9 (relative) or it wins with a warning.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "m", "exclusiveMinimum" = 0.0))]
    pub pixel_size: Option<f64>,
    /// Unit of a `.npy` or text map's heights: `"nm"`, `"um"` or `"m"`
    /// (default `"m"`); not for the instrument files, which give their own.
    /// Only with `topography`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("default" = "m"))]
    pub height_unit: Option<HeightUnit>,
    /// Factor on the map's heights after `height_unit` (e.g. `1e-9` for
    /// nm), > 0; default 1. Only with `topography`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "1", "exclusiveMinimum" = 0.0, "default" = 1.0))]
    pub height_scale: Option<f64>,
    /// Fill the map's missing pixels (NaN or masked in the file) from their
    /// neighbours instead of refusing the map; default false. Only with
    /// `topography`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("default" = false))]
    pub fill_missing: Option<bool>,
    /// Treat the map as periodic (remove only the mean, wrap neighbours);
    /// default false. Only with `topography`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("default" = false))]
    pub periodic: Option<bool>,
    /// Which model of the map the study uses: `"measured"` (default: an
    /// exact sum over the measured summits, each with its own height and
    /// radius) or `"moments"` (Gaussian GW with the parameters McCool's
    /// relations give from the measured moments). Only with `topography`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("default" = "measured"))]
    pub summits: Option<SummitSource>,
    /// Also run the other model of the map and report its headline numbers
    /// in the summary's `topography` object; default false. Only with
    /// `topography`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("default" = false))]
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
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct AdhesionSpec {
    /// Work of adhesion `w` (J/m^2), >= 0; 0 switches adhesion off.
    #[schemars(extend("x-unit" = "J/m^2"), range(min = 0.0))]
    pub w: f64,
    /// Equilibrium separation `z0` of the Lennard-Jones law (m), in
    /// `[1e-15, 1]`.
    #[schemars(extend("x-unit" = "m"), range(min = MIN_LENGTH, max = MAX_LENGTH))]
    pub z0: f64,
    /// Relative humidity of the surrounding vapour, in `[0, 1)`: water (or the
    /// liquid below) condenses into menisci around the contacts, which pull
    /// beside the dry adhesion `w`, `z0` (Kelvin radius
    /// `r_K = gamma V_m/(R_g T ln(1/RH))`, Laplace pressure `gamma/r_K`).
    /// Absent or 0: dry.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "1", "exclusiveMaximum" = 1.0), range(min = 0.0))]
    pub relative_humidity: Option<f64>,
    /// Surface tension `gamma` of the condensing liquid (N/m), > 0; default
    /// water at 20 C, 0.0728.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "N/m", "exclusiveMinimum" = 0.0, "default" = 0.0728))]
    pub surface_tension: Option<f64>,
    /// Contact angle of the liquid on the rough body (degrees), in
    /// `[0, 180]`; default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "deg", "default" = 0.0), range(min = 0.0, max = 180.0))]
    pub contact_angle_1: Option<f64>,
    /// Contact angle of the liquid on the flat (degrees), in `[0, 180]`;
    /// default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "deg", "default" = 0.0), range(min = 0.0, max = 180.0))]
    pub contact_angle_2: Option<f64>,
    /// Molar volume `V_m` of the liquid (m^3/mol), > 0; default water,
    /// 1.8e-5.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "m^3/mol", "exclusiveMinimum" = 0.0, "default" = 1.8e-5))]
    pub molar_volume: Option<f64>,
    /// Temperature `T` of the liquid and vapour (K), > 0; default 293.15.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "K", "exclusiveMinimum" = 0.0, "default" = 293.15))]
    pub temperature: Option<f64>,
}

impl AdhesionSpec {
    /// The meniscus these keys describe (`None` when dry: no
    /// `relative_humidity`, or 0, or a liquid that does not wet the gap).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming the `adhesion.*` key and its range.
    pub fn meniscus(&self) -> crate::Result<Option<crate::capillary::Meniscus>> {
        use crate::capillary as c;
        // The liquid's keys are checked even when dry.
        let positive = |x: Option<f64>, key: &str| match x {
            Some(v) => crate::error::Allowed::POSITIVE.check(key, v).map(|_| ()),
            None => Ok(()),
        };
        positive(self.surface_tension, "adhesion.surface_tension")?;
        positive(self.molar_volume, "adhesion.molar_volume")?;
        positive(self.temperature, "adhesion.temperature")?;
        let angle = |x: Option<f64>, key: &str| -> crate::Result<f64> {
            let x = x.unwrap_or(0.0);
            crate::error::Allowed::closed(0.0, 180.0).check(key, x)?;
            Ok(x.to_radians())
        };
        let t1 = angle(self.contact_angle_1, "adhesion.contact_angle_1")?;
        let t2 = angle(self.contact_angle_2, "adhesion.contact_angle_2")?;
        let Some(rh) = self.relative_humidity else {
            return Ok(None);
        };
        c::Meniscus::new(
            self.surface_tension.unwrap_or(c::WATER_SURFACE_TENSION),
            t1,
            t2,
            self.molar_volume.unwrap_or(c::WATER_MOLAR_VOLUME),
            self.temperature.unwrap_or(c::ROOM_TEMPERATURE),
            rh,
        )
        .map_err(|e| match e.field().map(str::to_string) {
            Some(f) if !f.starts_with("adhesion.") => e.renamed(&format!("adhesion.{f}")),
            _ => e,
        })
    }
}

/// `[law]`: the single-asperity law.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
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
    /// For `kind = "shaped"` (required there, refused otherwise):
    /// `"paraboloid"`, `"sphere"` (exact sphere), `"cone"`, `"flat"`,
    /// `"power"` or `"tabulated"`. The profile keys below apply only to
    /// `kind = "shaped"`, each to the profiles that use it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub profile: Option<ProfileKind>,
    /// Shaped: sphere/paraboloid radius or flat-punch radius (m), > 0;
    /// default `surface.radius`. The contact radius at an interference of
    /// `surface.sigma` must lie between `adhesion.z0` and the summit
    /// spacing.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "m", "exclusiveMinimum" = 0.0))]
    pub radius: Option<f64>,
    /// Shaped cone: `tan(beta)` of `f(r) = r tan(beta)`, > 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "1", "exclusiveMinimum" = 0.0))]
    pub tan_angle: Option<f64>,
    /// Shaped power law `f(r) = A r^n`: the exponent `n`, in `(0, 50]`.
    /// With the coefficient, the profile's contact radius at an
    /// interference of `surface.sigma` must lie between `adhesion.z0` and
    /// the summit spacing: an exponent that leaves no representable
    /// coefficient for that is refused naming `law.exponent`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "1", "exclusiveMinimum" = 0.0), range(max = 50.0))]
    pub exponent: Option<f64>,
    /// Shaped power law: the coefficient `A` (m^(1-n)), > 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "m^(1-n)", "exclusiveMinimum" = 0.0))]
    pub coefficient: Option<f64>,
    /// Shaped tabulated profile: radii `r` (m), strictly ascending from 0;
    /// 3 ..= 2000 points (`MAX_TABULATED_POINTS`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(
        extend("x-unit" = "m"),
        length(min = 3, max = MAX_TABULATED_POINTS),
        inner(range(min = 0.0))
    )]
    pub profile_r: Option<Vec<f64>>,
    /// Shaped tabulated profile: heights `f(r)` (m) at `profile_r` (as
    /// many), from 0 at the apex, non-decreasing, the last positive.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(
        extend("x-unit" = "m"),
        length(min = 3, max = MAX_TABULATED_POINTS),
        inner(range(min = 0.0))
    )]
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
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ProgramSpec {
    /// Closest separation of the flat from the mean summit plane (m).
    /// Exactly one of `closest_separation`, `max_load`, `separations` and
    /// `loads` must be given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "m"))]
    pub closest_separation: Option<f64>,
    /// Maximum compressive load on approach (N, > 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "N", "exclusiveMinimum" = 0.0))]
    pub max_load: Option<f64>,
    /// Separations (m, from the mean summit height) at which to report the
    /// approach state, in this order; 1 to 10,000 of them
    /// ([`MAX_LISTED_STATES`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "m"), length(min = 1, max = MAX_LISTED_STATES))]
    pub separations: Option<Vec<f64>>,
    /// Compressive loads (N, > 0) at which to report the approach state
    /// (the separation is solved for each), in this order; 1 to 10,000 of
    /// them ([`MAX_LISTED_STATES`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(
        extend("x-unit" = "N"),
        length(min = 1, max = MAX_LISTED_STATES),
        transform = positive_items
    )]
    pub loads: Option<Vec<f64>>,
    /// Separation where the program starts and ends (m), above the closest
    /// one; default: where the first asperity comes within range of the
    /// flat.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-unit" = "m"))]
    pub start_separation: Option<f64>,
    /// Points per leg (approach, retraction), in `[2, 1e6]`; default 200.
    #[serde(default = "default_points")]
    #[schemars(extend("x-unit" = "1"), range(min = 2, max = MAX_POINTS))]
    pub points: usize,
}

/// The schema of a list of positive numbers: each item > 0
/// (`schemars`' `inner(range(..))` states only inclusive bounds).
fn positive_items(schema: &mut schemars::Schema) {
    if let Some(items) = schema
        .get_mut("items")
        .and_then(serde_json::Value::as_object_mut)
    {
        items.insert("exclusiveMinimum".into(), 0.0.into());
    }
}

fn default_points() -> usize {
    200
}

/// `[outputs]`: what to compute; everything not asked for is skipped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
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

/// `[accuracy]`: the tolerance of every output, and whether the model
/// error of the law is measured.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct AccuracySpec {
    /// Relative tolerance of every output, in [1e-12, 0.1] (at least 1e-11
    /// with the calibrated law, whose table stalls below); default 1e-6.
    #[serde(default = "default_rtol")]
    #[schemars(extend("x-unit" = "1"), range(min = 1e-12, max = 0.1))]
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
