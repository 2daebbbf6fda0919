//! The JSON summary of a run. Its headline numbers (`max_load`, `max_area`,
//! `max_count`, `resistance_ohm`, ...) come from the plan's
//! [`QuantitySet`](crate::study::quantity::QuantitySet); the rest are the
//! run's scalar results and the optional features' objects.

use super::aliases::Aliases;
use super::topography::{self, TopographySummary};
use crate::study::plan::Plan;
use crate::study::quantity::{Headlines, StateRow};
use crate::study::run::{McResults, Results, MIN_SUMMITS_FOR_Z};
use crate::study::Warning;
use serde::Serialize;

/// The JSON summary of a run (SI units; `null` where not computed).
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    /// Scene title.
    pub title: Option<String>,
    /// Law used.
    pub law: String,
    /// Tabor parameter `mu` of one summit (`null` without adhesion).
    pub tabor_mu: Option<f64>,
    /// Maugis `lambda = 1.1570 mu` (`null` without adhesion).
    pub maugis_lambda: Option<f64>,
    /// Contact modulus `E*` (Pa): key `contact_modulus_Pa`.
    #[serde(rename = "contact_modulus_Pa")]
    pub contact_modulus: f64,
    /// Number of summits `eta A_n` (`null` for a rough sphere: no nominal
    /// area; its contacts are in `rough_sphere` and the states).
    pub summits: Option<f64>,
    /// Separation where the program started and ended (m): key
    /// `start_separation_m`.
    #[serde(rename = "start_separation_m")]
    pub start_separation: f64,
    /// Closest separation reached (m): key `closest_separation_m`.
    #[serde(rename = "closest_separation_m")]
    pub closest_separation: f64,
    /// Points per leg.
    pub points: usize,
    /// The quantities' headline numbers (`max_load_N` (largest on
    /// approach), `max_area_m2` and `max_count` at the closest approach,
    /// `resistance_ohm` with `[electrical]`, ...), by key (each key its
    /// sweep column, with its unit).
    #[serde(flatten)]
    pub headlines: Headlines,
    /// Pull-off force (N, negative = tensile): key `pull_off_load_N`.
    #[serde(rename = "pull_off_load_N")]
    pub pull_off_load: Option<f64>,
    /// Separation of the pull-off (m): key `pull_off_separation_m`.
    #[serde(rename = "pull_off_separation_m")]
    pub pull_off_separation: Option<f64>,
    /// The pull-off of one switch over populations of its `eta A_n`
    /// summits, with a finite surface whose pull-off is searched.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pull_off_population: Option<PopulationSummary>,
    /// Energy lost per cycle (J): key `hysteresis_energy_J`.
    #[serde(rename = "hysteresis_energy_J")]
    pub hysteresis_energy: Option<f64>,
    /// Requested relative tolerance.
    pub rtol: f64,
    /// Model error of the chosen law: its measured relative error against
    /// the full Lennard-Jones solution at this Tabor parameter
    /// ([`crate::law::errors::LawErrorTable`]); `null` when unknown
    /// (calibrated, no adhesion). `rtol` bounds only the numerics.
    pub law_model_error: Option<f64>,
    /// Model error of the headline outputs on this surface: each one's
    /// relative difference from the full Lennard-Jones solver's law on the
    /// same surface and program, and what it is measured against.
    pub model_error: Option<ModelErrorSummary>,
    /// Wall-clock time of the run (s).
    pub seconds: f64,
    /// The SIMD instruction set the vector passes ran on (`avx512`, `avx2`
    /// or `scalar`; `ASPERITY_SIMD` narrows it, [`crate::numeric::simd`]):
    /// the timings depend on it, the numbers do not.
    pub simd: &'static str,
    /// Law evaluations spent by quadrature.
    pub evaluations: usize,
    /// The explicit population beside the integral, if asked for.
    pub montecarlo: Option<McSummary>,
    /// The plan's decisions: `what: choice (why)`.
    pub plan: Vec<String>,
    /// Joule heating at the closest approach, with `electrical.current`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub heating: Option<HeatingSummary>,
    /// Plasticity diagnostics, when the materials give a yield strength.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plasticity: Option<PlasticitySummary>,
    /// The switch's stiction verdict, with `[switch]`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stiction: Option<StictionSummary>,
    /// The states listed in `[program]` (`separations` or `loads`), in the
    /// listed order: `separation_m` and each quantity's value.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub states: Option<Vec<StateRow>>,
    /// Where the scene or its results lie outside a model's validity, one
    /// sentence each (empty when none): the plan's, then the run's,
    /// written as their sentences ([`Warning`]'s `Display`).
    pub warnings: Vec<Warning>,
    /// The code of each warning ([`Warning::code`]), in the same order.
    pub warning_codes: Vec<&'static str>,
    /// The measured map (`[surface] topography`): its characterisation, the
    /// model used and, when asked, the other model's headline numbers.
    /// Absent without a map.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub topography: Option<TopographySummary>,
    /// With `[sphere]`: the bump's state at the closest approach (remote
    /// separation, approach, central deflection, load, the radius holding
    /// 95 % of the load against Hertz's, real area, contacts, resistance
    /// with the equivalent square of its interaction, outer mesh radius,
    /// nodes, model and warnings; each estimate with its numerical error).
    /// Absent without a sphere.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rough_sphere: Option<crate::roughsphere::SphereState>,
    /// The previous release's keys without a unit (`max_load`,
    /// `pull_off_load`, `start_separation`, ...), written beside the new
    /// ones with the same values for one release: deprecated
    /// ([`DEPRECATED_KEYS`]).
    #[serde(flatten)]
    pub deprecated: Aliases,
}

