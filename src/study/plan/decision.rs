//! The planner's decisions as data; [`fmt::Display`] renders them at the edge
//! (`asperity run --plan`, the summary's `plan` list).

use std::fmt;

/// How a total is obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Evaluation {
    /// `F_n` closed forms.
    ClosedForm,
    /// Exact sums over a finite sample of measured heights.
    SampleSum,
    /// Adaptive Gauss–Kronrod quadrature.
    Quadrature,
    /// Not computed.
    Skipped,
}

/// Why a total is (not) computed the way it is.
#[derive(Debug, Clone, PartialEq)]
pub enum OutputReason {
    /// Asked for; the method's own justification follows from the law and
    /// distribution names.
    Asked {
        /// The law's name.
        law: String,
        /// The distribution's name.
        distribution: String,
        /// The scene's tolerance.
        rtol: f64,
    },
    /// Everything-on mode.
    EverythingOn,
    /// Not asked for, but the hysteresis energy needs the load.
    NeededByHysteresis,
    /// Not asked for.
    NotAsked,
}

/// Why the law is the one chosen.
#[derive(Debug, Clone, PartialEq)]
pub enum LawReason {
    /// `w = 0`: Hertz.
    NoAdhesion,
    /// Everything-on mode: exact Maugis–Dugdale.
    EverythingOn,
    /// The cheapest law within `rtol` of the full solution (measured error).
    CheapestWithin {
        /// The scene's tolerance.
        rtol: f64,
        /// The law's measured error.
        error: f64,
        /// Where the measurement comes from.
        provenance: String,
    },
    /// No analytic law within `rtol`; the closest one.
    NoneWithin {
        /// The scene's tolerance.
        rtol: f64,
        /// The closest law's measured error.
        error: f64,
    },
    /// Named in the scene.
    Given,
    /// `auto` with a yield strength: Kogut–Etsion (the error table measures
    /// elastic laws only, and an elastic law ignores the yield strength).
    AutoPlastic,
    /// Named in the scene; its adhesion is left out because the JKR
    /// interference scale (m) is far below the tolerance.
    AdhesionNegligible {
        /// `(pi^2 w^2 R/K^2)^(1/3)` (m).
        jkr_scale: f64,
    },
    /// Menisci at `adhesion.relative_humidity` beside the dry law: the
    /// exact two-zone law (meniscus and solid Dugdale zones on one elastic
    /// sphere) or the dry law with the rigid (Derjaguin) meniscus beside it,
    /// whichever the model-error rule picks.
    Meniscus {
        /// The dry law's name.
        dry: String,
        /// Whether the exact two-zone law was built.
        exact: bool,
        /// Pull-off error of the Derjaguin meniscus against the elastic one
        /// (relative), if `lambda_m` is in the Maugis–Dugdale range.
        error: Option<f64>,
        /// The scene's tolerance (the law-choice share).
        rtol: f64,
        /// Kelvin radius `r_K` (m).
        kelvin_radius: f64,
        /// Meniscus height `h_m` (m).
        height: f64,
    },
    /// The full-solver law, from the on-disk cache or computed at run time.
    Calibrated {
        /// Whether the cache already holds it.
        cached: bool,
        /// The cache file.
        path: String,
        /// Chosen by `auto` because no analytic law meets `rtol`: the
        /// tolerance, the closest analytic law and its measured error.
        auto: Option<(f64, String, f64)>,
        /// Chosen by `auto` after the run: the analytic law met `rtol` for
        /// one summit but missed it on the scene's surface; the tolerance,
        /// that law, the output and its measured relative error there.
        surface: Option<(f64, String, String, f64)>,
    },
}

/// Why the program starts where it does.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StartReason {
    /// Given in the scene.
    Given,
    /// Summits beyond the flat's reach carry less than this fraction.
    TailFraction(f64),
    /// Everything-on mode: the last representable summit.
    EverythingOn,
}

