//! The study layer's warnings as data: where a scene or its results lie
//! outside a model's validity, one [`Warning`] each, with the numbers and
//! names as fields, a stable code ([`Warning::code`]) and its sentence
//! ([`Warning`]'s `Display`). Plans and results carry them typed; they are
//! worded only at the edge: `summary.json` (`warnings`, the sentences, and
//! `warning_codes`, the codes in the same order), the text report, the
//! command line and the Python package (a warning serialises as its
//! sentence).
//!
//! Where a lower layer finds the warning (a measured map's pixel sizes and
//! units, the rough sphere's model, the spot heating relation, the
//! calibration cache, the SIMD request, an elastic law on yielding
//! summits), the variant wraps that layer's typed value, whose `Display` is
//! the sentence, beside the numbers the study layer has.

use crate::electrical::SpotWarning;
use crate::gw::validity::Finding;
use crate::law::plastic::ElasticLawYields;
use crate::numeric::simd::IgnoredRequest;
use crate::roughsphere::SphereWarning;
use crate::study::cache::BadEntry;
use crate::topography::{PixelSizeMismatch, UnitWarning};
use serde::{Serialize, Serializer};
use std::fmt;

/// Which headline output a law's model error is of.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModelErrorOutput {
    /// The pull-off (N).
    PullOff,
    /// The load at the closest approach (N).
    MaxLoad,
    /// The hysteresis energy (J).
    HysteresisEnergy,
    /// The load at the listed state with the largest error (N).
    ListedLoad,
}

impl ModelErrorOutput {
    /// How the warning names it.
    pub fn name(self) -> &'static str {
        match self {
            ModelErrorOutput::PullOff => "pull-off",
            ModelErrorOutput::MaxLoad => "max load",
            ModelErrorOutput::HysteresisEnergy => "hysteresis energy",
            ModelErrorOutput::ListedLoad => "load at a listed state",
        }
    }

    /// Its unit.
    pub fn unit(self) -> &'static str {
        match self {
            ModelErrorOutput::HysteresisEnergy => "J",
            _ => "N",
        }
    }
}

