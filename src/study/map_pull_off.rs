//! GW's pull-off on a measured map against the adhesive boundary-element
//! solution of the same map ([`crate::bem::Problem::with_adhesion`]).
//!
//! GW is the run itself: the scene's law on the map's summits, retracted
//! from the program's closest approach; its pull-off `P_GW` (N) is the most
//! tensile load of that retraction. The exact model is the whole map as one
//! elastic half-space (contact modulus `E*`) under the exponential
//! interaction `phi(g) = -w exp(-g/rho)` per unit area: the same work of
//! adhesion `w` (J/m^2) as the scene, and the range `rho = w/sigma0 =
//! 9 sqrt(3) z0/16 = 0.9743 z0` (m) that gives it the same largest tension
//! `w/rho = sigma0 = 16 w/(9 sqrt(3) z0)` as the Lennard-Jones 9-3 law of
//! equilibrium spacing `z0` (Maugis's Dugdale stress,
//! [`crate::material::Adhesion::dugdale_stress`]). Its pull-off is the most
//! tensile mean pressure `p_min` (Pa) of a mean-gap-controlled retraction:
//! from the state at the run's largest load (load control, the gap that
//! gives the pressure), [`STEPS`] equal steps of the mean gap up to
//! `max h + END_RANGES rho`, each solve warm-started from the previous one
//! (the retraction branch), stopped once the surfaces are apart past the
//! minimum (continued up to twice as far while the contact holds); the most tensile step and its neighbours refined by golden
//! section to 1/32 of a step. `P_exact = p_min A_n` (N; `A_n` the run's
//! nominal area) and the difference `(P_GW - P_exact)/|P_exact|`.
//!
//! The adhesive solver needs a periodic map: a map that is not periodic is
//! mirrored into a periodic one of twice its rows and columns (its plane
//! removed first; the even extension, continuous at every edge, is the map
//! with mirror-symmetric edges, and its mean pressure is the map's).

use super::plan::Plan;
use crate::bem::{Options, Problem, Solution};
use crate::error::{Error, Result};
use crate::numeric::roots::golden_min;
use crate::surface::HeightMap;
use std::time::Instant;

/// The adhesive solves' stopping residual ([`Options::tolerance`]).
pub const TOLERANCE: f64 = 1e-8;

/// Equal steps of the mean gap from the largest load's state to the end of
/// the sweep.
pub const STEPS: usize = 24;

/// The sweep ends at the mean gap `max h + END_RANGES rho` (the rigid map
/// then `END_RANGES` ranges from the flat at its highest pixel).
pub const END_RANGES: f64 = 10.0;

/// Solves the measurement is priced at: the load-controlled start (about
/// 8 solves of its root-find), the sweep and the golden-section refinement
/// (9 solves).
const SOLVES: f64 = 8.0 + STEPS as f64 + 9.0;

/// Estimated conjugate-gradient iterations per adhesive solve (260 on
/// average measured on 32^2 and 48^2 maps at 1.2-1.7 ranges per step,
/// warm-started; the cold start and a few solves near an instability
/// take thousands).
const ITERATIONS_PER_SOLVE: f64 = 300.0;

/// Estimated CPU time (ns) per pixel of the periodic grid and iteration:
/// 95-100 ns measured on 32^2 and 48^2 grids (9000-9400 iterations in
/// 0.9-2.1 s of CPU), where the FFTs' fixed costs weigh more than on the
/// elastic comparison's larger padded grids.
const NS_PER_PIXEL_ITERATION: f64 = 100.0;

/// The estimated CPU time (s) of the adhesive pull-off of a `rows x cols`
/// map (mirrored to twice its rows and columns unless `periodic`).
pub fn estimate_seconds(rows: usize, cols: usize, periodic: bool) -> f64 {
    let grid = (rows * cols) as f64 * if periodic { 1.0 } else { 4.0 };
    SOLVES * ITERATIONS_PER_SOLVE * NS_PER_PIXEL_ITERATION * grid * 1e-9
}

