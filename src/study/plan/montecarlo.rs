//! The Monte Carlo part of a plan: population size, scale factor, and the
//! per-summit law (rescaled per radius when the law's kind allows).

use super::law::LawChoice;
use crate::error::{Error, Result};
use crate::gw::RoughSurface;
use crate::material::AsperityContact;
use crate::montecarlo::{PopulationSpec, RadiusSpec, SummitLaw, MAX_SUMMITS};
use crate::study::scene::MonteCarloSpec;

/// The Monte Carlo part of a plan.
#[derive(Debug, Clone)]
pub struct McPlan {
    /// The scene's request.
    pub spec: MonteCarloSpec,
    /// Summits drawn.
    pub summits: usize,
    /// `eta A_n / summits`: totals are multiplied by it.
    pub factor: f64,
    /// The per-summit law (the plan's law; rescaled per radius with a
    /// radius spread).
    pub law: SummitLaw,
}

impl McPlan {
    pub(super) fn new(
        spec: &MonteCarloSpec,
        surface: &RoughSurface,
        contact: &AsperityContact,
        law: &LawChoice,
    ) -> Result<McPlan> {
        let expected = surface.summits();
        let summits = match spec.summits {
            Some(n) => n,
            None => {
                if !(expected >= 0.5 && expected <= MAX_SUMMITS as f64) {
                    return Err(Error::invalid(
                        "montecarlo.summits",
                        format!(
                            "eta A_n = {expected:e} summits is not a population size in 1 ..= {MAX_SUMMITS}; \
                             give montecarlo.summits"
                        ),
                    ));
                }
                expected.round() as usize
            }
        };
        let summit_law = if spec.radius_log_std == 0.0 {
            SummitLaw::fixed(law.law.clone(), contact.radius)?
        } else {
            match law.law.radius_scaling() {
                Some(s) => SummitLaw::scaled(law.law.clone(), contact.radius, s)?,
                None => {
                    return Err(Error::invalid(
                        "montecarlo.radius_log_std",
                        format!(
                            "a radius spread needs a law that scales with R (hertz, dmt, jkr, bradley, \
                             or an elastic-plastic law without adhesion), not {}",
                            law.name
                        ),
                    ))
                }
            }
        };
        Ok(McPlan {
            spec: *spec,
            summits,
            factor: expected / summits as f64,
            law: summit_law,
        })
    }

    /// The population spec (heights scale `sigma`, radii, seed).
    ///
    /// # Errors
    /// Bad values, naming the `montecarlo.` field.
    pub fn population_spec(&self, surface: &RoughSurface) -> Result<PopulationSpec> {
        let radius = if self.spec.radius_log_std > 0.0 {
            RadiusSpec::LogNormal {
                median: surface.radius,
                log_std: self.spec.radius_log_std,
            }
        } else {
            RadiusSpec::Fixed(surface.radius)
        };
        PopulationSpec::new(self.summits, surface.sigma, radius, self.spec.seed)
            .map_err(|e| e.in_table("montecarlo"))
    }
}