/// One decision of a plan.
#[derive(Debug, Clone, PartialEq)]
pub enum Decision {
    /// The law.
    Law {
        /// Its name.
        name: String,
        /// Why.
        reason: LawReason,
        /// Tabor parameter of one summit.
        mu: f64,
        /// Maugis parameter.
        lambda: f64,
    },
    /// How one total is obtained.
    Output {
        /// `"load"`, `"area"` or `"count"`.
        observable: &'static str,
        /// The method.
        evaluation: Evaluation,
        /// Why.
        reason: OutputReason,
    },
    /// Where the program starts (m).
    Start {
        /// The separation (m).
        separation: f64,
        /// Why.
        reason: StartReason,
    },
    /// An expensive law replaced for the run by a Chebyshev table.
    Tabulation {
        /// The law's name.
        law: String,
        /// Relative tolerance of the table.
        tolerance: f64,
        /// Interference interval covered (m).
        interval: (f64, f64),
    },
    /// Whether the retraction leg is computed.
    Retraction {
        /// Computed (else copied from the approach).
        computed: bool,
        /// Attach and detach interferences (m) when they differ.
        hysteresis: Option<(f64, f64)>,
        /// The law's name.
        law: String,
    },
    /// Whether the pull-off is searched for.
    PullOff {
        /// Searched.
        searched: bool,
        /// Asked for in the scene.
        asked: bool,
        /// The contact is adhesive.
        adhesive: bool,
    },
    /// Whether the hysteresis energy is integrated.
    HysteresisEnergy {
        /// Computed.
        computed: bool,
    },
    /// An explicit population beside the integral.
    MonteCarlo {
        /// Summits drawn.
        summits: usize,
        /// Seed.
        seed: u64,
        /// The distribution's name.
        distribution: String,
        /// Log standard deviation of lognormal radii (0: fixed radius).
        radius_log_std: f64,
        /// `eta A_n / summits`.
        factor: f64,
    },
    /// The plasticity index of the surface (materials give a yield
    /// strength or hardness).
    Plasticity {
        /// `psi = (E*/H) sqrt(sigma/R)`.
        psi: f64,
        /// Hardness `H` (Pa).
        hardness: f64,
        /// Whether the law is elastic-plastic.
        plastic_law: bool,
    },
    /// How the contact resistance is computed.
    Resistance {
        /// Spreading model name.
        spreading: &'static str,
        /// Whether Greenwood's interaction term is added.
        greenwood: bool,
        /// Whether a film resistance is added.
        film: bool,
        /// Over a rough sphere's bump (the interaction over its apparent
        /// area, per state), not a square nominal area.
        bump: bool,
    },
    /// The states listed in `[program]`.
    Listed {
        /// How many.
        count: usize,
        /// Whether they are loads (else separations).
        loads: bool,
    },
    /// The pull-off distribution over populations of the surface's summits.
    PullOffPopulation {
        /// Populations asked for (0: none).
        seeds: usize,
        /// Summits of each.
        summits: usize,
        /// Why, in a sentence.
        why: String,
    },
    /// A rough sphere (`[sphere]`) on the scene's surface.
    Sphere {
        /// Sphere radius (m).
        radius: f64,
        /// Paraboloidal profile (else the exact sphere).
        paraboloid: bool,
        /// Greenwood–Tripp `mu`.
        mu: f64,
        /// The mesh extrapolation's relative tolerance on the load.
        tolerance: f64,
    },
    /// Which model of a measured map (`[surface] topography`).
    Topography {
        /// The choice, in a few words.
        choice: String,
        /// Why.
        why: String,
    },
}

impl Decision {
    /// What the decision is about.
    pub fn topic(&self) -> &str {
        match self {
            Decision::Law { .. } => "law",
            Decision::Output { observable, .. } => observable,
            Decision::Start { .. } => "start separation",
            Decision::Tabulation { .. } => "law evaluation",
            Decision::Retraction { .. } => "retraction",
            Decision::PullOff { .. } => "pull-off",
            Decision::HysteresisEnergy { .. } => "hysteresis energy",
            Decision::MonteCarlo { .. } => "montecarlo",
            Decision::Plasticity { .. } => "plasticity",
            Decision::Resistance { .. } => "resistance",
            Decision::Listed { .. } => "listed states",
            Decision::Topography { .. } => "topography",
            Decision::PullOffPopulation { .. } => "pull-off spread",
            Decision::Sphere { .. } => "rough sphere",
        }
    }