/// GW's pull-off against the adhesive boundary elements', or why it is not
/// measured; serialised as `summary.json`'s `model_error.pull_off_map`, in
/// this order.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct MapPullOff {
    /// GW's pull-off (N, negative tensile; `null` when not measured).
    #[serde(rename = "gw_N")]
    pub gw: Option<f64>,
    /// The exact pull-off `p_min A_n` (N, negative tensile).
    #[serde(rename = "exact_N")]
    pub exact: Option<f64>,
    /// `(GW - exact)/|exact|`.
    pub relative: Option<f64>,
    /// What the exact pull-off is (its interaction, tolerance and sweep), or
    /// why it is not measured (a sentence).
    pub reference: String,
    /// The adhesive solves' stopping residual (dimensionless),
    /// [`TOLERANCE`].
    pub tolerance: f64,
    /// What differs between GW and the exact model (interaction law, summit
    /// independence, grid resolution, and the edges of a mirrored map);
    /// empty when not measured.
    pub differences: String,
    /// The work of adhesion `w` (J/m^2) of both.
    #[serde(rename = "work_of_adhesion_J_m2")]
    pub energy: f64,
    /// The exponential interaction's range `rho = 0.9743 z0` (m).
    #[serde(rename = "range_m")]
    pub range: f64,
    /// The mean gap (m) of the exact pull-off.
    #[serde(rename = "gap_m")]
    pub gap: Option<f64>,
    /// The retraction's step of the mean gap (m).
    #[serde(rename = "gap_step_m")]
    pub gap_step: Option<f64>,
    /// The adhesive solves made.
    pub solves: usize,
    /// The most conjugate-gradient iterations of one solve.
    pub max_iterations: usize,
    /// The conjugate-gradient iterations of all solves.
    pub iterations: usize,
    /// The estimated CPU time (s).
    pub estimate_s: f64,
    /// The time it took (s, wall; 0 when not measured).
    pub seconds: f64,
}

impl MapPullOff {
    fn unmeasured(plan: &Plan, reference: String, estimate_s: f64) -> MapPullOff {
        let a = &plan.contact.adhesion;
        MapPullOff {
            reference,
            tolerance: TOLERANCE,
            differences: String::new(),
            gw: None,
            exact: None,
            relative: None,
            gap: None,
            energy: a.work(),
            range: a.dugdale_range(),
            gap_step: None,
            solves: 0,
            max_iterations: 0,
            iterations: 0,
            estimate_s,
            seconds: 0.0,
        }
    }

    /// The warning when GW's pull-off differs from the exact one by more
    /// than [`super::map_error::WARN_ABOVE`].
    pub fn warning(&self) -> Option<crate::study::Warning> {
        let (e, gw, exact) = (self.relative?, self.gw?, self.exact?);
        (e.abs() > super::map_error::WARN_ABOVE).then_some(crate::study::Warning::MapPullOff {
            difference: e,
            gw,
            exact,
        })
    }
}

/// The map the adhesive solver is given: the map itself when periodic,
/// else its plane removed and mirrored to `2 rows x 2 cols`.
fn periodic_map(plan: &Plan) -> Result<Option<(HeightMap, bool)>> {
    let Some(t) = &plan.topography else {
        return Ok(None);
    };
    let c = &t.characterisation;
    if c.periodic {
        return Ok(Some(((*t.map).clone(), false)));
    }
    let (r, k) = (c.rows, c.cols);
    let h = c.plane.residual(t.map.heights(), k);
    let mut m = vec![0.0; 4 * r * k];
    for i in 0..2 * r {
        let si = if i < r { i } else { 2 * r - 1 - i };
        for j in 0..2 * k {
            let sj = if j < k { j } else { 2 * k - 1 - j };
            m[i * 2 * k + j] = h[si * k + sj];
        }
    }
    Ok(Some((HeightMap::new(2 * r, 2 * k, m)?, true)))
}

