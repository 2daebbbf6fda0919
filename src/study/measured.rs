//! Running a scene with a measured map (`[surface] topography`): the
//! measured-summit model of the main curve, and the other model's headline
//! numbers beside it when the scene asks (`surface.compare`).

use super::plan::{Plan, Target, TopographyPlan};
use crate::error::{Error, Result};
use crate::gw::{GwModel, RoughSurface};
use crate::heights::Gaussian;
use crate::loading::{LoadingModel, LoadingProgram};
use crate::material::AsperityContact;
use crate::montecarlo::MeasuredSummits;
use crate::study::quantity::Headlines;
use crate::study::scene::SummitSource;
use std::sync::Arc;
use std::time::Instant;

/// Retraction samples of the comparison's pull-off search.
const PULL_OFF_SAMPLES: usize = 64;

/// The topography part of a run.
#[derive(Debug, Clone)]
pub struct TopographyResults {
    /// The other model's headline numbers, when `surface.compare = true`.
    pub other: Option<Headline>,
}

/// A model's headline numbers over the scene's program.
#[derive(Debug, Clone, PartialEq)]
pub struct Headline {
    /// `"measured"` or `"moments"`.
    pub model: &'static str,
    /// Number of summits on the nominal area, `eta A_n`.
    pub summits: f64,
    /// Summit density (1/m^2), radius (m) and height scale (m) of the model
    /// (measured: mean curvature radius and height std of the summits).
    pub density: f64,
    /// Summit radius (m).
    pub radius: f64,
    /// Summit-height standard deviation (m).
    pub sigma: f64,
    /// Separation where its program started (m).
    pub start_separation: f64,
    /// Closest separation (m).
    pub closest_separation: f64,
    /// The quantities' headline numbers over its program (`max_load`,
    /// `max_area`, `max_count`, ...).
    pub headlines: Headlines,
    /// Pull-off force (N), when searched and tensile.
    pub pull_off_load: Option<f64>,
    /// Its separation (m).
    pub pull_off_separation: Option<f64>,
    /// Wall-clock time (s).
    pub seconds: f64,
}

/// The exact sum over the measured summits for `plan`, scaled to its
/// nominal area (`None` unless the plan has a topography with a summit
/// law).
///
/// # Errors
/// As [`MeasuredSummits::new`], naming `surface.topography`.
pub fn measured_model(plan: &Plan, t: &TopographyPlan) -> Result<Option<MeasuredSummits>> {
    let Some(law) = &t.summit_law else {
        return Ok(None);
    };
    MeasuredSummits::new(&t.characterisation, law.clone(), plan.surface.nominal_area)
        .map(Some)
        .map_err(|e| e.in_table("surface"))
}

/// The model the main curve uses: the measured summits when the scene
/// says `summits = "measured"`.
///
/// # Errors
/// As [`measured_model`].
pub(super) fn main_model(plan: &Plan) -> Result<Option<MeasuredSummits>> {
    match &plan.topography {
        Some(t) if t.spec.summits == SummitSource::Measured => measured_model(plan, t),
        _ => Ok(None),
    }
}

/// The other model's headline numbers, when asked.
///
/// # Errors
/// As the model's curve, pull-off and load search.
pub(super) fn results(plan: &Plan) -> Result<Option<TopographyResults>> {
    let Some(t) = &plan.topography else {
        return Ok(None);
    };
    if !t.spec.compare {
        return Ok(Some(TopographyResults { other: None }));
    }
    let t0 = Instant::now();
    let c = &t.characterisation;
    let other = match t.spec.summits.other() {
        SummitSource::Moments => {
            let gw = c.gw_from_moments();
            let sigma = gw.sigma_m.ok_or_else(|| {
                Error::invalid(
                    "surface.compare",
                    "the moments give no summit-height spread (alpha <= 0.8968)",
                )
            })?;
            let surface = RoughSurface::new(
                gw.density_per_m2,
                gw.radius_m,
                sigma,
                plan.surface.nominal_area,
            )
            .map_err(|e| e.in_table("surface"))?;
            let contact = AsperityContact::new(
                gw.radius_m,
                plan.contact.contact_modulus,
                plan.contact.adhesion,
            )?;
            let kind = t
                .kind
                .ok_or_else(|| Error::invalid("surface.compare", "needs an analytic law"))?;
            let law = Arc::from(kind.build(&contact)?);
            let model = GwModel::new(surface, Arc::new(Gaussian::new()), law)?;
            // The plan's own rules: its method and its start.
            let accuracy = super::plan::accuracy_of(&model, &plan.budget, plan.mode)?;
            let model = model.with_accuracy(accuracy);
            let start = super::plan::start_of(&model, &plan.budget, plan.mode)
                .0
                .max(plan.start);
            let mut h = headline(plan, &model, start, "moments")?;
            (h.density, h.radius, h.sigma) = (gw.density_per_m2, gw.radius_m, sigma);
            h.summits = surface.summits();
            h
        }
        SummitSource::Measured => {
            let model = measured_model(plan, t)?.ok_or_else(|| {
                Error::invalid("surface.compare", "no law for the measured summits")
            })?;
            let start = model.interaction_onset().max(plan.start);
            let mut h = headline(plan, &model, start, "measured")?;
            let s = &c.stats;
            h.density = s.density_per_m2;
            h.radius = s.radius_m.unwrap_or(f64::NAN);
            h.sigma = s.height_std_m.unwrap_or(f64::NAN);
            h.summits = s.density_per_m2 * plan.surface.nominal_area;
            h
        }
    };
    Ok(Some(TopographyResults {
        other: Some(Headline {
            seconds: t0.elapsed().as_secs_f64(),
            ..other
        }),
    }))
}

/// The headline numbers of `model` over the plan's program from `start`.
fn headline<M: LoadingModel>(
    plan: &Plan,
    model: &M,
    start: f64,
    name: &'static str,
) -> Result<Headline> {
    let closest = match plan.target {
        Target::Separation(d) => d,
        Target::Load(p) => model
            .separation_at_load(p, start)
            .map_err(|e| plan.blame_target(e))?,
    };
    let program = LoadingProgram::new(start, closest, plan.points)?;
    let curve = model.curve(&program, plan.quantities.observables())?;
    let pull_off = if plan.pull_off {
        model.pull_off(closest, start, PULL_OFF_SAMPLES)?
    } else {
        None
    };
    Ok(Headline {
        model: name,
        summits: f64::NAN,
        density: f64::NAN,
        radius: f64::NAN,
        sigma: f64::NAN,
        start_separation: start,
        closest_separation: closest,
        headlines: plan
            .quantities
            .headlines(&plan.quantities.records(&curve.approach)),
        pull_off_load: pull_off.map(|p| p.load),
        pull_off_separation: pull_off.map(|p| p.separation),
        seconds: 0.0,
    })
}