    /// The choice, in a few words.
    pub fn choice(&self) -> String {
        match self {
            Decision::Law { name, .. } => name.clone(),
            Decision::Output { evaluation, .. } => match evaluation {
                Evaluation::ClosedForm => "closed form F_n",
                Evaluation::SampleSum => "exact sum over the sample",
                Evaluation::Quadrature => "adaptive Gauss-Kronrod",
                Evaluation::Skipped => "skipped",
            }
            .into(),
            Decision::Start { separation, .. } => format!("{separation:e} m"),
            Decision::Tabulation { .. } => "Chebyshev table".into(),
            Decision::Retraction { computed, .. } => if *computed {
                "computed"
            } else {
                "copied from approach"
            }
            .into(),
            Decision::PullOff { searched, .. } => {
                if *searched { "searched" } else { "skipped" }.into()
            }
            Decision::HysteresisEnergy { computed } => if *computed {
                "adaptive to rtol"
            } else {
                "skipped"
            }
            .into(),
            Decision::MonteCarlo { summits, seed, .. } => format!("{summits} summits, seed {seed}"),
            Decision::Plasticity { psi, .. } => format!("psi = {psi:.3}"),
            Decision::Resistance { spreading, .. } => format!("{spreading} spots"),
            Decision::Listed { count, loads } => {
                format!("{count} {}", if *loads { "loads" } else { "separations" })
            }
            Decision::Topography { choice, .. } => choice.clone(),
            Decision::Sphere { radius, .. } => format!("R = {radius:e} m"),
            Decision::PullOffPopulation { seeds, .. } => match seeds {
                0 => "none".into(),
                _ => format!("{seeds} populations"),
            },
        }
    }

    /// Why, in a sentence.
    pub fn why(&self) -> String {
        match self {
            Decision::Law {
                reason, mu, lambda, ..
            } => format!("{} [mu = {mu:.4}, lambda = {lambda:.4}]", law_why(reason, self)),
            Decision::Output {
                evaluation, reason, ..
            } => output_why(*evaluation, reason),
            Decision::Start { reason, .. } => match reason {
                StartReason::Given => "given in the scene".into(),
                StartReason::TailFraction(f) => format!(
                    "summits beyond the flat's reach there carry < rtol/100 = {f:e} of the heights: \
                     separations above it are skipped"
                ),
                StartReason::EverythingOn => {
                    "everything-on mode: from the last representable summit height".into()
                }
            },
            Decision::Tabulation {
                law,
                tolerance,
                interval: (lo, hi),
            } => format!(
                "exact {law} replaced by degree-6 Chebyshev interpolants to rtol/10 = {tolerance:e} on \
                 [{lo:.3e}, {hi:.3e}] m, built when the run starts (exact law outside)"
            ),
            Decision::Retraction {
                computed,
                hysteresis,
                law,
            } => match (computed, hysteresis) {
                (true, Some((a, d))) => format!(
                    "{law} asperities attach at {a:.3e} m and detach at {d:.3e} m: hysteresis"
                ),
                (true, None) => "everything-on mode".into(),
                (false, _) => format!("{law} has no hysteresis (attach = detach interference)"),
            },
            Decision::PullOff {
                searched,
                asked,
                adhesive,
            } => {
                if *searched {
                    "sampled retraction curve, then golden-section refinement to rtol * sigma".into()
                } else if !asked {
                    "not asked for in [outputs]".into()
                } else if !adhesive {
                    "w = 0: no adhesion, no tensile load".into()
                } else {
                    "not searched".into()
                }
            }
            Decision::HysteresisEnergy { computed } => if *computed {
                "int (P_approach - P_retract) dd over the program by adaptive Gauss-Kronrod; a \
                 trapezoid on the program's separations for a finite sample of summits"
            } else {
                "not asked for in [outputs]"
            }
            .into(),
            _ => self.feature_why(),
        }
    }

