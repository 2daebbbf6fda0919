//! The expensive inputs of a plan, gathered when a run starts: a measured
//! height map read and characterised (`[surface] topography`) and the
//! full-solver calibration of a `calibrated` law (from the on-disk cache,
//! or computed by the sphere solver and cached). The planner itself only
//! decides from them ([`super::Plan::decide`]); [`Inputs::at_hand`] is what
//! a preview (`asperity run --plan`) may use: nothing is computed, read
//! beyond the cache, or written.

use super::FullSolver;
use crate::error::{Error, Result};
use crate::sphere::{Calibration, Shape, SolverOptions, SphereProblem};
use crate::study::cache::CalibrationCache;
use crate::study::scene::{build_contact, resolve, LawName, Resolved, Scene};
use std::path::{Path, PathBuf};

/// What a plan needs beyond the scene.
#[derive(Debug, Clone, Default)]
pub struct Inputs {
    /// The measured map and the scene with its summit statistics, for a
    /// scene with `[surface] topography`.
    pub map: Option<Resolved>,
    /// The full-solver calibration, for `law.kind = "calibrated"` with
    /// adhesion.
    pub calibration: Option<CalibrationInput>,
}

/// A calibration and where it came from.
#[derive(Debug, Clone)]
pub struct CalibrationInput {
    /// The tabulated full solution at the scene's Tabor parameter.
    pub calibration: Calibration,
    /// Whether the cache held it before this run.
    pub cached: bool,
    /// Its cache file.
    pub path: PathBuf,
    /// Why the cache's entry was not used (damaged or altered: it failed
    /// its checksum) and was recomputed; a warning of the run.
    pub note: Option<crate::study::cache::BadEntry>,
}

/// What is still to be gathered when a run starts, for a preview.
#[derive(Debug, Clone, PartialEq)]
pub enum Pending {
    /// The map, read and characterised.
    Map(PathBuf),
    /// The calibration at this Tabor parameter, computed by the sphere
    /// solver (the cache does not hold it).
    Calibration {
        /// Tabor parameter of one summit.
        mu: f64,
        /// The cache file it will be stored in.
        path: PathBuf,
    },
}

/// The sphere problem of a scene's full-solver law (paraboloid, default
/// resolution): its `calibrated` law, or the reference of an analytic
/// adhesive law's model error; `None` without adhesion or without either.
///
/// # Errors
/// [`Error::Invalid`] naming `law.kind` when the Tabor parameter is outside
/// the solver's range.
fn problem(scene: &Scene) -> Result<Option<SphereProblem>> {
    // The full-solver law is the calibrated law itself, and the reference
    // of an analytic adhesive law's model error (or of `auto`'s choice).
    let need = match scene.law.kind {
        // `auto` with a yield strength chooses an elastic-plastic law.
        LawName::Auto if scene.plasticity().ok().flatten().is_some() => FullSolver::NoCounterpart,
        kind => FullSolver::of_scene(kind),
    };
    let needed = match need {
        FullSolver::Itself => true,
        FullSolver::Reference => scene.accuracy.model_error,
        FullSolver::NoCounterpart => false,
    };
    if !needed || !(scene.adhesion.w > 0.0) {
        return Ok(None);
    }
    let contact = build_contact(scene)?;
    let mu = contact.tabor();
    if need != FullSolver::Itself && !solver_reaches(mu) {
        // No reference there: the model error says so, `auto` keeps to the
        // analytic laws (JKR is the exact large-mu limit).
        return Ok(None);
    }
    SphereProblem::new(mu, Shape::Paraboloid, SolverOptions::default())
        .map(Some)
        .map_err(|e| {
            // Named "mu": the caller's mapping names the input that drove it.
            Error::invalid(
                "mu",
                format!("law.kind = \"calibrated\" needs the full solver at mu = {mu:.4}: {e}"),
            )
        })
}

/// Whether the full solver covers Tabor parameter `mu`
/// ([`SphereProblem::new`]'s range).
pub fn solver_reaches(mu: f64) -> bool {
    SphereProblem::new(mu, Shape::Paraboloid, SolverOptions::default()).is_ok()
}

impl Inputs {
    /// Everything the scene needs, computing what is missing: the map is
    /// read (its path relative to `base_dir`, the scene file's directory)
    /// and characterised, the calibration taken from the cache or computed
    /// and stored (seconds).
    ///
    /// # Errors
    /// As [`resolve`] and [`Calibration::compute`].
    pub fn gather(scene: &Scene, base_dir: &Path) -> Result<Inputs> {
        let map = resolve(scene, base_dir)?;
        let scene = map.as_ref().map_or(scene, |r| &r.scene);
        let calibration = match problem(scene)? {
            Some(p) => {
                let cache = CalibrationCache::default_location();
                let (calibration, cached, note) = cache.get_or_compute_noted(&p)?;
                Some(CalibrationInput {
                    cached,
                    path: cache.path_for(&p),
                    calibration,
                    note,
                })
            }
            None => None,
        };
        Ok(Inputs { map, calibration })
    }

    /// The inputs when they are at hand without expensive work: no map to
    /// read, and a calibration (if needed) already in the cache. Otherwise
    /// what is pending.
    ///
    /// # Errors
    /// As [`Inputs::gather`] for a scene that cannot be planned at all.
    pub fn at_hand(scene: &Scene, base_dir: &Path) -> Result<std::result::Result<Inputs, Pending>> {
        if let Some(path) = &scene.surface.topography {
            return Ok(Err(Pending::Map(base_dir.join(path))));
        }
        let Some(p) = problem(scene)? else {
            return Ok(Ok(Inputs::default()));
        };
        let cache = CalibrationCache::default_location();
        let path = cache.path_for(&p);
        Ok(match cache.load(&p) {
            Some(calibration) => Ok(Inputs {
                map: None,
                calibration: Some(CalibrationInput {
                    calibration,
                    cached: true,
                    path,
                    note: None,
                }),
            }),
            None => Err(Pending::Calibration { mu: p.mu(), path }),
        })
    }
}
