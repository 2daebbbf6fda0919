//! The law decision: the scene's law, or for `auto` the cheapest law whose
//! measured error against the full Lennard-Jones solution meets `rtol`.

use super::budget::{Budget, CALIBRATED_MIN_RTOL};
use super::decision::{Decision, LawReason};
use super::inputs::CalibrationInput;
use super::PlanMode;
use crate::error::{Error, Result};
use crate::law::errors::LawErrorTable;
use crate::law::{LawKernels, LawKind};
use crate::material::plastic::Variant;
use crate::material::{AsperityContact, MaugisScales};
use crate::study::scene::{LawName, Scene};
use std::sync::Arc;

/// The law a plan uses.
#[derive(Debug, Clone)]
pub struct LawChoice {
    /// Its name as shown (`"hertz"`, `"maugis"`, `"shaped (cone)"`, ...):
    /// for people, never compared.
    pub name: String,
    /// Which law it is (never [`LawName::Auto`]: the choice is made): the
    /// planner's record of its decision. The run asks [`LawChoice::facts`]
    /// and the law itself instead.
    pub source: LawName,
    /// What the run needs to know about the law, decided with it.
    pub facts: LawFacts,
    /// The built law (for a previewed, not yet calibrated law: Maugis–Dugdale
    /// at the same `lambda`, for the range decisions only).
    pub law: Arc<dyn LawKernels>,
    /// The law's measured error against the full Lennard-Jones solution at
    /// this Tabor parameter (relative, from [`LawErrorTable`]), if known.
    pub measured_error: Option<f64>,
}

/// What the run needs to know about a plan's law beyond what the law itself
/// answers ([`AsperityLaw`](crate::law::AsperityLaw)'s capabilities: history,
/// radius scaling, power form, ...), decided once by the planner from the
/// scene's `law.kind`: the run asks these, never the law's name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LawFacts {
    /// The variant of an elastic-plastic law (its contact regimes at the
    /// closest approach); `None` for an elastic law, whose regimes are
    /// diagnosed with Kogut–Etsion's limits.
    pub plastic: Option<Variant>,
    /// For an elastic-plastic law, the elastic law it reduces to as the
    /// plasticity index goes to 0 (JKR with adhesion, Hertz without), built
    /// by the run for the load–area comparison; `None` for other laws.
    pub elastic_limit: Option<LawKind>,
    /// The law's relation to the full Lennard-Jones sphere solver, which
    /// decides whether its model error is measured.
    pub full_solver: FullSolver,
    /// The analytic law to build for another summit radius (a measured
    /// map's comparison with the model of its moments, whose radius
    /// differs); `None` for a law that cannot be rebuilt so (calibrated:
    /// a table of one radius; elastic-plastic and shaped laws: not offered).
    pub rebuild: Option<LawKind>,
}

impl LawChoice {
    /// The adhesive interaction the law models, for people (what a
    /// comparison with another interaction states as the difference).
    pub fn interaction(&self) -> &'static str {
        match self.source {
            LawName::Analytic(LawKind::Hertz) => "Hertz (no adhesion)",
            LawName::Analytic(LawKind::Jkr) => {
                "JKR: zero-range adhesion (the surface energy w inside the contact only, an \
                 infinite stress at its edge, no attraction outside it)"
            }
            LawName::Analytic(LawKind::Maugis) => {
                "Maugis-Dugdale: a constant tension sigma0 = 1.0264 w/z0 up to the gap \
                 w/sigma0 = 0.9743 z0, none beyond"
            }
            LawName::Analytic(LawKind::Cos) => {
                "Carpick-Ogletree-Salmeron fit of Maugis-Dugdale (a constant tension up to \
                 0.9743 z0)"
            }
            LawName::Analytic(LawKind::Dmt) => {
                "DMT: Hertz's profile plus a constant pull 2 pi w R (the adhesion does not deform \
                 the summit)"
            }
            LawName::Analytic(LawKind::Bradley) => {
                "Bradley: a rigid summit under the Lennard-Jones 9-3 surface force of spacing z0"
            }
            LawName::Calibrated | LawName::Auto => {
                "full-solver law: an elastic sphere under the Lennard-Jones 9-3 surface force of \
                 spacing z0 (a repulsive wall, no hard contact)"
            }
            LawName::Plastic(_) => {
                "JKR adhesion on an elastic-plastic summit's unloading shape (the boundary \
                 elements are elastic)"
            }
            LawName::Shaped => "JKR adhesion on the law.profile shape",
        }
    }
}