/// GW's pull-off `gw_pull_off` (N) against the adhesive boundary elements'
/// on the scene's map (module documentation), retracted from the run's
/// largest load `max_load` (N): `None` without a map, without adhesion, on a
/// rough sphere or when the run searched no pull-off; unmeasured, with the
/// reason, when `accuracy.model_error = false`, without a compressive load,
/// or above the budget `max(gw_seconds, CPU_FLOOR)` (as the elastic
/// comparison's, [`super::map_error::CPU_FLOOR`]).
///
/// # Errors
/// Only [`Error::Cancelled`]; a failing solve leaves it unmeasured, with
/// the reason.
pub fn measure(
    plan: &Plan,
    gw_pull_off: Option<f64>,
    max_load: Option<f64>,
    gw_seconds: f64,
) -> Result<Option<MapPullOff>> {
    let Some(t) = &plan.topography else {
        return Ok(None);
    };
    if plan.sphere.is_some() || !(plan.contact.adhesion.work() > 0.0) || !plan.pull_off {
        return Ok(None);
    }
    if !plan.scene.accuracy.model_error {
        return Ok(Some(MapPullOff::unmeasured(
            plan,
            "not measured: accuracy.model_error = false (the adhesive boundary elements are not \
             run)"
                .into(),
            0.0,
        )));
    }
    let Some(p_max) = max_load.filter(|&l| l > 0.0) else {
        return Ok(Some(MapPullOff::unmeasured(
            plan,
            "not measured: the program has no compressive load to retract from".into(),
            0.0,
        )));
    };
    let c = &t.characterisation;
    let (rows, cols, periodic) = (c.rows, c.cols, c.periodic);
    let estimate = estimate_seconds(rows, cols, periodic);
    let (budget, budget_rule) = super::map_error::budget(gw_seconds);
    if estimate > budget {
        return Ok(Some(MapPullOff::unmeasured(
            plan,
            format!(
                "not measured: the adhesive boundary-element pull-off of this {rows} x {cols} \
                 map{} would cost an estimated {estimate:.1} s of CPU, above the budget of \
                 {budget:.1} s ({budget_rule}); \
                 crop or downsample the map to measure it",
                if periodic {
                    ""
                } else {
                    " (mirrored to twice its size)"
                },
            ),
            estimate,
        )));
    }
    let t0 = Instant::now();
    let mut out = match sweep(plan, p_max) {
        Ok(o) => o,
        Err(Error::Cancelled) => return Err(Error::Cancelled),
        Err(e) => {
            return Ok(Some(MapPullOff::unmeasured(
                plan,
                format!("not measured: the adhesive boundary-element solution failed ({e})"),
                estimate,
            )))
        }
    };
    out.seconds = t0.elapsed().as_secs_f64();
    out.estimate_s = estimate;
    out.gw = Some(gw_pull_off.unwrap_or(0.0));
    out.relative = out
        .exact
        .filter(|&x| x != 0.0)
        .map(|x| (out.gw.unwrap_or(0.0) - x) / x.abs());
    Ok(Some(out))
}

/// The adhesive problem of the map, its solves counted.
struct Counted {
    problem: Problem,
    options: Options,
    solves: usize,
    max_iterations: usize,
    iterations: usize,
}

impl Counted {
    fn count(&mut self, s: &Solution) {
        self.solves += 1;
        self.max_iterations = self.max_iterations.max(s.iterations);
        self.iterations += s.iterations;
    }

    /// The state at mean gap `g` (m), warm-started from `warm`.
    fn at(&mut self, g: f64, warm: &Solution) -> Result<Solution> {
        crate::cancel::check()?;
        let s = self.problem.solve_gap(g, &self.options, Some(warm))?;
        self.count(&s);
        Ok(s)
    }
}

/// The retraction's steps from `start` by `step` (m): the most tensile
/// `(gap, mean pressure)`, the state one step before it, and the steps
/// made (module documentation).
///
/// # Errors
/// As the solves; [`Error::Invalid`] when the contact has not pulled off
/// within twice the sweep.
fn retract(
    solver: &mut Counted,
    start: Solution,
    step: f64,
) -> Result<((f64, f64), Option<Solution>, usize)> {
    let u0 = start.mean_gap;
    let mut best = (u0, start.mean_pressure);
    let (mut best_k, mut k) = (0usize, 0usize);
    let mut before_best: Option<Solution> = None;
    let mut prev = start;
    // Past the minimum with the surfaces apart the tension only falls; a
    // contact that holds beyond the sweep's end is followed up to twice it.
    let bracketed = loop {
        k += 1;
        let u = u0 + step * k as f64;
        let s = solver.at(u, &prev)?;
        let apart = s.contact_pixels == 0;
        if s.mean_pressure < best.1 {
            best = (u, s.mean_pressure);
            best_k = k;
            before_best = Some(prev);
        } else if apart && k > best_k + 1 {
            break true;
        }
        if k >= 2 * STEPS || (k >= STEPS && apart && best_k < k) {
            break best_k < k;
        }
        prev = s;
    };
    if !bracketed {
        return Err(Error::invalid(
            "pull-off",
            format!(
                "the most tensile state is the last of {k} steps of the mean gap (up to {:.3e} m): \
                 the contact had not pulled off",
                u0 + step * k as f64
            ),
        ));
    }
    Ok((best, before_best, k))
}

