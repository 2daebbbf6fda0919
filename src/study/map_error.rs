//! GW's model error on a measured map: the run's summits against the exact
//! elastic half-space solution of the same map by FFT boundary elements
//! ([`crate::bem::Problem`]), at the same loads. With an elastic-plastic law
//! and the yielding body's hardness `H` the exact solution is the
//! elastic–perfectly-plastic half-space, the pressure capped at `H`
//! ([`crate::bem::Problem::with_hardness`]); GW stays Hertz's (the elastic
//! part), so the differences then include the plasticity, as the reference
//! sentence says.
//!
//! GW here is the run's own summit model (the measured summits summed
//! exactly, or Gaussian GW on the map's moments, `surface.summits`), with
//! Hertz's law: the elastic part of the model, what GW's independent
//! paraboloidal summits cost against the whole map deforming as one
//! half-space. With adhesion the run's law is not Hertz's; the comparison
//! is then of the elastic part only, and says so.
//!
//! At each load `P` (N; pressure `p = P/A_n`), with separations `d` from
//! the mean summit plane, `y_s` the mean summit height above the map's mean
//! plane and the summits' caps `V = sum pi R_i delta_i^2 = sum 3 pi a_i
//! P_i/(4 E*)` (Hertz: `a^2 = R delta`, `P = 4 E* a^3/(3R)`) flattened onto
//! the flat, GW's mean gap is `u = d + y_s + V/A_n`, measured like the
//! boundary elements' between the flat and the map's mean plane
//! ([`crate::gw::GwOnMoments`] defines it the same way). Reported per
//! state, `(GW - exact)/exact`: the real-area fraction and the mean gap at
//! the same load, and the load at the same mean gap (GW's separation solved
//! for the exact mean gap).

use super::plan::{Plan, Target};
use super::scene::{ProgramTarget, SummitSource};
use crate::bem::{memory_estimate, Options, Problem, Solution};
use crate::error::{Error, Result};
use crate::gw::{CapVolume, GwModel};
use crate::law::{ContactState, Hertz, LawKernels};
use crate::loading::{History, LoadingModel, Observable, Observables, PerAsperity};
use crate::montecarlo::{MeasuredSummits, SummitLaw};
use crate::numeric::roots::brent;
use crate::study::Warning;
use crate::surface::NayakPrediction;
use std::f64::consts::PI;
use std::sync::Arc;
use std::time::Instant;

/// The boundary elements' stopping residual ([`Options::tolerance`]).
pub const EXACT_TOLERANCE: f64 = 1e-10;

/// The CPU time (s) the measurement may always take; above it, only up to
/// the GW run's own time.
pub const CPU_FLOOR: f64 = 2.0;

/// The budget `max(gw_seconds, CPU_FLOOR)` (s) and how it was set, for a
/// "not measured" reason. The GW run's own time is named only when it sets
/// the budget, so that the same scene gives the same words run after run.
pub fn budget(gw_seconds: f64) -> (f64, String) {
    if gw_seconds > CPU_FLOOR {
        (
            gw_seconds,
            format!("the GW run's own CPU time, above the floor of {CPU_FLOOR} s"),
        )
    } else {
        (
            CPU_FLOOR,
            format!("the floor of {CPU_FLOOR} s; the GW run's own time was below it"),
        )
    }
}

/// A difference above this (relative) is a warning.
pub const WARN_ABOVE: f64 = 0.1;

/// Estimated CPU time (ns) of one conjugate-gradient iteration per pixel
/// of the FFT grid (the map, or the map padded to twice its size): two
/// real FFTs and the fused element passes (about 44 ns measured on the
/// 160^2 example map padded to 320^2, 88 iterations in 0.40 s with the
/// theories beside them; rounded up).
const NS_PER_PIXEL_ITERATION: f64 = 50.0;

/// Estimated conjugate-gradient iterations per load (27-33 measured on the
/// example map, warm-started; 40-60 on 256^2-512^2 self-affine maps).
const ITERATIONS_PER_LOAD: f64 = 60.0;

/// The fractions of the largest load at which a separation-controlled (or
/// `max_load`) program is measured: three loads a factor 3 apart.
pub const LOAD_FRACTIONS: [f64; 3] = [1.0 / 9.0, 1.0 / 3.0, 1.0];