impl LawFacts {
    /// An analytic elastic law of `kind`: rebuildable, measured against the
    /// full solver.
    fn analytic(kind: LawKind) -> LawFacts {
        LawFacts {
            plastic: None,
            elastic_limit: None,
            full_solver: FullSolver::Reference,
            rebuild: Some(kind),
        }
    }
}

/// A law's relation to the full Lennard-Jones sphere solver.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FullSolver {
    /// The law is the solver's own (`calibrated`, tabulated): its model
    /// error is that of the Lennard-Jones continuum and GW's independent
    /// summits, not measured.
    Itself,
    /// An analytic elastic law: with adhesion, the solver's law at the same
    /// Tabor parameter is the reference of its model error
    /// (`accuracy.model_error`, where the solver reaches that parameter).
    Reference,
    /// No full-solver counterpart: elastic-plastic and shaped laws (the
    /// solver is elastic and paraboloidal).
    NoCounterpart,
}

impl FullSolver {
    /// What the law a scene names in `law.kind` needs of the full solver,
    /// before the law is chosen (`auto` may choose an analytic law or the
    /// calibrated one: the solver serves it as a reference, or as the law
    /// when the analytic laws miss the tolerance).
    pub fn of_scene(kind: LawName) -> FullSolver {
        match kind {
            LawName::Calibrated => FullSolver::Itself,
            LawName::Auto | LawName::Analytic(_) => FullSolver::Reference,
            LawName::Plastic(_) | LawName::Shaped => FullSolver::NoCounterpart,
        }
    }
}

/// Picks the law and records the decision.
pub(super) fn choose(
    scene: &Scene,
    contact: &AsperityContact,
    mode: PlanMode,
    budget: &Budget,
    calibration: Option<&CalibrationInput>,
    decisions: &mut Vec<Decision>,
) -> Result<LawChoice> {
    let mu = contact.tabor();
    let lambda = contact.lambda();
    let rtol = budget.law_choice();
    let table = LawErrorTable::embedded();
    let w = contact.adhesion.work();
    let given = scene.law.kind;
    let (kind, reason) = match given {
        LawName::Plastic(v) => return plastic(scene, contact, v, false, budget, decisions),
        // An elastic law would ignore the yield strength the scene gives.
        LawName::Auto if scene.plasticity()?.is_some() => {
            return plastic(
                scene,
                contact,
                Variant::KogutEtsion,
                true,
                budget,
                decisions,
            )
        }
        LawName::Shaped => return shaped(scene, contact, decisions),
        LawName::Calibrated if w > 0.0 => {
            return calibrated(contact, calibration, None, rtol, decisions)
        }
        _ if w == 0.0 => {
            if !matches!(given, LawName::Auto | LawName::Analytic(LawKind::Hertz)) {
                return Err(Error::invalid(
                    "law.kind",
                    format!(
                        "{:?} needs adhesion, but adhesion.w = 0 (use \"hertz\" or \"auto\")",
                        given.name()
                    ),
                ));
            }
            (LawKind::Hertz, LawReason::NoAdhesion)
        }
        LawName::Auto if mode == PlanMode::EverythingOn => {
            (LawKind::Maugis, LawReason::EverythingOn)
        }
        LawName::Auto => match table.cheapest_within(mu, rtol) {
            Some((k, error)) => (
                k,
                LawReason::CheapestWithin {
                    rtol,
                    error,
                    provenance: table.provenance_short(),
                },
            ),
            None => {
                let (k, error) = table.most_accurate(mu);
                // The full-solver law, unless the scene declines to run
                // the solver (accuracy.model_error = false).
                if scene.accuracy.model_error && super::inputs::solver_reaches(mu) {
                    let why = (rtol, k.name(), error);
                    return calibrated(contact, calibration, Some(why), rtol, decisions);
                }
                (k, LawReason::NoneWithin { rtol, error })
            }
        },
        LawName::Analytic(k) => (k, LawReason::Given),
        // Calibrated without adhesion was answered above (w == 0).
        LawName::Calibrated => (LawKind::Hertz, LawReason::NoAdhesion),
    };
    let law: Arc<dyn LawKernels> = Arc::from(kind.build(contact)?);
    decisions.push(Decision::Law {
        name: kind.name().into(),
        reason,
        mu,
        lambda,
    });
    Ok(LawChoice {
        name: kind.name().to_string(),
        source: LawName::Analytic(kind),
        facts: LawFacts::analytic(kind),
        law,
        measured_error: table.error(kind, mu),
    })
}

