//! The topography part of a plan: which model of the measured map the run
//! uses (`surface.summits`), and whether the other one is run beside it
//! (`surface.compare`).

use super::law::LawChoice;
use crate::error::{Error, Result};
use crate::law::LawKind;
use crate::material::AsperityContact;
use crate::montecarlo::SummitLaw;
use crate::study::scene::{Resolved, Scene, SummitSource, TopographySpec};
use crate::surface::Characterisation;
use std::path::PathBuf;
use std::sync::Arc;

/// A scene's measured map in a plan.
#[derive(Debug, Clone)]
pub struct TopographyPlan {
    /// The scene's topography keys.
    pub spec: TopographySpec,
    /// The map file read.
    pub file: PathBuf,
    /// What the map gave.
    pub characterisation: Arc<Characterisation>,
    /// The map's heights (m), as read (the exact elastic solution of
    /// `study::map_error` solves on it).
    pub map: Arc<crate::surface::HeightMap>,
    /// The law for the measured summits (the plan's law, rescaled per
    /// summit radius), when they are summed (main model or comparison).
    pub summit_law: Option<SummitLaw>,
    /// The law's kind, to rebuild it for the moments' radius in a
    /// comparison.
    pub kind: Option<LawKind>,
}

impl TopographyPlan {
    pub(super) fn new(
        resolved: &Resolved,
        law: &LawChoice,
        contact: &AsperityContact,
    ) -> Result<TopographyPlan> {
        let spec = resolved.spec.clone();
        let kind = law.facts.rebuild;
        let needs_sum = spec.summits == SummitSource::Measured || spec.compare;
        let summit_law = if needs_sum {
            let field = if spec.summits == SummitSource::Measured {
                "surface.summits"
            } else {
                "surface.compare"
            };
            let scaling = law.law.radius_scaling().ok_or_else(|| {
                Error::invalid(
                    field,
                    format!(
                        "measured summits each have their own radius; law {} has no radius scaling \
                         (use law.kind = hertz, dmt or jkr, or summits = \"moments\" without compare)",
                        law.name
                    ),
                )
            })?;
            Some(SummitLaw::scaled(law.law.clone(), contact.radius, scaling)?)
        } else {
            None
        };
        if spec.compare && kind.is_none() {
            return Err(Error::invalid(
                "surface.compare",
                "the comparison rebuilds the law for the other model's radius: not for law.kind = \"calibrated\"",
            ));
        }
        Ok(TopographyPlan {
            spec,
            file: resolved.file.clone(),
            characterisation: Arc::new(resolved.characterisation.clone()),
            map: Arc::new(resolved.map.clone()),
            summit_law,
            kind,
        })
    }

    /// The decision's choice, in a few words.
    pub fn choice(&self) -> String {
        choice(&self.spec)
    }

    /// Why, in a sentence.
    pub fn why(&self) -> String {
        let c = &self.characterisation;
        let main = match self.spec.summits {
            SummitSource::Measured => format!(
                "exact sum over the {} measured summits of {}, each with its own height and radius \
                 (1/curvature), separations from their mean height",
                c.stats.count,
                self.file.display()
            ),
            SummitSource::Moments => format!(
                "Gaussian GW with McCool's parameters from the moments of {} (alpha = {:.3})",
                self.file.display(),
                c.bandwidth_alpha()
            ),
        };
        if self.spec.compare {
            format!(
                "{main}; the {} model runs beside it for the summary",
                self.spec.summits.other().name()
            )
        } else {
            main
        }
    }
}

/// The decisions of a scene with a map that need not read it: which model
/// of the map and whether the other runs beside it.
///
/// # Errors
/// As [`TopographySpec::of`].
pub(super) fn preview_decisions(scene: &Scene) -> Result<Vec<super::Decision>> {
    let Some(spec) = TopographySpec::of(&scene.surface)? else {
        return Ok(Vec::new());
    };
    let main = match spec.summits {
        SummitSource::Measured => format!(
            "an exact sum over the measured summits of {}, each with its own height and radius",
            spec.path
        ),
        SummitSource::Moments => format!(
            "Gaussian GW with McCool's parameters from the moments of {}",
            spec.path
        ),
    };
    Ok(vec![super::Decision::Topography {
        choice: choice(&spec),
        why: format!(
            "{main}{}",
            if spec.compare {
                format!("; the {} model runs beside it", spec.summits.other().name())
            } else {
                String::new()
            }
        ),
    }])
}

/// The decision's choice, in a few words.
fn choice(spec: &TopographySpec) -> String {
    format!(
        "{} summits{}",
        spec.summits.name(),
        if spec.compare {
            format!(" (and {})", spec.summits.other().name())
        } else {
            String::new()
        }
    )
}