/// The estimated CPU time (s) of the exact elastic solution of a `rows x
/// cols` map (padded to twice its size unless `periodic`) at `loads` loads.
pub fn estimate_seconds(rows: usize, cols: usize, periodic: bool, loads: usize) -> f64 {
    let grid = (rows * cols) as f64 * if periodic { 1.0 } else { 4.0 };
    loads as f64 * ITERATIONS_PER_LOAD * NS_PER_PIXEL_ITERATION * grid * 1e-9
}

/// One load: GW beside the exact solution.
#[derive(Debug, Clone, PartialEq)]
pub struct MapState {
    /// The load (N) on the nominal area.
    pub load: f64,
    /// Its mean pressure `P/A_n` (Pa).
    pub pressure: f64,
    /// The exact real-area fraction.
    pub exact_area_fraction: f64,
    /// The exact mean gap (m).
    pub exact_mean_gap: f64,
    /// GW's real-area fraction at the same load.
    pub gw_area_fraction: f64,
    /// GW's mean gap (m) at the same load.
    pub gw_mean_gap: f64,
    /// GW's load (N) at the exact mean gap, when GW reaches that gap.
    pub gw_load_at_exact_gap: Option<f64>,
    /// `(GW - exact)/exact` of the area fraction (null without exact contact).
    pub area: Option<f64>,
    /// Of the load at the same mean gap.
    pub load_at_gap: Option<f64>,
    /// Of the mean gap at the same load.
    pub mean_gap: Option<f64>,
    /// How the exact solve ended (it converged: a solve stopped at the
    /// iteration cap fails the measurement).
    pub solve: crate::bem::SolveReport,
}

/// GW's model error on the map, or why it is not measured.
#[derive(Debug, Clone, PartialEq)]
pub struct MapModelError {
    /// What it is measured against, or why not (a sentence).
    pub reference: String,
    /// The states, in the order of the loads (empty when not measured).
    pub states: Vec<MapState>,
    /// The estimated CPU time (s) of the exact solution.
    pub estimate_s: f64,
    /// The time it took (s, wall), 0 when not measured.
    pub seconds: f64,
}

impl MapModelError {
    fn unmeasured(reference: String, estimate_s: f64) -> MapModelError {
        MapModelError {
            reference,
            states: Vec::new(),
            estimate_s,
            seconds: 0.0,
        }
    }

    /// Warnings for the outputs (area, load at the same mean gap, mean gap)
    /// that differ from the exact solution by more than [`WARN_ABOVE`] at
    /// some state: the largest difference, its state, and how many states
    /// are beyond.
    pub fn warnings(&self) -> Vec<Warning> {
        type Pick = fn(&MapState) -> Option<f64>;
        let outputs: [(&'static str, &'static str, Pick); 3] = [
            ("real contact area", "model_error.area", |s| s.area),
            ("load at the same mean gap", "model_error.load", |s| {
                s.load_at_gap
            }),
            ("mean gap", "model_error.mean_gap", |s| s.mean_gap),
        ];
        let n = self.states.len();
        outputs
            .into_iter()
            .filter_map(|(quantity, key, pick)| {
                let beyond: Vec<(usize, f64)> = self
                    .states
                    .iter()
                    .enumerate()
                    .filter_map(|(i, s)| pick(s).map(|e| (i, e)))
                    .filter(|(_, e)| e.abs() > WARN_ABOVE)
                    .collect();
                let &(i, e) = beyond
                    .iter()
                    .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))?;
                Some(Warning::MapModelError {
                    quantity,
                    key,
                    difference: e,
                    pressure: self.states[i].pressure,
                    state: i,
                    states: n,
                    limit: WARN_ABOVE,
                    beyond: beyond.len(),
                })
            })
            .collect()
    }
}

/// The caps of Hertz summits of any radii, `pi R delta^2 = 3 pi a P/(4 E*)`
/// (m^3) from each summit's own state.
#[derive(Debug, Clone, Copy)]
struct HertzCaps {
    contact_modulus: f64,
}

