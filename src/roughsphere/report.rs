//! One state of the rough sphere in SI units, with every headline
//! quantity's numerical error estimate and the model's warnings.

use super::problem::RoughSphere;
use super::solve::{Estimate, Solved};
use super::units::hertz_load_fraction_radius;
use super::warning::SphereWarning;
use crate::electrical::{
    ContactResistance, Interaction, ResistanceObservables, SpotResistance, SpotSums, C_SQ,
};
use crate::error::Result;
use crate::loading::{History, Observables};
use serde::Serialize;

/// The real-area fraction at the centre above which a warning says that
/// Greenwood–Williamson's independent summits are no longer a fair model
/// (contacts merge; Greenwood & Williamson 1966 assumed sparse contacts).
pub const AREA_FRACTION_WARNING: f64 = 0.1;
/// The contact radius (95 % of the load) over the sphere radius above which
/// a warning says that the half-space (and, for the paraboloid, the
/// parabolic profile) is stretched.
pub const RADIUS_RATIO_WARNING: f64 = 0.1;

/// Electrical contact of the bump: the spots' resistance law and whether
/// Greenwood's interaction over the bump's apparent area is added.
#[derive(Debug, Clone, Copy)]
pub struct BumpElectrics {
    /// Per-spot resistance (Maxwell, Sharvin, Wexler, film).
    pub spot: SpotResistance,
    /// Independent spots, or with Greenwood's (1966) interaction.
    pub interaction: Interaction,
}

/// What to report besides the load.
#[derive(Debug, Clone, Default)]
pub struct SphereQuery {
    /// Radii (m) at which to report the pressure.
    pub radii: Vec<f64>,
    /// Real contact area and number of contacts.
    pub area_and_count: bool,
    /// The bump's contact resistance.
    pub electrics: Option<BumpElectrics>,
    /// The pressure profile at the finest mesh's nodes.
    pub profile: bool,
}

/// The pressure at one radius.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PressureAt {
    /// Radius (m).
    pub radius: f64,
    /// Pressure (Pa), > 0 compressive.
    pub pressure: Estimate,
}

/// The bump's resistance.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BumpResistance {
    /// Total (Ohm): parallel spots plus the interaction when asked and
    /// computed; `inf` without contact.
    pub resistance: Estimate,
    /// Independent parallel spots `1/sum G` (Ohm).
    pub parallel: f64,
    /// Greenwood's interaction term over the bump (Ohm).
    pub interaction: Option<f64>,
    /// Whether the interaction was asked for but left out (fewer than 2
    /// contacts).
    pub interaction_skipped: bool,
    /// Side (m) of the square whose Greenwood mean-field interaction equals
    /// the bump's: `c_sq / I`, `I` the conductance-weighted mean inverse
    /// distance between spots.
    pub equivalent_square_side: f64,
}

/// One state of the rough sphere.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SphereState {
    /// Remote separation `s = d - w(0)` (m): minus the approach of distant
    /// points.
    pub separation: f64,
    /// Central separation `d` (m) of the sphere's surface from the height
    /// origin.
    pub central_separation: f64,
    /// Approach of distant points `w(0) - d` (m).
    pub approach: Estimate,
    /// Central elastic deflection `w(0)` (m).
    pub central_deflection: Estimate,
    /// Load (N), > 0 compressive.
    pub load: Estimate,
    /// Radius holding 95 % of the load (m); `None` unless compressive.
    pub radius_95: Option<Estimate>,
    /// Hertz contact radius at the same load (m), `(3 P R/(4 E*))^(1/3)`.
    pub hertz_radius: Option<f64>,
    /// The radius holding 95 % of a Hertz load, `0.92967` of it (m).
    pub hertz_radius_95: Option<f64>,
    /// Real contact area (m^2).
    pub real_area: Option<Estimate>,
    /// Number of contacts.
    pub contacts: Option<Estimate>,
    /// Contact resistance of the bump.
    pub resistance: Option<BumpResistance>,
    /// Pressures at the queried radii.
    pub pressure: Vec<PressureAt>,
    /// `(r m, p Pa)` at the finest mesh's nodes, when asked.
    pub profile: Option<Vec<(f64, f64)>>,
    /// Outer radius of the mesh (m): the pressure is below `1e-16` of its
    /// scale beyond.
    pub outer_radius: f64,
    /// Nodes of the finest mesh.
    pub nodes: usize,
    /// Whether the load met the solver's tolerance.
    pub converged: bool,
    /// The model the numbers come from (its assumptions; the numerical
    /// error is in each [`Estimate`], the model's limits in `warnings`).
    pub model: String,
    /// Numerical or model warnings (serialised as their sentences).
    pub warnings: Vec<SphereWarning>,
}