/// One warning of a plan or a run.
#[derive(Debug, Clone, PartialEq)]
pub enum Warning {
    /// A GW validity finding that leaves the result possible but
    /// inaccurate ([`Finding`]; the impossible ones are errors).
    Validity(Finding),
    /// The hysteresis energy `energy` (J) is negative but within its
    /// tolerance `tolerance` (J): reported as 0.
    HysteresisZero {
        /// The energy computed (J).
        energy: f64,
        /// Its tolerance (J).
        tolerance: f64,
    },
    /// An elastic law on summits that yield: plasticity index `psi > 1`
    /// ([`crate::law::plastic::elastic_law_warning`]).
    ElasticLawYields(ElasticLawYields),
    /// Per-summit menisci with a Kelvin radius (m) below a molecular size.
    MeniscusMolecular {
        /// The Kelvin radius (m).
        kelvin_radius: f64,
    },
    /// The menisci merge: Kelvin radius above the summit radius or
    /// meniscus height above the summit-height spread (all m).
    MenisciMerge {
        /// The Kelvin radius (m).
        kelvin_radius: f64,
        /// The meniscus height (m).
        height: f64,
        /// The summit radius (m).
        radius: f64,
        /// The summit-height standard deviation (m).
        sigma: f64,
    },
    /// The rigid (Derjaguin) meniscus beside the law, off by `error` in
    /// the pull-off, above `rtol`.
    MeniscusRigid {
        /// Relative error of the pull-off against the elastic meniscus.
        error: f64,
        /// The scene's `rtol`.
        rtol: f64,
    },
    /// A calibration cache entry was bad and recomputed (its file and
    /// why).
    CalibrationCache(BadEntry),
    /// A measured map's pixel size given in the scene disagrees with the
    /// file's ([`crate::topography::pixel_sizes`]).
    MapPixelSize(PixelSizeMismatch),
    /// A measured map's heights or pixel sizes are probably in the wrong
    /// unit ([`crate::topography::unit_warnings`]; one code for the height
    /// and the length unit).
    MapUnits(UnitWarning),
    /// `ASPERITY_SIMD` was not followed
    /// ([`crate::numeric::simd::ignored_request`]).
    SimdNotFollowed(IgnoredRequest),
    /// `law.kind = "auto"`: the full-solver law failed; the results are the
    /// analytic law's.
    AutoLawFailed {
        /// The failure.
        error: crate::Error,
    },
    /// A law's model error above
    /// [`MODEL_ERROR_WARN`](crate::study::model_error::MODEL_ERROR_WARN)
    /// against the full Lennard-Jones solver's law on the same surface.
    ModelError {
        /// Which output.
        output: ModelErrorOutput,
        /// The law's name.
        law: String,
        /// Relative difference from the reference.
        error: f64,
        /// The reference value (the output's unit), when known.
        reference: Option<f64>,
        /// Whether the advice names only `calibrated` (the planner's
        /// decision, [`Plan::advises_calibrated_only`](crate::study::Plan::advises_calibrated_only):
        /// the scene's `law.kind` is `auto`).
        auto: bool,
    },
    /// GW's `quantity` on a measured map differs from the exact elastic
    /// solution beyond `limit`.
    MapModelError {
        /// The output as the warning names it (`real contact area`, ...).
        quantity: &'static str,
        /// Its summary key (`model_error.area`, ...).
        key: &'static str,
        /// The largest relative difference.
        difference: f64,
        /// Its mean pressure (Pa).
        pressure: f64,
        /// Its state (index from 0).
        state: usize,
        /// States compared.
        states: usize,
        /// The limit (relative).
        limit: f64,
        /// States beyond the limit.
        beyond: usize,
    },
    /// GW's pull-off on a measured map differs from the adhesive boundary
    /// elements' beyond [`WARN_ABOVE`](crate::study::map_error::WARN_ABOVE).
    MapPullOff {
        /// Relative difference.
        difference: f64,
        /// GW's pull-off (N).
        gw: f64,
        /// The exact pull-off (N).
        exact: f64,
    },
    /// The retraction ends at the program's start with the load still at
    /// its most tensile.
    PullOffAtStart {
        /// The start separation (m).
        separation: f64,
        /// The load there (N).
        load: f64,
    },
    /// The populations' pull-off and the integral's disagree.
    PopulationDisagrees {
        /// The integral's pull-off (N), when tensile.
        integral: Option<f64>,
        /// Expected summits carrying the tension at the integral's
        /// pull-off.
        carriers: Option<f64>,
        /// Summits of each population.
        summits: usize,
        /// The populations' mean pull-off (N).
        mean: f64,
        /// Its standard error (N).
        standard_error: f64,
        /// The 5 % quantile (N).
        p05: f64,
        /// The 95 % quantile (N).
        p95: f64,
        /// Populations drawn.
        populations: usize,
    },
    /// Too few populations for an interval of the 5 % and 95 % quantiles.
    PopulationIntervals {
        /// Populations drawn.
        populations: usize,
        /// The intervals' confidence.
        confidence: f64,
        /// Populations needed.
        needed: usize,
    },
    /// Too few populations to resolve the switch's `1 - confidence`
    /// quantile.
    PopulationConfidence {
        /// `switch.confidence`.
        confidence: f64,
        /// Populations drawn.
        populations: usize,
        /// Populations needed, `ceil(1/(1 - confidence))`.
        needed: f64,
    },
    /// Spots of the Monte Carlo sample merged where they overlapped.
    SpotsMerged {
        /// Spots merged into others.
        merged: usize,
        /// Spots left.
        spots: usize,
    },
    /// Spots soften or melt under the scene's current at the reported
    /// states; the hottest at separation `separation`.
    SpotHeating {
        /// `electrical.current` (A).
        current: f64,
        /// The hottest reported state's separation (m).
        separation: f64,
        /// What the hottest spot does at its voltage (softens or melts,
        /// [`crate::electrical::Heating::warning`]; one code for both).
        spot: SpotWarning,
        /// Reported states beyond softening.
        beyond: usize,
        /// Reported states.
        reported: usize,
    },
    /// Greenwood's interaction left out at `states` states with fewer than
    /// 2 expected contacts.
    GreenwoodSkipped {
        /// States where it was left out.
        states: usize,
    },
    /// The rough sphere's own warning at the closest approach
    /// ([`crate::roughsphere::SphereState::warnings`]; one code for all
    /// its kinds).
    RoughSphere(SphereWarning),
}