    /// Why, for the decisions on features beyond the curve (Monte Carlo,
    /// plasticity, resistance, listed states, maps, populations, spheres).
    fn feature_why(&self) -> String {
        match self {
            Decision::MonteCarlo {
                distribution,
                radius_log_std,
                factor,
                ..
            } => format!(
                "drawn from the {distribution} heights{}, summed exactly with each summit's attach/detach \
                 state; compared point by point with the integral in standard errors{}",
                if *radius_log_std > 0.0 {
                    format!(", lognormal radii (log std {radius_log_std})")
                } else {
                    String::new()
                },
                if *factor != 1.0 {
                    format!("; totals scaled by {factor:.4} to the whole surface")
                } else {
                    String::new()
                }
            ),
            Decision::Plasticity {
                psi,
                hardness,
                plastic_law,
            } => format!(
                "GW plasticity index (E*/H) sqrt(sigma/R) with H = {hardness:.4e} Pa: {}; {}",
                if *psi > 1.0 {
                    "above 1, most contacts yield"
                } else {
                    "below 1, most contacts stay elastic"
                },
                if *plastic_law {
                    "the elastic-plastic law follows them (regime fractions at the closest approach in the summary)"
                } else {
                    "the law is elastic"
                }
            ),
            Decision::Resistance {
                greenwood, film, bump, ..
            } => format!(
                "each contact spot from the law's contact radius, summed in parallel{}{}",
                if *greenwood && *bump {
                    " plus Greenwood's mean-field interaction over the bump's apparent area, per \
                     state: the spots' conductance-weighted mean inverse distance I from the \
                     local GW state at every radius (the square of side c_sq/I has the same \
                     interaction; left out where fewer than 2 contacts are expected)"
                } else if *greenwood {
                    " plus Greenwood's mean-field interaction in the square apparent area (left out where fewer than 2 contacts are expected)"
                } else {
                    " (independent spots, no interaction)"
                },
                if *film { ", with a film resistance per spot" } else { "" }
            ),
            Decision::Listed { loads, .. } => format!(
                "reported on approach in the listed order{}; the curve runs to the {}",
                if *loads { ", each separation solved for its load" } else { "" },
                if *loads { "largest load" } else { "closest separation" }
            ),
            Decision::Topography { why, .. } => why.clone(),
            Decision::PullOffPopulation { why, .. } => why.clone(),
            Decision::Sphere {
                paraboloid,
                mu,
                tolerance,
                ..
            } => format!(
                "an elastic {} on the surface (Greenwood & Tripp 1967): the pressure at radius r \
                 is the GW pressure of the local gap, which holds the sphere's shape and the \
                 elastic displacement that pressure causes; the apparent area is the solution's \
                 (surface.nominal_area is not used) and every total is over the bump; \
                 separations are remote (minus the approach of distant points); Newton on \
                 nested meshes, Richardson-extrapolated to {tolerance:e} of the load, outer \
                 radius from the pressure's decay [Greenwood-Tripp mu = {mu:.4}: {}]",
                if *paraboloid {
                    "paraboloid r^2/(2R)"
                } else {
                    "sphere"
                },
                if *mu > 10.0 {
                    "a stiff rough layer, Hertz-like at heavy loads"
                } else if *mu < 0.1 {
                    "a compliant rough layer, close to GW on a rigid sphere"
                } else {
                    "rough layer and bulk both deform"
                }
            ),
                    _ => unreachable!("why() answers the curve's decisions"),
        }
    }
}

