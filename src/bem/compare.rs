//! The exact boundary-element states of a height map beside the two
//! statistical theories of the same surface at the same mean pressures:
//! GW on the map's finite-difference moments ([`GwOnMoments`]: McCool's
//! `eta`, `R`, `sigma`, Hertz summits, Gaussian heights, as `asperity
//! surface` characterises a map) and Persson on the map's radial spectrum
//! ([`Persson`], [`radial_psd_xy`]), with the relative differences
//! `model/exact - 1` of the real-area fraction and the mean gap, the
//! contact resistance of the clusters and GW's with a resistivity, and what
//! lies outside a model's validity as [`Warning`]s.
//!
//! The exact states are load-controlled (mean pressures) or gap-controlled
//! (mean gaps), each warm-started from the previous one; the theories are
//! asked at each state's mean pressure `p` (none where `p <= 0`).

use super::clusters::size_distribution;
use super::resistance::cluster_resistance;
use super::{Cluster, Exponential, Options, Problem, SizeBin, Solution};
use crate::electrical::{Interaction, ResistanceObservables, SpotResistance, Spreading};
use crate::error::Error;
use crate::gw::{Accuracy, GwOnMoments, GwPressureState};
use crate::loading::{Derived, History, LoadingModel, Observables};
use crate::persson::{Persson, PerssonState};
use crate::spectrum::radial::radial_psd_xy;
use crate::stickiness::{AdhesiveInteraction, Criteria, Roughness};
use crate::surface::{HeightMap, Topography};
use serde::Serialize;
use std::fmt;
use std::time::Instant;

/// What the exact solves hold fixed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Control {
    /// The mean pressures (Pa): load control.
    Pressure,
    /// The mean gaps (m): mean-gap control.
    Gap,
}

impl CompareInput {
    /// The pixel sizes `(dx, dy)` (m).
    pub fn pixels(&self) -> (f64, f64) {
        (
            self.pixel_size,
            self.pixel_size_y.unwrap_or(self.pixel_size),
        )
    }
}

/// The inputs of [`compare`] besides the map.
#[derive(Debug, Clone, PartialEq)]
pub struct CompareInput {
    /// Pixel size `dx` (m) along x (a row).
    pub pixel_size: f64,
    /// Pixel size `dy` (m) along y (a column), when it differs from `dx`
    /// (rectangular pixels: [`Problem::with_pixels`]).
    pub pixel_size_y: Option<f64>,
    /// Contact modulus `E*` (Pa).
    pub contact_modulus: f64,
    /// Whether the map is periodic (else padded to twice its size).
    pub periodic: bool,
    /// What [`CompareInput::targets`] hold fixed.
    pub control: Control,
    /// Mean pressures (Pa) or mean gaps (m), each > 0, solved in order.
    pub targets: Vec<f64>,
    /// The exponential adhesion of the exact solves, if any (periodic maps
    /// only; the theories stay non-adhesive).
    pub adhesion: Option<Exponential>,
    /// The hardness `H` (Pa) capping the exact solves' contact pressure
    /// ([`Problem::with_hardness`]), if any (the theories stay elastic).
    pub hardness: Option<f64>,
    /// The Yang–Persson factor `gamma` in `[0, 1]` of Persson's mean gap.
    pub gamma: f64,
    /// Resistivity `rho` (Ohm m, both bodies): adds the contact resistances
    /// (Maxwell spots).
    pub resistivity: Option<f64>,
    /// The solver's options.
    pub options: Options,
}

/// The step of [`compare`] that failed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Step {
    /// The boundary-element problem ([`Problem::with_pixels`]: the map, the pixel
    /// size, the modulus, the memory limit).
    Problem,
    /// The adhesion ([`Problem::with_adhesion`]).
    Adhesion,
    /// The spots' resistivity ([`SpotResistance::same_metal`]).
    Resistivity,
    /// The map as a topography ([`Topography::with_pixels`]: the heights'
    /// magnitude, the pixel size).
    Topography,
    /// The map's moments and summits ([`Topography::characterise`]).
    Characterise,
    /// The map's radial spectrum ([`radial_psd_xy`]).
    Spectrum,
    /// Persson's theory on it ([`Persson::new`]: `gamma`).
    Persson,
    /// The exact solve of target `index`, of value `target`.
    Solve {
        /// Its index in the targets.
        index: usize,
        /// Its value (Pa or m).
        target: f64,
    },
    /// A state's contact resistance.
    Resistance,
}