/// The summary keys renamed to carry their unit, as `(old, new)`: the old
/// names are still written for one release (deprecated aliases, the same
/// value), then dropped. `montecarlo.` keys are inside the `"montecarlo"`
/// object.
pub const DEPRECATED_KEYS: [(&str, &str); 15] = [
    ("contact_modulus", "contact_modulus_Pa"),
    ("start_separation", "start_separation_m"),
    ("closest_separation", "closest_separation_m"),
    ("max_load", "max_load_N"),
    ("max_area", "max_area_m2"),
    ("pull_off_load", "pull_off_load_N"),
    ("pull_off_separation", "pull_off_separation_m"),
    ("hysteresis_energy", "hysteresis_energy_J"),
    ("montecarlo.max_load", "montecarlo.max_load_N"),
    (
        "montecarlo.max_load_standard_error",
        "montecarlo.max_load_standard_error_N",
    ),
    ("montecarlo.pull_off_load", "montecarlo.pull_off_load_N"),
    (
        "montecarlo.integral_sampled_pull_off_load",
        "montecarlo.integral_sampled_pull_off_load_N",
    ),
    (
        "montecarlo.pull_off_other_seeds",
        "montecarlo.pull_off_other_seeds_N",
    ),
    (
        "montecarlo.pull_off_seed_mean",
        "montecarlo.pull_off_seed_mean_N",
    ),
    (
        "montecarlo.pull_off_seed_std",
        "montecarlo.pull_off_seed_std_N",
    ),
];

/// The model error of the headline outputs (relative: `(law -
/// reference)/|reference|`; `null` where not measured).
#[derive(Debug, Clone, Serialize)]
pub struct ModelErrorSummary {
    /// Of the pull-off.
    pub pull_off: Option<f64>,
    /// Of the load at the closest approach.
    pub max_load: Option<f64>,
    /// Of the hysteresis energy.
    pub hysteresis_energy: Option<f64>,
    /// What it is measured against.
    pub reference: String,
    /// The reference's pull-off (N).
    #[serde(rename = "reference_pull_off_N")]
    pub reference_pull_off_n: Option<f64>,
    /// The reference's load at the closest approach (N).
    #[serde(rename = "reference_max_load_N")]
    pub reference_max_load_n: Option<f64>,
    /// The reference's hysteresis energy (J).
    #[serde(rename = "reference_hysteresis_energy_J")]
    pub reference_hysteresis_energy_j: Option<f64>,
    /// Of the load at each listed state, in the listed order (absent when
    /// no state is listed).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub listed_loads: Vec<Option<f64>>,
    /// On a measured map, per state (`states`): GW's real-area fraction
    /// against the exact elastic solution's at the same load, `(GW -
    /// exact)/exact` (absent without a measured map or when not measured).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub area: Vec<Option<f64>>,
    /// The same of GW's load at the exact solution's mean gap.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub load: Vec<Option<f64>>,
    /// The same of GW's mean gap at the same load.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub mean_gap: Vec<Option<f64>>,
    /// The states compared, with both models' values.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub states: Vec<MapStateSummary>,
    /// The exact solution's estimated CPU time (s), on a measured map.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exact_estimate_s: Option<f64>,
    /// Its time (s, wall), when measured.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exact_seconds: Option<f64>,
    /// On a measured map with adhesion: GW's pull-off against the adhesive
    /// boundary-element solution of the map, or why it is not measured
    /// (`pull_off` and `reference_pull_off_N` above are its relative
    /// difference and exact pull-off when measured there).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pull_off_map: Option<crate::study::map_pull_off::MapPullOff>,
}