fn law_why(reason: &LawReason, d: &Decision) -> String {
    let name = match d {
        Decision::Law { name, .. } => name.as_str(),
        _ => "",
    };
    match reason {
        LawReason::NoAdhesion => "adhesion.w = 0: no adhesion machinery, Hertz asperities".into(),
        LawReason::EverythingOn => "everything-on mode: the exact Maugis-Dugdale law".into(),
        LawReason::CheapestWithin {
            rtol,
            error,
            provenance,
        } => format!(
            "cheapest law within rtol = {rtol:e} of the full Lennard-Jones solution \
             (measured error {error:.2e}; {provenance})"
        ),
        LawReason::NoneWithin { rtol, error } => format!(
            "no analytic law is within rtol = {rtol:e} of the Lennard-Jones solution; {name} is the \
             closest (measured error {error:.2e}); ask for law.kind = \"calibrated\" for the \
             full-solver law"
        ),
        LawReason::Given => "given in the scene".into(),
        LawReason::AutoPlastic => "law.kind = \"auto\" with materials.yield_strength set: \
             elastic-plastic summits (Kogut-Etsion loading, elastic unloading, JKR adhesion on the \
             flattened shape when w > 0); the measured errors against the full solver are of \
             elastic laws, which would ignore the yield strength"
            .into(),
        LawReason::AdhesionNegligible { jkr_scale } => format!(
            "given in the scene; adhesion left out: its JKR interference scale {jkr_scale:.3e} m is \
             below 1e-6 x rtol x sigma"
        ),
        LawReason::Meniscus {
            dry,
            exact,
            error,
            rtol,
            kelvin_radius,
            height,
        } => format!(
            "menisci at adhesion.relative_humidity (Kelvin radius {kelvin_radius:.3e} m, meniscus \
             height {height:.3e} m) beside the dry law {dry}: {}",
            match (exact, error) {
                (true, Some(e)) => format!(
                    "the rigid (Derjaguin) meniscus is off by {e:.2e} > rtol = {rtol:e} in the \
                     pull-off, so the exact two-zone Maugis-Dugdale law (meniscus and the solid's \
                     Dugdale zone on one elastic sphere)"
                ),
                (true, None) => "the exact two-zone Maugis-Dugdale law (meniscus and the \
                     solid's Dugdale zone on one elastic sphere)"
                    .into(),
                (false, Some(e)) if *e <= *rtol => format!(
                    "the rigid (Derjaguin) meniscus beside it, within rtol = {rtol:e} of the \
                     elastic meniscus (pull-off error {e:.2e})"
                ),
                (false, Some(e)) => format!(
                    "the rigid (Derjaguin) meniscus beside it (no exact two-zone form for this \
                     law; pull-off error {e:.2e} against the elastic meniscus)"
                ),
                (false, None) => "the rigid (Derjaguin) meniscus beside it".into(),
            }
        ),
        LawReason::Calibrated {
            cached,
            path,
            auto,
            surface,
        } => format!(
            "{}{}full Lennard-Jones sphere solver (paraboloid), tabulated on both branches to 100 pi \
             w R, with the Lennard-Jones attraction never cut (the Dugdale laws cut it at ~z0: on \
             rough surfaces this tail can dominate the pull-off); {} {path}",
            match auto {
                Some((rtol, law, error)) => format!(
                    "no analytic law is within rtol = {rtol:e} of the Lennard-Jones solution (the \
                     closest, {law}, is off by {error:.2e} for one summit): "
                ),
                None => String::new(),
            },
            match surface {
                Some((rtol, law, output, error)) => format!(
                    "law.kind = \"auto\": {law} meets rtol = {rtol:e} for one summit, but on this \
                     surface its {output} differs by {:.1} % from the full-solver law's, so the run \
                     uses the full-solver law: ",
                    100.0 * error.abs()
                ),
                None => String::new(),
            },
            if *cached {
                "read from the cache"
            } else {
                "computed and cached at"
            }
        ),
    }
}

fn output_why(evaluation: Evaluation, reason: &OutputReason) -> String {
    match reason {
        OutputReason::Asked {
            law,
            distribution,
            rtol,
        } => match evaluation {
            Evaluation::SampleSum => format!(
                "{distribution} heights are a finite sample: the totals are exact averages over the \
                 measured summits"
            ),
            Evaluation::ClosedForm => format!(
                "{law} is a sum of powers and {distribution} heights have closed-form F_n: exact to \
                 ~1e-13, no quadrature"
            ),
            _ => format!(
                "no closed form for {law} on {distribution} heights; error controlled to rtol = \
                 {rtol:e} of int |integrand|"
            ),
        },
        OutputReason::EverythingOn => "everything-on mode".into(),
        OutputReason::NeededByHysteresis => {
            "not asked for, but the hysteresis energy needs it".into()
        }
        OutputReason::NotAsked => "not asked for in [outputs]".into(),
    }
}

impl fmt::Display for Decision {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {} ({})", self.topic(), self.choice(), self.why())
    }
}