impl PerAsperity for HertzCaps {
    fn name(&self) -> &str {
        "cap_volume_m3"
    }

    fn value(&self, state: &ContactState) -> f64 {
        3.0 * PI * state.radius * state.load.max(0.0) / (4.0 * self.contact_modulus)
    }
}

/// The elastic GW of the run's summits, with its observables, the slot of
/// the caps' volume, and `y_s` (m).
struct ElasticGw {
    model: Box<dyn LoadingModel>,
    observables: Observables,
    cap_slot: usize,
    mean_summit_height: f64,
    nominal_area: f64,
}

/// A GW state: load (N), area fraction, mean gap (m).
struct GwState {
    load: f64,
    area_fraction: f64,
    mean_gap: f64,
}

impl ElasticGw {
    fn new(plan: &Plan) -> Result<Option<ElasticGw>> {
        let Some(t) = &plan.topography else {
            return Ok(None);
        };
        let estar = plan.contact.contact_modulus;
        let a_n = plan.surface.nominal_area;
        let (model, cap, y_s): (Box<dyn LoadingModel>, Observable, f64) = match t.spec.summits {
            SummitSource::Measured => {
                let r0 = plan.surface.radius;
                let hertz: Arc<dyn LawKernels> = Arc::new(Hertz::new(r0, estar)?);
                let scaling = hertz
                    .radius_scaling()
                    .ok_or_else(|| Error::invalid("law", "Hertz has a radius scaling"))?;
                let law = SummitLaw::scaled(hertz, r0, scaling)?;
                let m = MeasuredSummits::new(&t.characterisation, law, a_n)?;
                let y_s = m.origin_m();
                let cap = Observable::Custom(Arc::new(HertzCaps {
                    contact_modulus: estar,
                }));
                (Box::new(m), cap, y_s)
            }
            SummitSource::Moments => {
                let r = plan.surface.radius;
                let law = Arc::new(Hertz::new(r, estar)?);
                let m = GwModel::new(plan.surface, plan.distribution.clone(), law)?
                    .with_accuracy(plan.accuracy);
                let y_s = NayakPrediction::from_moments(&t.characterisation.moments).mean_height_m;
                (
                    Box::new(m),
                    Observable::Custom(Arc::new(CapVolume::new(r)?)),
                    y_s,
                )
            }
        };
        let observables = Observables::standard(true, true, false).with(cap.clone())?;
        let cap_slot = observables
            .slot(&cap)
            .ok_or_else(|| Error::invalid("observables", "the caps' slot"))?;
        Ok(Some(ElasticGw {
            model,
            observables,
            cap_slot,
            mean_summit_height: y_s,
            nominal_area: a_n,
        }))
    }

    fn at(&self, d: f64) -> Result<GwState> {
        let s = self.model.state(d, History::Approach, &self.observables)?;
        let a_n = self.nominal_area;
        Ok(GwState {
            load: s.load().unwrap_or(0.0),
            area_fraction: s.area().unwrap_or(0.0) / a_n,
            mean_gap: d
                + self.mean_summit_height
                + s.totals.get(self.cap_slot).unwrap_or(0.0) / a_n,
        })
    }

    fn separation_at_load(&self, load: f64) -> Result<f64> {
        self.model
            .separation_at_load(load, self.model.interaction_onset())
    }

    /// GW's load (N) at mean gap `u` (m): the separation where its mean
    /// gap is `u` (increasing in `d` while `A/A_n < 1/2`), bracketed from
    /// `d0` by steps of the height scale, then Brent's method to 1e-12
    /// of the height scale.
    fn load_at_gap(&self, u: f64, d0: f64) -> Result<Option<f64>> {
        let h = self.model.height_scale();
        let f = |d: f64| self.at(d).map_or(f64::NAN, |s| s.mean_gap - u);
        let (mut lo, mut hi) = (d0, d0);
        let mut k = 0;
        while f(lo) > 0.0 && k < 200 {
            lo -= h;
            k += 1;
        }
        while f(hi) < 0.0 && k < 400 {
            hi += h;
            k += 1;
        }
        if !(f(lo) <= 0.0 && f(hi) >= 0.0) {
            return Ok(None);
        }
        let Some(d) = brent(f, lo, hi, 1e-12 * h) else {
            return Ok(None);
        };
        Ok(Some(self.at(d)?.load))
    }
}