/// One state of a measured map's model error: GW beside the exact elastic
/// solution at the same load.
#[derive(Debug, Clone, Serialize)]
pub struct MapStateSummary {
    /// The load (N) on the nominal area.
    #[serde(rename = "load_N")]
    pub load_n: f64,
    /// Its mean pressure (Pa).
    #[serde(rename = "pressure_Pa")]
    pub pressure_pa: f64,
    /// The exact real-area fraction.
    pub exact_area_fraction: f64,
    /// The exact mean gap (m).
    #[serde(rename = "exact_mean_gap_m")]
    pub exact_mean_gap_m: f64,
    /// GW's real-area fraction at the same load.
    pub gw_area_fraction: f64,
    /// GW's mean gap (m) at the same load (negative where GW's summits
    /// are pressed below the mean plane).
    #[serde(rename = "gw_mean_gap_m")]
    pub gw_mean_gap_m: f64,
    /// GW's load (N) at the exact mean gap.
    #[serde(rename = "gw_load_at_exact_gap_N")]
    pub gw_load_at_exact_gap_n: Option<f64>,
    /// How the exact solve ended: its iterations, final residual
    /// (dimensionless, below the tolerance) and `converged` (always: a
    /// solve stopped at the iteration cap fails the measurement); its keys
    /// inline.
    #[serde(flatten)]
    pub solve: crate::bem::SolveReport,
}

impl ModelErrorSummary {
    fn new(m: &crate::study::model_error::ModelError) -> ModelErrorSummary {
        let states = m.map.as_ref().map_or(&[][..], |x| &x.states[..]);
        let map_pull = m.map_pull_off.as_ref().filter(|p| p.exact.is_some());
        ModelErrorSummary {
            pull_off: m.pull_off.or(map_pull.and_then(|p| p.relative)),
            max_load: m.max_load,
            hysteresis_energy: m.hysteresis_energy,
            reference: m.full_reference(),
            reference_pull_off_n: m.reference_pull_off.or(map_pull.and_then(|p| p.exact)),
            reference_max_load_n: m.reference_max_load,
            reference_hysteresis_energy_j: m.reference_hysteresis_energy,
            listed_loads: m.listed_loads.clone(),
            area: states.iter().map(|s| s.area).collect(),
            load: states.iter().map(|s| s.load_at_gap).collect(),
            mean_gap: states.iter().map(|s| s.mean_gap).collect(),
            states: states
                .iter()
                .map(|s| MapStateSummary {
                    load_n: s.load,
                    pressure_pa: s.pressure,
                    exact_area_fraction: s.exact_area_fraction,
                    exact_mean_gap_m: s.exact_mean_gap,
                    gw_area_fraction: s.gw_area_fraction,
                    gw_mean_gap_m: s.gw_mean_gap,
                    gw_load_at_exact_gap_n: s.gw_load_at_exact_gap,
                    solve: s.solve,
                })
                .collect(),
            exact_estimate_s: m.map.as_ref().map(|x| x.estimate_s),
            exact_seconds: m
                .map
                .as_ref()
                .filter(|x| !x.states.is_empty())
                .map(|x| x.seconds),
            pull_off_map: m.map_pull_off.clone(),
        }
    }
}

/// Joule heating of the contact at the closest approach.
#[derive(Debug, Clone, Serialize)]
pub struct HeatingSummary {
    /// Current (A).
    #[serde(rename = "current_A")]
    pub current_a: f64,
    /// Bulk temperature (K).
    #[serde(rename = "bulk_temperature_K")]
    pub bulk_temperature_k: f64,
    /// Contact voltage `I R` (V).
    #[serde(rename = "contact_voltage_V")]
    pub contact_voltage_v: Option<f64>,
    /// Peak contact temperature `sqrt(T0^2 + U^2/(4L))` (K).
    #[serde(rename = "max_temperature_K")]
    pub max_temperature_k: Option<f64>,
}