/// Every code [`Warning::code`] gives, each once.
pub const CODES: [&str; 28] = [
    "eta-r-sigma",
    "contact-radius",
    "deeper-than-radius",
    "area-fraction",
    "area-above-nominal",
    "resolution",
    "hysteresis-energy-zero",
    "elastic-law-yields",
    "meniscus-molecular",
    "menisci-merge",
    "meniscus-rigid",
    "calibration-cache-recomputed",
    "map-pixel-size",
    "map-units",
    "simd-not-followed",
    "auto-law-failed",
    "model-error",
    "map-model-error",
    "map-pull-off-error",
    "pull-off-at-start",
    "pull-off-population-disagrees",
    "pull-off-population-intervals",
    "pull-off-population-confidence",
    "montecarlo-spots-merged",
    "spot-heating",
    "greenwood-interaction-skipped",
    "rough-sphere",
    "listed-state-model-error",
];

impl Warning {
    /// Its stable code: kebab-case, one per kind of warning (a validity
    /// finding's by its kind; a model error at a listed state has its own),
    /// listed in [`CODES`].
    pub fn code(&self) -> &'static str {
        match self {
            Warning::Validity(f) => match f {
                Finding::EtaRSigma { .. } => "eta-r-sigma",
                Finding::ContactRadius { .. } => "contact-radius",
                Finding::DeeperThanRadius { .. } => "deeper-than-radius",
                Finding::AreaFraction { .. } => "area-fraction",
                Finding::AreaAboveNominal { .. } => "area-above-nominal",
                Finding::Resolution { .. } => "resolution",
            },
            Warning::HysteresisZero { .. } => "hysteresis-energy-zero",
            Warning::ElasticLawYields(_) => "elastic-law-yields",
            Warning::MeniscusMolecular { .. } => "meniscus-molecular",
            Warning::MenisciMerge { .. } => "menisci-merge",
            Warning::MeniscusRigid { .. } => "meniscus-rigid",
            Warning::CalibrationCache(_) => "calibration-cache-recomputed",
            Warning::MapPixelSize(_) => "map-pixel-size",
            Warning::MapUnits(_) => "map-units",
            Warning::SimdNotFollowed(_) => "simd-not-followed",
            Warning::AutoLawFailed { .. } => "auto-law-failed",
            Warning::ModelError {
                output: ModelErrorOutput::ListedLoad,
                ..
            } => "listed-state-model-error",
            Warning::ModelError { .. } => "model-error",
            Warning::MapModelError { .. } => "map-model-error",
            Warning::MapPullOff { .. } => "map-pull-off-error",
            Warning::PullOffAtStart { .. } => "pull-off-at-start",
            Warning::PopulationDisagrees { .. } => "pull-off-population-disagrees",
            Warning::PopulationIntervals { .. } => "pull-off-population-intervals",
            Warning::PopulationConfidence { .. } => "pull-off-population-confidence",
            Warning::SpotsMerged { .. } => "montecarlo-spots-merged",
            Warning::SpotHeating { .. } => "spot-heating",
            Warning::GreenwoodSkipped { .. } => "greenwood-interaction-skipped",
            Warning::RoughSphere(_) => "rough-sphere",
        }
    }

    /// The codes of `warnings`, in order.
    pub fn codes<'a>(warnings: impl IntoIterator<Item = &'a Warning>) -> Vec<&'static str> {
        warnings.into_iter().map(Warning::code).collect()
    }
}