/// The law calibrated from the full Lennard-Jones sphere solver at this
/// Tabor parameter ([`super::Inputs::gather`] took it from the cache or
/// computed it). Without it (a preview of an uncached calibration)
/// Maugis–Dugdale at the same `lambda` stands in for the range decisions,
/// and the decision says so.
/// `auto`: why, as `(rtol, the closest analytic law, its error)`.
fn calibrated(
    contact: &AsperityContact,
    calibration: Option<&CalibrationInput>,
    auto: Option<(f64, &'static str, f64)>,
    rtol: f64,
    decisions: &mut Vec<Decision>,
) -> Result<LawChoice> {
    if let Some(why) = calibrated_rtol_refusal(rtol) {
        let auto = auto.map_or(String::new(), |(_, law, error)| {
            format!(
                "; law.kind = \"auto\" chose the calibrated law because no analytic law \
                 meets rtol (the closest, {law}, is {error:.1e} off)"
            )
        });
        return Err(Error::invalid("accuracy.rtol", format!("{why}{auto}")));
    }
    let law: Arc<dyn LawKernels> = match calibration {
        Some(c) => Arc::new(c.calibration.law(
            contact.radius,
            contact.contact_modulus,
            contact.adhesion.work(),
        )?),
        None => Arc::from(LawKind::Maugis.build(contact)?),
    };
    decisions.push(Decision::Law {
        name: "calibrated".into(),
        reason: LawReason::Calibrated {
            cached: calibration.is_some_and(|c| c.cached),
            path: calibration
                .map_or_else(|| "the cache".to_string(), |c| c.path.display().to_string()),
            auto: auto.map(|(rtol, law, error)| (rtol, law.to_string(), error)),
            surface: None,
        },
        mu: contact.tabor(),
        lambda: contact.lambda(),
    });
    Ok(LawChoice {
        name: "calibrated".into(),
        source: LawName::Calibrated,
        facts: LawFacts {
            plastic: None,
            elastic_limit: None,
            full_solver: FullSolver::Itself,
            rebuild: None,
        },
        law,
        measured_error: None,
    })
}

/// An elastic-plastic law: the variant's loading fit, elastic unloading from
/// the flattened shape, and JKR adhesion on that shape when `w > 0`;
/// `auto`: chosen by `law.kind = "auto"` for a scene with a yield strength.
fn plastic(
    scene: &Scene,
    contact: &AsperityContact,
    variant: Variant,
    auto: bool,
    budget: &Budget,
    decisions: &mut Vec<Decision>,
) -> Result<LawChoice> {
    use crate::law::plastic::{build, AdhesivePlastic, PlasticLaw};
    let plasticity = scene.plasticity()?.ok_or_else(|| {
        Error::invalid(
            "materials.yield_strength",
            format!(
                "the {} law needs the yield strength of the softer body (Pa)",
                variant.name()
            ),
        )
    })?;
    let loading = build(variant, contact.radius, contact.contact_modulus, plasticity)
        .map_err(|e| e.in_table("materials"))?;
    let w = contact.adhesion.work();
    // JKR interference scale of the unflattened summit (MaugisScales):
    // where it is below the budget's share of sigma the adhesion cannot
    // change any output at the tolerance (and underflows the JKR scales),
    // so the bare law serves.
    let jkr_scale = if w > 0.0 {
        MaugisScales::new(contact.radius, contact.contact_modulus, w)?.interference
    } else {
        0.0
    };
    let negligible = jkr_scale < budget.negligible_adhesion() * scene.surface.sigma;
    let law: Arc<dyn LawKernels> = if w > 0.0 && !negligible {
        Arc::new(AdhesivePlastic::new(loading.as_loading(), w)?)
    } else {
        PlasticLaw::as_law(loading)
    };
    let reason = if auto {
        LawReason::AutoPlastic
    } else if w > 0.0 && negligible {
        LawReason::AdhesionNegligible { jkr_scale }
    } else {
        LawReason::Given
    };
    decisions.push(Decision::Law {
        name: variant.name().into(),
        reason,
        mu: contact.tabor(),
        lambda: contact.lambda(),
    });
    Ok(LawChoice {
        name: variant.name().into(),
        source: LawName::Plastic(variant),
        facts: LawFacts {
            plastic: Some(variant),
            elastic_limit: Some(if w > 0.0 {
                LawKind::Jkr
            } else {
                LawKind::Hertz
            }),
            full_solver: FullSolver::NoCounterpart,
            rebuild: None,
        },
        law,
        measured_error: None,
    })
}

/// JKR on the scene's axisymmetric profile (Chebyshev-tabulated, exact
/// beyond the table).
fn shaped(
    scene: &Scene,
    contact: &AsperityContact,
    decisions: &mut Vec<Decision>,
) -> Result<LawChoice> {
    if contact.adhesion.work() == 0.0 {
        return Err(Error::invalid(
            "adhesion.w",
            "kind = \"shaped\" is JKR adhesion on the profile: it needs w > 0",
        ));
    }
    let profile = scene.law.profile(contact.radius)?;
    let name = format!("shaped ({})", profile.name());
    let law =
        crate::law::shaped::Shaped::new(profile, contact.contact_modulus, contact.adhesion.work())
            // The profile keys are valid (checked with the scene): what fails here
            // is derived (instabilities out of floating-point range for these
            // moduli and work of adhesion), named by the caller's mapping.
            .map_err(|e| shaped_error(scene, e))?;
    decisions.push(Decision::Law {
        name: name.clone(),
        reason: LawReason::Given,
        mu: contact.tabor(),
        lambda: contact.lambda(),
    });
    Ok(LawChoice {
        name,
        source: LawName::Shaped,
        facts: LawFacts {
            plastic: None,
            elastic_limit: None,
            full_solver: FullSolver::NoCounterpart,
            rebuild: None,
        },
        law: Arc::new(law),
        measured_error: None,
    })
}

/// A shaped law that cannot be built from valid profile keys: its
/// instabilities left the floating-point range. Names the input furthest
/// from typical values among the profile's own keys, `adhesion.w` and the
/// moduli (`|ln(value/typical)|`).
fn shaped_error(scene: &Scene, e: Error) -> Error {
    let l = &scene.law;
    let m = &scene.materials;
    use crate::material::gold;
    let candidates = [
        ("law.tan_angle", l.tan_angle, 0.3),
        ("law.exponent", l.exponent, 2.0),
        ("law.radius", l.radius, gold::SUMMIT_RADIUS),
        ("adhesion.w", Some(scene.adhesion.w), gold::WORK_OF_ADHESION),
        ("materials.e1", Some(m.e1), gold::YOUNGS_MODULUS),
        ("materials.e2", Some(m.e2), gold::YOUNGS_MODULUS),
    ];
    let pick = candidates
        .iter()
        .filter_map(|(n, v, t)| v.filter(|v| *v > 0.0).map(|v| (*n, (v / t).ln().abs())))
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map_or("adhesion.w", |x| x.0);
    Error::invalid(
        pick,
        format!(
            "the shaped law cannot be built ({e}); {pick} is the input furthest from typical values"
        ),
    )
}

/// `accuracy.rtol` of a calibrated law is at least
/// [`CALIBRATED_MIN_RTOL`].
///
/// # Errors
/// [`Error::Invalid`] naming `accuracy.rtol`, with the range and why.
pub fn check_calibrated_rtol(rtol: f64) -> Result<()> {
    match calibrated_rtol_refusal(rtol) {
        Some(why) => Err(Error::invalid("accuracy.rtol", why)),
        None => Ok(()),
    }
}

/// Why `rtol` is too tight for a calibrated law, if it is.
fn calibrated_rtol_refusal(rtol: f64) -> Option<String> {
    (rtol < CALIBRATED_MIN_RTOL).then(|| {
        format!(
            "{rtol:e} is below what the calibrated law's GW quadrature reaches: its \
             interpolated solver table stalls at a residual of a few 1e-12 (5e-12 ran 14 s and \
             failed); allowed [{CALIBRATED_MIN_RTOL:e}, 0.1] with the calibrated law"
        )
    })
}