/// A failure of [`compare`]: the step and the error of the core function
/// called there (named by that function's arguments).
#[derive(Debug)]
pub struct CompareError {
    /// Where it failed.
    pub step: Step,
    /// The error.
    pub error: Error,
}

impl From<CompareError> for Error {
    fn from(e: CompareError) -> Error {
        e.error
    }
}

/// A statistical theory beside the exact states.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Theory {
    /// Greenwood–Williamson on the map's moments.
    Gw,
    /// Persson on the map's radial spectrum.
    Persson,
}

impl fmt::Display for Theory {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Theory::Gw => "GW",
            Theory::Persson => "Persson",
        })
    }
}

/// What lies outside a model's validity or resolution, as data (`Display`
/// words it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Warning {
    /// At least 10 clusters of state `state`, more than half of them
    /// (`singles` of `clusters`) single pixels: the spots are not resolved.
    UnresolvedSpots {
        /// The state's index.
        state: usize,
        /// Single-pixel clusters.
        singles: usize,
        /// All clusters.
        clusters: usize,
    },
    /// A theory gives no state at state `state`'s mean pressure (Pa).
    NoPrediction {
        /// The state's index.
        state: usize,
        /// The theory.
        theory: Theory,
        /// The mean pressure (Pa).
        pressure: f64,
    },
    /// GW's real-area fraction above [`GW_AREA_LIMIT`] at a mean pressure
    /// (Pa): beyond its light-load validity.
    GwBeyondLightLoad {
        /// The mean pressure (Pa).
        pressure: f64,
        /// GW's `A/A0` there.
        area_fraction: f64,
    },
    /// GW's real-area fraction above 1 at a mean pressure (Pa): its summit
    /// areas summed past the whole nominal area (they never overlap in
    /// GW), not a fraction; reported as null.
    GwAreaAboveOne {
        /// The state's index.
        state: usize,
        /// The mean pressure (Pa).
        pressure: f64,
        /// GW's summed `A/A0` there.
        area_fraction: f64,
    },
    /// McCool's summit heights have no variance on this map (bandwidth
    /// `alpha <= 0.8968`): no GW at all.
    NoGw,
    /// The exact states are adhesive, the theories are not.
    NonAdhesiveTheories,
    /// The exact states are elastic–perfectly-plastic, the theories are
    /// elastic.
    ElasticTheories,
    /// A theory's `quantity` differs from the exact one by more than
    /// [`DIFFERENCE_LIMIT`] at `beyond` of the `states` states; the largest
    /// difference `difference` (relative, `model/exact - 1`) is at state
    /// `state`, mean pressure `pressure` (Pa).
    Differs {
        /// The theory.
        theory: Theory,
        /// `"area fraction"` or `"mean gap"`.
        quantity: &'static str,
        /// The state of the largest difference.
        state: usize,
        /// Its mean pressure (Pa).
        pressure: f64,
        /// The largest difference.
        difference: f64,
        /// States beyond the limit.
        beyond: usize,
        /// States compared.
        states: usize,
    },
    /// State `state` stopped at the iteration cap (allowed): its residual
    /// `residual` after `iterations` iterations is above `tolerance`.
    Unconverged {
        /// The state's index.
        state: usize,
        /// Iterations spent.
        iterations: usize,
        /// The last residual.
        residual: f64,
        /// The tolerance it did not reach.
        tolerance: f64,
    },
    /// State `state` has no contact: its mean gap `mean_gap` (m) is beyond
    /// the surface's highest point, `highest` (m) above its mean plane.
    NoContact {
        /// The state's index.
        state: usize,
        /// Its mean gap (m).
        mean_gap: f64,
        /// The highest point above the mean plane (m).
        highest: f64,
    },
    /// GW's mean gap is negative at state `state`: its summits, flattened
    /// one by one, are pressed below the mean plane, which no surface
    /// does (the exact mean gap is always positive).
    GwNegativeGap {
        /// The state's index.
        state: usize,
        /// The mean pressure (Pa).
        pressure: f64,
        /// GW's mean gap there (m).
        mean_gap: f64,
    },
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Warning::UnresolvedSpots {
                state,
                singles,
                clusters,
            } => write!(
                f,
                "state {state}: {singles} of {clusters} clusters are single pixels: the contact \
                 spots are not resolved (use a finer map)"
            ),
            Warning::NoPrediction {
                state,
                theory,
                pressure,
            } => write!(
                f,
                "state {state}: {theory} gives no state at the mean pressure {pressure:e} Pa \
                 (none without contact pressure, or outside its range): its values are null"
            ),
            Warning::GwBeyondLightLoad {
                pressure,
                area_fraction,
            } => write!(
                f,
                "GW at p = {pressure:e} Pa: area fraction {area_fraction:.3} > 0.1, outside GW's \
                 light-load validity"
            ),
            Warning::GwAreaAboveOne {
                state,
                pressure,
                area_fraction,
            } => write!(
                f,
                "state {state}: GW's area fraction at p = {pressure:e} Pa is null: its sum of \
                 summit areas is {area_fraction:.3} of the nominal area, more than all of it (GW \
                 holds below about 0.1, without asperity interaction)"
            ),
            Warning::NoGw => f.write_str(
                "GW: the map's bandwidth leaves McCool's summit heights no variance; no GW \
                 prediction",
            ),
            Warning::ElasticTheories => f.write_str(
                "GW and Persson columns are the elastic theories at the same mean pressure; the \
                 exact states are elastic-perfectly-plastic (pressure capped at the hardness), so \
                 their differences include the plasticity",
            ),
            Warning::NonAdhesiveTheories => f.write_str(
                "GW and Persson columns are the non-adhesive theories at the same mean pressure",
            ),
            Warning::Differs {
                theory,
                quantity,
                state,
                pressure,
                difference,
                beyond,
                states,
            } => write!(
                f,
                "{theory}'s {quantity} differs from the exact one by more than {:.0} % at {beyond} \
                 of {states} states, by {:+.1} % at state {state} (p = {pressure:e} Pa)",
                100.0 * DIFFERENCE_LIMIT,
                100.0 * difference
            ),
            Warning::Unconverged {
                state,
                iterations,
                residual,
                tolerance,
            } => write!(
                f,
                "state {state}: not converged: stopped at the iteration cap after {iterations} \
                 iterations with residual {residual:.3e} above the tolerance {tolerance:e}; its \
                 values are the last iterate's (converged: false)"
            ),
            Warning::NoContact {
                state,
                mean_gap,
                highest,
            } => write!(
                f,
                "state {state}: no contact: the mean gap {mean_gap:.4e} m is beyond the surface's \
                 highest point ({highest:.4e} m above its mean plane)"
            ),
            Warning::GwNegativeGap {
                state,
                pressure,
                mean_gap,
            } => write!(
                f,
                "state {state}: GW's mean gap at p = {pressure:e} Pa is negative ({mean_gap:.4e} m): \
                 its independently flattened summits are pressed below the mean plane, which the \
                 exact surface never is; GW's gap is meaningless there"
            ),
        }
    }
}