impl fmt::Display for Warning {
    // One match over the kinds of warning, each arm its sentence as the
    // study layer wrote it before it was typed (the longest in functions).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Warning::Validity(finding) => write!(f, "{finding}"),
            Warning::HysteresisZero { energy, tolerance } => write!(
                f,
                "hysteresis energy: {energy:.3e} J is zero within its tolerance {tolerance:.3e} \
                 J; reported as 0"
            ),
            Warning::ElasticLawYields(w) => write!(f, "{w}"),
            Warning::CalibrationCache(w) => write!(f, "{w}"),
            Warning::MapPixelSize(w) => write!(f, "{w}"),
            Warning::MapUnits(w) => write!(f, "{w}"),
            Warning::SimdNotFollowed(w) => write!(f, "{w}"),
            Warning::MeniscusMolecular { kelvin_radius } => write!(
                f,
                "adhesion.relative_humidity: the Kelvin radius {kelvin_radius:.3e} m is below a \
                 molecular size (0.2 nm): the continuum Kelvin equation does not hold, the \
                 menisci are adsorbed layers a molecule thick"
            ),
            Warning::MenisciMerge {
                kelvin_radius,
                height,
                radius,
                sigma,
            } => write!(
                f,
                "adhesion.relative_humidity: the menisci merge (Kelvin radius {kelvin_radius:.3e} \
                 m, meniscus height {height:.3e} m, against the summit radius {radius:.3e} m and \
                 the summit-height standard deviation {sigma:.3e} m): per-summit menisci no \
                 longer hold and the interface floods (the flooded model, Laplace pressure on the \
                 area where the gap is below the meniscus height, applies instead)"
            ),
            Warning::MeniscusRigid { error, rtol } => write!(
                f,
                "adhesion.relative_humidity: the menisci are in their rigid (Derjaguin) form \
                 beside this law, off by {error:.2e} in the pull-off against the elastic meniscus \
                 (above rtol = {rtol:e})"
            ),
            Warning::AutoLawFailed { error } => write!(
                f,
                "law.kind = \"auto\": the full-solver law, which the model error above asks for, \
                 failed on this scene ({error}); the results are the analytic law's"
            ),
            Warning::ModelError {
                output,
                law,
                error,
                reference,
                auto,
            } => model_error(f, *output, law, *error, *reference, *auto),
            Warning::MapModelError { .. } => map_model_error(f, self),
            Warning::MapPullOff {
                difference,
                gw,
                exact,
            } => write!(
                f,
                "model error: GW's pull-off on this map differs from the adhesive boundary-element \
                 solution of the same map by {:+.1} % (GW {gw:.4e} N, exact {exact:.4e} N; \
                 model_error.pull_off; what differs: model_error.pull_off_map.differences)",
                100.0 * difference
            ),
            Warning::PullOffAtStart { separation, load } => write!(
                f,
                "pull-off: the retraction ends at program.start_separation = {separation:e} m \
                 with the load still at its most tensile ({load:.3e} N): the contact has not \
                 pulled off within the program, and the true pull-off lies further out (start \
                 further out, or leave start_separation unset for the law's reach)"
            ),
            Warning::PopulationDisagrees { .. } => population_disagrees(f, self),
            Warning::PopulationIntervals { .. } | Warning::PopulationConfidence { .. } => {
                population_quantiles(f, self)
            }
            Warning::SpotsMerged { merged, spots } => write!(
                f,
                "montecarlo spots: {merged} spots overlapped others at their random positions and \
                 were merged into spots of their joint area ({spots} spots remain)"
            ),
            Warning::SpotHeating {
                current,
                separation,
                spot,
                beyond,
                reported,
            } => write!(
                f,
                "electrical.current = {current:e} A at d = {separation:.4e} m: {spot} ({beyond} \
                 of the {reported} reported states, the closest approach and the listed ones, are \
                 beyond softening; electrical.softening_temperature and melting_temperature set \
                 the metal, gold's by default)"
            ),
            Warning::GreenwoodSkipped { states } => write!(
                f,
                "electrical.interaction = \"greenwood\": left out at {states} states where fewer \
                 than 2 contacts are expected (the mean field needs several spots)"
            ),
            Warning::RoughSphere(w) => write!(f, "rough sphere at the closest approach: {w}"),
        }
    }
}

/// [`Warning::ModelError`]'s sentence.
fn model_error(
    f: &mut fmt::Formatter<'_>,
    output: ModelErrorOutput,
    law: &str,
    error: f64,
    reference: Option<f64>,
    auto: bool,
) -> fmt::Result {
    let advice = if auto {
        "law.kind = \"calibrated\" uses the full-solver law"
    } else {
        "law.kind = \"calibrated\" (or \"auto\") uses the full-solver law"
    };
    let reference = reference.map_or(String::new(), |r| format!(" ({r:.4e} {})", output.unit()));
    write!(
        f,
        "model error: the {} of law {law} differs by {:.1} % from the full \
         Lennard-Jones solver's law on this surface{reference}; {advice}",
        output.name(),
        100.0 * error,
    )
}