/// The loads (N) at which `plan` is measured: the listed loads, or three
/// loads ([`LOAD_FRACTIONS`]) up to the program's largest: `max_load`, or
/// the elastic GW's load at the closest separation `closest` (m).
fn loads(plan: &Plan, gw: &ElasticGw, closest: f64) -> Result<Vec<f64>> {
    if let Some(ProgramTarget::Loads(l)) = &plan.listed {
        return Ok(l.iter().copied().filter(|&p| p > 0.0).collect());
    }
    let top = match plan.target {
        Target::Load(p) => p,
        Target::Separation(_) => gw.at(closest)?.load,
    };
    if !(top > 0.0) {
        return Ok(Vec::new());
    }
    Ok(LOAD_FRACTIONS.iter().map(|f| f * top).collect())
}

/// GW's model error on the scene's map (module documentation): `None` for
/// a scene without a map; unmeasured, with the reason, when
/// `accuracy.model_error = false`, when the program has no compressive
/// load, or when the exact solution's estimated cost is above
/// `max(gw_seconds, CPU_FLOOR)` (`gw_seconds`: the GW run's own time) or
/// its memory above the solver's limit. `closest` is the program's
/// closest separation (m).
///
/// # Errors
/// As the GW states; a failing exact solve leaves the error unmeasured,
/// with the reason.
pub fn measure(plan: &Plan, closest: f64, gw_seconds: f64) -> Result<Option<MapModelError>> {
    let Some(t) = &plan.topography else {
        return Ok(None);
    };
    if plan.sphere.is_some() {
        // A rough sphere is not the flat contact the map's solution is.
        return Ok(None);
    }
    if !plan.scene.accuracy.model_error {
        return Ok(Some(MapModelError::unmeasured(
            "not measured: accuracy.model_error = false (the exact elastic solution of the map is \
             not run)"
                .into(),
            0.0,
        )));
    }
    let Some(gw) = ElasticGw::new(plan)? else {
        return Ok(None);
    };
    let loads = loads(plan, &gw, closest)?;
    if loads.is_empty() {
        return Ok(Some(MapModelError::unmeasured(
            "not measured: the program has no compressive load to compare at".into(),
            0.0,
        )));
    }
    let c = &t.characterisation;
    let (rows, cols, periodic) = (c.rows, c.cols, c.periodic);
    let estimate = estimate_seconds(rows, cols, periodic, loads.len());
    let (budget, budget_rule) = budget(gw_seconds);
    let options = Options {
        tolerance: EXACT_TOLERANCE,
        ..Options::default()
    };
    let memory = memory_estimate(rows, cols, periodic);
    if estimate > budget || memory > options.memory_limit {
        return Ok(Some(MapModelError::unmeasured(
            format!(
                "not measured: the exact elastic solution of this {rows} x {cols} map{} at {} \
                 loads would cost an estimated {estimate:.1} s of CPU and {:.0} MiB, above the \
                 budget of {budget:.1} s ({budget_rule}) or {:.0} MiB; crop or downsample the map to measure it, or \
                 run `asperity bem` on it",
                if periodic {
                    ""
                } else {
                    " (padded to twice its size)"
                },
                loads.len(),
                memory as f64 / 1048576.0,
                options.memory_limit as f64 / 1048576.0
            ),
            estimate,
        )));
    }
    let t0 = Instant::now();
    // Elastic–perfectly-plastic: no state carries a mean pressure above H.
    let cap = exact_hardness(plan).map_or(f64::INFINITY, |h| h * gw.nominal_area);
    let all = loads.len();
    let loads: Vec<f64> = loads.into_iter().filter(|&l| l <= cap).collect();
    match exact_states(plan, &gw, &loads, &options) {
        Ok(states) => Ok(Some(MapModelError {
            reference: reference(plan, all - loads.len()),
            states,
            estimate_s: estimate,
            seconds: t0.elapsed().as_secs_f64(),
        })),
        Err(Error::Cancelled) => Err(Error::Cancelled),
        Err(e) => Ok(Some(MapModelError::unmeasured(
            format!("not measured: the exact elastic solution of the map failed ({e})"),
            estimate,
        ))),
    }
}