/// Plasticity diagnostics of a run.
#[derive(Debug, Clone, Serialize)]
pub struct PlasticitySummary {
    /// GW plasticity index `psi = (E*/H) sqrt(sigma/R)`.
    pub plasticity_index: f64,
    /// Hardness used (Pa).
    #[serde(rename = "hardness_Pa")]
    pub hardness_pa: f64,
    /// Fraction of the contacts at the closest approach that are elastic.
    pub elastic_fraction: Option<f64>,
    /// ... elastic-plastic.
    pub elastic_plastic_fraction: Option<f64>,
    /// ... fully plastic.
    pub fully_plastic_fraction: Option<f64>,
}

/// The stiction verdict (`pull_off_N` negative, tensile).
#[derive(Debug, Clone, Serialize)]
pub struct StictionSummary {
    /// Pull-off of the rough contact (N, <= 0).
    #[serde(rename = "pull_off_N")]
    pub pull_off_n: f64,
    /// Restoring force `k x travel` (N).
    #[serde(rename = "restoring_force_N")]
    pub restoring_force_n: f64,
    /// `k x travel - |pull_off|` (N).
    #[serde(rename = "margin_N")]
    pub margin_n: f64,
    /// Whether the margin is negative.
    pub sticks: bool,
    /// Probability that one switch sticks: the fraction of the populations
    /// whose pull-off exceeds the restoring force (0 or 1 on the integral
    /// basis).
    pub sticks_probability: f64,
    /// Its Clopper–Pearson 95 % interval (population basis only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sticks_probability_interval: Option<(f64, f64)>,
    /// Confidence of `pull_off_N` (population basis: its `1 - confidence`
    /// quantile; `switch.confidence`).
    pub confidence: f64,
    /// `"population"` (the populations' quantile) or `"integral"` (the GW
    /// integral's pull-off).
    pub pull_off_basis: &'static str,
}

/// The pull-off distribution over populations (N, signed: negative is
/// tensile; quantiles ascend, so `p05_N` is the more tensile end).
#[derive(Debug, Clone, Serialize)]
pub struct PopulationSummary {
    /// Populations drawn.
    pub seeds: usize,
    /// Seed of the first (the others follow it).
    pub first_seed: u64,
    /// Summits of each, `eta A_n` rounded.
    pub summits: usize,
    /// `"exact"`: each the `[montecarlo]` population of its seed (its
    /// summits within the flat's reach drawn from the top, bit for bit).
    pub draw: &'static str,
    /// Mean pull-off.
    #[serde(rename = "mean_N")]
    pub mean_n: Option<f64>,
    /// Its standard error, `std / sqrt(seeds)`.
    #[serde(rename = "mean_se_N")]
    pub mean_se_n: Option<f64>,
    /// Median.
    #[serde(rename = "median_N")]
    pub median_n: Option<f64>,
    /// Sample standard deviation (divisor `n - 1`).
    #[serde(rename = "std_N")]
    pub std_n: Option<f64>,
    /// 5 % quantile (type 7).
    #[serde(rename = "p05_N")]
    pub p05_n: Option<f64>,
    /// Its distribution-free 95 % interval: the shortest pair of order
    /// statistics whose exact binomial coverage is at least 95 %; null when
    /// no pair reaches it (`interval_note` says why).
    #[serde(rename = "p05_interval_N")]
    pub p05_interval_n: Option<(f64, f64)>,
    /// The exact coverage of `p05_interval_N` (the probability that it
    /// holds the true 5 % quantile, from the binomial distribution).
    pub p05_interval_coverage: Option<f64>,
    /// 95 % quantile.
    #[serde(rename = "p95_N")]
    pub p95_n: Option<f64>,
    /// Its distribution-free 95 % interval (as `p05_interval_N`).
    #[serde(rename = "p95_interval_N")]
    pub p95_interval_n: Option<(f64, f64)>,
    /// The exact coverage of `p95_interval_N`.
    pub p95_interval_coverage: Option<f64>,
    /// Why a quantile interval is null: too few populations for any pair
    /// of order statistics to reach the confidence.
    pub interval_note: Option<String>,
    /// Expected summits in contact at the integral's pull-off separation.
    pub carriers: Option<f64>,
    /// The integral's pull-off, for comparison.
    #[serde(rename = "integral_N")]
    pub integral_n: Option<f64>,
    /// Numerical error: each population's minimum is sampled at the
    /// program's separations.
    pub numerical_error: &'static str,
    /// Why none or fewer were drawn.
    pub note: Option<String>,
    /// Wall-clock time (s).
    pub seconds: f64,
}