/// [`Warning::MapModelError`]'s sentence (nothing for another kind).
fn map_model_error(f: &mut fmt::Formatter<'_>, w: &Warning) -> fmt::Result {
    let Warning::MapModelError {
        quantity,
        key,
        difference,
        pressure,
        state,
        states,
        limit,
        beyond,
    } = w
    else {
        return Ok(());
    };
    write!(
        f,
        "model error: GW's {quantity} on this map differs from the exact elastic \
         solution by {:+.1} % at p = {pressure:.4e} Pa (state {} of {states}; beyond \
         {:.0} % at {beyond} of {states} states, {key})",
        100.0 * difference,
        state + 1,
        100.0 * limit,
    )
}

/// [`Warning::PopulationDisagrees`]'s sentence (nothing for another kind).
fn population_disagrees(f: &mut fmt::Formatter<'_>, w: &Warning) -> fmt::Result {
    let Warning::PopulationDisagrees {
        integral,
        carriers,
        summits,
        mean,
        standard_error,
        p05,
        p95,
        populations,
    } = w
    else {
        return Ok(());
    };
    let integral_text = match integral {
        Some(p) => {
            format!("the integral gives {p:.3e} N, the minimum of the mean load curve")
        }
        None => "the integral's mean load is never tensile on retraction".into(),
    };
    let carriers = match carriers {
        Some(c) => {
            format!("only {c:.3} summits carry the tension at the integral's pull-off")
        }
        None => "no summit carries a tensile mean load".into(),
    };
    write!(
        f,
        "pull-off: {integral_text}; one switch of {summits} summits pulls off at \
         {mean:.3e} N on average (standard error {standard_error:.1e} N; 5 %-95 %: \
         {p05:.3e} .. {p95:.3e} N over {populations} populations): {carriers}, so \
         each switch's pull-off is that of its own highest summits, not of the mean \
         surface"
    )
}

/// [`Warning::PopulationIntervals`]' and [`Warning::PopulationConfidence`]'s
/// sentences (nothing for another kind).
fn population_quantiles(f: &mut fmt::Formatter<'_>, w: &Warning) -> fmt::Result {
    match w {
        Warning::PopulationIntervals {
            populations,
            confidence,
            needed,
        } => write!(
            f,
            "pull-off population: {populations} populations are too few for a {:.0} % \
             interval of the 5 % and 95 % quantiles (p05_interval_N, p95_interval_N are \
             null; {needed} are needed, montecarlo.seeds)",
            100.0 * confidence
        ),
        Warning::PopulationConfidence {
            confidence,
            populations,
            needed,
        } => write!(
            f,
            "pull-off population: switch.confidence = {confidence} asks for the pull-off only \
             {:.3} % of switches exceed, but {populations} populations cannot resolve it (at \
             least {needed:.0} are needed): its quantile is interpolated between the two most \
             tensile pull-offs drawn, not resolved",
            100.0 * (1.0 - confidence)
        ),
        _ => Ok(()),
    }
}