/// A theory's relative difference from the exact state above which
/// [`Warning::Differs`].
pub const DIFFERENCE_LIMIT: f64 = 0.1;

/// GW's real-area fraction above which [`Warning::GwBeyondLightLoad`]:
/// GW neglects the elastic interaction of the summits.
pub const GW_AREA_LIMIT: f64 = 0.1;

/// Contact resistances of a state (Ohm).
#[derive(Serialize, Debug, Clone, Copy, PartialEq)]
pub struct Resistance {
    /// The clusters as independent parallel Holm spots, `1/sum 1/R_i`.
    pub bem_parallel_ohm: f64,
    /// The clusters with Greenwood's (1966) interaction.
    pub bem_greenwood_ohm: f64,
    /// GW's on the same map's moments at the same mean pressure: Hertz
    /// summits' spots, Greenwood's interaction over the map's area.
    pub gw_ohm: Option<f64>,
}

/// One exact state.
#[derive(Debug, Clone, PartialEq)]
pub struct ExactState {
    /// The converged fields and their means.
    pub solution: Solution,
    /// Contact clusters (8-connected pixels in contact).
    pub clusters: usize,
    /// Their sizes (pixels) in logarithmic bins.
    pub cluster_sizes: Vec<SizeBin>,
    /// Contact resistances, with a resistivity.
    pub resistance: Option<Resistance>,
    /// GW's separation (m) of the flat from the mean summit height at the
    /// state's mean pressure, where GW has a state.
    pub gw_separation: Option<f64>,
}