impl PopulationSummary {
    fn new(r: &crate::study::population::PopulationResults) -> PopulationSummary {
        let s = r.statistics.as_ref();
        let interval = |q: f64| s.and_then(|s| s.quantile_interval(q).ok());
        PopulationSummary {
            seeds: r.drawn,
            first_seed: r.plan.first_seed,
            summits: r.plan.summits,
            draw: "exact",
            mean_n: s.map(|s| s.mean()),
            mean_se_n: s.map(|s| s.mean_standard_error()),
            median_n: s.map(|s| s.quantile(0.5)),
            std_n: s.map(|s| s.std()),
            p05_n: s.map(|s| s.quantile(0.05)),
            p05_interval_n: interval(0.05).map(|i| i.bounds),
            p05_interval_coverage: interval(0.05).map(|i| i.ranks.coverage),
            p95_n: s.map(|s| s.quantile(0.95)),
            p95_interval_n: interval(0.95).map(|i| i.bounds),
            p95_interval_coverage: interval(0.95).map(|i| i.ranks.coverage),
            interval_note: s.and_then(crate::study::population::interval_note),
            carriers: r.carriers,
            integral_n: r.integral,
            numerical_error: "each population's pull-off is its most tensile load at the \
                              program's separations (within one step of its true minimum)",
            note: r.note.clone(),
            seconds: r.seconds,
        }
    }
}

/// The Monte Carlo part of a summary.
#[derive(Debug, Clone, Serialize)]
pub struct McSummary {
    /// Summits drawn.
    pub summits: usize,
    /// Seed.
    pub seed: u64,
    /// Largest approach load of the population (N), scaled to the surface.
    #[serde(rename = "max_load_N")]
    pub max_load: Option<f64>,
    /// Its standard error (N); `null` with fewer than
    /// [`MIN_SUMMITS_FOR_Z`] summits in contact there.
    #[serde(rename = "max_load_standard_error_N")]
    pub max_load_standard_error: Option<f64>,
    /// Most tensile sampled retraction load of this one realisation (N):
    /// the pull-off of one switch with these summits (the minimum of its
    /// own load curve).
    #[serde(rename = "pull_off_load_N")]
    pub pull_off_load: Option<f64>,
    /// The integral's most tensile load at the same sampled separations
    /// (N): the minimum of the *mean* load curve, which is not the mean of
    /// the realisations' minima (each realisation's few tensile summits
    /// detach at their own separations), so the two differ by far more than
    /// the standard errors of the curve.
    #[serde(rename = "integral_sampled_pull_off_load_N")]
    pub integral_sampled_pull_off_load: Option<f64>,
    /// Pull-offs (N) of the populations with seeds `seed + 1 ..` (the
    /// scatter of one switch's pull-off, from `pull_off_population`; empty
    /// without it); `null` entries have no tensile load.
    #[serde(rename = "pull_off_other_seeds_N")]
    pub pull_off_other_seeds: Vec<Option<f64>>,
    /// Mean of the pull-offs of all seeds drawn (this one and the others).
    #[serde(rename = "pull_off_seed_mean_N")]
    pub pull_off_seed_mean: Option<f64>,
    /// Their sample standard deviation (N, divisor n - 1): how much one
    /// realisation's pull-off scatters.
    #[serde(rename = "pull_off_seed_std_N")]
    pub pull_off_seed_std: Option<f64>,
    /// States where fewer than [`MIN_SUMMITS_FOR_Z`] summits of the
    /// population are in contact: no standard error or deviation is
    /// reported there (the central limit does not hold).
    pub states_without_standard_error: usize,
    /// Largest deviation from the integral over the curve, in standard
    /// errors (`< 5` expected when the population follows the model).
    pub max_abs_z: Option<f64>,
    /// Wall-clock time of drawing and summing (s).
    pub seconds: f64,
    /// With `[electrical]`: the sample's own spots at the closest
    /// separation, at random positions in the area it stands for.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spots: Option<SampleSpotsSummary>,
    /// The previous release's keys without a unit (`max_load`,
    /// `pull_off_load`, ...), deprecated ([`DEPRECATED_KEYS`]).
    #[serde(flatten)]
    pub deprecated: Aliases,
}

/// Resistances of a population's explicit spots (Ohm).
#[derive(Debug, Clone, Serialize)]
pub struct SampleSpotsSummary {
    /// Number of spots (summits in contact).
    pub count: usize,
    /// Side of the square the spots were placed in (m): `sqrt(summits/eta)`.
    pub side_m: f64,
    /// Independent parallel spots.
    pub parallel_ohm: f64,
    /// Greenwood's formula for the explicit positions.
    pub greenwood_ohm: f64,
    /// The exact equal-potential solution (`null` above 3000 spots).
    pub exact_ohm: Option<f64>,
}