impl Serialize for Warning {
    /// As its sentence (`Display`).
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One warning of every kind.
    fn one_of_each() -> Vec<Warning> {
        let findings = [
            Finding::EtaRSigma { value: 0.15 },
            Finding::ContactRadius {
                depth: 1e-8,
                ratio: 0.4,
                from_law: false,
            },
            Finding::DeeperThanRadius {
                depth: 1e-6,
                top: 1e-6,
                closest: -1e-6,
            },
            Finding::AreaFraction { fraction: 0.2 },
            Finding::AreaAboveNominal { fraction: 2.0 },
            Finding::Resolution {
                inside: 3.0,
                points: 20,
                onset: 1e-8,
                start: 1e-7,
            },
        ];
        let model_error = |output| Warning::ModelError {
            output,
            law: "jkr".into(),
            error: 0.2,
            reference: Some(1e-6),
            auto: false,
        };
        findings
            .into_iter()
            .map(Warning::Validity)
            .chain([
                Warning::HysteresisZero {
                    energy: -1e-30,
                    tolerance: 1e-20,
                },
                Warning::ElasticLawYields(ElasticLawYields {
                    law: "jkr".into(),
                    psi: 2.0,
                }),
                Warning::MeniscusMolecular {
                    kelvin_radius: 1e-10,
                },
                Warning::MenisciMerge {
                    kelvin_radius: 1e-6,
                    height: 1e-6,
                    radius: 1e-7,
                    sigma: 1e-8,
                },
                Warning::MeniscusRigid {
                    error: 0.1,
                    rtol: 1e-3,
                },
                Warning::CalibrationCache(BadEntry {
                    path: "entry.json".into(),
                    why: crate::study::cache::BadReason::Checksum,
                }),
                Warning::MapPixelSize(PixelSizeMismatch {
                    name: "surface.pixel_size".into(),
                    given: 1e-7,
                    file: (2e-7, 2e-7),
                }),
                Warning::MapUnits(UnitWarning::PixelAbove {
                    axis: 'x',
                    size: 5e-3,
                }),
                Warning::SimdNotFollowed(IgnoredRequest {
                    wanted: "avx1".into(),
                    used: "scalar",
                }),
                Warning::AutoLawFailed {
                    error: crate::Error::invalid("law.kind", "text"),
                },
                model_error(ModelErrorOutput::PullOff),
                Warning::MapModelError {
                    quantity: "mean gap",
                    key: "model_error.mean_gap",
                    difference: 0.2,
                    pressure: 1e6,
                    state: 0,
                    states: 3,
                    limit: 0.1,
                    beyond: 1,
                },
                Warning::MapPullOff {
                    difference: 0.2,
                    gw: -1e-6,
                    exact: -1.2e-6,
                },
                Warning::PullOffAtStart {
                    separation: 1e-7,
                    load: -1e-6,
                },
                Warning::PopulationDisagrees {
                    integral: None,
                    carriers: None,
                    summits: 100,
                    mean: -1e-6,
                    standard_error: 1e-8,
                    p05: -2e-6,
                    p95: -1e-7,
                    populations: 40,
                },
                Warning::PopulationIntervals {
                    populations: 10,
                    confidence: 0.9,
                    needed: 45,
                },
                Warning::PopulationConfidence {
                    confidence: 0.99,
                    populations: 10,
                    needed: 100.0,
                },
                Warning::SpotsMerged {
                    merged: 2,
                    spots: 10,
                },
                Warning::SpotHeating {
                    current: 0.1,
                    separation: 1e-9,
                    spot: SpotWarning::Molten {
                        voltage: 1.0,
                        melting_voltage: 0.43,
                        melting_temperature: 1337.33,
                    },
                    beyond: 1,
                    reported: 2,
                },
                Warning::GreenwoodSkipped { states: 3 },
                Warning::RoughSphere(SphereWarning::InteractionSkipped),
                model_error(ModelErrorOutput::ListedLoad),
            ])
            .collect()
    }

    #[test]
    fn every_kind_has_its_own_kebab_case_code() {
        let codes = Warning::codes(&one_of_each());
        // one example per code, in the order of CODES: every code is given
        // and no two kinds share one
        assert_eq!(codes, CODES);
        let mut sorted = codes.clone();
        sorted.sort_unstable();
        sorted.dedup();
        assert_eq!(sorted.len(), CODES.len(), "{codes:?}");
        for c in codes {
            let kebab = !c.is_empty()
                && !c.starts_with('-')
                && !c.ends_with('-')
                && !c.contains("--")
                && c.chars().all(|x| x.is_ascii_lowercase() || x == '-');
            assert!(kebab, "{c}");
        }
    }

    #[test]
    fn a_warning_serialises_as_its_sentence() {
        let w = Warning::GreenwoodSkipped { states: 132 };
        assert_eq!(
            serde_json::to_value(&w).unwrap(),
            serde_json::Value::String(
                "electrical.interaction = \"greenwood\": left out at 132 states where fewer than \
                 2 contacts are expected (the mean field needs several spots)"
                    .into()
            )
        );
        assert_eq!(w.code(), "greenwood-interaction-skipped");
    }