/// GW's summits on the map's moments (McCool).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GwSummits {
    /// Summit density `eta` (1/m^2).
    pub density: f64,
    /// Summit radius `R` (m).
    pub radius: f64,
    /// Summit-height standard deviation `sigma` (m).
    pub sigma: f64,
}

/// A theory's prediction at a state's mean pressure (null where it has
/// none).
#[derive(Serialize, Debug, Clone, Copy, PartialEq)]
pub struct Prediction {
    /// Mean pressure `p` (Pa).
    #[serde(rename = "pressure_Pa")]
    pub pressure: f64,
    /// Real-area fraction `A/A0`.
    pub area_fraction: Option<f64>,
    /// Mean gap `u` (m).
    pub mean_gap_m: Option<f64>,
}

/// Relative differences `model/exact - 1` at a state's mean pressure
/// (null where the model has no value or the exact one is 0).
#[derive(Serialize, Debug, Clone, Copy, PartialEq)]
pub struct Difference {
    /// Mean pressure (Pa).
    #[serde(rename = "pressure_Pa")]
    pub pressure: f64,
    /// GW's area against the exact.
    pub gw_area: Option<f64>,
    /// GW's mean gap against the exact.
    pub gw_mean_gap: Option<f64>,
    /// Persson's area against the exact.
    pub persson_area: Option<f64>,
    /// Persson's mean gap against the exact.
    pub persson_mean_gap: Option<f64>,
}

/// What [`compare`] returns.
#[derive(Debug, Clone, PartialEq)]
pub struct Comparison {
    /// The exact states, in the order of the targets.
    pub states: Vec<ExactState>,
    /// GW at their mean pressures.
    pub gw: Vec<Prediction>,
    /// Persson at their mean pressures.
    pub persson: Vec<Prediction>,
    /// The theories against the exact states.
    pub differences: Vec<Difference>,
    /// Wall-clock time of the solves and predictions (s).
    pub solve_wall_s: f64,
    /// What lies outside a model's validity, in the order found.
    pub warnings: Vec<Warning>,
    /// The stickiness criteria of the map with the adhesion, if any
    /// ([`Problem::roughness`], [`Criteria`]).
    pub criteria: Option<Criteria>,
    /// The map's scales those criteria use.
    pub roughness: Option<Roughness>,
    /// GW's summits (none when McCool's heights have no variance).
    pub gw_summits: Option<GwSummits>,
}

/// The map's theories: GW (none when McCool's heights have no variance),
/// Persson, the map's nominal area `A_n` (m^2), and the spots' resistance.
struct Theories {
    gw: Option<GwOnMoments>,
    persson: Persson,
    nominal_area: f64,
    spot: Option<SpotResistance>,
}

/// `model/exact - 1`, `None` without a model value or with `exact = 0`.
fn relative(model: Option<f64>, exact: f64) -> Option<f64> {
    model.filter(|_| exact != 0.0).map(|m| m / exact - 1.0)
}

