//! Result tables (the curve as CSV, a JSON summary) and the figures.

mod feature_figures;
mod figures;
mod topography;

pub use feature_figures::{feature_charts, FeatureChart};
pub use figures::{charts, si_prefix, si_prefix_area, write_outputs};
pub use topography::{HeadlineJson, MeasuredJson, MomentsJson, TopographySummary};

use crate::loading::State;
use crate::study::plan::Plan;
use crate::study::run::Results;
use serde::Serialize;
use std::fmt::Write as _;

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
    /// Contact modulus `E*` (Pa).
    pub contact_modulus: f64,
    /// Number of summits `eta A_n`.
    pub summits: f64,
    /// Separation where the program started and ended (m).
    pub start_separation: f64,
    /// Closest separation reached (m).
    pub closest_separation: f64,
    /// Points per leg.
    pub points: usize,
    /// Largest approach load (N).
    pub max_load: Option<f64>,
    /// Real contact area at the closest separation (m^2).
    pub max_area: Option<f64>,
    /// Number of contacts at the closest separation.
    pub max_count: Option<f64>,
    /// Pull-off force (N, negative = tensile).
    pub pull_off_load: Option<f64>,
    /// Separation of the pull-off (m).
    pub pull_off_separation: Option<f64>,
    /// Energy lost per cycle (J).
    pub hysteresis_energy: Option<f64>,
    /// Requested relative tolerance.
    pub rtol: f64,
    /// Model error of the chosen law: its measured relative error against
    /// the full Lennard-Jones solution at this Tabor parameter
    /// ([`crate::law::errors::LawErrorTable`]); `null` when unknown
    /// (calibrated, no adhesion). `rtol` bounds only the numerics.
    pub law_model_error: Option<f64>,
    /// Wall-clock time of the run (s).
    pub seconds: f64,
    /// Law evaluations spent by quadrature.
    pub evaluations: usize,
    /// The explicit population beside the integral, if asked for.
    pub montecarlo: Option<McSummary>,
    /// The plan's decisions: `what: choice (why)`.
    pub plan: Vec<String>,
    /// Contact resistance at the closest approach (Ohm), with
    /// `outputs.resistance`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub resistance_ohm: Option<f64>,
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
    /// listed order.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub states: Option<Vec<StateRow>>,
    /// Where the scene or its results lie outside a model's validity, one
    /// sentence each (empty when none).
    pub warnings: Vec<String>,
    /// The measured map (`[surface] topography`): its characterisation, the
    /// model used and, when asked, the other model's headline numbers.
    /// Absent without a map.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub topography: Option<TopographySummary>,
}

/// One listed state (approach).
#[derive(Debug, Clone, Serialize)]
pub struct StateRow {
    /// Separation of the flat from the mean summit height (m).
    pub separation_m: f64,
    /// Total load (N, > 0 compressive).
    #[serde(rename = "load_N")]
    pub load_n: Option<f64>,
    /// Real contact area (m^2).
    pub real_area_m2: Option<f64>,
    /// Expected number of contacts.
    pub contacts: Option<f64>,
    /// Contact resistance (Ohm), with `[electrical]`; `null` without
    /// contact.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub resistance_ohm: Option<Option<f64>>,
    /// Contact voltage `I R` (V), with `electrical.current`.
    #[serde(rename = "contact_voltage_V", skip_serializing_if = "Option::is_none")]
    pub contact_voltage_v: Option<Option<f64>>,
    /// Peak contact temperature (K), with `electrical.current`.
    #[serde(rename = "max_temperature_K", skip_serializing_if = "Option::is_none")]
    pub max_temperature_k: Option<Option<f64>>,
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
}