    /// The sentences of the lower layers' typed warnings, byte for byte as
    /// those layers worded them before they were typed (the strings below
    /// are the earlier formats' output, several copied from the command
    /// line's and the example scenes' stderr).
    #[test]
    fn the_lower_layers_sentences_are_unchanged() {
        use crate::study::cache::BadReason;
        let heating = crate::electrical::Heating::new(293.15).unwrap();
        let cases = [
            (
                Warning::ElasticLawYields(ElasticLawYields {
                    law: "dmt".into(),
                    psi: 8.5641,
                }),
                "plasticity index psi = 8.564 > 1: most contacts yield, but the law dmt is elastic \
                 (it over-predicts the load at a given area); consider kogut-etsion or \
                 jackson-green",
            ),
            (
                Warning::CalibrationCache(BadEntry {
                    path: "/c/e.json".into(),
                    why: BadReason::Checksum,
                }),
                "calibration cache entry /c/e.json fails its checksum (altered or damaged): \
                 recomputed and stored again",
            ),
            (
                Warning::CalibrationCache(BadEntry {
                    path: "/c/e.json".into(),
                    why: BadReason::Unreadable("Permission denied (os error 13)".into()),
                }),
                "calibration cache entry /c/e.json cannot be read (Permission denied (os error \
                 13)): recomputed and stored again",
            ),
            (
                Warning::MapPixelSize(PixelSizeMismatch {
                    name: "--pixel-size".into(),
                    given: 6e-8,
                    file: (5e-8, 5e-8),
                }),
                "--pixel-size = 6e-8 m disagrees with the file's pixels of 5e-8 m (x) by 5e-8 m \
                 (y) beyond 1e-9 relative: using --pixel-size; omit it to trust the file",
            ),
            (
                Warning::MapUnits(UnitWarning::RmsHeight {
                    rms_height: 4.9937e-5,
                    height_unit: "--height-unit".into(),
                    scale: "--scale".into(),
                }),
                "the RMS height 4.994e-5 m is above 10 um: the height unit is probably wrong, \
                 heights in mm (4.994e-8 m) read as m? (give --height-unit, or --scale)",
            ),
            (
                Warning::MapUnits(UnitWarning::PixelAbove {
                    axis: 'x',
                    size: 5e-3,
                }),
                "the pixel size along x, 5.000e-3 m, is above 1 mm: the length unit is probably \
                 wrong, a size in mm (5.000e-6 m) or um (5.000e-9 m) read as m?",
            ),
            (
                Warning::MapUnits(UnitWarning::PixelBelow {
                    axis: 'y',
                    size: 1e-11,
                }),
                "the pixel size along y, 1.000e-11 m, is below 0.1 nm: the length unit is \
                 probably wrong, a size in m (1.000e-5 m if it was in um, 1.000e-2 m if in nm) \
                 converted once more?",
            ),
            (
                Warning::SimdNotFollowed(IgnoredRequest {
                    wanted: "bogus".into(),
                    used: "avx512",
                }),
                "ASPERITY_SIMD=bogus not followed (allowed: avx2, scalar, avx512, native, or \
                 unset for the widest set the CPU has): the vector passes ran on avx512 (the \
                 numbers are the same at every width, only the time differs)",
            ),
            (
                Warning::AutoLawFailed {
                    error: crate::Error::invalid("materials", "no"),
                },
                "law.kind = \"auto\": the full-solver law, which the model error above asks \
                 for, failed on this scene (materials: no); the results are the analytic law's",
            ),
            (
                Warning::SpotHeating {
                    current: 0.1,
                    separation: 1e-9,
                    spot: heating.warning(0.1).unwrap().unwrap(),
                    beyond: 1,
                    reported: 2,
                },
                "electrical.current = 1e-1 A at d = 1.0000e-9 m: the contact voltage 1.0000e-1 V \
                 is above the softening voltage 0.0722 V (softening temperature 373.15 K): the \
                 spot softens at 433.9 K and grows, so the resistance at this load and the \
                 temperature from it no longer hold (1 of the 2 reported states, the closest \
                 approach and the listed ones, are beyond softening; \
                 electrical.softening_temperature and melting_temperature set the metal, gold's \
                 by default)",
            ),
            (
                Warning::RoughSphere(SphereWarning::AreaFraction { fraction: 0.92 }),
                "rough sphere at the closest approach: model: the real-area fraction at the \
                 centre is 0.92 (> 0.1): GW's independent summits overstate the stiffness of the \
                 rough layer there",
            ),
        ];
        for (w, sentence) in cases {
            assert_eq!(w.to_string(), sentence);
        }
        assert_eq!(
            heating.warning(10.0).unwrap().unwrap().to_string(),
            "the contact voltage 1.0000e1 V is above the melting voltage 0.4079 V (melting \
             temperature 1337.33 K): the spot melts; Holm's relation gives no temperature above \
             melting, so none is reported"
        );
    }
}
