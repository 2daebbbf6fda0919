//! `law.kind = "auto"` held to its promise on the scene's own surface: the
//! planner picks the cheapest analytic law whose error for one summit
//! (`data/law_errors.json`) meets `rtol`, and the run measures that law's
//! model error on the surface (`study::model_error`). When a headline output
//! misses `rtol` there (the Dugdale and JKR laws cut the Lennard-Jones
//! attraction that carries much of a rough surface's pull-off), the run is
//! repeated with the full-solver (calibrated) law, which `auto` promised
//! (`Plan::auto_replanned` decides that plan).

use super::Results;

/// The headline output of `results` whose measured model error is the
/// largest above `rtol`, as `(its name, the relative error)`.
pub(super) fn missed(results: &Results, rtol: f64) -> Option<(&'static str, f64)> {
    let m = results.model_error.as_ref()?;
    let listed = m
        .listed_loads
        .iter()
        .flatten()
        .map(|&e| ("load at a listed state", e));
    [
        ("pull-off", m.pull_off),
        ("max load", m.max_load),
        ("hysteresis energy", m.hysteresis_energy),
    ]
    .into_iter()
    .filter_map(|(n, e)| e.map(|e| (n, e)))
    .chain(listed)
    .filter(|(_, e)| e.abs() > rtol || e.is_nan())
    .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
}