impl Summary {
    /// Summarises a run of `plan`.
    pub fn new(plan: &Plan, results: &Results) -> Summary {
        let plan = results.plan(plan);
        let adhesive = plan.contact.adhesion.work() > 0.0;
        Summary {
            title: plan.scene.title.clone(),
            law: plan.law.name.clone(),
            tabor_mu: adhesive.then(|| plan.contact.tabor()),
            maugis_lambda: adhesive.then(|| plan.contact.lambda()),
            contact_modulus: plan.contact.contact_modulus,
            summits: plan.sphere.is_none().then(|| plan.surface.summits()),
            start_separation: plan.start,
            closest_separation: results.curve.program.closest,
            points: plan.points,
            headlines: plan.quantities.headlines(&results.records.approach),
            pull_off_load: results.pull_off.map(|p| p.load),
            pull_off_separation: results.pull_off.map(|p| p.separation),
            pull_off_population: results
                .pull_off_population
                .as_ref()
                .map(PopulationSummary::new),
            hysteresis_energy: results.hysteresis_energy,
            rtol: plan.budget.rtol,
            law_model_error: plan.law.measured_error.filter(|_| adhesive),
            model_error: results.model_error.as_ref().map(ModelErrorSummary::new),
            seconds: results.seconds,
            simd: crate::numeric::simd::arch_name(),
            evaluations: results.evaluations,
            montecarlo: results
                .montecarlo
                .as_ref()
                .map(|m| McSummary::new(plan, results, m)),
            plan: plan.decisions.iter().map(|d| d.to_string()).collect(),
            heating: heating(plan, results),
            plasticity: plasticity(plan, results),
            stiction: results.stiction.map(|s| StictionSummary {
                pull_off_n: s.pull_off,
                restoring_force_n: super::format::tidy(s.restoring_force),
                margin_n: s.margin,
                sticks: s.sticks,
                sticks_probability: results
                    .stiction_odds
                    .map_or(f64::from(u8::from(s.sticks)), |o| o.probability),
                sticks_probability_interval: results.stiction_odds.map(|o| o.interval),
                confidence: results
                    .stiction_odds
                    .map_or(plan.stiction_confidence(), |o| o.confidence),
                pull_off_basis: if results.stiction_odds.is_some() {
                    "population"
                } else {
                    "integral"
                },
            }),
            states: plan.listed.as_ref().map(|_| {
                results
                    .listed
                    .iter()
                    .map(|r| plan.quantities.row(r))
                    .collect()
            }),
            warnings: plan
                .warnings
                .iter()
                .chain(&results.warnings)
                .cloned()
                .collect(),
            warning_codes: Warning::codes(plan.warnings.iter().chain(&results.warnings)),
            topography: topography::summary(plan, results),
            rough_sphere: results.sphere.clone(),
            deprecated: Aliases::default(),
        }
        .with_aliases()
    }

    /// The deprecated aliases ([`DEPRECATED_KEYS`]) of this summary's
    /// values, set from them.
    fn with_aliases(mut self) -> Summary {
        use serde_json::json;
        let headlines = self
            .headlines
            .0
            .iter()
            .filter(|(h, _)| h.key != h.sweep)
            .map(|(h, v)| (h.key.as_str(), json!(v)));
        self.deprecated = Aliases::of(
            [
                ("contact_modulus", json!(self.contact_modulus)),
                ("start_separation", json!(self.start_separation)),
                ("closest_separation", json!(self.closest_separation)),
            ]
            .into_iter()
            .chain(headlines)
            .chain([
                ("pull_off_load", json!(self.pull_off_load)),
                ("pull_off_separation", json!(self.pull_off_separation)),
                ("hysteresis_energy", json!(self.hysteresis_energy)),
            ]),
        );
        if let Some(m) = self.montecarlo.as_mut() {
            m.deprecated = Aliases::of([
                ("max_load", json!(m.max_load)),
                ("max_load_standard_error", json!(m.max_load_standard_error)),
                ("pull_off_load", json!(m.pull_off_load)),
                (
                    "integral_sampled_pull_off_load",
                    json!(m.integral_sampled_pull_off_load),
                ),
                ("pull_off_other_seeds", json!(m.pull_off_other_seeds)),
                ("pull_off_seed_mean", json!(m.pull_off_seed_mean)),
                ("pull_off_seed_std", json!(m.pull_off_seed_std)),
            ]);
        }
        self
    }