/// The exact retraction from the mean pressure `p_max/A_n` (module
/// documentation).
///
/// # Errors
/// As the solves and [`retract`].
fn sweep(plan: &Plan, p_max: f64) -> Result<MapPullOff> {
    let Some((map, mirrored)) = periodic_map(plan)? else {
        return Err(Error::invalid("surface.topography", "no map"));
    };
    let c = &plan
        .topography
        .as_ref()
        .ok_or_else(|| Error::invalid("surface.topography", "no map"))?
        .characterisation;
    let (w, rho) = (
        plan.contact.adhesion.work(),
        plan.contact.adhesion.dugdale_range(),
    );
    let options = Options {
        tolerance: TOLERANCE,
        ..Options::default()
    };
    let problem = Problem::with_pixels(
        &map,
        (c.pixel_size_m, c.pixel_size_y_m),
        plan.contact.contact_modulus,
        true,
        &options,
    )?
    .with_adhesion(w, rho)?;
    let a_n = plan.surface.nominal_area;
    // The start: the gap that gives the largest load (its root-find's
    // solves count as one; their iterations are the last solve's).
    let start = problem.solve_pressure(p_max / a_n, &options, None)?;
    let step = (problem.zero_load_gap() + END_RANGES * rho - start.mean_gap).max(END_RANGES * rho)
        / STEPS as f64;
    let mut solver = Counted {
        problem,
        options,
        solves: 0,
        max_iterations: 0,
        iterations: 0,
    };
    solver.count(&start);
    let (mut best, before_best, k) = retract(&mut solver, start, step)?;
    // Golden section on the two steps about the most tensile, each solve
    // warm-started from the state one step before it.
    if let Some(warm) = before_best {
        let mut failure: Option<Error> = None;
        let (u, p) = golden_min(
            |u| match solver.at(u, &warm) {
                Ok(s) => s.mean_pressure,
                Err(e) => {
                    failure.get_or_insert(e);
                    f64::NAN
                }
            },
            best.0 - step,
            best.0 + step,
            step / 32.0,
        );
        if let Some(e) = failure {
            return Err(e);
        }
        if p < best.1 {
            best = (u, p);
        }
    }
    Ok(MapPullOff {
        reference: reference(w, rho, k, step, mirrored.then_some((c.rows, c.cols))),
        tolerance: TOLERANCE,
        differences: differences(plan, rho, mirrored),
        gw: None,
        exact: Some(best.1.min(0.0) * a_n),
        relative: None,
        gap: Some(best.0),
        energy: w,
        range: rho,
        gap_step: Some(step),
        solves: solver.solves,
        max_iterations: solver.max_iterations,
        iterations: solver.iterations,
        estimate_s: 0.0,
        seconds: 0.0,
    })
}

/// The reference sentence of a measured pull-off: `k` steps of `step` (m);
/// `mirrored`: the map's rows and columns when it was mirrored.
fn reference(w: f64, rho: f64, k: usize, step: f64, mirrored: Option<(usize, usize)>) -> String {
    format!(
        "the adhesive boundary elements: the whole map{} as one elastic half-space under the \
         exponential interaction -w exp(-g/rho), w = {w:e} J/m^2, rho = {rho:.4e} m (the \
         Lennard-Jones law's largest tension w/rho = 1.0264 w/z0), tolerance {TOLERANCE:e}; \
         pull-off the most tensile mean pressure of a mean-gap-controlled retraction from the \
         run's largest load, {k} steps of {step:.3e} m refined by golden section to {:.2e} m",
        match mirrored {
            Some((rows, cols)) => format!(
                " (mirrored into a periodic {} x {} map)",
                2 * rows,
                2 * cols
            ),
            None => " (periodic)".into(),
        },
        step / 32.0
    )
}

/// What differs between GW's pull-off and the exact one: the interaction
/// law, the summits' independence, the grid's resolution of the range,
/// and the edges of a mirrored map.
fn differences(plan: &Plan, rho: f64, mirrored: bool) -> String {
    let Some(t) = &plan.topography else {
        return String::new();
    };
    let c = &t.characterisation;
    // The height change over one pixel: the RMS gradient sqrt(2 m2) times
    // the pixel size.
    let per_pixel = (2.0 * c.moments.m2).sqrt() * c.pixel_size_m.max(c.pixel_size_y_m);
    format!(
        "interaction law: GW's {} against the exponential -w exp(-g/rho) of the same w and \
         largest tension; summit independence: GW's {} summits are independent paraboloids \
         (no elastic coupling between them, no coalescence of their contacts, no attraction \
         between them) against the whole map deforming as one half-space; grid resolution: the \
         range rho = {rho:.3e} m against the height change over one pixel, {per_pixel:.3e} m \
         (ratio {:.2}; below about 1 the interaction acts on single pixels and the exact \
         pull-off depends on the grid and on the retraction's step){}",
        plan.law.interaction(),
        c.summits.len(),
        rho / per_pixel,
        if mirrored {
            "; edges: the map mirrored into a periodic one (the adhesive solver needs a periodic \
             map), its edges mirror-symmetric"
        } else {
            ""
        }
    )
}