/// The Monte Carlo part of a summary.
#[derive(Debug, Clone, Serialize)]
pub struct McSummary {
    /// Summits drawn.
    pub summits: usize,
    /// Seed.
    pub seed: u64,
    /// Largest approach load of the population (N), scaled to the surface.
    pub max_load: Option<f64>,
    /// Its standard error (N); `null` with fewer than
    /// [`crate::study::run::MIN_SUMMITS_FOR_Z`] summits in contact there.
    pub max_load_standard_error: Option<f64>,
    /// Most tensile sampled retraction load of this one realisation (N):
    /// the pull-off of one switch with these summits (the minimum of its
    /// own load curve).
    pub pull_off_load: Option<f64>,
    /// The integral's most tensile load at the same sampled separations
    /// (N): the minimum of the *mean* load curve, which is not the mean of
    /// the realisations' minima (each realisation's few tensile summits
    /// detach at their own separations), so the two differ by far more than
    /// the standard errors of the curve.
    pub integral_sampled_pull_off_load: Option<f64>,
    /// Pull-offs (N) of populations with seeds `seed + 1 ..` (the scatter
    /// of one switch's pull-off; empty when the population is too large,
    /// see [`crate::study::run::SEED_SPREAD_BUDGET`]); `null` entries have
    /// no tensile load.
    pub pull_off_other_seeds: Vec<Option<f64>>,
    /// Mean of the pull-offs of all seeds drawn (this one and the others).
    pub pull_off_seed_mean: Option<f64>,
    /// Their sample standard deviation (N, divisor n - 1): how much one
    /// realisation's pull-off scatters.
    pub pull_off_seed_std: Option<f64>,
    /// States where fewer than [`crate::study::run::MIN_SUMMITS_FOR_Z`]
    /// summits of the population are in contact: no standard error or
    /// deviation is reported there (the central limit does not hold).
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
        let closest = results.curve.approach.first();
        let adhesive = plan.contact.adhesion.work() > 0.0;
        Summary {
            title: plan.scene.title.clone(),
            law: plan.law.name.clone(),
            tabor_mu: adhesive.then(|| plan.contact.tabor()),
            maugis_lambda: adhesive.then(|| plan.contact.lambda()),
            contact_modulus: plan.contact.contact_modulus,
            summits: plan.surface.summits(),
            start_separation: plan.start,
            closest_separation: results.curve.program.closest,
            points: plan.points,
            max_load: results.max_load().filter(|_| plan.scene.outputs.load),
            max_area: closest.and_then(|s| s.area()),
            max_count: closest.and_then(|s| s.count()),
            pull_off_load: results.pull_off.map(|p| p.load),
            pull_off_separation: results.pull_off.map(|p| p.separation),
            hysteresis_energy: results.hysteresis_energy,
            rtol: plan.scene.accuracy.rtol,
            law_model_error: plan.law.measured_error.filter(|_| adhesive),
            seconds: results.seconds,
            evaluations: results.evaluations,
            montecarlo: results.montecarlo.as_ref().map(|m| {
                // A standard error only where enough summits are in contact.
                let min = crate::study::run::MIN_SUMMITS_FOR_Z as f64;
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
                let seeds: Vec<f64> = m
                    .pull_off
                    .map(|p| p.load)
                    .into_iter()
                    .chain(m.seed_pull_offs.iter().filter_map(|s| s.1))
                    .collect();
                let (mean, std) = mean_std(&seeds);
                McSummary {
                    pull_off_other_seeds: m.seed_pull_offs.iter().map(|s| s.1).collect(),
                    pull_off_seed_mean: mean,
                    pull_off_seed_std: std,
                    states_without_standard_error: m
                        .contacts
                        .iter()
                        .filter(|&&c| c < crate::study::run::MIN_SUMMITS_FOR_Z as f64)
                        .count(),
                    summits: plan.montecarlo.as_ref().map_or(0, |p| p.summits),
                    seed: plan.montecarlo.as_ref().map_or(0, |p| p.spec.seed),
                    max_load: top.map(|t| t.0),
                    max_load_standard_error: top.and_then(|t| t.1),
                    pull_off_load: m.pull_off.map(|p| p.load),
                    integral_sampled_pull_off_load: results
                        .curve
                        .sampled_pull_off()
                        .map(|p| p.load),
                    max_abs_z: m.max_abs_z,
                    seconds: m.seconds,
                    spots: m.spots.map(|s| SampleSpotsSummary {
                        count: s.spots,
                        side_m: plan
                            .montecarlo
                            .as_ref()
                            .map_or(f64::NAN, |p| (plan.surface.nominal_area / p.factor).sqrt()),
                        parallel_ohm: s.parallel,
                        greenwood_ohm: s.greenwood,
                        exact_ohm: s.exact,
                    }),
                }
            }),
            plan: plan.decisions.iter().map(|d| d.to_string()).collect(),
            resistance_ohm: if plan.scene.outputs.resistance {
                closest.and_then(|s| resistance_of(plan, s))
            } else {
                None
            },
            heating: plan.heating.map(|(i, h)| {
                let r = closest.and_then(|s| resistance_of(plan, s));
                HeatingSummary {
                    current_a: i,
                    bulk_temperature_k: h.bulk_temperature(),
                    contact_voltage_v: r.map(|r| i * r),
                    max_temperature_k: r.and_then(|r| h.max_temperature_at(i, r).ok()),
                }
            }),
            plasticity: plan.plasticity.map(|p| {
                let f = results.regimes.filter(|f| f.contacts_per_summit > 0.0);
                PlasticitySummary {
                    plasticity_index: crate::material::plastic::plasticity_index(
                        plan.contact.contact_modulus,
                        p.hardness(),
                        plan.surface.sigma,
                        plan.surface.radius,
                    ),
                    hardness_pa: p.hardness(),
                    elastic_fraction: f.map(|f| f.elastic),
                    elastic_plastic_fraction: f.map(|f| f.elastic_plastic),
                    fully_plastic_fraction: f.map(|f| f.fully_plastic),
                }
            }),
            stiction: results.stiction.map(|s| StictionSummary {
                pull_off_n: s.pull_off,
                restoring_force_n: s.restoring_force,
                margin_n: s.margin,
                sticks: s.sticks,
            }),
            states: plan.listed.as_ref().map(|_| {
                results
                    .listed
                    .iter()
                    .map(|s| StateRow {
                        separation_m: s.separation,
                        load_n: s.load(),
                        real_area_m2: s.area(),
                        contacts: s.count(),
                        resistance_ohm: plan.resistance.as_ref().map(|_| resistance_of(plan, s)),
                        contact_voltage_v: plan
                            .heating
                            .map(|(i, _)| resistance_of(plan, s).map(|r| i * r)),
                        max_temperature_k: plan.heating.map(|(i, h)| {
                            resistance_of(plan, s).and_then(|r| h.max_temperature_at(i, r).ok())
                        }),
                    })
                    .collect()
            }),
            warnings: plan
                .warnings
                .iter()
                .chain(&results.warnings)
                .cloned()
                .collect(),
            topography: topography::summary(plan, results),
        }
    }

    /// Pretty JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default()
    }
}

