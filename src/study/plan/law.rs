//! The law decision: the scene's law, or for `auto` the cheapest law whose
//! measured error against the full Lennard-Jones solution meets `rtol`.

use super::decision::{Decision, LawReason};
use super::PlanMode;
use crate::error::{Error, Result};
use crate::law::errors::LawErrorTable;
use crate::law::{AsperityLaw, LawKind};
use crate::material::AsperityContact;
use crate::study::scene::Scene;
use std::sync::Arc;

/// Where the plan's law comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LawSource {
    /// An analytic law.
    Kind(LawKind),
    /// The law calibrated from the full Lennard-Jones sphere solver.
    Calibrated,
}

/// The law a plan uses.
#[derive(Debug, Clone)]
pub struct LawChoice {
    /// Its name (`"hertz"`, `"maugis"`, `"calibrated"`, ...).
    pub name: String,
    /// Where it comes from.
    pub source: LawSource,
    /// The built law (for a previewed, not yet calibrated law: Maugis–Dugdale
    /// at the same `lambda`, for the range decisions only).
    pub law: Arc<dyn AsperityLaw>,
    /// The law's measured error against the full Lennard-Jones solution at
    /// this Tabor parameter (relative, from [`LawErrorTable`]), if known.
    pub measured_error: Option<f64>,
}

/// Picks the law and records the decision.
pub(super) fn choose(
    scene: &Scene,
    contact: &AsperityContact,
    mode: PlanMode,
    preview: bool,
    decisions: &mut Vec<Decision>,
) -> Result<LawChoice> {
    let mu = contact.tabor();
    let lambda = contact.lambda();
    let rtol = scene.accuracy.rtol;
    let table = LawErrorTable::embedded();
    let w = contact.adhesion.work();
    let kind_name = scene.law.kind.as_str();
    if kind_name == "calibrated" && w > 0.0 {
        return calibrated(contact, preview, decisions);
    }
    let (kind, reason) = if w == 0.0 {
        if !matches!(kind_name, "auto" | "hertz") {
            return Err(Error::invalid(
                "law.kind",
                format!(
                    "{kind_name:?} needs adhesion, but adhesion.w = 0 (use \"hertz\" or \"auto\")"
                ),
            ));
        }
        (LawKind::Hertz, LawReason::NoAdhesion)
    } else if kind_name == "auto" && mode == PlanMode::EverythingOn {
        (LawKind::Maugis, LawReason::EverythingOn)
    } else if kind_name == "auto" {
        match table.cheapest_within(mu, rtol) {
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
                (k, LawReason::NoneWithin { rtol, error })
            }
        }
    } else {
        let k = LawKind::parse(kind_name).map_err(|e| e.renamed("law.kind"))?;
        (k, LawReason::Given)
    };
    let law: Arc<dyn AsperityLaw> = Arc::from(kind.build(contact)?);
    decisions.push(Decision::Law {
        name: kind.name().into(),
        reason,
        mu,
        lambda,
    });
    Ok(LawChoice {
        name: kind.name().to_string(),
        source: LawSource::Kind(kind),
        law,
        measured_error: table.error(kind, mu),
    })
}

/// The law calibrated from the full Lennard-Jones sphere solver at this
/// Tabor parameter (paraboloid, default resolution), from the on-disk cache
/// when it is there ([`crate::sphere::calibrate`]). A preview never runs the
/// solver: without a cached calibration it stands in Maugis–Dugdale at the
/// same `lambda` for the range decisions and says so.
fn calibrated(
    contact: &AsperityContact,
    preview: bool,
    decisions: &mut Vec<Decision>,
) -> Result<LawChoice> {
    use crate::sphere::{Shape, SolverOptions, SphereProblem};
    use crate::study::cache::CalibrationCache;
    let mu = contact.tabor();
    let problem =
        SphereProblem::new(mu, Shape::Paraboloid, SolverOptions::default()).map_err(|e| {
            Error::invalid(
                "law.kind",
                format!("\"calibrated\" needs the full solver at mu = {mu:.4}: {e}"),
            )
        })?;
    let cache = CalibrationCache::default_location();
    let cached = cache.load(&problem);
    let is_cached = cached.is_some();
    let law: Arc<dyn AsperityLaw> = match cached {
        Some(c) => Arc::new(c.law(
            contact.radius,
            contact.contact_modulus,
            contact.adhesion.work(),
        )?),
        None if preview => Arc::from(LawKind::Maugis.build(contact)?),
        None => Arc::new(cache.get_or_compute(&problem)?.law(
            contact.radius,
            contact.contact_modulus,
            contact.adhesion.work(),
        )?),
    };
    decisions.push(Decision::Law {
        name: "calibrated".into(),
        reason: LawReason::Calibrated {
            cached: is_cached,
            path: cache.path_for(&problem).display().to_string(),
        },
        mu,
        lambda: contact.lambda(),
    });
    Ok(LawChoice {
        name: "calibrated".into(),
        source: LawSource::Calibrated,
        law,
        measured_error: None,
    })
}