/// `f` with its error tagged by `step`.
fn at<T>(step: Step, r: crate::Result<T>) -> Result<T, CompareError> {
    r.map_err(|error| CompareError { step, error })
}

/// The exact elastic contact of `map` (heights in m) by FFT boundary
/// elements at `input`'s targets, beside GW and Persson at the same mean
/// pressures (module documentation).
///
/// # Errors
/// [`CompareError`]: the step and the error of the core function called
/// there ([`Step`]); [`Error::Cancelled`] at [`Step::Solve`].
pub fn compare(map: &HeightMap, input: &CompareInput) -> Result<Comparison, CompareError> {
    let options = &input.options;
    let mut problem = at(
        Step::Problem,
        Problem::with_pixels(
            map,
            input.pixels(),
            input.contact_modulus,
            input.periodic,
            options,
        ),
    )?;
    if let Some(a) = input.adhesion {
        problem = at(Step::Adhesion, problem.with_adhesion(a.energy, a.range))?;
    }
    if let Some(h) = input.hardness {
        problem = at(Step::Problem, problem.with_hardness(h))?;
    }
    let theories = Theories::new(map, input)?;
    let start = Instant::now();
    let mut out = Comparison {
        states: Vec::with_capacity(input.targets.len()),
        gw: Vec::new(),
        persson: Vec::new(),
        differences: Vec::new(),
        solve_wall_s: 0.0,
        warnings: Vec::new(),
        criteria: None,
        roughness: None,
        gw_summits: theories.gw.as_ref().map(|g| GwSummits {
            density: g.params.density_per_m2,
            radius: g.params.radius_m,
            sigma: g.sigma,
        }),
    };
    if let Some(a) = input.adhesion {
        let interaction = AdhesiveInteraction {
            contact_modulus: input.contact_modulus,
            energy: a.energy,
            range: a.range,
        };
        let r = problem.roughness();
        out.criteria = Some(at(Step::Adhesion, Criteria::new(&r, &interaction))?);
        out.roughness = Some(r);
    }
    for (index, &target) in input.targets.iter().enumerate() {
        let warm = out.states.last().map(|s| &s.solution);
        let solve = |warm| match input.control {
            Control::Pressure => problem.solve_pressure(target, options, warm),
            Control::Gap => problem.solve_gap(target, options, warm),
        };
        // A warm start from a far state (the previous target without
        // contact, say 1e-300 Pa before 1e6 Pa) can keep the iteration from
        // converging where a cold start does: a failed warm start is
        // retried cold.
        // An unconverged warm start (allowed) is retried cold likewise, and
        // the smaller residual kept.
        let solved = match solve(warm) {
            Err(Error::NoConvergence { .. }) if warm.is_some() => solve(None),
            Ok(s) if !s.converged && warm.is_some() => match solve(None) {
                Ok(cold) if cold.converged || cold.residual < s.residual => Ok(cold),
                _ => Ok(s),
            },
            r => r,
        };
        let s = at(Step::Solve { index, target }, solved)?;
        if !s.converged {
            out.warnings.push(Warning::Unconverged {
                state: index,
                iterations: s.iterations,
                residual: s.residual,
                tolerance: options.tolerance,
            });
        }
        if s.contact_pixels == 0 && s.mean_gap >= problem.zero_load_gap() {
            out.warnings.push(Warning::NoContact {
                state: index,
                mean_gap: s.mean_gap,
                highest: problem.zero_load_gap(),
            });
        }
        let cl = problem.clusters(&s);
        let state = theories.beside(&problem, s, &cl, &mut out)?;
        out.states.push(state);
    }
    differences_beyond(&mut out);
    if theories.gw.is_none() {
        out.warnings.push(Warning::NoGw);
    }
    if input.adhesion.is_some() {
        out.warnings.push(Warning::NonAdhesiveTheories);
    }
    if input.hardness.is_some() {
        out.warnings.push(Warning::ElasticTheories);
    }
    out.solve_wall_s = start.elapsed().as_secs_f64();
    Ok(out)
}