/// The contact resistance of a state (Ohm), with `[electrical]`; `None`
/// without contact.
pub fn resistance_of(plan: &Plan, state: &State) -> Option<f64> {
    let r = plan
        .resistance
        .as_ref()?
        .resistance(&plan.curve_outputs, &state.totals)?;
    r.resistance.is_finite().then_some(r.resistance)
}

/// The curve as CSV: one row per separation and leg, columns
/// `leg,separation_m,load_N,area_m2,count` (empty cells for outputs not
/// computed), approach rows from far to near, then retraction rows from
/// near to far (the order of the program).
pub fn curve_csv(results: &Results, plan: &Plan) -> String {
    let o = plan.scene.outputs;
    let mut out = String::from("leg,separation_m,load_N,area_m2,count");
    out.push_str(if o.resistance {
        ",resistance_ohm\n"
    } else {
        "\n"
    });
    let cell = |x: Option<f64>, asked: bool| match x {
        Some(v) if asked => format!("{v:e}"),
        _ => String::new(),
    };
    let mut row = |leg: &str, s: &State| {
        let _ = write!(
            out,
            "{leg},{:e},{},{},{}",
            s.separation,
            cell(s.load(), o.load),
            cell(s.area(), o.area),
            cell(s.count(), o.count)
        );
        if o.resistance {
            let _ = write!(out, ",{}", cell(resistance_of(plan, s), true));
        }
        out.push('\n');
    };
    for s in results.curve.approach.iter().rev() {
        row("approach", s);
    }
    for s in &results.curve.retract {
        row("retract", s);
    }
    out
}

/// Mean and sample standard deviation (divisor `n - 1`) of `x`; `None`
/// for the deviation with fewer than two values.
fn mean_std(x: &[f64]) -> (Option<f64>, Option<f64>) {
    if x.is_empty() {
        return (None, None);
    }
    let n = x.len() as f64;
    let mean = x.iter().sum::<f64>() / n;
    let std = (x.len() >= 2)
        .then(|| (x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt());
    (Some(mean), std)
}

/// The population's curve as CSV: `leg,separation_m,load_N,load_se_N,
/// area_m2,area_se_m2,count,count_se,z_load,z_area,z_count,contacts,note`
/// (standard errors and deviations from the integral in standard errors;
/// `contacts` is the population's summits in contact), in the order of
/// [`curve_csv`]. Where fewer than
/// [`crate::study::run::MIN_SUMMITS_FOR_Z`] summits are in contact the
/// standard-error and deviation cells are empty and `note` says why: a
/// standard error estimated from so few summits is not one (the central
/// limit does not hold; deviations of 30 "standard errors" appear).
pub fn montecarlo_csv(results: &Results) -> Option<String> {
    let m = results.montecarlo.as_ref()?;
    let mut out = String::from(
        "leg,separation_m,load_N,load_se_N,area_m2,area_se_m2,count,count_se,z_load,z_area,z_count,contacts,note\n",
    );
    let min = crate::study::run::MIN_SUMMITS_FOR_Z;
    let cell = |x: Option<f64>| x.map_or(String::new(), |v| format!("{v:e}"));
    let n = m.curve.approach.len();
    let rows = m
        .curve
        .approach
        .iter()
        .enumerate()
        .rev()
        .map(|(i, s)| ("approach", s, m.z[i], i))
        .chain(
            m.curve
                .retract
                .iter()
                .enumerate()
                .map(|(i, s)| ("retract", s, m.z[n + i], n + i)),
        );
    for (leg, s, z, k) in rows {
        let contacts = m.contacts.get(k).copied().unwrap_or(0.0);
        let honest = contacts >= min as f64;
        let se = |i: usize, x: Option<f64>| {
            cell(
                x.and_then(|_| s.totals.error(i))
                    .filter(|e| honest && e.is_finite()),
            )
        };
        let z = if honest {
            z
        } else {
            [None; crate::loading::SLOTS]
        };
        let note = if honest {
            String::new()
        } else {
            format!("no standard error: fewer than {min} summits in contact")
        };
        let _ = writeln!(
            out,
            "{leg},{:e},{},{},{},{},{},{},{},{},{},{contacts},{note}",
            s.separation,
            cell(s.load()),
            se(0, s.load()),
            cell(s.area()),
            se(1, s.area()),
            cell(s.count()),
            se(2, s.count()),
            cell(z[0]),
            cell(z[1]),
            cell(z[2])
        );
    }
    Some(out)
}