    /// Pretty JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default()
    }

    /// The scalar results by sweep column (`max_load_N`, `pull_off_N`,
    /// `mc_max_load_N`, `sticks` as 1/0, ...), in the order of
    /// [`Plan::result_columns`]; a sweep's `results.csv` has one column
    /// each.
    pub fn scalars(&self) -> Vec<(String, Option<f64>)> {
        let mut v: Vec<(String, Option<f64>)> = self
            .headlines
            .0
            .iter()
            .map(|(h, x)| (h.sweep.clone(), *x))
            .collect();
        v.extend(
            RUN_SCALARS
                .iter()
                .map(|r| (r.name.to_string(), (r.read)(self))),
        );
        v
    }
}

/// Which part of a run a run-level scalar belongs to: a plan reports it
/// when the scene asks for that part.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ScalarGroup {
    /// `[outputs] pull_off`.
    PullOff,
    /// `[outputs] hysteresis_energy`.
    Hysteresis,
    /// A `[montecarlo]` section.
    MonteCarlo,
    /// A `[switch]` section.
    Switch,
}

/// A run-level scalar beside the quantities' headline numbers: its name
/// (a sweep column and a [`Summary::scalars`] key, with its unit suffix),
/// the part of the run it belongs to, and how a summary gives it.
#[derive(Debug, Clone, Copy)]
pub struct RunScalar {
    /// The column name.
    pub name: &'static str,
    /// What the scene must ask for.
    pub group: ScalarGroup,
    /// Its value in a summary (`None`: not computed, or no such value).
    pub read: fn(&Summary) -> Option<f64>,
}

/// Every run-level scalar, declared once: the sweep's columns
/// ([`Plan::result_columns`]) and the summary's values
/// ([`Summary::scalars`]) both come from this list.
pub const RUN_SCALARS: [RunScalar; 10] = [
    RunScalar {
        name: "pull_off_N",
        group: ScalarGroup::PullOff,
        read: |s| s.pull_off_load,
    },
    RunScalar {
        name: "pull_off_separation_m",
        group: ScalarGroup::PullOff,
        read: |s| s.pull_off_separation,
    },
    RunScalar {
        name: "hysteresis_energy_J",
        group: ScalarGroup::Hysteresis,
        read: |s| s.hysteresis_energy,
    },
    RunScalar {
        name: "mc_max_load_N",
        group: ScalarGroup::MonteCarlo,
        read: |s| s.montecarlo.as_ref().and_then(|m| m.max_load),
    },
    RunScalar {
        name: "mc_max_load_se_N",
        group: ScalarGroup::MonteCarlo,
        read: |s| {
            s.montecarlo
                .as_ref()
                .and_then(|m| m.max_load_standard_error)
        },
    },
    RunScalar {
        name: "mc_pull_off_N",
        group: ScalarGroup::MonteCarlo,
        read: |s| s.montecarlo.as_ref().and_then(|m| m.pull_off_load),
    },
    RunScalar {
        name: "mc_max_abs_z",
        group: ScalarGroup::MonteCarlo,
        read: |s| s.montecarlo.as_ref().and_then(|m| m.max_abs_z),
    },
    RunScalar {
        name: "stiction_margin_N",
        group: ScalarGroup::Switch,
        read: |s| s.stiction.as_ref().map(|t| t.margin_n),
    },
    // 1 when the switch sticks (margin < 0), else 0.
    RunScalar {
        name: "sticks",
        group: ScalarGroup::Switch,
        read: |s| s.stiction.as_ref().map(|t| f64::from(u8::from(t.sticks))),
    },
    // The share of the pull-off population's switches that stick (0 or 1
    // without a population).
    RunScalar {
        name: "sticks_probability",
        group: ScalarGroup::Switch,
        read: |s| s.stiction.as_ref().map(|t| t.sticks_probability),
    },
];

impl Plan {
    /// Whether this plan reports the run-level scalars of `group`.
    pub fn reports(&self, group: ScalarGroup) -> bool {
        let o = self.scene.outputs;
        match group {
            ScalarGroup::PullOff => o.pull_off,
            ScalarGroup::Hysteresis => o.hysteresis_energy,
            ScalarGroup::MonteCarlo => self.montecarlo.is_some(),
            ScalarGroup::Switch => self.switch.is_some(),
        }
    }