impl RoughSphere {
    /// The state at remote separation `separation` (m) after `history`
    /// (on retraction, `closest` is the closest remote separation), with
    /// the quantities of `query`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `separation` or
    /// `closest_separation`; [`crate::Error::NoConvergence`].
    pub fn sphere_state(
        &self,
        separation: f64,
        history: History,
        query: &SphereQuery,
    ) -> Result<SphereState> {
        history.check(separation)?;
        let sigma = self.units().sigma;
        let solved = match history {
            History::Approach => self.approach_remote(separation / sigma)?,
            History::Retract { closest } => {
                self.retract_remote(separation / sigma, closest / sigma)?
            }
        };
        self.report(&solved, query)
    }

    /// The approach state at central separation `d` (m).
    ///
    /// # Errors
    /// As [`sphere_state`](Self::sphere_state).
    pub fn sphere_state_central(&self, d: f64, query: &SphereQuery) -> Result<SphereState> {
        crate::error::finite("central_separation", d)?;
        let s = self.approach_central(d / self.units().sigma)?;
        self.report(&s, query)
    }

    pub(crate) fn report(&self, s: &Solved, query: &SphereQuery) -> Result<SphereState> {
        let u = self.units();
        let core = &self.core;
        let (l, sigma, pu, fu) = (u.length(), u.sigma, u.pressure(), u.load());
        let scaled = |e: Estimate, k: f64| Estimate {
            value: e.value * k,
            error: e.error * k,
        };
        let mut warnings = Vec::new();
        let load = scaled(core.load(s), fu);
        let u0 = scaled(core.central_deflection(s), sigma);
        let radius_95 = core.load_radius(s, 0.95).map(|e| scaled(e, l));
        let hertz_radius = (load.value > 0.0)
            .then(|| (3.0 * load.value * u.sphere_radius / (4.0 * u.contact_modulus)).cbrt());
        if !s.converged {
            warnings.push(SphereWarning::Unconverged {
                load_error: load.error,
                tolerance: core.options.tolerance,
                max_nodes: core.options.max_nodes,
            });
        }
        if let Some(a) = radius_95 {
            if a.value > RADIUS_RATIO_WARNING * u.sphere_radius {
                warnings.push(SphereWarning::ContactRadius { radius: a.value });
            }
        }
        let bottom = core.law.bottom();
        if s.levels
            .iter()
            .any(|lv| lv.sol.h.iter().any(|h| *h < bottom))
        {
            warnings.push(SphereWarning::GapsBelowSummits { bottom });
        }
        let pressure = query
            .radii
            .iter()
            .map(|&r| PressureAt {
                radius: r,
                pressure: scaled(core.pressure_at(s, r / l), pu),
            })
            .collect();
        let (real_area, contacts, resistance) = self.bump_totals(s, query, &mut warnings)?;
        let profile = query.profile.then(|| {
            let (rho, p) = core.profile(s);
            rho.iter().zip(&p).map(|(r, p)| (r * l, p * pu)).collect()
        });
        let last = s.levels.last().expect("levels");
        let remote = self.remote(s);
        Ok(SphereState {
            separation: remote.value * sigma,
            central_separation: s.d * sigma,
            approach: Estimate {
                value: -remote.value * sigma,
                error: remote.error * sigma,
            },
            central_deflection: u0,
            load,
            radius_95,
            hertz_radius,
            hertz_radius_95: hertz_radius.map(|a| a * hertz_load_fraction_radius(0.95)),
            real_area,
            contacts,
            resistance,
            pressure,
            profile,
            outer_radius: last.mesh.rho_max() * l,
            nodes: last.mesh.len(),
            converged: s.converged,
            model: format!(
                "Greenwood & Tripp (1967): local GW pressure of {} summits on {} heights \
                 (independent summits), elastic half-space, {} profile",
                self.model().law().name(),
                self.model().distribution().name(),
                match self.profile() {
                    super::problem::SphereProfile::Paraboloid => "paraboloidal",
                    super::problem::SphereProfile::Sphere => "spherical",
                }
            ),
            warnings,
        })
    }