/// A [`Warning::Differs`] for each theory and quantity that differs from
/// the exact states by more than [`DIFFERENCE_LIMIT`] at some state.
fn differences_beyond(out: &mut Comparison) {
    type Pick = fn(&Difference) -> Option<f64>;
    let picks: [(Theory, &'static str, Pick); 4] = [
        (Theory::Gw, "area fraction", |d| d.gw_area),
        (Theory::Gw, "mean gap", |d| d.gw_mean_gap),
        (Theory::Persson, "area fraction", |d| d.persson_area),
        (Theory::Persson, "mean gap", |d| d.persson_mean_gap),
    ];
    let states = out.differences.len();
    for (theory, quantity, pick) in picks {
        let beyond: Vec<(usize, f64)> = out
            .differences
            .iter()
            .enumerate()
            .filter_map(|(i, d)| pick(d).map(|e| (i, e)))
            .filter(|(_, e)| e.abs() > DIFFERENCE_LIMIT)
            .collect();
        if let Some(&(state, difference)) =
            beyond.iter().max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
        {
            out.warnings.push(Warning::Differs {
                theory,
                quantity,
                state,
                pressure: out.differences[state].pressure,
                difference,
                beyond: beyond.len(),
                states,
            });
        }
    }
}

impl Theories {
    /// GW from the map's finite-difference moments (as `asperity surface`
    /// characterises it), Persson from its radial spectrum, and the spots.
    fn new(map: &HeightMap, input: &CompareInput) -> Result<Self, CompareError> {
        let spot = input
            .resistivity
            .map(|r| {
                at(
                    Step::Resistivity,
                    SpotResistance::same_metal(Spreading::Maxwell, r, None),
                )
            })
            .transpose()?;
        let topo = at(
            Step::Topography,
            Topography::with_pixels(map.clone(), input.pixel_size, input.pixels().1),
        )?;
        let charac = at(Step::Characterise, topo.characterise(input.periodic))?;
        let nominal_area = charac.nominal_area_m2();
        let gw = GwOnMoments::new(&charac.moments, input.contact_modulus, nominal_area).ok();
        let psd = at(
            Step::Spectrum,
            radial_psd_xy(map, input.pixels(), input.periodic),
        )?;
        let persson = at(
            Step::Persson,
            Persson::new(psd, input.contact_modulus, input.gamma),
        )?;
        Ok(Theories {
            gw,
            persson,
            nominal_area,
            spot,
        })
    }

    /// The exact state of solution `s` (clusters `cl`) with the theories
    /// beside it, their predictions, differences and warnings appended to
    /// `out` (the state's index is `out.states.len()`).
    fn beside(
        &self,
        problem: &Problem,
        s: Solution,
        cl: &[Cluster],
        out: &mut Comparison,
    ) -> Result<ExactState, CompareError> {
        let index = out.states.len();
        let singles = cl.iter().filter(|c| c.pixels == 1).count();
        if cl.len() >= 10 && singles * 2 > cl.len() {
            out.warnings.push(Warning::UnresolvedSpots {
                state: index,
                singles,
                clusters: cl.len(),
            });
        }
        let p = s.mean_pressure;
        let gw = self
            .gw
            .as_ref()
            .filter(|_| p > 0.0)
            .and_then(|g| g.state(p).ok())
            .filter(|g| g.area_fraction.is_finite() && g.mean_gap.is_finite());
        // A state whose gap is not representable (p/E* far outside contact
        // mechanics) is no prediction: its values would be null unexplained.
        let pe = (p > 0.0)
            .then(|| self.persson.state(p).ok())
            .flatten()
            .filter(|s| s.area_fraction.is_finite() && s.mean_gap.is_finite());
        for (theory, missing) in [(Theory::Gw, gw.is_none()), (Theory::Persson, pe.is_none())] {
            if missing {
                out.warnings.push(Warning::NoPrediction {
                    state: index,
                    theory,
                    pressure: p,
                });
            }
        }
        if let Some(g) = gw.filter(|g| g.area_fraction > GW_AREA_LIMIT && g.area_fraction <= 1.0) {
            out.warnings.push(Warning::GwBeyondLightLoad {
                pressure: p,
                area_fraction: g.area_fraction,
            });
        }
        if let Some(g) = gw.filter(|g| g.mean_gap < 0.0) {
            out.warnings.push(Warning::GwNegativeGap {
                state: index,
                pressure: p,
                mean_gap: g.mean_gap,
            });
        }
        let resistance = self.resistance(problem, cl, gw.as_ref())?;
        let gw_separation = gw.map(|g| g.separation);
        let (mut gw, pe) = (prediction_gw(p, gw), prediction_persson(p, pe));
        // GW sums its summits' areas as if they never overlapped: above 1
        // that sum is not a fraction, so it is not reported.
        if let Some(a) = gw.area_fraction.filter(|&a| a > 1.0) {
            out.warnings.push(Warning::GwAreaAboveOne {
                state: index,
                pressure: p,
                area_fraction: a,
            });
            gw.area_fraction = None;
        }
        let (area, gap) = (s.area_fraction(), s.mean_gap);
        out.differences.push(Difference {
            pressure: p,
            gw_area: relative(gw.area_fraction, area),
            gw_mean_gap: relative(gw.mean_gap_m, gap),
            persson_area: relative(pe.area_fraction, area),
            persson_mean_gap: relative(pe.mean_gap_m, gap),
        });
        out.gw.push(gw);
        out.persson.push(pe);
        Ok(ExactState {
            solution: s,
            clusters: cl.len(),
            cluster_sizes: size_distribution(cl),
            resistance,
            gw_separation,
        })
    }

    /// The clusters' resistances and GW's at its state `gw`, with a
    /// resistivity; `None` without one or without contact.
    fn resistance(
        &self,
        problem: &Problem,
        cl: &[Cluster],
        gw: Option<&GwPressureState>,
    ) -> Result<Option<Resistance>, CompareError> {
        let Some(spot) = &self.spot else {
            return Ok(None);
        };
        let exact = at(Step::Resistance, cluster_resistance(problem, cl, spot))?;
        let gw_ohm = match (&self.gw, gw) {
            (Some(model), Some(st)) => at(
                Step::Resistance,
                self.gw_resistance(model, st.separation, spot),
            )?,
            _ => None,
        };
        Ok(exact.map(|b| Resistance {
            bem_parallel_ohm: b.parallel,
            bem_greenwood_ohm: b.greenwood,
            gw_ohm,
        }))
    }

    /// GW's contact resistance (Ohm) at separation `d` (m): the engine's
    /// one GW integrator on the same summits, the spot conductances as
    /// observables ([`ResistanceObservables`], by quadrature to
    /// [`Accuracy::DEFAULT`]), Greenwood's interaction over the map's
    /// square of area `A_n`.
    fn gw_resistance(
        &self,
        gw: &GwOnMoments,
        d: f64,
        spot: &SpotResistance,
    ) -> crate::Result<Option<f64>> {
        let model = gw.model().clone().with_accuracy(Accuracy::DEFAULT);
        let r = ResistanceObservables::new(*spot, Interaction::Greenwood, self.nominal_area.sqrt());
        let outputs = r.add_to(Observables::LOAD)?;
        let state = model.state(d, History::Approach, &outputs)?;
        Ok(r.value(&outputs, &state.totals))
    }
}

/// GW's prediction at mean pressure `p` (Pa).
fn prediction_gw(p: f64, s: Option<GwPressureState>) -> Prediction {
    Prediction {
        pressure: p,
        area_fraction: s.map(|g| g.area_fraction),
        mean_gap_m: s.map(|g| g.mean_gap),
    }
}

/// Persson's prediction at mean pressure `p` (Pa).
fn prediction_persson(p: f64, s: Option<PerssonState>) -> Prediction {
    Prediction {
        pressure: p,
        area_fraction: s.map(|g| g.area_fraction),
        mean_gap_m: s.map(|g| g.mean_gap),
    }
}