/// The hardness `H` (Pa) capping the exact solution's pressure: the
/// yielding body's (`materials.hardness`, or its default from the yield
/// strength) when the scene's law is elastic-plastic; `None` (the elastic
/// half-space) for an elastic law or without plastic data.
fn exact_hardness(plan: &Plan) -> Option<f64> {
    plan.decisions.iter().find_map(|d| match d {
        super::plan::Decision::Plasticity {
            hardness,
            plastic_law: true,
            ..
        } => Some(*hardness),
        _ => None,
    })
}

/// The reference sentence of a measured comparison; `dropped` loads above
/// the hardness times the nominal area (no elastic–perfectly-plastic state
/// carries them) are named.
fn reference(plan: &Plan, dropped: usize) -> String {
    let adhesive = plan.contact.adhesion.work() > 0.0;
    let solid = match exact_hardness(plan) {
        Some(h) => format!(
            "exact elastic–perfectly-plastic half-space, hardness H = {h:e} Pa (the contact \
             pressure capped at H{})",
            if dropped > 0 {
                format!(
                    "; {dropped} load(s) above H times the nominal area have no such state and \
                     are left out"
                )
            } else {
                String::new()
            }
        ),
        None => "exact elastic half-space".to_string(),
    };
    let gw = if exact_hardness(plan).is_some() {
        ", elastic: the differences include the plasticity the exact states have"
    } else {
        ""
    };
    format!(
        "{solid}, FFT boundary elements, tolerance {EXACT_TOLERANCE:e}, on the \
         same map{}: GW is the run's summits with Hertz's law{gw}{} (area and mean_gap at the \
         same load, load at the same mean gap, per state)",
        match &plan.topography {
            Some(t) if t.characterisation.periodic => " (periodic)",
            _ => " (padded to twice its size)",
        },
        if adhesive {
            ", the elastic part of the model only (the adhesion of the run's law is not in \
             this comparison)"
        } else {
            ""
        }
    )
}

/// The exact states at `loads` (N) beside GW's.
fn exact_states(
    plan: &Plan,
    gw: &ElasticGw,
    loads: &[f64],
    options: &Options,
) -> Result<Vec<MapState>> {
    let t = plan
        .topography
        .as_ref()
        .ok_or_else(|| Error::invalid("surface.topography", "no map"))?;
    let c = &t.characterisation;
    let problem = Problem::with_pixels(
        &t.map,
        (c.pixel_size_m, c.pixel_size_y_m),
        plan.contact.contact_modulus,
        c.periodic,
        options,
    )?;
    let problem = match exact_hardness(plan) {
        Some(h) => problem.with_hardness(h)?,
        None => problem,
    };
    let a_n = gw.nominal_area;
    let mut warm: Option<Solution> = None;
    let mut out = Vec::with_capacity(loads.len());
    for &load in loads {
        crate::cancel::check()?;
        let p = load / a_n;
        let s = problem.solve_pressure(p, options, warm.as_ref())?;
        let d = gw.separation_at_load(load)?;
        let g = gw.at(d)?;
        let gw_load_at_exact_gap = gw.load_at_gap(s.mean_gap, d)?;
        let (area, gap) = (s.area_fraction(), s.mean_gap);
        out.push(MapState {
            load,
            pressure: p,
            exact_area_fraction: area,
            exact_mean_gap: gap,
            gw_area_fraction: g.area_fraction,
            gw_mean_gap: g.mean_gap,
            gw_load_at_exact_gap,
            area: relative(g.area_fraction, area),
            load_at_gap: gw_load_at_exact_gap.and_then(|l| relative(l, load)),
            mean_gap: relative(g.mean_gap, gap),
            solve: s.report(),
        });
        warm = Some(s);
    }
    Ok(out)
}

/// `(model - exact)/|exact|`, `None` where the exact value is 0.
fn relative(model: f64, exact: f64) -> Option<f64> {
    (exact != 0.0 && model.is_finite()).then(|| (model - exact) / exact.abs())
}