    /// The real area, the contacts and the contact resistance summed over
    /// the bump (when the query asks for them), with their warnings.
    #[allow(clippy::type_complexity)]
    fn bump_totals(
        &self,
        s: &Solved,
        query: &SphereQuery,
        warnings: &mut Vec<SphereWarning>,
    ) -> Result<(Option<Estimate>, Option<Estimate>, Option<BumpResistance>)> {
        let (mut real_area, mut contacts, mut resistance) = (None, None, None);
        let u = self.units();
        let core = &self.core;
        let l = u.length();
        let scaled = |e: Estimate, k: f64| Estimate {
            value: e.value * k,
            error: e.error * k,
        };
        if query.area_and_count || query.electrics.is_some() {
            let mut obs = Observables::ALL;
            let mut ro = None;
            if let Some(e) = &query.electrics {
                let r = ResistanceObservables::new(e.spot, e.interaction, 1.0);
                obs = r.add_to(obs)?;
                ro = Some(r);
            }
            let slot_of = |name: &str| {
                ro.as_ref()?;
                obs.extras()
                    .iter()
                    .position(|o| o.name() == name)
                    .map(|i| 3 + i)
            };
            let g_slot = slot_of("spot_conductance_S");
            let (totals, inverse) = core.totals(s, &obs, g_slot)?;
            let area_unit = u.area();
            real_area = totals[1].map(|e| scaled(e, area_unit));
            contacts = totals[2].map(|e| scaled(e, area_unit));
            if let (Some(e), Some(inv), Some(g), Some(g2)) = (
                &query.electrics,
                inverse,
                slot_of("spot_conductance_S").and_then(|k| totals[k]),
                slot_of("spot_conductance_sq_S2").and_then(|k| totals[k]),
            ) {
                let sums = SpotSums {
                    contacts: totals[2].map_or(0.0, |t| t.value * area_unit),
                    conductance: g.value * area_unit,
                    conductance_sq: g2.value * area_unit,
                };
                let inv_si = inv.value / l;
                let side = if inv_si > 0.0 {
                    C_SQ / inv_si
                } else {
                    f64::INFINITY
                };
                let cr = ContactResistance::from_sums(&sums, &e.spot, e.interaction, side);
                resistance = Some(bump_resistance(&cr, &g, &inv, side));
                if cr.interaction_skipped {
                    warnings.push(SphereWarning::InteractionSkipped);
                }
            }
            if let Some(frac) = self.central_area_fraction(s)? {
                if frac > 1.0 {
                    // GW sums its summits' areas as if they never overlapped:
                    // above 1 that sum is not a fraction of anything, and the
                    // bump's real area built on it is no result.
                    real_area = None;
                    warnings.push(SphereWarning::AreaAboveOne {
                        fraction: frac,
                        hertz: self.central_hertz_fraction(s),
                    });
                } else if frac > AREA_FRACTION_WARNING {
                    warnings.push(SphereWarning::AreaFraction { fraction: frac });
                }
            }
        }
        Ok((real_area, contacts, resistance))
    }

    /// The real-area fraction elastic summits without adhesion (Hertz)
    /// would have at the central gap: `pi eta R sigma F_1(H)` (Greenwood &
    /// Williamson 1966), the same summits and heights.
    fn central_hertz_fraction(&self, s: &Solved) -> f64 {
        let model = self.core.law.model();
        let surface = model.surface();
        std::f64::consts::PI
            * surface.density
            * surface.radius
            * surface.sigma
            * model.distribution().moment_above(1.0, s.d)
    }

    /// Real-area fraction at the centre (area per nominal area of the
    /// local state at the central gap); `None` without an area.
    fn central_area_fraction(&self, s: &Solved) -> Result<Option<f64>> {
        let model = self.core.law.model();
        let sigma = model.surface().sigma;
        let st = crate::loading::LoadingModel::state(
            model,
            s.d * sigma,
            match &s.retraction {
                Some(r) if s.d >= r.h_min[0][0] => History::Retract {
                    closest: r.h_min[0][0] * sigma,
                },
                _ => History::Approach,
            },
            &Observables::standard(false, true, false),
        )?;
        Ok(st.area().map(|a| a / model.surface().nominal_area))
    }
}

/// The bump's resistance with an error estimate from the conductance's and
/// the inverse distance's (relative errors added).
fn bump_resistance(
    cr: &ContactResistance,
    g: &Estimate,
    inv: &Estimate,
    side: f64,
) -> BumpResistance {
    let rel_g = g.error / g.value.abs().max(1e-300);
    let rel_i = inv.error / inv.value.abs().max(1e-300);
    let err = cr.parallel * rel_g + cr.interaction.unwrap_or(0.0) * (rel_i + 2.0 * rel_g);
    BumpResistance {
        resistance: Estimate {
            value: cr.resistance,
            error: if cr.resistance.is_finite() { err } else { 0.0 },
        },
        parallel: cr.parallel,
        interaction: cr.interaction,
        interaction_skipped: cr.interaction_skipped,
        equivalent_square_side: side,
    }
}