    /// The columns of a sweep's `results.csv` for this plan's outputs:
    /// the headline number of every asked quantity, then the pull-off,
    /// the hysteresis energy, the Monte Carlo and stiction results when the
    /// scene asks for them (names as in [`Summary::scalars`]).
    pub fn result_columns(&self) -> Vec<String> {
        let mut cols: Vec<String> = self
            .quantities
            .iter()
            .filter(|q| q.asked)
            .filter_map(|q| q.headline.as_ref().map(|h| h.sweep.clone()))
            .collect();
        cols.extend(
            RUN_SCALARS
                .iter()
                .filter(|r| self.reports(r.group))
                .map(|r| r.name.to_string()),
        );
        cols
    }
}

/// The heating object at the closest approach, with a current.
fn heating(plan: &Plan, results: &Results) -> Option<HeatingSummary> {
    let (i, h) = plan.heating?;
    let closest = results.records.approach.first();
    let value = |name: &str| {
        let (k, _) = plan.quantities.find(name)?;
        closest.and_then(|r| r.values[k])
    };
    Some(HeatingSummary {
        current_a: i,
        bulk_temperature_k: h.bulk_temperature(),
        contact_voltage_v: value("contact_voltage"),
        max_temperature_k: value("max_temperature"),
    })
}

/// The plasticity object, with a yield strength.
fn plasticity(plan: &Plan, results: &Results) -> Option<PlasticitySummary> {
    let p = plan.plasticity?;
    let f = results.regimes.filter(|f| f.contacts_per_summit > 0.0);
    Some(PlasticitySummary {
        plasticity_index: plan
            .surface
            .plasticity_index(plan.contact.contact_modulus, p.hardness())
            .unwrap_or(f64::NAN),
        hardness_pa: p.hardness(),
        elastic_fraction: f.map(|f| f.elastic),
        elastic_plastic_fraction: f.map(|f| f.elastic_plastic),
        fully_plastic_fraction: f.map(|f| f.fully_plastic),
    })
}

impl McSummary {
    fn new(plan: &Plan, results: &Results, m: &McResults) -> McSummary {
        // A standard error only where enough summits are in contact.
        let min = MIN_SUMMITS_FOR_Z as f64;
        let top = m
            .curve
            .approach
            .iter()
            .zip(&m.contacts)
            .filter_map(|(s, &c)| {
                s.load().map(|p| {
                    let se = s.totals.error(0).filter(|e| c >= min && e.is_finite());
                    (p, se)
                })
            })
            .max_by(|a, b| a.0.total_cmp(&b.0));
        let mc = plan.montecarlo.as_ref();
        // The pull-off populations start with this population's seed when
        // they draw the same summits: the others are its other seeds.
        let same = |p: &crate::study::population::PopulationResults| {
            mc.is_some_and(|m| m.spec.seed == p.plan.first_seed && m.summits == p.plan.summits)
        };
        let stats = results
            .pull_off_population
            .as_ref()
            .filter(|p| same(p))
            .and_then(|p| p.statistics.as_ref());
        McSummary {
            pull_off_other_seeds: stats.map_or(Vec::new(), |s| {
                s.values[1..]
                    .iter()
                    .map(|&v| (v < 0.0).then_some(v))
                    .collect()
            }),
            pull_off_seed_mean: stats.map(|s| s.mean()),
            pull_off_seed_std: stats.filter(|s| s.len() > 1).map(|s| s.std()),
            states_without_standard_error: m.contacts.iter().filter(|&&c| c < min).count(),
            summits: mc.map_or(0, |p| p.summits),
            seed: mc.map_or(0, |p| p.spec.seed),
            max_load: top.map(|t| t.0),
            max_load_standard_error: top.and_then(|t| t.1),
            pull_off_load: m.pull_off.map(|p| p.load),
            integral_sampled_pull_off_load: results.curve.sampled_pull_off().map(|p| p.load),
            max_abs_z: m.max_abs_z,
            seconds: m.seconds,
            spots: m.spots.map(|s| SampleSpotsSummary {
                count: s.spots,
                side_m: mc.map_or(f64::NAN, |p| (plan.surface.nominal_area / p.factor).sqrt()),
                parallel_ohm: s.parallel,
                greenwood_ohm: s.greenwood,
                exact_ohm: s.exact,
            }),
            deprecated: Aliases::default(),
        }
    }
}
